"""Code printers for generated kernels: sympy's NumPy and C99 printers, extended as visitors.

Extensions (``_print_<Class>`` methods, no string surgery):

* small integer powers print as products (``x*x``, ``1.0/(x*x)``), half powers as ``sqrt``;
* ``Piecewise`` prints as a one-line conditional expression (C ternary, ``numpy.where``);
* :class:`KernelTorchPrinter` and :class:`KernelJaxPrinter` print the same programs for
  PyTorch (from sympy's ``TorchPrinter``) and JAX (sympy's ``JaxPrinter``): floats only
  (``2.0``, so a float32 tensor stays float32), ``where`` for ``Piecewise``;
* :class:`KernelCFloatPrinter` prints the float32 kernels: each symbol has a C type (a
  precision plan, :mod:`rigidsym.codegen.accuracy.float32`) and each expression a context, float or
  double: float literals (``2.0f``) and ``sqrtf`` in float context, float symbols cast to
  double in double context.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import JaxPrinter, NumPyPrinter
from sympy.printing.precedence import PRECEDENCE

__all__ = ["KernelNumPyPrinter", "KernelCPrinter", "KernelCFloatPrinter", "KernelJaxPrinter",
           "torch_printer", "numpy_code", "c_code"]

_MAX_EXPAND = 4


class _PowMixin:
    """Shared ``_print_Pow``: products for small integer exponents, sqrt for halves."""

    def _print_QuotientBase(self, expr):
        # a removable quotient (codegen.removable): its branch, series below t*, closed
        # form above at a safe argument, printed as this printer prints a Piecewise
        return self._print(expr.expansion())

    _one = "1"
    #: the compensated a b - c d of :mod:`rigidsym.codegen.accuracy.compensated`, as the printed
    #: module names it (a helper the templates define)
    _diffprod = "_diffprod"

    #: the compensated sum of products (:class:`rigidsym.codegen.accuracy.compensated.SumProd`)
    _sumprod = "_sumprod"
    #: ``{compensated node: temp name}``: nodes a program computes once as a named temp
    #: (:func:`rigidsym.codegen.arrays.hoist_compensated`), printed as that name
    named: dict = {}

    def compensated_call(self, expr) -> str:
        """The call of the helper that evaluates the compensated node ``expr``."""
        name = self._diffprod if expr.func.__name__ == "DiffProd" else \
            self._sumprod.format(n=len(expr.args) // 2)
        return f"{name}({', '.join(self._print(a) for a in expr.args)})"

    def named_call(self, expr) -> str:
        """The right-hand side of the named temp (``named``) of the compensated node
        ``expr``: its helper's call (the JAX printer wraps it)."""
        return self.compensated_call(expr)

    def _print_DiffProd(self, expr):
        return self.named.get(expr) or self.compensated_call(expr)

    _print_SumProd = _print_DiffProd

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
        d = _dyadic(expr)
        return d if d is not None else super()._print_Rational(expr)

    def _print_Integer(self, expr):  # doubles throughout: 2 -> 2.0
        return f"{int(expr)}.0"


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
        # computed once for all its readers (JAX_KEEP_SOURCE, issue 38)
        return f"_keep({self.compensated_call(expr)})"

    # the sine and cosine of one argument share one evaluation (JAX_TRIG_SOURCE, issue 38)
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


def _torch_base():
    """sympy's ``TorchPrinter``; its module imports torch when installed only to read
    ``torch.__version__`` (which printing never uses), seconds on a small machine: the
    generator blocks that import while it loads the printer, so generation stays cheap."""
    import sys

    if "sympy.printing.pytorch" in sys.modules or "torch" in sys.modules:
        from sympy.printing.pytorch import TorchPrinter
        return TorchPrinter
    sys.modules["torch"] = None  # type: ignore[assignment]  # import torch -> ImportError
    try:
        from sympy.printing.pytorch import TorchPrinter
    finally:
        del sys.modules["torch"]
    return TorchPrinter


_TORCH_PRINTER: list = []


def torch_printer():
    """A PyTorch printer for kernel programs: sympy's ``TorchPrinter`` extended with the
    kernel printers' visitors (products for small powers, ``torch.sqrt``, float literals,
    ``torch.where`` for ``Piecewise``); built on first use (see :func:`_torch_base`)."""
    if not _TORCH_PRINTER:
        base = _torch_base()

        class KernelTorchPrinter(_PowMixin, base):
            _one = "1.0"

            def __init__(self, settings=None):
                super().__init__({"torch_version": "2", **(settings or {})})

            def _sqrt(self, arg: str) -> str:
                return f"{self._module_format('torch.sqrt')}({arg})"

            def _print_Rational(self, expr):
                d = _dyadic(expr)
                return d if d is not None else f"({int(expr.p)}.0/{int(expr.q)}.0)"

            def _print_Integer(self, expr):
                return f"{int(expr)}.0"

            def _print_Piecewise(self, expr):
                *head, (last, cond) = expr.args
                if cond is not sp.true:
                    raise ValueError("Piecewise without a default branch")
                text = self._print(last)
                for e, c in reversed(head):
                    text = f"{self._module_format('torch.where')}({self._print(c)}, " \
                           f"{self._print(e)}, {text})"
                return text

        _TORCH_PRINTER.append(KernelTorchPrinter)
    return _TORCH_PRINTER[0]()


def numpy_code(expr) -> str:
    """Print ``expr`` as a NumPy expression."""
    return KernelNumPyPrinter().doprint(expr)


def c_code(expr) -> str:
    """Print ``expr`` as a C99 expression on doubles."""
    return KernelCPrinter().doprint(expr)

