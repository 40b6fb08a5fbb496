"""Edited subterms marked for display: ``⟦…⟧`` in text, ``\\boxed{…}`` in LaTeX (which the
HTML report turns into ``<mrow class="rigidsym-edit">``). Marks are never decided: the zero
test sees the unmarked tree.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.repairing.shapes import is_matrix

__all__ = ["Marked", "MarkedScalar", "mark"]


# --------------------------------------------------------------------------- marks
def _negative(x) -> bool:
    if isinstance(x, sp.MatMul):
        c = sp.Mul(*[a for a in x.args if not isinstance(a, sp.MatrixExpr | sp.MatrixBase)])
        return bool(c.could_extract_minus_sign())
    return bool(x.could_extract_minus_sign())


class Marked(sp.MatrixExpr):
    """A matrix subterm marked as edited: prints ``⟦X⟧`` (text) and ``\\boxed{X}`` (LaTeX),
    a sign that can be pulled out outside the mark (``- ⟦sin φ E⟧``)."""

    def __new__(cls, arg):
        return sp.Basic.__new__(cls, arg)

    @property
    def shape(self):
        return self.args[0].shape

    def _entry(self, i, j, **kwargs):
        return self.args[0]._entry(i, j, **kwargs)

    def could_extract_minus_sign(self) -> bool:
        return _negative(self.args[0])

    def __neg__(self):
        return Marked(-self.args[0])  # as the printers negate an unmarked term

    def _sympystr(self, printer) -> str:
        return f"⟦{printer._print(self.args[0])}⟧"

    def _latex(self, printer) -> str:
        return rf"\boxed{{{printer._print(self.args[0])}}}"


class MarkedScalar(sp.Function):
    """A scalar subterm marked as edited (see :class:`Marked`)."""

    nargs = 1

    @classmethod
    def eval(cls, arg):
        return None

    def could_extract_minus_sign(self) -> bool:
        return bool(self.args[0].could_extract_minus_sign())

    def __neg__(self):
        return MarkedScalar(-self.args[0])

    def _sympystr(self, printer) -> str:
        a = self.args[0]
        if a.could_extract_minus_sign():
            return f"-⟦{printer._print(-a)}⟧"
        return f"⟦{printer._print(a)}⟧"

    def _latex(self, printer) -> str:
        a = self.args[0]
        if a.could_extract_minus_sign():
            return rf"-\boxed{{{printer._print(-a)}}}"
        return rf"\boxed{{{printer._print(a)}}}"


def mark(x):
    """``x`` wrapped as an edited subterm (for displays only; never decided)."""
    return Marked(x) if is_matrix(x) else MarkedScalar(x)
