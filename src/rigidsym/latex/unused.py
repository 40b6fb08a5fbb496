"""A ``--let`` the statement does not use: said back as a note, or refused as a near miss.

A reader shares one set of ``--let``s across a book's statements (as a document's reading
file does), so a declaration a statement does not use is no error in itself. It is one when
it may be a misspelling: the statement holds a glyph that nothing declares, read by a
default (a free symbol of the conventional shape, a reading of an undeclared hat, the
identity of a bold capital), whose spelling is near the ``--let``'s NAME (the same letter
under another font, accent, subscript, superscript, left index or prime: ``\\mathbf{L}``
and ``L_1``, ``\\omega`` and ``\\hat{\\omega}``). Then the ``--let`` was likely meant for
that glyph, which has fallen back to the default reading: bad input, naming both
spellings. Otherwise the ``--let`` is ignored and the reading says so (``not used: ...``).
"""

from __future__ import annotations

import re

from rigidsym.core.errors import BadInput

__all__ = ["base_letter", "defaulted_glyphs", "near_spellings", "unused_lets"]

#: the font and accent macros a glyph's letter may stand under
_WRAPPERS = re.compile(
    r"\\(?:math(?:bf|rm|it|sf|tt|cal|bb|frak|scr)|boldsymbol|bm|pmb|vec|overrightarrow|"
    r"widetilde|tilde|widehat|hat|ddot|dot|bar|overline|check|breve|mathring|acute|grave|"
    r"underline)"
    r"(?![A-Za-z])")
#: a left index, ``{}^{G}`` or ``{}_B``
_LEFT_INDEX = re.compile(r"^\{\}[\^_](?:\{[^{}]*\}|\\?[A-Za-z0-9]+)")


def base_letter(key: str) -> str | None:
    """The letter a glyph key names, under its fonts, accents, indices and primes
    (``\\tilde{\\boldsymbol{\\omega}}'`` and ``{}^{G}\\omega_{B}``: ``\\omega``); ``None`` for a
    key with no letter."""
    s = key.strip()
    while (m := _LEFT_INDEX.match(s)) is not None:
        s = s[m.end():]
    s = _WRAPPERS.sub("", s).replace("{", "").replace("}", "").lstrip()
    m = re.match(r"\\[A-Za-z]+|[A-Za-z]", s)
    return m.group(0) if m else None


#: a reading note of a glyph read by default (``\\mathbf{I}: the identity (no --let ...``)
_DEFAULT_NOTE = re.compile(r"^(?:in --let '.*?': )?(\S+): the identity \(no --let declares")


def defaulted_glyphs(occurs, declared, rd, notes) -> set[str]:
    """The glyph keys of ``occurs`` that no ``--let`` declares (``declared``: their keys) and
    that are read by a default: a free symbol of the conventional shape, one reading of a
    choice point (an undeclared hat: a unit vector or a skew matrix), the identity of a
    bold capital (said in ``notes``). A rate of a declared function, a module's symbol, a
    ``--book`` row and a ``--notation`` line are read by what the user chose: not defaults.

    Args:
        occurs: the glyph keys of the LaTeX and the models.
        declared: the keys the ``--let``s declare.
        rd: the :class:`~rigidsym.latex.reader_glyphs.GlyphReader` that read them.
        notes: the reading's notes.
    """
    out = set()
    for k in set(occurs) - set(declared):
        g = rd.over.get(k) or rd.glyphs.get(k)
        if g is None or k in rd.by_notation or g.kind == "module" or g.section != "*" \
                or g.meaning.startswith("the time derivative of") \
                or g.meaning == "body velocity":  # the reader's own, never the user's
            continue
        out.add(k)
    return out | {m.group(1) for n in notes if (m := _DEFAULT_NOTE.match(n))} - set(declared)


def near_spellings(key: str, candidates) -> list[str]:
    """The ``candidates`` (glyph keys) spelt near ``key``: another key of the same letter."""
    letter = base_letter(key)
    if letter is None:
        return []
    return sorted(k for k in candidates if k != key and base_letter(k) == letter)


def unused_lets(unused, defaulted, glyphs, occurring=()) -> list[str]:
    """The notes that say back the ``unused`` ``--let``s (each with ``.key`` and ``.text``).

    Args:
        unused: the ``--let``s whose NAME occurs neither in the LaTeX nor in a model.
        defaulted: the keys of the glyphs nothing declares, read by a default
            (:func:`defaulted_glyphs`).
        glyphs: the LaTeX's glyph keys, named in a refusal.
        occurring: every glyph key of the LaTeX and its models that no ``--let``
            declares: an unused ``--let`` of a letter one of them writes (Wie's
            ``\\mathbf{q}(t): unit 4-vector`` beside the entries ``q_1 ... q_4``) may hold
            what they need (a unit norm, a time), so it is never ignored; beside a glyph a
            ``--let`` declares (Wen & Kreutz-Delgado's ``\\bar{q}``) it is the book's shared
            line, ignored.

    Returns:
        One note, ``not used: --let '...'; ...``, or none when nothing is unused.

    Raises:
        BadInput: an unused ``--let`` whose NAME is spelt near a defaulted glyph (the likely
            misspelling), naming both and what to write.
    """
    for x in unused:
        near = near_spellings(x.key, defaulted) or near_spellings(x.key, occurring)
        if near:
            names = ", ".join(near)
            raise BadInput(
                f"--let '{x.text}': {x.key} does not occur in the LaTeX nor in a model, and "
                f"the LaTeX's {names}, which no --let declares, is spelt near it (the "
                f"LaTeX's glyphs: {', '.join(sorted(glyphs)) or 'none'}): declare the "
                f"name as the LaTeX writes it (--let '{near[0]}: KIND' or "
                f"--let '{near[0]} = ...'), or write {x.key} in the LaTeX")
    if not unused:
        return []
    return ["not used: " + "; ".join(f"--let '{x.text}'" for x in unused)
            + " (its NAME occurs neither in the LaTeX nor in a model; ignored)"]
