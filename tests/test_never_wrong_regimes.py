"""Property-based tests of the accuracy rule for every public kernel: Hypothesis strategies
for the regimes a user meets (inputs from 1e-300 to 1e300 in float64 and 1e-35 to 1e35 in
float32, subnormals among them, squares that overflow; angles near 0 and near pi; unit
vectors near an axis; a NaN or inf in one component) drive the agreement of C, NumPy,
PyTorch and JAX (the same NaN positions; elsewhere values within the tolerance below) and
items 3-4 (a finite input whose NumPy result, its long-double rescue, is finite is finite
on every back-end; check=False returns what check=True returns).

Both profiles are derandomized; the quick one runs C against NumPy on a sample of the
kernels in the README's test command; PyTorch and JAX join where installed (marked
``extra``); the thorough profile runs every kernel and type at three times the examples.
"""

from __future__ import annotations

import numpy as np
import pytest
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_kernels_props import KERNELS, valid
from test_never_wrong_arrays import (
    QUICK_JAX,
    array_call,
    assert_agree,
    backend,
    nan_rows,
    numpy_and_c,
    outs,
)

from rigidsym import kernels as K

#: samples per example (one batch a call: a fixed size, JAX compiles once per shape)
ROWS = 8
#: 2^±EMAX spans 1e-300..1e300 (float64), 1e-35..1e35 (float32); SUB more below it reaches
#: the subnormals
EMAX, SUB = {np.float64: 995, np.float32: 116}, {np.float64: 60, np.float32: 20}
#: agreement between back-ends, normwise per output and sample: C and NumPy compute in
#: float64 (float32 too); PyTorch and JAX compute float32 in float32, so their float32 is
#: compared at that type's rounding times a condition number of up to ~1e3 (angles drawn
#: within 1e-6 of pi are ill-conditioned for the axis: its error grows as 1/(pi - phi))
TOL = {np.float64: 2.0**-26, np.float32: 2.0**-6}
#: exponential coordinates (a rotation vector w, a twist xi): scaled from the subnormals up
#: to 2^4 only, since their sines and cosines of angles of 1e300 are no regime a user meets
#: and are ill-conditioned (condition number ~ the angle); a homogeneous transform T is not
#: scaled (it would be no transform)
EXPONENTIAL, FIXED = ("w", "xi"), ("T",)
_SETTINGS = {"deadline": None, "suppress_health_check": [HealthCheck.function_scoped_fixture,
                                                         HealthCheck.too_slow]}


@st.composite
def regime_batch(draw, name: str, dtype) -> dict:
    """``ROWS`` samples of kernel ``name``'s inputs, each argument of each sample in a regime
    of its own: free arguments scaled by 2^k over the whole range (or left as drawn), angles
    near 0 or pi (or tiny), unit vectors near an axis; now and then a NaN or inf."""
    specs = KERNELS[name][1]
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    x = {s["name"]: np.array(valid(s, (ROWS,), rng), dtype=np.float64) for s in specs}
    emax, sub = EMAX[dtype], SUB[dtype]
    for r in range(ROWS):
        for s in specs:
            v = x[s["name"]].reshape(ROWS, -1)[r]
            if s["kind"] == "angle" or s["name"] == "angles":
                how = draw(st.sampled_from(["drawn", "near 0", "near pi", "tiny"]))
                j = draw(st.integers(1, 15 if dtype == np.float64 else 7))
                sign = draw(st.sampled_from([-1.0, 1.0]))
                if how == "near 0":
                    v[...] = sign * 10.0**-j
                elif how == "near pi":
                    v[...] = sign * (np.pi - 10.0**-j)
                elif how == "tiny":
                    v[...] = sign * np.ldexp(1.0, -draw(st.integers(20, emax)))
            elif s["kind"] == "unit":
                if draw(st.booleans()):      # near an axis: two components of 2^-k
                    k = draw(st.integers(10, emax))
                    v[...] = np.ldexp(v, -k)
                    v.flat[draw(st.integers(0, v.size - 1))] = 1.0
                    v /= np.linalg.norm(v)
            elif s["name"] in EXPONENTIAL:
                if draw(st.booleans()):
                    v *= np.ldexp(1.0, draw(st.integers(-emax - sub, 4)))
            elif s["kind"] == "transform" and draw(st.booleans()):    # its translation
                v[[3, 7, 11]] *= np.ldexp(1.0, draw(st.integers(-emax - sub, emax)))
            elif s["kind"] == "any" and s["name"] not in FIXED and draw(st.booleans()):
                v *= np.ldexp(1.0, draw(st.integers(-emax - sub, emax)))
        if draw(st.integers(0, 5)) == 0:     # a NaN or inf in one component
            s = specs[draw(st.integers(0, len(specs) - 1))]
            v = x[s["name"]].reshape(ROWS, -1)[r]
            v.flat[draw(st.integers(0, max(v.size, 1) - 1))] = draw(
                st.sampled_from([np.nan, np.inf, -np.inf]))
    with np.errstate(over="ignore"):
        return {n: v.astype(dtype) for n, v in x.items()}


def _kw(name: str, check: bool) -> dict:
    return {"check": check} if name == "euler_rate_matrix" else {"check": check,
                                                                  "on_singular": "nan"}


