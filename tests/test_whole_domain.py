"""Kernels right over their whole domain: the cases an outside audit found where
no regime of the harness looked.

1. The inverse Jacobians near ``|w| = 2 pi k``: the closed form above the removable series
   was ``(2 - 2 cos t - t sin t) / (t^2 (1 - cos t))``, whose ``1 - cos t`` cancels
   completely there (relative error 2.5e-2 at ``2 pi - 1e-9``; ``NonFiniteResultError``
   at ``2 pi - 1e-10``, where the exact result has norm 8.9e10). The generator now prints
   a quotient whose denominator vanishes at ``2 pi`` in half angles
   (:func:`rigidsym.codegen.removable.singularities.half_angle`): ``1/t^2 - cot(t/2)/(2 t)``.
2. The SE(3) inverse Jacobian against pytransform3d's ``left_jacobian_SE3_inv`` at
   ``|w|`` in {3, pi, 4.5}: within the rule's ``max(2 e_ref, 4 u)`` of the peer.
3. ``rotation_from_euler_rodrigues`` normalises: any non-zero eta gives a rotation, which
   every kernel that takes a rotation accepts.

References: the declared formulas of ``derivations/lie_maps.py`` in mpmath at 60 digits
and more, at the float64 input the kernel got.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from _profile import examples, fast_or_slow
from hypothesis import given, settings
from hypothesis import strategies as st
from rigidsym.derivations import lie_maps as L

from rigidsym import kernels

U = 2.0**-53
AXIS = np.array([0.36, -0.48, 0.8])
INVERSES = ["rotation_vector_left_jacobian_inverse", "rotation_vector_right_jacobian_inverse",
            "exponential_coordinates_left_jacobian_inverse"]
TWO_PI = 2 * np.pi
#: norms at and near the zero set of 1 - cos t (t = 2 pi k) and of sin t (k pi)
NEAR = [TWO_PI - 1e-6, TWO_PI - 3e-8, TWO_PI - 1e-8, TWO_PI - 1e-9, TWO_PI - 1e-10,
        TWO_PI + 1e-9, 2 * TWO_PI - 1e-8, 3 * TWO_PI + 1e-7, 3 * np.pi - 1e-8, 7.0]

#: open against the peer (measured ratio to max(2 e_peer, 4 u), C): the 6 x 6 product at
#: 3 pi - 1e-8, 10.8 u where pytransform3d is 4.0 u (within 8 u (kappa + 1))
OPEN_PEER = {("exponential_coordinates_left_jacobian_inverse", 3 * np.pi - 1e-8): 1.4}

_FNS: dict = {}


def _fn(name, n_in):
    """The declared formula of ``name`` as an mpmath function of its ``n_in`` inputs."""
    if name not in _FNS:
        x = sp.Matrix(sp.symbols(f"x0:{n_in}", real=True))
        _FNS[name] = sp.lambdify(list(x), sp.Matrix(getattr(L, name)(x)), "mpmath")
    return _FNS[name]


def _ref(name, x, dps=80):
    """The formula at the float64 point ``x`` (exactly), to ``dps`` digits."""
    with mp.workdps(dps):
        v = mp.matrix(_fn(name, len(x))(*[mp.mpf(float(t)) for t in x]))
        return np.array([[v[i, j] for j in range(v.cols)] for i in range(v.rows)])


def _rel(got, ref) -> float:
    """Norm-wise (Frobenius) relative error of a float result against an mpmath one."""
    with mp.workdps(40):
        d = mp.sqrt(sum((mp.mpf(float(g)) - r) ** 2 for g, r in zip(
            np.ravel(got), np.ravel(ref), strict=True)))
        n = mp.sqrt(sum(r**2 for r in np.ravel(ref)))
        return float(d / n)


def _kappa(name, x) -> float:
    """The relative condition number of the result at ``x``: ``||D f|| ||x|| / ||f||``
    (Frobenius norms, derivative by an 80-digit central difference)."""
    with mp.workdps(100):
        f0 = _ref(name, x, 100)
        n0 = mp.sqrt(sum(r**2 for r in np.ravel(f0)))
        h = mp.mpf("1e-40")
        s = 0
        for i in range(len(x)):
            xp = [mp.mpf(float(t)) for t in x]
            xm = list(xp)
            xp[i] += h
            xm[i] -= h
            fp, fm = (mp.matrix(_fn(name, len(x))(*p)) for p in (xp, xm))
            s += sum(((fp[r, c] - fm[r, c]) / (2 * h)) ** 2
                     for r in range(fp.rows) for c in range(fp.cols))
        nx = mp.sqrt(sum(mp.mpf(float(t)) ** 2 for t in x))
        return float(mp.sqrt(s) * nx / n0)


def _call(name, x, backend, **kw):
    old = kernels.backend()
    kernels.use_backend(backend)
    try:
        return np.asarray(getattr(kernels, name)(np.asarray(x), **kw))
    finally:
        kernels.use_backend(old)


def _backends():
    return ["c", "numpy"] if kernels.backend() == "c" else ["numpy"]


def _peer(name, x):
    """pytransform3d's value of the same operation at ``x``, or None without it."""
    try:
        import pytransform3d.rotations as pr
        import pytransform3d.transformations as pt
    except ImportError:
        return None
    if name == "rotation_vector_left_jacobian_inverse":
        return pr.left_jacobian_SO3_inv(np.asarray(x))
    if name == "rotation_vector_right_jacobian_inverse":
        return pr.left_jacobian_SO3_inv(-np.asarray(x))
    return pt.left_jacobian_SE3_inv(np.asarray(x))


