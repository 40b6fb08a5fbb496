"""The zero test: sound on the constraint set, exact witnesses when an identity fails."""

from __future__ import annotations

from fractions import Fraction

import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.algebra.primitives import cpm, rotation_from_natural_invariants, vect
from rigidsym.algebra.symbols import TIME, angle, rotation, unit_vector, vector
from rigidsym.core.settings import ENGINE
from rigidsym.zero.decide import decide_zero, evaluate, make_plan

e = unit_vector("ze")
phi = angle("zphi")
Q = rotation_from_natural_invariants(e, phi)


def test_rotation_from_natural_invariants_is_orthogonal_exactly():
    r = decide_zero(list(Q.T * Q - sp.eye(3)))
    assert r.zero is True and r.method == "exact-cancel"
    assert decide_zero([Q.det() - 1]).zero is True


def test_unit_norm_is_used_and_not_assumed_elsewhere():
    # e.e = 1 holds; e.e = 2 and a free vector of unit norm do not
    assert decide_zero([(e.T * e)[0] - 1]).zero is True
    r = decide_zero([(e.T * e)[0] - 2])
    assert r.zero is False and r.method == "counterexample"
    x = vector("zx")
    assert decide_zero([(x.T * x)[0] - 1]).zero is False


def test_witness_is_an_exact_counterexample():
    expr = sp.cos(phi) ** 2 - sp.sin(phi) ** 2 - 1
    r = decide_zero([expr])
    assert r.zero is False
    value = evaluate(expr, r.plan, r.witness)
    assert isinstance(value, Fraction) and value != 0


def test_half_angles_and_tangents():
    ids = [sp.sin(phi / 2) ** 2 - (1 - sp.cos(phi)) / 2,
           sp.tan(phi / 2) - sp.sin(phi) / (1 + sp.cos(phi)),
           sp.cos(3 * phi) - (4 * sp.cos(phi) ** 3 - 3 * sp.cos(phi)),
           sp.sin(phi + sp.pi / 2) - sp.cos(phi)]
    assert decide_zero(ids).zero is True
    assert decide_zero([sp.tan(phi / 2) - sp.sin(phi) / (1 - sp.cos(phi))]).zero is False


def test_bare_angle_is_independent_of_its_sine():
    # phi * cos(phi)**2 + phi * sin(phi)**2 - phi == 0, but phi - sin(phi) is not 0
    assert decide_zero([phi * sp.cos(phi) ** 2 + phi * sp.sin(phi) ** 2 - phi]).zero is True
    assert decide_zero([phi - sp.sin(phi)]).zero is False


def test_generic_rotation_and_cpm_identities():
    R = rotation("zR")
    v = vector("zv")
    ids = list(R.T * R - sp.eye(3)) + [R.det() - 1]
    ids += list(R * cpm(v) * R.T - cpm(R * v))  # cpm is equivariant under rotations
    ids += list(vect(cpm(v)) - v)
    assert decide_zero(ids).zero is True


def test_time_derivatives_stay_on_the_constraint_set():
    f = unit_vector("zf", TIME)
    th = angle("zth", TIME)
    R = rotation_from_natural_invariants(f, th)
    Om = R.diff(TIME) * R.T
    assert decide_zero(list(Om + Om.T)).zero is True          # Omega is skew
    assert decide_zero([(f.T * f.diff(TIME))[0]]).zero is True  # e . e_dot = 0
    assert decide_zero([(f.T * f.diff(TIME, 2))[0]]).zero is False
    # angular velocity of a rotation about a fixed axis is phi_dot e
    g = unit_vector("zg")
    R2 = rotation_from_natural_invariants(g, th)
    w = vect(R2.diff(TIME) * R2.T)
    assert decide_zero(list(w - th.diff(TIME) * g)).zero is True


def test_large_expressions_take_the_schwartz_zippel_path(monkeypatch):
    monkeypatch.setattr(ENGINE, "cancel_node_limit", 5)
    r = decide_zero(list(Q.T * Q - sp.eye(3)))
    assert r.zero is True and r.method == "random-exact"
    assert "P(false zero) <=" in r.detail
    r = decide_zero([(Q.T * Q)[0, 0] - 1 + sp.Rational(1, 10**9) * e[0]])
    assert r.zero is False


@settings(max_examples=examples(25), deadline=None)
@given(st.integers(-50, 50), st.integers(1, 50), st.integers(-50, 50), st.integers(1, 50))
def test_plan_points_satisfy_unit_norm_exactly(p, q, r, s):
    plan = make_plan(list(e))
    u, v = plan.params
    pt = {u: Fraction(p, q), v: Fraction(r, s)}
    vals = [evaluate(c, plan, pt) for c in e]
    assert sum(x * x for x in vals) == 1
