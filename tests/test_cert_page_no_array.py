"""A printed side that is no array, read as such: (3.94)'s ``[[F-dot, O], [O_34, O]]``, its
``F-dot`` (N-dot, L-dot or H-dot, 4 x 3 under the member's lines) in a slot that ``O_34``
and the left side ``S-dot`` (6 x 7) size 3 x 4. certcheck's second reader reads the blocks,
finds the one block of another shape than its slot and requires the certificate's side to
be the page's with distinct fresh free atoms in that slot: so every other block is held to
the page, and any edit of the certificate's blocks is rejected or leaves the side NOT READ,
never read."""

from __future__ import annotations

import copy

import pytest
from test_cert_page import another_printed_text, page_outcome, relabelled, relation_dropped
from test_cert_page_momenta import certificates, read_lines, rejection


@pytest.fixture(scope="module")
def cert() -> dict:
    return certificates(["3.94"])["3.94"]


def _entry(c: dict, i: int, j: int, new) -> dict:
    t = copy.deepcopy(c)
    rhs = t["relations"][0]["rhs"]
    rhs[i][j] = new(rhs[i][j])
    return t


def test_no_array_as_printed_read_on_both_sides(book, cert):
    lines = read_lines(cert, book)
    assert len(lines) == 1 and lines[0].startswith("read from the page: relation 1's lhs")
    assert "and rhs (through no array as printed" in lines[0], lines
    assert page_outcome(cert, book) == "read"


def test_an_edit_of_the_blocks_is_rejected(book, cert):
    """The zero blocks beside and below the slot (``O``, ``O_34``) each given a non-zero
    entry, the left side doubled: rejected naming the id (the page's blocks read)."""
    lhs2 = copy.deepcopy(cert)
    lhs2["relations"][0]["lhs"] = [[f"2*({x})" for x in row] for row in
                                   lhs2["relations"][0]["lhs"]]
    for t in (_entry(cert, 0, 4, lambda x: "1"), _entry(cert, 3, 0, lambda x: "e_1"),
              _entry(cert, 5, 6, lambda x: "phi"), lhs2, relabelled(cert, "verified"),
              another_printed_text(cert, book, "3.93")):
        assert "(3.94)" in rejection(t, book)


def test_the_slot_needs_fresh_entries(book, cert):
    """The slot's entries a constant, a doubled atom, one atom twice, an atom of a page
    glyph, the printed relation dropped: never read on every side."""
    first = cert["relations"][0]["rhs"][0][0]
    for t in (_entry(cert, 0, 0, lambda x: "0"), _entry(cert, 1, 2, lambda x: f"2*({x})"),
              _entry(cert, 2, 3, lambda x: first), _entry(cert, 0, 1, lambda x: "e_1"),
              relation_dropped(cert, 0)):
        assert page_outcome(t, book) != "read"
