"""The glyph table of a text: one row per glyph and section, as data its reading names.

A text's reading (:mod:`rigidsym.reading`) may name a glyph table, a CSV beside it
(``[reading] glyphs``); the book's reading names the chapter's
(:func:`rigidsym.registry.declarations.book_reading`). A row gives the glyph's LaTeX key
(``\\mathbf{d}_{P}``, ``\\dot{\\boldsymbol{\\omega}}``), the section it applies to (``*`` for
every section, or ``3.2.1``: a more specific section wins), the name of the book symbol in
the declarations (``d_P``), its shape (``3``, ``4x3``, ``scalar``), its kind (``vector``,
``matrix``, ``scalar``, ``angle``, or a notation such as ``norm``), its meaning in words,
and for a notational atom its definition in LaTeX (the transcription check replaces the
atom by it). The book reuses letters (``W`` three times, ``U``, ``s``, ``η``, ``p``): the
section column tells them apart. The rows are consulted only where a text is read as the
book's (a declaration's LaTeX, ``--book SECTION``): a reader's own LaTeX sees none of them.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from rigidsym.core.errors import BadInput
from rigidsym.reading import glyph_file, load_reading

__all__ = ["Glyph", "glyph_table", "lookup", "read_glyph_table"]


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


#: the columns of a glyph table, in order (``definition`` may be left out)
COLUMNS = ("latex", "section", "name", "shape", "kind", "meaning", "definition")


@cache
def read_glyph_table(path: Path) -> tuple[Glyph, ...]:
    """The rows of the glyph table at ``path`` (a CSV; ``#`` lines are comments).

    Args:
        path: the CSV file, with the header row :data:`COLUMNS`.

    Returns:
        Its rows as :class:`Glyph` objects, in file order (read once per process and path).

    Raises:
        BadInput: a file that cannot be read, a header other than :data:`COLUMNS`, a row
            with an empty key, section or name, a shape that is not ``scalar``, ``n`` or
            ``rxc``, or one glyph given twice for one section (each naming the file and row).
    """
    try:
        text = Path(path).read_text("utf-8")
    except OSError as exc:
        raise BadInput(f"glyph table {path}: cannot read the file ({exc.strerror})") from None
    reader = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    if tuple(reader.fieldnames or ()) not in (COLUMNS, COLUMNS[:-1]):
        raise BadInput(f"glyph table {path}: expected the header {','.join(COLUMNS)}, got "
                       f"{','.join(reader.fieldnames or ())!r}")
    rows, seen = [], set()
    for n, r in enumerate(reader, start=1):
        where = f"glyph table {path}: row {n}"
        if not all((r.get(k) or "").strip() for k in ("latex", "section", "name")):
            raise BadInput(f"{where}: latex, section and name must be non-empty")
        try:
            shape = glyph_shape(r["shape"] or "")
        except ValueError:
            raise BadInput(f"{where}: shape {r['shape']!r}; expected scalar, n or rxc") from None
        if (r["latex"], r["section"]) in seen:
            raise BadInput(f"{where}: {r['latex']} is given twice for section {r['section']}")
        seen.add((r["latex"], r["section"]))
        rows.append(Glyph(r["latex"], r["section"], r["name"], shape, r["kind"], r["meaning"],
                          r.get("definition") or ""))
    return tuple(rows)


@cache
def glyph_table() -> tuple[Glyph, ...]:
    """The book's glyph table: the one its reading names (``[reading] glyphs``).

    Returns:
        Its rows, in file order (read once per process).

    Raises:
        BadInput: the book names no reading, or its reading names no glyph table (a book
            section cannot name glyphs then), or as ``read_glyph_table`` of this module.
    """
    from rigidsym.registry.declarations import book_reading

    path = book_reading()
    if path is None:
        raise BadInput("the book names no reading file (READING), so no glyph table names "
                       "the glyphs of its sections")
    table = glyph_file(load_reading(path))
    if table is None:
        raise BadInput(f"reading {path}: names no glyph table ([reading] glyphs), so the "
                       f"glyphs of the book's sections have no rows")
    return read_glyph_table(table)


@cache
def _index() -> dict:
    out: dict = {}
    for g in glyph_table():
        out[(g.latex, g.section)] = g
    return out


def lookup(latex: str, section: str = "*") -> Glyph | None:
    """The row of the book's glyph table for a glyph in a section.

    Args:
        latex: the glyph's LaTeX key as the parser normalises it (``\\mathbf{d}_{P}``).
        section: a book (sub)section (``"3.4.2"``) or ``"*"``.

    Returns:
        The row of the most specific section that lists the glyph (``3.4.2``, then
        ``3.4``, then ``*``), or ``None``.

    Raises:
        BadInput: as :func:`rigidsym.latex.glyph_table`.
    """
    idx = _index()
    parts = section.split(".") if section != "*" else []
    while parts:
        g = idx.get((latex, ".".join(parts)))
        if g is not None:
            return g
        parts.pop()
    return idx.get((latex, "*"))
