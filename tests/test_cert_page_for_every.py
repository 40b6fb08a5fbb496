"""A does-not-hold certified on the printed relation itself where the page never gives one
of its glyphs: (3.148)'s ``M_A = M_C + m P P^T``, ``P`` a fresh 6 x 6 array of free atoms
(``checking/certifying/for_every.py``), failing at one point for every real ``P`` (certcheck's
``for_every``: ``x^T (lhs - rhs) x`` a non-zero constant plus squares weighted of its sign).
Both printed sides are read (``M_A`` through the model's Hessian line, ``M_C`` through
(3.138)'s ``M``, ``P`` its atoms); a coefficient, a sign, a transpose of the page's sides, a
changed line, a dropped relation, another id's text, the other verdicts and a changed
evidence are each rejected naming the id."""

from __future__ import annotations

import copy

import pytest
from test_cert_page import another_printed_text, doubled_rhs, page_outcome, relabelled
from test_cert_page_momenta import certificates, line_changed, rejection


@pytest.fixture(scope="module")
def steiner() -> dict:
    return certificates(["3.148"])["3.148"]


def _printed(c: dict) -> dict:
    return next(r for r in c["relations"] if r["role"] == "printed")


def _p_term(c: dict, new) -> dict:
    """The printed rhs with its ``m P P^T`` replaced by ``new(m, P)`` (texts in the atoms;
    ``m`` the model's mass, the body's ``sum (1 + mu_i^2)``)."""
    t = copy.deepcopy(c)
    rel, ev = _printed(t), _printed(t)["evidence"]
    P = [ev["for_every"][6 * i:6 * i + 6] for i in range(6)]
    m = " + ".join(f"(1 + s38_mu{k}^2)" for k in range(1, 5))
    ppt = lambda X, i, j: " + ".join(f"{X[i][k]}*{X[j][k]}" for k in range(6))  # noqa: E731
    rel["rhs"] = [[f"({x}) - ({m})*({ppt(P, i, j)}) + ({new(m, P, i, j, ppt)})"
                   for j, x in enumerate(row)] for i, row in enumerate(rel["rhs"])]
    return t


def test_the_printed_relation_is_read_and_refuted_for_every_p(steiner, book):
    from certcheck import check_certificate

    c = steiner
    ev = _printed(c)["evidence"]
    assert len(ev["for_every"]) == 36 and page_outcome(c, book) == "read"
    verdict, lines = check_certificate(c)
    assert verdict == "does-not-hold" and any("does not hold for any real" in x for x in lines)
    same = _p_term(c, lambda m, P, i, j, f: f"({m})*({f(P, i, j)})")  # no change: read
    assert page_outcome(same, book) == "read"
    Pt = lambda P: [list(r) for r in zip(*P, strict=True)]  # noqa: E731
    page = [_p_term(c, lambda m, P, i, j, f: f"2*({m})*({f(P, i, j)})"),  # 2 m P P^T
            _p_term(c, lambda m, P, i, j, f: f"-({m})*({f(P, i, j)})"),  # M_C - m P P^T
            _p_term(c, lambda m, P, i, j, f: f"({m})*({f(Pt(P), i, j)})"),  # m P^T P
            _p_term(c, lambda m, P, i, j, f: "0"),  # M_C alone
            line_changed(c, "\\mathbf{M}_C", "m\\mathbf{1}", "2m\\mathbf{1}"),
            line_changed(c, "\\mathbf{M}_A", "& \\mathbf{1}", "& 2\\mathbf{1}"),
            line_changed(c, "\\mathbf{M}_A", "\\mathbf{P}_i - \\mathbf{A}",
                         "\\mathbf{A} - \\mathbf{P}_i")]
    transposed = copy.deepcopy(c)  # the table's P read column by column
    entry = next(e for e in transposed["symbols"] if e["glyph"] == "\\mathbf{P}")
    entry["atoms"] = [entry["atoms"][6 * j + i] for i in range(6) for j in range(6)]
    for t in [*page, transposed]:
        assert page_outcome(t, book).startswith("rejected: (3.148)"), t["symbols"][-1]
        assert "(3.148)" in rejection(t, book)
    dropped = copy.deepcopy(c)
    dropped["relations"] = [r for r in c["relations"] if r["role"] != "printed"]
    proof = [dropped, doubled_rhs(c), another_printed_text(c, book, "3.147"),
             *(relabelled(c, v) for v in ("verified", "definition"))]
    for change in (lambda e: e["squares"][0].__setitem__(0, str(-int(e["squares"][0][0]))),
                   lambda e: e["squares"].pop(),
                   lambda e: e.__setitem__("form", ["0"] * 6),
                   lambda e: e["for_every"].pop(),
                   lambda e: e["point"].update({e["for_every"][0]: "1"}),
                   lambda e: e.__setitem__("for_every", [*e["for_every"][:35], "s38_a_1"])):
        t = copy.deepcopy(c)
        change(_printed(t)["evidence"])
        proof.append(t)
    for t in proof:
        assert "(3.148)" in rejection(t, book)
