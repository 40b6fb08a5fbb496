"""The PyTorch printer of kernel programs: sympy's ``TorchPrinter`` with the kernel printers'
visitors, floats only (``2.0``: a float32 tensor stays float32), ``torch.where`` for
``Piecewise``.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.backends.printing import KernelPrinterMixin, dyadic_repr

__all__ = ["torch_printer"]


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

        class KernelTorchPrinter(KernelPrinterMixin, base):
            _one = "1.0"

            def __init__(self, settings=None):
                super().__init__({"torch_version": "2", **(settings or {})})

            def _sqrt(self, arg: str) -> str:
                return f"{self._module_format('torch.sqrt')}({arg})"

            def _print_Rational(self, expr):
                d = dyadic_repr(expr)
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
