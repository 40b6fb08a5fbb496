"""Every numeric box of every exercise (the book's data): a member of the key's class
doubled or halved is the ``factor 2`` slip, and the key rounded to 1 or 2 significant
figures outside the tolerance is ``rounded`` with its figures (unless a slip the grader
tries first gives the same value: then that slip is named); neither is ever right.

The members come from tests/test_grading_classes.py's group actions (written there, not by
the grader); the edits and the expected names are plain NumPy here. Graded as a class
grades under its default policy (no slips along the way). The default run takes one
member of five exercises' boxes; ``-m slow`` twenty members of every exercise's.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from _profile import examples
from hypothesis import HealthCheck, given, settings
from test_grading_classes import (
    IDS,
    RTOL,
    SIGN_GROUPS,
    in_class,
    key_of,
    members,
    one_edit_slips,
)

from rigidsym.course.grading import grade


def _near(a, b, scale) -> bool:
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= RTOL * scale + 1e-12))


def _same(name, a, b, scale) -> bool:
    """Equal within the tolerance; an angle (a one-number box in rad) modulo 2 pi."""
    if a.ndim == 0 and ("phi" in name or "rad" in name or "angle" in name):
        w = (a - b + math.pi) % (2 * math.pi) - math.pi
        return _near(w, np.zeros_like(w), scale)
    return _near(a, b, scale)


def _graded(ex_id, name, value, member):
    """Box ``name`` graded alone, with the rest of its sign group as in ``member``."""
    s, key = key_of(ex_id)
    group = SIGN_GROUPS.get(ex_id, ("", "", ()))
    ctx = {n: member[n].tolist() for n in (group[0], group[1], *group[2])
           if n in key and n != name}
    return next(g for g in grade(s, {**ctx, name: value.tolist()}, replay=False)
                if g.name == name)


def _own(ex_id) -> dict:
    """The exercise's own slips (its module's ``slips``: a reference point, a transfer's
    sign), box -> values: a value one of them gives is named by it first."""
    import sympy as sp

    from rigidsym.course.worked import exercise_module

    s, _ = key_of(ex_id)
    own = getattr(exercise_module(ex_id), "slips", None)
    return {n: [np.array(sp.N(sp.Matrix(v), 17).tolist(), dtype=float)
                if isinstance(v, sp.MatrixBase) else np.array(float(sp.N(v, 17)))
                for _, _, v in items] for n, items in (own(s) if own else {}).items()}


def _check(ex_id, member):
    _, key = key_of(ex_id)
    own = _own(ex_id)
    for name, (k, truth) in key.items():
        scale = max(float(np.max(np.abs(k))), 1e-300)
        if truth or not np.any(np.abs(k) > 1e-12):
            continue
        v = member[name]
        for f in (2.0, 0.5):
            value = f * v
            if in_class(ex_id, name, value, member):
                continue
            g = _graded(ex_id, name, value, member)
            assert g.correct is False and g.slip is not None, (ex_id, name, f, g.detail)
            # named factor 2 unless an edit the grader tries first gives the same value
            earlier = [w for w, x in one_edit_slips(name, v, ex_id)
                       if _same(name, x, value, scale)]
            earlier += [x for x in own.get(name, ()) if _same(name, x, value, scale)]
            assert g.slip == "factor 2" or earlier, (ex_id, name, f, g.slip, g.detail)
        keyed = {n: x for n, (x, _) in key.items()}     # the rounding of the key itself
        for figures in (1, 2):
            r = np.vectorize(lambda x, n=figures: float(f"{x:.{n - 1}e}"))(k)
            if _near(r, k, scale) or in_class(ex_id, name, r, {**keyed, name: r}):
                continue                      # a rounding inside the tolerance is right
            if any(_same(name, x, r, scale) for _, x in one_edit_slips(name, k, ex_id)) or \
                    _same(name, 2 * k, r, scale) or _same(name, k / 2, r, scale) or \
                    any(_same(name, x, r, scale) for x in own.get(name, ())):
                continue                      # the rounding is also an earlier slip
            g = _graded(ex_id, name, r, {**keyed, name: r})
            assert g.correct is False, (ex_id, name, figures, g.detail)
            assert g.slip == "rounded" and g.note == f"rounded {figures} s.f.", \
                (ex_id, name, figures, g.slip, g.note)


def _property(ex_id, n):
    @given(member=members(ex_id))
    @settings(max_examples=examples(n), deadline=None, derandomize=True, database=None,
              suppress_health_check=list(HealthCheck))
    def run(member):
        _check(ex_id, member)

    run()


#: the default run's exercises: a sign group with a point of its axis (3.1, 3.6), the
#: exercise's own slips (3.11, 3.19), a rotation stated by its property (3.14)
QUICK = ("ex3.1", "ex3.6", "ex3.11", "ex3.14", "ex3.19")


@pytest.mark.parametrize("ex_id", QUICK)
def test_factor_two_and_rounding_of_every_box_are_named(ex_id):
    _property(ex_id, 1)


@pytest.mark.slow
@pytest.mark.thorough(1 / 3)     # each commit a third of the exercises (all: exhaustive)
@pytest.mark.parametrize("ex_id", IDS)
def test_factor_two_and_rounding_of_every_box_are_named_exhaustive(ex_id):
    _property(ex_id, 20)
