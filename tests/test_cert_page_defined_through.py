"""A glyph read through a definition the page prints before the id: (3.24)'s ``e``, ``n``
through (3.22)'s ``e \\equiv (p_2 - p_1)/||p_2 - p_1||``, ``n \\equiv p_1 \\times e``. The
model's relation is free of the line's length (``e`` is ``u``), so the certificate names the
atoms of the glyphs that definition reaches (``p_2 = p_1 + ell u``, ``ell``), and its table
writes ``p_2``; certcheck reads ``||p_2 - p_1||`` unsquared, in K(s). A coefficient, a sign,
another relation's side, the right side doubled, a relation dropped, another id's text and
the other verdicts are each rejected naming the id; ``p_2``'s line dropped leaves it NOT
READ. Not a change, so not tried: ``p_2``'s line changed (the Plücker constraints hold for
every two distinct points; ``p_2 = p_1`` divides by zero: rejected)."""

from __future__ import annotations

import copy

import pytest
from test_cert_page import another_printed_text, doubled_rhs, page_outcome, relabelled
from test_cert_page_momenta import BOOK, certificates, line_changed, rejection


@pytest.fixture(scope="module")
def book() -> str:
    if not BOOK.exists():
        pytest.skip("the book is never shipped")
    return BOOK.read_text(encoding="utf-8")


def _side(c: dict, k: int, side: str, change) -> dict:
    t = copy.deepcopy(c)
    r = [r for r in t["relations"] if r["role"] == "printed"][k]
    r[side] = [[change(x) for x in row] for row in r[side]]
    return t


def test_plucker_constraints_read_through_the_line_definition(book):
    c = certificates(["3.24"])["3.24"]
    assert any(s["glyph"] == "\\mathbf{p}_2" for s in c["symbols"])
    assert page_outcome(c, book) == "read"
    e_dot_e = c["relations"][0]["lhs"][0][0]
    dropped = copy.deepcopy(c)
    dropped["relations"] = dropped["relations"][1:]
    page = [_side(c, 0, "lhs", lambda x: f"2*({x})"),  # a coefficient
            _side(c, 0, "lhs", lambda x: f"-({x})"),  # a sign
            _side(c, 1, "lhs", lambda x: e_dot_e),  # e . e in place of n . e
            doubled_rhs(c), dropped, another_printed_text(c, book, "3.23"),
            line_changed(c, "\\mathbf{p}_2", "\\mathbf{p}_1 + \\ell\\mathbf{u}",
                         "\\mathbf{p}_1")]  # p_2 = p_1: a division by zero
    for t in page:
        assert page_outcome(t, book).startswith("rejected: (3.24)"), t["relations"]
    for t in (doubled_rhs(c), *(relabelled(c, v) for v in ("definition", "does-not-hold"))):
        assert "(3.24)" in rejection(t, book)
    unlined = copy.deepcopy(c)
    unlined["symbols"] = [s for s in c["symbols"] if s["glyph"] != "\\mathbf{p}_2"]
    assert page_outcome(unlined, book) == "not read"
