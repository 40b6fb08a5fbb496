"""A ``--let`` the statement does not use: said back as a note, or refused as a near miss.

A reader shares one set of ``--let``s across a book's statements (as a document's reading
file does), so a declaration a statement does not use is no error in itself. It is one when
it may be a misspelling: the statement holds a glyph that nothing declares, read as a free
symbol by default, whose spelling is near the ``--let``'s NAME (the same letter under another
font, accent, subscript, superscript, left index or prime: ``\\mathbf{L}`` and ``L_1``,
``\\omega`` and ``\\hat{\\omega}``). Then the ``--let`` was likely meant for that glyph, which
has fallen back to the default reading: bad input, naming both spellings. Otherwise the
``--let`` is ignored and the reading says so (``not used: ...``).
"""

from __future__ import annotations

import re

from rigidsym.core.errors import BadInput

__all__ = ["base_letter", "near_spellings", "unused_lets"]

#: the font and accent macros a glyph's letter may stand under
_WRAPPERS = re.compile(
    r"\\(?:math(?:bf|rm|it|sf|tt|cal|bb|frak|scr)|boldsymbol|bm|pmb|vec|overrightarrow|"
    r"widetilde|tilde|widehat|hat|ddot|dot|bar|overline|check|breve|acute|grave|underline)"
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


def near_spellings(key: str, candidates) -> list[str]:
    """The ``candidates`` (glyph keys) spelt near ``key``: another key of the same letter."""
    letter = base_letter(key)
    if letter is None:
        return []
    return sorted(k for k in candidates if k != key and base_letter(k) == letter)


def unused_lets(unused, defaulted, glyphs) -> list[str]:
    """The notes that say back the ``unused`` ``--let``s (each with ``.key`` and ``.text``).

    Args:
        unused: the ``--let``s whose NAME occurs neither in the LaTeX nor in a model.
        defaulted: the keys of the glyphs nothing declares, read by default as free symbols.
        glyphs: the LaTeX's glyph keys, named in a refusal.

    Returns:
        One note, ``not used: --let '...'; ...``, or none when nothing is unused.

    Raises:
        BadInput: an unused ``--let`` whose NAME is spelt near a defaulted glyph (the likely
            misspelling), naming both and what to write.
    """
    for x in unused:
        near = near_spellings(x.key, defaulted)
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
