"""Lines of a pitch the page defines twice in one display, once per unit.

(3.7), (3.53) and (3.109) each print their pitch as ``G \\equiv X \\quad \\text{or} \\quad G
\\equiv Y`` (for (3.109) ``G = Y``), and the words after the display give the units: "m/rad
or, correspondingly, of m/turn". One table line for ``G`` cannot serve both alternatives
(``X = Y`` only where the pitch is zero), so each certificate relation of an alternative
(labelled ``G in m/rad`` or ``G in m/turn`` in the derivation) carries its own line: ``G``
as that alternative's first member prints it, with the alternative's unit. certcheck holds
those lines to the page (each the first member of its alternative, verbatim, its unit the
words' k-th) and reads each alternative under its own line.

Reading ``G`` through the page's own definiens checks what a definition can be checked for:
that the certificate's side for ``G`` is the page's definiens under the table's lines of
the other glyphs (``d_0``, ``v_0``, ``n_0``), in the alternative's unit; the other members
of the chain (``= d_P^T e / phi``, ...) are read against the same line, a real check.
"""

from __future__ import annotations

import re

__all__ = ["PITCHES", "unit_symbols"]

#: the section -> (the id, the pitch's glyph, its first member in m/rad, in m/turn), as the
#: page prints them
PITCHES = {
    "3.2": ("3.7", "p", r"\frac{d_0}{\phi}", r"\frac{2\pi d_0}{\phi}"),
    "3.4.1": ("3.53", "p'", r"\frac{v_0}{\|\boldsymbol{\omega}\|}",
              r"\frac{2\pi v_0}{\|\boldsymbol{\omega}\|}"),
    "3.7": ("3.109", "p''", r"\frac{n_0}{\|\mathbf{f}\|}",
            r"\frac{2\pi \mathbf{n}_P \cdot \mathbf{f}}{\|\mathbf{f}\|^2}"),
}


def unit_symbols(label: str, section: str) -> list[dict]:
    """The line of one alternative's pitch for a relation labelled ``G in m/rad`` or ``G in
    m/turn`` in the section of :data:`PITCHES` that defines ``G`` (``{"glyph", "latex",
    "printed_as", "unit"}``); ``[]`` for any other label or section."""
    m = re.fullmatch(r"(p'*) in (m/rad|m/turn)", label or "")
    if m is None or section not in PITCHES or PITCHES[section][1] != m.group(1):
        return []
    eq_id, glyph, rad, turn = PITCHES[section]
    return [{"glyph": glyph, "latex": rad if m.group(2) == "m/rad" else turn,
             "printed_as": f"({eq_id})", "unit": m.group(2)}]
