r"""The second semantics' reading of an undeclared hat, ``\hat{X}``,
written from the books, not from the reader: Lynch & Park's and Corke's ``\hat\omega`` is a
unit vector of its own, Murray, Li & Sastry's (2.9) and Ma, Soatto, Košecká & Sastry's
``\widehat{T}`` the skew matrix of the vector under it. Both are readings of one choice
point (``hat`` and the glyph's text); :func:`rigidsym.numeval.random_points.residuals` evaluates
each and keeps those whose sides have one shape. Imports lark, mpmath and the standard
library only (the import-linter contract of :mod:`rigidsym.numeval`)."""

from __future__ import annotations

import lark

from rigidsym.numeval import values as V
from rigidsym.numeval.sampler import sample

__all__ = ["undeclared_hat"]


def undeclared_hat(ev, t, key: str, text: str):
    r"""The value of the accented glyph ``t`` (``\hat{T}``, its accent canonical) that no
    declaration names, at the choice point's reading; ``None`` where it is no hat of one
    glyph or free glyphs are not read (a notation's meanings).

    Args:
        ev: the :class:`rigidsym.numeval.evaluator.Evaluator` (its ``env`` and ``choose``).
        t: the ``accented`` tree: the accent token, then the glyph under it.
        key: the glyph key of ``t`` (where its unit-vector reading is drawn, once per point).
        text: its text, for the choice point's key and the messages.

    Returns:
        A unit 3-vector of its own (``"unit"``, the first reading) or the 3 x 3 skew matrix
        of the glyph under the hat (``"skew"``; of a value that is no 3-vector
        :class:`~rigidsym.numeval.values.NotCovered`, so the reading is dropped).
    """
    if str(t.children[0]) not in ("\\hat", "\\widehat") or len(t.children) != 2 \
            or not ev.env.free:
        return None
    inner = t.children[1]
    if not isinstance(inner, lark.Tree):
        return None
    if inner.data == "bare":
        inner = lark.Tree("glyph", [lark.Tree("base", list(inner.children))])
    if ev.choose(f"hat {text}", ("unit", "skew")) == "skew":
        v = ev.value(inner)
        if not V.is_matrix(v) or (v.rows, v.cols) != (3, 1):
            raise V.NotCovered(f"the skew matrix {text} of a value that is no 3-vector")
        return V.hat(v)
    point = ev.env.point
    if key not in point:
        point[key] = sample("unit vector", ev.env.rng)
        ev.env.names[key] = text
    return point[key]
