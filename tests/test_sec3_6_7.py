"""Sections 3.6-3.7: kernels by property, and the checks are sensitive to misprints."""

from __future__ import annotations

import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations import sec3_6, sec3_7, sec3_7_reciprocity

from rigidsym.algebra.primitives import cpm, rotation_from_quaternion
from rigidsym.checking.checker import decide_rel
from rigidsym.registry.declarations import Rel

ints = st.integers(-9, 9)
vec3 = st.tuples(ints, ints, ints).map(lambda v: sp.Matrix(v))
nonzero = vec3.filter(lambda v: any(v))


@settings(max_examples=examples(30), deadline=None)
@given(nonzero, vec3, vec3, vec3, st.integers(-5, 5))
def test_wrench_axis_point_and_pitch(f, n_A, a, q, lam):
    """The kernel point has the moment parallel to f, is normal to f, minimises |n|."""
    p0 = sec3_7.wrench_axis_point(n_A, f, a)

    def moment(x):
        return n_A + (a - x).cross(f)

    assert f.cross(moment(p0)) == sp.zeros(3, 1)
    assert f.dot(p0) == 0
    assert moment(p0 + lam * f) == moment(p0)
    assert moment(q).dot(moment(q)) >= moment(p0).dot(moment(p0))
    assert moment(p0) == sec3_7.wrench_pitch(n_A, f) * f
    assert sec3_7.wrench_pitch(moment(q), f) == sec3_7.wrench_pitch(n_A, f)


@settings(max_examples=examples(30), deadline=None)
@given(vec3, vec3, vec3, vec3)
def test_wrench_transfer(n_A, f, a, p):
    """w_P = V w_A is the moment transfer (3.106); V^-1 = U^T."""
    w_P = sec3_7.wrench_transfer(sp.Matrix.vstack(n_A, f), a, p)
    assert w_P == sp.Matrix.vstack(n_A + (a - p).cross(f), f)
    V = sec3_7.wrench_transfer_matrix(a, p)
    U = sp.Matrix(sp.BlockMatrix([[sp.eye(3), sp.zeros(3)],
                                  [cpm(a) - cpm(p), sp.eye(3)]]).as_explicit())
    assert V.inv() == U.T


def test_moving_frame_acceleration_against_differentiation():
    """(3.105) kernel equals the second derivative of o + Q rho_M along a concrete motion."""
    t = sp.Symbol("t", real=True)
    Q = rotation_from_quaternion([t, 1 - t**2, 2 * t, 3])
    o = sp.Matrix([t**3, sp.sin(t), 1])
    rho = sp.Matrix([t, t**2, 5])
    Om = Q.diff(t) * Q.T
    omega = sp.Matrix([Om[2, 1], Om[0, 2], Om[1, 0]])
    got = sec3_6.moving_frame_acceleration(o.diff(t, 2), Q, omega, omega.diff(t), rho,
                                           rho.diff(t), rho.diff(t, 2))
    want = (o + Q * rho).diff(t, 2)
    for tv in (sp.Rational(1, 3), sp.Rational(-2, 5)):
        assert max(abs(x) for x in sp.N((got - want).subs(t, tv), 40)) < 1e-30


def test_misprints_are_caught():
    """A Coriolis factor 1, a sign flip in (3.111) and U V = 1 are each found false."""
    st5 = sec3_6.acceleration_in_fixed_frame()
    s6 = sec3_6
    wrong = (s6.oddot_F + (s6.Omegadot_F + s6.Omega_F * s6.Omega_F) * s6.Q_F * s6.rho_M
             + s6.Omega_F * s6.Q_F * s6.rhodot_M + s6.Q_F * s6.rhoddot_M)
    assert decide_rel(Rel(s6.pddot_F, wrong), st5.model, 1).zero is False
    st11 = sec3_7.wrench_axis_nearest_point()
    s7 = sec3_7
    flipped = s7._x(s7.f, sp.Matrix(s7.n_A) + s7._x(s7.f, s7.a)) / s7.norm_f**2
    assert decide_rel(Rel(s7.p0_w, flipped), st11.model, 1).zero is False
    st21 = sec3_7_reciprocity.transfer_matrices_product()
    assert decide_rel(Rel(s7.U * s7.V, sp.Identity(6)), st21.model, 1).zero is False
