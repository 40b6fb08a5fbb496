"""The tilde over a vector in the second semantics (issue 63, the second outside trial): an
undeclared ``\\tilde{X}`` of a 3-vector ``X`` is a choice point, read as the cross-product
matrix of ``X`` (Wittenburg, Shabana, Greenwood, Schaub & Junkins) or as a vector of its own
(an estimate's error), every tilde of a reading the same way; the enumeration of
:func:`rigidsym.numeval.evaluator.residuals` keeps each reading whose sides have one shape.
As the reader does (:mod:`rigidsym.latex.transformer.tilde`), written again here: this
semantics imports nothing of the symbolic one."""

from __future__ import annotations

import lark

from rigidsym.numeval import values as V
from rigidsym.numeval.sampler import sample

__all__ = ["POINT", "tilde_value"]

#: the choice point's key, one for every tilde of a reading
POINT = "tilde"
_OPTIONS = ("skew", "own")


def tilde_value(ev, t, key: str):
    """The value of the undeclared accented glyph ``t`` (its key ``key``) where it is a
    tilde over a 3-vector: its cross-product matrix, or a vector of its own drawn once per
    point, as the point's choices say; ``None`` for any other accent or operand.

    Args:
        ev: the :class:`~rigidsym.numeval.evaluator.Evaluator` (its ``env`` and ``value``).
        t: the ``accented`` or ``accented_bare`` subtree.
        key: its glyph key (:func:`~rigidsym.numeval.evaluator.glyph_key`).
    """
    if len(t.children) != 2 or str(t.children[0]) not in ("\\tilde", "\\widetilde"):
        return None
    inner = t.children[1]
    if inner.data == "bare":
        inner = lark.Tree("glyph", [lark.Tree("base", list(inner.children))])
    v = V.scalar(ev.value(inner))
    if not (V.is_matrix(v) and (v.rows, v.cols) == (3, 1)):
        return None
    point = ev.env.point
    point.setdefault(" met", {})[POINT] = _OPTIONS
    if point.get(" choices", {}).get(POINT, _OPTIONS[0]) == "skew":
        return V.hat(v)
    if key not in point:  # drawn once per point, named in a message by its LaTeX
        point[key] = sample("vector", ev.env.rng)
        ev.env.names[key] = " ".join(str(x) for x in t.scan_values(
            lambda x: isinstance(x, lark.Token)))
    return point[key]
