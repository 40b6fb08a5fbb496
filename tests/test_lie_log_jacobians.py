"""The Jacobian kernels of the branched Lie maps (issue 38 item 2: "each map gets its
Jacobian kernel"): ``rotation_vector_from_rotation_with_jacobians`` and
``euler_rodrigues_from_rotation_with_jacobians``, each branch differentiated with its value
(``Kernel.branch_jacobian``, :mod:`rigidsym.codegen.jacobians`).

A rotation moves along its manifold, ``Q -> Q Exp(t b)``: there every branch's derivative is
the declared map's, ``d Log = J_r(w)^-1 b`` and ``d eta = eta (x) [b/2; 0]`` (Solà et al.
2018, App. B), checked at ``|w|`` in {0, 1e-12, 1e-8, 1e-4, 1e-2, 1, pi - 1e-6, pi - 1e-9}
against 50 digits, within ``8 u (kappa + 1)``, on NumPy (C: ``slow``; PyTorch and JAX,
whose derivative of these kernels is now the Jacobian kernel: ``extra``). Off the manifold each
branch keeps its own extension's derivative: the kernel's ambient finite differences agree
with it inside every branch.

On the main of before, ``kernels.jacobian`` had no such kernel (``KeyError``): these tests
fail there. ``exponential_coordinates_from_transform`` has none yet (open: its 6 x 16
Jacobian compiles in 516 s to 5331 operations).
"""

from __future__ import annotations

from functools import cache

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from rigidsym.derivations import lie_maps as L

from rigidsym import kernels as K
from tests.test_lie_acceptance import U, _kappa, _log_case, _mp, _points

NAMES = ["rotation_vector_from_rotation", "euler_rodrigues_from_rotation"]
_X = sp.Matrix(sp.symbols("x0:3", real=True))


def _cpm(b):
    return np.array([[0, -b[2], b[1]], [b[2], 0, -b[0]], [-b[1], b[0], 0]])


def _tangent_reference(name):
    """``w -> [d out / dt of out(Exp(w) Exp(t b_k))]_k`` in mpmath (the columns for the
    coordinate axes b_k)."""
    if name == "rotation_vector_from_rotation":
        M = L.rotation_vector_right_jacobian_inverse(_X)
    else:
        th = sp.sqrt((_X.T * _X)[0])
        r, r0 = sp.sin(th / 2) / th * _X, sp.cos(th / 2)
        M = sp.Matrix.vstack(r0 / 2 * sp.eye(3) + sp.Matrix([[0, -r[2], r[1]], [r[2], 0, -r[0]],
                                                             [-r[1], r[0], 0]]) / 2,
                             -r.T / 2)
    return sp.lambdify(list(_X), M, "mpmath")


def _kernel_jacobian(backend, name, Q):
    """d out / d Q (out.shape + (3, 3)) of the kernel on ``backend``, float64."""
    if backend in ("c", "numpy"):
        old = K.backend()
        K.use_backend(backend)
        try:
            _, d = K.jacobian(name)(Q)
        finally:
            K.use_backend(old)
        (out,) = d
        return np.asarray(d[out]["Q"])
    if backend == "torch":
        torch = pytest.importorskip("torch", reason="needs the [torch] extra")
        from rigidsym.kernels import torch as rk

        return torch.autograd.functional.jacobian(getattr(rk, name), torch.tensor(Q)).numpy()
    jax = pytest.importorskip("jax", reason="needs the [jax] extra")
    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as rj

    return np.asarray(jax.jacfwd(getattr(rj, name))(jax.numpy.asarray(Q)))


@cache
def _cases(name):
    """``[(w, Q, reference, kappa)]`` at the acceptance norms (50 digits, once)."""
    ref_fn = _tangent_reference(name)
    out = []
    for x in _points(3):
        w, Q, _, _ = _log_case(np.r_[x, 0, 0, 0])
        ref = _mp(ref_fn, w)
        out.append((w, Q, np.array(ref, dtype=float), _kappa(ref_fn, w, ref)))
    return out


