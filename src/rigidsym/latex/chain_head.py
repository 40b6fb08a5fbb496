"""A chain headed by a name that nothing declares: ``A = X = Y`` read as the definition
``A = X``, then the claim ``X = Y``.

Bottema & Roth print the rotation in Euler parameters as ``A = \\frac{1}{\\Delta}[\\dots] =
(I - B)^{-1}(I + B)``: the chain names ``A`` by its first link and claims the rest. The reader's
convention would make an undeclared ``A`` a scalar, and the statement a shape error. Where no
``--let`` declares the head and no ``--book`` or ``--notation`` names glyphs, where the head is
one glyph that occurs nowhere else (in the chain's other sides, in a declaration), the first
link is its definition, as the document reader takes a relation whose left side is not yet
defined (:mod:`rigidsym.documents`). The statement that both semantics read is then the rest of
the chain, and the reading says so. A head that something declares stays a claim.
"""

from __future__ import annotations

import re

import lark
import sympy as sp

from rigidsym.core.errors import BadInput

__all__ = ["defined_head"]

#: a glyph key's subscript, accent or font: what is left names the letter
_DRESS = re.compile(r"_\{[^{}]*\}|\\(?:mathbf|boldsymbol|bm|dot|ddot|hat|bar|tilde|check|"
                    r"breve|mathring|vec)\{|[{}]")


def _stem(key: str) -> str:
    """The letter of a glyph key: ``\\mathbf{q}_{1}`` and ``\\dot{q}`` are ``q``."""
    return _DRESS.sub("", key).strip()


def _glyphs(text: str) -> set[str] | None:
    """The glyph keys of ``text`` (LaTeX of one side or a model), ``None`` where it cannot be
    read alone."""
    from rigidsym.latex import LatexError, parse_latex

    try:
        return set(parse_latex(f"{text} = 0", None).glyphs)
    except (LatexError, BadInput, ValueError, TypeError):
        return None


def defined_head(latex: str, let: object, *, book: str | None = None,
                 notation: str | None = None) -> tuple[str, object, str]:
    """``(latex, let, note)``: the chain ``HEAD = X = Y ...`` without its first link where
    HEAD is one glyph that no declaration names and that occurs nowhere else (the first link
    its definition); ``note`` says so. Else all unchanged and ``note`` is ``""``.

    Args:
        latex: the statement, as ``check --latex`` takes it.
        let: its declarations (:func:`rigidsym.latex.lets.read_lets`'s forms).
        book: a ``--book`` section (its glyph table declares glyphs: nothing is respelt).
        notation: a ``--notation`` (its kinds declare glyphs: nothing is respelt).

    Returns:
        The LaTeX to read, the declarations (unchanged) and the note.
    """
    from rigidsym.latex import LatexError
    from rigidsym.latex.lets import read_lets
    from rigidsym.latex.lexing import parsed_text, tree

    if book is not None or notation is not None:
        return latex, let, ""
    try:
        parsed = tree(latex)
        lets = read_lets(let)
    except (LatexError, BadInput, ValueError, TypeError):
        return latex, let, ""  # read later, where the error is said
    chains = [c for c in parsed.children if isinstance(c, lark.Tree) and c.data == "chain"]
    if len(chains) != 1 or len(chains[0].children) < 5:
        return latex, let, ""
    kids = chains[0].children
    head, side = kids[0], kids[2]
    if not all(isinstance(k, lark.Tree) and not k.meta.empty for k in (head, side)):
        return latex, let, ""
    text = parsed_text(latex)
    head_text = text[head.meta.start_pos:head.meta.end_pos].strip()
    from rigidsym.latex import parse_latex

    try:
        alone = parse_latex(f"{head_text} = 0", None)
    except (LatexError, BadInput, ValueError, TypeError):
        return latex, let, ""
    if len(alone.glyphs) != 1 or not isinstance(alone.chains[0][0], sp.Symbol | sp.MatrixSymbol):
        return latex, let, ""
    key = next(iter(alone.glyphs))
    declared = {x.key for x in lets}
    if key in declared or _stem(key) in {_stem(k) for k in declared}:
        return latex, let, ""
    rest = text[side.meta.start_pos:]
    elsewhere = [_glyphs(rest)] + [_glyphs(x.latex) for x in lets if x.latex]
    if any(g is None or any(_stem(k) == _stem(key) for k in g) for g in elsewhere):
        return latex, let, ""
    first = text[side.meta.start_pos:side.meta.end_pos].strip()
    first = first if len(first) <= 60 else first[:57].rstrip() + " ..."
    note = (f"{head_text}: no --let declares it, and it heads the chain: read as defined by "
            f"its first link ({head_text} = {first}); the rest of the chain is checked "
            f"(--let '{head_text}: KIND' makes the first link a claim)")
    return text[:head.meta.start_pos] + rest, let, note
