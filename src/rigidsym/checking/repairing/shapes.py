"""The structure of a printed form's tree as the edit generator sees it: which children are
editable, positions (paths of child indices), and shapes (``None`` for a scalar,
``(rows, cols)`` for a matrix) of trees rebuilt raw, where sympy checked nothing.

A node's shape depends only on its children's shapes: the repair search's pruning of pairs
(:mod:`rigidsym.checking.repairing.candidates`) rests on it.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.matrices.expressions.slice import MatrixSlice

from rigidsym.algebra.operators import Cpm, Cross, Det, Diff, Vect
from rigidsym.algebra.rigid_motions import LieOp

__all__ = ["ShapeError", "RawBlocks", "is_matrix", "children", "node_at", "positions", "shape"]


class ShapeError(ValueError):
    """An edited tree whose shapes do not fit (a 3x1 times a 3x1, a sum of a scalar and a
    matrix): not a candidate at all."""


class RawBlocks(sp.MatrixExpr):
    """A block matrix rebuilt raw (sympy's ``BlockMatrix`` constructor costs a millisecond):
    ``args`` are the grid's rows and columns, then the blocks row by row. Never shown: a
    canonical rebuild makes a ``BlockMatrix`` of it."""

    def __new__(cls, rows, cols, *blocks):
        return sp.Basic.__new__(cls, sp.Integer(rows), sp.Integer(cols), *blocks)

    @property
    def grid(self) -> list[list]:
        """The blocks as rows of a grid."""
        r, c = int(self.args[0]), int(self.args[1])
        b = self.args[2:]
        return [list(b[i * c:(i + 1) * c]) for i in range(r)]

    @property
    def shape(self):
        g = self.grid
        return (sum(row[0].shape[0] for row in g), sum(x.shape[1] for x in g[0]))


def is_matrix(x) -> bool:
    """Whether ``x`` is matrix-valued (a matrix expression or an explicit matrix)."""
    return isinstance(x, sp.MatrixExpr | sp.MatrixBase)


# --------------------------------------------------------------------------- structure
_OPAQUE = (sp.MatrixSymbol, sp.MatrixBase, sp.Identity, sp.ZeroMatrix, AppliedUndef,
           sp.Derivative)
_ALL_ARGS = (sp.Add, sp.Mul, sp.MatAdd, sp.MatMul, sp.Transpose, sp.Inverse, sp.Trace,
             sp.Determinant, sp.Abs, Cross, Det, Cpm, Vect, sp.sin, sp.cos, sp.tan, sp.cot)


def _children_rule(cls) -> int:
    """0: no editable children; 1: the first argument only; 2: every argument; 3: blocks."""
    if issubclass(cls, _OPAQUE) or getattr(cls, "is_Atom", False):
        return 0
    if issubclass(cls, sp.BlockMatrix):
        return 3
    if issubclass(cls, RawBlocks):
        return 4
    if issubclass(cls, sp.Pow | sp.MatPow | MatrixElement | MatrixSlice | Diff):
        return 1
    if issubclass(cls, LieOp):  # the operands; the order flag is no editable child
        return 5
    if issubclass(cls, _ALL_ARGS):
        return 2
    return 0


_RULES: dict = {}


def children(x) -> tuple:
    """The editable children of a node (exponents, indices and slices are not: a
    coefficient edit must not turn ``Ω²`` into ``Ω³``)."""
    cls = type(x)
    rule = _RULES.get(cls)
    if rule is None:
        rule = _RULES[cls] = _children_rule(cls)
    if rule == 2:
        return x.args
    if rule == 1:
        return x.args[:1]
    if rule == 3:
        return tuple(x.blocks)
    if rule == 4:
        return x.args[2:]
    if rule == 5:
        return x.args[:x.operands]
    return ()


def node_at(root, path: tuple):
    """The node of ``root`` at ``path``."""
    for i in path:
        root = children(root)[i]
    return root


def positions(root, path: tuple = ()) -> Iterator[tuple[tuple, object]]:
    """Every ``(path, node)`` of ``root`` in pre-order (a parent before its children)."""
    yield path, root
    for i, c in enumerate(children(root)):
        yield from positions(c, path + (i,))


# --------------------------------------------------------------------------- shapes
def shape(x, memo: dict | None = None):
    """The shape of a (raw) tree: ``None`` for a scalar, ``(rows, cols)`` for a matrix.

    Raises:
        ShapeError: when the shapes do not fit (the candidate is no candidate).
    """
    memo = {} if memo is None else memo
    hit = memo.get(x)
    if hit is not None:
        if hit is _MISFIT:
            raise ShapeError("misfit")
        return hit[0]
    try:
        s = _shape(x, memo)
    except ShapeError:
        memo[x] = _MISFIT
        raise
    memo[x] = (s,)
    return s


_MISFIT = ("misfit",)


def _shape(x, memo):
    if isinstance(x, sp.MatrixSymbol | sp.MatrixBase | sp.Identity | sp.ZeroMatrix
                  | sp.BlockMatrix | MatrixSlice):
        return (int(x.shape[0]), int(x.shape[1]))
    if not isinstance(x, sp.Basic) or x.is_Atom or isinstance(x, AppliedUndef | sp.Derivative):
        return None
    kids = [shape(k, memo) for k in children(x)]
    if isinstance(x, sp.MatAdd):
        if any(k is None for k in kids) or len(set(kids)) != 1:
            raise ShapeError("a sum of different shapes")
        return kids[0]
    if isinstance(x, sp.MatMul):
        mats = [k for k in kids if k is not None]
        for a, b in zip(mats, mats[1:], strict=False):
            if a[1] != b[0]:
                raise ShapeError(f"a {a[0]}x{a[1]} times a {b[0]}x{b[1]}")
        return (mats[0][0], mats[-1][1]) if mats else None
    if isinstance(x, sp.Transpose):
        return None if kids[0] is None else (kids[0][1], kids[0][0])
    if isinstance(x, sp.Inverse | sp.MatPow):
        if kids[0] is None or kids[0][0] != kids[0][1]:
            raise ShapeError("a power of a non-square matrix")
        return kids[0]
    if isinstance(x, sp.Trace | sp.Determinant | Det):
        if kids[0] is None or kids[0][0] != kids[0][1]:
            raise ShapeError("a trace or determinant of a non-square matrix")
        return None
    if isinstance(x, MatrixElement):
        if kids[0] is None or not (0 <= int(x.i) < kids[0][0] and 0 <= int(x.j) < kids[0][1]):
            raise ShapeError("an entry outside the matrix")
        return None
    if isinstance(x, RawBlocks):
        r, c = int(x.args[0]), int(x.args[1])
        g = [kids[i * c:(i + 1) * c] for i in range(r)]
        if any(k is None for k in kids) or \
                any(len({k[0] for k in row}) != 1 for row in g) or \
                any(len({g[i][j][1] for i in range(r)}) != 1 for j in range(c)):
            raise ShapeError("blocks that do not fit")
        return (sum(row[0][0] for row in g), sum(k[1] for k in g[0]))
    if isinstance(x, Cross | Cpm | Vect | Diff | LieOp):
        return _operator_shape(x, kids)
    if any(k is not None for k in kids):
        raise ShapeError(f"a matrix inside {type(x).__name__}")
    return None


def _operator_shape(x, kids: list):
    """The shape of a book operator (cross product, CPM, vect, a derivative, a word of
    the rigid-motion vocabulary) from its operands'."""
    if isinstance(x, Cross):
        if kids != [(3, 1), (3, 1)]:
            raise ShapeError("a cross product of non-3-vectors")
        return (3, 1)
    if isinstance(x, Cpm):  # the lazy CPM(v) and vect(A) of book symbols
        if kids != [(3, 1)]:
            raise ShapeError("a cross-product matrix of a non-3-vector")
        return (3, 3)
    if isinstance(x, Vect):
        if kids != [(3, 3)]:
            raise ShapeError("the axial vector of a non-3x3 matrix")
        return (3, 1)
    if isinstance(x, Diff):
        if kids[0] is None:
            raise ShapeError("a matrix derivative of a scalar")
        return kids[0]
    # a word of rigidsym.algebra.rigid_motions (hat, vee, transform, Ad, ad, expm)
    if any(k is None for k in kids):
        raise ShapeError(f"a scalar inside {x.label}")
    try:
        return x.shape_of(kids)
    except ValueError as exc:
        raise ShapeError(str(exc)) from None
