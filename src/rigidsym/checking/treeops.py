"""The printed form's expression tree as the edit generator sees it: children, positions,
shapes, and the three ways to rebuild a tree after an edit (raw, canonical, marked).

A printed member is a sympy tree over book symbols (``mat("Q")``, ``vec("e")``,
``MatAdd``/``MatMul``/``Add``/``Mul``, ``Transpose``, ``sin``…), before the model is
substituted. An edit replaces the nodes at some *positions* (``(side, path)``: side 0 is the
left side, 1 the right; ``path`` the child indices from the side's root, as
:func:`children` numbers them).

- **raw** rebuilds (:func:`apply`) skip sympy's canonicalisation (``Basic.__new__``): about
  1 µs a node instead of 100 µs, and the tree keeps the shape the edit gave it, which the
  fast evaluator of :mod:`rigidsym.checking.repair` memoises on. They are never shown.
- **canonical** rebuilds (:func:`canonical`) run sympy's constructors on the new nodes only
  (unchanged subtrees are reused as they are): the form that is decided and compared.
- **marked** rebuilds wrap the edited subterm in :class:`Marked` (a matrix) or
  :class:`MarkedScalar`, which print as ``⟦…⟧`` in text and ``\\boxed{…}`` in LaTeX.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.matrices.expressions.slice import MatrixSlice

from rigidsym.algebra.operators import Cross, Det

__all__ = ["Marked", "MarkedScalar", "mark", "children", "positions", "shape", "is_matrix",
           "apply", "canonical", "node_ids", "sides", "replace_at", "RawBlocks", "ShapeError",
           "DROP", "add", "mul", "neg", "node_at"]

#: what a change returns to remove the node from its sum (drop a term)
DROP = sp.Symbol("__rigidsym_drop__")


class ShapeError(ValueError):
    """An edited tree whose shapes do not fit (a 3x1 times a 3x1, a sum of a scalar and a
    matrix): not a candidate at all."""


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


def sides(rel) -> tuple:
    """``(lhs, rhs)`` of a relation as sympy trees (explicit matrices made immutable, so
    that every node is hashable)."""
    out = []
    for x in (rel.lhs, rel.rhs):
        x = sp.sympify(x)
        out.append(sp.ImmutableMatrix(x) if isinstance(x, sp.MatrixBase) else x)
    return tuple(out)


def is_matrix(x) -> bool:
    """Whether ``x`` is matrix-valued (a matrix expression or an explicit matrix)."""
    return isinstance(x, sp.MatrixExpr | sp.MatrixBase)


def mark(x):
    """``x`` wrapped as an edited subterm (for displays only; never decided)."""
    return Marked(x) if is_matrix(x) else MarkedScalar(x)


# --------------------------------------------------------------------------- structure
_OPAQUE = (sp.MatrixSymbol, sp.MatrixBase, sp.Identity, sp.ZeroMatrix, AppliedUndef,
           sp.Derivative)
_ALL_ARGS = (sp.Add, sp.Mul, sp.MatAdd, sp.MatMul, sp.Transpose, sp.Inverse, sp.Trace,
             sp.Determinant, sp.Abs, Cross, Det, sp.sin, sp.cos, sp.tan, sp.cot)


def _children_rule(cls) -> int:
    """0: no editable children; 1: the first argument only; 2: every argument; 3: blocks."""
    if issubclass(cls, _OPAQUE) or getattr(cls, "is_Atom", False):
        return 0
    if issubclass(cls, sp.BlockMatrix):
        return 3
    if issubclass(cls, RawBlocks):
        return 4
    if issubclass(cls, sp.Pow | sp.MatPow | MatrixElement | MatrixSlice):
        return 1
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
    if isinstance(x, Cross):
        if kids != [(3, 1), (3, 1)]:
            raise ShapeError("a cross product of non-3-vectors")
        return (3, 1)
    if any(k is not None for k in kids):
        raise ShapeError(f"a matrix inside {type(x).__name__}")
    return None
