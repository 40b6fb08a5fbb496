"""The tilde over a vector in a reader's LaTeX (the second outside trial): the
cross-product matrix in the multibody and attitude books (Wittenburg's and Shabana's
``\\tilde{\\mathbf{a}}``, Greenwood's and Schaub & Junkins' ``\\tilde\\omega``: ``\\tilde{a} b
= a \\times b``), a vector of its own elsewhere (an estimate's error ``\\tilde{\\mathbf{x}}``).

An undeclared ``\\tilde{X}`` of a 3-vector ``X`` is a choice point of the reader (
item 2; :mod:`rigidsym.latex.statement`): every tilde of the LaTeX and its models read the
one way or the other together (a book writes it one way), each reading that type-checks
decided, a verdict only when all agree. A ``--let`` of the tilde's own glyph settles it
(``--let '\\tilde{\\mathbf{a}}: vector'``, ``--let '\\tilde{\\mathbf{a}} =
[\\mathbf{a}]_\\times'``). The second semantics reads it alike
(:mod:`rigidsym.numeval.tilde`).
"""

from __future__ import annotations

from rigidsym.algebra import rigid_motions
from rigidsym.latex.shapes import LatexError, matrix_shape

__all__ = ["TILDE_POINT", "own_tilde", "tilde_of"]

#: the key of the tilde choice point: one for all the tildes of a reading
TILDE_POINT = "\\tilde"


def tilde_of(tr, key: str, inner):
    """The value of ``\\tilde{inner}`` (glyph key ``key``) in the reading ``tr`` (a
    ``LatexTransformer``) where it is a choice: the cross-product matrix of the 3-vector
    ``inner.value``, or ``None`` (the glyph of its own, by the rules: a vector's tilde when
    the reading chose so, or no choice at all: a declared tilde, a tilde of no 3-vector).

    Args:
        tr: the transformer (its ``overrides``, ``choices``, ``choice_points``, ``_note``).
        key: the tilde glyph's key, ``\\tilde{\\mathbf{a}}``.
        inner: the :class:`~rigidsym.latex.transformer.glyphs.GlyphKey` under the tilde.
    """
    from rigidsym.latex.transformer.meanings import alternatives

    if not getattr(tr, "reader", False) or key in tr.overrides \
            or matrix_shape(inner.value) != (3, 1):
        return None
    tr.choice_points.setdefault(TILDE_POINT, alternatives(TILDE_POINT))
    if tr.choices.get(TILDE_POINT, "skew") != "skew":
        tr._note(f"{key}: a vector of its own (a choice: or the cross-product matrix "
                 f"[{inner.key}]_\\times)")
        return None
    tr._note(f"{key}: the cross-product matrix [{inner.key}]_\\times, as in Wittenburg, "
             f"Shabana, Greenwood, Schaub & Junkins (a choice: or a vector of its own)")
    # the chapter's CPM, not a reader's bracket: [\tilde{a}] is then never Shuster's [[a]]
    return rigid_motions.hat(inner.value)


def own_tilde(tr, x) -> None:
    """``[\\tilde{\\mathbf{a}}]`` where the reading takes the tilde as a vector of its own:
    Schaub & Junkins' bracket marks the tilde *matrix*, never the hat of a vector named
    ``\\tilde{a}``; that reading is dropped (a shape error) so only the matrix one stays.

    Raises:
        LatexError: in that reading, naming the bracket.
    """
    key = getattr(x, "key", "")
    if getattr(tr, "reader", False) and key.startswith("\\tilde{") and key not in tr.overrides \
            and tr.choices.get(TILDE_POINT) == "own":
        raise LatexError(f"[{key}]: the bracket of Schaub & Junkins' tilde matrix, not the "
                         f"hat of a vector of its own", "shapes")
