"""Sec. 3.8 by property on random bodies: positive (semi)definiteness of I_C and M_A,
Steiner's theorem in 3x3 and 6x6 form, the failure of (3.148) with M_C = diag(I_C, m 1),
and the four-point-mass reduction the symbolic model rests on.

Book: J. Angeles, Fundamentals of Robotic Mechanical Systems, Sec. 3.8, Eqs. (3.130),
(3.133a), (3.147), (3.148) and Exercise 3.20.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations.sec3_8 import (
    inertia_at_point,
    inertia_dyad_at_point,
    kinetic_energy,
    newton_euler_wrench,
)

_IC = sp.Matrix(3, 3, sp.symbols("I0:9", real=True))
_m = sp.Symbol("m", real=True)
_c, _a, _w, _wd, _v = (sp.Matrix(sp.symbols(f"{n}0:3", real=True)) for n in "cawdv")
_ARGS = [list(_IC), _m, list(_c), list(_a)]
steiner = sp.lambdify(_ARGS, inertia_at_point(_IC, _m, _c, _a), "numpy")
dyad = sp.lambdify(_ARGS, inertia_dyad_at_point(_IC, _m, _c, _a), "numpy")
energy = sp.lambdify([list(_IC), _m, list(_w), list(_v)], kinetic_energy(_IC, _m, _w, _v),
                     "numpy")
wrench = sp.lambdify([list(_IC), _m, list(_w), list(_wd), list(_v)],
                     newton_euler_wrench(_IC, _m, _w, _wd, _v), "numpy")


def cross_matrix(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def body(seed: int, n: int = 7, spread=(1.0, 1.0, 1.0)):
    """Random positive masses at random positions (optionally squashed along axes)."""
    rng = np.random.default_rng(seed)
    masses = rng.uniform(0.1, 3.0, n)
    pts = rng.normal(size=(n, 3)) * np.asarray(spread) + rng.normal(size=3)
    return masses, pts


def moments(masses, pts):
    m = masses.sum()
    c = masses @ pts / m
    r = pts - c
    I_C = sum(mi * (ri @ ri * np.eye(3) - np.outer(ri, ri)) for mi, ri in zip(masses, r,
                                                                               strict=True))
    return m, c, I_C


def inertia_about(masses, pts, a):
    d = pts - a
    return sum(mi * (di @ di * np.eye(3) - np.outer(di, di)) for mi, di in zip(masses, d,
                                                                               strict=True))


seeds = st.integers(0, 2**32 - 1)


@settings(max_examples=examples(60), deadline=None)
@given(seeds)
def test_centroidal_inertia_is_a_gram_form_and_positive_definite(seed):
    masses, pts = body(seed)
    m, c, I_C = moments(masses, pts)
    x = np.random.default_rng(seed + 1).normal(size=3)
    gram = sum(mi * np.sum(np.cross(p - c, x) ** 2) for mi, p in zip(masses, pts, strict=True))
    assert np.isclose(x @ I_C @ x, gram, rtol=1e-12)
    assert np.linalg.eigvalsh(I_C).min() > 0


@settings(max_examples=examples(30), deadline=None)
@given(seeds, st.floats(1e-9, 1e-3))
def test_inertia_of_a_nearly_linear_body_is_semidefinite_along_the_line(seed, eps):
    masses, pts = body(seed, spread=(1.0, eps, eps))  # near the singular set: a segment
    m, c, I_C = moments(masses, pts)
    lam, vec = np.linalg.eigh(I_C)
    assert lam[0] >= -1e-12 * lam[-1] and lam[0] <= 1e-4 * lam[-1]
    assert abs(abs(vec[:, 0] @ np.array([1.0, 0, 0])) - 1) < 1e-4  # null space along x


@settings(max_examples=examples(60), deadline=None)
@given(seeds)
def test_steiner_3x3_and_6x6(seed):
    masses, pts = body(seed)
    m, c, I_C = moments(masses, pts)
    a = np.random.default_rng(seed + 2).normal(size=3) * 2
    I_A = np.asarray(steiner(I_C.ravel(), m, c, a), dtype=float)
    assert np.allclose(I_A, inertia_about(masses, pts, a), rtol=1e-10, atol=1e-10)
    M_A = np.asarray(dyad(I_C.ravel(), m, c, a), dtype=float)
    # M_A is the matrix of the kinetic energy in the twist at A
    w, v = np.random.default_rng(seed + 3).normal(size=(2, 3))
    T = 0.5 * sum(mi * np.sum((v + np.cross(w, p - a)) ** 2)
                  for mi, p in zip(masses, pts, strict=True))
    tA = np.concatenate([w, v])
    assert np.isclose(0.5 * tA @ M_A @ tA, T, rtol=1e-10)
    assert np.linalg.eigvalsh(M_A).min() > 0
    # corrected (3.148): M_A = diag(I_C, O) + m P P^T, P = [C - A; 1]
    P = np.vstack([cross_matrix(c - a), np.eye(3)])
    top = np.zeros((6, 6))
    top[:3, :3] = I_C
    assert np.allclose(M_A, top + m * P @ P.T, rtol=1e-10, atol=1e-10)
    # printed (3.148) with M_C = diag(I_C, m 1): M_A - M_C is indefinite, so no real P
    M_C = top.copy()
    M_C[3:, 3:] = m * np.eye(3)
    assert np.linalg.eigvalsh(M_A - M_C).min() < 0


@settings(max_examples=examples(40), deadline=None)
@given(seeds)
def test_kinetic_energy_and_wrench_kernels(seed):
    masses, pts = body(seed)
    m, c, I_C = moments(masses, pts)
    w, wd, cd = np.random.default_rng(seed + 4).normal(size=(3, 3))
    T = 0.5 * sum(mi * np.sum((cd + np.cross(w, p - c)) ** 2)
                  for mi, p in zip(masses, pts, strict=True))
    assert np.isclose(energy(I_C.ravel(), m, w, cd), T, rtol=1e-10)
    wr = np.asarray(wrench(I_C.ravel(), m, w, wd, cd), dtype=float).ravel()
    assert np.allclose(wr[:3], I_C @ wd + np.cross(w, I_C @ w))
    assert np.allclose(wr[3:], m * cd)


@settings(max_examples=examples(40), deadline=None)
@given(seeds, st.integers(4, 30))
def test_every_body_has_the_moments_of_four_equal_point_masses(seed, n):
    """The reduction of the module docstring: X = V V^T, rotate V so its last row is
    sqrt(m)/2 [1, 1, 1, 1]; the columns are sqrt(m/4) [p_k; 1]."""
    masses, pts = body(seed, n)
    m, c, I_C = moments(masses, pts)
    H = np.hstack([pts, np.ones((n, 1))])
    X = H.T @ (masses[:, None] * H)
    lam, U = np.linalg.eigh(X)
    V = U @ np.diag(np.sqrt(np.clip(lam, 0, None)))
    ell = V[3]
    target = np.full(4, np.sqrt(m) / 2)
    # Householder reflection O with ell^T O = target^T (|ell| = |target| = sqrt(m))
    u = ell - target
    O = np.eye(4) - 2 * np.outer(u, u) / (u @ u) if u @ u > 1e-300 else np.eye(4)
    W = V @ O
    assert np.allclose(W[3], target)
    pts4 = (W[:3] / W[3]).T
    m4, c4, I4 = moments(np.full(4, m / 4), pts4)
    assert np.isclose(m4, m) and np.allclose(c4, c) and np.allclose(I4, I_C, atol=1e-9)
