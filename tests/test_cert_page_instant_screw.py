"""Sections 3.3-3.4.2 read from the page: the symbol table's lines of
``rigidsym.checking.certifying.instant_screw_symbols`` (3.3's ``p = Q p_0`` and its rate,
``Omega``, ``omega``; the ISA's point ``p'_0`` closest to the origin, its points ``p``,
``r``, ``A``, ``b`` of (3.62b), (3.66); 3.4.2's pitch, pure translation and printed arrays)
let certcheck's second reader read those ids firmly; each line doubled, a changed side and
another id's text are rejected naming the id. One id here, every id read through the lines
in slow."""

from __future__ import annotations

import pytest
from test_cert_page import another_printed_text, doubled_rhs, relabelled, shifted_sides
from test_cert_page_momenta import (
    certificates,
    line_changed,
    line_doubled,
    read_lines,
    rejection,
)

#: the ids whose every printed side is read, each through at least one line (measured)
READ_THROUGH_LINES = ["3.41", "3.42", "3.43", "3.44", "3.45", "3.46", "3.56", "3.60", "3.61",
                      "3.62a", "3.62b", "3.63", "3.64", "3.65", "3.66", "3.67", "3.70", "3.71",
                      "3.73", "3.74", "3.75", "3.53"]
#: ids with a side read through a line and another not read (||omega|| not squared: a
#: square root)
PARTLY = ["3.52"]



#: a line whose doubling changes nothing the id reads: 3.64's omega^T p'_0 = 0 is
#: homogeneous in p'_0; 3.73's omega is 0 (a pure translation)
NO_CHANGE = {"3.64": "\\mathbf{p}'_0", "3.73": "\\boldsymbol{\\omega}"}


def _cases(c: dict, lines: list[str], book: str, other: str) -> list:
    """Each line the reading used doubled (p'_0 also made the ISA's point r, its
    omega-component kept, where p'_0 is read for itself), both sides shifted, the right
    side doubled (where not 0: no change), another id's printed text, the other verdict."""
    from _reading_groups import INSTANT_SCREW_GLYPHS

    used = [g for g in INSTANT_SCREW_GLYPHS if any(f"{g} as the model's" in x for x in lines)]
    assert used, (c["id"], lines)
    out = [line_doubled(c, g) for g in used if NO_CHANGE.get(c["id"]) != g]
    if "\\mathbf{p}'_0" in used and "\\mathbf{p}" not in used:  # r, another ISA point
        # (not where p'_0 only places p, any point of the ISA: 3.60-3.63 hold for each)
        line, r = (next(e["latex"] for e in c["symbols"] if e["glyph"] == g)
                   for g in ("\\mathbf{p}'_0", "\\mathbf{r}"))
        out.append(line_changed(c, "\\mathbf{p}'_0", line, r))
    if any(x != "0" for r in c["relations"] if r["role"] == "printed"
           for row in r["rhs"] for x in row):
        out.append(doubled_rhs(c))
    return out + [shifted_sides(c), another_printed_text(c, book, other),
                  relabelled(c, "definition" if c["verdict"] == "verified" else "verified")]


def test_isa_point_read_firmly_and_tamperings_rejected(book):
    """3.65 (A p'_0 = b: A, b as printed in (3.66) below, p'_0 the ISA's point closest to
    the origin) read firmly on both sides; p'_0 made the ISA's point r (its omega-component
    kept), each line doubled, both sides shifted, the right side doubled, another id's
    text, the verdict changed: rejected naming the id."""
    c = certificates(["3.65"])["3.65"]
    lines = read_lines(c, book, fast=False)
    assert lines and all(x.startswith("read from the page") for x in lines), lines
    cases = _cases(c, lines, book, "3.64")
    assert None not in cases and len(cases) == 8
    for t in cases:
        assert "(3.65)" in rejection(t, book)


@pytest.mark.slow
def test_sections_3_3_to_3_4_2_read_through_the_lines_and_tamperings_rejected(book):
    """Every id of the lists read through the lines: every printed side read firmly (a side
    of 3.52; 3.53's alternatives each under its own line of p', m/rad and m/turn), and each
    line it uses doubled (where that changes what is read), p'_0 made r, both sides
    shifted, the right side doubled (where not 0), another id's text, the other verdict:
    rejected naming the id."""
    ids = READ_THROUGH_LINES + PARTLY
    certs = certificates(ids)
    for k, (i, c) in enumerate(certs.items()):
        lines = read_lines(c, book)
        read = [x.startswith("read from the page") for x in lines]
        assert lines and (any(read) if i in PARTLY else all(read)), (i, lines)
        for t in filter(None, _cases(c, lines, book, ids[k - 1])):
            assert f"({i})" in rejection(t, book), i


@pytest.mark.slow
def test_a_brace_that_fails_read_as_the_does_not_hold_printed_relation(book):
    """3.59 (p-dot = brace - brace): its certificate proves the p-dot_perp brace false (the
    minus sign outside the brace); the brace is a printed relation of the page, read in
    either order with p-dot_perp the component of p-dot normal to omega and p, a the body
    point's and the reference point's (a kept as the certificate's atoms though the relation
    cancels it): both sides read. Each line doubled, the right side doubled, both sides
    shifted, another id's text and the verdict verified: rejected naming the id (~20 s: the
    quaternion motion's differing sides)."""
    c = certificates(["3.59"])["3.59"]
    lines = read_lines(c, book)
    assert len(lines) == 1 and lines[0].startswith("read from the page: relation 1's lhs")
    assert " and rhs" in lines[0] and "\\dot{\\mathbf{p}}_{\\perp} as the model's" in lines[0]
    assert {g["group"] for g in c["atoms"]} >= {"s34_a_1", "s34_r_1"}
    cases = [line_doubled(c, "\\dot{\\mathbf{p}}_{\\perp}"), line_doubled(c, "\\mathbf{p}"),
             doubled_rhs(c), shifted_sides(c), another_printed_text(c, book, "3.60"),
             relabelled(c, "verified")]
    assert None not in cases
    for t in cases:
        assert "(3.59)" in rejection(t, book)