def _point(name, t):
    w = t * AXIS
    return w if name.startswith("rotation_vector") else np.r_[w, 0.3, -1.2, 0.5]


# quick: the rotation vector's left inverse (1-2 s); the twist's (about 15 s: a 6 x 6 reference
# at 80 digits per norm) and the right one thorough
@pytest.mark.parametrize("name", fast_or_slow(INVERSES, {"rotation_vector_left_jacobian_inverse"}))
def test_inverse_jacobians_near_2pi_k(name):
    """Within 8 u (kappa + 1) of the declared formula at every norm of NEAR (guards against:
    2.5e-2 at 2 pi - 1e-9, kappa u = 7e-7; NonFiniteResultError at 2 pi - 1e-10), and within
    ``max(2 e_peer, 4 u)`` of pytransform3d's ``left_jacobian_SO3_inv``/``_SE3_inv``."""
    for t in NEAR:
        x = _point(name, t)
        ref = _ref(name, x)
        kappa = _kappa(name, x)
        peer = _peer(name, x)
        e_peer = _rel(peer, ref) if peer is not None else np.inf
        for b in _backends():
            got = _call(name, x, b)     # raise mode: no flag anywhere here
            err = _rel(got, ref)
            assert err <= 8 * U * (kappa + 1), (name, b, t, err, kappa * U)
            if peer is not None:
                limit = OPEN_PEER.get((name, t), 1.0)
                assert err <= limit * max(2 * e_peer, 4 * U), (name, b, t, err, e_peer)


def test_se3_inverse_jacobian_against_pytransform3d():
    """|w| in {3, pi, 4.5}, 20 random axes and v each, against the rule's ``max(2 e_peer, 4 u)``
    of pytransform3d's ``left_jacobian_SE3_inv``: a form that cancels has 33 of these 60 outside
    (worst 2.4 times; the audit's 25 of 60, 6.9 times). Open: 3 at |w| = 4.5 on C and NumPy,
    worst 1.32 times (the 6 x 6 product as generated; the same products in NumPy, associated as
    pytransform3d's, were within at all 60): held to at most 3 samples and 1.5 times."""
    pytest.importorskip("pytransform3d")
    name = "exponential_coordinates_left_jacobian_inverse"
    rng = np.random.default_rng(48)
    bad = []
    for t in (3.0, np.pi, 4.5):
        for _ in range(20):
            d = rng.normal(size=3)
            x = np.r_[t * d / np.linalg.norm(d), rng.normal(size=3)]
            ref = _ref(name, x, 50)
            e_peer = _rel(_peer(name, x), ref)
            for b in _backends():
                err = _rel(_call(name, x, b), ref)
                if err > max(2 * e_peer, 4 * U):
                    bad.append((t, b, err / U, e_peer / U, err / max(2 * e_peer, 4 * U)))
    assert len({(t, e) for t, _, _, e, _ in bad}) <= 3, bad
    assert max((r for *_, r in bad), default=0) <= 1.5, bad


# ----------------------------------------------------------------------------------------
# rotation_from_euler_rodrigues normalises (item 4)

