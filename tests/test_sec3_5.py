"""Sec. 3.5 (Angeles, Eqs. (3.84)-(3.97e)): formula functions and the misprint evidence.

The declarations use the rate formulas with the book's symbols (compact forms); here the
explicit forms in ``(e, phi, omega)`` -- what the code generator emits -- are checked
against the derivatives taken along a generic motion, and the evidence lines of the
does-not-hold verdicts are backed by exact zero tests.
"""

from __future__ import annotations

import pytest
import sympy as sp
from rigidsym.derivations import sec3_5_rate_equations as RE
from rigidsym.derivations import sec3_5_rates as R
from rigidsym.derivations.common import Mt
from rigidsym.derivations.sec3_5 import point_acceleration

from rigidsym.algebra.primitives import block, cpm
from rigidsym.algebra.symbols import TIME
from rigidsym.checking.checker import explicit
from rigidsym.zero.decide import decide_zero


def _zero(lhs, rhs, model=None):
    lhs, rhs = explicit(lhs, model), explicit(rhs, model)
    return decide_zero(list(lhs - rhs), seed=7).zero


@pytest.fixture(scope="module")
def motion():
    m = R.rates_model()
    return m, m[Mt.e], m[Mt.phi], m[Mt.omega]


@pytest.mark.parametrize("fn, rate", [
    (R.N_matrix_dot, R.Rt.N_dot), (R.L_matrix_dot, R.Rt.L_dot), (R.H_matrix_dot, R.Rt.H_dot),
    (R.N_tilde_dot, R.Rt.Nt_dot), (R.L_tilde_dot, R.Rt.Lt_dot), (R.H_tilde_dot, R.Rt.Ht_dot),
])
def test_explicit_rate_formula_equals_derivative_along_the_motion(fn, rate, motion):
    """``fn(e, phi, omega)`` with omega = vect(Q_dot Q^T) of the motion equals d/dt F."""
    m, e, phi, omega = motion
    assert _zero(m[rate], fn(e, phi, omega)) is True


def test_B_matrix_is_the_scaled_upper_block_of_N_dot(motion):
    m, e, phi, omega = motion
    assert _zero(m[R.Rt.B], R.B_matrix(e, phi, omega)) is True


def test_explicit_and_book_forms_agree_at_a_point():
    """Explicit mode and book-symbol mode are the same formula (spot value, exact)."""
    e = sp.Matrix([sp.Rational(2, 3), sp.Rational(1, 3), sp.Rational(2, 3)])
    phi, w = sp.Rational(7, 10), sp.Matrix([1, -2, sp.Rational(1, 2)])
    nu_dot = R._N(e, phi) * w
    model = {Mt.e: e, Mt.phi: phi, Mt.omega: w, Mt.Omega: cpm(w), Mt.E: cpm(e),
             Mt.e_dot: nu_dot[:3, :], Mt.phi_dot: nu_dot[3], R.I3: sp.eye(3),
             R.Rt.E_dot: cpm(nu_dot[:3, :])}
    model = {k: (sp.ImmutableMatrix(v) if isinstance(v, sp.MatrixBase) else v)
             for k, v in model.items()}
    for fn in (R.B_matrix, R.N_matrix_dot, R.N_tilde_dot):
        diff = explicit(R._book(fn), model) - fn(e, phi, w)
        assert all(abs(sp.N(x, 40)) < 1e-30 for x in diff), fn.__name__


def test_397a_repaired_reading_still_misses_the_E_dot_term(motion):
    """Even with the tilde and phi restored, (3.97a) lacks (1 - cos phi) E_dot."""
    m, e, phi, _ = motion
    e_dot, phi_dot = e.diff(TIME), phi.diff(TIME)
    repaired = block([[phi_dot * (sp.cos(phi) * sp.eye(3) + sp.sin(phi) * cpm(e)), e_dot]])
    assert _zero(m[R.Rt.Nt_dot], repaired) is False
    missing = block([[(1 - sp.cos(phi)) * cpm(e_dot), sp.zeros(3, 1)]])
    assert _zero(m[R.Rt.Nt_dot], repaired + missing) is True


def test_397c_repaired_reading_is_half_the_rate(motion):
    m, e, phi, _ = motion
    r, r0 = sp.sin(phi / 2) * e, sp.cos(phi / 2)
    repaired = block([[r0.diff(TIME) * sp.eye(3) + cpm(r.diff(TIME)), -r.diff(TIME)]])
    assert _zero(m[R.Rt.Ht_dot], repaired) is False
    assert _zero(m[R.Rt.Ht_dot], 2 * repaired) is True


def test_the_other_left_inverse_of_L_is_a_left_inverse(motion):
    """[1 + (U - u u^T)/D, -u] L = 1: (3.97b, d) are its rates; (3.77c) differs from it."""
    _, e, phi, _ = motion
    u, D = sp.sin(phi) * e, 1 + sp.cos(phi)
    alt = block([[sp.eye(3) + (cpm(u) - u * u.T) / D, -u]])
    assert _zero(alt * R._L(e, phi), sp.eye(3)) is True
    assert _zero(alt, R._L_tilde(e, phi)) is False


def test_397b_sign_of_u_dot(motion):
    """With the printed +u_dot, [V/D, u_dot] is not the rate of any of the two left inverses."""
    m, *_ = motion
    printed = sp.BlockMatrix([[RE._V_printed() / R.Rt.D, R.Rt.u_dot]])
    assert _zero(R.Rt.Lt_alt_dot, printed, m) is False
    assert _zero(R.Rt.Lt_dot, printed, m) is False


def test_point_acceleration_uniform_rotation():
    """Uniform rotation about z: the acceleration is centripetal, -w^2 (p - a) in the plane."""
    w = sp.Symbol("w", positive=True)
    p = sp.Matrix([2, 0, 5])
    acc = point_acceleration(sp.zeros(3, 1), sp.Matrix([0, 0, w]), sp.zeros(3, 1), p,
                             sp.zeros(3, 1))
    assert acc == sp.Matrix([-2 * w**2, 0, 0])
