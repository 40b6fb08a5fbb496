"""The PyTorch and JAX kernels on a CUDA GPU: every public kernel's values on the
GPU are the NumPy kernel's (float64: 1e-12 relative; float32: the accuracy harness's bound),
the results stay on the device, the gradients on the GPU are the CPU's generated Jacobians,
and a singular sample raises there as on the CPU.

Skipped where no GPU is visible (CI has none): run on a GPU machine with
``python -m pytest -m extra tests/test_arrays_cuda.py``. benchmarks/RESULTS.md's
``arrays-gpu`` section records the run."""

from __future__ import annotations

import numpy as np
import pytest

from rigidsym import kernels as K
from tests._arrays_cases import sample, singular_probes

pytestmark = pytest.mark.extra

torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
if not torch.cuda.is_available():
    pytest.skip("no CUDA GPU visible (run on a GPU machine)", allow_module_level=True)
from rigidsym.kernels import torch as rk  # noqa: E402

ALL = list(K.KERNEL_NAMES)
GPU = torch.device("cuda")


def _tuple(v):
    return v if isinstance(v, tuple) else (v,)


def _close(got, ref, rtol):
    ref = np.asarray(ref, dtype=np.float64)
    scale = max(1.0, float(np.abs(ref).max())) if ref.size else 1.0
    np.testing.assert_allclose(np.asarray(got, dtype=np.float64), ref, rtol=rtol,
                               atol=rtol * scale)


@pytest.mark.parametrize("name", ALL)
def test_torch_values_on_the_gpu_are_the_numpy_kernels(name):
    xs = sample(name, 64, seed=11)
    ref = _tuple(getattr(K, name)(*xs))
    got = _tuple(getattr(rk, name)(*[torch.tensor(x, device=GPU) for x in xs]))
    assert len(got) == len(ref)
    for g, r in zip(got, ref, strict=True):
        assert g.device.type == "cuda" and g.dtype == torch.float64
        _close(g.cpu(), r, 1e-12)


@pytest.mark.parametrize("name", ALL)
def test_torch_float32_on_the_gpu(name):
    xs = sample(name, 64, seed=12)
    ref = _tuple(getattr(K, name)(*xs))
    got = _tuple(getattr(rk, name)(*[torch.tensor(x, device=GPU, dtype=torch.float32)
                                      for x in xs]))
    for g, r in zip(got, ref, strict=True):
        assert g.device.type == "cuda" and g.dtype == torch.float32
        # float32 on well-conditioned random samples: a few hundred ulp of the output scale
        _close(g.cpu(), r, 5e-5)


@pytest.mark.parametrize("name", ALL)
def test_torch_gradients_on_the_gpu_are_the_cpu_ones(name):
    xs = sample(name, 8, seed=13)
    fn = getattr(rk, name)
    grads = []
    for dev in ("cpu", GPU):
        ts = [torch.tensor(x, device=dev, requires_grad=True) for x in xs]
        sum((o * (1 + torch.arange(o.numel(), device=dev, dtype=o.dtype).reshape(o.shape)
                  / o.numel())).sum() for o in _tuple(fn(*ts))).backward()
        grads.append([t.grad for t in ts])
    for c, g in zip(*grads, strict=True):
        assert (c is None) == (g is None)
        if c is not None:
            _close(g.cpu(), c, 1e-11)


@pytest.mark.parametrize("name", [n for n in ALL if singular_probes(n) is not None])
def test_no_nan_gradient_near_the_singular_sets_on_the_gpu(name):
    xs = [torch.tensor(x, device=GPU, requires_grad=True) for x in singular_probes(name)]
    sum(o.sum() for o in _tuple(getattr(rk, name)(*xs))).backward()
    for x in xs:
        assert x.grad is None or torch.isfinite(x.grad).all(), name


def test_a_singular_sample_raises_on_the_gpu():
    omega = torch.tensor([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]], dtype=torch.float64,
                         device=GPU)
    a = torch.zeros(2, 3, dtype=torch.float64, device=GPU)
    with pytest.raises(K.SingularConfigurationError, match=r"\(1,\)"):
        rk.instant_screw_axis(omega, a, a)
    p0, pitch, _ = rk.instant_screw_axis(omega, a, a, on_singular="nan")
    assert pitch.device.type == "cuda" and torch.isnan(pitch[1]) and torch.isfinite(pitch[0])


def test_jax_values_on_the_gpu_are_the_numpy_kernels():
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    try:
        gpu = jax.devices("gpu")[0]
    except RuntimeError:
        pytest.skip("JAX sees no GPU")
    from rigidsym.kernels import jax as rj
    old = jax.config.jax_enable_x64
    jax.config.update("jax_enable_x64", True)
    try:
        for name in ALL:
            xs = sample(name, 32, seed=14)
            ref = _tuple(getattr(K, name)(*xs))
            got = _tuple(jax.jit(getattr(rj, name))(*[jax.device_put(x, gpu) for x in xs]))
            for g, r in zip(got, ref, strict=True):
                assert g.devices() == {gpu}, name
                _close(np.asarray(g), r, 1e-12)
    finally:
        jax.config.update("jax_enable_x64", old)