def _is_rotation(Q, tol=8 * U):
    Q = np.asarray(Q).reshape(3, 3)
    return np.abs(Q.T @ Q - np.eye(3)).max() <= tol and abs(np.linalg.det(Q) - 1) <= tol


def test_euler_rodrigues_near_unit_is_a_rotation_the_logs_accept():
    """``|eta| - 1 = 4e-9`` (inside the unit tolerance): guards against the matrix
    ``|eta|^2 Q``, ``|Q^T Q - 1| = 1.6e-8``, rejected by the logs ("Q: not orthogonal")."""
    eta = np.array([0.1, -0.5, 0.3, 0.8])
    eta = eta / np.linalg.norm(eta) * (1 + 4e-9)
    for b in _backends():
        old = kernels.backend()
        kernels.use_backend(b)
        try:
            Q = kernels.rotation_from_euler_rodrigues(eta)
            assert _is_rotation(Q), (b, Q.T @ Q)
            kernels.rotation_vector_from_rotation(Q)
            back = kernels.euler_rodrigues_from_rotation(Q)
            assert np.allclose(back, eta / np.linalg.norm(eta), atol=8 * U, rtol=0)
        finally:
            kernels.use_backend(old)


def test_euler_rodrigues_far_from_unit():
    """``check=True`` still names an eta far from unit; ``check=False`` gives the rotation
    of eta / |eta| (not 4 Q for |eta| = 2, det 64); eta = 0 is singular."""
    eta = np.array([0.2, 0.4, -0.4, 0.8]) * 2          # |eta| = 2
    with pytest.raises(ValueError, match="eta"):
        kernels.rotation_from_euler_rodrigues(eta)
    Q = kernels.rotation_from_euler_rodrigues(eta, check=False)
    assert _is_rotation(Q)
    assert np.allclose(Q, kernels.rotation_from_euler_rodrigues(eta / 2), atol=4 * U, rtol=0)
    with pytest.raises(kernels.SingularConfigurationError):
        kernels.rotation_from_euler_rodrigues(np.zeros(4), check=False)