def _finite_rows(x: dict) -> np.ndarray:
    return np.logical_and.reduce([np.isfinite(v.reshape(ROWS, -1)).all(1) for v in x.values()])


def _valid_rows(x: dict, name: str) -> np.ndarray:
    """Rows with finite inputs whose constrained arguments pass validation (a unit vector
    cast to float32 near an axis may not)."""
    ok = _finite_rows(x)
    call = KERNELS[name][0]
    for r in np.flatnonzero(ok):
        try:
            call(**{n: v[r] for n, v in x.items()}, **_kw(name, True))
        except ValueError:
            ok[r] = False
    return ok


def check_backends(name: str, x: dict, dtype, arrays=()) -> None:
    """NumPy is the reference (its long-double rescue): C and ``arrays`` back-ends give its
    NaN positions and its values to TOL; a finite-input row with a finite reference is
    finite everywhere; check=True returns what check=False does on the valid rows."""
    call = KERNELS[name][0]
    K.use_backend("numpy")
    ref = outs(call(**x, **_kw(name, False)))
    got = {}
    if K.use_backend("c") == "c":
        try:
            got["c"] = outs(call(**x, **_kw(name, False)))
            ok = _valid_rows(x, name)
            if ok.any():
                sub = {n: v[ok] for n, v in x.items()}
                for g, w in zip(outs(call(**sub, **_kw(name, True))), outs(call(
                        **sub, **_kw(name, False))), strict=True):
                    np.testing.assert_array_equal(g, w, err_msg=f"c check {name}")
        finally:
            K.use_backend("numpy")
    for b in arrays:
        mod, to, back = backend(b)
        f = array_call(mod, name)
        got[b] = outs(f(**{n: to(v) for n, v in x.items()}, **_kw(name, False)), back)
        ok = _valid_rows(x, name)
        if ok.any():
            sub = {n: to(v[ok]) for n, v in x.items()}
            for g, w in zip(outs(f(**sub, **_kw(name, True)), back),
                            outs(f(**sub, **_kw(name, False)), back), strict=True):
                np.testing.assert_array_equal(g, w, err_msg=f"{b} check {name}")
    fin = _finite_rows(x)
    for b, g in got.items():
        # XLA on CPU flushes subnormal results to zero (FTZ): JAX within the smallest normal
        atol = float(np.finfo(dtype).tiny) if b == "jax" else 0.0
        assert_agree(g, ref, TOL[dtype], (b, name, dtype), atol)
        for o, w in zip(g, ref, strict=True):
            rows = fin & np.isfinite(w.reshape(ROWS, -1)).all(1)
            assert np.isfinite(o.reshape(ROWS, -1)[rows]).all(), (b, name, "finite")


DTYPES = [np.float64, np.float32]


@pytest.mark.parametrize("name", sorted(KERNELS))
def test_float32_nan_policy_c_numpy(name):
    """float32, check=False, a NaN or inf in one input component: NumPy gives the NaN
    positions of C (and of float64). Guards against: NumPy's float32 path re-ran only flagged
    rows, so an inf input kept its IEEE limits there (natural_invariants_from_rotation: a
    finite phi where C has NaN)."""
    x, _ = nan_rows(KERNELS[name][1], np.random.default_rng(4))
    x32 = {n: v.astype(np.float32) for n, v in x.items()}
    res = numpy_and_c(name, x32, **_kw(name, False))
    ref64 = numpy_and_c(name, x, **_kw(name, False))["numpy"]
    for b, got in res.items():
        for g, w in zip(got, ref64, strict=True):
            np.testing.assert_array_equal(np.isnan(g), np.isnan(w), err_msg=f"{b} {name}")


@pytest.mark.sample
@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("name", sorted(KERNELS))
@settings(max_examples=examples(3), derandomize=True, **_SETTINGS)
@given(data=st.data())
def test_regimes_c_numpy(name, dtype, data):
    check_backends(name, data.draw(regime_batch(name, dtype)), dtype)


@pytest.mark.sample
@pytest.mark.extra
@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("name", [
    # JAX's kernels: the thorough run takes a seeded one of their slow (kernel, type)
    # members (0.1 of 7), beside those of the quick sample (every one in the ``exhaustive``
    # profile; the seed rotates per commit)
    pytest.param(n, marks=pytest.mark.thorough(0.1)) if n in QUICK_JAX else n
    for n in sorted(KERNELS)])
@settings(max_examples=examples(3), derandomize=True, **_SETTINGS)
@given(data=st.data())
def test_regimes_four_backends(name, dtype, data):
    """C, NumPy, PyTorch (every kernel) and JAX (QUICK_JAX's: its eager operations compile
    once per kernel, type and shape, 3-5 s each, 300-460 s of a CI worker for every kernel;
    the thorough run: those of the quick sample and a seeded one of the others. JAX meets
    NaN, inf and bad inputs in tests/test_never_wrong_arrays.py, on a seeded share of the
    kernels in each thorough run, subnormals in its ``test_subnormal_inputs_arrays``)."""
    arrays = ("torch", "jax") if name in QUICK_JAX else ("torch",)
    check_backends(name, data.draw(regime_batch(name, dtype)), dtype, arrays)
