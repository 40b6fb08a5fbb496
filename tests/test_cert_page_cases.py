"""One printed relation the page states for several cases: (3.35)'s ``||q||^2 + q_0^2 = 1``
"In the first two cases", the Euler-Rodrigues parameters and the linear invariants, each
defined by an untagged display above it (``q \\equiv ..., \\quad q_0 \\equiv ...``). Each
certificate relation carries its case's lines, verbatim; certcheck holds them to those
displays, in order (``book._cases``), and reads the relation once per case, firmly. A changed
line, a coefficient, a sign, the cases swapped or one copied, a dropped case, another id's
text and the other verdicts are each rejected naming the id; the lines dropped leave it NOT
READ."""

from __future__ import annotations

import copy

from test_cert_page import another_printed_text, doubled_rhs, page_outcome, relabelled
from test_cert_page_momenta import certificates, rejection


def printed_of(c: dict) -> list:
    """The certificate's printed relations (a tampering's handle on them)."""
    return [r for r in c["relations"] if r["role"] == "printed"]


def tampered(c: dict, change) -> dict:
    """A copy of ``c`` whose printed relations ``change`` edits in place."""
    t = copy.deepcopy(c)
    change(printed_of(t))
    return t


def _line(k: int, glyph: str, old: str, new: str):
    def change(rels: list) -> None:
        line = next(s for s in rels[k]["symbols"] if s["glyph"] == glyph)
        assert old in line["latex"]
        line["latex"] = line["latex"].replace(old, new)
    return change


def test_each_case_read_under_its_display_and_tamperings_rejected(book):
    c = certificates(["3.35"])["3.35"]
    assert [len(r.get("symbols", [])) for r in printed_of(c)] == [2, 2]
    assert page_outcome(c, book) == "read"
    swap = lambda rels: [r.update(symbols=s) for r, s in zip(  # noqa: E731
        rels, [rels[1]["symbols"], rels[0]["symbols"]], strict=True)]
    page = [tampered(c, _line(0, "\\mathbf{q}", "{2}", "{3}")),  # a coefficient of a line
            tampered(c, _line(1, "q_0", "\\cos", "-\\cos")),  # a sign
            tampered(c, _line(1, "\\mathbf{q}", "(\\sin \\phi)", "")),  # case 3's q = e
            tampered(c, swap),  # the cases swapped
            tampered(c, lambda rels: rels[1].update(symbols=rels[0]["symbols"])),  # copied
            tampered(c, lambda rels: rels[1]["symbols"].pop()),  # a line dropped
            tampered(c, lambda rels: rels[0].update(  # the lhs doubled (each case's lhs
                lhs=[[f"2*({rels[0]['lhs'][0][0]})"]])),  # is 1 under e's unit norm: the
            doubled_rhs(c)]  # other case's lhs, or 2 lhs - 1, would be no change)
    dropped = copy.deepcopy(c)  # the linear invariants' case left out
    dropped["relations"] = [r for r in c["relations"] if r["label"] != "linear invariants"]
    page.append(dropped)
    for t in page:
        assert page_outcome(t, book).startswith("rejected: (3.35)"), t["relations"]
    for t in (another_printed_text(c, book, "3.36"), doubled_rhs(c),
              *(relabelled(c, v) for v in ("definition", "does-not-hold"))):
        assert "(3.35)" in rejection(t, book)
    unlined = tampered(c, lambda rels: [r.pop("symbols") for r in rels])
    assert page_outcome(unlined, book) == "not read"  # one relation, two models: matched
