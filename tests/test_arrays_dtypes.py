"""dtypes of the PyTorch and JAX kernels as the libraries treat them.

float16 and bfloat16 are computed in float32 and rounded once to the input dtype (never
torch's raw ``NotImplementedError: "lu_cpu"`` from the rotation check for float16, nor
bfloat16 rejected against the float64 tolerance); mixed dtypes promote by the library's
own rule (checked against ``torch.result_type`` / ``jnp.result_type``, not restated); a
unit-norm check uses the tolerance of the lowest precision among the inputs (so a float32
unit axis with a float64 angle is not "not a unit vector 5e-8 > 1e-8"); a float type
outside the four is refused naming those accepted.
"""

from __future__ import annotations

import numpy as np
import pytest

from rigidsym import kernels as K

pytestmark = pytest.mark.extra

E = np.array([[2.0, 3.0, 6.0], [1.0, -4.0, 8.0]]) / np.array([[7.0], [9.0]])
PHI = np.array([0.7, 2.9])
#: (kernel, arguments): a rotation in, a rotation out, a Jacobian kernel with its backward
CASES = [("rotation_from_natural_invariants", (E, PHI)), ("N_matrix", (E, PHI))]


def _torch():
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    from rigidsym.kernels import torch as rk
    return torch, rk


def _jax():
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    from rigidsym.kernels import jax as rj
    jax.config.update("jax_enable_x64", True)
    return jax, rj


def _within_one_u(got: np.ndarray, ref: np.ndarray, eps: float) -> None:
    """One rounding of a float32 result to a type of epsilon ``eps``: at most u = eps / 2 of
    each entry's magnitude, plus float32's own error (checked against 0.6 eps)."""
    err = np.abs(got - ref) / np.maximum(np.abs(ref), 2.0 ** -14)
    assert float(err.max()) <= 0.6 * eps, float(err.max())


@pytest.mark.parametrize("dt", ["float16", "bfloat16"])
@pytest.mark.parametrize("name,args", CASES)
def test_torch_half_types_computed_in_float32(dt, name, args):
    torch, rk = _torch()
    dtype = getattr(torch, dt)
    xs = [torch.tensor(a, dtype=dtype) for a in args]
    ref = getattr(K, name)(*[x.double().numpy() for x in xs], check=False)
    x = xs[1].clone().requires_grad_()
    out = getattr(rk, name)(xs[0], x)
    assert out.dtype == dtype
    _within_one_u(out.detach().double().numpy(), ref, torch.finfo(dtype).eps)
    out.sum().backward()
    assert x.grad.dtype == dtype and torch.isfinite(x.grad).all()
    if name == "rotation_from_natural_invariants":  # a half rotation is a valid input
        e, phi = rk.natural_invariants_from_rotation(out)
        assert e.dtype == dtype
        np.testing.assert_allclose(phi.detach().double().numpy(), xs[1].double().numpy(),
                                   atol=4 * torch.finfo(dtype).eps)


@pytest.mark.parametrize("dt", ["float16", "bfloat16"])
def test_jax_half_types_computed_in_float32(dt):
    jax, rj = _jax()
    import jax.numpy as jnp
    dtype = getattr(jnp, dt)
    e, phi = jnp.asarray(E, dtype=dtype), jnp.asarray(PHI, dtype=dtype)
    ref = K.rotation_from_natural_invariants(np.asarray(e, np.float64),
                                             np.asarray(phi, np.float64), check=False)
    out = rj.rotation_from_natural_invariants(e, phi)
    assert out.dtype == dtype
    _within_one_u(np.asarray(out, np.float64), ref, float(jnp.finfo(dtype).eps))
    g = jax.grad(lambda p: rj.rotation_from_natural_invariants(e, p).sum())(phi)
    assert g.dtype == dtype and np.isfinite(np.asarray(g, np.float64)).all()


def test_torch_mixed_dtypes_promote_as_torch_does():
    torch, rk = _torch()
    f32, f64 = torch.float32, torch.float64
    e32 = torch.tensor(E[0], dtype=f32)  # a unit vector rounded to float32: off by ~5e-8
    for phi in (torch.tensor([0.7], dtype=f64), torch.tensor(0.7, dtype=f64),
                np.array([0.7]), torch.tensor([0.7], dtype=torch.float16)):
        want = torch.result_type(e32, torch.as_tensor(phi))
        assert rk.N_matrix(e32, phi).dtype == want
    assert rk.N_matrix(e32, 0.7).dtype == f32  # a Python number is weak


def test_jax_mixed_dtypes_promote_as_jax_does():
    jax, rj = _jax()
    import jax.numpy as jnp
    e32 = jnp.asarray(E[0], dtype=jnp.float32)
    for phi in (jnp.asarray([0.7]), jnp.asarray([0.7], dtype=jnp.bfloat16)):
        assert rj.N_matrix(e32, phi).dtype == jnp.result_type(e32, phi)


def test_unit_check_uses_the_lowest_precision_among_inputs():
    torch, rk = _torch()
    f16 = torch.float16
    off = torch.tensor(E[0] * (1 + 2e-3), dtype=f16)  # within float16's 8 eps = 7.8e-3
    assert rk.N_matrix(off, torch.tensor([0.7], dtype=torch.float64)).dtype == torch.float64
    with pytest.raises(ValueError, match="e: not a unit vector"):
        rk.N_matrix(torch.tensor(E[0] * 1.02, dtype=f16), 0.7)
    with pytest.raises(ValueError, match="e: not a unit vector"):  # float64 keeps 1e-8
        rk.N_matrix(torch.tensor(E[0] * (1 + 1e-6), dtype=torch.float64), 0.7)


def test_unsupported_float_types_are_refused_naming_the_accepted():
    torch, rk = _torch()
    with pytest.raises(TypeError, match="e: torch.float8_e4m3fn is not supported; expected "
                                        "float16, bfloat16, float32 or float64"):
        rk.N_matrix(torch.tensor(E[0]).to(torch.float8_e4m3fn), 0.7)
    if np.dtype(np.longdouble).itemsize > 8:
        with pytest.raises(TypeError, match="e: float128 is not supported"):
            rk.N_matrix(np.asarray(E[0], dtype=np.longdouble), 0.7)
