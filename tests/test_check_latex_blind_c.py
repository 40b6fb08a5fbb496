"""The third blind trial (``tests/data/blind_trial_c.json``): 50 statements from eight books no
corpus of the project used (Jazar, Khalil & Dombre, LaValle, Szeliski, Farrell, Stevens–Lewis–
Johnson, Thornton & Marion, Stillwell), typed with the ``--let`` declarations a reader writes
from docs/check-latex.md and committed with their NumPy truth (``tests/blind_trial_c_truth.py``,
which never imports rigidsym) before the checker read any of them. No verdict may be wrong: a
``verified`` statement is true, a ``does-not-hold`` one false. The answers as typed are
recorded by ``benchmarks/blind_trial_c.py`` in benchmarks/results/blind_trial_c.json."""

from __future__ import annotations

import json
from pathlib import Path

import _blind_trial
import blind_trial_c_truth as truth
import pytest

import rigidsym

DATA = Path(__file__).resolve().parent / "data" / "blind_trial_c.json"
CASES = json.loads(DATA.read_text())["cases"]

#: wrong as typed: none (Szeliski's quaternion (x, y, z, w) multiplied by Hamilton's rule
#: (2.42) is asked: the readings of \otimes include Hamilton's rule with the scalar last)
KNOWN_WRONG: set[str] = set()


def test_the_recorded_truths_are_the_numpy_checks():
    """Cheap: each case's recorded truth is what its NumPy check says (and the set is a blind
    trial's floor: at least 40 statements, about one in four a slip)."""
    assert len(CASES) >= 40
    assert 0.2 <= sum(not c["truth"] for c in CASES) / len(CASES) <= 0.35
    for c in CASES:
        name = c["check"].rsplit("::", 1)[1]
        assert bool(truth.holds(name)) == c["truth"], c["id"]


@pytest.mark.slow
@pytest.mark.parametrize("case", _blind_trial.params(CASES, KNOWN_WRONG))
def test_no_verdict_of_the_blind_trial_is_wrong(case):
    _blind_trial.assert_not_wrong(case)


def test_a_counterexample_avoids_the_points_where_a_side_is_undefined():
    """Stevens-Lewis-Johnson's Euler rates with a sign slipped: tan(theta) in a --let is
    undefined at theta = pi/2, a small witness the search meets; the point shown is one where
    both sides are defined (before: undecided, 'ZeroDivisionError while checking')."""
    case = next(c for c in CASES if c["id"] == "sl-euler-rates-slip")
    r = rigidsym.check_latex(case["latex"], let=case["lets"], repairs=False)
    assert r.verdict == "does-not-hold", (r.verdict, r.detail)
    assert r.counterexample and "theta" in r.counterexample["point"]
