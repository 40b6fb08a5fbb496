"""Optional cross-check of a few kernels against Pinocchio (an independent C++ implementation).

Pinocchio is NOT a dependency of rigidsym (it is not in pyproject.toml): install it with
``pip install pin`` to run these tests; without it the module is skipped (importorskip).

Cross-checked, at a few dozen random points each, tolerance ~1e-12:

* ``rotation_from_natural_invariants(e, phi)`` vs ``pinocchio.exp3(phi e)``;
* ``natural_invariants_from_rotation(Q)`` vs ``pinocchio.log3(Q)`` (= phi e), including
  angles near pi; Q built from the float64 pi keeps a ~1e-16 skew part that fixes the sign
  of e (both libraries agree, sign included); for an exactly symmetric Q (phi = pi) the sign
  of e is a convention (ours: the component of largest magnitude is positive; Pinocchio's
  differs on some points), so there phi e is compared up to sign and through exp3;
* ``twist_transfer`` / ``wrench_transfer`` vs ``SE3(I, p - a).actInv`` on ``Motion`` /
  ``Force``. Pinocchio orders motions [v; omega] and forces [f; n], we order [omega; v] and
  [n; f]: converted with ``swap_blocks``. Point convention: ``SE3(R, r)`` maps quantities
  expressed in frame B (origin at r in frame A) to frame A by ``act``, so moving the reference
  point from A to P (frame at P = frame at A translated by p - a) is ``actInv``. Hand check
  (``test_transfer_point_convention_by_hand``): a pure rotation omega about an axis through A
  gives v_P = omega x (p - a);
* ``inertia_dyad_at_point(I_C, m, c, a)`` vs ``Inertia(m, c - a, I_C).matrix()`` (the 6x6
  spatial inertia about the frame origin A in [v; omega] order): ``swap_blocks(.., matrix=True)``
  applies P M P with P the block-swap permutation.
"""

from __future__ import annotations

import numpy as np
import pytest

from rigidsym import kernels as K

# the [oracles] extra: the default run counts only tests without the mark (tests/test_budget.py)
pytestmark = pytest.mark.extra

pin = pytest.importorskip("pinocchio")

N = 40
TOL = 1e-12


def _unit(rng, n):
    x = rng.standard_normal((n, 3))
    return x / np.linalg.norm(x, axis=1, keepdims=True)


def _close(got, ref, tol=TOL):
    """max|got - ref| <= tol * max(1, max|ref|)."""
    got, ref = np.asarray(got, dtype=float), np.asarray(ref, dtype=float)
    scale = max(1.0, float(np.abs(ref).max()))
    err = float(np.abs(got - ref).max())
    assert err <= tol * scale, f"max error {err:.3g} > {tol:.0e} * {scale:.3g}"


def test_rotation_from_natural_invariants_vs_exp3():
    rng = np.random.default_rng(1)
    e = _unit(rng, N)
    phi = np.concatenate([rng.uniform(-2 * np.pi, 2 * np.pi, N - 6),
                          [1e-12, 1e-6, np.pi - 1e-8, np.pi, -np.pi, 3.0]])
    Q = K.rotation_from_natural_invariants(e, phi)
    for i in range(N):
        _close(Q[i], pin.exp3(phi[i] * e[i]))


def test_natural_invariants_from_rotation_vs_log3():
    rng = np.random.default_rng(2)
    e = _unit(rng, N)
    # (0, pi), with a cluster near pi where the axis comes from the symmetric part of Q
    phi = np.concatenate([rng.uniform(1e-3, np.pi - 1e-3, N - 8),
                          np.pi - np.array([1e-2, 1e-4, 1e-6, 1e-8]),
                          [1e-3, 0.5, 2.0 * np.pi / 3.0, 2.5]])
    Q = np.array([pin.exp3(p * u) for p, u in zip(phi, e, strict=True)])
    e_got, phi_got = K.natural_invariants_from_rotation(Q)
    for i in range(N):
        ref = pin.log3(Q[i])
        _close(phi_got[i] * e_got[i], ref)
        _close(phi_got[i], np.linalg.norm(ref))
        _close(pin.exp3(phi_got[i] * e_got[i]), Q[i])


def _pi_axes(rng):
    return np.concatenate([_unit(rng, 12), np.eye(3), -np.eye(3)])


def test_natural_invariants_at_float_pi_vs_log3():
    """Q from the float64 pi keeps a skew part of ~1e-16 (sin(pi) != 0 in floats), which
    fixes the sign of e: ours and Pinocchio's agree including the sign."""
    e = _pi_axes(np.random.default_rng(3))
    Q = K.rotation_from_natural_invariants(e, np.full(len(e), np.pi))
    e_got, phi_got = K.natural_invariants_from_rotation(Q)
    for i in range(len(e)):
        _close(phi_got[i], np.pi)
        _close(phi_got[i] * e_got[i], pin.log3(Q[i]))
        _close(e_got[i], e[i])


