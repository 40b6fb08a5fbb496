"""Spellings of one glyph that the second semantics takes as one (issue 63): an accent over a
bare letter followed by a subscript, ``\\dot{\\Omega}_1`` or ``\\dot\\Omega_1``, is the
accent over the subscripted letter, ``\\dot{\\Omega_1}`` (TeX sets the same glyph, and the
reader keys them alike). Imports lark and the standard library only."""

from __future__ import annotations

import lark

__all__ = ["canonical"]


def canonical(t):
    """``t`` with an accent's trailing subscript moved under the accent; any other tree as
    it is.

    Args:
        t: a parse subtree (``accented``, ``accented_bare``, or anything).
    """
    if not isinstance(t, lark.Tree) or t.data not in ("accented", "accented_bare") \
            or len(t.children) != 3:
        return t
    accent, inner, sub = t.children
    if not isinstance(sub, lark.Tree) or sub.data != "subscript":
        return t
    if t.data == "accented_bare":
        base = lark.Tree("base", list(inner.children))
    elif inner.data == "glyph" and len(inner.children) == 1 \
            and isinstance(inner.children[0], lark.Tree):
        base = inner.children[0]
    else:
        return t
    return lark.Tree("accented", [accent, lark.Tree("glyph", [base, sub])])
