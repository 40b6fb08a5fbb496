"""The relations a page prints under its braces, decided from the page: each
``\\underbrace{X}_{Y}`` is the printed relation ``X = Y`` unless its label Y is a count in
words (``_{2k \\text{ factors}}``) or a name the page uses in words only: a glyph the brace
introduces (not defined on the page before the id), printed in no later display and not
modelled by the id's symbol table (3.4's ``d_{P/A}``), which names X and claims nothing. A
label printed in a later display (3.130's ``I_C``), one defined before (3.129's ``m``), one
the table models (3.59's ``ṗ⊥``) or an expression (3.129's ``-R^2``) is a printed relation
of the id, so a certificate that leaves it out proves fewer relations than the page prints
(:func:`certcheck.compare.compare`)."""

from __future__ import annotations

import re
from itertools import accumulate

from certcheck.reader import tokens

__all__ = ["brace_relations", "displays_after"]

# a bare glyph: a letter or a command, bold or Greek, with a dot, primes and subscripts
_GLYPH = re.compile(r"(\\(?:dot|ddot|tilde)\{)?(\\(?:mathbf|boldsymbol)\{[^{}]*\}|\\?[A-Za-z]+)"
                    r"\}?(?:'|_\{[^{}]*\}|_\w)*")


def displays_after(book: str, eq_id: str) -> str:
    """The book's displays after ``eq_id``'s, joined, spaces removed ("" when the id is
    not found): a glyph printed there is a quantity of the page, not a name in words."""
    tag = re.compile(r"(?:\(\s*|\\tag\{)" + re.escape(eq_id) + r"\s*[)}]")
    shown = re.findall(r"\$\$(.*?)\$\$", book, re.S)
    k = next((n for n, d in enumerate(shown) if tag.search(d)), len(shown))
    return "".join(shown[k + 1:]).replace(" ", "")


def brace_relations(page: str, symbols: list, defs: dict, later: str = "") -> list[str]:
    """The printed relations ``X = Y`` of ``page``'s braces, in the page's order.

    Args:
        page: the id's printed LaTeX (its display, the tag removed).
        symbols: the certificate's symbol table (a label glyph it models is held to X).
        defs: the glyphs defined on the page before the id
            (:func:`certcheck.book.definitions_before`).
        later: the book's displays after the id (:func:`displays_after`).
    """
    t = tokens(page)
    table = {str(e.get("glyph")).replace(" ", "") for e in symbols if isinstance(e, dict)}
    depth = list(accumulate((c == "{") - (c == "}") for c in t))
    out = []
    for i in (k for k, x in enumerate(t[:-1]) if x == "\\underbrace" and t[k + 1] == "{"):
        j = depth.index(depth[i], i + 1)  # X's closing brace
        y = t[j + 3:depth.index(depth[i], j + 3)] if t[j + 2:j + 3] == ["{"] else t[j + 2:j + 3]
        label = "".join(y)
        named = _GLYPH.fullmatch(label) and label not in table and label not in defs
        if "\\text" in y or not y or named and label not in later:  # a count in words, or
            continue  # a name the brace introduces and the page uses in words only
        out.append(" ".join(t[i + 2:j]) + " = " + " ".join(y))
    return out
