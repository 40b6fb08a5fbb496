"""Code printers for generated kernels: sympy's NumPy and C99 printers, extended as visitors.

Extensions (``_print_<Class>`` methods, no string surgery):

* small integer powers print as products (``x*x``, ``1.0/(x*x)``), half powers as ``sqrt``;
* ``Piecewise`` prints as a one-line conditional expression (C ternary, ``numpy.where``).
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import PRECEDENCE

__all__ = ["KernelNumPyPrinter", "KernelCPrinter", "numpy_code", "c_code"]

_MAX_EXPAND = 4


class _PowMixin:
    """Shared ``_print_Pow``: products for small integer exponents, sqrt for halves."""

    _one = "1"

    def _sqrt(self, arg: str) -> str:  # pragma: no cover - overridden
        raise NotImplementedError

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and 2 <= int(exp) <= _MAX_EXPAND:
            b = self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            # parenthesised: the Mul printer may place a Pow after "/" without parentheses
            return "(" + "*".join([b] * int(exp)) + ")"
        if exp.is_Integer and -_MAX_EXPAND <= int(exp) <= -1:
            if exp == -1:
                return f"{self._one}/{self.parenthesize(base, PRECEDENCE['Mul'], strict=True)}"
            b = self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            return f"{self._one}/({'*'.join([b] * -int(exp))})"
        if exp == sp.S.Half:
            return self._sqrt(self._print(base))
        if exp == -sp.S.Half:
            return f"{self._one}/{self._sqrt(self._print(base))}"
        if exp.is_Rational and exp.q == 2 and abs(exp.p) <= 2 * _MAX_EXPAND + 1:
            # x**(k/2) = x**((k-1)/2) * sqrt(x): one sqrt, no pow()
            b = self._print(base)
            k = (abs(exp.p) - 1) // 2
            whole = self._print(sp.Pow(base, k, evaluate=False)) if k > 1 else \
                self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            num = f"({whole}*{self._sqrt(b)})"
            return num if exp > 0 else f"{self._one}/{num}"
        if isinstance(self, NumPyPrinter):
            return super()._print_Pow(expr, rational=rational)
        return super()._print_Pow(expr)


def _dyadic(expr) -> str | None:
    """``repr`` of a rational with a power-of-two denominator (exact in binary), else None."""
    q = int(expr.q)
    if q & (q - 1) == 0:
        return repr(float(expr))
    return None


class KernelNumPyPrinter(_PowMixin, NumPyPrinter):
    """NumPy printer for element-wise kernels over component arrays (``numpy.`` prefix)."""

    _one = "1.0"

    def __init__(self, settings=None):
        super().__init__(settings or {})

    def _sqrt(self, arg: str) -> str:
        return f"{self._module_format('numpy.sqrt')}({arg})"

    def _print_Rational(self, expr):
        d = _dyadic(expr)
        return d if d is not None else super()._print_Rational(expr)

    def _print_Piecewise(self, expr):
        # numpy.where(c1, e1, numpy.where(c2, e2, ...)); the last condition must be True
        *head, (last, cond) = expr.args
        if cond is not sp.true:
            raise ValueError("Piecewise without a default branch")
        text = self._print(last)
        for e, c in reversed(head):
            text = f"{self._module_format('numpy.where')}({self._print(c)}, " \
                   f"{self._print(e)}, {text})"
        return text


class KernelCPrinter(_PowMixin, C99CodePrinter):
    """C99 printer for per-sample kernels on ``double`` locals."""

    _one = "1.0"

    def __init__(self, settings=None):
        super().__init__(settings or {})

    def _sqrt(self, arg: str) -> str:
        return f"sqrt({arg})"

    def _print_Piecewise(self, expr):
        *head, (last, cond) = expr.args
        if cond is not sp.true:
            raise ValueError("Piecewise without a default branch")
        text = self._print(last)
        for e, c in reversed(head):
            text = f"(({self._print(c)}) ? ({self._print(e)}) : ({text}))"
        return text

    def _print_Rational(self, expr):
        d = _dyadic(expr)
        return d if d is not None else super()._print_Rational(expr)

    def _print_Integer(self, expr):  # doubles throughout: 2 -> 2.0
        return f"{int(expr)}.0"


def numpy_code(expr) -> str:
    """Print ``expr`` as a NumPy expression."""
    return KernelNumPyPrinter().doprint(expr)


def c_code(expr) -> str:
    """Print ``expr`` as a C99 expression on doubles."""
    return KernelCPrinter().doprint(expr)

