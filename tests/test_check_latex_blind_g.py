"""The seventh blind trial (``tests/data/blind_trial_g.json``): 51 statements, 20 of them slips,
from seven sources no corpus or earlier trial of the project used (Paul, Altmann, Arnold, Curtis,
Sidi, Vince, Bottema & Roth), typed in each source's glyphs with the ``--let`` declarations a
reader writes from docs/check-latex.md and committed with their NumPy truth
(``tests/blind_trial_g_truth.py``, which never imports rigidsym) before the checker read any of
them. No verdict may be wrong: a ``verified`` statement is true, a ``does-not-hold`` one false;
and the share decided as typed may not fall below the record of ``benchmarks/blind_trial_g.py``
(benchmarks/results/blind_trial_g.json: RECORD_FIGURES)."""

from __future__ import annotations

import json
from pathlib import Path

import _blind_trial
import _numpy_truth
import blind_trial_g_truth as truth
import pytest

import rigidsym

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_g.json"
RECORD = ROOT / "benchmarks" / "results" / "blind_trial_g.json"
CASES = json.loads(DATA.read_text())["cases"]

#: wrong as typed: none
KNOWN_WRONG: set[str] = set()

#: whether each case was decided as typed, filled by the per-case test for the share's test
_DECIDED: dict[str, bool] = {}


def test_the_recorded_truths_are_the_numpy_checks():
    """Cheap: each case's recorded truth is what its NumPy check says (and the set is a blind
    trial's floor: at least 40 statements, about one in three a slip, at least six sources)."""
    assert len(CASES) >= 40
    assert len({c["id"] for c in CASES}) == len(CASES)
    assert 0.2 <= sum(not c["truth"] for c in CASES) / len(CASES) <= 0.4
    assert len({c["book"] for c in CASES}) >= 6
    for c in CASES:
        assert (c["slip"] is None) is c["truth"], c["id"]  # a slip is false, a truth has none
        name = c["check"].rsplit("::", 1)[1]
        assert bool(truth.holds(name)) == c["truth"], c["id"]


def test_each_slip_is_one_edit_of_a_true_statement_of_its_book():
    """Cheap: a slip's id is its true statement's id with ``-slip``, from the same book and
    place, so that each slip is judged beside the statement it was typed from."""
    by_id = {c["id"]: c for c in CASES}
    for c in CASES:
        if c["truth"]:
            continue
        base = by_id[c["id"].removesuffix("-slip")]
        assert base["truth"] and base["book"] == c["book"] and base["where"] == c["where"], c["id"]


def test_the_truths_are_independent_of_rigidsym():
    """Cheap: the judge never imports the judged."""
    for module in (truth, _numpy_truth):
        source = Path(module.__file__).read_text()
        assert "import rigidsym" not in source and "from rigidsym" not in source


def test_the_record_is_of_these_statements():
    """Cheap: the benchmark's record names each case once, with its truth, judged consistently
    with its verdict, and its totals are its rows'."""
    record = json.loads(RECORD.read_text())
    rows = record["rows"]
    assert [r["id"] for r in rows] == [c["id"] for c in CASES]
    for row, case in zip(rows, CASES, strict=True):
        assert row["truth"] == case["truth"], row["id"]
        if row["verdict"] in ("bad-input", "undecided"):
            assert row["judged"] == "undecided", row["id"]
        else:
            said = row["verdict"] in ("verified", "definition")
            assert row["judged"] == ("right" if said == case["truth"] else "WRONG"), row["id"]
    assert record["n"] == len(rows)
    assert record["decided_as_typed"] == sum(r["judged"] != "undecided" for r in rows)
    assert record["wrong"] == [r["id"] for r in rows if r["judged"] == "WRONG"]
    assert set(record["wrong"]) == KNOWN_WRONG
    assert record["commit"] and record["host"]["cores"]


def _decided(case: dict) -> bool:
    try:
        r = rigidsym.check_latex(case["latex"], let=case["lets"], notation=case["notation"],
                                 repairs=False, timeout=None)
    except ValueError:
        return False
    return r.verdict != "undecided"


@pytest.mark.slow
@pytest.mark.parametrize("case", _blind_trial.params(CASES, KNOWN_WRONG))
def test_no_verdict_of_the_blind_trial_is_wrong(case):
    _blind_trial.assert_not_wrong(case)
    _DECIDED[case["id"]] = _decided(case)


@pytest.mark.slow
def test_the_share_decided_as_typed_is_not_below_the_record():
    record = json.loads(RECORD.read_text())
    decided = sum(_DECIDED[c["id"]] if c["id"] in _DECIDED else _decided(c) for c in CASES)
    assert decided >= record["decided_as_typed"], (decided, record["decided_as_typed"])
