"""The second semantics at a given point (issue 62): the symbolic path's counterexample,
handed over as plain data (a glyph's parse tree and its value as decimal strings), fixes
those glyphs; each relation's residual is evaluated there at :data:`~rigidsym.numeval.
evaluator.DIGITS` digits. A glyph the point does not give is reported, never guessed."""

from __future__ import annotations

import mpmath as mp

from rigidsym.numeval.evaluator import DIGITS, Residual, glyph_key, residuals

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
        NotCovered: as :func:`~rigidsym.numeval.evaluator.residuals`.
        ValueError: a value that is not plain (:func:`value_of`).
    """
    with mp.workdps(DIGITS + 10):
        fixed = {glyph_key(t): value_of(v) for t, v in given}
    found = residuals(tree, decls, 1, fixed=fixed)
    drawn = sorted({k for r in found for k in r.point if k not in fixed})
    return found, drawn


def subtree_values(decls, given: list, subtrees: list) -> list:
    """Each parse subtree's value at the point ``given`` (as :func:`residuals_at`), in this
    semantics' first reading; ``None`` for one it cannot evaluate alone. The values a
    disagreement is located by."""
    import random

    from rigidsym.numeval.evaluator import Env, Evaluator

    with mp.workdps(DIGITS + 10):
        fixed = {glyph_key(t): value_of(v) for t, v in given}
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
