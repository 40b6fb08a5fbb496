"""Candidates of the repair search built fast: single edits once, pairs from them.

A single edit that changes one node is applied once: its new node and its edited side are
kept. A pair of such edits on different sides then needs no rebuilding at all (the left
side of one, the right side of the other); a pair on disjoint branches of one side
rebuilds only the ancestors of the second change; a nested pair applies the outer edit to
the node the inner one left. A drop next to another change of one side, and edits of
several nodes, go through the general :func:`rigidsym.checking.mutate.apply_edits`.

A single edit that makes a node misfit (a 3x3 times a 3x1 on the wrong side, a 3x1 term
in a sum of 3x3) leaves that node misfitting in any pair whose other edit changes nothing
inside it: such pairs are skipped without being counted, which is exact.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from rigidsym.checking import mutate
from rigidsym.checking import treeops as T

__all__ = ["Single", "prepare", "pairs"]


@dataclass
class Single:
    """A single edit, applied.

    Attributes:
        edit: the edit.
        raw: the candidate ``(lhs, rhs)`` it gives alone, or ``None`` when it does not fit.
        side, path, new: for an edit of one node, where and what (else ``None``).
        breaks: the path of the deepest node the edit alone makes misfit (``()`` the
            side's root, the edit's own path when the new node itself does not fit), or
            ``None`` when the edited side fits.
        neutral: the new node has the shape of the node it replaces (so no other node
            changes shape).
        valid: the candidate of this edit alone fits (sides of one shape).
        side_shape: the shape of the edited side (a scalar as 1 x 1) when it fits.
    """

    edit: mutate.Edit
    raw: tuple | None
    side: int | None = None
    path: tuple | None = None
    new: object = None
    breaks: tuple | None = None
    neutral: bool = False
    valid: bool = False
    side_shape: tuple | None = None


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


def _neutral(old, new, shapes: dict) -> bool:
    if new is T.DROP:
        return False
    try:
        return T.shape(old, shapes) == T.shape(new, shapes)
    except T.ShapeError:
        return False


def prepare(rel, edits, sides: tuple, shapes: dict) -> list[Single]:
    """Apply each single edit once."""
    out = []
    for e in edits:
        if len(e.changes) != 1:
            try:
                raw = mutate.apply_edits(rel, (e,), sides=sides)
            except T.ShapeError:
                raw = None
            out.append(Single(e, raw, valid=raw is not None and _fits(raw, shapes)))
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
        out.append(Single(e, raw, c.side, c.path, new, brk, _neutral(old, new, shapes),
                          side_shape is not None and _fits(raw, shapes), side_shape))
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


def _hopeless(a: Single, b: Single) -> bool:
    """Whether ``a`` breaks a node that ``b`` does not touch: then the pair misfits there
    exactly as ``a`` alone does."""
    if a.breaks is None:
        return False
    return not any(c.side == a.side and c.path[:len(a.breaks)] == a.breaks
                   for c in b.edit.changes)


def _mute(a: Single, b: Single) -> bool:
    """Whether ``a`` changes no shape in the pair (its new node has the old node's shape and
    it is not applied on top of ``b``) while ``b`` alone misfits: then every node of the
    pair has the shape it has with ``b`` alone."""
    return a.neutral and not b.valid and b.path[:len(a.path)] != a.path


def _conflict(a: Single, b: Single) -> bool:
    """:func:`rigidsym.checking.mutate.compatible` negated, for two edits of one node each
    on one side."""
    if a.path == b.path:
        return True
    for up, down in ((a, b), (b, a)):
        if up.new is T.DROP and down.path[:len(up.path)] == up.path:
            return True
    return False


def pairs(rel, singles: list[Single], sides: tuple) -> Iterator[tuple[tuple, object]]:
    """``(edits, raw)`` of every compatible pair that can fit: ``(i, j)`` for ``j``
    ascending, then ``i < j``, so that a budget covers every pair among the first singles;
    ``raw`` is ``None`` for a pair whose shapes do not fit."""
    for j, b in enumerate(singles):
        for i in range(j):
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
            if _hopeless(a, b) or _hopeless(b, a):
                continue
            if one and (_mute(a, b) or _mute(b, a)):
                continue  # shapes as in the other edit alone, which misfits
            try:
                raw = _pair_raw(rel, a, b, sides)
            except T.ShapeError:
                raw = None
            yield (a.edit, b.edit), raw
