"""Section 3.2's displacement, lines and pose read from the page: the symbol
table's lines of ``rigidsym.checking.certifying.displacement_symbols`` (the glyphs sections
3.2-3.2.3 define in words, by a later display or by the id's own definition) let certcheck's
second reader read those ids firmly; a changed line, a changed side and another id's text
are rejected naming the id. Four ids here, every id read through the lines in slow."""

from __future__ import annotations

import copy

import pytest
from _book import READING, book_path
from test_cert_page import (
    another_printed_text,
    book_text,
    certs_for,
    definitions_before,
    doubled_rhs,
    locate,
    rejection,
    relabelled,
    shifted_sides,
    unit_declared_free,
)

#: the ids the lines make read on every printed side (measured; 3.40's [Q] by its line: Q in
#: the triad's frame, the words before (3.39))
EVERY_SIDE = ["3.3", "3.5", "3.6a", "3.6b", "3.9a", "3.10", "3.11", "3.15", "3.21", "3.22",
              "3.23", "3.25", "3.26", "3.29a", "3.29b", "3.33", "3.34", "3.37", "3.39", "3.40"]


def _lines(c: dict, book: str) -> list[str]:
    from certcheck.compare import compare

    i = c["id"]
    return compare(c, locate(book, i), fast=True, defs=definitions_before(book, i))


def _mine(c: dict) -> list[str]:
    """The glyphs of the id's table that are this module's lines with LaTeX."""
    from _reading_groups import DISPLACEMENT_GLYPHS

    return [e["glyph"] for e in c["symbols"] if e["glyph"] in DISPLACEMENT_GLYPHS
            and "latex" in e]


def _doubled(c: dict, glyph: str) -> dict:
    """The table's line of ``glyph`` multiplied by 2 (another quantity of that name)."""
    t = copy.deepcopy(c)
    entry = next(e for e in t["symbols"] if e.get("glyph") == glyph)
    entry["latex"] = f"2({entry['latex']})"
    return t


def _tamperings(c: dict, book: str, other: str) -> list[dict]:
    """Each line of the module doubled, both sides shifted, the right sides doubled (where
    not 0), another id's printed text, the other verdicts, a unit declared free, a family
    in words transposed, and a marked chain member's right side doubled."""
    out = [_doubled(c, g) for g in _mine(c)]
    out += [shifted_sides(c), another_printed_text(c, book, other),
            *(relabelled(c, v) for v in ("verified", "definition", "does-not-hold")
              if v != c["verdict"])]
    if any(x != "0" for r in c["relations"] if r["role"] == "printed"
           for row in r["rhs"] for x in row):  # 2 x 0 is no change
        out.append(doubled_rhs(c))
    if (t := unit_declared_free(c)) is not None:
        out.append(t)
    for e in c["symbols"]:
        if e.get("family"):  # the family in words transposed
            t = copy.deepcopy(c)
            next(f for f in t["symbols"] if f.get("family"))["family"] = e["family"][::-1]
            out.append(t)
    for k, r in enumerate(c["relations"]):
        if "page" in r:
            t = copy.deepcopy(c)
            t["relations"][k]["rhs"] = [[f"2*({x})" for x in row] for row in r["rhs"]]
            out.append(t)
    return out


def test_lines_only_where_the_id_prints_the_glyph():
    """The reading gives a line where the id prints the glyph before the page defines it
    (3.10's A, b), as its own definition (3.11) or as the model derives it (3.15's alpha
    from A^T A), and nowhere else: 3.12 reads A through (3.11)."""
    from rigidsym.checking.certifying.reading_table import id_lets, reading_of

    reading = reading_of(READING)
    glyphs = {i: sorted(x.let.split(" = ")[0] for x in id_lets(reading, i) if " = " in x.let
                        and x.let.split(" = ")[0] in ("\\mathbf{A}", "\\mathbf{b}", "\\alpha",
                                                          "\\beta"))
              for i in ("3.10", "3.11", "3.12", "3.15")}
    assert glyphs == {"3.10": ["\\mathbf{A}", "\\mathbf{b}"],
                      "3.11": ["\\mathbf{A}", "\\mathbf{b}"], "3.12": [],
                      "3.15": ["\\alpha", "\\beta", "\\mathbf{A}"]}


def _twice_x(lines: list[dict]) -> dict:
    """A definition certificate of ``2 x = 2 x`` over a free 3-vector ``x``, its symbol table
    ``x`` and ``lines``."""
    x = ["x_1", "x_2", "x_3"]
    cert = {"format": "rigidsym-certificate", "version": 1, "id": "3.999",
            "verdict": "definition", "let": [],
            "atoms": [{"group": a, "kind": "free", "names": [a], "timed": False} for a in x],
            "symbols": [{"glyph": "\\mathbf{x}", "kind": "free", "atoms": x}, *lines],
            "relations": [{"role": "printed", "label": "", "lhs": [[f"2*{a}"] for a in x],
                           "rhs": [[f"2*{a}"] for a in x], "evidence": {"type": "statement"}}]}
    return cert