def test_natural_invariants_at_exactly_pi_vs_log3():
    """Exactly symmetric Q = 2 e e^T - 1 (phi = pi): e and -e give the same Q, so phi e is
    compared up to sign; our sign rule (largest-magnitude component of e positive) is
    checked, and both logs must reproduce Q. (Pinocchio's sign choice differs from ours
    on some of these points; neither is wrong.)"""
    e = _pi_axes(np.random.default_rng(3))
    Q = 2.0 * np.einsum("ni,nj->nij", e, e) - np.eye(3)
    e_got, phi_got = K.natural_invariants_from_rotation(Q)
    for i in range(len(e)):
        ref = pin.log3(Q[i])
        got = phi_got[i] * e_got[i]
        _close(phi_got[i], np.pi)
        _close(np.linalg.norm(ref), np.pi)
        _close(got, (1.0 if got @ ref > 0 else -1.0) * ref)
        assert e_got[i][np.argmax(np.abs(e_got[i]))] > 0
        _close(pin.exp3(got), Q[i])
        _close(pin.exp3(ref), Q[i])


def _points(rng):
    return rng.standard_normal((N, 3)) * 2.0, rng.standard_normal((N, 3)) * 2.0


def test_transfer_point_convention_by_hand():
    """Pure rotation about an axis through A: v_A = 0, so v_P = omega x (p - a)."""
    omega, a, p = np.array([0.0, 0.0, 2.0]), np.array([1.0, 0.0, 0.0]), np.array([1.0, 3.0, 0.0])
    v_p = np.cross(omega, p - a)                     # = [-6, 0, 0]
    t_p = K.twist_transfer(np.r_[omega, 0.0, 0.0, 0.0], a, p)
    _close(t_p, np.r_[omega, v_p])
    m = pin.SE3(np.eye(3), p - a).actInv(pin.Motion(np.zeros(3), omega))
    _close(np.r_[m.angular, m.linear], np.r_[omega, v_p])
    # the other way round (act) would give the opposite velocity
    m_wrong = pin.SE3(np.eye(3), p - a).act(pin.Motion(np.zeros(3), omega))
    assert not np.allclose(m_wrong.linear, v_p)


def test_twist_transfer_vs_se3_actinv():
    rng = np.random.default_rng(4)
    t_a = rng.standard_normal((N, 6))
    a, p = _points(rng)
    t_p = K.twist_transfer(t_a, a, p)
    for i in range(N):
        m = pin.SE3(np.eye(3), p[i] - a[i]).actInv(pin.Motion(K.swap_blocks(t_a[i])))
        _close(t_p[i], K.swap_blocks(m.vector))
        # and back: act returns to A
        back = pin.SE3(np.eye(3), p[i] - a[i]).act(pin.Motion(K.swap_blocks(t_p[i])))
        _close(K.swap_blocks(back.vector), t_a[i])


def test_wrench_transfer_vs_se3_actinv():
    rng = np.random.default_rng(5)
    w_a = rng.standard_normal((N, 6))
    a, p = _points(rng)
    w_p = K.wrench_transfer(w_a, a, p)
    for i in range(N):
        f = pin.SE3(np.eye(3), p[i] - a[i]).actInv(pin.Force(K.swap_blocks(w_a[i])))
        _close(w_p[i], K.swap_blocks(f.vector))
    # power is invariant under the change of point (twist . wrench)
    t_a = rng.standard_normal((N, 6))
    t_p = K.twist_transfer(t_a, a, p)
    _close(np.einsum("ij,ij->i", t_p, w_p), np.einsum("ij,ij->i", t_a, w_a))


def test_inertia_dyad_at_point_vs_pinocchio_inertia():
    rng = np.random.default_rng(6)
    # a rigid body's inertia: tr(S) 1 - S of a second moment S (positive definite), so
    # that its principal moments obey the triangle inequality the kernel checks
    B = rng.standard_normal((N, 3, 3))
    S = B @ np.swapaxes(B, -1, -2) + 0.1 * np.eye(3)
    I_C = np.trace(S, axis1=-2, axis2=-1)[:, None, None] * np.eye(3) - S
    m = rng.uniform(0.1, 10.0, N)
    c, a = _points(rng)
    M_A = K.inertia_dyad_at_point(I_C, m, c, a)
    for i in range(N):
        M_pin = pin.Inertia(m[i], c[i] - a[i], I_C[i]).matrix()
        _close(M_A[i], K.swap_blocks(M_pin, matrix=True))
    # kinetic energy 1/2 t^T M_A t agrees with Pinocchio's 1/2 v^T Y v (vtiv)
    t_a = rng.standard_normal((N, 6))
    for i in range(N):
        Y = pin.Inertia(m[i], c[i] - a[i], I_C[i])
        _close(0.5 * t_a[i] @ M_A[i] @ t_a[i], 0.5 * Y.vtiv(pin.Motion(K.swap_blocks(t_a[i]))))
