"""The fourth blind trial (``tests/data/blind_trial_d.json``): 49 statements from seven sources no
corpus of the project used (Ginsberg, Ardema, Landau & Lifshitz, Davidson & Hunt, Marsden &
Ratiu, Mahony–Hamel–Pflimlin (2008), Gallier), typed with the ``--let`` declarations a reader
writes from docs/check-latex.md and committed with their NumPy truth
(``tests/blind_trial_d_truth.py``, which never imports rigidsym) before the checker read any of
them. No verdict may be wrong: a ``verified`` statement is true, a ``does-not-hold`` one false.
The answers as typed are recorded by ``benchmarks/blind_trial_d.py`` in
benchmarks/results/blind_trial_d.json (39 of 49 decided, 0 wrong, 10 refused)."""

from __future__ import annotations

import json
from pathlib import Path

import _blind_trial
import _numpy_truth
import blind_trial_d_truth as truth
import pytest

DATA = Path(__file__).resolve().parent / "data" / "blind_trial_d.json"
CASES = json.loads(DATA.read_text())["cases"]

#: wrong as typed: none (the 10 misses are refusals, each named in the benchmark's NOTES)
KNOWN_WRONG: set[str] = set()


def test_the_recorded_truths_are_the_numpy_checks():
    """Cheap: each case's recorded truth is what its NumPy check says (and the set is a blind
    trial's floor: at least 40 statements, about one in four a slip, at least six sources)."""
    assert len(CASES) >= 40
    assert 0.2 <= sum(not c["truth"] for c in CASES) / len(CASES) <= 0.35
    assert len({c["book"] for c in CASES}) >= 6
    for c in CASES:
        name = c["check"].rsplit("::", 1)[1]
        assert bool(truth.holds(name)) == c["truth"], c["id"]


def test_the_truths_are_independent_of_rigidsym():
    """Cheap: the judge never imports the judged."""
    for module in (truth, _numpy_truth):
        source = Path(module.__file__).read_text()
        assert "import rigidsym" not in source and "from rigidsym" not in source


@pytest.mark.slow
@pytest.mark.parametrize("case", _blind_trial.params(CASES, KNOWN_WRONG))
def test_no_verdict_of_the_blind_trial_is_wrong(case):
    _blind_trial.assert_not_wrong(case)
