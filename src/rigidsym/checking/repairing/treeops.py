"""The three ways to rebuild a printed form's tree after an edit (raw, canonical, marked),
on the structure of :mod:`rigidsym.checking.repairing.shapes` and the marks of
:mod:`rigidsym.checking.repairing.marks`.

A printed member is a sympy tree over book symbols (``mat("Q")``, ``vec("e")``,
``MatAdd``/``MatMul``/``Add``/``Mul``, ``Transpose``, ``sin``…), before the model is
substituted. An edit replaces the nodes at some *positions* (``(side, path)``: side 0 is the
left side, 1 the right; ``path`` the child indices from the side's root, as
:func:`children` numbers them).

- **raw** rebuilds (:func:`apply`) skip sympy's canonicalisation (``Basic.__new__``): about
  1 µs a node instead of 100 µs, and the tree keeps the shape the edit gave it, which the
  fast evaluator of :mod:`rigidsym.checking.repairing.repair` memoises on. They are never shown.
- **canonical** rebuilds (:func:`canonical`) run sympy's constructors on the new nodes only
  (unchanged subtrees are reused as they are): the form that is decided and compared.
- **marked** rebuilds wrap the edited subterm in :class:`Marked` (a matrix) or
  :class:`MarkedScalar`, which print as ``⟦…⟧`` in text and ``\\boxed{…}`` in LaTeX.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy as sp
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.matrices.expressions.slice import MatrixSlice

from rigidsym.algebra.operators import Diff
from rigidsym.algebra.rigid_motions import LieOp
from rigidsym.checking.repairing.marks import Marked, MarkedScalar, mark
from rigidsym.checking.repairing.shapes import (
    RawBlocks,
    ShapeError,
    children,
    is_matrix,
    node_at,
    positions,
    shape,
)

# the structure and the marks live in their own modules; the generator reads them here
__all__ = ["Marked", "MarkedScalar", "mark", "children", "positions", "shape", "is_matrix",
           "apply", "canonical", "node_ids", "sides", "replace_at", "RawBlocks", "ShapeError",
           "DROP", "add", "mul", "neg", "node_at"]

#: what a change returns to remove the node from its sum (drop a term)
DROP = sp.Symbol("__rigidsym_drop__")


def sides(rel) -> tuple:
    """``(lhs, rhs)`` of a relation as sympy trees (explicit matrices made immutable, so
    that every node is hashable)."""
    out = []
    for x in (rel.lhs, rel.rhs):
        x = sp.sympify(x)
        out.append(sp.ImmutableMatrix(x) if isinstance(x, sp.MatrixBase) else x)
    return tuple(out)


def _rebuild_raw(x, kids: list):
    try:
        return _rebuild_raw_unchecked(x, kids)
    except (ValueError, TypeError, IndexError) as exc:  # sympy's ShapeError is a ValueError
        raise ShapeError(str(exc)) from exc


_RAW_UNARY = (sp.Transpose, sp.Inverse, sp.Trace, sp.Determinant, sp.MatPow, sp.Pow,
              MatrixElement, MatrixSlice)


def _rebuild_raw_unchecked(x, kids: list):
    if isinstance(x, sp.MatAdd | sp.MatMul):  # before Add/Mul, which they subclass
        return sp.Basic.__new__(x.func, *kids)
    if isinstance(x, sp.Add | sp.Mul):
        return x.func._from_args(kids, True)  # scalars commute: skip the assumption query
    if isinstance(x, _RAW_UNARY):  # the first argument replaced; shapes are checked by shape()
        return sp.Basic.__new__(x.func, kids[0], *x.args[1:])
    if isinstance(x, sp.BlockMatrix):
        return RawBlocks(*x.blocks.shape, *kids)
    if isinstance(x, RawBlocks):
        return RawBlocks(x.args[0], x.args[1], *kids)
    return _rebuild_with(x, kids, raw=True)


def _rebuild_with(x, kids: list, raw: bool):
    if isinstance(x, sp.BlockMatrix | RawBlocks):
        rows, cols = x.blocks.shape if isinstance(x, sp.BlockMatrix) else \
            (int(x.args[0]), int(x.args[1]))
        cls = type(x) if isinstance(x, sp.BlockMatrix) else sp.BlockMatrix
        try:
            return cls([[kids[i * cols + j] for j in range(cols)] for i in range(rows)])
        except (ValueError, TypeError) as exc:
            raise ShapeError(str(exc)) from exc
    if isinstance(x, sp.Pow):
        return sp.Pow(kids[0], x.exp)
    if isinstance(x, sp.MatPow):
        return sp.MatPow(kids[0], x.exp)
    if isinstance(x, MatrixElement):
        return kids[0][x.i, x.j]
    if isinstance(x, MatrixSlice):
        return sp.Basic.__new__(MatrixSlice, kids[0], *x.args[1:])
    if isinstance(x, sp.Transpose):
        return kids[0].arg if isinstance(kids[0], sp.Transpose) else sp.Transpose(kids[0])
    if isinstance(x, LieOp | Diff):  # operands edited; the order flag or variable kept
        return x.func(*kids, *x.args[len(kids):])
    return x.func(*kids)


def _rebuild_canonical(x, kids: list):
    if isinstance(x, sp.MatMul):  # before Mul: sympy's MatMul subclasses Mul
        return _matmul(kids)
    if isinstance(x, sp.MatAdd):
        return _matadd(kids)
    if isinstance(x, sp.Add | sp.Mul):
        return x.func(*kids)
    return _rebuild_with(x, kids, raw=False)


def _matmul(kids: list):
    """A product as the book writes it: nested products flattened, the scalars gathered in
    front (``-1 (-sin φ E)`` is ``sin φ E``). No ``doit``: it would expand a dot product
    written as ``Trace(eᵀ ω)`` into its components."""
    scal, mats = [], []
    for k in kids:
        for a in (k.args if isinstance(k, sp.MatMul) else (k,)):
            (mats if is_matrix(a) else scal).append(a)
    c = sp.Mul(*scal)
    if not mats:
        return c
    if c == 0:
        return sp.ZeroMatrix(mats[0].shape[0], mats[-1].shape[1])
    if c == 1:
        return mats[0] if len(mats) == 1 else sp.MatMul(*mats)
    return sp.MatMul(c, *mats)


def _matadd(kids: list):
    """A sum with nested sums flattened and zero matrices dropped (like terms are not
    combined: the display shows what the edit wrote)."""
    terms = [a for k in kids for a in (k.args if isinstance(k, sp.MatAdd) else (k,))
             if not isinstance(a, sp.ZeroMatrix)]
    if not terms:
        return sp.ZeroMatrix(*kids[0].shape)
    if not any(is_matrix(t) for t in terms):
        return sp.Add(*terms)
    return terms[0] if len(terms) == 1 else sp.MatAdd(*terms)


# --------------------------------------------------------------------------- builders
def add(x, term):
    """``x + term`` (raw): a term appended to a sum, or a new sum of the two."""
    if isinstance(x, sp.MatAdd | sp.Add):
        return _rebuild_raw(x, [*x.args, term])  # (MatAdd first inside _rebuild_raw)
    if is_matrix(x):
        return sp.Basic.__new__(sp.MatAdd, x, term)
    return sp.Add._from_args((x, term), True)


def mul(left, right):
    """``left right`` (raw): a matrix product when either is a matrix."""
    if is_matrix(left) or is_matrix(right):
        return sp.Basic.__new__(sp.MatMul, left, right)
    return sp.Mul._from_args((left, right), True)


def neg(x):
    """``-x`` (raw)."""
    return mul(sp.S.NegativeOne, x)


# --------------------------------------------------------------------------- apply
Fn = Callable  # (node, mark) -> node or DROP


def _trie(changes) -> dict:
    root: dict = {}
    for path, fn in changes:
        t = root
        for i in path:
            t = t.setdefault(i, {})
        t.setdefault(None, []).append(fn)
    return root


def _zero_like(x):
    if is_matrix(x):
        return sp.ZeroMatrix(*x.shape)
    return sp.S.Zero


def _apply(node, trie: dict, marker):
    kid_edits = {k: v for k, v in trie.items() if k is not None}
    if kid_edits:
        kids = list(children(node))
        for i, sub in kid_edits.items():
            kids[i] = _apply(kids[i], sub, marker)
        if any(k is DROP for k in kids):
            if not isinstance(node, sp.Add | sp.MatAdd):
                raise ShapeError("only a term of a sum can be dropped")
            kids = [k for k in kids if k is not DROP]
            node = kids[0] if len(kids) == 1 else (_rebuild_raw(node, kids) if kids
                                                    else _zero_like(node))
        else:
            node = _rebuild_raw(node, kids)
    for fn in trie.get(None, ()):
        node = fn(node, marker)
    return node


def _identity(x):
    return x


def replace_at(root, path: tuple, new):
    """``root`` with the node at ``path`` replaced by ``new`` (raw rebuilds of the
    ancestors; :data:`DROP` removes a term from its sum).

    Raises:
        ShapeError: when a rebuilt node does not fit.
    """
    chain = [root]
    for i in path[:-1]:
        chain.append(children(chain[-1])[i])
    for node, i in zip(reversed(chain), reversed(path), strict=True):
        kids = list(children(node))
        kids[i] = new
        if new is DROP:
            if not isinstance(node, sp.Add | sp.MatAdd):
                raise ShapeError("only a term of a sum can be dropped")
            del kids[i]
            new = kids[0] if len(kids) == 1 else (_rebuild_raw(node, kids) if kids
                                                   else _zero_like(node))
        else:
            new = _rebuild_raw(node, kids)
    return new


def apply(root, changes, marked: bool = False):
    """Apply ``changes`` (``[(path, fn)]`` on one side) to ``root`` with raw rebuilds.

    Each ``fn(node, mark)`` returns the new node (or :data:`DROP` for a term to drop); it
    is applied after the changes below it, so edits nested in one another compose.

    Raises:
        ShapeError: when a rebuilt block matrix does not fit.
    """
    if not changes:
        return root
    return _apply(root, _trie(changes), mark if marked else _identity)


def canonical(root, changes, keep: set, marked: bool = False):
    """Apply ``changes`` and canonicalise every node that is not an original one (sympy's
    constructors); with ``marked`` the subterms the changes name are wrapped in
    :class:`Marked`.

    Args:
        root: the side's tree.
        changes: ``[(path, fn)]``.
        keep: ``id``s of the nodes to reuse as they are (those of the statement's trees,
            from :func:`node_ids`).
        marked: wrap the edited subterms for display.

    Raises:
        ShapeError: when the shapes do not fit.
    """
    if not changes:
        return root
    raw = _apply(root, _trie(changes), mark if marked else _identity)
    return _canon(raw, keep)


def node_ids(*roots) -> set:
    """``id`` of every node of ``roots`` (the nodes :func:`canonical` leaves alone)."""
    out: set = set()
    for r in roots:
        for _, x in positions(r):
            out.add(id(x))
    return out


def _canon(x, keep: set):
    if id(x) in keep:
        return x
    if isinstance(x, Marked | MarkedScalar):
        return type(x)(_canon(x.args[0], keep))
    kids = [_canon(k, keep) for k in children(x)]
    if not kids:
        return x
    try:
        return _rebuild_canonical(x, kids)
    except (ValueError, TypeError, IndexError) as exc:
        raise ShapeError(str(exc)) from exc
