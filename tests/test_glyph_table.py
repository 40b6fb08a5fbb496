"""The glyph table is a text's data, named by its reading (``[reading] glyphs``): the
chapter's lies beside the chapter's reading, every row checked when read (fail closed), and
the LaTeX reader consults it only where a text is read as the book's."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from _book import READING
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.core.errors import BadInput
from rigidsym.latex import parse_latex
from rigidsym.latex.table import COLUMNS, Glyph, glyph_table, read_glyph_table
from rigidsym.reading import glyph_file, load_reading, parse_reading

HEADER = ",".join(COLUMNS) + "\n"


def test_the_book_s_glyph_table_is_the_one_its_reading_names_beside_it():
    path = glyph_file(load_reading(READING))
    assert path == READING.with_name("angeles-chapter3.glyphs.csv") and path.is_file()
    assert glyph_table() == read_glyph_table(path) and len(glyph_table()) > 100


def test_src_holds_no_glyph_table():
    src = Path(__file__).resolve().parents[1] / "src"
    assert not [p for p in src.rglob("*.csv") if p.read_text("utf-8").count(",") > 0
                and "latex,section" in p.read_text("utf-8")]


def test_a_reader_s_latex_sees_no_row_unless_it_names_a_section():
    """``\\mathbf{t}`` is the chapter's twist (a 6-vector) only in the chapter's sections;
    in a text of one's own (the default) a bold lower-case letter is a 3-vector."""
    assert parse_latex(r"\mathbf{t} = \mathbf{t}").chains[0][0] == sp.MatrixSymbol("t", 3, 1)
    assert parse_latex(r"\mathbf{t} = \mathbf{t}", "3.4").chains[0][0].shape == (6, 1)


_key = st.sampled_from([r"\mathbf{a}", r"\mathbf{B}", r"\phi", r"\dot{\mathbf{u}}"])
_section = st.sampled_from(["*", "2", "2.1", "2.1.3"])
_shape = st.sampled_from([("scalar", ()), ("3", (3, 1)), ("4x3", (4, 3))])


@settings(max_examples=30)
@given(st.dictionaries(st.tuples(_key, _section), st.tuples(_shape, st.sampled_from(
    ["vector", "angle", "notation"])), max_size=6))
def test_a_table_reads_back_row_by_row(tmp_path_factory, rows):
    path = tmp_path_factory.mktemp("g") / "notes.glyphs.csv"
    text = "# a comment\n" + HEADER + "".join(
        f"{k},{s},n{i},{shape[0]},{kind},meaning {i},\n"
        for i, ((k, s), (shape, kind)) in enumerate(rows.items()))
    path.write_text(text, encoding="utf-8")
    assert read_glyph_table(path) == tuple(
        Glyph(k, s, f"n{i}", shape[1], kind, f"meaning {i}", "")
        for i, ((k, s), (shape, kind)) in enumerate(rows.items()))


@pytest.mark.parametrize(("text", "says"), [
    ("latex,section,name\n", "expected the header"),
    (HEADER + r"\mathbf{a},*,a,3,vector,m," + "\n" + r"\mathbf{a},*,b,3,vector,m," + "\n",
     "given twice for section"),
    (HEADER + r"\mathbf{a},*,a,three,vector,m," + "\n", "shape 'three'"),
    (HEADER + r"\mathbf{a},,a,3,vector,m," + "\n", "must be non-empty"),
])
def test_a_table_the_reader_cannot_trust_is_an_error_naming_it(tmp_path, text, says):
    path = tmp_path / "bad.glyphs.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(BadInput, match=f"glyph table .*bad.glyphs.csv.*{says}"):
        read_glyph_table(path)
    with pytest.raises(BadInput, match="cannot read the file"):
        read_glyph_table(tmp_path / "absent.csv")


def test_a_reading_names_its_glyph_table_beside_it(tmp_path):
    head = '[reading]\nformat = 1\npage = "notes.md"\n'
    path = tmp_path / "notes.reading.toml"
    path.write_text(head + 'glyphs = "notes.glyphs.csv"\n', encoding="utf-8")
    assert glyph_file(load_reading(path)) == tmp_path / "notes.glyphs.csv"
    assert glyph_file(parse_reading(head)) is None
    with pytest.raises(BadInput, match="no path to find it beside"):
        glyph_file(parse_reading(head + 'glyphs = "notes.glyphs.csv"\n'))
    with pytest.raises(BadInput, match=r"\[reading\] glyphs must be a non-empty string"):
        parse_reading(head + "glyphs = 3\n")
