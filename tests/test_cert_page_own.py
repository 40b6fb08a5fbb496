"""Glyphs sections 3.7 and 3.8 define on the id itself, read by certcheck's second reader:
``Gamma``, ``w_A``, ``w_P``, ``V``, ``q_O``, ``c``, ``r``,
``T``, ``M``, ``I_A``, ``M_A`` as symbol-table lines
(``checking/certifying/wrench_inertia_symbols.py``), the centre of mass and a body point
where the certificate's relation is free of the body's shape, the particles' ``r_i = Q
rho_i`` where it is free of ``o`` (3.138), and an ``\\underbrace{X}_{Y}`` read as the
printed relation ``X = Y`` where the certificate proves it (3.129, 3.130). Tamperings by
mathematics on 3.112, 3.118 and 3.125 here, on the other newly read ids in slow."""

from __future__ import annotations

import copy

import pytest
from _book import book_path
from test_cert_page import (
    another_printed_text,
    book_text,
    certs_for,
    doubled_rhs,
    rejection,
    relabelled,
    shifted_sides,
    unit_declared_free,
)
from test_cert_page_chains import page_comparison

#: newly read ids, each with a line of its table the page reads, and a change of it
CHANGED = {"3.112": ("\\mathbf{\\Gamma}", "& \\mathbf{1} \\\\", "& 2\\mathbf{1} \\\\"),
           "3.118": ("\\mathbf{w}_A", "\\mathbf{n}_A \\\\", "2\\mathbf{n}_A \\\\"),
           "3.125": ("\\mathbf{c}", "\\mathbf{o}", "2\\mathbf{o}"),
           "3.119a": ("\\mathbf{V}", "\\mathbf{A} - \\mathbf{P}", "\\mathbf{A} + \\mathbf{P}"),
           "3.119b": ("\\mathbf{V}", "\\mathbf{A} - \\mathbf{P}", "\\mathbf{A} + \\mathbf{P}"),
           "3.124": ("\\mathbf{q}_O", "\\mathbf{p} d", "2\\mathbf{p} d"),
           "3.126": ("T", "\\frac{1}{2}", "\\frac{1}{3}"),
           "3.127": ("\\mathbf{c}", "\\mathbf{o}", "2\\mathbf{o}"),
           "3.128": ("\\mathbf{c}", "\\mathbf{o}", "2\\mathbf{o}"),
           "3.129": ("m", "\\rho d", "2\\rho d"),
           "3.130": ("T", "\\frac{1}{2}", "\\frac{1}{3}"),
           "3.131": ("\\mathbf{I}_A", "\\mathbf{1} -", "2\\mathbf{1} -"),
           "3.132": ("\\mathbf{p}", "\\mathbf{pP}", "2\\mathbf{pP}"),
           "3.134a": ("\\mathbf{f}", "\\ddot{\\mathbf{p}}", "2\\ddot{\\mathbf{p}}"),
           "3.138": ("\\mathbf{M}", "m\\mathbf{1}", "2m\\mathbf{1}"),
           "3.147": ("\\mathbf{M}_A", "& \\mathbf{1}", "& 2\\mathbf{1}")}
#: read on every side (3.134a's f, the resultant the motion requires, through the body's
#: shape its certificate keeps: tests/test_cert_page_cancelled.py)
EVERY_SIDE = set(CHANGED)


def _tamperings(c: dict, book: str) -> list[dict]:
    """Another id's printed text, both sides shifted, the other verdicts, the right sides
    doubled (where not all 0), a unit declared free, and the id's line changed."""
    i = c["id"]
    out = [another_printed_text(c, book, "3.106" if i != "3.106" else "3.107"),
           shifted_sides(c), *(relabelled(c, v) for v in ("verified", "definition",
                                                          "does-not-hold") if v != c["verdict"])]
    if any(x != "0" for r in c["relations"] if r["role"] == "printed"
           for row in r["rhs"] for x in row):  # 2 x 0 is no change
        out.append(doubled_rhs(c))
    if (t := unit_declared_free(c)) is not None:
        out.append(t)
    glyph, old, new = CHANGED[i]
    t = copy.deepcopy(c)
    entry = next(e for e in t["symbols"] if e.get("glyph") == glyph)
    assert old in entry["latex"], (i, entry)
    entry["latex"] = entry["latex"].replace(old, new)
    return [*out, t]


