"""Book operators and symbol constructors: the vocabulary printed forms are written in.

Book symbols are ``sympy.MatrixSymbol`` objects named as in ``NOTATION.md`` so that a
printed equation transcribes readably (``(Q - 1)^T (Q a - a')``). The operators are lazy:
they print as the book writes them and become explicit on ``doit()`` once the checker has
substituted the model: ``Cross(u, v)``, ``Det(M)`` and the block matrix ``Blocks``.
"""

from __future__ import annotations

import sympy as sp

__all__ = ["MS", "I3", "O3", "vec", "mat", "Cross", "Det", "Blocks"]

I3 = sp.Identity(3)
O3 = sp.ZeroMatrix(3, 3)


def MS(name: str, rows: int = 3, cols: int = 1) -> sp.MatrixSymbol:
    """A book matrix symbol (vector by default)."""
    return sp.MatrixSymbol(name, rows, cols)


def vec(name: str) -> sp.MatrixSymbol:
    """A book 3-vector symbol."""
    return sp.MatrixSymbol(name, 3, 1)


def mat(name: str) -> sp.MatrixSymbol:
    """A book 3 x 3 matrix symbol."""
    return sp.MatrixSymbol(name, 3, 3)


# --------------------------------------------------------------------------- book operators
class Cross(sp.MatrixExpr):
    """The book's ``u x v`` of two 3-vectors as a matrix expression.

    Prints as ``Cross(u, v)``; ``doit()`` gives the explicit cross product once both
    factors are explicit (after the checker substitutes the model).
    """

    def __new__(cls, u, v):
        return sp.Basic.__new__(cls, u, v)

    @property
    def shape(self):
        return (sp.Integer(3), sp.Integer(1))

    def _entry(self, i, j, **kwargs):
        u, v = self.args
        k, m = (i + 1) % 3, (i + 2) % 3
        return u[k, 0] * v[m, 0] - u[m, 0] * v[k, 0]

    def doit(self, **hints):
        u, v = (a.doit(**hints) if isinstance(a, sp.Basic) else a for a in self.args)
        u, v = (x.as_explicit() if isinstance(x, sp.MatrixExpr) and
                not x.atoms(sp.MatrixSymbol) else x for x in (u, v))
        if isinstance(u, sp.MatrixBase) and isinstance(v, sp.MatrixBase):
            return sp.ImmutableMatrix(sp.Matrix(u).cross(sp.Matrix(v)))
        return Cross(u, v)


class Blocks(sp.BlockMatrix):
    """A book block matrix (``[[1, O], [A - B, 1]]``) that becomes explicit on ``doit()``
    once its blocks are (sympy's ``BlockMatrix`` stays symbolic inside a product, and the
    product's ``as_explicit`` then goes through symbolic sums: slow)."""

    def doit(self, **hints):
        r = super().doit(**hints)
        if isinstance(r, sp.BlockMatrix) and not r.atoms(sp.MatrixSymbol):
            return sp.ImmutableMatrix(r.as_explicit())
        return r


class Det(sp.Function):
    """The book's ``det(M)`` of a square matrix expression.

    Prints as ``Det(M)``; ``doit()`` substitutes the entries of an explicit ``M`` into the
    cofactor expansion of a generic 3 x 3 (no expansion, no cancellation: shared subtrees
    stay shared), where sympy's ``Determinant`` expands (slow) or stays unevaluated.
    """

    @classmethod
    def eval(cls, M):
        return None

    def doit(self, **hints):
        M = self.args[0]
        M = M.doit(**hints) if isinstance(M, sp.Basic) else M
        if isinstance(M, sp.MatrixExpr) and not M.atoms(sp.MatrixSymbol):
            M = M.as_explicit()
        if not isinstance(M, sp.MatrixBase):
            return Det(M)
        n = M.rows
        if n > 3:  # larger ones here are sparse (block triangular): sympy's det is fast
            return M.det()
        g = sp.Matrix(n, n, [sp.Dummy() for _ in range(n * n)])
        return g.det(method="berkowitz").xreplace(dict(zip(g, M, strict=True)))

    def _sympystr(self, printer):
        return f"Det({printer.doprint(self.args[0])})"
