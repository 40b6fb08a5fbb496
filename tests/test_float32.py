"""float32 kernels: dtype rules (NEP 50), float32 out, tolerances scaled with the dtype, and
the error against the 50-digit reference evaluated at the *same* float32 inputs.

Error measure of tests/test_kernels.py (max-norm of the difference over the max-norm of the
reference, per sample). The C kernels compute in float32 arithmetic, in float64 only for the
subexpressions their precision plan keeps there (issue 20; rigidsym.codegen.float32, named
in each generated header): bounded at 2 ulp of float32, at random and adversarial points
alike. The NumPy backend computes in float64 and rounds once (about half an ulp).
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest
from test_kernels import (
    ADV_PHI,
    AVAILABLE,
    EULER,
    PUBLIC,
    inputs,
    ref_eval,
    rel_err,
    row_tol,
)

from rigidsym import kernels as K
from rigidsym.kernels import _scale

ULP32 = float(np.finfo(np.float32).eps)         # 2**-23
#: random points: the float32 arithmetic of the C kernels, within 2 ulp of float32 (issue 20;
#: the plans aim at 1.5 ulp at their own points); the only loosening of this test, from 1 ulp
TOL_RANDOM = 2 * ULP32
#: adversarial rows (phi -> 0, pi, ||omega|| -> 0, gimbal lock, Q near 1 and pi), at the same
#: float32 inputs: the same 2 ulp
TOL_ADVERSARIAL = 2 * ULP32
N_ADV = len(ADV_PHI)


@pytest.fixture(scope="module", params=["numpy", "c"])
def backend(request):
    if request.param == "c" and K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    return request.param


_CASES: dict = {}


def _case(name: str, n: int):
    """float32 inputs (random rows, then the adversarial ones) and the 50-digit reference at
    exactly those values."""
    if (name, n) not in _CASES:
        arrays = [a.astype(np.float32) for a in inputs(AVAILABLE[name], n, seed=11)]
        wide = [a.astype(np.float64) for a in arrays]
        try:
            ref = ref_eval(name, wide)
        except ZeroDivisionError:
            # a rounded adversarial input can sit exactly where the declared formula (not
            # the generated branch) divides by zero: no reference there, row left out
            keep = []
            for i in range(n + N_ADV):
                try:
                    ref_eval(name, [w[i:i + 1] for w in wide])
                    keep.append(i)
                except ZeroDivisionError:
                    pass
            assert len(keep) >= n + N_ADV - 1, f"{name}: reference undefined at many rows"
            arrays = [a[keep] for a in arrays]
            ref = ref_eval(name, [w[keep] for w in wide])
        _CASES[name, n] = arrays, ref
    return _CASES[name, n]


def _run32(name, arrays, backend):
    kernel = AVAILABLE[name]
    n = arrays[0].shape[0]
    outs = [np.empty((n,) + o.shape, dtype=np.float32) for o in kernel.outputs]
    with np.errstate(all="ignore"):
        K.batch_function(name, backend, dtype=np.float32)(*arrays, *outs)
    return np.concatenate([o.reshape(n, -1) for o in outs], axis=1)


@pytest.mark.parametrize("name", PUBLIC + EULER)
def test_float32_error_bound_against_50_digits(name, backend):
    arrays, ref = _case(name, 200 if name in PUBLIC else 30)
    got = _run32(name, arrays, backend)
    assert got.dtype == np.float32
    # ON_SO3 kernels: the rounding of a float32 Q over sin^2(phi), as in test_kernels
    err = rel_err(got.astype(np.float64), ref) / row_tol(name, ref, ULP32 / 2, TOL_RANDOM)
    err = err * TOL_RANDOM     # unchanged for every other kernel (row_tol is TOL_RANDOM)
    rnd, adv = err[:-N_ADV], err[-N_ADV:]
    assert np.isfinite(err).all(), f"{name}: non-finite output"
    assert rnd.max() <= TOL_RANDOM, f"{name} [{backend}] random: {rnd.max():.3g}"
    assert adv.max() <= TOL_ADVERSARIAL, f"{name} [{backend}] adversarial: {adv.max():.3g}"


@pytest.mark.slow
@pytest.mark.parametrize("name", PUBLIC)
def test_float32_error_bound_1000_points(name):
    """Issue 20: 1000 random points and the adversarial ones per kernel, compiled float32."""
    if K.use_backend("c") != "c":
        pytest.skip("no C backend")
    arrays, ref = _case(name, 1000)
    err = rel_err(_run32(name, arrays, "c").astype(np.float64), ref)
    # ON_SO3 kernels: the rounding of a float32 Q over sin^2(phi), as in the default test
    # (the reference is the declared formula at the rounded, off-rotation Q: issue 30)
    err = err / row_tol(name, ref, ULP32 / 2, TOL_RANDOM) * TOL_RANDOM
    assert np.isfinite(err).all(), f"{name}: non-finite output"
    assert err.max() <= TOL_RANDOM, f"{name}: {err.max() / ULP32:.2f} ulp"


def test_dtype_rules_nep50(backend):
    K.use_backend(backend)
    e = np.array([0.0, 0.6, 0.8], dtype=np.float32)
    phi32 = np.float32(0.3)
    assert K.rotation_from_natural_invariants(e, phi32).dtype == np.float32
    assert K.rotation_from_natural_invariants(e, 0.3).dtype == np.float32     # weak float
    assert K.rotation_from_natural_invariants(e, [0.3]).dtype == np.float64   # a list
    assert K.rotation_from_natural_invariants(e, np.float64(0.3)).dtype == np.float64
    assert K.rotation_from_natural_invariants([0, 0, 1], 1).dtype == np.float64
    assert K.rotation_from_natural_invariants(e.astype(np.int64).clip(0, 1) * 0 + [0, 0, 1],
                                              np.float32(1)).dtype == np.float64


def test_out_dtype_must_match(backend):
    K.use_backend(backend)
    e = np.tile(np.float32([0.0, 0.6, 0.8]), (4, 1))
    phi = np.float32([0.1, 0.2, 0.3, 0.4])
    out = np.empty((4, 3, 3), dtype=np.float32)
    assert K.rotation_from_natural_invariants(e, phi, out=out) is out
    np.testing.assert_array_equal(out, K.rotation_from_natural_invariants(e, phi))
    with pytest.raises(TypeError, match="out"):
        K.rotation_from_natural_invariants(e, phi, out=np.empty((4, 3, 3)))
    with pytest.raises(TypeError, match="out"):
        K.rotation_from_natural_invariants(e.astype(float), phi, out=out, check=False)


def test_tolerances_scale_with_dtype(backend):
    K.use_backend(backend)
    e32 = (np.float32([0.0, 0.6, 0.8]) * np.float32(1 + 3e-7)).astype(np.float32)
    assert K.rotation_from_natural_invariants(e32, np.float32(0.3)).dtype == np.float32
    with pytest.raises(ValueError, match="e: not a unit vector"):
        K.rotation_from_natural_invariants(e32.astype(np.float64), 0.3)
    with pytest.raises(ValueError, match="e: not a unit vector"):
        K.rotation_from_natural_invariants(np.float32([0.0, 0.6, 0.8001]), 0.3)
    Q = K.rotation_from_natural_invariants([0, 0.6, 0.8], 0.7).astype(np.float32)
    assert K.natural_invariants_from_rotation(Q)[1].dtype == np.float32
    with pytest.raises(ValueError, match="Q: not orthogonal"):
        K.natural_invariants_from_rotation(Q * np.float32(1.001))


def test_float32_overflow_flagged(backend):
    """Finite float32 inputs whose float64 result does not fit float32: flagged, never inf."""
    K.use_backend(backend)
    args = (np.eye(3, dtype=np.float32), np.float32(1.0),
            np.float32([[1e20, 0, 0], [1, 0, 0]]), np.float32([0, 0, 0]))
    T = K.kinetic_energy(*args, on_singular="nan")
    assert T.dtype == np.float32 and np.isnan(T[0]) and T[1] == 0.5
    with pytest.raises(K.NonFiniteResultError, match=r"\[\(0,\)\]"):
        K.kinetic_energy(*args)


@pytest.mark.extra
def test_float32_threads_and_dask_keep_the_bits(backend):
    if backend != "c":
        pytest.skip("threads: C")
    da = pytest.importorskip("dask.array", reason="Dask is not installed (the [dask] extra)")
    rng = np.random.default_rng(4)
    n = 2 * _scale.MIN_PARALLEL + 123
    e = rng.standard_normal((n, 3))
    e = (e / np.linalg.norm(e, axis=1, keepdims=True)).astype(np.float32)
    phi = rng.uniform(-3, 3, n).astype(np.float32)
    ref = K.rotation_from_natural_invariants(e, phi, threads=1)
    np.testing.assert_array_equal(K.rotation_from_natural_invariants(e, phi, threads=3), ref)
    lazy = K.rotation_from_natural_invariants(da.from_array(e, chunks=(7001, 3)), phi)
    assert lazy.dtype == np.float32
    np.testing.assert_array_equal(lazy.compute(), ref)
