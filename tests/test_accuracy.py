"""Accuracy against the condition of the problem and never worse than the textbook
formula or a peer: the regimes of ``benchmarks/accuracy.py`` as a test, in float64
on a subsample of the approach steps, so that a rewrite that loses digits fails here.

Every public kernel (and a few Jacobian and Euler-angle kernels) at exact points rounded to
float64, over random points and the approaches to every cancellation its inputs' kinds have
(angles to 0 and pi from both sides, rotations to 1 and a half turn, norms to 0, gimbal
lock, scales 1e-6..1e6, unit vectors a few ulps off): the error of every output within
``8 u (kappa + 1)`` of the declared formula in ``arb`` balls, and no flagged sample where the
exact result is finite and kappa < 1e12. The full sweep (both types, every kernel) is the
``slow`` test at the end (the thorough run: a seeded third of the kernels, SWEEP_ALWAYS
among them).
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import _profile
import numpy as np
import pytest

from rigidsym import kernels as K

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
pytest.importorskip("flint")
from rigidsym.codegen.accuracy.harness import judge as A  # noqa: E402

#: the approach steps of the subsample: far, midway, the spacing of 1, the smallest used
SMALL = [1e-1, 1e-8, 1e-15, 1e-75]
EXTRA = ["plucker_from_points_with_jacobians", "instant_screw_axis_with_jacobians",
         "euler_angle_rates_zyz_body", "euler_angle_rates_xyz_fixed"]


def available_backends() -> list[str]:
    if K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        return ["numpy"]
    return ["c", "numpy"]


def _losses(rows) -> str:
    return "\n".join(f"{r.kernel} {r.backend} {r.regime}: err {r.err:.2g} = "
                     f"{r.worst_ratio:.3g} x 8u(kappa+1), kappa {r.kappa:.2g}, rule "
                     f"{r.rule_ratio:.3g} (vs e_ref {r.ref_ratio:.3g}, {r.ref_source}), "
                     f"spurious {r.spurious[:1]} at {r.worst_point}"
                     for r in rows if not r.accurate)


#: Open losses to the accuracy rule (float64; the worst rule ratio over the full sweep,
#: benchmarks/RESULTS.md): the test holds them to it, so they cannot grow unseen.
#: The slow full sweep's limit on the rule's ratio (more points than the default test's):
#: what is still open there is FMA contraction and the Lie kernels at points scaled 1e6
#: (`rotation_from_rotation_vector` 1.88). It was LIBMVEC_RULE = 6.0 while the C kernels
#: took sin/cos from glibc's libmvec (within 4 ulp: up to 5.8); their own vectorised sin/cos
#: (c_common.h.j2, within 1 ulp) brought every trig kernel within the rule at the default
#: test's points, so that test allows libmvec nothing (a libmvec build fails it:
#: rotation_from_natural_invariants 1.9, euler_angle_rates_xzx_fixed 3.2).
SWEEP_RULE = 2.0
# (L_tilde_dot_with_jacobians float64, NumPy 1.6, is gone: no default test judged it; its
# worst point is held by test_at_the_old_worst_point)
OPEN = {
        # the Jacobian at ||f|| -> 0 by pow now (NumPy 0.84; 1.67 before); C 4.7 u where
        # the textbook is 1.95 u at one point: glibc's pow against NumPy's SIMD power (the
        # textbook's), each within 0.6 ulp, rounding the derivative differently
        ("wrench_axis_with_jacobians", "c", "float64"): 1.2,
        ("instant_screw_axis_with_jacobians", "numpy", "float64"): 1.4,
        ("instant_screw_axis_with_jacobians", "c", "float64"): 1.4,
        # (screw_of_displacement float64, 1.6 at Q: phi -> 0, is gone: the harness no
        # longer forgives the textbook the rounding of Q there, _diff; 0.87 at these points)
        # float32 (test_float32_c_plans_over_the_regimes): the rounding of a constrained
        # input (Q, e), which the truth does not see, weighs differently on the kernel's
        # form and the textbook's; NumPy (float64 arithmetic, rounded once) the same
        ("screw_of_displacement", "c", "float32"): 1.4,
        ("screw_of_displacement", "numpy", "float32"): 1.4,
        # since the plans and the textbook use correctly rounded sin, cos, atan2
        # (rigidsym.codegen.accuracy.elementary; one yardstick on every CPU): 1.3 -> 1.50
        # at a unit e off by ulps, and L_tilde_with_jacobians 1.09 at a random point (both
        # on seeds 0-3; the search over every kernel no longer finds either)
        ("L_tilde_dot_with_jacobians", "c", "float32"): 1.65,
        ("L_tilde_dot_with_jacobians", "numpy", "float32"): 1.65,
        ("L_tilde_with_jacobians", "c", "float32"): 1.2,
        ("L_tilde_with_jacobians", "numpy", "float32"): 1.2,
        # the derived regimes (|w| -> 2 pi k): the 1 - cos form is 2.5e-2 off at
        # 2 pi - 1e-9 (ratio ~1e13); the half-angle form is
        # within 8 u (kappa + 1) everywhere there but, a step 0.1 past 6 pi (|w| = 18.95),
        # 2.38 times max(2 e_ref, 4 u) against pytransform3d's tan(theta/2) form, and the
        # SE(3) inverse 1.89 there (1.06 at 2 pi + 0.1 against the textbook): open
        **{(k, b, "float64"): 2.5 for k in ("rotation_vector_left_jacobian_inverse",
                                           "rotation_vector_right_jacobian_inverse")
           for b in ("c", "numpy")},
        **{("exponential_coordinates_left_jacobian_inverse", b, "float64"): 2.0
           for b in ("c", "numpy")},
        # found by the same derived regimes: Exp near 6 pi + 0.1 1.09 against pytransform3d,
        # the SE(3) Exp near 4 pi 1.72 against the textbook (both within 8 u (kappa + 1):
        # 0.20, 0.14)
        **{("rotation_from_rotation_vector", b, "float64"): 1.15 for b in ("c", "numpy")},
        **{("transform_from_exponential_coordinates", b, "float64"): 1.8
           for b in ("c", "numpy")}}


def _within(rows) -> list:
    """The rows past the rule (OPEN allowed for)."""
    return [r for r in rows
            if r.rule_ratio > OPEN.get((r.kernel, r.backend, r.dtype), 1.0) or r.spurious]


#: Found by the ends of the range (the harness's regimes) in the Lie kernels, open for the
#: rescue: strict, so a fix turns them into a failure to remove here.
#: (The Jacobian inverses' "finite wrong values" at 1e-300 were the reference's: a ball 1e-3
#: wide at 2000 bits taken for the truth; harness.reference.max_prec. At 1e300 they return
#: J(w (1 + d)), |d| ~ 2^-65: test_lie_jacobian_inverse_at_the_range_ends. The SE(3) log's
#: "NaN at 1e-160" was a random 4 x 4 that is no transform: the "transform" kind.) None open.
RANGE_DEFECTS: dict[str, str] = {}


@pytest.mark.sample
@pytest.mark.parametrize("name", [
    pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=RANGE_DEFECTS[n]))
    if n in RANGE_DEFECTS else n for n in sorted(K.KERNEL_NAMES) + EXTRA])
def test_accurate_over_the_regimes_float64(name):
    """The condition half on every row; the whole accuracy rule on every row but the
    open ones (OPEN). Guards against a harness without the second yardstick
    (tests/test_accuracy_rule.py shows the loss it lets through) and a libmvec build (the trig
    kernels on C past the rule: rotation_from_natural_invariants 1.9)."""
    rows = A.sweep([name], [np.float64], available_backends(), n_random=3, small=SMALL)
    K.use_backend("numpy")
    assert rows and sum(r.samples for r in rows) >= 5
    assert all(r.worst_ratio <= 1 and not r.spurious for r in rows), _losses(rows)
    assert not _within(rows), _losses(_within(rows))


#: float32 kernels whose C precision plan was past the rule at the harness's regimes on old
#: main (rule ratio): the planner (rigidsym.codegen.accuracy.float32) measured none of them; it
#: measures them now, drawn with seeds of its own (not these)
F32_PLANNED = {"euler_angle_rates_yzy_body": 1.73, "euler_angle_rates_xzx_fixed": 2.32,
               "euler_angle_rates_yxy_fixed": 2.35, "euler_angle_rates_xyz_fixed": 1.84,
               "screw_axis_point_with_jacobians": 1.35, "L_tilde_with_jacobians": 1.18,
               "L_tilde_dot_with_jacobians": 1.56, "screw_of_displacement": 1.39}


def test_float32_c_plan_at_gimbal_lock():
    """euler_angle_rates_yzy_body in float32 on C at the gimbal-lock points of seed 2 (the
    middle angle 1e-1 .. 1e-15 from 0 and pi). A plan that measures no point near pi keeps
    a random omega's cancelling numerator in float: 1.73 of the rule, 11.9 u where the
    textbook is 3.4 u."""
    if "c" not in available_backends():
        pytest.skip("no C backend")
    name = "euler_angle_rates_yzy_body"
    pts = A.P.regimes(A.R.kernel_of(name), np.float32, seed=2)["gimbal lock"]
    rows = A.judge(name, "gimbal lock", pts, np.float32, ["c"])
    assert rows[0].samples == 60 and not _within(rows), _losses(rows)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(F32_PLANNED))
def test_float32_c_plans_over_the_regimes(name):
    """The harness's float32 rows of the kernels of F32_PLANNED (seeds 0-3, every regime):
    within the rule, OPEN aside (F32_PLANNED: the ratios of plans that do not measure
    these regimes)."""
    rows = A.sweep([name], [np.float32], available_backends(), seeds=(0, 1, 2, 3))
    K.use_backend("numpy")
    assert not _within(rows), _losses(_within(rows))


def test_lie_jacobian_inverse_at_the_range_ends():
    """J_l(w)^-1 = 1 - [w]/2 + c(theta) [w]^2, c = 1/theta^2 - sin theta / (2 theta (1 - cos
    theta)) -> 1/12: at |w| ~ 1e-300 the reference resolves the removable singularity (old
    main: a ball 1e-3 wide at 2000 bits, taken for the truth, called the kernel's exact I
    "1.45e12 x 8 u (kappa + 1)" off). At |w| ~ 1e300 the value is -(theta/2) cot(theta/2)
    (e e^T - 1) - [w]/2 + ...: no float64 theta fixes theta mod 2 pi (kappa ~ theta), the
    condition says so (guards against: a step 2^-100 |w| = 1e270 spanned 1e269 periods, kappa read
    1e-74, the row was skipped unjudged), and the kernel returns J at a w (1 + d), |d| <<
    u: backward stable, as sin(theta) of the rounded theta in every peer (the rescue's long
    double theta; measured d = -3.6e-20 at w = (-1.35, 0.41, 0.77) 1e300)."""
    from rigidsym.codegen.accuracy import regimes as P

    name = "rotation_vector_left_jacobian_inverse"
    e = np.array([0.48, -0.6, 0.64])
    w = e * 2.0**-997
    f = A.R.pick(name, list(w))
    ref, _ = A.R.reference(f, [P.q(x) for x in w])
    W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    np.testing.assert_array_equal(ref.reshape(3, 3), np.eye(3) - W / 2)     # + W^2/12 ~ 1e-600
    np.testing.assert_array_equal(K.rotation_vector_left_jacobian_inverse(w), ref.reshape(3, 3))
    big = [P.q(x) for x in e * 2.0**997]
    ref, prec = A.R.reference(f, big)
    scale, norms = A.R.condition(name, f, [big], [9], ref, prec)
    assert A.kappa_of(scale, norms) * 2.0**-53 >= 0.125
    # every real m is (theta'/2) cot(theta'/2) for a theta' within 2 pi of theta: the value
    # is right for a w' = w (1 + d), |d| ~ 1e-299, iff it has the form of J_l(w')^-1:
    # skew part -[w]/2, symmetric part e e^T + m (1 - e e^T) (then J w = w)
    wb = e * 2.0**997
    Wb = np.array([[0, -wb[2], wb[1]], [wb[2], 0, -wb[0]], [-wb[1], wb[0], 0]])
    for b in available_backends():
        K.use_backend(b)
        J = K.rotation_vector_left_jacobian_inverse(wb)
        S, P_ = (J + J.T) / 2, np.eye(3) - np.outer(e, e)
        m = np.trace(S @ P_) / 2
        tol = 8 * 2.0**-53 * np.linalg.norm(J)
        assert np.isfinite(J).all() and abs(m) > 1e200, b
        assert np.linalg.norm((J - J.T) / 2 + Wb / 2) <= tol, b
        assert np.linalg.norm(S - np.outer(e, e) - m * P_) <= tol, b
    K.use_backend("numpy")


def _declared_numpy(name):
    """The declared outputs of ``name`` lambdified for NumPy, no rewrite: the generated
    kernel without the rewrites."""
    import sympy as sp

    from rigidsym.codegen.accuracy.harness import reference as R
    from rigidsym.codegen.generator import _flatten
    from rigidsym.codegen.spec import flat_symbols, input_symbols

    k = R.kernel_of(name)
    f = sp.lambdify([s for _, ss in flat_symbols(k) for s in ss],
                    _flatten(k, k.build(**input_symbols(k))), modules="numpy")

    def run(name_, arrays, dtype, backend):
        cols = [c for a in arrays for c in a.reshape(len(a), -1).T]
        with np.errstate(all="ignore"):
            return np.array([np.broadcast_to(v, (len(arrays[0]),)) for v in f(*cols)]).T
    return run


def test_the_harness_sees_the_loss_it_was_built_for():
    """The declared p0 of screw_of_displacement, 3 - tr Q in the denominator: relative error
    eps/phi^2 against a condition number 1/phi, and a singular flag at phi ~ 1e-9. The
    harness must call it losing (the regime the kernel's rewrite fixed)."""
    rows = A.sweep(["screw_of_displacement"], [np.float64], ["numpy"], n_random=1,
                   small=[1e-5, 1e-9], runner=_declared_numpy("screw_of_displacement"))
    bad = {r.regime for r in rows if not r.accurate}
    assert "Q: phi->0" in bad


def test_no_singular_error_at_a_small_representable_angle():
    """The headline of a rotation by 1e-9 rad has a finite screw (p0 ~ |t|/phi),
    condition ~ 1/phi; the kernel neither raises nor loses the digits."""
    e = np.array([0.48, 0.6, 0.64])
    Q = K.rotation_from_natural_invariants(e, 1e-9)
    a, d = np.array([0.3, -0.2, 1.0]), np.array([1e-3, 2e-3, -1e-3])
    _, phi, p0, pitch, _ = K.screw_of_displacement(Q, a, Q @ a + d)
    # (3.18) with Q - 1 = sin(phi) E + (1 - cos phi) E^2, E = CPM(e):
    # p0 = cot(phi/2)/2 e x d + (d - e (e . d))/2, and cot(phi/2)/2 = 1/phi - phi/12 - ...
    ref = np.cross(e, d) / 1e-9 + (d - e * (e @ d)) / 2
    assert abs(phi - 1e-9) <= 1e-9 * 1e-6
    assert np.linalg.norm(p0 - ref) <= 1e-5 * np.linalg.norm(ref)


def test_accuracy_rows_are_shipped():
    row = K.accuracy("screw_of_displacement")
    assert set(row) >= {"float64", "float32", "regimes", "accurate", "singular", "threshold"}
    assert row["float64"]["bound"] <= 8 and row["float32"]["bound"] <= 8
    assert "Q: phi->0" in row["regimes"] and row["threshold"]
    row["float64"]["bound"] = -1              # a copy: the shipped data stays
    assert K.accuracy("screw_of_displacement")["float64"]["bound"] > 0
    for name in K.KERNEL_NAMES:
        r = K.accuracy(name)
        # accurate means the whole rule, on every back-end and type
        f64, f32 = r["float64"], r["float32"]
        assert set(f64["backends"]) >= {"numpy"} and "rule" in f64, name
        assert r["accurate"] == (max(f64["rule"], f32["rule"]) <= 1 and not f64["spurious"]
                                 and not f32["spurious"]), name
        assert "Accuracy: error <=" in getattr(K, name).__doc__, name
    with pytest.raises(KeyError, match="name: no kernel 'nope'"):
        K.accuracy("nope")


#: the kernels the full sweep judges in every run: the SE(3) inverse Jacobian (sympy's
#: "Can't calculate derivative wrt" on its Grouped marks), the sweep's worst row
#: (rotation_from_rotation_vector, 1.88 of SWEEP_RULE) and the two a libmvec build loses
SWEEP_ALWAYS = ("exponential_coordinates_left_jacobian_inverse",
                "exponential_coordinates_left_jacobian_inverse_with_jacobians",
                "rotation_from_rotation_vector", "rotation_from_natural_invariants",
                "euler_angle_rates_xzx_fixed")


def sweep_kernels() -> list[str]:
    """The full sweep's kernels: SWEEP_ALWAYS, RANGE_DEFECTS and the thorough run's seeded
    third of the others (every kernel in the ``exhaustive`` profile; the seed rotates per
    commit, and test_accurate_over_the_regimes_float64 judges every public kernel in
    float64 each run)."""
    names = A.kernel_names()
    always = set(SWEEP_ALWAYS) | set(RANGE_DEFECTS)
    drawn = set(_profile.share([n for n in names if n not in always], 1 / 3))
    return [n for n in names if n in always or n in drawn]


@pytest.mark.slow
def test_full_sweep_both_types():
    """The whole harness: every kernel (the thorough run's share, :func:`sweep_kernels`),
    float64 and float32, C and NumPy (minutes; 8.3 min for every kernel on the loaded
    2-core host with the [oracles] extra). It guards against sympy's "Can't calculate
    derivative wrt" on the SE(3) inverse Jacobian's Grouped marks:
    spec.Grouped._eval_derivative differentiates what it groups."""
    assert set(SWEEP_ALWAYS) <= set(A.kernel_names())
    rows = A.sweep(sweep_kernels(), [np.float64, np.float32], available_backends(), n_random=4)
    K.use_backend("numpy")
    # every row of every regime is judged, the Lie kernels' at the ends of the range too
    # (RANGE_DEFECTS: none open)
    rows = [r for r in rows if not (r.kernel in RANGE_DEFECTS and r.regime.startswith("range"))]
    over = [r for r in rows if r.worst_ratio > 1]
    assert not over, [(r.kernel, r.backend, r.dtype, r.regime, r.worst_ratio) for r in over]
    # open: the per-row limits of OPEN were measured at the default test's points;
    # over this sweep more C rows pass max(2 e_ref, 4 u) by up to SWEEP_RULE (fma
    # contraction, Lie kernels at points scaled 1e6): none beyond it, no spurious singularity
    past = [r for r in rows if r.rule_ratio > SWEEP_RULE or r.spurious]
    assert not past, _losses(past)


#: (kernel, regime, seed, limit on the rule's ratio): old worst points of closed rows
OLD_WORST = [
    # phi = -0.68: found at 1.03 (d e_dot / d phi 4.7 u where the textbook is 2.3 u:
    # sympy.diff's cancelling fractions in cos phi, merged by accurate_rules._angle_fractions)
    ("N_tilde_dot_with_jacobians", "random", 2, 0.8),
    # phi = 2.67: found at 1.39 (6.3 u where the textbook is 2.3 u: the half-angle program
    # read sin(phi/2) apart from cos phi; the polynomial in tan(phi/2) of codegen.tan_half)
    ("L_tilde_dot", "random", 2, 0.8),
    # phi = -1.79: found at 1.95 (d/dphi 7.8 u where the textbook is 1.9 u); that polynomial
    # differentiated: 1.14 (4.6 u, the cancellation in d/dphi, open in docs/accuracy.md)
    ("L_tilde_dot_with_jacobians", "unit off by ulps", 1, 1.2),
]


@pytest.mark.parametrize("name,regime,seed,limit", OLD_WORST)
def test_at_the_old_worst_point(name, regime, seed, limit):
    """A closed row at its old worst point (float64, C and NumPy): within ``limit``, where
    a program past the rule was found (OLD_WORST)."""
    pts = A.P.regimes(A.R.kernel_of(name), np.float64, n_random=8, seed=seed)[regime]
    rows = A.judge(name, regime, pts, np.float64, available_backends())
    K.use_backend("numpy")
    assert all(r.rule_ratio <= limit for r in rows), _losses(rows)
