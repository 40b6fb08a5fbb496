"""The glyph table: one row per glyph of the chapter and section, as data (``glyphs.csv``).

A row gives the glyph's LaTeX key (``\\mathbf{d}_{P}``, ``\\dot{\\boldsymbol{\\omega}}``),
the section it applies to (``*`` for every section, or ``3.2.1``: a more specific section
wins), the name of the book symbol in the declarations (``d_P``), its shape (``3``, ``4x3``,
``scalar``), its kind (``vector``, ``matrix``, ``scalar``, ``angle``, or a notation such as
``norm``), its meaning in words, and for a notational atom its definition in LaTeX (the
transcription check replaces the atom by it). The book reuses letters (``W`` three times,
``U``, ``s``, ``η``, ``p``): the section column tells them apart. Built from
``NOTATION.md``'s book-symbol table and the chapter's own uses; read by the parser and by
``rigidsym show``.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import cache
from importlib import resources

__all__ = ["Glyph", "glyph_table", "lookup"]


@dataclass(frozen=True)
class Glyph:
    """One row of the glyph table.

    Attributes:
        latex: the glyph's LaTeX key, as the parser normalises it.
        section: ``*`` or a book (sub)section (``"3.4.2"``).
        name: the book symbol's name in the declarations (``MatrixSymbol``/``Symbol``).
        shape: ``()`` for a scalar, else ``(rows, cols)``.
        kind: ``vector``, ``matrix``, ``scalar``, ``angle``, ``notation`` ...
        meaning: in words.
        definition: for a notational atom, its definition in LaTeX; else ``""``.
    """

    latex: str
    section: str
    name: str
    shape: tuple
    kind: str
    meaning: str
    definition: str = ""


def glyph_shape(text: str) -> tuple:
    """The shape of a glyph table's shape cell: ``()`` for a scalar (empty or ``scalar``),
    ``(r, c)`` for ``rxc`` and ``(n, 1)`` for ``n``."""
    text = text.strip()
    if text in ("", "scalar"):
        return ()
    if "x" in text:
        r, c = text.split("x")
        return int(r), int(c)
    return int(text), 1


@cache
def glyph_table() -> tuple[Glyph, ...]:
    """Every row of the glyph table.

    Returns:
        The rows of ``glyphs.csv`` as :class:`Glyph` objects, in file order (read once per
        process).
    """
    text = resources.files("rigidsym.latex").joinpath("glyphs.csv").read_text("utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return tuple(Glyph(r["latex"], r["section"], r["name"], glyph_shape(r["shape"]), r["kind"],
                       r["meaning"], r.get("definition") or "") for r in rows)


@cache
def _index() -> dict:
    out: dict = {}
    for g in glyph_table():
        out[(g.latex, g.section)] = g
    return out


def lookup(latex: str, section: str = "*") -> Glyph | None:
    """The row for a glyph in a section.

    Args:
        latex: the glyph's LaTeX key as the parser normalises it (``\\mathbf{d}_{P}``).
        section: a book (sub)section (``"3.4.2"``) or ``"*"``.

    Returns:
        The row of the most specific section that lists the glyph (``3.4.2``, then
        ``3.4``, then ``*``), or ``None``.
    """
    idx = _index()
    parts = section.split(".") if section != "*" else []
    while parts:
        g = idx.get((latex, ".".join(parts)))
        if g is not None:
            return g
        parts.pop()
    return idx.get((latex, "*"))
