"""Gradients as documented: a sample masked by ``on_singular="nan"``
gives a zero gradient and never a NaN in a parameter the batch shares; double backward
through the PyTorch kernels and ``jax.hessian`` through the JAX ones.

The masked-row case of the issue: ``Q = stack([1, Q1]) * s``, a loss reading row 1 only.
Row 0 is on the singular set (the ZXZ lock), or, for
``natural_invariants_from_rotation`` and ``screw_of_displacement``, which answer Q = 1 with
phi = 0 and the documented defaults, a row whose derivative is not defined there. Guards
against ``s.grad = nan`` and a NaN gradient in row 0 (``natural_invariants_from_rotation``,
``screw_of_displacement``, ``euler_angle_rates``, autograd through the expression, 0 * inf
in the backward of the masked row) and refused ``create_graph=True``; these tests fail there.
"""

from __future__ import annotations

import numpy as np
import pytest

from rigidsym import kernels as K
from rigidsym.kernels.arrays import inputs as _arrays
from rigidsym.kernels.runtime import inputs as _runtime_inputs
from rigidsym.kernels.runtime import state as _state

Q1 = K.rotation_from_natural_invariants(np.array([0.0, 0.6, 0.8]), 0.7)
A = np.array([0.1, -0.2, 0.3])


def test_the_safe_point_is_regular_for_every_kernel():
    """The point substituted in singular samples (``kernels.arrays.inputs.safe_point``) must
    itself be regular, values and Jacobians finite, for every generated kernel (Euler ones
    too)."""
    meta = _state.meta()
    for name, m in meta.items():
        flat, xs, k = _arrays.safe_point(m["args"]), [], 0
        for a in m["args"]:
            n = int(np.prod(a["shape"]))
            xs.append(np.array(flat[k:k + n]).reshape(a["shape"]))
            k += n
        # the safe point stands in for masked rows, where only regularity matters: a body's
        # physical checks (m > 0, I_C positive semi-definite) are the checked call's, not its
        check = name not in _runtime_inputs.BODY_KERNELS
        res = _state.call(name, tuple(xs), check=check, on_singular="raise", threads=None)
        for r in res if isinstance(res, tuple) else (res,):
            assert np.isfinite(r).all(), name


def _cases(lib, s):
    """``{kernel: (function of s, rows)}``: two samples, row 0 on the singular set."""
    eye = lib.eye(3, dtype=s.dtype)
    Q = lib.stack([eye, lib.asarray(Q1, dtype=s.dtype)]) * s
    a = lib.asarray(A, dtype=s.dtype) * s
    ang = lib.asarray([[0.1, 0.0, 0.3], [0.1, 0.2, 0.3]], dtype=s.dtype) * s  # ZXZ lock at 0
    return {"natural_invariants_from_rotation": ((Q,), {}),
            "screw_of_displacement": ((Q, lib.stack([a, a]), lib.stack([2 * a, -a])), {}),
            "euler_angle_rates": ((ang, lib.stack([a, 2 * a])), {"sequence": "ZXZ"})}


MASKED = ["natural_invariants_from_rotation", "screw_of_displacement", "euler_angle_rates"]


@pytest.mark.extra
@pytest.mark.parametrize("name", MASKED)
def test_torch_masked_row_has_zero_gradient(name):
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    from rigidsym.kernels import torch as rk

    def loss(s, row, leaves=False):
        args, kw = _cases(torch, s)[name]
        if leaves:
            args = tuple(x.detach().requires_grad_() for x in args)
        outs = getattr(rk, name)(*args, **kw, on_singular="nan")
        outs = outs if isinstance(outs, tuple) else (outs,)
        if name in ("natural_invariants_from_rotation", "screw_of_displacement"):
            # Q = 1 is answered (phi = 0, the default axis), not masked: the shared
            # parameter's gradient must still be finite and row 1's alone
            assert (outs[1][0] == 0).all() and torch.isfinite(outs[0][0]).all()
        else:
            assert all(torch.isnan(o[0]).all() for o in outs)  # row 0 masked
        return sum(o[row].sum() for o in outs), args

    s = torch.tensor(1.0, dtype=torch.float64, requires_grad=True)
    total, _ = loss(s, 1)
    (gs,) = torch.autograd.grad(total, s)
    assert torch.isfinite(gs)
    # the same derivative as row 1 alone (no masked row in the batch)
    one = torch.tensor(1.0, dtype=torch.float64, requires_grad=True)
    args, kw = _cases(torch, one)[name]
    outs = getattr(rk, name)(*[x[1:] for x in args], **kw)
    outs = outs if isinstance(outs, tuple) else (outs,)
    (g1,) = torch.autograd.grad(sum(o.sum() for o in outs), one)
    torch.testing.assert_close(gs, g1, rtol=1e-14, atol=0)
    total, leaves = loss(torch.tensor(1.0, dtype=torch.float64), 1, leaves=True)
    for g in torch.autograd.grad(total, leaves):
        assert (g[0] == 0).all() and torch.isfinite(g).all()


