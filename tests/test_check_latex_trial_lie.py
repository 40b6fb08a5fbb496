"""An outside trial of the estimation and Lie-theory books (``tests/data/trial_lie_books.py``):
42 statements from Barfoot, Forster et al., Kok-Hol-Schön, Chirikjian and manif's
documentation, typed as their readers would with the ``--let``s docs/check-latex.md teaches,
judged by the data file's own NumPy truth (which never imports rigidsym). No verdict may be
wrong, and no case the checker decided as typed may become undecided or refused.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

import rigidsym

DATA = Path(__file__).resolve().parent / "data"
_spec = importlib.util.spec_from_file_location("trial_lie_books", DATA / "trial_lie_books.py")
trial = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(trial)
CASES = {c["id"]: c for c in trial.CASES}

#: cheap cases for the default run: one per book, a slip among them
FAST = {"b-hat-conj", "f-jr-phi", "c-trace-slip", "k-rot-orth", "m-jr-norm"}


def _holds(case: dict) -> bool:
    rng = np.random.default_rng(81)
    return max(case["truth"](rng) for _ in range(5)) < trial.TRUTH_TOLERANCE


def answer(case: dict, **options) -> str:
    """right / WRONG / refused / undecided, judged by the NumPy truth."""
    try:
        r = rigidsym.check_latex(case["latex"], let=case["let"], repairs=False, **options)
    except ValueError:
        return "refused"
    if r.verdict == "undecided":
        return "undecided"
    said = r.verdict in ("verified", "definition")
    return "right" if said == _holds(case) else "WRONG"


def test_the_trial_is_at_least_thirty_cases_from_at_least_four_books_with_slips():
    books = {c["book"] for c in trial.CASES}
    assert len(trial.CASES) >= 30 and len(books) >= 4, (len(trial.CASES), books)
    assert sum(c["slip"] for c in trial.CASES) >= 10
    assert set(trial.BEFORE) == set(CASES)


def test_the_numpy_truth_tells_each_slip_from_its_equation():
    for c in trial.CASES:
        assert _holds(c) is not c["slip"], c["id"]


def _params(ids):
    return [pytest.param(i, marks=() if i in FAST else pytest.mark.slow) for i in ids]


@pytest.mark.parametrize("cid", _params(CASES))
def test_a_trial_case_is_never_wrong_and_keeps_its_decision(cid):
    got = answer(CASES[cid])
    assert got != "WRONG", cid
    if trial.BEFORE[cid] == "right":
        assert got == "right", (cid, got)
