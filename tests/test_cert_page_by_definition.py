"""A printed relation that holds by definition (:mod:`certcheck.by_definition`): beside the
other relations of a verified id, one the certificate writes with identical sides, or
constants only (VACUOUS: never evidence), is read on every side where the second reader
read both its printed sides firmly, and classified an identity by definition; otherwise its
sides are not read (the id exits 3). Quick: 3.116 (``(Γ s_w)^T s_t ≡ s_w^T Γ^T s_t``) and
3.121 (``U^T V`` and the product of its blocks, constants only); slow: 3.129's ``∫ρ dB =
m``, 3.130's ``I_C`` under the brace and 3.136's ``ṁ = m c̈``. The vacuous relation's sides
tampered (scaled, negated, shifted alike, so that it stays vacuous): rejected naming the id;
the relation dropped: rejected, or NOT READ on some side (exit 3), never checked."""

from __future__ import annotations

import copy
import sys
from pathlib import Path

import pytest
from _book import READING, book_path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "certcheck" / "src"))

from certcheck.book import definitions_before, locate  # noqa: E402
from certcheck.by_definition import unread_vacuous  # noqa: E402
from certcheck.check import Statement, is_vacuous  # noqa: E402
from test_cert_page import BOOK, book_text, certs_for, rejection  # noqa: E402

from certcheck import check_certificate  # noqa: E402

QUICK = ["3.116", "3.121"]
SLOW = ["3.129", "3.130", "3.136"]
#: the vacuous relation's sides are 0 as read (3.116: the model's screws are reciprocal)
ZERO = {"3.116"}
#: a brace the reader reads as a relation only where the certificate proves one more
#: relation than the page's chains: 3.130's ``I_C`` dropped, the brace reads as a name
BRACE_AS_NAME = {"3.130"}


def vacuous_index(cert: dict) -> int:
    """The index in ``cert["relations"]`` of its one vacuous printed relation."""
    st = Statement(cert)
    found = [k for k, r in enumerate(st.rels) if r[0]["role"] == "printed"
             and is_vacuous(r, st)]
    assert len(found) == 1, (cert["id"], found)
    return found[0]


def read(cert: dict, book: str) -> tuple[int, int, list]:
    """certcheck's count for ``cert``: (sides read, printed sides, lines), the vacuous
    relations' sides deducted where not read firmly, as ``certcheck --book`` counts."""
    from certcheck.compare import compare

    i = cert["id"]
    lines = compare(cert, locate(book, i), fast=True, defs=definitions_before(book, i),
                    counts=(counts := []))
    (k, n, firm), = counts
    vac, more = unread_vacuous(cert, firm)
    return k - 2 * vac, n, lines + more


def tampered(cert: dict, how) -> dict:
    """The vacuous relation's two sides, each entry ``x`` written ``how(x)``: still vacuous,
    so the certificate proves it; only the page refutes it."""
    c = copy.deepcopy(cert)
    r = c["relations"][vacuous_index(c)]
    for side in ("lhs", "rhs"):
        r[side] = [[how(x) for x in row] for row in r[side]]
    return c


def dropped(cert: dict) -> dict:
    """The vacuous relation dropped from the certificate."""
    c = copy.deepcopy(cert)
    del c["relations"][vacuous_index(c)]
    return c


def _check_ids(certs: dict, book: str) -> None:
    for i, c in certs.items():
        assert check_certificate(c, fast=True)[0] == "verified", i
        k, n, lines = read(c, book)
        assert k == n, (i, k, n, lines)  # read on every side
        assert sum("an identity by definition" in x for x in lines) == 1, (i, lines)
        assert not any(x.startswith(("NOT READ", "matched")) for x in lines), (i, lines)
        cases = [tampered(c, lambda x: f"({x}) + 1")]
        if i not in ZERO:  # 2 x 0 and -0 are no change
            cases += [tampered(c, lambda x: f"2*({x})"), tampered(c, lambda x: f"-({x})")]
        for t in cases:
            assert f"({i})" in rejection(t, book, page_first=True), i
        if i in BRACE_AS_NAME:
            continue
        try:  # dropped: rejected, or (3.129's brace: the page's braces then are not read
            why = rejection(dropped(c), book, page_first=True)  # as relations) NOT READ
        except AssertionError:  # on some side: exit 3, never CHECKED
            why = None
        assert f"({i})" in why if why is not None else read(dropped(c), book)[0] < \
            read(dropped(c), book)[1], i


@pytest.fixture(scope="module")
def quick_certs(tmp_path_factory):
    book_path()  # skips where the chapter is absent (tests/_book.py)
    return certs_for(tmp_path_factory.mktemp("by_definition"), QUICK)


def test_vacuous_relation_read_on_both_sides_and_tamperings_rejected(quick_certs):
    _check_ids(quick_certs, book_text())


def test_vacuous_relation_not_read_firmly_stays_unread(quick_certs):
    """Fail closed: a vacuous relation the reader did not read firmly on both sides (here:
    none given as read) counts its two sides as not read, and a relation that is not
    vacuous is never classified so; a definition or a does-not-hold has none."""
    for i, c in quick_certs.items():
        k = vacuous_index(c)
        assert unread_vacuous(c, []) == (1, []), i
        others = [r for j, r in enumerate(c["relations"]) if j != k]
        assert unread_vacuous(c, others) == (1, []), i  # only the vacuous one's reading counts
        n, lines = unread_vacuous(c, [c["relations"][k]])
        assert n == 0 and len(lines) == 1 and "identity by definition" in lines[0], i
        same = copy.deepcopy(c["relations"][k])  # an equal relation is not the one read
        assert unread_vacuous(c, [same]) == (1, []), i
        assert unread_vacuous({**c, "verdict": "definition"}, []) == (0, []), i


def test_cli_counts_the_vacuous_relation_read(quick_certs, tmp_path, capsys):
    """``certcheck --book``: the two ids CHECKED (exit 0, every side read), the identity by
    definition printed beside the check's VACUOUS line (not evidence)."""
    book_path()  # the run's manifest names the chapter (tests/_book.py)
    from certcheck.__main__ import main

    folder = tmp_path / "run"
    certs_for(folder, QUICK)
    rc = main(["--book", str(BOOK), "--reading", str(READING), str(folder)])
    out = capsys.readouterr().out
    assert rc == 0, out
    for i in QUICK:
        assert f"CHECKED ({i}) verified" in out, out
    assert out.count("an identity by definition") == 2 and out.count("VACUOUS") == 2, out
    assert "2 of 2 certificates checked" in out and "(0 of " in out, out


@pytest.mark.slow
def test_momenta_vacuous_relations_read(tmp_path_factory):
    """3.129's ``∫ρ dB = m``, 3.130's brace ``I_C``, 3.136's ``ṁ = m c̈`` (about 5 s)."""
    book_path()  # skips where the chapter is absent (tests/_book.py)
    _check_ids(certs_for(tmp_path_factory.mktemp("momenta"), SLOW), book_text())
