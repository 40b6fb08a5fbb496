"""float32 kernels: dtype rules (NEP 50), float32 out, tolerances scaled with the dtype, and
the error against the 50-digit reference evaluated at the *same* float32 inputs.

The C kernels compute in float32 arithmetic, in float64 only for the subexpressions their
precision plan keeps there (rigidsym.codegen.accuracy.float32, named in each generated
header). Plan and test read the same rule, rigidsym.codegen.accuracy.rule's:
per output, the normwise relative error within ``max(2 e_ref, 4 u)``, ``e_ref`` the textbook
formula's error (the declaration, naively, in float32 arithmetic) at the same inputs,
``u = 2**-24``, at random and adversarial points alike (the rule's condition half is
benchmarks/accuracy.py's, tests/test_accuracy.py). The NumPy backend computes in float64
and rounds once (about half an ulp).
"""

from __future__ import annotations

import shutil

import numpy as np
import pytest
from test_kernels import (
    ADV_PHI,
    AVAILABLE,
    EULER,
    ON_SO3,
    PUBLIC,
    inputs,
    ref_eval,
    row_tol,
)

from rigidsym import kernels as K
from rigidsym.codegen.accuracy import float32 as F32
from rigidsym.codegen.accuracy import rule
from rigidsym.codegen.accuracy.error import normwise
from rigidsym.kernels.runtime import scale as _scale

ULP32 = float(np.finfo(np.float32).eps)         # 2**-23
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


def _rule_ratio(name, arrays, got, ref):
    """Per sample, the worst ratio over the outputs of the error to what the rule allows
    (rigidsym.codegen.accuracy.float32.BUDGET: the rule with the textbook formula in float32)."""
    kernel = AVAILABLE[name]
    n = arrays[0].shape[0]
    tb = rule.textbook(kernel, [c for a in arrays for c in a.reshape(n, -1).T], np.float32)
    offs = np.cumsum([0] + [o.size for o in kernel.outputs])
    groups = [slice(a, b) for a, b in zip(offs[:-1], offs[1:], strict=True)]
    err = normwise(got.astype(np.float64), ref, groups)
    allowed = F32.BUDGET(normwise(tb, ref, groups))
    # ON_SO3 kernels: the rounding of a float32 Q over sin^2(phi) (the model error of an input
    # that is not exactly a rotation), as in test_kernels
    if name in ON_SO3:
        allowed = allowed + row_tol(name, ref, ULP32 / 2, 0.0)[:, None]
    with np.errstate(all="ignore"):
        return np.where(err == 0, 0.0, err / allowed).max(axis=1)


#: Open: C float32 rows past the rule at this test's points, each held to its
#: measured ratio (+10 %). The plans meet the rule at the planner's points; the C float32 code
#: is compiled without FMA contraction as the planner simulates it (RIGIDSYM_F32_BEGIN; with
#: contraction instant_screw_axis 1.3, point_acceleration 1.3, wrench_axis 1.4 were open
#: here, euler_angle_rates_xzx_fixed 1.25 -> 1.01, within 1 since the plans are measured over
#: the harness's regimes too).
OPEN_C: dict = {}


@pytest.mark.sample
@pytest.mark.parametrize("name", PUBLIC + EULER)
def test_float32_error_bound_against_50_digits(name, backend):
    """The plan's budget and this test's are both the accuracy rule (a stricter budget,
    1 ulp against the float64 program, keeps 9 of instant_screw_axis's 11 nodes in double:
    0.90x float64's time)."""
    arrays, ref = _case(name, 200 if name in PUBLIC else 30)
    got = _run32(name, arrays, backend)
    assert got.dtype == np.float32
    r = _rule_ratio(name, arrays, got, ref)
    rnd, adv = r[:-N_ADV], r[-N_ADV:]
    limit = OPEN_C.get(name, 1.0) if backend == "c" else 1.0
    assert np.isfinite(got).all(), f"{name}: non-finite output"
    assert rnd.max() <= limit, f"{name} [{backend}] random: {rnd.max():.3g} of the rule"
    assert adv.max() <= limit, f"{name} [{backend}] adversarial: {adv.max():.3g} of the rule"


@pytest.mark.slow
@pytest.mark.parametrize("name", PUBLIC)
def test_float32_error_bound_1000_points(name):
    """1000 random points and the adversarial ones per kernel, compiled float32."""
    if K.use_backend("c") != "c":
        pytest.skip("no C backend")
    arrays, ref = _case(name, 1000)
    got = _run32(name, arrays, "c")
    r = _rule_ratio(name, arrays, got, ref)
    assert np.isfinite(got).all(), f"{name}: non-finite output"
    limit = OPEN_C_1000.get(name, 1.0)
    assert r.max() <= limit, f"{name}: {r.max():.3g} of the rule"


#: Open: at 1000 points these float32 plans pass max(2 e_ref, 4 u) by
#: these factors (measured +10 %), the planner's points not covering them; each is held to it.
#: Compiled with FMA contraction seven were open (instant_screw_axis 3.9, wrench_axis 4.5,
#: moving_frame_acceleration 1.85, now within 1); without it (RIGIDSYM_F32_BEGIN) four.
#: Since the plans are measured over the harness's regimes too (REGIME_SEEDS) L_tilde_dot
#: (1.09), exponential_coordinates_left_jacobian (1.35) and screw_axis_point (1.69) are within
#: 1 here; exponential_coordinates_left_jacobian_inverse went 1.10 -> 1.45 at one of these
#: points although its plan got better over 20000 random points (past the rule at 25 of them,
#: worst 2.2; the old plan at 46, worst 3.0): a tail of random points that 1000 planner points
#: do not reach (4000 reach more: 9 of 20000, worst 1.65, at 3x the plan's time). Since the plans
#: and the textbook use correctly rounded sin, cos, atan2 (one yardstick on every CPU),
#: screw_axis_point 1.19 at one of these points (its header: 0.956 of the rule at the planner's).
OPEN_C_1000 = {"exponential_coordinates_left_jacobian_inverse": 1.6, "screw_axis_point": 1.31}


def test_the_plans_range_is_the_c_kernels():
    """The planner leaves out the points whose inputs the C float32 kernels hand to the
    rescue (rigidsym_any_extreme_f32): its range must be theirs, or a plan is chosen for
    points C never computes in float (guards against: norm(omega) down to 1e-18, re-run in long
    double by C) while missing the ones it does."""
    from rigidsym.kernels.runtime.rescue import RANGE32

    assert F32.RANGE32 == RANGE32
    k = next(k for k in _kernels() if k.name == "instant_screw_axis_with_jacobians")
    cols, exact = F32.plan_inputs(k)
    m = np.abs(np.stack(list(cols.values())))
    assert ((m == 0) | ((m >= RANGE32[0]) & (m < RANGE32[1]))).all()
    assert len(cols["omega_0"]) > F32.N_RANDOM          # the harness's regimes joined
    assert set(exact) == set(cols)


def _kernels():
    from rigidsym.derivations.kernels_spec import KERNELS

    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels

    return list(KERNELS) + jacobian_kernels([k for k in KERNELS if k.public])


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
