"""The corpus of equations from the robotics books: each entry read with
its book's symbol table alone (``tests/data/latex_corpus/``), decided by
``rigidsym.check_latex`` and compared with the verdict the corpus's own NumPy evaluation
confirms at random points.

An entry passes when a true equation is ``verified`` and a slip is ``does-not-hold`` with a
counterexample (or, for a slip NumPy cannot even form, a bad input naming the shapes).
``XFAIL`` lists the entries that fail (recorded in ``baseline.json`` on the day the corpus
was committed, before the reader was changed), each with what is wrong: ``unread`` (bad input
on a well-formed entry), ``wrong`` (a true equation does-not-hold, a slip verified),
``undecided``. They are strict xfails: an entry that starts passing fails the run until its
line is removed. A quick share runs in the README's command, the rest is ``slow``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent / "data" / "latex_corpus"
sys.path.insert(0, str(HERE))

import corpus  # noqa: E402
import record  # noqa: E402

ENTRIES = {e["id"]: e for e in corpus.entries()}
BASELINE = json.loads((HERE / "baseline.json").read_text())

# one or two per book, quick to decide (the README's command: <= 15 s in all)
QUICK = {"lynch-park-06", "lynch-park-07", "murray-li-sastry-16", "siciliano-12",
         "spong-07", "spong-08", "corke-11", "featherstone-01", "craig-01", "craig-16",
         "barfoot-03", "sola-03", "sola-04", "diebel-11", "shuster-06"}

XFAIL = {  # id -> what is wrong with its reading today (remove a line once fixed)
    "siciliano-09": "unread",  # \boldsymbol{S}(\cdot) an operator: no notation line gives it
}


def _outcome(entry: dict, got: dict) -> str | None:
    """``None`` if rigidsym's answer is the entry's verdict, else what is wrong."""
    v = got["verdict"]
    if entry["holds"]:
        return None if v == "verified" else {
            "bad-input": "unread", "does-not-hold": "wrong"}.get(v, v)
    if v == "does-not-hold" and got["counterexample"]:
        return None
    if v == "bad-input" and got.get("construct") == "shapes" \
            and corpus.confirm(entry)[1].startswith("shapes"):
        return None
    return {"bad-input": "unread", "verified": "wrong"}.get(v, v)


def _param(i: str):
    marks = [] if i in QUICK else [pytest.mark.slow]
    if i in XFAIL:
        marks.append(pytest.mark.xfail(strict=True, reason=f"{XFAIL[i]}: "
                                       f"{BASELINE[i]['message'][:120]}"))
    return pytest.param(i, marks=marks, id=i)


def test_the_corpus_is_large_enough_and_its_tables_are_kinds():
    from rigidsym.latex.lets import kind_of

    books = {e["book"]["key"] for e in ENTRIES.values()}
    assert len(ENTRIES) >= 150 and len(books) >= 8
    assert {e["holds"] for e in ENTRIES.values()} == {True, False}
    for e in ENTRIES.values():
        assert e["section"] and e["number"] and e["book"]["edition"], e["id"]
    for name, kind in {r for e in ENTRIES.values() for r in corpus._rows(e["table"])}:
        if kind != "spatial transform":  # a kind of the corpus's own
            kind_of(kind, f"{name}: {kind}")


@pytest.mark.parametrize("i", sorted(ENTRIES))
def test_each_expected_verdict_is_confirmed_by_numpy_at_random_points(i):
    entry = ENTRIES[i]
    holds, how = corpus.confirm(entry)
    assert holds == entry["holds"], f"{i}: NumPy says {holds} ({how})"


@pytest.mark.parametrize("i", [_param(i) for i in sorted(ENTRIES)])
def test_each_entry_reads_with_its_books_table_and_gets_its_verdict(i):
    entry = ENTRIES[i]
    got = record.run(entry)
    assert got["verdict"] != "crash", got["message"]
    if got["verdict"] == "undecided":  # never without a reason
        assert got["message"].strip(), f"{i}: undecided with no reason"
    assert _outcome(entry, got) is None, f"{i}: {got['verdict']}: {got['message']}"


def test_the_acceptance_floor_holds_for_the_failures_left():
    """The strict xfails keep XFAIL equal to what fails; the floor is then a count."""
    unread = [i for i, w in XFAIL.items() if w == "unread"]
    wrong_true = [i for i, w in XFAIL.items() if w == "wrong" and ENTRIES[i]["holds"]]
    missed_slips = [i for i in XFAIL if not ENTRIES[i]["holds"]]
    assert len(unread) <= 0.05 * len(ENTRIES), unread
    assert not wrong_true and not missed_slips, (wrong_true, missed_slips)


def test_the_baseline_records_every_entry():
    assert set(BASELINE) == set(ENTRIES)
    assert set(XFAIL) <= set(ENTRIES)
