"""Lines given as measurements: Exercise 3.5's Plücker coordinates and 3.7's
moments written to 6 decimals are judged within the tolerance, not exactly.

The lines are drawn here (a rational unit direction from a Pythagorean quadruple, a point
of small integers), their exact Plücker coordinates and moments computed here, then
written to 6 decimals: the exercise solves them, prints the residual (the distance to the
nearest line's data, within the digits' tolerance whatever the line's distance or the
points' spread), and its answers are the exact line's; the same data moved off a line are
refused at the digits' tolerance, in one sentence naming a tolerance that would accept
them, and solved when that tolerance is given.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import rigidsym.exercises as ex
from rigidsym.course.worked import render_text

QUADRUPLES = ((1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (2, 6, 9, 11), (4, 4, 7, 9))
ints = st.integers(-4, 4)
points = st.tuples(ints, ints, ints).map(lambda v: sp.Matrix(v))


@st.composite
def unit_directions(draw) -> sp.Matrix:
    """A rational unit vector: a Pythagorean quadruple, permuted, with signs."""
    a, b, c, n = draw(st.sampled_from(QUADRUPLES))
    order = draw(st.permutations([a, b, c]))
    signs = draw(st.tuples(*[st.sampled_from([-1, 1])] * 3))
    return sp.Matrix([s * x for s, x in zip(signs, order, strict=True)]) / n


def _six(v: sp.Matrix) -> list[str]:
    return [f"{float(x):.6f}" for x in v]


def _f(v) -> np.ndarray:
    return np.array(sp.N(v, 17).tolist() if isinstance(v, sp.MatrixBase) else sp.N(v, 17),
                    dtype=float)


def _settings(n: int):
    return settings(max_examples=n, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def _line_35(e, p, scale):
    """3.5 on the line through p along e, its coordinates scaled and written to 6
    decimals; then moved off a line by e.n = 1e-3."""
    n = p.cross(e)
    assume(any(n))
    exact_pstar = e.cross(n)                          # the foot of the perpendicular
    data = _six(sp.Matrix.vstack(e, n) * scale)       # homogeneous: any positive scale
    s = ex.solve("3.5", plucker=data)
    assert s.status == "solved", s.reason
    assert all(c.passed for c in s.checks)
    residual = s.answers.get("residual", 0)
    assert 0 <= float(residual) <= float(s.tol)
    if "residual" in s.answers:
        assert "residual" in render_text(s)
    assert np.allclose(_f(s.answers["p_star"]).ravel(), _f(exact_pstar).ravel(), atol=1e-5)
    assert abs(float(sp.N(s.answers["d"])) - float(sp.N(n.norm()))) < 1e-5
    off = sp.Matrix.vstack(e, n + sp.Rational(1, 1000) * e)    # e.n = 1e-3: no line
    bent = ex.solve("3.5", plucker=_six(off))
    assert bent.status == "ill-posed" and "tol = " in bent.reason
    assert "--tol" in bent.reason
    assert ex.solve("3.5", plucker=_six(off), tol="0.002").status == "solved"


def _moments_37(e, p, a, b):
    """3.7 on the line through p along e, its moments about a and b written to 6
    decimals; then n_B moved 1e-3 m off every line's."""
    nA, nB = (p - a).cross(e), (p - b).cross(e)
    assume(any(nA.cross(nB)) and a != b)              # the moments decide the direction
    exact_pstar = p - p.dot(e) * e
    data = {"a": list(a), "b": list(b), "n_A": _six(nA), "n_B": _six(nB)}
    s = ex.solve("3.7", **data)
    assert s.status == "solved", s.reason
    assert all(c.passed for c in s.checks)
    assert np.allclose(_f(s.answers["e"]).ravel(), _f(e).ravel(), atol=1e-5)
    assert np.allclose(_f(s.answers["p_star"]).ravel(), _f(exact_pstar).ravel(), atol=1e-4)
    if "residual" in s.answers:
        assert 0 <= float(s.answers["residual"]) <= float(s.tol)
        assert "residual" in render_text(s)
    # n_B moved 1e-3 m along b - a: then (n_A - n_B).(b - a) = 1e-3 |b - a|, while every
    # line has n_A - n_B = (b - a) x e, so the data are at least 1e-3/sqrt(2) m from any
    # line's moments (the gradient of that product has norm sqrt(2) |b - a|)
    bent = dict(data, n_B=_six(nB - sp.Rational(1, 1000) * (b - a).normalized()))
    refused = ex.solve("3.7", **bent)
    assert refused.status == "ill-posed" and "tol = " in refused.reason, refused.reason
    assert ex.solve("3.7", tol="0.01", **bent).status == "solved"


LINES = dict(e=unit_directions(), p=points, scale=st.sampled_from([1, 2, 3]))
MOMENTS = dict(e=unit_directions(), p=points, a=points, b=points)


@_settings(3)
@given(**LINES)
def test_35_plucker_coordinates_to_six_decimals(e, p, scale):
    _line_35(e, p, scale)


@_settings(3)
@given(**MOMENTS)
def test_37_moments_to_six_decimals(e, p, a, b):
    _moments_37(e, p, a, b)


@pytest.mark.slow
@_settings(60)
@given(**LINES)
def test_35_plucker_coordinates_to_six_decimals_exhaustive(e, p, scale):
    _line_35(e, p, scale)


@pytest.mark.slow
@_settings(60)
@given(**MOMENTS)
def test_37_moments_to_six_decimals_exhaustive(e, p, a, b):
    _moments_37(e, p, a, b)
