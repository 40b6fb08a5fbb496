"""Sec. 3.4.2 formula functions, by property: left inverses, projectors, rates along explicit
trajectories (mpmath finite differences at 40 digits), twist transfer.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, Sec. 3.4.2, (3.76)-(3.83).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations.sec3_4_2 import (
    H_matrix,
    H_tilde,
    L_matrix,
    L_tilde,
    N_matrix,
    N_tilde,
    twist_transfer,
    twist_transfer_matrix,
)

from rigidsym.algebra.primitives import rotation_from_natural_invariants, vect

_e = sp.Matrix(sp.symbols("e1:4", real=True))
_phi = sp.Symbol("phi", real=True)
_F = {name: sp.lambdify([*_e, _phi], f(_e, _phi), "numpy")
      for name, f in (("N", N_matrix), ("L", L_matrix), ("H", H_matrix), ("Nt", N_tilde),
                      ("Lt", L_tilde), ("Ht", H_tilde))}


def _mats(e, phi):
    return {k: np.asarray(f(*e, phi), dtype=float) for k, f in _F.items()}


def _projector(name, e, phi):
    s, c = np.sin(phi), np.cos(phi)
    if name == "N":
        return np.eye(4) - np.outer(np.r_[e, -s], np.r_[e, 0.0])
    lam = np.r_[s * e, c]
    if name == "L":
        return np.eye(4) - np.outer(np.r_[s * e, 1 + c], lam) / (1 + c)
    eta = np.r_[np.sin(phi / 2) * e, np.cos(phi / 2)]
    return np.eye(4) - np.outer(eta, eta)


unit = st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda v: np.linalg.norm(v) > 0.1).map(
    lambda v: np.asarray(v) / np.linalg.norm(v))
# uniform angles, and angles near the singular sets phi -> 0 and phi -> pi
angles = st.one_of(st.floats(0.05, 2 * np.pi - 0.05),
                   st.floats(1e-6, 1e-2), st.floats(np.pi - 1e-2, np.pi - 1e-6))


@settings(max_examples=examples(60), deadline=None)
@given(unit, angles)
def test_left_inverses_and_projectors(e, phi):
    m = _mats(e, phi)
    for F in ("N", "L", "H"):
        Ft = m[F + "t"]
        if (F == "N" and phi < 1e-2) or (F == "L" and abs(phi - np.pi) < 1e-2):
            continue  # singular set of the pair (N at phi = 0, Ltilde at phi = pi)
        assert np.allclose(Ft @ m[F], np.eye(3), atol=1e-8)
        P = m[F] @ Ft
        assert np.allclose(P, _projector(F, e, phi), atol=1e-8)
        assert np.allclose(P @ P, P, atol=1e-8)


@settings(max_examples=examples(30), deadline=None)
@given(unit, st.floats(1e-6, 1e-2))
def test_regular_near_singular_sets(e, eps):
    """Ntilde, L, H, Htilde stay bounded at phi -> 0; N, Ntilde, H, Htilde at phi -> pi."""
    for phi, names in ((eps, ("Nt", "L", "H", "Ht", "Lt")), (np.pi - eps, ("N", "Nt", "H", "Ht"))):
        m = _mats(e, phi)
        for k in names:
            assert np.all(np.isfinite(m[k])) and np.abs(m[k]).max() < 10


@pytest.mark.parametrize("t0", ["0.3", "1.1", "2.9"])
def test_rates_along_an_explicit_trajectory(t0):
    """nu_dot = N omega, lambda_dot = L omega, eta_dot = H omega and omega = Ftilde q_dot,
    with omega = vect(Qdot Q^T) and the rates by mpmath differentiation at 40 digits."""
    with mpmath.workdps(40):
        def e_of(t):
            v = mpmath.matrix([mpmath.cos(t), mpmath.sin(2 * t), 1 + t / 3])
            return v / mpmath.norm(v)

        def phi_of(t):
            return mpmath.mpf("0.4") + t + mpmath.sin(t) / 2

        ee, ph = sp.Matrix(sp.symbols("a1:4")), sp.Symbol("b")
        Qf = sp.lambdify([*ee, ph], rotation_from_natural_invariants(ee, ph), "mpmath")

        def Q_of(t):
            return mpmath.matrix(Qf(*e_of(t), phi_of(t)).tolist())

        def q_of(t):
            e, p = e_of(t), phi_of(t)
            return {"N": list(e) + [p],
                    "L": [mpmath.sin(p) * x for x in e] + [mpmath.cos(p)],
                    "H": [mpmath.sin(p / 2) * x for x in e] + [mpmath.cos(p / 2)]}

        t = mpmath.mpf(t0)
        Qd = mpmath.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                Qd[i, j] = mpmath.diff(lambda s, i=i, j=j: Q_of(s)[i, j], t)
        Om = Qd * Q_of(t).T
        om = sp.Matrix(vect(sp.Matrix(Om.tolist())))
        e, p = e_of(t), phi_of(t)
        fns = {"N": (N_matrix, N_tilde), "L": (L_matrix, L_tilde), "H": (H_matrix, H_tilde)}
        for k, (F, Ft) in fns.items():
            qd = sp.Matrix([mpmath.diff(lambda s, n=n, k=k: q_of(s)[k][n], t) for n in range(4)])
            Fv = F(sp.Matrix(list(e)), sp.Float(p, 40)).evalf(40)
            Ftv = Ft(sp.Matrix(list(e)), sp.Float(p, 40)).evalf(40)
            assert max(abs(x) for x in (qd - Fv * om)) < 1e-30, k
            assert max(abs(x) for x in (om - Ftv * qd)) < 1e-30, k


@settings(max_examples=examples(40), deadline=None)
@given(*[st.lists(st.floats(-5, 5), min_size=3, max_size=3)] * 4)
def test_twist_transfer(a, p, w, vA):
    a_, p_ = sp.Matrix(a), sp.Matrix(p)
    tA = sp.Matrix(w + vA)
    tP = np.asarray(twist_transfer(tA, a_, p_), dtype=float).ravel()
    om = np.asarray(w)
    assert np.allclose(tP[:3], om)
    assert np.allclose(tP[3:], np.asarray(vA) + np.cross(np.asarray(a) - np.asarray(p), om))
    UU = np.asarray(twist_transfer_matrix(a_, p_) * twist_transfer_matrix(p_, a_), dtype=float)
    assert np.allclose(UU, np.eye(6))
