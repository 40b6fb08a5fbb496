"""A display that defines one glyph twice, joined by ``\\quad \\text{or} \\quad``, once per
unit: (3.7)'s ``p``, (3.53)'s ``p'``, (3.109)'s ``p''``, each "in m/rad or, correspondingly,
in m/turn" (the words after the display). Each certificate relation of an alternative
carries its own line of the pitch (the alternative's first member, its unit); certcheck holds
the lines to the page, one per alternative, in order, each unit the words' (``certcheck.
alternatives.check_units``), and reads each alternative under its own line. A coefficient
(``2 pi`` dropped or doubled), a sign, the alternatives swapped, an alternative dropped,
another id's text, the other verdicts, a unit word changed, one alternative's relations under
two lines are each rejected naming the id; the lines dropped leave the pitch NOT READ. (3.7)
in the default run, the rest slow."""

from __future__ import annotations

import copy

import pytest
from test_cert_page import another_printed_text, doubled_rhs, page_outcome, relabelled
from test_cert_page_cases import printed_of, tampered
from test_cert_page_momenta import certificates, rejection

#: the id -> another id's printed text for the tampering
OTHER = {"3.7": "3.8", "3.53": "3.52", "3.109": "3.108"}




def _sides(k: int, f):
    """Both sides of the k-th printed relation through ``f`` (a consistent certificate)."""
    def change(rels: list) -> None:
        for s in ("lhs", "rhs"):
            rels[k][s] = [[f(x) for x in row] for row in rels[k][s]]
    return change


def _line(k: int, old: str, new: str):
    def change(rels: list) -> None:
        line = rels[k]["symbols"][0]
        assert old in line["latex"] or old in line["unit"], line
        key = "latex" if old in line["latex"] else "unit"
        line[key] = line[key].replace(old, new)
    return change


def _swap(rels: list) -> None:
    lines = [r["symbols"] for r in rels]
    for r, s in zip(rels, lines[::-1], strict=True):
        r["symbols"] = s


@pytest.mark.parametrize("eq_id", ["3.7", pytest.param("3.53", marks=pytest.mark.slow),
                                   pytest.param("3.109", marks=pytest.mark.slow)])
def test_each_alternative_read_in_its_unit_and_tamperings_rejected(book, eq_id):
    c = certificates([eq_id])[eq_id]
    own = printed_of(c)
    units = [r["symbols"][0]["unit"] for r in own]
    assert units[0] == "m/rad" and units[-1] == "m/turn" and len(set(units)) == 2
    assert page_outcome(c, book) == "read"
    last = len(own) - 1
    page = [tampered(c, _sides(last, lambda x: x.replace("2*pi*", ""))),  # 2 pi dropped
            tampered(c, _sides(last, lambda x: f"2*({x})")),  # 2 pi doubled
            tampered(c, _sides(0, lambda x: f"-({x})")),  # a sign
            tampered(c, _line(last, "2\\pi", "")),  # the m/turn line without 2 pi
            tampered(c, _line(last, "2\\pi", "4\\pi")),  # 2 pi doubled in the line
            tampered(c, _line(0, "m/rad", "m/turn")),  # the unit word changed
            tampered(c, _swap),  # the alternatives' lines swapped
            tampered(c, lambda rels: rels[last].update(symbols=rels[0]["symbols"])),  # copied
            doubled_rhs(c)]
    if last > 1:  # (3.53)'s two m/rad relations: the second under the m/turn line
        page.append(tampered(c, lambda rels: rels[1].update(symbols=rels[last]["symbols"])))
    swapped = copy.deepcopy(c)  # the relations themselves swapped, each with its line
    idx = [k for k, r in enumerate(swapped["relations"]) if r["role"] == "printed"]
    rel = swapped["relations"]
    rel[idx[0]], rel[idx[-1]] = rel[idx[-1]], rel[idx[0]]
    page.append(swapped)
    dropped = copy.deepcopy(c)  # the m/turn alternative left out
    dropped["relations"] = [r for r in c["relations"] if not r["label"].endswith("m/turn")]
    page.append(dropped)
    for t in page:
        assert page_outcome(t, book).startswith(f"rejected: ({eq_id})"), t["relations"]
    other = {"definition": ("verified", "does-not-hold")}.get(c["verdict"],
                                                             ("definition", "does-not-hold"))
    for t in (another_printed_text(c, book, OTHER[eq_id]), doubled_rhs(c),
              *(relabelled(c, v) for v in other)):
        assert f"({eq_id})" in rejection(t, book)
    unlined = tampered(c, lambda rels: [r.pop("symbols") for r in rels])
    assert page_outcome(unlined, book) == "not read"  # the pitch's glyph without a line
