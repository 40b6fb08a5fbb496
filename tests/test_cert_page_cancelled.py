"""Glyphs whose atoms the model's relation cancels, read from the page through the atoms
the certificate keeps, and a formula read against the model's derivation of its glyph.

(3.24)'s ``e``, ``n`` through (3.22)'s ``e \\equiv (p_2 - p_1)/||p_2 - p_1||``, ``n \\equiv
p_1 \\times e``, a definition the page prints before it: the model's relation is free of the
line's length (``e`` is ``u``), so the certificate names the atoms of the glyphs that
definition reaches (``p_2 = p_1 + ell u``, ``ell``) and its table writes ``p_2``; certcheck
reads ``||p_2 - p_1||`` unsquared, in K(s). Not a change, so not tried: ``p_2``'s line
changed (the Plücker constraints hold for every two distinct points; ``p_2 = p_1`` divides
by zero: rejected).

(3.134a)'s ``f``, the force the motion requires, the integral of ``rho p_ddot``: the model's
sum over the particles is kept as written, so the certificate keeps the body's shape and
``Q`` (their terms cancel in the checker's arithmetic) and both sides are read through the
body's lines, ``c_ddot`` as (3.124)-(3.125)'s ``(1/m) int rho p_ddot``.

(3.18)'s ``p_0``, read as (3.10) and (3.12) read it: the model's point of the axis closest
to the origin, ``w - (e^T w) e``, of a displacement written about its own line (a rotation
about the line through ``w`` along ``e`` and a slide ``d_0`` along it), against the printed
formula (the characterising conditions are claims). Not a change, so not tried: the slide's
sign in ``c``'s line (``(Q - 1)^T e = 0``: the printed formula is free of it); the printed
relation dropped with the claims kept leaves it NOT READ (a certificate of claims only).

On each, a coefficient, a sign, another relation's side or a transpose, the right side
doubled, a relation dropped, another id's text and the other verdicts are each rejected
naming the id; the line the id is read through dropped leaves it NOT READ."""

from __future__ import annotations

import copy

import pytest
from test_cert_page import another_printed_text, doubled_rhs, page_outcome, relabelled
from test_cert_page_momenta import certificates, line_changed, rejection


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


@pytest.mark.slow
def test_newton_equation_read_through_the_body_and_tamperings_rejected(book):
    c = certificates(["3.134a"])["3.134a"]
    assert page_outcome(c, book) == "read"
    page = [_side(c, 0, "lhs", lambda x: f"2*({x})"),  # a coefficient
            _side(c, 0, "rhs", lambda x: f"-({x})"),  # a sign
            doubled_rhs(c), another_printed_text(c, book, "3.134b"),
            line_changed(c, "\\mathbf{f}", "\\ddot{\\mathbf{p}}", "2\\ddot{\\mathbf{p}}"),
            line_changed(c, "\\ddot{\\mathbf{c}}", "\\frac{1}{m}", "\\frac{2}{m}")]
    transposed = copy.deepcopy(c)  # the 3 x 1 right side as a 1 x 3 row
    transposed["relations"][0]["rhs"] = [[row[0] for row in c["relations"][0]["rhs"]]]
    page.append(transposed)
    for t in page:
        assert page_outcome(t, book).startswith("rejected: (3.134a)"), t["relations"]
    dropped = {**copy.deepcopy(c), "relations": []}
    for t in (dropped, doubled_rhs(c),
              *(relabelled(c, v) for v in ("definition", "does-not-hold"))):
        assert "(3.134a)" in rejection(t, book)
    unlined = copy.deepcopy(c)
    unlined["symbols"] = [s for s in c["symbols"] if s["glyph"] != "\\mathbf{f}"]
    assert page_outcome(unlined, book) == "not read"


@pytest.mark.slow
def test_screw_axis_point_read_against_the_models_point_and_tamperings_rejected(book):
    c = certificates(["3.18"])["3.18"]
    assert page_outcome(c, book) == "read"
    transposed = copy.deepcopy(c)  # the 3 x 1 right side as a 1 x 3 row
    transposed["relations"][0]["rhs"] = [[row[0] for row in c["relations"][0]["rhs"]]]
    page = [_side(c, 0, "lhs", lambda x: f"2*({x})"),  # a coefficient
            _side(c, 0, "rhs", lambda x: f"-({x})"),  # a sign
            transposed, doubled_rhs(c), another_printed_text(c, book, "3.17"),
            line_changed(c, "\\mathbf{p}_0", "} - (", "} + (")]
    for t in page:
        assert page_outcome(t, book).startswith("rejected: (3.18)"), t["relations"]
    dropped = {**copy.deepcopy(c), "relations": []}
    for t in (dropped, doubled_rhs(c),
              *(relabelled(c, v) for v in ("definition", "does-not-hold"))):
        assert "(3.18)" in rejection(t, book)
    claims_only = copy.deepcopy(c)
    claims_only["relations"] = [r for r in c["relations"] if r["role"] != "printed"]
    unlined = copy.deepcopy(c)
    unlined["symbols"] = [s for s in c["symbols"] if s["glyph"] != "\\mathbf{p}_0"]
    assert page_outcome(claims_only, book) == page_outcome(unlined, book) == "not read"
