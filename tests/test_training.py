"""The training example (examples/train_rigid_motion.py): from w = 0, Adam in
PyTorch and jax.grad steps in JAX reach the known motion within 1e-6 rad and 1e-6 m from
noiseless pairs; a network's normalised quaternion through rotation_from_euler_rodrigues
trains (a reader's own exponential map is NaN at w = 0, so nothing trains through it).
"""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.extra

_EX = Path(__file__).resolve().parents[1] / "examples" / "train_rigid_motion.py"


@pytest.fixture(scope="module")
def ex():
    spec = importlib.util.spec_from_file_location("train_rigid_motion", _EX)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_torch_adam_from_zero_reaches_the_motion(ex):
    pytest.importorskip("torch", reason="needs the [torch] extra")
    p, q, xi = ex.problem()
    rot, trans = ex.errors(ex.fit_torch(p, q), xi)
    assert rot < 1e-6 and trans < 1e-6, (rot, trans)


def test_jax_grad_steps_from_zero_reach_the_motion(ex):
    pytest.importorskip("jax", reason="needs the [jax] extra")
    p, q, xi = ex.problem()
    rot, trans = ex.errors(ex.fit_jax(p, q), xi)
    assert rot < 1e-6 and trans < 1e-6, (rot, trans)


def test_gradient_at_zero_is_finite_and_exact():
    # the first step's gradient, at xi = 0 exactly, against the analytic one: d/dxi of
    # mean |Exp(xi) p - q|^2 at 0 is mean 2 [p x (p - q)... ] (the twist acting on p)
    torch = pytest.importorskip("torch", reason="needs the [torch] extra")
    from rigidsym.kernels import torch as rk

    rng = np.random.default_rng(1)
    p, q = rng.normal(size=(16, 3)), rng.normal(size=(16, 3))
    xi = torch.zeros(6, dtype=torch.float64, requires_grad=True)
    T = rk.transform_from_exponential_coordinates(xi)
    P, Q = torch.as_tensor(p), torch.as_tensor(q)
    ((P @ T[:3, :3].T + T[:3, 3] - Q) ** 2).sum(-1).mean().backward()
    r = p - q                      # residual at the identity
    # d(Exp(xi) p)/dw = -[p], d/dv = 1 at xi = 0
    gw = np.mean([2 * np.cross(pi, ri) for pi, ri in zip(p, r, strict=True)], axis=0)
    gv = np.mean(2 * r, axis=0)
    np.testing.assert_allclose(xi.grad.numpy(), np.r_[gw, gv], rtol=1e-13, atol=1e-14)


def test_quaternion_network_trains(ex):
    pytest.importorskip("torch", reason="needs the [torch] extra")
    from rigidsym import kernels

    target = kernels.rotation_from_rotation_vector(np.array([0.3, -1.2, 0.5]))
    Q = ex.fit_quaternion_network(target)
    assert np.abs(Q - target).max() < 1e-6


def test_the_readmes_pytorch_example_runs_and_fits_the_motion():
    # the README's PyTorch example is this training loop: run as printed
    torch = pytest.importorskip("torch", reason="needs the [torch] extra")
    text = (_EX.parents[1] / "README.md").read_text()
    block = re.search(r"\n((?:    .*\n|\n)*?    import torch\n(?:    .*\n|\n)*?)\S", text)
    code = "\n".join(line[4:] for line in block.group(1).splitlines())
    scope: dict = {}
    torch.manual_seed(0)
    exec(compile(code, "README.md", "exec"), scope)  # noqa: S102 -- the README's own text
    rk, xi = scope["rk"], scope["xi"].detach()
    T = rk.transform_from_exponential_coordinates(xi)
    R = rk.rotation_from_rotation_vector(scope["w"])
    assert float(scope["loss"].detach()) < 1e-6
    assert torch.allclose(T[:3, :3], R, atol=1e-3)
    assert torch.allclose(T[:3, 3], torch.tensor([1.0, 0.0, -0.5], dtype=T.dtype), atol=1e-3)
