"""Candidates of the repair search built fast: single edits once, pairs from them.

A single edit that changes one node is applied once: its new node and its edited side are
kept. A pair of such edits on different sides then needs no rebuilding at all (the left
side of one, the right side of the other); a pair on disjoint branches of one side
rebuilds only the ancestors of the second change; a nested pair applies the outer edit to
the node the inner one left. A drop next to another change of one side, and edits of
several nodes, go through the general :func:`rigidsym.checking.repairing.mutate.apply_edits`.

Pairs whose shapes cannot fit are skipped without being counted, by rules that are exact
because a node's shape depends only on its children's shapes:

- an edit that makes a node misfit (a 3x3 times a 3x1 on the wrong side, a 3x1 term in a
  sum of 3x3) leaves it misfitting in any pair whose other edit changes nothing inside it;
- an edit whose new node has the old node's shape (*neutral*) changes no shape in a pair,
  unless it is applied on top of the other edit and its result's shape depends on its
  input's (it is not *transparent*, as a sign flip or a scalar factor is): such a pair has
  the shapes of the other edit alone, and misfits when that edit alone does.
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Iterator
from dataclasses import dataclass, field

from rigidsym.checking.repairing import mutate
from rigidsym.checking.repairing import treeops as T

__all__ = ["Single", "prepare", "pairs"]


@dataclass
class Single:
    """A single edit, applied.

    Attributes:
        edit: the edit.
        raw: the candidate ``(lhs, rhs)`` it gives alone, or ``None`` when it does not fit.
        side, path, new: for an edit of one node, where and what (else ``None``).
        breaks: the path of the deepest node on the edit's path that the edit alone makes
            misfit, or ``None``.
        neutral: every new node has the shape of the node it replaces.
        transparent: its new node has its input's shape whatever that is (a sign, a
            scalar factor).
        valid: the candidate of this edit alone fits (sides of one shape).
        side_shape: the shape of the edited side (a scalar as 1 x 1) when it fits.
        places: ``(side, path)`` of every change.
    """

    edit: mutate.Edit
    raw: tuple | None
    side: int | None = None
    path: tuple | None = None
    new: object = None
    breaks: tuple | None = None
    neutral: bool = False
    transparent: bool = False
    valid: bool = False
    side_shape: tuple | None = None
    places: tuple = field(default=())


def _identity(x):
    return x


def _breaks(root, path: tuple, shapes: dict) -> tuple | None:
    """The path of the deepest node on ``path`` (from ``root``) whose shapes misfit."""
    chain = [root]
    for i in path:
        kids = T.children(chain[-1])
        if i >= len(kids):
            break
        chain.append(kids[i])
    for k in range(len(chain) - 1, -1, -1):
        try:
            T.shape(chain[k], shapes)
        except T.ShapeError:
            return path[:k]
    return None


def _fits(raw, shapes: dict) -> bool:
    try:
        a, b = T.shape(raw[0], shapes), T.shape(raw[1], shapes)
    except T.ShapeError:
        return False
    return (a or (1, 1)) == (b or (1, 1))


def _same_shape(old, new, shapes: dict) -> bool:
    if new is T.DROP:
        return False
    try:
        return T.shape(old, shapes) == T.shape(new, shapes)
    except T.ShapeError:
        return False


def _transparent(e: mutate.Edit) -> bool:
    if e.kind in ("flip-sign", "scale-term"):
        return True
    return e.kind == "multiply-factor" and not T.is_matrix(e.what[2])


def prepare(rel, edits, sides: tuple, shapes: dict) -> list[Single]:
    """Apply each single edit once."""
    out = []
    for e in edits:
        places = tuple((c.side, c.path) for c in e.changes)
        if len(e.changes) != 1:
            try:
                raw = mutate.apply_edits(rel, (e,), sides=sides)
            except T.ShapeError:
                raw = None
            neutral = all(_same_shape(T.node_at(sides[c.side], c.path),
                                      c.fn(T.node_at(sides[c.side], c.path), _identity),
                                      shapes) for c in e.changes)
            out.append(Single(e, raw, neutral=neutral, places=places,
                              valid=raw is not None and _fits(raw, shapes)))
            continue
        c = e.changes[0]
        old = T.node_at(sides[c.side], c.path)
        new = c.fn(old, _identity)
        try:
            edited = T.replace_at(sides[c.side], c.path, new) if c.path else new
            raw = (edited, sides[1]) if c.side == 0 else (sides[0], edited)
            brk = _breaks(edited, c.path if new is not T.DROP else c.path[:-1], shapes)
        except T.ShapeError:
            raw, brk = None, None
        side_shape = None
        if raw is not None and brk is None:
            side_shape = T.shape(raw[c.side], shapes) or (1, 1)
        out.append(Single(e, raw, c.side, c.path, new, brk, _same_shape(old, new, shapes),
                          _transparent(e), side_shape is not None and _fits(raw, shapes),
                          side_shape, places))
    return out


def _nested(p: tuple, q: tuple) -> bool:
    return p[:len(q)] == q or q[:len(p)] == p


def _pair_raw(rel, a: Single, b: Single, sides: tuple):
    """The candidate of two compatible edits, or ``None`` when it does not fit."""
    fast = a.side is not None and b.side is not None and a.raw is not None \
        and b.raw is not None
    if not fast:
        return mutate.apply_edits(rel, (a.edit, b.edit), sides=sides)
    if a.side != b.side:
        return (a.raw[0], b.raw[1]) if a.side == 0 else (b.raw[0], a.raw[1])
    if _nested(a.path, b.path):
        outer, inner = (a, b) if len(a.path) <= len(b.path) else (b, a)
        root = inner.raw[inner.side]  # the inner edit applied, then the outer one on top
        new = outer.edit.changes[0].fn(T.node_at(root, outer.path), _identity)
        edited = T.replace_at(root, outer.path, new) if outer.path else new
    elif a.new is T.DROP or b.new is T.DROP:  # a drop renumbers its siblings
        return mutate.apply_edits(rel, (a.edit, b.edit), sides=sides)
    else:
        edited = T.replace_at(a.raw[a.side], b.path, b.new)
    return (edited, sides[1]) if a.side == 0 else (sides[0], edited)


def _above(a: Single, b: Single) -> bool:
    """Whether a change of ``a`` sits at or above a change of ``b``."""
    return any(sa == sb and pb[:len(pa)] == pa for sa, pa in a.places for sb, pb in b.places)


def _hopeless(a: Single, b: Single) -> bool:
    """Whether ``a`` breaks a node that ``b`` does not touch: then the pair misfits there
    exactly as ``a`` alone does."""
    if a.breaks is None:
        return False
    return not any(s == a.side and p[:len(a.breaks)] == a.breaks for s, p in b.places)


def _mute(a: Single, b: Single) -> bool:
    """Whether ``a`` changes no shape in the pair while ``b`` alone misfits: then every node
    of the pair has the shape it has with ``b`` alone."""
    return a.neutral and not b.valid and (a.transparent or not _above(a, b))


def _conflict(a: Single, b: Single) -> bool:
    """:func:`rigidsym.checking.repairing.mutate.compatible` negated, for two edits of one node each
    on one side."""
    if a.path == b.path:
        return True
    for up, down in ((a, b), (b, a)):
        if up.new is T.DROP and down.path[:len(up.path)] == up.path:
            return True
    return False


class _Index:
    """Which earlier singles can pair with a given one at all (a superset of those the
    rules above keep): the loop over every pair is the search's cost on long members."""

    def __init__(self, singles: list[Single]):
        self.singles = singles
        self.moving = [i for i, s in enumerate(singles) if not s.neutral]
        self.valid = [i for i, s in enumerate(singles) if s.valid]
        self.at: dict = {}
        for i, s in enumerate(singles):
            for place in s.places:
                self.at.setdefault(place, []).append(i)

    def _before(self, idx: list, j: int) -> list:
        return idx[:bisect_left(idx, j)]

    def partners(self, j: int) -> list:
        b = self.singles[j]
        if not b.valid:  # a must change a shape, or sit above b and not be transparent
            keep = set(self._before(self.moving, j))
            for side, path in b.places:
                for k in range(len(path) + 1):
                    keep.update(i for i in self.at.get((side, path[:k]), ()) if i < j)
            return sorted(keep)
        if b.neutral and b.transparent:  # a must fit alone
            return self._before(self.valid, j)
        return list(range(j))


def pairs(rel, singles: list[Single], sides: tuple) -> Iterator[tuple[tuple, object]]:
    """``(edits, raw)`` of every compatible pair that can fit: ``(i, j)`` for ``j``
    ascending, then ``i < j``, so that a budget covers every pair among the first singles;
    ``raw`` is ``None`` for a pair whose shapes do not fit."""
    index = _Index(singles)
    for j, b in enumerate(singles):
        for i in index.partners(j):
            a = singles[i]
            one = a.side is not None and b.side is not None
            if one and a.side != b.side:
                # the sides are those of each edit alone: fits iff their shapes agree
                if a.side_shape is None or a.side_shape != b.side_shape:
                    continue
                yield (a.edit, b.edit), ((a.raw[0], b.raw[1]) if a.side == 0
                                         else (b.raw[0], a.raw[1]))
                continue
            if one:
                if _conflict(a, b):
                    continue
            elif not mutate.compatible(a.edit, b.edit):
                continue
            if _hopeless(a, b) or _hopeless(b, a) or _mute(a, b) or _mute(b, a):
                continue
            try:
                raw = _pair_raw(rel, a, b, sides)
            except T.ShapeError:
                raw = None
            yield (a.edit, b.edit), raw
