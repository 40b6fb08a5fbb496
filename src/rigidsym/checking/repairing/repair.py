"""The repair search: the smallest edits that make a failing member hold, each verified.

For a printed member that does not hold, the edits of :mod:`rigidsym.checking.repairing.mutate` are
tried, single edits first, then pairs. Each candidate is

1. built raw (no sympy canonicalisation) and its shapes checked: a candidate whose shapes
   do not fit is no candidate and is not counted;
2. evaluated at two fixed exact points modulo a prime, reusing the values of unchanged
   subtrees (:mod:`rigidsym.checking.repairing.fasteval`): a candidate whose sides differ there does
   not hold (exactly), and most die here;
3. if it survives: rejected when its two sides are the same expression with the book
   symbols left unsubstituted (``Eᵀ = Eᵀ``, ``(M_A - M_A)[:3, 3:] = O``): such a
   "repair" holds trivially and says nothing;
4. decided by the full sound zero test (the checker's ``decide_rel``): only a candidate
   decided to hold is a repair, with its method and failure bound.

The search is bounded by a count of candidates (``ENGINE.repair_budget`` per member), so its
results do not depend on the machine, and, where the run sets one (``--repair-seconds``),
by a time limit (:mod:`.deadline`), after which it says it stopped and how many
candidates it tried. It reports every single-edit repair,
else every two-edit one, sorted by edit kind and then position in the tree, keeps
``ENGINE.keep`` and says how many were found; a repaired equation found twice by the same kind
of edit (``-Eᵀ = E`` and ``Eᵀ = -E``) counts once (found by two kinds, it is two
explanations of the slip, and both are reported).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

import sympy as sp
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.polys.matrices import DomainMatrix

from rigidsym.checking.deciding.explicit import entries_of, explicit, shape_of
from rigidsym.checking.repairing import candidates, mutate
from rigidsym.checking.repairing import treeops as T
from rigidsym.checking.repairing.deadline import Late
from rigidsym.checking.repairing.fasteval import (
    GenericValues,
    Inconclusive,
    Undecidable,
    difference,
    differs,
    points_for,
)
from rigidsym.core.settings import ENGINE
from rigidsym.registry.declarations import Rel
from rigidsym.zero.decide import Unsupported, make_plan

__all__ = ["Search", "Found", "Decision", "Shared",
           "share",
           "search_member", "book_difference", "same_relation", "trivial"]

# the search's budget, what it keeps and its full tests: rigidsym.core.settings


@dataclass
class Decision:
    """A decision in the shape :func:`rigidsym.checking.deciding.records.member_record` reads."""

    zero: bool | None
    method: str
    detail: str


@dataclass
class Found:
    """A verified repair: the edits, the repaired member (canonical), its decision."""

    edits: tuple
    rel: Rel
    method: str
    detail: str

    @property
    def rel_sides(self) -> tuple:
        """``(lhs, rhs)`` of the repaired member."""
        return (self.rel.lhs, self.rel.rhs)


@dataclass
class Search:
    """What the search of one member did and found."""

    member: str
    candidates: int = 0
    complete: bool = False
    depth: int = 0
    found: list = field(default_factory=list)
    full_tests: int = 0
    undecidable: int = 0
    stopped: str = ""
    limit: float = 0.0  # the time limit it ran under, seconds (0: none)


@dataclass
class Shared:
    """What the searches of one statement share: the pools, the fixed points (with their
    memoised values), the generic evaluator and the shapes."""

    rels: list
    model: dict
    pools: mutate.Pools
    points: list
    decide: Callable
    seed: int
    generic: GenericValues = field(default_factory=GenericValues)
    shapes: dict = field(default_factory=dict)


@dataclass
class _Ctx:
    rel: Rel
    sh: Shared
    budget: int
    search: Search
    sides: tuple
    seen: set = field(default_factory=set)
    found_diffs: list = field(default_factory=list)
    deadline: float | None = None  # time.monotonic() after which the search stops

    def late(self) -> bool:
        """Past the deadline: the search stops, saying so."""
        if self.deadline is not None and time.monotonic() > self.deadline:
            self.search.stopped = "time"
            return True
        return False


# --------------------------------------------------------------------------- book symbols
def book_difference(lhs, rhs) -> list | None:
    """``lhs - rhs`` entry by entry, expanded, with the book symbols left unsubstituted
    (``None`` when the shapes differ, or when a word has no value on free book symbols:
    ``expm`` of an axis not known to be unit)."""
    if shape_of(lhs) != shape_of(rhs):
        return None
    try:
        a, b = explicit(lhs, {}), explicit(rhs, {})
    except (ValueError, NotImplementedError):
        return None
    diffs = [x - y for x, y in zip(entries_of(a), entries_of(b), strict=True)]
    return _rational(diffs) or [sp.expand(x) for x in diffs]


def _rational(xs: list) -> list | None:
    """``xs`` as rational functions of their atoms (entries of matrix symbols, symbols,
    ``cos θ`` as a generator, as :func:`sympy.expand` takes it), each one cancelled
    fraction (zero exactly when it is zero), or ``None`` when they are not (a square
    root): the inverse of a 4x4's entries (McCarthy, Sola's ``Ad`` of ``M^{-1}``) took
    ``expand`` 30 s, the fraction field under 1 s."""
    sub = {a: sp.Dummy() for x in xs for a in sp.sympify(x).atoms(MatrixElement)}
    try:
        dm = DomainMatrix.from_list_sympy(1, len(xs), [[sp.sympify(x).xreplace(sub)
                                                        for x in xs]])
    except (sp.PolificationFailed, sp.CoercionFailed, sp.GeneratorsError):
        return None
    if dm.domain.is_EX or dm.domain.is_EXRAW:
        return None
    back = {v: k for k, v in sub.items()}
    return [x.xreplace(back) for x in dm.to_Matrix()]


def _generic(g: GenericValues, lhs, rhs):
    lhs, rhs = T.sides(Rel(lhs, rhs))  # hashable (a declared side may be a mutable Matrix)
    try:
        return difference(g, lhs, rhs)
    except Inconclusive:
        return None


def same_relation(g: GenericValues, r1: tuple, r2: tuple) -> bool:
    """Whether ``r1 = (lhs, rhs)`` and ``r2`` state the same equation with the book symbols
    left unsubstituted: their expanded differences are equal or opposite (``a = b`` is
    ``-a = -b``). A generic evaluation rules most pairs out; the expansion confirms."""
    d1, d2 = _generic(g, *r1), _generic(g, *r2)
    if d1 is not None and d2 is not None and d1 != d2 and d1 != -d2:
        return False
    e1, e2 = book_difference(*r1), book_difference(*r2)
    if e1 is None or e2 is None or len(e1) != len(e2):
        return False
    return all(sp.expand(x - y) == 0 for x, y in zip(e1, e2, strict=True)) or \
        all(sp.expand(x + y) == 0 for x, y in zip(e1, e2, strict=True))


def trivial(g: GenericValues, lhs, rhs) -> bool:
    """Whether the two sides are the same expression with the book symbols left
    unsubstituted (``Eᵀ = Eᵀ``): expanded, their difference is zero."""
    d = _generic(g, lhs, rhs)
    if d is not None and any(x != 0 for x in d.entries()):
        return False
    e = book_difference(lhs, rhs)
    return e is not None and all(x == 0 for x in e)


# --------------------------------------------------------------------------- search
def _plan(rels, model, pl: mutate.Pools):
    exprs = []
    for k in list(model) + [a for group in pl.symbols.values() for a in group]:
        exprs += entries_of(explicit(k, model))  # a bare angle a factor brings in, too
    for r in rels:
        exprs += entries_of(explicit(r.lhs, model)) + entries_of(explicit(r.rhs, model))
    return make_plan(exprs)


def share(failing: list[Rel], rels: list[Rel], model: dict, decide: Callable,
          seed: int) -> Shared:
    """The shared part of the searches of one statement's failing members.

    Args:
        failing: the members that do not hold.
        rels: the statement's printed members and claims (the pools of terms, factors and
            symbols; never the corrected form).
        model: the statement's model.
        decide: ``decide(rel, model, seed)`` -> an outcome with ``zero``, ``method`` and
            ``detail`` (the checker's sound decision of one relation).
        seed: the seed of the fixed points and of the full tests.
    """
    pl = mutate.pools(rels, model)
    try:
        plan = _plan(rels, model, pl)
        pts = points_for(model, plan, [x for r in failing for x in T.sides(r)], seed)
    except (Unsupported, TypeError, ValueError):
        pts = []
    return Shared(rels, model, pl, pts, decide, seed)


def search_member(rel: Rel, sh: Shared, budget: int | None = None,
                  deadline: float | None = None, limit: float = 0.0) -> Search:
    """Search the repairs of one failing member.

    Args:
        rel: the member that does not hold.
        sh: from :func:`share`.
        budget: the most candidates to try (default
            ``ENGINE.repair_budget``).
        deadline: ``time.monotonic()`` after which the search stops (``None``: none).
        limit: the time limit in seconds, for the words (:func:`search_record`).

    Returns:
        A :class:`Search`; ``found`` holds the verified repairs in report order.
    """
    s = Search(member=rel.label, limit=limit)
    budget = ENGINE.repair_budget if budget is None else budget
    ctx = _Ctx(rel, sh, budget, s, T.sides(rel), deadline=deadline)
    if ctx.late():
        return s
    try:
        return _member(ctx)
    except Late:  # the time limit passed inside a step (time_limit)
        s.stopped, s.complete = "time", False
        s.found.sort(key=lambda f: reader_key(f.edits, ctx.sides))
        return s


def _member(ctx: _Ctx) -> Search:
    """:func:`search_member`'s body."""
    rel, sh, s = ctx.rel, ctx.sh, ctx.search
    singles = candidates.prepare(rel, mutate.single_edits(rel, sh.pools), ctx.sides,
                                 sh.shapes)
    done = _run(ctx, (((x.edit,), x.raw) for x in singles))
    if s.found:
        s.depth, s.complete = 1, done
        s.found.sort(key=lambda f: reader_key(f.edits, ctx.sides))
        return s
    if not done:
        return s
    done = _run(ctx, candidates.pairs(rel, singles, ctx.sides))
    s.depth = 2 if s.found else 0
    s.complete = done
    s.found.sort(key=lambda f: reader_key(f.edits, ctx.sides))
    return s


def reader_key(edits, sides: tuple) -> tuple:
    """The order of found repairs, as a reader fixes an equation (``docs/repairs.md``):
    an edit that inserts a copy of a side (the same equation, moved: ``Ω = (R - Rᵀ)/sin θ
    - Ω``) after every other; then, for ``X = ...`` with ``X`` a bare symbol, an edit of
    the formula's side before one of ``X`` (the ½ goes on the right, not a 2 on ``Ω``);
    then the edit kinds' order (:data:`mutate.KINDS`) and the positions in the tree."""
    moved = any(e.kind == "insert-term" and e.what[1] in sides for e in edits)
    defined = isinstance(sides[0], sp.Symbol | sp.MatrixSymbol)
    on_defined = defined and any(c.side == 0 for e in edits for c in e.changes)
    return (moved, on_defined, sorted(e.order for e in edits))


def _run(ctx: _Ctx, cands) -> bool:
    """Try ``(edits, raw)`` candidates in order; True when they were all tried within the
    budget."""
    survivors = []
    shapes = ctx.sh.shapes
    for edits, raw in cands:
        if raw is None or raw in ctx.seen:
            continue
        ctx.seen.add(raw)
        try:
            a, b = T.shape(raw[0], shapes), T.shape(raw[1], shapes)
        except T.ShapeError:
            continue
        if (a or (1, 1)) != (b or (1, 1)):
            continue
        if ctx.search.candidates >= ctx.budget:
            ctx.search.stopped = "budget"
            _verify(ctx, survivors)
            return False
        if ctx.late():
            return False
        ctx.search.candidates += 1
        if not _dies(ctx, raw):
            survivors.append(edits)
    return _verify(ctx, survivors)


def _dies(ctx: _Ctx, raw) -> bool:
    """Whether the candidate is out: it differs at a fixed point (so it does not hold), or
    the engine cannot decide it at all (counted in ``undecidable``)."""
    for pv in ctx.sh.points:
        try:
            if differs(pv, raw[0], raw[1]):
                return True
        except Undecidable:
            ctx.search.undecidable += 1
            return True
        except Inconclusive:
            continue
        except (ValueError, ZeroDivisionError, ArithmeticError):  # a singular candidate
            return True  # (an inverse of a singular block): skipped, never raised
    return False


def _verify(ctx: _Ctx, survivors) -> bool:
    sh = ctx.sh
    for edits in survivors:
        if ctx.late():
            return False
        if ctx.search.full_tests >= ENGINE.full_tests:
            ctx.search.stopped = "full tests"
            return False
        try:
            lhs, rhs = mutate.apply_edits(ctx.rel, edits, "canonical", sh.pools.keep)
            if shape_of(lhs) != shape_of(rhs) or trivial(sh.generic, lhs, rhs):
                continue  # holds trivially, with the book symbols left unsubstituted
        except (T.ShapeError, TypeError, ValueError):
            continue
        kinds = [e.kind for e in edits]
        if any([e.kind for e in f.edits] == kinds
               and same_relation(sh.generic, (lhs, rhs), f.rel_sides)
               for f in ctx.search.found):
            continue  # the same repaired equation by the same kind of edit (-Eᵀ = E, Eᵀ = -E)
        ctx.search.full_tests += 1
        try:
            out = sh.decide(Rel(lhs, rhs, ctx.rel.label), sh.model, sh.seed)
        except (ValueError, ArithmeticError, TypeError, Unsupported):
            ctx.search.undecidable += 1  # no meaning: the inverse of a singular matrix
            continue
        if out.zero is True:
            ctx.search.found.append(Found(tuple(edits), Rel(lhs, rhs, ctx.rel.label),
                                          out.method, out.detail))
    return True
