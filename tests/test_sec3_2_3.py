"""Property tests of the Sec. 3.2-3.3 formula functions (screw axis, pitch, Plücker lines).

Random displacements and lines, sampled uniformly and near the singular sets (phi -> 0,
phi -> pi), evaluated at 50 digits: the formulas must satisfy the conditions that
characterise them (Angeles, Sec. 3.2.1-3.2.2, Eqs. (3.7), (3.18), (3.21)-(3.31)).
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations.sec3_2_1 import pitch_of_displacement, screw_axis_point
from rigidsym.derivations.sec3_2_2 import (
    plucker_from_points,
    plucker_transfer,
    plucker_transfer_matrix,
)

from rigidsym.algebra.primitives import cpm

DIGITS = 50
coord = st.floats(-5, 5, allow_nan=False, allow_infinity=False)
vec3 = st.tuples(coord, coord, coord)
#: angles uniform in (0, pi], and close to the singular phi = 0 and to phi = pi
angles = st.one_of(st.floats(1e-3, 3.14159),
                   st.floats(1e-9, 1e-4),
                   st.floats(3.14159 - 1e-6, 3.14159265))


def _f(x) -> sp.Float:
    return sp.Float(mpmath.mpf(x), DIGITS)


def _col(v) -> sp.Matrix:
    return sp.Matrix([_f(x) for x in v])


def _unit(v) -> sp.Matrix | None:
    m = _col(v)
    n = sp.sqrt((m.T * m)[0, 0])
    return None if n < 1e-3 else m / n


def _rotation(e, phi) -> sp.Matrix:
    c, s = sp.cos(_f(phi)), sp.sin(_f(phi))
    return e * e.T + c * (sp.eye(3) - e * e.T) + s * cpm(e)


def _small(x, scale=1) -> bool:
    return abs(sp.N(x, DIGITS)) < sp.Float(10) ** (-(DIGITS - 20)) * scale


@settings(max_examples=examples(40), deadline=None)
@given(axis=vec3, phi=angles, a=vec3, c=vec3)
def test_screw_axis_point_is_closest_point_of_the_axis(axis, phi, a, c):
    e = _unit(axis)
    if e is None:
        return
    Q = _rotation(e, phi)
    a, c = _col(a), _col(c)
    p0 = screw_axis_point(Q, a, Q * a + c, _f(phi))
    d0 = Q * p0 + c - p0  # displacement of p0 under x -> Q x + c
    # 50-digit rounding is amplified by 1 / (1 - cos phi) near phi = 0
    scale = (1 + (c.T * c)[0, 0] + (a.T * a)[0, 0]) / (1 - sp.cos(_f(phi)))
    assert _small((e.T * p0)[0, 0], scale)
    for x in (sp.eye(3) - e * e.T) * d0:
        assert _small(x, scale)


@settings(max_examples=examples(40), deadline=None)
@given(axis=vec3, phi=angles, a=vec3, p=vec3, c=vec3)
def test_pitch_is_the_same_from_every_point(axis, phi, a, p, c):
    e = _unit(axis)
    if e is None:
        return
    Q = _rotation(e, phi)
    a, p, c = _col(a), _col(p), _col(c)
    pa = pitch_of_displacement(e, Q * a + c - a, _f(phi))
    pp = pitch_of_displacement(e, Q * p + c - p, _f(phi))
    assert _small(pa - pp, 1 + abs(pa))


@settings(max_examples=examples(40), deadline=None)
@given(p1=vec3, p2=vec3, t=coord)
def test_plucker_array_satisfies_its_constraints_and_is_point_independent(p1, p2, t):
    p1, p2 = _col(p1), _col(p2)
    d = p2 - p1
    if (d.T * d)[0, 0] < 1e-4:
        return
    k = plucker_from_points(p1, p2)
    e, n = k[:3, :], k[3:, :]
    assert _small((e.T * e)[0, 0] - 1)
    assert _small((n.T * e)[0, 0], 100)
    # another pair of points of the same line gives the same array
    k2 = plucker_from_points(p1 + _f(t) * d, p1 + (_f(t) + 2) * d)
    for x in k - k2:
        assert _small(x, 1000)


@settings(max_examples=examples(40), deadline=None)
@given(p=vec3, axis=vec3, a=vec3, b=vec3)
def test_plucker_transfer_moves_the_moment(p, axis, a, b):
    e = _unit(axis)
    if e is None:
        return
    p, a, b = _col(p), _col(a), _col(b)
    kA = sp.Matrix.vstack(e, (p - a).cross(e))
    kB = plucker_transfer(kA, a, b)
    for x in kB - sp.Matrix.vstack(e, (p - b).cross(e)):
        assert _small(x, 100)


def test_plucker_transfer_matrix_is_unimodular_with_the_printed_inverse():
    a, b = sp.Matrix(sp.symbols("a1:4")), sp.Matrix(sp.symbols("b1:4"))
    U = plucker_transfer_matrix(a, b)
    Uinv = sp.Matrix(sp.BlockMatrix([[sp.eye(3), sp.zeros(3)],
                                     [cpm(b) - cpm(a), sp.eye(3)]]))
    assert sp.expand(U.det()) == 1
    assert (U * Uinv).expand() == sp.eye(6)


def test_plucker_transfer_rejects_a_wrong_shape():
    with pytest.raises(ValueError, match="kappa_A"):
        plucker_transfer(sp.zeros(3, 1), sp.zeros(3, 1), sp.zeros(3, 1))
