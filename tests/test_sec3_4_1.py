"""Sec. 3.4.1 kernels (instant screw) against their defining properties, numerically.

Book: Angeles, Sec. 3.4.1, Eqs. (3.53)-(3.55), (3.70). The velocity field of a rigid body
is ``v(x) = a_dot + omega x (x - a)`` (Eq. (3.50)); the instant screw axis (ISA) is the
set of points whose velocity is parallel to ``omega``.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations.sec3_4_1 import (
    instant_screw_axis_point,
    instant_screw_pitch,
    instant_screw_plucker,
)

_num = st.integers(-50, 50).map(lambda k: sp.Rational(k, 7))
_vec = st.tuples(_num, _num, _num).map(lambda v: sp.Matrix(v))
_nonzero = _vec.filter(lambda w: any(x != 0 for x in w))
# angular velocities near the singular set omega = 0
_small = st.tuples(_nonzero, st.integers(3, 12)).map(lambda t: t[0] / sp.Integer(10) ** t[1])


def _velocity(x, omega, a, a_dot):
    return a_dot + omega.cross(x - a)


def _check_point_and_pitch(omega, a, a_dot):
    p0 = instant_screw_axis_point(omega, a, a_dot)
    assert (omega.T * p0)[0] == 0  # (3.64): nearest point is normal to omega
    assert omega.cross(_velocity(p0, omega, a, a_dot)) == sp.zeros(3, 1)  # on the ISA
    # every other point of the ISA is farther from the origin
    for alpha in (sp.Rational(1, 3), -2):
        q = p0 + alpha * omega
        assert omega.cross(_velocity(q, omega, a, a_dot)) == sp.zeros(3, 1)
        assert (q.T * q)[0] > (p0.T * p0)[0]
    # the pitch is the same for every body point (Corollary 3.4.1)
    x = a + sp.Matrix([1, -2, sp.Rational(1, 2)])
    assert instant_screw_pitch(omega, _velocity(x, omega, a, a_dot)) == \
        instant_screw_pitch(omega, a_dot)


@settings(max_examples=examples(40), deadline=None)
@given(_nonzero, _vec, _vec)
def test_isa_point_and_pitch_uniform(omega, a, a_dot):
    _check_point_and_pitch(omega, a, a_dot)


@settings(max_examples=examples(20), deadline=None)
@given(_small, _vec, _vec)
def test_isa_point_and_pitch_near_pure_translation(omega, a, a_dot):
    _check_point_and_pitch(omega, a, a_dot)


@settings(max_examples=examples(20), deadline=None)
@given(_nonzero, _vec, _vec)
def test_plucker_array_is_a_unit_line_through_the_isa(omega, a, a_dot):
    k = instant_screw_plucker(omega, a, a_dot)
    with mpmath.workdps(40):
        e = [mpmath.mpf(sp.N(x, 45)) for x in k[:3]]
        n = [mpmath.mpf(sp.N(x, 45)) for x in k[3:]]
        assert abs(sum(x * x for x in e) - 1) < mpmath.mpf(10) ** -35
        assert abs(sum(x * y for x, y in zip(e, n, strict=True))) < mpmath.mpf(10) ** -30
        # the moment is p x e' for any ISA point p (here p'_0 + 2 omega)
        p = instant_screw_axis_point(omega, a, a_dot) + 2 * omega
        pe = sp.Matrix(p).cross(sp.Matrix(k[:3]))
        assert max(abs(mpmath.mpf(sp.N(x - y, 45))) for x, y in zip(pe, k[3:],
                                                                     strict=True)) < 1e-30
