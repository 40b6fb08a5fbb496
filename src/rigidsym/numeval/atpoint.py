"""The second semantics at a given point: the symbolic path's counterexample,
handed over as plain data (a glyph's parse tree and its value as decimal strings), fixes
those glyphs; each relation's residual is evaluated there at :data:`~rigidsym.numeval.
evaluator.DIGITS` digits. A glyph the point does not give is reported, never guessed."""

from __future__ import annotations

import random

import lark
import mpmath as mp

from rigidsym.numeval import motion
from rigidsym.numeval.evaluator import DIGITS, TIME, Residual, text_of
from rigidsym.numeval.names import glyph_key
from rigidsym.numeval.random_points import residuals

__all__ = ["value_of", "residuals_at", "subtree_values"]


def value_of(v):
    """A plain value as mpmath: a decimal string (a scalar) or a list of rows of decimal
    strings (a matrix; a vector one column).

    Raises:
        ValueError: ``v`` is neither (mpmath's own message on a malformed number).
    """
    if isinstance(v, str):
        return mp.mpf(v)
    if isinstance(v, list | tuple) and v and all(isinstance(r, list | tuple) for r in v):
        return mp.matrix([[mp.mpf(x) for x in row] for row in v])
    raise ValueError(f"a point's value: expected a decimal string or rows of them, got {v!r}")


def residuals_at(tree, decls, given: list) -> tuple[list[Residual], list[str]]:
    """Each relation of ``tree`` at the point ``given`` (``[(glyph tree, plain value)]``).

    Returns:
        ``(residuals, drawn)``: one :class:`Residual` per relation (and reading), and the
        glyphs the point did not give that the evaluation drew at random (empty when the
        point fixes the statement).

    Raises:
        NotCovered: as :func:`~rigidsym.numeval.random_points.residuals`.
        ValueError: a value that is not plain (:func:`value_of`).
    """
    with mp.workdps(DIGITS + 10):
        fixed = {glyph_key(t): value_of(v) for t, v in given}
        fixed = _moving(decls, fixed)
    found = residuals(tree, decls, 1, fixed=fixed)
    drawn = sorted({k for r in found for k in r.point if k not in fixed})
    names = {glyph_key(t): text_of(t) for t, _ in given} | {TIME: "t"}
    for r in found:  # the point as given, by the glyphs' LaTeX (a motion: its value at t = 0)
        r.point = {names.get(k, k): motion.at(v, 0) if isinstance(v, tuple) else v
                   for k, v in r.point.items()}
    return found, drawn


def _accent(accent: str, name):
    return glyph_key(lark.Tree("accented", [lark.Token("ACCENT", accent), name]))


def _moving(decls, fixed: dict) -> dict:
    """``fixed`` with each function of time it gives (``X(t): KIND``, its value and, where
    given, ``\\dot X`` and ``\\ddot X``) replaced by a motion of its kind through them at
    the time t = 0 (:func:`~rigidsym.numeval.motion.through`), t fixed there.

    Raises:
        ValueError: the point gives t itself (not 0), or rates a motion cannot take.
    """
    timed = [d for d in decls if d.timed and d.kind and d.body is None
             and glyph_key(d.name) in fixed]
    if not timed:
        return fixed
    out = dict(fixed)
    if out.setdefault(TIME, mp.mpf(0)) != 0:
        raise ValueError("a point that gives the time t of a function of time")
    rng = random.Random(64)
    for d in timed:
        key = glyph_key(d.name)
        dot, ddot = out.pop(_accent("\\dot", d.name), None), out.pop(_accent("\\ddot", d.name),
                                                                       None)
        out[key] = motion.through(motion.curve(d.kind, rng), out[key], dot, ddot)
    return out


def subtree_values(decls, given: list, subtrees: list) -> list:
    """Each parse subtree's value at the point ``given`` (as :func:`residuals_at`), in this
    semantics' first reading; ``None`` for one it cannot evaluate alone. The values a
    disagreement is located by."""
    from rigidsym.numeval.evaluator import Env, Evaluator

    with mp.workdps(DIGITS + 10):
        fixed = _moving(decls, {glyph_key(t): value_of(v) for t, v in given})
    table = {glyph_key(d.name): d for d in decls}
    rng = random.Random(62)
    out = []
    with mp.workdps(DIGITS):
        ev = Evaluator(Env(table, {" choices": {}, " met": {}, **fixed}, rng))
        for s in subtrees:
            try:
                out.append(ev.value(s))
            except Exception:  # noqa: BLE001 -- a fragment without its context
                out.append(None)
    return out
