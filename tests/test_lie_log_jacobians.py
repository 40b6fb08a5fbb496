"""The Jacobian kernels of the branched Lie maps ("each map gets its
Jacobian kernel"): ``rotation_vector_from_rotation_with_jacobians`` and
``euler_rodrigues_from_rotation_with_jacobians``, each branch differentiated with its value
(``Kernel.branch_jacobian``, :mod:`rigidsym.codegen.derivatives.jacobians`).

A rotation moves along its manifold, ``Q -> Q Exp(t b)``: there every branch's derivative is
the declared map's, ``d Log = J_r(w)^-1 b`` and ``d eta = eta (x) [b/2; 0]`` (Solà et al.
2018, App. B), checked at ``|w|`` in {0, 1e-12, 1e-8, 1e-4, 1e-2, 1, pi - 1e-6, pi - 1e-9}
against 50 digits, within ``8 u (kappa + 1)``, on NumPy (C: ``slow``; PyTorch and JAX,
whose derivative of these kernels is now the Jacobian kernel: ``extra``). Off the manifold each
branch keeps its own extension's derivative: the kernel's ambient finite differences agree
with it inside every branch.

On the main of before, ``kernels.jacobian`` had no such kernel (``KeyError``): these tests
fail there. The log of SE(3), ``exponential_coordinates_from_transform``, has its 6 x 16
Jacobian kernel by forward mode over each branch's optimised program (by sympy on the
expanded formula it took 516 s to generate; main 0171638 had none): ``d Log(T Exp(t b)) =
J_r(xi)^-1 b``, checked the same way.
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

    from rigidsym.codegen.accuracy.regimes import q, rotation, unit

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
    kernel computes, one branch per sample for both (guards against: no Jacobian kernel)."""
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
    for name in [*NAMES, "exponential_coordinates_from_transform"]:
        assert callable(K.jacobian(name)), name


# ------------------------------------------------------------------------------------------
# the log of SE(3): its Jacobian kernel by forward mode over each branch's optimised program
# (Kernel.jacobian_from = "program"); none would raise ValueError from K.jacobian

_XI = sp.Matrix(sp.symbols("x0:6", real=True))
SE3 = "exponential_coordinates_from_transform"


def _hat(b):
    """The 4 x 4 of b = [w; v] in se(3): T Exp(t b) moves T by T hat(b) at t = 0."""
    H = np.zeros((4, 4))
    H[:3, :3], H[:3, 3] = _cpm(b[:3]), b[3:]
    return H


@cache
def _se3_cases():
    """``[(norm of w, T, J_r(xi)^-1, kappa)]`` at the acceptance norms: T of the exact w
    (rounded) and p; xi = [w; J_l(w)^-1 p] and the reference ``J_r(xi)^-1 = J_l(-xi)^-1``
    (the derivative of Log(T Exp(t b)) at t = 0, Barfoot Sec. 7.1.5) to 50 digits."""
    jl_inv3 = sp.lambdify(list(_X), L.rotation_vector_left_jacobian_inverse(_X), "mpmath")
    q = sp.lambdify(list(_XI), L.se3_q_block(_XI[:3, :], _XI[3:, :]), "mpmath")

    def jr_inv(*x):       # the blocks of L.exponential_coordinates_left_jacobian_inverse(-xi)
        A, Q = mp.matrix(jl_inv3(*(-c for c in x[:3]))), mp.matrix(q(*(-c for c in x)))
        M = mp.zeros(6, 6)
        B = -A * Q * A
        for i in range(3):
            for j in range(3):
                M[i, j] = M[i + 3, j + 3] = A[i, j]
                M[i + 3, j] = B[i, j]
        return M
    out = []
    for x in _points(6):
        w, _, T, _ = _log_case(x)
        A = _mp(jl_inv3, w)
        with mp.workdps(60):
            v = [sum(A[i, j] * mp.mpf(float(x[3 + j])) for j in range(3)) for i in range(3)]
        # kappa's point in floats; at w = 0 the point 1e-30 away where _mp takes the limit
        xi = [float(c) for c in (w if w.any() else [1e-30, 2e-30, -1e-30])] + \
            [float(c) for c in v]
        ref = _mp(jr_inv, [mp.mpf(c) for c in w] + v)
        out.append((float(np.linalg.norm(w)), T, np.array(ref, dtype=float),
                    _kappa(jr_inv, xi, _mp(jr_inv, xi))))
    return out


