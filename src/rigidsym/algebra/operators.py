"""Book operators and symbol constructors: the vocabulary printed forms are written in.

Book symbols are ``sympy.MatrixSymbol`` objects named as in ``NOTATION.md`` so that a
printed equation transcribes readably (``(Q - 1)^T (Q a - a')``). The operators are lazy:
they print as the book writes them and become explicit on ``doit()`` once the checker has
substituted the model: ``Cross(u, v)``, ``Det(M)``, the block matrix ``Blocks``, and
``Cpm(v)``/``Vect(A)`` (what :func:`rigidsym.algebra.primitives.cpm` and ``vect`` return
for a book symbol, so that a printed form reads ``CPM(ω)``, not its nine entries).
"""

from __future__ import annotations

import sympy as sp

__all__ = ["MS", "I3", "O3", "vec", "mat", "Cross", "Det", "Blocks", "Cpm", "Vect", "Diff",
           "DiffEntry", "is_symbolic"]

#: The book's 3 x 3 identity ``1`` as a matrix expression (``sympy.Identity(3)``).
I3 = sp.Identity(3)
#: The book's 3 x 3 zero matrix ``O`` as a matrix expression (``sympy.ZeroMatrix(3, 3)``).
O3 = sp.ZeroMatrix(3, 3)


def MS(name: str, rows: int = 3, cols: int = 1) -> sp.MatrixSymbol:
    """A book matrix symbol (vector by default).

    Args:
        name: the book name, as printed.
        rows: number of rows.
        cols: number of columns.

    Returns:
        A ``sympy.MatrixSymbol`` (a symbol until the model gives it a value).
    """
    return sp.MatrixSymbol(name, rows, cols)


def vec(name: str) -> sp.MatrixSymbol:
    """A book 3-vector symbol.

    Args:
        name: the book name, as printed (``"a_prime"`` prints as ``a'``).

    Returns:
        A 3 x 1 ``sympy.MatrixSymbol``.
    """
    return sp.MatrixSymbol(name, 3, 1)


def mat(name: str) -> sp.MatrixSymbol:
    """A book 3 x 3 matrix symbol.

    Args:
        name: the book name, as printed.

    Returns:
        A 3 x 3 ``sympy.MatrixSymbol``.
    """
    return sp.MatrixSymbol(name, 3, 3)


# --------------------------------------------------------------------------- book operators
class Cross(sp.MatrixExpr):
    """The book's ``u x v`` of two 3-vectors as a matrix expression.

    Prints as ``Cross(u, v)``; ``doit()`` gives the explicit cross product once both
    factors are explicit (after the checker substitutes the model).

    Args:
        u: the first factor, a 3 x 1 matrix expression (or explicit matrix).
        v: the second factor, likewise.
    """

    def __new__(cls, u, v):
        return sp.Basic.__new__(cls, sp.sympify(u), sp.sympify(v))

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
    product's ``as_explicit`` then goes through symbolic sums: slow).

    Args:
        rows: a list of rows of matrix expressions whose shapes fit, as for
            ``sympy.BlockMatrix``.
    """

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

    Args:
        M: a square matrix expression (or explicit matrix).
    """

    @classmethod
    def eval(cls, M):
        return None

    def _eval_is_commutative(self):
        return True  # a scalar, though its argument is a matrix: det(M) M is a scaling

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


def is_symbolic(x) -> bool:
    """Whether ``x`` is a matrix expression of book symbols (not an explicit matrix): the
    operators then stay lazy and print as the book writes them."""
    return isinstance(x, sp.MatrixExpr) and not isinstance(x, sp.MatrixBase) and \
        bool(x.atoms(sp.MatrixSymbol))


def explicit(a, **hints):
    """The explicit form of ``a``: sympy's ``doit`` of an expression (with ``hints``), and an
    explicit matrix for a matrix expression that no longer holds a matrix symbol; anything
    else as it is."""
    a = a.doit(**hints) if isinstance(a, sp.Basic) else a
    if isinstance(a, sp.MatrixExpr) and not a.atoms(sp.MatrixSymbol):
        a = a.as_explicit()
    return a


