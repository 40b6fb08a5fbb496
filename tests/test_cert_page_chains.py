"""Chains and section 3.7's wrench ids read by certcheck's second reader. A chain ``a \\equiv b
= c`` is read as ``a = b`` and ``a = c``, its later ``a`` read as ``b`` (the page says ``a``
is ``b``); the certificate marks the claim that proves a member the definition does not
state (``"page": k``), so the member is read against a proof, not only claimed. The wrench
axis (``p_0''``, ``e''``, ``n''``, ``n_0``) and the wrench and twist arrays ``w = [n; f]``,
``t = [omega; v]`` are symbol-table lines as the models have them. Tamperings by mathematics
on 3.109 and 3.115 here, on the other ids this file covers in slow."""

from __future__ import annotations

import copy
import json

import pytest
from _book import book_path
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

#: newly read ids, each with a line of its table the page reads, and a change of it
CHANGED = {"3.109": ("\\mathbf{n}_P", "\\mathbf{c}", "2\\mathbf{c}"),
           "3.115": ("\\mathbf{s}_w", "{W}\\mathbf{e}", "{W}2\\mathbf{e}"),
           "3.108": ("\\mathbf{p}_0''", "\\frac{1}{W}", "\\frac{2}{W}"),
           "3.110": ("\\mathbf{e}''", "\\mathbf{e}", "2\\mathbf{e}"),
           "3.111": ("\\mathbf{p}_0''", "(\\mathbf{e}^T\\mathbf{r}_1)", "2(\\mathbf{e}^T"
                     "\\mathbf{r}_1)"),
           "3.113": ("\\mathbf{n}", "h\\mathbf{f}", "2h\\mathbf{f}"),
           "3.114": ("\\Pi", "\\mathbf{c} \\cdot", "2\\mathbf{c} \\cdot"),
           "3.120": ("\\mathbf{n}_A", "+ \\mathbf{c}", "+ 2\\mathbf{c}")}


def page_comparison(c: dict, book: str) -> list[str]:
    from certcheck.compare import compare

    i = c["id"]
    return compare(c, locate(book, i), fast=True, defs=definitions_before(book, i))


def _tamperings(c: dict, book: str) -> list[dict]:
    """The acceptance list's tamperings of a firmly read id: another id's printed text, the
    other verdicts, the right sides doubled, both sides shifted, a unit declared free, a
    line the page reads changed, and a marked chain member's right side doubled or moved."""
    i = c["id"]
    out = [another_printed_text(c, book, "3.106"), shifted_sides(c),
           *(relabelled(c, v) for v in ("verified", "definition", "does-not-hold")
             if v != c["verdict"])]
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
    out.append(t)
    for k, r in enumerate(c["relations"]):
        if "page" in r:  # a chain's member, proved as a claim
            t = copy.deepcopy(c)
            t["relations"][k]["rhs"] = [[f"2*({x})" for x in row] for row in r["rhs"]]
            out.append(t)
            t = copy.deepcopy(c)
            t["relations"][k]["page"] = 3 if r["page"] != 3 else 1
            out.append(t)
    return out


@pytest.fixture(scope="module")
def chains_read(tmp_path_factory):
    book_path()  # skips where the chapter is absent (tests/_book.py)
    return certs_for(tmp_path_factory.mktemp("chains"), ["3.109", "3.115"])


def test_chain_member_and_wrench_arrays_read_and_tamperings_rejected(chains_read):
    """3.109 (``p'' \\equiv n_0/||f|| = n_P . f/||f||^2 or p'' = 2 pi ...``): the certificate
    marks its claim "second member" as the page's relation 2, whose lhs is read through the
    m/rad alternative's line of ``p''`` (``n_0/||f||``, ``n_0`` through (3.108); without the
    alternatives' lines, as the chain's second member) and rhs through the one-force
    model; 3.115 (``w = W Gamma s_w, t = T s_t``) through ``w = [n; f]``, ``t = [omega;
    v]`` and the screws as the model solves them: every side read firmly. Each tampering
    rejected naming the id."""
    book = book_text()
    c = chains_read["3.109"]
    assert [r.get("page") for r in c["relations"] if r["role"] == "claim"] == [2, None, None]
    lines = page_comparison(c, book)
    assert any(x.startswith("read from the page: relation 2's lhs") and " and rhs" in x
               and "p'' as printed in (3.109)" in x for x in lines), lines  # its m/rad line
    assert not any(x.startswith("NOT READ") for x in lines), lines  # each alternative's p''
    c = copy.deepcopy(c)  # without the alternatives' lines: p'' NOT READ, relation 2's lhs
    for r in c["relations"]:  # through the chain's second member
        r.pop("symbols", None)
    lines = page_comparison(c, book)
    assert any(x.startswith("read from the page: relation 2's lhs") and " and rhs" in x
               and "the chain's second member" in x for x in lines), lines
    assert sum(x.startswith("NOT READ") for x in lines) == 2, lines  # p'' defined, twice
    c = chains_read["3.109"]
    lines = page_comparison(chains_read["3.115"], book)
    assert sum(x.startswith("read from the page") and " and rhs" in x for x in lines) == 2
    assert not any(x.startswith(("NOT READ", "matched")) for x in lines), lines
    for i, c in chains_read.items():
        for t in _tamperings(c, book):
            assert f"({i})" in rejection(t, book), i


@pytest.mark.slow
def test_chapter_section_3_7_wrench_ids_read_and_tamperings_rejected(chapter_certificates):
    """3.108 (both members of ``n_0 = n_0 f/||f||, n_0 \\equiv ...``, the first the marked
    claim), 3.110 (the Plücker array of the wrench axis), 3.111 (``p_0''`` against the
    model's solved point), 3.113 (``w = [n; f]``), 3.114 (``Pi = t^T w`` on the moving
    body) and 3.120 (``t_P^T w_P = t_A^T U^T V w_A``, U and V through (3.83b), (3.119b)):
    every side read firmly, each tampering rejected naming the id."""
    book_path()  # skips where the chapter is absent (tests/_book.py)
    book = book_text()
    # the run's shared certificates (3.120's alone costs ~15 s to build again), each a copy
    for i in ["3.108", "3.110", "3.111", "3.113", "3.114", "3.120"]:
        c = json.loads(json.dumps(chapter_certificates[i]))
        lines = page_comparison(c, book)
        assert not any(x.startswith(("NOT READ", "matched")) for x in lines), (i, lines)
        for t in _tamperings(c, book):
            assert f"({i})" in rejection(t, book), i