def _check_tangent(name, backend):
    for w, Q, ref, kappa in _cases(name):
        J = _kernel_jacobian(backend, name, Q)
        got = np.stack([np.tensordot(J, Q @ _cpm(b), axes=2) for b in np.eye(3)], axis=-1)
        assert np.isfinite(J).all(), (name, backend, w)
        err = float(np.abs(got - ref).max())
        assert err <= 8 * U * (kappa + 1) * float(np.abs(ref).max()), \
            (name, backend, float(np.linalg.norm(w)), err / U, kappa)


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("backend", [pytest.param("c", marks=pytest.mark.slow), "numpy"])
def test_log_jacobians_along_the_manifold(name, backend):
    _check_tangent(name, backend)


@pytest.mark.parametrize("backend", ["c", "numpy"])
def test_log_jacobian_at_a_half_turn(backend):
    """Closer to pi: Q of the Euler-Rodrigues parameters (e, tau), phi = 2 atan(1/tau), tau
    down to 0 (a half turn), exact then rounded. Before the near-pi branch read phi from
    atan2(e . vect Q, cos phi) (not |vect Q|) the derivative was 1.7e4 u off at tau = 1e-12
    and 6.5e10 u at 1e-15, and NaN at 1e-40."""
    from flint import fmpq

    from rigidsym.codegen.regimes import q, rotation, unit

    rng = np.random.default_rng(7)
    fn = _tangent_reference("rotation_vector_from_rotation")
    for tau in (1e-12, 1e-15, 1e-40, 0.0):
        e = unit(rng)
        Q = np.array([float(x) for x in rotation(e, fmpq(1), q(tau))]).reshape(3, 3)
        with mp.workdps(50):
            phi = 2 * mp.atan2(1, mp.mpf(tau))
            w = [phi * mp.mpf(int(x.p)) / int(x.q) for x in e]
        J = _kernel_jacobian(backend, "rotation_vector_from_rotation", Q)
        if tau == 0 and np.dot(K.rotation_vector_from_rotation(Q),
                               [float(x) for x in w]) < 0:
            w = [-x for x in w]       # at a half turn w and -w are both logarithms
        with mp.workdps(50):
            ref = np.array(mp.matrix(fn(*w)).tolist(), dtype=float)
        got = np.stack([np.tensordot(J, Q @ _cpm(b), axes=2) for b in np.eye(3)], axis=-1)
        assert np.abs(got - ref).max() <= 8 * U * 2 * np.abs(ref).max(), (backend, tau)


@pytest.mark.extra
@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_log_jacobians_along_the_manifold_arrays(name, backend):
    _check_tangent(name, backend)


@pytest.mark.parametrize("name", NAMES)
def test_each_branch_is_differentiated_with_its_value(name):
    """Ambient central differences of the value kernel (step 1e-6, error ~1e-12) against the
    Jacobian kernel, inside the small branch (0.3 rad), the main one (1.2; Shepperd's 2.2 for
    the quaternion) and near pi (2.9): the Jacobian is the derivative of the function the
    kernel computes, one branch per sample for both (old main: no Jacobian kernel)."""
    e = np.array([0.48, -0.6, 0.64])
    for th in (0.3, 1.2, 2.2, 2.9):
        Q = np.array(_mp(sp.lambdify(list(_X), L.rotation_from_rotation_vector(_X), "mpmath"),
                         th * e), dtype=float)
        val, d = K.jacobian(name)(Q)
        (out,) = d
        J = np.asarray(d[out]["Q"])
        np.testing.assert_allclose(np.asarray(val), getattr(K, name)(Q), rtol=0, atol=4 * U)
        h = 1e-6
        fd = np.zeros_like(J)
        for i in range(3):
            for j in range(3):
                dQ = np.zeros((3, 3))
                dQ[i, j] = h
                fd[..., i, j] = (getattr(K, name)(Q + dQ, check=False) -
                                 getattr(K, name)(Q - dQ, check=False)) / (2 * h)
        assert np.abs(fd - J).max() <= 1e-7 * np.abs(J).max(), (name, th)


def test_the_branched_maps_have_their_jacobian_kernels():
    mp.mp.dps = 50
    for name in NAMES:
        assert callable(K.jacobian(name)), name
    with pytest.raises(ValueError, match="name"):
        K.jacobian("exponential_coordinates_from_transform")   # open: none yet
