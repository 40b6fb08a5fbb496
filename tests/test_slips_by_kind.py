"""Slip credit only where a slip means something, over every exercise's boxes.

Every numeric box of every exercise (the book's data) and the true-or-false boxes of the
proofs' variants: an all-zero, blank-equivalent (``0``, ``-0``, ``1e-13``), constant or
random answer is never named a slip (so never earns slip credit); a truth or a reason
number takes no slip at all; a length multiplied by 180/pi is no "degrees" slip; and a
real slip (the key negated, a length in mm) is still named. The answers are built here
from the key with plain NumPy; what a slip is, is the test's own reading of the docs.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym.course.exam import variants_module
from rigidsym.course.grading import grade, key_array
from rigidsym.course.worked import EXERCISE_IDS, solve

_BOOK = {}
# one worker solves each exercise once for every test of the module (Exercise 3.10's
# solution costs about 7 s: two workers each solved it again)
pytestmark = pytest.mark.xdist_group("slips_by_kind")
_PROOFS = ("ex3.9", "ex3.16", "ex3.20", "ex3.3", "ex3.8")


def _solution(ex_id):
    if ex_id not in _BOOK:
        _BOOK[ex_id] = solve(ex_id)
    return _BOOK[ex_id]


def _numeric_boxes(s):
    """``{name: float array}`` of the solution's numeric boxes (no expression in symbols,
    no truth)."""
    out = {}
    for n, v in s.answers.items():
        if isinstance(v, str) or v in (sp.true, sp.false):
            continue
        if getattr(v, "free_symbols", None):
            continue
        try:
            out[n] = key_array(v)
        except TypeError:
            continue
    return out


#: the exercises the quick run grades box by box (lengths, angles, vectors, a rotation, a
#: reason's neighbours); the others' boxes in the thorough run: each exercise is solved
#: when its test runs, never at collection (solving all 21 costs tens of seconds)
QUICK = ("ex3.1", "ex3.4", "ex3.5", "ex3.10", "ex3.19")
EXERCISES = [pytest.param(e, marks=() if e in QUICK else pytest.mark.slow, id=e[2:])
             for e in EXERCISE_IDS]


def _boxes(ex_id):
    """The exercise's numeric boxes (``[]`` where it is not solved)."""
    s = _solution(ex_id)
    return [] if s.status != "solved" else list(_numeric_boxes(s))


def _typed(a: np.ndarray):
    """An array as a student types it (nested lists of floats, a number as a float)."""
    return a.tolist() if a.ndim else float(a)


def _graded(s, name, value):
    (g,) = [g for g in grade(s, {name: value}, replay=False) if g.name == name]
    return g


@pytest.mark.parametrize("ex_id", EXERCISES)
def test_zero_and_blank_equivalents_earn_no_slip(ex_id):
    s = _solution(ex_id)
    for name in _boxes(ex_id):
        k = _numeric_boxes(s)[name]
        for z in (0.0, -0.0, 1e-13):
            g = _graded(s, name, _typed(np.full(k.shape, z)))
            assert g.slip is None, (name, z, g.detail)
        if k.ndim:
            g = _graded(s, name, ",".join(["0"] * k.size) if k.ndim == 1 or k.shape[1] == 1
                        else ";".join(",".join(["0"] * k.shape[1])
                                      for _ in range(k.shape[0])))
            assert g.slip is None, g.detail


@pytest.mark.parametrize("ex_id", EXERCISES)
@settings(max_examples=examples(6), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(c=st.floats(-1e3, 1e3, allow_nan=False), seed=st.integers(0, 2**31 - 1))
def test_constant_and_random_answers_earn_no_slip(ex_id, c, seed):
    s = _solution(ex_id)
    for name in _boxes(ex_id):
        k = _numeric_boxes(s)[name]
        flat = k.reshape(-1)
        if k.size > 1 and np.ptp(flat) > 1e-3 * float(np.max(np.abs(flat))):
            # (a constant key's slips are constant: those are real slips of it)
            g = _graded(s, name, _typed(np.full(k.shape, c)))
            assert g.slip is None, (name, c, g.detail)
            rng = np.random.default_rng(seed)
            r = rng.uniform(-10, 10, k.shape) * max(float(np.max(np.abs(k))), 1.0)
            g = _graded(s, name, _typed(r))
            assert g.slip is None or g.correct, (name, r, g.detail)


def _length(ex_id, name) -> bool:
    from rigidsym.course.worked import exercise_module
    from rigidsym.course.worked.units import answer_unit

    return answer_unit(exercise_module(ex_id), name) == "m"


@pytest.mark.parametrize("ex_id", EXERCISES)
def test_a_real_slip_still_earns_it_and_a_length_has_no_degrees(ex_id):
    s = _solution(ex_id)
    for name in _boxes(ex_id):
        k = _numeric_boxes(s)[name]
        flat = k.reshape(-1)
        top = float(np.max(np.abs(flat)))
        if top == 0 or (flat.size > 1 and np.ptp(flat) <= 1e-3 * top):
            continue   # a zero or constant key: its slips are trivial answers
        g = _graded(s, name, _typed(-k))
        assert g.correct or g.slip is not None, (name, g.detail)
        if _length(ex_id, name):
            g = _graded(s, name, _typed(k * 1000))
            assert g.slip == "unit", g.detail
            g = _graded(s, name, _typed(k * 180 / np.pi))
            assert g.slip != "degrees" and not g.correct, g.detail


@pytest.fixture(scope="module")
def proofs():
    out = []
    for ex_id in _PROOFS:
        s = variants_module().draw(ex_id, random.Random(f"slips by kind {ex_id}"))
        out.append(s)
    return out


def test_truths_and_reasons_take_no_slip(proofs):
    """Every wrong truth triple and every wrong reason triple of each drawn variant: no
    slip named (so no slip credit), and the key's own triple right."""
    import itertools

    for s in proofs:
        holds = [int(x) for x in s.answers["holds"]]
        why = [int(x) for x in s.answers["why"]]
        for t in itertools.product((0, 1), repeat=3):
            for typed in (list(t), ",".join("true" if x else "false" for x in t)):
                g = _graded(s, "holds", typed)
                assert g.correct is (list(t) == holds) and g.slip is None, (s.id, t)
        for r in itertools.product((1, 2, 3, 4), repeat=3):
            g = _graded(s, "why", list(r))
            assert g.correct is (list(r) == why) and g.slip is None, (s.id, r)


def test_an_all_zero_or_false_sheet_scores_nothing_at_slip_credit(proofs):
    """A sheet of zeros and falses on every box earns no slip: at any slip credit its
    score is the boxes whose key is that zero or false."""
    for s in [*proofs, _solution("ex3.5"), _solution("ex3.19")]:
        boxes = _numeric_boxes(s)
        sheet = {n: _typed(np.zeros(k.shape)) for n, k in boxes.items()}
        for g in grade(s, sheet, replay=True):
            assert g.slip is None, (s.id, g.name, g.detail)