def test_reader_reads_a_vector_between_two_points_as_a_glyph():
    """``\\overrightarrow{AP_1}`` is one glyph of the table (3.37's triad); without its line
    it is NOT READ, never passed."""
    from certcheck.compare import compare

    cert = _twice_x([{"glyph": "\\overrightarrow{AP_1}", "latex": "2\\mathbf{x}",
                      "model": "twice x"},
                     {"glyph": "\\mathbf{e}_1", "latex": "2\\mathbf{x}", "model": "2 x"}])
    page = "\\mathbf{e}_1 \\equiv \\overrightarrow{AP_1}"
    lines = compare(cert, page, fast=False)
    assert lines[0].startswith("read from the page: relation 1's lhs") and " and rhs" in \
        lines[0], lines
    cert["symbols"] = cert["symbols"][:1] + cert["symbols"][2:]
    lines = compare(cert, page, fast=False)
    assert any(x.startswith("NOT READ: relation 1's rhs") for x in lines), lines


def test_reader_reads_a_family_the_table_states_in_words():
    """A relation with indices and no printed range (3.39's ``q_ij = e_i . e'_j``) is read as
    a family over 1, 2, 3 where a table line carries ``"family": "ij"`` (row i, column j);
    without it, NOT READ; with ``ji``, the transpose, which a non-symmetric side rejects."""
    from certcheck.check import CheckError
    from certcheck.compare import compare

    x = [f"x_{k}{m}" for k in (1, 2, 3) for m in (1, 2, 3)]
    lines = [{"glyph": f"q_{{{k}{m}}}", "latex": f"y_{{{k}{m}}}", "model": "q_km"}
             for k in (1, 2, 3) for m in (1, 2, 3)]
    lines += [{"glyph": f"y_{{{k}{m}}}", "kind": "free", "atoms": [f"x_{k}{m}"]}
              for k in (1, 2, 3) for m in (1, 2, 3)]
    lines += [{"glyph": f"z_{{{k}{m}}}", "kind": "free", "atoms": [f"x_{k}{m}"]}
              for k in (1, 2, 3) for m in (1, 2, 3)]
    lines[0]["family"] = "ij"
    rows = [x[3 * k:3 * k + 3] for k in range(3)]
    cert = {"format": "rigidsym-certificate", "version": 1, "id": "3.999",
            "verdict": "verified", "let": [],
            "atoms": [{"group": a, "kind": "free", "names": [a], "timed": False} for a in x],
            "symbols": lines, "relations": [{"role": "printed", "label": "", "lhs": rows,
                                             "rhs": rows, "evidence": {"type": "identity"}}]}
    page = "q_{ij} = z_{ij}"
    assert compare(cert, page, fast=False)[0].startswith(
        "read from the page: relation 1's lhs"), cert
    del lines[0]["family"]
    assert all(x.startswith("NOT READ") for x in compare(cert, page, fast=False))
    lines[0]["family"] = "ji"
    with pytest.raises(CheckError, match="3.999"):
        compare(cert, page, fast=False)


@pytest.fixture(scope="module")
def displacement_read(tmp_path_factory):
    book_path()  # skips where the chapter is absent (tests/_book.py)
    return certs_for(tmp_path_factory.mktemp("displacement"), ["3.6b", "3.10", "3.22", "3.29a"])


def test_displacement_ids_read_firmly_and_tamperings_rejected(displacement_read):
    """3.6b (a chain and a definition: its middle member the marked claim, d_par, d_perp,
    bold d_0 as printed), 3.10 (A p_0 = b before (3.11) prints A, b), 3.22 (e, n as
    printed, ||p_2 - p_1|| the model's length ell) and 3.29a (U of (3.29b), printed after
    it): every side read firmly; each line doubled, both sides
    shifted, the right side doubled, another id's text, the other verdicts, a unit declared
    free, the marked member changed: rejected naming the id."""
    book = book_text()
    for i, c in displacement_read.items():
        lines = _lines(c, book)
        assert lines and all(x.startswith("read from the page") for x in lines), (i, lines)
        assert _mine(c), i
        assert all(any(f"{g.replace(' ', '')} as the model's" in x for x in lines)
                   for g in _mine(c)), i
        for t in _tamperings(c, book, "3.8"):
            assert f"({i})" in rejection(t, book), i


