"""The residuals of a statement: each relation of its parse tree evaluated by the second
semantics (:class:`rigidsym.numeval.evaluator.Evaluator`) at random points of the declared
kinds, the difference of its two sides beside the size of their terms."""

from __future__ import annotations

import itertools
import random

import lark
import mpmath as mp

from rigidsym.numeval import rates, tilde
from rigidsym.numeval import values as V
from rigidsym.numeval.evaluator import DIGITS, Decl, Env, Evaluator, Residual
from rigidsym.numeval.names import glyph_key
from rigidsym.numeval.values import NotCovered

__all__ = ["residuals"]


def _size(v):
    if V.is_matrix(v):
        return max((abs(x) for x in v), default=mp.mpf(0))
    if isinstance(v, V.Eye):
        return abs(v.c)
    if isinstance(v, V.Zero):
        return mp.mpf(0)
    return abs(v)


def _difference(a, b, where: str):
    """``(|a - b|, size of the terms)``, an unsized identity or zero taking the other
    side's shape."""
    if isinstance(a, V.Eye) and isinstance(b, V.Eye) and not a.n and not b.n:
        return abs(a.c - b.c), max(abs(a.c), abs(b.c), mp.mpf(1))
    a2, b2 = V.sized(a, b), V.sized(b, a)
    a2, b2 = V.sized(a2, b2), V.sized(b2, a2)
    if V.is_matrix(a2) != V.is_matrix(b2):
        s = b2 if V.is_matrix(a2) else a2
        if s != 0:
            raise NotCovered(f"{where}: a scalar and a matrix")
        m = a2 if V.is_matrix(a2) else b2
        return _size(m), max(_size(m), mp.mpf(1))
    if V.is_matrix(a2) and (a2.rows, a2.cols) != (b2.rows, b2.cols):
        raise NotCovered(f"{where}: the two sides differ in shape ({a2.rows}x{a2.cols} and "
                         f"{b2.rows}x{b2.cols})")
    return _size(a2 - b2), max(_size(a2), _size(b2), mp.mpf(1))


def residuals(tree, decls: list[Decl], points: int = 6, seed: int = 62,
              free: bool = True, spread: float = 1, fixed=None,
              choices: dict | None = None) -> list[Residual]:
    """Each relation of ``tree`` (a parse of the statement) at ``points`` random points.

    Args:
        tree: lark's parse tree of the LaTeX (``start`` of ``chain`` s).
        decls: the ``--let`` declarations as :class:`Decl` (glyph trees, kinds, models).
        points: how many points.
        seed: the sampler's seed (a check is reproducible).
        free: an undeclared glyph is free with the book's conventional shape; ``False``
            (a book's notation gives meanings): it is not covered.
        spread: unconstrained reals (free scalars, vectors' entries) in (-2s, 2s).
        fixed: glyph key -> its value at every point (a given point); others are drawn.
        choices: choice point -> the reading taken there (``{"bracket cross [C ω\\wedge]":
            "bind"}``): that one reading alone is evaluated, no other enumerated.

    Returns:
        One :class:`Residual` per relation and point (``relative``: the largest entry of
        the difference over the largest of the terms, at least 1).

    Raises:
        NotCovered: a construct, a kind or shapes this semantics does not evaluate.
    """
    table = {glyph_key(d.name): d for d in rates.with_rates(decls, glyph_key)}
    chains = [c for c in tree.children if isinstance(c, lark.Tree) and c.data == "chain"]
    if not chains:
        raise NotCovered("a statement with no relation")
    if choices is not None:
        return _at_points(chains, table, points, seed, free, dict(choices), spread, fixed)[0]
    first_error = None
    try:
        out, met = _at_points(chains, table, points, seed, free, {}, spread, fixed)
    except NotCovered as exc:
        out, met, first_error = [], getattr(exc, "met", {}), exc
    if first_error is None:  # a free bold capital read as the convention: no choice
        met = {k: v for k, v in met.items() if not k.startswith("shape ")}
    if not met:
        if first_error is not None:
            raise first_error
        return out
    # choice points: every reading whose evaluation succeeds (sides of one shape) is kept,
    # each with its own reading number; the rule asks all of them to agree
    # a point met only under another reading (a second hat past the first one's) joins
    keys, kept, errors = [], [], []
    while set(keys) != set(sorted(met)[:3]):
        keys, kept, errors, seen = sorted(met)[:3], [], [], dict(met)
        for combo in itertools.product(*(seen[k] for k in keys)):
            try:
                rs, m = _at_points(chains, table, points, seed, free,
                                   {**dict(zip(keys, combo, strict=True)),
                                    " capitals": first_error is not None}, spread, fixed)
            except NotCovered as exc:
                errors.append(exc)
                met.update(getattr(exc, "met", {}))
                continue
            met.update(m)
            kept.append(rs)
    # a reading that leaves a declaration unused gives way to one that uses them all (q_1
    # beside a declared q: its entry); where none uses them all, an unused declaration is
    # the user's extra line (a book's shared declarations), and every reading stays
    using = [rs for rs in kept if not any(getattr(r, "unused", False) for r in rs)]
    kept = using or kept
    if not kept:
        raise tilde.reported(first_error, errors)  # a tilde's own first: it names the --let
    for n, rs in enumerate(kept):
        for r in rs:
            r.reading = n
    return [r for rs in kept for r in rs]


def _at_points(chains, table, points, seed, free, choices, spread=1, fixed=None):
    """:func:`residuals` for one reading of its choice points; ``(residuals, met)``, the
    choice points met (a :class:`NotCovered` carries them as ``met``)."""
    out = []
    met: dict = {}
    rng = random.Random(seed)
    rng.spread = spread
    with mp.workdps(DIGITS):
        for _ in range(points):
            point: dict = {" choices": choices, " met": met, **(fixed or {})}
            env = Env(table, point, rng, free=free)
            ev = Evaluator(env)
            n = 0
            for chain in chains:
                sides = [c for c in chain.children if isinstance(c, lark.Tree)]
                try:
                    vals = [ev.value(s) for s in sides]
                    _difference(vals[0], vals[-1], "relation")  # one shape, or not covered
                except NotCovered as exc:
                    exc.met = met
                    raise
                for k in range(1, len(vals)):
                    n += 1
                    diff, size = _difference(vals[0], vals[k], f"relation {n}")
                    names = point.get("", {})
                    r = Residual(n, vals[0], vals[k], diff / size,
                                 {names.get(g, g): v for g, v in point.items()
                                  if g and not g.startswith(" ")})
                    out.append(r)
            unused = bool(set(table) - point.get(" used", set()))
            for r in out[-n:]:  # this point's relations, once every chain is read
                r.unused = unused
    return out, met