def _check(certs: dict, book: str) -> None:
    for i, c in certs.items():
        lines = page_comparison(c, book)
        assert any(x.startswith("read from the page") for x in lines), (i, lines)
        assert not any(x.startswith("matched") for x in lines), (i, lines)
        if i in EVERY_SIDE:
            assert not any(x.startswith("NOT READ") for x in lines), (i, lines)
        for t in _tamperings(c, book):
            assert f"({i})" in rejection(t, book), i


@pytest.fixture(scope="module")
def own_read(tmp_path_factory):
    book_path()  # skips where the chapter is absent (tests/_book.py)
    return certs_for(tmp_path_factory.mktemp("own"), ["3.112", "3.118", "3.125"])


def test_glyphs_defined_on_the_id_read_firmly_and_tamperings_rejected(own_read):
    """3.112 (``Gamma \\equiv [O, 1; 1, O]``), 3.118 (``w_A \\equiv [n_A; f], w_P \\equiv
    [n_P; f]``, (3.113)'s arrays of the system of forces) and 3.125 (``c \\equiv q_O / m``:
    the model's centre of mass is ``o``, ``q_O`` through (3.124)'s integral): every side read
    firmly; another id's text, the other verdicts, the right side doubled, both sides
    shifted and the line changed are each rejected naming the id."""
    _check(own_read, book_text())


@pytest.mark.slow
def test_chapter_sections_3_7_3_8_own_glyphs_read_and_tamperings_rejected(tmp_path):
    """The other ids these lines read (3.119a's ``V`` of (3.119b), not (3.97d)'s; 3.124,
    3.126, 3.130's ``T``; 3.127, 3.128 (its ``R = CPM(r)`` a claim: the page says it in
    words), 3.132's ``c`` without the body's shape; 3.134a's ``f`` on the body; 3.129's
    and 3.130's underbraces; 3.131's ``I_A``; 3.138's ``M`` on ``r_i = Q rho_i``; 3.147's
    ``M_A``, the kinetic energy's Hessian): read firmly, each tampering rejected naming
    the id."""
    book_path()  # skips where the chapter is absent (tests/_book.py)
    _check(certs_for(tmp_path, sorted(set(CHANGED) - {"3.112", "3.118", "3.125"})), book_text())


def test_an_underbrace_is_a_printed_relation_where_the_certificate_proves_it():
    """``x = 2\\underbrace{y + z}_{w}`` with a certificate of two printed relations (``x =
    2 (y + z)`` and the brace's ``y + z = w``) is read as two relations, the brace's firmly:
    a certificate whose second relation is not the brace's is rejected, and so is one that
    drops the brace's relation while its label ``w`` is a glyph of the symbol table (the
    page decides what it prints: certcheck.braces); where the label is no glyph the
    certificate models, the brace is only the term it groups."""
    from certcheck.compare import compare

    from certcheck import CheckError

    names = ("x", "y", "z", "w")
    cert = {"format": "rigidsym-certificate", "version": 1, "id": "t", "verdict": "verified",
            "let": [],
            "atoms": [{"group": n, "kind": "free", "names": [n], "timed": False} for n in names],
            "symbols": [{"glyph": n, "kind": "free", "atoms": [n]} for n in names],
            "relations": [{"label": "", "role": "printed", "lhs": [[a]], "rhs": [[b]],
                           "evidence": {"type": "identity"}}
                          for a, b in (("x", "2*(y + z)"), ("y + z", "w"))]}
    page = "x = 2\\underbrace{y + z}_{w}"
    lines = compare(cert, page)
    assert lines == [f"read from the page: relation {k}'s lhs and rhs, the certificate's under"
                     " the symbol table" for k in (1, 2)], lines
    forged = copy.deepcopy(cert)
    forged["relations"][1]["rhs"] = [["2*w"]]
    with pytest.raises(CheckError, match=r"\(t\) the printed rhs of relation 2"):
        compare(forged, page)
    one = {**cert, "relations": cert["relations"][:1]}
    with pytest.raises(CheckError, match=r"\(t\) the page prints 2 relation\(s\), the "
                       r"certificate proves 1"):
        compare(one, page)
    unnamed = {**one, "atoms": cert["atoms"][:3], "symbols": cert["symbols"][:3]}
    assert compare(unnamed, page) == [lines[0]]
