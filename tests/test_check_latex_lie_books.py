"""The estimation and Lie-theory books (``tests/data/lie_books_typed.py``): 42 statements
from Barfoot, Forster et al., Kok-Hol-Schön, Chirikjian and manif's documentation, typed as
their readers would with the ``--let``s docs/check-latex.md teaches,
judged by the data file's own NumPy truth (which never imports rigidsym). No verdict may be
wrong, each case answers as recorded (as typed, and after the one attempt its message names),
and no case the baseline checker decided as typed (``BASELINE``) is undecided or refused.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import _typed_trials as typed_trials
import pytest
from _profile import fast_or_slow

DATA = Path(__file__).resolve().parent / "data"
_spec = importlib.util.spec_from_file_location("lie_books_typed", DATA / "lie_books_typed.py")
trial = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(trial)
CASES = {c["id"]: c for c in trial.CASES}

#: cheap cases for the default run: one per book, a slip among them, and one attempt
FAST = {"b-hat-conj", "f-jr-phi", "c-trace-slip", "k-odot", "m-so3-ad"}


def _holds(case: dict) -> bool:
    return typed_trials.holds(case, trial.TRUTH_TOLERANCE)


def answer(case: dict, latex: str | None = None, lets: list | None = None) -> str:
    return typed_trials.answer(case, trial.TRUTH_TOLERANCE, latex, lets)


def test_the_trial_is_at_least_thirty_cases_from_at_least_four_books_with_slips():
    books = {c["book"] for c in trial.CASES}
    assert len(trial.CASES) >= 30 and len(books) >= 4, (len(trial.CASES), books)
    assert sum(c["slip"] for c in trial.CASES) >= 10
    assert set(trial.BASELINE) == set(CASES)


def test_the_numpy_truth_tells_each_slip_from_its_equation():
    for c in trial.CASES:
        assert _holds(c) is not c["slip"], c["id"]


@pytest.mark.parametrize("cid", fast_or_slow(CASES, FAST))
def test_a_trial_case_is_never_wrong_and_answers_as_recorded(cid):
    case = CASES[cid]
    got = answer(case)
    assert got != "WRONG" and got == trial.AS_TYPED[cid], (cid, got)
    if trial.BASELINE[cid] == "right":
        assert got == "right", (cid, got)
    if cid in trial.ATTEMPT:
        got = answer(case, *trial.attempted(case))
        assert got != "WRONG" and got == trial.AS_ATTEMPTED[cid], (cid, got)


def test_the_record_meets_the_floor_no_wrong_verdict_and_90_percent_decided():
    final = {c: trial.AS_ATTEMPTED.get(c, trial.AS_TYPED[c]) for c in CASES}
    assert "WRONG" not in trial.BASELINE.values() and "WRONG" not in final.values()
    decided = sum(v == "right" for v in final.values())
    assert decided >= 0.9 * len(CASES), decided
    assert sum(v == "right" for v in trial.AS_TYPED.values()) >= \
        sum(v == "right" for v in trial.BASELINE.values())
