"""A slip's replay for its values only (floating data, rigidsym.course.worked.solve_values)
gives the grader and the STACK export the exact replay's values: the same float64 bits,
an entry within ZERO of 0 written 0; decisions too close to call, measured data and the
exercises that do not allow it are solved exactly."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from test_grading_replays_kept import assert_compared_as_exact

from rigidsym.course.exam import drawn_exercises
from rigidsym.course.grading import compared_answers, replayed_values
from rigidsym.course.slips import data_slips, replays
from rigidsym.course.worked import (
    EXERCISE_IDS,
    Undecided,
    exact_check,
    exercise_module,
    is_zero,
    settled,
    solve,
    solve_values,
)
from rigidsym.course.worked.checks import ZERO, for_values

#: the exercises whose solvers run on floating data for a replay
FLOATING = [e for e in EXERCISE_IDS if getattr(exercise_module(e), "VALUES_REPLAY", False)]


def _drawn(ex_id: str, seed: int):
    """A student's solution of ``ex_id`` as an exam draws it."""
    (s, _), = drawn_exercises({"problem": [{"exercise": ex_id, "variants": 1}]}, seed)
    return s


def _same_as_exact(s) -> int:
    """Compare every replay of ``s`` for its values with the exact replay, answer by
    answer; the number of replays solved on floating data."""
    fast, exact = list(replays(s, values=True, compare=compared_answers)), list(replays(s))
    assert_compared_as_exact(fast, exact, ZERO)
    tol = {"tol": s.tol} if s.tol is not None else {}
    floating = 0
    for _, _, data in data_slips(s.id, s.data):
        try:
            floating += solve_values(s.id, **tol, **data).values_only
        except (ValueError, TypeError):
            continue
    return floating


def test_the_floating_exercises_are_those_of_a_class_with_many_replays():
    assert {"ex3.2", "ex3.6", "ex3.12"} <= set(FLOATING)


@pytest.mark.sample(fraction=0.3)  # one exercise in the quick run (its exact replays are
@pytest.mark.parametrize("ex_id", FLOATING)  # the cost), the others slow
def test_a_students_replays_for_their_values_are_the_exact_replays(ex_id):
    assert _same_as_exact(_drawn(ex_id, 1)) >= 3


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(2, 8))
@pytest.mark.parametrize("ex_id", FLOATING)
def test_more_students_replays_for_their_values_are_the_exact_replays(ex_id, seed):
    assert _same_as_exact(_drawn(ex_id, seed)) >= 1


def test_the_kept_replays_are_the_floating_ones():
    s = _drawn("3.6", 1)
    kept, fresh = replayed_values(s), list(replays(s, values=True, compare=compared_answers))
    assert [(w, d) for w, d, _ in kept] == [(w, d) for w, d, _ in fresh]
    for (_, _, a), (_, _, b) in zip(kept, fresh, strict=True):
        assert all(np.array_equal(a[n], b[n]) for n in b)


@pytest.mark.parametrize("data", [
    {"P_3": [1, 0, 0]},                                            # P_2 = P_3: no f_1
    {"P_1": [0, 0, 0], "P_2": [1, 0, 0], "P_3": [1, 1, 0], "P_4": [0, 1, 0]},  # f = 0
])
def test_a_decision_at_zero_is_left_to_the_exact_solve(data):
    s = solve_values("3.2", **data)
    assert s.values_only is False
    assert s.status == solve("3.2", **data).status == "ill-posed"


def test_measured_data_and_other_exercises_are_solved_exactly():
    measured = solve_values("3.6", face_normal=[1.0, 1.02, 0.98])
    assert measured.values_only is False and measured.tol is not None
    assert "ex3.19" not in FLOATING
    assert solve_values("3.19") is solve("3.19")


def test_a_floating_solution_keeps_the_exact_data_and_runs_no_check():
    data = {"p": [1, 2, 3]}
    s = solve_values("3.6", **data)
    assert s.values_only is True and s.status == "solved"
    assert s.data == solve("3.6", **data).data
    assert not any(c.passed for c in s.checks)
    assert all(isinstance(x, sp.Float) for x in s.answers["e"])


def test_decisions_in_a_replay_for_values():
    tiny, clear = sp.Float("1e-30", 50), sp.Float("1e-3", 50)
    assert is_zero(sp.Integer(0)) is True and settled(tiny) is tiny   # exact: no margin
    with for_values():
        assert is_zero(sp.Matrix([0, clear])) is False
        assert settled(-clear) == -clear
        for undecided in (lambda: is_zero(sp.Matrix([tiny, 0])), lambda: settled(tiny)):
            with pytest.raises(Undecided):
                undecided()
        c = exact_check("never run", [sp.sqrt(2) - 1])
        assert not c.passed and "not run" in c.detail
    assert exact_check("run", [sp.sqrt(2) ** 2 - 2]).passed