@pytest.mark.slow
def test_chapter_section_3_2_read_through_the_lines_and_tamperings_rejected(tmp_path):
    """Every id the lines make read (3.15: alpha, beta as the model derives them from A^T A,
    against the printed values; 3.40's [Q], Q in the frame of the triad e_1, e_2, e_3 the
    words before (3.39) name): every printed side read firmly, each of its lines doubled and
    the acceptance list's tamperings rejected naming the id."""
    book_path()  # skips where the chapter is absent (tests/_book.py)
    book = book_text()
    for i, c in certs_for(tmp_path, EVERY_SIDE).items():
        lines = _lines(c, book)
        assert lines and all(x.startswith("read from the page") for x in lines), (i, lines)
        assert _mine(c) or i == "3.5", i  # 3.5: its marked member alone
        other = "3.8" if i != "3.8" else "3.12"
        for t in _tamperings(c, book, other):
            assert f"({i})" in rejection(t, book), i


def test_reader_reads_components_in_a_frame_the_table_names():
    """``[G]`` with no frame printed is read through the table's line of ``[G]`` (3.40's
    ``[Q]``: Q in the frame the page's words name); without that line it is NOT READ, and a
    line of another frame's components is rejected."""
    from certcheck.compare import compare

    from certcheck import CheckError

    cert = _twice_x([{"glyph": "[\\mathbf{x}]", "latex": "2\\mathbf{x}",
                      "model": "x in a frame of half the unit length"}])
    page = "[\\mathbf{x}] \\equiv 2\\mathbf{x}"
    lines = compare(cert, page, fast=False)
    assert lines[0].startswith("read from the page: relation 1's lhs (through [\\mathbf{x}]")
    assert "NOT READ" not in " ".join(lines), lines
    cert["symbols"][1]["latex"] = "\\mathbf{x}"
    with pytest.raises(CheckError, match=r"\(3\.999\) the printed lhs"):
        compare(cert, page, fast=False)
    cert["symbols"] = cert["symbols"][:1]
    assert compare(cert, page, fast=False)[0].startswith("NOT READ: relation 1's lhs ([G]")


def test_displaced_points_read_where_the_relation_cancels_the_translation():
    """3.1 (p' - a' = Q(p - a)): the relation cancels the displacement's translation c, yet
    the certificate keeps c as atoms, so p' and a' read as the model's displaced points
    (x' = Q x + c): both sides read. a''s line with 2c, both sides shifted and the verdict
    a definition: rejected naming the id."""
    from test_cert_page_momenta import certificates, line_changed, read_lines

    book_path()  # skips where the chapter is absent (tests/_book.py)
    book = book_text()
    c = certificates(["3.1"])["3.1"]
    lines = read_lines(c, book)
    assert len(lines) == 1 and lines[0].startswith("read from the page: relation 1's lhs")
    assert " and rhs" in lines[0] and "\\mathbf{a}' as the model's" in lines[0], lines
    assert "c_1" in {n for g in c["atoms"] for n in g["names"]}
    cases = [line_changed(c, "\\mathbf{a}'", "\\mathbf{c}", "2\\mathbf{c}"), shifted_sides(c),
             relabelled(c, "definition")]
    assert None not in cases
    for t in cases:
        assert "(3.1)" in rejection(t, book)


def test_a_determinant_read_from_the_page(tmp_path):
    """The reader's ``\\det`` expands a square array by its first row: a 3 x 3 array of
    numbers gives the determinant computed by hand (18; 0 with two equal rows), a 2 x 3 one
    is NOT READ. 3.30 (``det(U) = 1``, U by (3.29b), A and B the cross-product matrices of
    a and b) is read on both sides; its right side doubled, both sides shifted, another id's
    text and the other verdicts: rejected naming the id."""
    from certcheck.arrays import M, NotRead, det

    rows = [["2", "1", "0"], ["1", "3", "1"], ["0", "1", "4"]]
    assert eval(det(M(rows)).rows[0][0]) == 2 * (3 * 4 - 1) - 1 * (1 * 4 - 0)
    assert eval(det(M([rows[0], rows[0], rows[2]])).rows[0][0]) == 0
    with pytest.raises(NotRead, match="determinant"):
        det(M(rows[:2]))
    book = book_text()
    c = certs_for(tmp_path, ["3.30"])["3.30"]
    assert c["verdict"] == "restatement"
    lines = _lines(c, book)
    assert lines == ["read from the page: relation 1's lhs (through \\mathbf{U} by (3.29b)) "
                     "and rhs, the certificate's under the symbol table"], lines
    cases = [shifted_sides(c), doubled_rhs(c), another_printed_text(c, book, "3.29b")]
    cases += [relabelled(c, v) for v in ("verified", "definition", "does-not-hold")]
    for t in cases:
        assert "(3.30)" in rejection(t, book, page_first=True)
