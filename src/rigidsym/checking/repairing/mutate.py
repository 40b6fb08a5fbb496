"""One generator of small edits of a printed form, for two users:

- the **mutation test** of the zero test ("Soundness stays first"): a verified
  member with a term's sign flipped, a constant changed, a transpose dropped, ``sin ↔ cos``
  swapped or a term dropped must be decided does-not-hold whenever it is non-zero;
- the **repair search** (:mod:`rigidsym.checking.repairing.repair`): the smallest
  edit that makes a failing member hold.

The vocabulary, in the order repairs are reported (:data:`KINDS`):

============== ==============================================================================
flip-sign      flip the sign of one term of a sum (a side or a block counts as a one-term sum)
drop-term      drop one term of a sum
insert-term    insert, with either sign, a term that occurs elsewhere in the statement
scale-term     multiply one term by 2, 1/2 or -1
coefficient    replace a numeric coefficient by 1, 2, 1/2, 3, 4 or itself ± 1, same sign
transpose      transpose one occurrence of a matrix symbol
drop-transpose drop one transpose
transpose-every transpose every occurrence of one matrix symbol
swap-factors   swap two adjacent factors of a matrix product
reverse-product reverse a matrix product of three or more factors
sin-cos        ``sin ↔ cos`` of one occurrence
one-minus      ``cos θ ↔ 1 - cos θ`` (or ``sin``) of one occurrence (Rodrigues' versine)
replace-symbol replace one occurrence of a symbol by another of the same shape that occurs
               in the statement or is a key of its model (``N`` for ``Ñ``, ``θ`` for ``φ``)
replace-every  the same for every occurrence of the symbol
multiply-factor multiply one term by a factor that occurs elsewhere in the statement, on the
               left or (for matrices) on the right
============== ==============================================================================

The tree is the book-symbol tree of a member, before the model is substituted (see
:mod:`rigidsym.checking.repairing.treeops`). The search never looks at the declared corrected form:
its pools of terms, factors and symbols come from the printed members, the claims and the
model's keys.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.rigid_motions import LieOp
from rigidsym.algebra.symbols import TIME, constraint_of
from rigidsym.checking.repairing import treeops as T
from rigidsym.checking.repairing.edit_words import describe

__all__ = ["KINDS", "MUTATION_KINDS", "VOCABULARY_VERSION", "Edit", "Pools", "pools",
           "single_edits", "compatible", "apply_edits", "describe", "mutants"]

#: bumped whenever the vocabulary or its order changes (it joins the verdict cache's key)
VOCABULARY_VERSION = 3  # 2: a reader's order; 3: one-minus
KINDS = ("flip-sign", "drop-term", "insert-term", "scale-term", "coefficient", "transpose",
         "drop-transpose", "transpose-every", "swap-factors", "reverse-product", "sin-cos",
         "one-minus", "replace-symbol", "replace-every", "multiply-factor")
#: the kinds of the mutation test
MUTATION_KINDS = ("flip-sign", "coefficient", "drop-transpose", "sin-cos", "drop-term")
_RANK = {k: i for i, k in enumerate(KINDS)}
_SCALES = (sp.Integer(2), sp.Rational(1, 2), sp.S.NegativeOne)
_SMALL = (sp.Integer(1), sp.Integer(2), sp.Rational(1, 2), sp.Integer(3), sp.Integer(4))


@dataclass(frozen=True)
class Change:
    """One node replaced: ``fn(node, mark)`` gives the new node (``mark`` wraps the part a
    display highlights); ``printed_mark`` says whether the display of the printed form
    highlights the node that was there."""

    side: int
    path: tuple
    fn: object = field(compare=False)
    printed_mark: bool = True
    drop: bool = False


@dataclass(frozen=True)
class Edit:
    """One edit: kind, changed nodes, description (``what``, printed by :func:`describe`)."""

    kind: str
    changes: tuple
    what: tuple = field(compare=False)

    @property
    def order(self) -> tuple:
        """Sort key: the kind's rank in :data:`KINDS`, then the position in the tree, the
        right side first (the formula; the left usually names what it gives: ``Eᵀ = -E``
        rather than ``-Eᵀ = E``), pre-order within a side."""
        return (_RANK[self.kind], tuple((1 - c.side, c.path) for c in self.changes))


@dataclass
class Pools:
    """What edits may bring in from elsewhere in the statement (never from its corrected
    form): terms, factors and symbols by shape, in a deterministic order."""

    terms: list
    factors: list
    symbols: dict
    keep: set


# --------------------------------------------------------------------------- pools
def _sorted_unique(items) -> list:
    seen, out = set(), []
    for x in sorted(items, key=sp.default_sort_key):
        if x not in seen:
            seen.add(x)
            out.append(x)
    return out


def _shape(x):
    try:
        return T.shape(x)
    except T.ShapeError:
        return "bad"


def _is_scalar_atom(x) -> bool:
    return (isinstance(x, sp.Symbol | AppliedUndef | sp.Derivative) and x != TIME
            and x is not T.DROP)


def _term_paths(root) -> list[tuple]:
    """Paths of the terms of ``root``: children of sums, blocks of block matrices, the
    operands of a rigid-motion word (``transform(R, p)``'s ``p``), and the root itself when
    it is not a sum."""
    out = [] if isinstance(root, sp.Add | sp.MatAdd) else [()]
    for path, x in T.positions(root):
        if isinstance(x, sp.Add | sp.MatAdd | sp.BlockMatrix | LieOp):
            out += [path + (i,) for i in range(len(T.children(x)))]
    return sorted(set(out))


def pools(rels, model: dict) -> Pools:
    """Pools of terms, factors and symbols from ``rels`` (the printed members and claims)
    and the keys of ``model``."""
    sides = [s for r in rels for s in T.sides(r)]
    terms, factors, atoms = [], [], []
    for root in sides:
        terms += [T.node_at(root, p) for p in _term_paths(root)]
        for _, x in T.positions(root):
            if isinstance(x, sp.Mul | sp.MatMul):
                factors += [a for a in x.args if not a.is_Number]
            if isinstance(x, sp.Pow) and x.exp.is_Integer and x.exp < 0:
                factors.append(x.base)
            if isinstance(x, sp.MatrixSymbol) or _is_scalar_atom(x):
                atoms.append(x)
    atoms += [k for k in model if isinstance(k, sp.MatrixSymbol) or _is_scalar_atom(k)]
    symbols: dict = {}
    for a in _sorted_unique(atoms):
        symbols.setdefault(_shape(a), []).append(a)
    factors += [a for a in atoms if not isinstance(a, sp.Derivative)]
    return Pools(terms=[t for t in _sorted_unique(terms) if _shape(t) != "bad"],
                 factors=[f for f in _sorted_unique(factors) if _shape(f) != "bad"],
                 symbols=symbols, keep=T.node_ids(*sides))


# --------------------------------------------------------------------------- edits
def _edit(kind, side, path, fn, what, printed_mark=True, drop=False) -> Edit:
    return Edit(kind, (Change(side, path, fn, printed_mark, drop),), what)


def _sum_edits(side, root, pl: Pools, kinds) -> list[Edit]:
    out = []
    for p in _term_paths(root):
        t = T.node_at(root, p)
        if "flip-sign" in kinds:
            out.append(_edit("flip-sign", side, p, lambda x, m: m(T.neg(x)), ("flip", t)))
        if "drop-term" in kinds and p and isinstance(T.node_at(root, p[:-1]),
                                                     sp.Add | sp.MatAdd):
            out.append(_edit("drop-term", side, p, lambda x, m: T.DROP, ("drop", t),
                             drop=True))
        if "scale-term" in kinds:
            out += [_edit("scale-term", side, p, lambda x, m, k=k: T.mul(m(k), x),
                          ("scale", t, k)) for k in _SCALES]
        if "multiply-factor" in kinds:
            out += _factor_edits(side, p, t, pl)
    if "insert-term" in kinds:
        sites = [(p, x) for p, x in T.positions(root) if isinstance(x, sp.Add | sp.MatAdd)]
        sites += [(p, T.node_at(root, p)) for p in _term_paths(root)
                  if not isinstance(T.node_at(root, p), sp.Add | sp.MatAdd)
                  and (not p or isinstance(T.node_at(root, p[:-1]), sp.BlockMatrix))]
        for p, x in sorted(sites, key=lambda s: s[0]):
            here = set(x.args) if isinstance(x, sp.Add | sp.MatAdd) else {x}
            shp = _shape(x)
            for t in pl.terms:
                if t in here or _shape(t) != shp:
                    continue
                for sgn in (1, -1):
                    out.append(_edit("insert-term", side, p,
                                     lambda x, m, t=t, s=sgn: T.add(x, m(t if s > 0 else
                                                                       T.neg(t))),
                                     ("insert", t, sgn), printed_mark=False))
    return out


def _factor_edits(side, p, t, pl: Pools) -> list[Edit]:
    out = []
    for f in pl.factors:
        if f == t:
            continue
        sides = ("left", "right") if T.is_matrix(f) or T.is_matrix(t) else ("left",)
        for where in sides:
            fn = (lambda x, m, f=f: T.mul(m(f), x)) if where == "left" else \
                (lambda x, m, f=f: T.mul(x, m(f)))
            out.append(_edit("multiply-factor", side, p, fn, ("multiply", t, f, where)))
    return out


def _is_angle(x) -> bool:
    c = constraint_of(x)
    return c is not None and c.kind == "angle"


def _in_trig(root, path: tuple) -> bool:
    """Whether the node at ``path`` sits in the argument of a trigonometric function (there
    only an angle can replace an angle: the zero test knows no ``sin`` of anything else)."""
    return any(isinstance(T.node_at(root, path[:k]), sp.sin | sp.cos | sp.tan | sp.cot)
               for k in range(len(path)))


def _coefficients(c) -> list:
    sgn = 1 if c > 0 else -1
    mags = [*_SMALL, abs(c) - 1, abs(c) + 1]
    return _sorted_unique(sgn * m for m in mags if m > 0 and sgn * m != c)


def _leaf_edits(side, root, pl: Pools, kinds) -> list[Edit]:
    out = []
    for p, x in T.positions(root):
        parent = T.node_at(root, p[:-1]) if p else None
        if "coefficient" in kinds and x.is_Rational and x != 0:
            out += [_edit("coefficient", side, p, lambda x, m, c=c: m(c), ("coef", x, c))
                    for c in _coefficients(x)]
        if "transpose" in kinds and isinstance(x, sp.MatrixSymbol) and \
                not isinstance(parent, sp.Transpose):
            out.append(_edit("transpose", side, p, lambda x, m: m(sp.Transpose(x)),
                             ("transpose", x)))
        if "drop-transpose" in kinds and isinstance(x, sp.Transpose):
            out.append(_edit("drop-transpose", side, p, lambda x, m: m(x.arg),
                             ("untranspose", x)))
        if "sin-cos" in kinds and isinstance(x, sp.sin | sp.cos):
            other = sp.cos if isinstance(x, sp.sin) else sp.sin
            out.append(_edit("sin-cos", side, p, lambda x, m, o=other: m(o(x.args[0])),
                             ("sincos", x, other(x.args[0]))))
        if "one-minus" in kinds:
            out += _one_minus(side, p, x)
        if "replace-symbol" in kinds and (isinstance(x, sp.MatrixSymbol) or
                                          _is_scalar_atom(x)):
            trig = _in_trig(root, p)
            out += [_edit("replace-symbol", side, p, lambda x, m, s=s: m(s), ("replace", x, s))
                    for s in pl.symbols.get(_shape(x), []) if s != x
                    and (not trig or _is_angle(s))]
        if isinstance(x, sp.MatMul) and kinds & {"swap-factors", "reverse-product"}:
            out += _product_edits(side, p, x, kinds)
    return out


def _one_minus(side, p, x) -> list[Edit]:
    """``cos θ → 1 - cos θ`` and back (or ``sin``): what a reader slips as one edit."""
    if isinstance(x, sp.sin | sp.cos):
        new = 1 - x
    elif isinstance(x, sp.Add) and len(x.args) == 2 and sp.S.One in x.args:
        rest = x.args[0] if x.args[1] == 1 else x.args[1]
        if not (rest.could_extract_minus_sign() and isinstance(-rest, sp.sin | sp.cos)):
            return []
        new = -rest
    else:
        return []
    return [_edit("one-minus", side, p, lambda x, m, n=new: m(n), ("oneminus", x, new))]


def _product_edits(side, p, x, kinds) -> list[Edit]:
    idx = [i for i, a in enumerate(x.args) if T.is_matrix(a)]
    out = []

    def permuted(order):
        def fn(node, m):
            args = list(node.args)
            new = list(args)
            for i, j in zip(idx, order, strict=True):
                new[i] = args[j]
            return m(sp.Basic.__new__(sp.MatMul, *new))
        return fn

    if "swap-factors" in kinds:
        for k in range(len(idx) - 1):
            order = list(idx)
            order[k], order[k + 1] = order[k + 1], order[k]
            out.append(_edit("swap-factors", side, p, permuted(order),
                             ("swap", x, x.args[idx[k]], x.args[idx[k + 1]])))
    if "reverse-product" in kinds and len(idx) >= 3:
        out.append(_edit("reverse-product", side, p, permuted(idx[::-1]), ("reverse", x)))
    return out


def _global_edits(rel, pl: Pools, kinds) -> list[Edit]:
    """Edits of every occurrence of one symbol (transpose every ``Q``, every ``θ`` → ``φ``)."""
    occ: dict = {}
    for side, root in enumerate(T.sides(rel)):
        for p, x in T.positions(root):
            if isinstance(x, sp.MatrixSymbol) or _is_scalar_atom(x):
                occ.setdefault(x, []).append((side, p))
    out = []
    for sym in _sorted_unique(occ):
        where = occ[sym]
        if len(where) < 2:
            continue  # one occurrence: the same as the one-occurrence edit
        if "transpose-every" in kinds and isinstance(sym, sp.MatrixSymbol):
            out.append(Edit("transpose-every", tuple(
                Change(s, p, lambda x, m: m(sp.Transpose(x))) for s, p in where),
                ("transpose-every", sym)))
        if "replace-every" in kinds:
            trig = any(_in_trig(T.sides(rel)[sd], p) for sd, p in where)
            for s in pl.symbols.get(_shape(sym), []):
                if s != sym and (not trig or _is_angle(s)):
                    out.append(Edit("replace-every", tuple(
                        Change(sd, p, lambda x, m, s=s: m(s)) for sd, p in where),
                        ("replace-every", sym, s)))
    return out


def single_edits(rel, pl: Pools, kinds=KINDS) -> list[Edit]:
    """Every single edit of ``rel`` (a :class:`~rigidsym.registry.declarations.Rel`) of the
    given kinds, sorted by kind (:data:`KINDS` order) and then position in the tree."""
    kinds = set(kinds)
    out = []
    for side, root in enumerate(T.sides(rel)):
        out += _sum_edits(side, root, pl, kinds) + _leaf_edits(side, root, pl, kinds)
    out += _global_edits(rel, pl, kinds)
    return sorted(out, key=lambda e: e.order)


def compatible(a: Edit, b: Edit) -> bool:
    """Whether two edits can be applied together: no node changed twice, and nothing
    changed inside a term the other drops."""
    for ca in a.changes:
        for cb in b.changes:
            if ca.side != cb.side:
                continue
            if ca.path == cb.path:
                return False
            for up, down in ((ca, cb), (cb, ca)):
                if up.drop and down.path[:len(up.path)] == up.path:
                    return False
    return True


def apply_edits(rel, edits, how: str = "raw", keep: set | None = None,
                sides: tuple | None = None) -> tuple:
    """``(lhs, rhs)`` of ``rel`` with ``edits`` applied.

    Args:
        rel: the member.
        edits: compatible edits.
        how: ``raw`` (fast, for evaluation), ``canonical`` (to decide and compare),
            ``marked`` (the repaired form with the edited subterms marked) or ``printed``
            (the printed form with the subterms the edits change marked).
        keep: node ids left as they are by canonical rebuilds (:attr:`Pools.keep`).
        sides: ``treeops.sides(rel)`` when the caller has it already.

    Raises:
        treeops.ShapeError: when the shapes do not fit.
    """
    out = []
    for side, root in enumerate(sides or T.sides(rel)):
        ch = [(c.path, c.fn) if how != "printed" else
              (c.path, (lambda x, m: m(x)) if c.printed_mark else (lambda x, m: x))
              for e in edits for c in e.changes if c.side == side]
        if how == "raw":
            out.append(T.apply(root, ch))
        else:
            out.append(T.canonical(root, ch, keep or set(), marked=how != "canonical"))
    return tuple(out)


def mutants(rel, rels, model: dict, kinds=MUTATION_KINDS) -> list[tuple[Edit, tuple]]:
    """Every single-edit mutant of ``rel`` of the given kinds: ``(edit, (lhs, rhs))``,
    canonical (the form the zero test decides); edits whose shapes do not fit are left out.

    Args:
        rel: the member to mutate.
        rels: the statement's members (the pools; see :func:`pools`).
        model: the statement's model.
        kinds: kinds of :data:`KINDS` (default: the mutation test's, :data:`MUTATION_KINDS`).
    """
    pl = pools(rels, model)
    out = []
    for e in single_edits(rel, pl, kinds):
        try:
            lhs, rhs = apply_edits(rel, (e,), "canonical", pl.keep)
            if (T.shape(lhs) or (1, 1)) != (T.shape(rhs) or (1, 1)):
                continue
        except T.ShapeError:
            continue
        out.append((e, (lhs, rhs)))
    return out
