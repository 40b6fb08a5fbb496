"""One answer on every back-end (issue 37): the C kernels compute the program the NumPy
kernels compute, operation for operation, so where neither calls a library function of its
own (C's sine and cosine, NumPy's SIMD arctan2, the compensated products: C's hardware fma
against NumPy's exact emulation), their float64 results are the same bits.

Old main failed this on 9 kernels (moving_frame_acceleration at 18 % of random points,
wrench_axis_with_jacobians 1024 ulps of a small component): GCC's SLP vectorizer fused
products into vfmaddsub/vfmsubadd in the lanes loops despite -ffp-contract=off
(rigidsym.kernels._build.KERNEL_FLAGS).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from test_accuracy import _backends

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import accuracy as A  # noqa: E402

GEN = Path(__file__).resolve().parents[1] / "generated" / "c"
#: what either back-end computes with a function of its own (results within 1 ulp, not equal)
OWN = ("atan2", "acos", "asin", "rigidsym_sin", "rigidsym_cos", "sincos", "_sample_trig",
       "rigidsym_sumprod", "rigidsym_diffprod")


def _plain(name: str) -> bool:
    text = (GEN / f"{name}.h").read_text()
    return not any(f in text for f in OWN)


def test_c_and_numpy_give_the_same_bits():
    if "c" not in _backends():
        pytest.skip("no C backend")
    names = [n for n in A.kernel_names() if _plain(n)]
    assert len(names) >= 40, len(names)      # 41 of 158 on this main
    differ = {}
    for name in names:
        k = A.R.kernel_of(name)
        pts = A.P.regimes(k, np.float64, n_random=12, seed=5, small=[1e-3])["random"]
        arrays = A._round(pts, np.float64, k)
        c = A.run_kernel(name, arrays, np.float64, "c")
        n = A.run_kernel(name, arrays, np.float64, "numpy")
        same = (c == n) | (np.isnan(c) & np.isnan(n))
        if not same.all():
            differ[name] = float(np.mean(~same))
    assert not differ, differ