@pytest.mark.extra
@pytest.mark.parametrize("name", [n if n == "euler_angle_rates" else pytest.param(
    n, marks=pytest.mark.slow) for n in MASKED])  # JAX's eager dispatch: 9 s each on 2 cores
def test_jax_masked_row_has_zero_gradient(name):
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    import jax.numpy as jnp

    from rigidsym.kernels import jax as rj
    jax.config.update("jax_enable_x64", True)

    def loss(s, row):
        args, kw = _cases(jnp, s)[name]
        outs = getattr(rj, name)(*args, **kw, on_singular="nan")
        outs = outs if isinstance(outs, tuple) else (outs,)
        return sum(o[row].sum() for o in outs)

    s = jnp.float64(1.0)
    gs = jax.grad(loss)(s, 1)
    assert np.isfinite(gs)
    gj = jax.jit(jax.grad(loss), static_argnums=1)(s, 1)
    np.testing.assert_allclose(gj, gs, rtol=1e-14)

    def leaves_loss(args, kw):
        outs = getattr(rj, name)(*args, **kw, on_singular="nan")
        outs = outs if isinstance(outs, tuple) else (outs,)
        return sum(o[1].sum() for o in outs)
    args, kw = _cases(jnp, s)[name]
    for g in jax.grad(leaves_loss)(args, kw):
        assert (np.asarray(g[0]) == 0).all() and np.isfinite(g).all()


@pytest.mark.extra
def test_torch_masked_row_of_a_jacobian_kernel_double_backward():
    """A kernel with a generated Jacobian (instant_screw_axis, singular at omega = 0): the
    second derivative through a masked row is finite too (the Jacobian takes safe inputs
    there; 0 * inf in the backward of the backward otherwise)."""
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    from rigidsym.kernels import torch as rk
    s = torch.tensor(1.0, dtype=torch.float64, requires_grad=True)
    omega = torch.tensor([[0.0, 0.0, 0.0], [0.3, -0.2, 1.0]], dtype=torch.float64) * s
    a = torch.tensor([[0.1, 0.2, 0.3]] * 2, dtype=torch.float64)
    _, pitch, _ = rk.instant_screw_axis(omega, a, a * s, on_singular="nan")
    (g,) = torch.autograd.grad(pitch[1], s, create_graph=True)
    (h,) = torch.autograd.grad(g, s)
    assert torch.isfinite(g) and torch.isfinite(h)


#: six kernels with a generated Jacobian (their backward is differentiated again) and the
#: two branch kernels (autograd through the expression, twice)
SECOND = ["rotation_from_euler_rodrigues", "rotation_from_natural_invariants", "N_matrix",
          "instant_screw_axis", "newton_euler_wrench", "screw_axis_point"]
FEW_SECOND = {"instant_screw_axis", "N_matrix"}


@pytest.mark.extra
@pytest.mark.parametrize("name", [n if n in FEW_SECOND else pytest.param(
    n, marks=pytest.mark.slow) for n in SECOND])
def test_gradgradcheck(name):
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    from rigidsym.kernels import torch as rk
    from tests._arrays_cases import sample
    xs = [torch.tensor(x, requires_grad=True) for x in sample(name, 2, seed=11)]
    fn = getattr(rk, name)
    assert torch.autograd.gradgradcheck(lambda *a: fn(*a, check=False), xs)


@pytest.mark.slow
@pytest.mark.extra
def test_jax_hessian_matches_torch_double_backward():
    """The Hessian of a scalar of instant_screw_axis, by jax.hessian (forward over reverse
    through the custom_jvp) and by torch's double backward: two independent programs of
    second derivatives of the same generated Jacobian agree; kinetic energy's is 3 * 1
    (T = x.x/2 + m x.x/2, I = 1, m = 2)."""
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    import jax.numpy as jnp

    from rigidsym.kernels import jax as rj
    from rigidsym.kernels import torch as rk
    jax.config.update("jax_enable_x64", True)
    a = np.array([0.1, 0.2, 0.3])
    a_dot = np.array([-0.4, 0.5, 0.2])
    w = np.array([0.3, -0.2, 1.0])
    Hj = jax.hessian(lambda v: rj.instant_screw_axis(v, jnp.asarray(a), jnp.asarray(a_dot))[1])(
        jnp.asarray(w))
    Ht = torch.autograd.functional.hessian(
        lambda v: rk.instant_screw_axis(v, torch.tensor(a), torch.tensor(a_dot))[1],
        torch.tensor(w))
    np.testing.assert_allclose(np.asarray(Hj), Ht.numpy(), rtol=1e-13, atol=1e-13)
    x = jnp.asarray(w)
    HT = jax.hessian(lambda v: rj.kinetic_energy(jnp.eye(3), 2.0, v, v))(x)
    np.testing.assert_allclose(np.asarray(HT), 3 * np.eye(3), rtol=0, atol=1e-15)
