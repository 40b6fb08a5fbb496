"""The tilde over a vector in the second semantics (the second outside trial): an
undeclared ``\\tilde{X}`` of a 3-vector ``X`` is a choice point, read as the cross-product
matrix of ``X`` (Wittenburg, Shabana, Greenwood, Schaub & Junkins) or as a vector of its own
(an estimate's error), every tilde of a reading the same way; the enumeration of
:func:`rigidsym.numeval.random_points.residuals` keeps each reading it evaluates. The second
reading is not evaluated (an undeclared accent's meaning is the reader's), so a verdict
that rests on it alone is refused.
As the reader does (:mod:`rigidsym.latex.transformer.tilde`), written again here: this
semantics imports nothing of the symbolic one."""

from __future__ import annotations

import lark

from rigidsym.numeval import values as V

__all__ = ["POINT", "tilde_value"]

#: the choice point's key, one for every tilde of a reading
POINT = "tilde"
_OPTIONS = ("skew", "own")


def tilde_value(ev, t, key: str):
    """The value of the undeclared accented glyph ``t`` (its key ``key``) where it is a
    tilde over a 3-vector read as its cross-product matrix; ``None`` for any other accent
    or operand.

    Args:
        ev: the :class:`~rigidsym.numeval.evaluator.Evaluator` (its ``env`` and ``value``).
        t: the ``accented`` or ``accented_bare`` subtree.
        key: its glyph key (:func:`~rigidsym.numeval.evaluator.glyph_key`).

    Raises:
        NotCovered: the reading of the tilde as a vector of its own, which only a ``--let``
            declares (the enumeration drops that reading; alone, the check is refused).
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
    # a vector of its own: the reader's meaning, which only a --let gives (as for any
    # undeclared accent: x~ = x - x^ is Kalman's definition, not an identity to refute)
    text = " ".join(str(x) for x in t.scan_values(lambda x: isinstance(x, lark.Token)))
    raise V.NotCovered(f"the undeclared glyph {text} as a vector of its own (an accent's "
                       f"meaning is the reader's: --let '{key_text(t)}: vector')")


def key_text(t) -> str:
    """The LaTeX of an accented glyph's subtree, braced as a ``--let`` NAME is written
    (``\\tilde{\\mathbf{a}}``)."""
    toks = [str(x) for x in t.scan_values(lambda x: isinstance(x, lark.Token))]
    if len(toks) == 3 and toks[1] in ("\\mathbf", "\\boldsymbol", "\\bm"):  # \tilde \mathbf a
        return f"{toks[0]}{{{toks[1]}{{{toks[2]}}}}}"
    return f"{toks[0]}{{{''.join(toks[1:])}}}" if toks else ""


def reported(first, errors: list):
    """The error to report when no reading of the choice points is evaluated: a tilde read
    as a vector of its own where one was met (it names the ``--let`` that settles it), else
    the first reading's (``first``, or the first of ``errors``)."""
    own = [e for e in errors if "as a vector of its own" in str(e)]
    return own[0] if own else first or errors[0]