class Cpm(sp.MatrixExpr):
    """The book's ``CPM(v)``, the cross-product matrix of a 3-vector expression ``v``
    (Eq. (2.38)), kept lazy: prints ``CPM(v)``; ``doit()`` gives the explicit
    skew-symmetric matrix once ``v`` is explicit."""

    def __new__(cls, v):  # sympified: a mutable Matrix argument is unhashable
        return sp.Basic.__new__(cls, sp.sympify(v))

    @property
    def shape(self):
        return (sp.Integer(3), sp.Integer(3))

    def _entry(self, i, j, **kwargs):
        v = self.args[0]
        return sp.Matrix([[0, -v[2, 0], v[1, 0]], [v[2, 0], 0, -v[0, 0]],
                          [-v[1, 0], v[0, 0], 0]])[i, j]

    def doit(self, **hints):
        v = explicit(self.args[0], **hints)
        if isinstance(v, sp.MatrixBase):
            return sp.ImmutableMatrix(3, 3, lambda i, j: Cpm(v)._entry(i, j))
        return Cpm(v)

    def _sympystr(self, printer):
        return f"CPM({printer._print(self.args[0])})"

    def _latex(self, printer):
        return rf"\mathrm{{CPM}}\left({printer._print(self.args[0])}\right)"


class Vect(sp.MatrixExpr):
    """The book's ``vect(A)``, the axial vector of a 3 x 3 matrix expression (Sect. 2.3.3),
    kept lazy: prints ``vect(A)``; ``doit()`` gives ``1/2 [a32 - a23, a13 - a31, a21 -
    a12]`` once ``A`` is explicit."""

    def __new__(cls, A):
        return sp.Basic.__new__(cls, sp.sympify(A))

    @property
    def shape(self):
        return (sp.Integer(3), sp.Integer(1))

    def _entry(self, i, j, **kwargs):
        A = self.args[0]
        k, m = (int(i) + 1) % 3, (int(i) + 2) % 3
        return sp.Rational(1, 2) * (A[m, k] - A[k, m])

    def doit(self, **hints):
        A = explicit(self.args[0], **hints)
        if isinstance(A, sp.MatrixBase):
            return sp.ImmutableMatrix(3, 1, lambda i, j: Vect(A)._entry(i, j))
        return Vect(A)

    def _sympystr(self, printer):
        return f"vect({printer._print(self.args[0])})"

    def _latex(self, printer):
        return rf"\mathrm{{vect}}\left({printer._print(self.args[0])}\right)"


class Diff(sp.MatrixExpr):
    """The derivative ``dX/dv`` of a matrix expression ``X`` (a book symbol with a model, an
    operator of them) with respect to a scalar ``v``, kept lazy: prints ``dX/dv``;
    ``doit()`` differentiates entry by entry once ``X`` is explicit. The book's dot accents
    (``Q_dot``) are its special case ``v = t``. sympy's own ``Derivative`` of a matrix
    symbol is a scalar to sympy (it has no shape, and a product with it fails).

    Args:
        X: a matrix expression (or explicit matrix).
        v: the variable, a real symbol (an angle, :data:`TIME`, a scalar).
    """

    def __new__(cls, X, v):
        return sp.Basic.__new__(cls, sp.sympify(X), sp.sympify(v))

    @property
    def shape(self):
        return self.args[0].shape

    def _entry(self, i, j, **kwargs):
        # lazy: the entry of a book symbol does not depend on v until the model is
        # substituted (sympy's diff, and even its unevaluated Derivative, call it 0)
        return DiffEntry(self.args[0], self.args[1], i, j)

    def doit(self, **hints):
        X = explicit(self.args[0], **hints)
        if isinstance(X, sp.MatrixBase):
            return sp.ImmutableMatrix(X).diff(self.args[1])
        return Diff(X, self.args[1])

    def _sympystr(self, printer):
        return f"d{printer._print(self.args[0])}/d{printer._print(self.args[1])}"

    def _latex(self, printer):
        return (rf"\frac{{\mathrm{{d}} {printer._print(self.args[0])}}}"
                rf"{{\mathrm{{d}} {printer._print(self.args[1])}}}")


class DiffEntry(sp.Function):
    """The entry ``(i, j)`` of :class:`Diff` ``(X, v)``, lazy until ``X`` is explicit."""

    nargs = 4
    is_real = True

    @classmethod
    def eval(cls, X, v, i, j):
        if isinstance(X, sp.MatrixBase):
            return sp.diff(X[int(i), int(j)], v)
        return None

    def doit(self, **hints):
        X = explicit(self.args[0], **hints)
        return DiffEntry(X, *self.args[1:]) if isinstance(X, sp.MatrixBase) else self

    def _sympystr(self, printer):
        X, v, i, j = self.args
        return f"(d{printer._print(X)}/d{printer._print(v)})[{i}, {j}]"
