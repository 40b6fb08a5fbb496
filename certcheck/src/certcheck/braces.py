"""The relations a page prints under its braces, decided from the page: each
``\\underbrace{X}_{Y}`` is the printed relation ``X = Y`` unless its label Y is a count in
words (``_{2k \\text{ factors}}``) or a glyph the brace introduces that the certificate does
not model (3.4's ``d_{P/A}``: neither in the id's symbol table nor defined on the page
before the id), which names X and claims nothing. A label the symbol table models (3.130's
``I_C``, 3.59's ``ṗ⊥``), one defined on the page before (3.129's ``m``) or an expression
(3.129's ``-R^2``) is a printed relation of the id, so a certificate that leaves it out
proves fewer relations than the page prints (:func:`certcheck.compare.compare`)."""

from __future__ import annotations

import re
from itertools import accumulate

from certcheck.reader import tokens

__all__ = ["brace_relations"]

# a bare glyph: a letter or a command, bold or Greek, with a dot, primes and subscripts
_GLYPH = re.compile(r"(\\(?:dot|ddot|tilde)\{)?(\\(?:mathbf|boldsymbol)\{[^{}]*\}|\\?[A-Za-z]+)"
                    r"\}?(?:'|_\{[^{}]*\}|_\w)*")


def brace_relations(page: str, symbols: list, defs: dict) -> list[str]:
    """The printed relations ``X = Y`` of ``page``'s braces, in the page's order.

    Args:
        page: the id's printed LaTeX (its display, the tag removed).
        symbols: the certificate's symbol table (a label glyph it models is held to X).
        defs: the glyphs defined on the page before the id
            (:func:`certcheck.book.definitions_before`).
    """
    t = tokens(page)
    table = {str(e.get("glyph")).replace(" ", "") for e in symbols if isinstance(e, dict)}
    depth = list(accumulate((c == "{") - (c == "}") for c in t))
    out = []
    for i in (k for k, x in enumerate(t[:-1]) if x == "\\underbrace" and t[k + 1] == "{"):
        j = depth.index(depth[i], i + 1)  # X's closing brace
        y = t[j + 3:depth.index(depth[i], j + 3)] if t[j + 2:j + 3] == ["{"] else t[j + 2:j + 3]
        label = "".join(y)
        if "\\text" in y or not y or _GLYPH.fullmatch(label) and label not in table and \
                label not in defs:  # a count in words, or a name the brace introduces
            continue
        out.append(" ".join(t[i + 2:j]) + " = " + " ".join(y))
    return out
