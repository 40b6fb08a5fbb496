"""The C99 printers of kernel programs: :class:`KernelCPrinter` on ``double`` locals (the
extension module's kernels; the C target's printers extend it) and
:class:`KernelCFloatPrinter`, the float32 kernels under a precision plan
(:mod:`rigidsym.codegen.accuracy.float32`): each symbol has a C type and each expression a
context, float or double: float literals (``2.0f``) and ``sqrtf`` in float context, float
symbols cast to double in double context.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.printing.c import C99CodePrinter

from rigidsym.codegen.backends.printing import KernelPrinterMixin, dyadic_repr

__all__ = ["KernelCPrinter", "KernelCFloatPrinter", "KernelCVectorPrinter", "c_code"]


class KernelCPrinter(KernelPrinterMixin, C99CodePrinter):
    """C99 printer for per-sample kernels on ``double`` locals."""

    _one = "1.0"
    _diffprod = "rigidsym_diffprod"
    _sumprod = "rigidsym_sumprod{n}"

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
        d = dyadic_repr(expr)
        return d if d is not None else super()._print_Rational(expr)

    def _print_Integer(self, expr):  # doubles throughout: 2 -> 2.0
        return f"{int(expr)}.0"


class KernelCVectorPrinter(KernelCPrinter):
    """The same programs on columns of 4 samples (``rigidsym_v4d``, GCC vector types: the
    vector lanes of ``RIGIDSYM_VEC_F64`` in ``c_common.h.j2``): operators act lane by lane as
    printed; the compensated helpers and the square root by their ``_v4`` forms (the same
    operations); a ``Piecewise`` as ``rigidsym_select_v4`` of both branches by the condition's
    lane mask (each lane gets the branch the scalar ternary takes, bit for bit; the other
    branch is evaluated too, which can only raise a floating-point flag, and a raised flag
    only sends the block to its exact per-sample test)."""

    _diffprod = "rigidsym_diffprod_v4"
    _sumprod = "rigidsym_sumprod{n}_v4"

    def _sqrt(self, arg: str) -> str:
        return f"rigidsym_sqrt_v4({arg})"

    def compensated_call(self, expr) -> str:
        name = self._diffprod if expr.func.__name__ == "DiffProd" else \
            self._sumprod.format(n=len(expr.args) // 2)
        return f"{name}({', '.join(self.column(a) for a in expr.args)})"

    def column(self, expr) -> str:
        """``expr`` as a column: a number broadcast to the 4 lanes (a scalar converts to a
        vector only in GCC's binary operators)."""
        if sp.sympify(expr).is_Number:
            v = self._print(expr)
            return f"((rigidsym_v4d){{{v}, {v}, {v}, {v}}})"
        return self._print(expr)

    def _print_Piecewise(self, expr):
        *head, (last, cond) = expr.args
        if cond is not sp.true:
            raise ValueError("Piecewise without a default branch")
        text = self.column(last)
        for e, c in reversed(head):
            text = f"rigidsym_select_v4(({self._print(c)}), ({self.column(e)}), ({text}))"
        return text


class KernelCFloatPrinter(KernelCPrinter):
    """C99 printer of the float32 kernels: ``prec`` gives each symbol's C type (``"f"``
    float, the default, or ``"d"`` double); :meth:`print_in` prints an expression in float
    context (float arithmetic: C promotes an operation to double only where a double symbol
    or function value enters it) or double context (every float symbol cast to double).
    sin, cos and atan2 are C's double functions in both."""

    def __init__(self, prec: dict[str, str], settings=None):
        super().__init__(settings)
        self.prec = prec
        self.ctx = "f"

    @property
    def _one(self) -> str:  # type: ignore[override]
        return "1.0f" if self.ctx == "f" else "1.0"

    def print_in(self, expr, ctx: str) -> str:
        """``expr`` printed in context ``ctx`` (``"f"`` or ``"d"``)."""
        self.ctx = ctx
        try:
            return self.doprint(expr)
        finally:
            self.ctx = "f"

    def is_double(self, expr) -> bool:
        """Whether C evaluates ``expr`` in double in float context (a double symbol, or a
        function value, enters it)."""
        expr = sp.sympify(expr)
        return any(self.prec.get(str(s), "f") == "d" for s in expr.free_symbols) or \
            any(isinstance(n, sp.Function) for n in sp.preorder_traversal(expr))

    def _print_Symbol(self, expr):
        name = super()._print_Symbol(expr)
        if self.ctx == "d" and self.prec.get(name, "f") == "f":
            return f"((double){name})"
        return name

    def _float_literal(self, value: float) -> str:
        return f"{float(np.float32(value))!r}f"

    def _print_Integer(self, expr):
        return f"{int(expr)}.0f" if self.ctx == "f" else super()._print_Integer(expr)

    def _print_Rational(self, expr):
        if self.ctx == "f":
            return self._float_literal(float(expr))
        return super()._print_Rational(expr)

    def _print_Float(self, expr):
        if self.ctx == "f":
            return self._float_literal(float(expr))
        return super()._print_Float(expr)

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if self.ctx == "f" and exp in (sp.S.Half, -sp.S.Half) and not self.is_double(base):
            root = f"sqrtf({self._print(base)})"
            return root if exp == sp.S.Half else f"1.0f/{root}"
        return super()._print_Pow(expr, rational)


def c_code(expr) -> str:
    """Print ``expr`` as a C99 expression on doubles."""
    return KernelCPrinter().doprint(expr)
