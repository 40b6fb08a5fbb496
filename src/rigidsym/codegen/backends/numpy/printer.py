"""The NumPy printer of kernel programs: sympy's ``NumPyPrinter`` with the kernel printers'
visitors (:class:`~rigidsym.codegen.backends.printing.KernelPrinterMixin`), ``numpy.where``
for ``Piecewise``. The accuracy meter evaluates the forms it chooses through it, as the
kernels print them.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from rigidsym.codegen.backends.printing import KernelPrinterMixin, dyadic_repr

__all__ = ["KernelNumPyPrinter", "numpy_code"]


class KernelNumPyPrinter(KernelPrinterMixin, NumPyPrinter):
    """NumPy printer for element-wise kernels over component arrays (``numpy.`` prefix)."""

    _one = "1.0"

    def __init__(self, settings=None):
        super().__init__(settings or {})

    def _sqrt(self, arg: str) -> str:
        return f"{self._module_format('numpy.sqrt')}({arg})"

    def _print_Rational(self, expr):
        d = dyadic_repr(expr)
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


def numpy_code(expr) -> str:
    """Print ``expr`` as a NumPy expression."""
    return KernelNumPyPrinter().doprint(expr)
