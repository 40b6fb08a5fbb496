"""The JAX printer of kernel programs (``jax.numpy.``): the NumPy kernel printer's visitors
on sympy's ``JaxPrinter`` module names; floats only (``2.0``: a float32 array stays float32),
``where`` for ``Piecewise``; sine and cosine through the shared ``_sincos`` pair and named
compensated sums through ``_keep`` (the helpers of
:mod:`rigidsym.codegen.backends.arrays.programs`).
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.numpy import JaxPrinter

from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter

__all__ = ["KernelJaxPrinter"]


class KernelJaxPrinter(KernelNumPyPrinter, JaxPrinter):
    """JAX printer (``jax.numpy.``): the NumPy kernel printer's visitors on sympy's
    ``JaxPrinter`` module names; integers print as floats (weakly typed: float32 stays)."""

    _module = "jax.numpy"

    def _sqrt(self, arg: str) -> str:
        return f"{self._module_format('jax.numpy.sqrt')}({arg})"

    def _print_Piecewise(self, expr):
        *head, (last, cond) = expr.args
        if cond is not sp.true:
            raise ValueError("Piecewise without a default branch")
        text = self._print(last)
        for e, c in reversed(head):
            text = f"{self._module_format('jax.numpy.where')}({self._print(c)}, " \
                   f"{self._print(e)}, {text})"
        return text

    def _print_Integer(self, expr):
        return f"{int(expr)}.0"

    def named_call(self, expr) -> str:
        # computed once for all its readers (JAX_KEEP_SOURCE)
        return f"_keep({self.compensated_call(expr)})"

    # the sine and cosine of one argument share one evaluation (JAX_TRIG_SOURCE)
    def _print_sin(self, expr):
        return f"_sin({self._print(expr.args[0])})"

    def _print_cos(self, expr):
        return f"_cos({self._print(expr.args[0])})"

    def _print_And(self, expr):  # sympy's stacks the operands into one array first
        return self._fold("jax.numpy.logical_and", expr.args)

    def _print_Or(self, expr):
        return self._fold("jax.numpy.logical_or", expr.args)

    def _fold(self, fn: str, args) -> str:
        text = self._print(args[0])
        for a in args[1:]:
            text = f"{self._module_format(fn)}({text}, {self._print(a)})"
        return text
