"""The accented glyphs that no declaration names and the second semantics still reads
(the second outside trial), each as the reader does:

- a tilde over a 3-vector: its cross-product matrix, one reading of a choice whose other
  (a vector of its own) only a declaration gives (:mod:`rigidsym.numeval.tilde`);
- ``\\dot X`` of an ``X`` declared a scalar or an angle but no function of time (Greenwood's
  ``\\dot\\psi`` beside ``\\psi: angle``): the rate's value at the instant, a scalar drawn
  once per point (the reader takes it so only where the statement takes no derivative,
  :func:`rigidsym.latex.guards.takes_no_derivative`)."""

from __future__ import annotations

import lark

from rigidsym.numeval import tilde
from rigidsym.numeval.sampler import sample

__all__ = ["undeclared_accent"]


def undeclared_accent(ev, t, key: str):
    """The value of the undeclared accented glyph ``t`` (glyph key ``key``) in the
    evaluator ``ev``, or ``None`` where this semantics has none (then not covered).

    Args:
        ev: the :class:`~rigidsym.numeval.evaluator.Evaluator` (its ``env`` and ``value``).
        t: the ``accented`` or ``accented_bare`` subtree.
        key: its glyph key (:func:`~rigidsym.numeval.evaluator.glyph_key`).
    """
    v = tilde.tilde_value(ev, t, key)
    if v is not None or len(t.children) != 2 or str(t.children[0]) != "\\dot":
        return v
    inner = t.children[1]
    if inner.data == "bare":
        inner = lark.Tree("glyph", [lark.Tree("base", list(inner.children))])
    from rigidsym.numeval.names import glyph_key

    d = ev.env.decls.get(glyph_key(inner))
    if d is None or d.timed or d.body is not None or d.params \
            or d.kind.split(" in ")[0] not in ("angle", "scalar"):
        return None
    point = ev.env.point
    if key not in point:
        point[key] = sample("scalar", ev.env.rng)
        ev.env.names[key] = " ".join(str(x) for x in t.scan_values(
            lambda x: isinstance(x, lark.Token)))
    return point[key]
