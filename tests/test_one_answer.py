"""One answer on every back-end: the C kernels compute the program the NumPy
kernels compute, operation for operation, so where neither calls a library function of its
own (C's sine and cosine, NumPy's SIMD arctan2, the compensated products: C's hardware fma
against NumPy's exact emulation), their float64 results are the same bits.

It guards against C's failing this on moving_frame_acceleration (18 % of random points),
plucker_transfer and twist_transfer: GCC's SLP vectorizer fused products into
vfmaddsub/vfmsubadd in the lanes loops despite -ffp-contract=off
(rigidsym.kernels.cbuild.driver.KERNEL_FLAGS). PyTorch and JAX (eager) compute the same program
column by column: the same bits too.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest
from test_accuracy import available_backends

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from rigidsym.codegen.accuracy.harness import judge as A  # noqa: E402

GEN = Path(__file__).resolve().parents[1] / "generated" / "c"
#: what a back-end computes with a function of its own (libm's, NumPy's SIMD loops, torch's
#: SLEEF, C's own sine and cosine; the compensated products: C's hardware fma against its
#: exact emulation): results within an ulp or two, not the same bits
OWN = re.compile(r"\b(sin|cos|tan|asin|acos|atan|atan2|exp|log|pow|sincos)\(|_sample_trig|"
                 r"rigidsym_(sin|cos|sumprod|diffprod)")


def plain(name: str) -> bool:
    """Whether kernel ``name``'s C program calls no function of its own (only + - * / and
    sqrt, correctly rounded everywhere)."""
    return not OWN.search((GEN / f"{name}.h").read_text())


def test_c_and_numpy_give_the_same_bits():
    if "c" not in available_backends():
        pytest.skip("no C backend")
    names = [n for n in A.kernel_names() if plain(n)]
    assert len(names) >= 25, len(names)      # 27 of 158 on this main
    differ = {}
    for name in names:
        arrays = list(_random(name).values())
        c = A.run_kernel(name, arrays, np.float64, "c")
        n = A.run_kernel(name, arrays, np.float64, "numpy")
        same = (c == n) | (np.isnan(c) & np.isnan(n))
        if not same.all():
            differ[name] = float(np.mean(~same))
    assert not differ, differ


def _random(name: str):
    k = A.R.kernel_of(name)
    pts = A.P.regimes(k, np.float64, n_random=12, seed=5, small=[1e-3])["random"]
    return {a.name: x for a, x in zip(k.args, A.round_points(pts, np.float64, k), strict=True)}


def _tuple(r):
    return r if isinstance(r, tuple) else (r,)


@pytest.mark.extra
@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_torch_and_jax_give_numpys_bits(backend):
    """Eager PyTorch and JAX against the NumPy kernels on every public kernel that calls no
    function of its own: the same bits (float64)."""
    from rigidsym import kernels as K
    if backend == "torch":
        torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
        from rigidsym.kernels import torch as mod
        conv = torch.as_tensor
    else:
        jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
        jax.config.update("jax_enable_x64", True)
        import jax.numpy as jnp

        from rigidsym.kernels import jax as mod
        conv = jnp.asarray
    names = [n for n in A.kernel_names() if plain(n) and hasattr(mod, n)]
    assert len(names) >= 10, names
    K.use_backend("numpy")
    differ = {}
    for name in names:
        kw = _random(name)
        ref = _tuple(getattr(K, name)(**kw, check=False))
        got = _tuple(getattr(mod, name)(**{k: conv(v) for k, v in kw.items()}, check=False))
        frac = max(float(np.mean(np.asarray(g) != r)) for g, r in zip(got, ref, strict=True))
        if frac:
            differ[name] = frac
    assert not differ, differ
