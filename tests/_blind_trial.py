"""The blind trials' one rule, shared by their tests (``tests/test_check_latex_blind_*.py``):
no verdict of ``check_latex`` on a statement as typed may be wrong; a refusal or an undecided
answer is not decided, never wrong."""

from __future__ import annotations

import pytest

import rigidsym


def params(cases: list[dict], known_wrong: set[str]) -> list:
    """One pytest param a case, named by its id; the ids of ``known_wrong`` a strict xfail."""
    return [pytest.param(c, id=c["id"], marks=pytest.mark.xfail(strict=True,
                                                              reason="wrong as typed"))
            if c["id"] in known_wrong else pytest.param(c, id=c["id"]) for c in cases]


def assert_not_wrong(case: dict) -> bool:
    """The case's verdict as typed is its NumPy truth, or no verdict at all; returns whether
    it was decided."""
    try:
        r = rigidsym.check_latex(case["latex"], let=case["lets"], notation=case["notation"],
                                 repairs=False, timeout=None)
    except ValueError:
        return False  # refused: not decided, never wrong
    if r.verdict == "undecided":
        return False
    said = r.verdict in ("verified", "definition")
    assert said is case["truth"], (r.verdict, r.model)
    return True


def assert_slips_paired(cases: list[dict]) -> None:
    """Each slip's id is its true statement's id with ``-slip``, from the same book and
    place, so that each slip is judged beside the statement it was typed from."""
    by_id = {c["id"]: c for c in cases}
    for c in cases:
        if c["truth"]:
            continue
        base = by_id[c["id"].removesuffix("-slip")]
        assert base["truth"] and base["book"] == c["book"] and base["where"] == c["where"], c["id"]


def assert_independent(*modules) -> None:
    """The judges (the trial's NumPy truths) never import the judged."""
    from pathlib import Path

    for module in modules:
        source = Path(module.__file__).read_text()
        assert "import rigidsym" not in source and "from rigidsym" not in source, module


def decided(case: dict) -> bool:
    """Whether the case as typed gets a verdict (a refusal or undecided does not)."""
    try:
        r = rigidsym.check_latex(case["latex"], let=case["lets"], notation=case["notation"],
                                 repairs=False, timeout=None)
    except ValueError:
        return False
    return r.verdict != "undecided"


def assert_record_of(record: dict, cases: list[dict], known_wrong: set[str]) -> None:
    """A trial's benchmark record names each case once, in order, with its truth, judged
    consistently with its verdict, and its totals are its rows'."""
    rows = record["rows"]
    assert [r["id"] for r in rows] == [c["id"] for c in cases]
    for row, case in zip(rows, cases, strict=True):
        assert row["truth"] == case["truth"], row["id"]
        if row["verdict"] in ("bad-input", "undecided"):
            assert row["judged"] == "undecided", row["id"]
        else:
            said = row["verdict"] in ("verified", "definition")
            assert row["judged"] == ("right" if said == case["truth"] else "WRONG"), row["id"]
    assert record["n"] == len(rows)
    assert record["decided_as_typed"] == sum(r["judged"] != "undecided" for r in rows)
    assert record["wrong"] == [r["id"] for r in rows if r["judged"] == "WRONG"]
    assert set(record["wrong"]) == known_wrong
    assert record["commit"] and record["host"]["cores"]
