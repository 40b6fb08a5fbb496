"""The Euler angles of a rotation (derivations/euler_angles.py, the kernels
``euler_angles_from_rotation_<seq>``, ``rigidsym.kernels.euler_angles_from_rotation``):
the derivation's identities hold and a false one is rejected; off the lock the angles
rebuild Q (SciPy's intrinsic composition, independent of rigidsym) on both branches, the
principal branch in its range and equal to the angles Q was made of; at the gimbal lock,
exactly and with the entry +-sin b (+-cos b) rounded past 1, a flagged member of the family,
finite, c = 0, rebuilding Q."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations import euler_angles as E
from rigidsym.derivations.exercises.ex3_10 import PROPER_EULER, SEQUENCES

from rigidsym import kernels as K

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

FAST = ["ZYX", "ZXZ"]


def _Q(seq, angles):
    # SciPy: upper-case axes are intrinsic rotations, Q = R_i(a) R_j(b) R_k(c)
    return Rotation.from_euler(seq, np.atleast_2d(angles)).as_matrix()


def _principal(seq, rng, n):
    a = rng.uniform(-np.pi, np.pi, (n, 3))
    if seq in PROPER_EULER:
        a[:, 1] = rng.uniform(0.01, np.pi - 0.01, n)
    else:
        a[:, 1] = rng.uniform(-np.pi / 2 + 0.01, np.pi / 2 - 0.01, n)
    return a


@pytest.mark.parametrize("seq", FAST)
def test_derivation_identities_hold(seq):
    assert all(holds for _, holds in E.checks(seq)), E.checks(seq)


@pytest.mark.slow
@pytest.mark.parametrize("seq", SEQUENCES)
def test_derivation_identities_hold_for_all_twelve(seq):
    assert all(holds for _, holds in E.checks(seq)), E.checks(seq)


def test_the_zero_test_rejects_a_false_identity():
    import sympy as sp
    x, y = sp.symbols("x y", real=True)
    assert E._is_zero(sp.sin(x)**2 + sp.cos(x)**2 - 1)
    assert not E._is_zero(sp.sin(x)**2 - sp.cos(x)**2)
    assert not E._is_zero(sp.sin(x) * sp.cos(y) - sp.sin(y) * sp.cos(x))


def _check_off_lock(seq, ang):
    Q = _Q(seq, ang)
    got, lock = K.euler_angles_from_rotation(Q, seq)
    other, lock2 = K.euler_angles_from_rotation(Q, seq, branch="other")
    assert not lock.any() and not lock2.any()
    assert np.abs(got - ang).max() <= 1e-12
    for a in (got, other):
        assert np.abs(_Q(seq, a) - Q).max() <= 4e-16 * 8
    assert np.all(np.abs(other) <= np.pi)
    b2 = other[:, 1]
    if seq in PROPER_EULER:
        assert np.all(b2 <= 0)
    else:
        assert np.all(np.abs(b2) >= np.pi / 2)


@pytest.mark.parametrize("seq", FAST)
def test_off_the_lock_both_branches_rebuild_q(seq):
    _check_off_lock(seq, _principal(seq, np.random.default_rng(0), 200))


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(seq=st.sampled_from(SEQUENCES), seed=st.integers(0, 2**32 - 1))
def test_off_the_lock_every_sequence(seq, seed):
    _check_off_lock(seq, _principal(seq, np.random.default_rng(seed), 50))


def _lock_matrix(seq, a, c, upper):
    """Q exactly at the lock: cos b = 0 (Tait-Bryan) or sin b = 0 (proper) exactly."""
    def R(axis, cs, sn):
        i = "XYZ".index(axis)
        j, k = (i + 1) % 3, (i + 2) % 3
        M = np.eye(3)
        M[j, j], M[j, k], M[k, j], M[k, k] = cs, -sn, sn, cs
        return M
    if seq in PROPER_EULER:
        mid = R(seq[1], 1.0 if upper else -1.0, 0.0)
    else:
        mid = R(seq[1], 0.0, 1.0 if upper else -1.0)
    return R(seq[0], np.cos(a), np.sin(a)) @ mid @ R(seq[2], np.cos(c), np.sin(c))


def _check_lock(seq, rng):
    for upper in (True, False):
        a, c = rng.uniform(-np.pi, np.pi, 2)
        Q = _lock_matrix(seq, a, c, upper)
        i, k = "XYZ".index(seq[0]), "XYZ".index(seq[2])
        past = Q.copy()
        past[i, k] = np.nextafter(past[i, k], 2.0 * np.sign(past[i, k]))   # |.| > 1
        for M in (Q, past):
            for branch in ("principal", "other"):
                got, lock = K.euler_angles_from_rotation(M, seq, branch=branch)
                assert lock and np.isfinite(got).all() and got[2] == 0.0
                assert np.abs(_Q(seq, got)[0] - Q).max() <= 1e-15 * 8


@pytest.mark.parametrize("seq", FAST)
def test_at_the_lock_a_flagged_member_never_nan(seq):
    _check_lock(seq, np.random.default_rng(1))


@pytest.mark.slow
@pytest.mark.parametrize("seq", SEQUENCES)
def test_at_the_lock_every_sequence(seq):
    _check_lock(seq, np.random.default_rng(2))


def test_bad_sequence_and_branch_are_named():
    with pytest.raises(ValueError, match="sequence"):
        K.euler_angles_from_rotation(np.eye(3), "ZZY")
    with pytest.raises(ValueError, match="branch"):
        K.euler_angles_from_rotation(np.eye(3), "ZYX", branch="second")


@pytest.mark.extra
def test_jax_gives_the_numpy_angles_and_flag():
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    from rigidsym.kernels import jax as rj

    old = jax.config.jax_enable_x64
    jax.config.update("jax_enable_x64", True)
    try:
        rng = np.random.default_rng(3)
        Q = np.concatenate([_Q("ZYX", _principal("ZYX", rng, 5)),
                            _lock_matrix("ZYX", 0.3, -1.2, True)[None]])
        for branch in ("principal", "other"):
            want, wlock = K.euler_angles_from_rotation(Q, "ZYX", branch=branch)
            got, lock = rj.euler_angles_from_rotation(jax.numpy.asarray(Q), "ZYX",
                                                      branch=branch)
            assert np.abs(np.asarray(got) - want).max() <= 1e-14
            assert (np.asarray(lock) == wlock).all() and wlock[-1] and not wlock[:-1].any()
    finally:
        jax.config.update("jax_enable_x64", old)
