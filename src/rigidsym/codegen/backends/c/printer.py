"""Printers of the C-only target: the kernels' programs as C99 on ``double`` (the package's
:class:`~rigidsym.codegen.backends.extension.printer.KernelCPrinter`) or on ``float`` only.

:class:`FloatOnlyPrinter` prints a program in float arithmetic throughout: float literals
(``2.0f``, rationals rounded once to float), the C99 float functions (``sinf``, ``cosf``,
``sqrtf``, ``atan2f``, ``fmaf`` in the compensated products' helpers), so that a float
function of the target has no double operation (checked on a Cortex-M4F object by the
tests: no ``__aeabi_d*`` helper is referenced).
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.codegen.ast import float32, float80, real

from rigidsym.codegen.backends.extension.printer import KernelCPrinter

__all__ = ["BranchFreeSign", "DoublePrinter", "FloatOnlyPrinter", "SpelledSymbols", "WidePrinter",
           "negative_operand"]


class SpelledSymbols:
    """Prints a symbol by its C spelling in ``names`` (``{symbol name: C identifier}``, set
    by the target: the arguments', outputs' and components' names in their own namespace,
    :func:`rigidsym.codegen.backends.c.target.spelling`); a symbol not there (a CSE
    temporary) as the C printer does."""

    names: dict = {}

    def _print_Symbol(self, expr):
        return self.names.get(expr.name) or super()._print_Symbol(expr)


def negative_operand(expr):
    """``x`` where ``expr`` is ``Piecewise((-1, x < 0), (1, True))`` (the sign choice of a
    kernel, -1 or 1), else None."""
    if not isinstance(expr, sp.Piecewise) or len(expr.args) != 2:
        return None
    (a, cond), (b, last) = expr.args
    if last is not sp.true or a != -1 or b != 1:
        return None
    if isinstance(cond, sp.StrictLessThan) and cond.rhs == 0:
        return cond.lhs
    if isinstance(cond, sp.StrictGreaterThan) and cond.lhs == 0:
        return cond.rhs
    return None


class BranchFreeSign:
    """Prints ``Piecewise((-1, x < 0), (1, True))`` as ``rigidsym_c_negative_<t>(x)``
    (rigidsym_c_impl.h: the same value for every x, -0 and NaN included, by a mask instead of
    a branch); every other ``Piecewise`` as the C printer does."""

    _negative = "rigidsym_c_negative_d"

    def _print_Piecewise(self, expr):
        x = negative_operand(expr)
        if x is None:
            return super()._print_Piecewise(expr)
        return f"{self._negative}({self._print(x)})"


class DoublePrinter(BranchFreeSign, SpelledSymbols, KernelCPrinter):
    """The package's double printer, with the target's compensated-product helpers."""

    _diffprod = "rigidsym_c_diffprod"
    _sumprod = "rigidsym_c_sumprod{n}"


class FloatOnlyPrinter(BranchFreeSign, SpelledSymbols, KernelCPrinter):
    """C99 printer of float-only programs (every literal, function and helper in float)."""

    _one = "1.0f"
    _negative = "rigidsym_c_negative_f"
    _diffprod = "rigidsym_c_diffprodf"
    _sumprod = "rigidsym_c_sumprod{n}f"

    def __init__(self, settings=None):
        super().__init__({"type_aliases": {real: float32}, **(settings or {})})

    def _sqrt(self, arg: str) -> str:
        return f"sqrtf({arg})"

    @staticmethod
    def _literal(value: float) -> str:
        return f"{float(np.float32(value))!r}f"

    def _print_Integer(self, expr):
        return f"{int(expr)}.0f"

    def _print_Rational(self, expr):
        return self._literal(float(expr))

    def _print_Float(self, expr):
        return self._literal(float(expr))

    def _print_NumberSymbol(self, expr):
        return self._literal(float(expr))

    def _print_Pi(self, expr):
        return self._literal(float(sp.pi))


class WidePrinter(SpelledSymbols, KernelCPrinter):
    """C99 printer of the long double rescue of the double functions (``sinl``, ``sqrtl``,
    ``L`` literals; doubles' exact literals stay as they are: they widen exactly)."""

    _diffprod = "rigidsym_c_diffprodl"
    _sumprod = "rigidsym_c_sumprod{n}l"

    def __init__(self, settings=None):
        super().__init__({"type_aliases": {real: float80}, **(settings or {})})

    def _sqrt(self, arg: str) -> str:
        return f"sqrtl({arg})"