def _se3_jacobian(backend, T):
    if backend in ("c", "numpy"):
        old = K.backend()
        K.use_backend(backend)
        try:
            return np.asarray(K.jacobian(SE3)(T)[1]["xi"]["T"])
        finally:
            K.use_backend(old)
    if backend == "torch":
        torch = pytest.importorskip("torch", reason="needs the [torch] extra")
        from rigidsym.kernels import torch as rk

        return torch.autograd.functional.jacobian(getattr(rk, SE3), torch.tensor(T)).numpy()
    jax = pytest.importorskip("jax", reason="needs the [jax] extra")
    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as rj

    return np.asarray(jax.jacfwd(getattr(rj, SE3))(jax.numpy.asarray(T)))


def _check_se3(backend):
    for norm, T, ref, kappa in _se3_cases():
        J = _se3_jacobian(backend, T)
        assert J.shape == (6, 4, 4) and np.isfinite(J).all(), (backend, norm)
        got = np.stack([np.tensordot(J, T @ _hat(b), axes=2) for b in np.eye(6)], axis=-1)
        err = float(np.abs(got - ref).max())
        assert err <= 8 * U * (kappa + 1) * float(np.abs(ref).max()), \
            (backend, norm, err / U, kappa)


@pytest.mark.parametrize("backend", [pytest.param("c", marks=pytest.mark.slow), "numpy"])
def test_se3_log_jacobian_along_the_manifold(backend):
    """d Log(T Exp(t b)) / dt = J_r(xi)^-1 b, within 8 u (kappa + 1) of 50 digits at |w| in
    {0, 1e-12, 1e-8, 1e-4, 1e-2, 1, pi - 1e-6, pi - 1e-9}, every branch (small, main,
    near pi)."""
    _check_se3(backend)


@pytest.mark.extra
@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_se3_log_jacobian_along_the_manifold_arrays(backend):
    """PyTorch and JAX differentiate the SE(3) log through its Jacobian kernel (a branched
    kernel's derivative: the Jacobian kernel contracted)."""
    _check_se3(backend)


def test_se3_log_each_branch_is_differentiated_with_its_value():
    """Ambient central differences of the value kernel (step 1e-6) in all 12 free entries of
    T (R and p) against the Jacobian kernel, in the small branch (0.3 rad), the main one
    (1.2) and near pi (2.9): the derivative of the function the kernel computes there; the
    last row (constant on SE(3)) has a zero derivative."""
    e, p = np.array([0.48, -0.6, 0.64]), np.array([0.3, -1.1, 0.7])
    for th in (0.3, 1.2, 2.9):
        T = np.eye(4)
        T[:3, :3] = np.array(_mp(sp.lambdify(list(_X), L.rotation_from_rotation_vector(_X),
                                             "mpmath"), th * e), dtype=float)
        T[:3, 3] = p
        val, d = K.jacobian(SE3)(T)
        J = np.asarray(d["xi"]["T"])
        np.testing.assert_allclose(np.asarray(val), K.exponential_coordinates_from_transform(T),
                                   rtol=0, atol=8 * U)
        assert not J[:, 3, :].any()
        h, fd = 1e-6, np.zeros((6, 3, 4))
        for i in range(3):
            for j in range(4):
                dT = np.zeros((4, 4))
                dT[i, j] = h
                fd[:, i, j] = (K.exponential_coordinates_from_transform(T + dT, check=False) -
                               K.exponential_coordinates_from_transform(T - dT, check=False)) \
                    / (2 * h)
        assert np.abs(fd - J[:, :3, :]).max() <= 1e-7 * np.abs(J).max(), th