def _producers(rng, n):
    """(name, Q) of every kernel that returns a rotation, at ``n`` random valid inputs."""
    e = rng.normal(size=(n, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    phi = rng.uniform(-4, 4, size=n)
    eta = rng.normal(size=(n, 4))
    eta /= np.linalg.norm(eta, axis=1, keepdims=True)
    eta *= 1 + rng.uniform(-4e-9, 4e-9, size=(n, 1))   # inside the unit tolerance
    w = rng.normal(size=(n, 3)) * rng.choice([1e-9, 1, 3, 10], size=(n, 1))
    xi = np.c_[w, rng.normal(size=(n, 3))]
    T = kernels.transform_from_exponential_coordinates(xi)
    return [("rotation_from_natural_invariants", kernels.rotation_from_natural_invariants(e, phi)),
            ("rotation_from_euler_rodrigues", kernels.rotation_from_euler_rodrigues(eta)),
            ("rotation_from_rotation_vector", kernels.rotation_from_rotation_vector(w)),
            ("transform_from_exponential_coordinates", T[:, :3, :3])], T


def _consumers(Q, T, rng):
    """Every kernel that takes a rotation (or a transform), fed ``Q`` (``T``)."""
    n = len(Q)
    v = rng.normal(size=(n, 3))
    e = v / np.linalg.norm(v, axis=1, keepdims=True)
    kernels.natural_invariants_from_rotation(Q, on_singular="nan")
    kernels.rotation_vector_from_rotation(Q)
    kernels.euler_rodrigues_from_rotation(Q)
    kernels.screw_of_displacement(Q=Q, a=v, a_prime=v + 1.0, on_singular="nan")
    kernels.moving_frame_acceleration(
        **{a: (Q if a == "Q" else (e if a.startswith("e") else v))
           for a in _arg_names("moving_frame_acceleration")})
    TQ = np.array(T)
    TQ[:, :3, :3] = Q
    kernels.exponential_coordinates_from_transform(TQ)


def _arg_names(name):
    import inspect

    return [p for p in inspect.signature(getattr(kernels, name)).parameters
            if p not in ("out", "check", "on_singular", "threads")]


@settings(max_examples=examples(6), deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_every_rotation_is_accepted_by_every_kernel_that_takes_one(seed):
    """Chain each kernel that returns a rotation into each kernel that takes one (check=True:
    no "not orthogonal" for a rotation a kernel made)."""
    rng = np.random.default_rng(seed)
    prods, T = _producers(rng, 16)
    for _, Q in prods:
        _consumers(np.ascontiguousarray(Q), T, rng)


# ----------------------------------------------------------------------------------------
# one answer per row (item 3)

#: kernels of unconstrained vectors whose singular or overflow sets the rows below reach
ROW_KERNELS = ["rotation_vector_left_jacobian_inverse", "rotation_vector_right_jacobian_inverse",
               "exponential_coordinates_left_jacobian_inverse", "rotation_from_rotation_vector",
               "transform_from_exponential_coordinates", "exponential_coordinates_left_jacobian"]
#: row norms: ordinary, near 2 pi k, zero, tiny, huge (squares overflow: the rescue), past
#: the range of the result (overflow: a flag)
SCALES = [1.0, TWO_PI - 1e-8, TWO_PI - 1e-10, 2 * TWO_PI + 1e-9, 0.0, 1e-300, 1e-160, 1e160,
          1e300, 3.0]


def _rows(rng, n, width):
    d = rng.normal(size=(n, width))
    d[:, :3] /= np.linalg.norm(d[:, :3], axis=1, keepdims=True)
    d[:, :3] *= rng.choice(SCALES, size=(n, 1))
    return d


def _run(name, x, backend, mode):
    """(values, raised indices or None) of ``name`` on the batch ``x``."""
    try:
        return _call(name, x, backend, on_singular=mode), None
    except kernels.SingularConfigurationError as e:
        return None, sorted(int(np.ravel(i)[0]) for i in e.indices)


def _same(a, b) -> bool:
    return bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))


@settings(max_examples=examples(5), deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_one_answer_per_row(seed):
    """A row's value or NaN depends only on that row, the dtype and on_singular: alone or in
    a random batch, C or NumPy; NaN (nan mode) exactly where raise mode raises. Guards against a C
    fast path that keeps its NaN rows in nan mode unless some row has an input of extreme
    magnitude, and re-runs them (a number) in raise mode."""
    rng = np.random.default_rng(seed)
    for name in ROW_KERNELS:
        x = _rows(rng, 8, 3 if name.startswith("rotation") else 6)
        nan_rows = None
        for b in _backends():
            batch, _ = _run(name, x, b, "nan")
            bad = np.isnan(batch.reshape(len(x), -1)).any(axis=1)
            if nan_rows is None:
                nan_rows = bad
            assert np.array_equal(bad, nan_rows), (name, b, x)   # C = NumPy on NaN
            _, raised = _run(name, x, b, "raise")
            assert (raised or []) == list(np.flatnonzero(bad)), (name, b, raised, bad)
            for i in range(len(x)):
                alone, _ = _run(name, x[i:i + 1], b, "nan")
                assert _same(alone[0], batch[i]), (name, b, x[i])
                _, r1 = _run(name, x[i:i + 1], b, "raise")
                assert (r1 is not None) == bool(bad[i]), (name, b, x[i])


def test_20000_rows_near_2pi_k_c_equals_numpy_on_nan():
    """The audit's batch: 20 000 rows at 2 pi k - 10^-j (k = 1, 2, 3, j = 6 .. 15), random
    axes: C and NumPy give NaN in the same rows (none: the half-angle form neither cancels
    nor overflows there) in both modes (a form that cancels makes 804 rows differ in nan mode)."""
    rng = np.random.default_rng(4820)
    n = 20000
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    t = TWO_PI * rng.integers(1, 4, size=n) - 10.0 ** -rng.uniform(6, 15, size=n)
    for name in INVERSES:
        x = d * t[:, None]
        if name.startswith("exponential"):
            x = np.c_[x, rng.normal(size=(n, 3))]
        pats = []
        for b in _backends():
            v, _ = _run(name, x, b, "nan")
            pats.append(np.isnan(v.reshape(n, -1)).any(axis=1))
            _, raised = _run(name, x, b, "raise")
            assert (raised or []) == list(np.flatnonzero(pats[-1])), (name, b)
        assert all(np.array_equal(p, pats[0]) for p in pats), name
        assert not pats[0].any(), (name, int(pats[0].sum()))


# ----------------------------------------------------------------------------------------
# the search's worst points (harness/search.py, item 1), kept as regression
# cases: each was outside the rule where it was found (ratio to the rule there, measured by
# the same judge), C and NumPy

#: (kernel, point, the rule ratio where it was found, float type): c68045c for the
#: first four; d987a31e for the SE(3) Jacobian's and the inverse's at |w| ~ 200 .. 240,
#: where Barfoot's Q cancelled (lie_maps.se3_q_block now writes it without)
SEARCHED = [
    ("rotation_vector_left_jacobian_inverse",
     [[0.005347627677738755, -0.023251940379964108, -6.686345435212432]], 1.12, "float64"),
    ("exponential_coordinates_left_jacobian_inverse",
     [[-0.436380335850562, -3.7931994509065983, -242.45010759734396, 145.3209406391062,
       -0.642034277435111, -17.431943554373824]], 63.4, "float64"),
    ("exponential_coordinates_left_jacobian_inverse",
     [[-0.042496583603165786, 4.689070860700868, -29.4639169419144, 171.10450865151466,
       -0.020737665236134264, -0.8209681803259875]], 285, "float64"),
    ("exponential_coordinates_left_jacobian_inverse",
     [[0.35250768180837566, 192.90000854833602, 3.2318591671716392, 178.91961179455316,
       0.006362471803228915, 69.6997919915548]], 471, "float64"),
    # the slow search's worst points on d987a31e (seeds 1, 0, 0, 0; 512, 592, 760 and
    # 1229 u); 0.30, 0.50, 0.52 and 0.51 of the rule after the rewrite of Q
    ("exponential_coordinates_left_jacobian",
     [[0.08756754816368344, -0.8485405984102032, 206.75740596236682, -167.3256836554757,
       -12.097511157512505, 1.5796770998647207]], 16.9, "float64"),
    ("exponential_coordinates_left_jacobian",
     [[-0.436380335850562, -3.7931994509341997, -242.45010759734396, 145.3209406391061,
       -0.6219707065594166, -17.43300751526504]], 4.06, "float64"),
    ("exponential_coordinates_left_jacobian",
     [[-0.436380335850562, -3.7931994509342033, -242.45010759734396, -145.32107909261197,
       -0.6421129566494134, -17.431949788015302]], 5.07, "float32"),
    ("exponential_coordinates_left_jacobian_inverse",
     [[0.436380335850562, -3.793315210194787, -242.45010759734396, 145.3209406391041,
       -0.6470304241294565, 17.431943554373824]], 1.68, "float64"),
    # the slow search with every peer judging (Pinocchio's exp6 4.4 u,
    # jaxlie 3.8 u; the kernel 16 u, its cloud median 3.7 times theirs) before J_l(w) v was
    # written without its cancellation (lie_maps.rotation_vector_left_jacobian_times)
    ("transform_from_exponential_coordinates",
     [[0.38809818457524436, -13.470552770915118, -10.398374014686407, 120.50548345606701,
       -0.013960675525783684, 13.470253145779274]], 1.83, "float64"),
]


def test_exp_se3_kernel_is_the_declared_formula():
    """The SE(3) exponential's kernel builds ``J_l(w) v`` expanded (``[w]^2 v = w (w.v) -
    theta^2 v``, Pinocchio's form; lie_maps.rotation_vector_left_jacobian_times
    with its products Grouped); equal to ``lie_maps``' formula at random
    rational points to 50 digits, theta from 1e-3 to 40 (an expansion that dropped a term
    is off by O(1) somewhere there)."""
    import importlib

    spec = importlib.import_module("rigidsym.derivations.kernels_spec_lie")
    k = next(k for k in spec.LIE_KERNELS if k.name == "transform_from_exponential_coordinates")
    x = sp.Matrix(sp.symbols("x0:6"))
    got, want = k.build(xi=x)["T"], L.transform_from_exponential_coordinates(x)
    rng = np.random.default_rng(48)
    for scale in (1e-3, 0.5, 3.0, 18.0, 40.0):
        d = rng.standard_normal(6)
        d[:3] *= scale / np.linalg.norm(d[:3])
        sub = {s: sp.Rational(float(v)) for s, v in zip(x, d * [1, 1, 1, 50, 50, 50],
                                                         strict=True)}
        diff = (got.xreplace(sub).doit() - want.xreplace(sub)).evalf(60)  # doit: Grouped
        assert max(abs(e) for e in diff) < sp.Float("1e-45"), scale


def _harness():
    import sys
    from pathlib import Path

    pytest.importorskip("flint")
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    from rigidsym.codegen.accuracy.harness import judge as A

    return A


#: open (measured rule ratio now, C and NumPy): strict, so a fix shows here. (J_l^-1 at
#: |w| = 6.686, 2.39 per point, and the SE(3) inverse at |w| = 242, 1.06, pass since the
#: reference half is decided over a cloud of neighbouring inputs: a yardstick's luck there)
OPEN_SEARCHED: dict[float, str] = {}


@pytest.mark.parametrize("name,point,on_main,dtype", [
    pytest.param(*c, marks=pytest.mark.xfail(strict=True, reason=OPEN_SEARCHED[c[2]]))
    if c[2] in OPEN_SEARCHED else c for c in SEARCHED])
def test_searched_worst_points(name, point, on_main, dtype):
    """Within the harness's rule (both halves) at the search's worst points of main."""
    A = _harness()
    pt = [[A.P.q(x) for x in a] for a in point]
    rows = A.judge(name, "searched", [pt], np.dtype(dtype).type, _backends())
    assert all(r.rule_ratio <= 1 and not r.spurious for r in rows), \
        [(r.backend, r.rule_ratio, on_main) for r in rows]


#: (kernel, dtype) where the slow search below still finds a point past the rule (seeds 0
#: and 1; the reference half decided over a cloud of neighbouring inputs where the point
#: fails it, harness/cloud.py), measured with the [oracles] extra installed
SEARCH_OPEN = {
    ("transform_from_exponential_coordinates", "float32"):
        "C only (NumPy 0.03): the float32 precision plan squares w in float and sums and "
        "roots in double, so theta = |w| carries up to theta u / 2 into sin and cos (in "
        "float32 throughout, sqrt(fl(x^2)) = |x|: the textbook's theta is nearly exact where "
        "one component dominates; cos median 2.9 u against 0.8 u over a cloud at |w| = "
        "24.5): at main's worst point (|w| = 24.5, 1.16 of "
        "the rule) the cloud's medians are 5.4 u (R, absolute) and 7.7 u (p) against the "
        "float32 textbook's 1.7 u and 2.3 u, 1.16 still; the seeds' searches now find 0.56 "
        "and 0.99, seeds 5 and 7 1.3 and 2.7 at |w| = 122, 179 (main: 2.3 at the latter); "
        "J_l(w) v, which lost theta relative there, no longer does"}


@pytest.mark.slow
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("name", INVERSES + ["rotation_vector_left_jacobian",
                                             "rotation_from_rotation_vector",
                                             "transform_from_exponential_coordinates",
                                             "exponential_coordinates_left_jacobian"])
def test_search_finds_nothing_outside_the_rule(name, dtype, request):
    """The Herbie-style search (exponent-uniform starts, hill climbing on the measured rule
    ratio, seeded) finds no point outside the rule for the Lie-group maps (a form that cancels
    gives 471 times the rule in the SE(3) inverse Jacobian, 1.12 in J_l^-1 near 2 pi).

    Where the search still finds a point past the rule (SEARCH_OPEN, the
    float32 C Exp of SE(3), measured), the case is an expected failure naming it, so
    that the search keeps reporting it without failing CI; the list shrinks as the forms
    improve. (A yardstick lucky at one input would fail rotation_from_rotation_vector, ratio
    34 at |w| = 248, and J^-1 1.17 at |w| ~ 56; the cloud of neighbouring inputs sees it
    for what it is.)"""
    if (name, np.dtype(dtype).name) in SEARCH_OPEN:
        request.applymarker(pytest.mark.xfail(
            strict=False, reason="open: the search finds a point past the rule: "
                                 + SEARCH_OPEN[name, np.dtype(dtype).name]))
    _harness()
    from rigidsym.codegen.accuracy.harness import search as S

    for seed in (0, 1):
        ratio, point = S.search(name, dtype, tuple(_backends()), seed=seed, n_start=12,
                                steps=40)
        assert ratio <= 1, (name, np.dtype(dtype).name, seed, ratio,
                            [[float(x) for x in a] for a in point])
