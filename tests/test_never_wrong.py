"""Kernels never silently wrong: never worse than the textbook formula, finite in
finite out over the whole floating range, one NaN policy, the same answer on C and NumPy.

Each test names the defect it guards against.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from rigidsym import kernels as K

U64 = 2.0**-53


def _plucker_ref(p1, p2, dps=50):
    """The moment of the line through p1, p2 at the exact float inputs (mpmath, 50 digits)."""
    with mpmath.workdps(dps):
        a = [mpmath.mpf(float(x)) for x in p1]
        b = [mpmath.mpf(float(x)) for x in p2]
        d = [y - x for x, y in zip(a, b, strict=True)]
        n = mpmath.sqrt(sum(x * x for x in d))
        e = [x / n for x in d]
        m = [a[1] * e[2] - a[2] * e[1], a[2] * e[0] - a[0] * e[2], a[0] * e[1] - a[1] * e[0]]
        return np.array([float(x) for x in e]), np.array([float(x) for x in m])


def _rel(got, ref):
    return float(np.abs(got - ref).max() / np.abs(ref).max())


#: two hard cases: a large offset with a small difference, and nearly coincident
#: points near the unit sphere (|p2 - p1| = 2e-9)
_rng = np.random.default_rng(37)
_P = _rng.standard_normal(3)
_P /= np.linalg.norm(_P)
PLUCKER_CASES = [
    (1e6 * np.array([0.3, -0.7, 1.1]), 1e6 * np.array([0.3, -0.7, 1.1])
     + 1e-6 * np.array([0.25, -0.5, 0.75])),
    (_P, _P + 2e-9 * _rng.standard_normal(3) / np.sqrt(3)),
]


@pytest.mark.parametrize("case", range(len(PLUCKER_CASES)))
def test_plucker_nearly_coincident_points(case):
    """The moment within max(2 e_ref, 4 u) of the 50-digit reference, e_ref the textbook
    p1 x (p2 - p1)/||p2 - p1|| in float64; C and NumPy within that of each other.
    Guards against: 8e12 u (C) and 1.9e13 u (NumPy) at the first case, ~1e8 u at the second."""
    p1, p2 = PLUCKER_CASES[case]
    e_ref_true, m_ref = _plucker_ref(p1, p2)
    d = p2 - p1
    textbook = np.cross(p1, d / np.linalg.norm(d))
    allowed = max(2 * _rel(textbook, m_ref), 4 * U64)
    got = {}
    for b in ("numpy", "c"):
        if K.use_backend(b) != b:
            continue
        try:
            kappa = K.plucker_from_points(p1, p2)
        finally:
            K.use_backend("numpy")
        got[b] = kappa
        assert _rel(kappa[3:], m_ref) <= allowed, (b, _rel(kappa[3:], m_ref) / U64)
        assert _rel(kappa[:3], e_ref_true) <= 4 * U64
    if len(got) == 2:
        assert _rel(got["c"][3:], got["numpy"][3:]) <= allowed


def _backends():
    for b in ("numpy", "c"):
        if K.use_backend(b) == b:
            yield b
    K.use_backend("numpy")


def relative_error(got, want):
    got, want = np.asarray(got, dtype=np.float64), np.asarray(want, dtype=np.float64)
    scale = np.abs(want).max()
    return float(np.abs(got - want).max() / scale) if scale else float(np.abs(got).max())


#: kernels with an exact scaling law: (name, inputs(rng), scaled(inputs, s), outputs scaled)
#: scaling by a power of two is exact, so the kernel at the scaled inputs must give the
#: scaled outputs (to its rounding): the truth is representable wherever they are
def _plucker(rng):
    p1 = rng.standard_normal(3)
    return (p1, p1 + rng.standard_normal(3))


SCALING = {
    # e invariant, the moment n linear in the points
    "plucker_from_points": (_plucker, lambda x, s: (x[0] * s, x[1] * s),
                            lambda y, s: np.concatenate([y[:3], y[3:] * s])),
    # omega and a_dot scaled together: the axis (p0, pitch, Plücker array) is unchanged
    "instant_screw_axis": (lambda rng: tuple(rng.standard_normal((3, 3))),
                           lambda x, s: (x[0] * s, x[1], x[2] * s), lambda y, s: y),
    # the wrench scaled: its axis is unchanged
    "wrench_axis": (lambda rng: (rng.standard_normal(6), rng.standard_normal(3)),
                    lambda x, s: (x[0] * s, x[1]), lambda y, s: y),
}
EXPONENTS = {np.float64: [-990, -700, -520, -300, 300, 512, 515, 700, 990],
             np.float32: [-110, -90, -64, -40, 40, 64, 90, 110]}


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("name", sorted(SCALING))
def test_finite_in_finite_out(name, dtype):
    """Inputs from 1e-300 to 1e300 (float64; 1e-35 to 1e35 float32) whose result is
    representable: the result, never NonFiniteResultError nor a finite wrong value, on C
    and NumPy, with check=True and check=False alike. Guards against: plucker_from_points at
    |p| = 1e155 and instant_screw_axis at |omega| = 7.5e154 raised NonFiniteResultError;
    with check=False NumPy returned e = [-0, 0, -0], C NaN; float32 plucker_from_points at
    |p| = 1e20 failed on C."""
    make, scale_in, scale_out = SCALING[name]
    f = getattr(K, name)
    u = np.finfo(dtype).eps / 2
    rng = np.random.default_rng(7)
    for _ in range(3):
        x = tuple(np.asarray(a, dtype=dtype) for a in make(rng))
        for b in _backends():
            K.use_backend(b)
            y = f(*x)
            y = np.concatenate([np.ravel(v) for v in (y if isinstance(y, tuple) else (y,))])
            for k in EXPONENTS[dtype]:
                s = dtype(2.0) ** k if abs(k) < 120 else np.ldexp(dtype(1.0), k)
                xs = tuple(np.asarray(a, dtype=dtype) for a in scale_in(x, s))
                for check in (True, False):
                    got = f(*xs, check=check)
                    got = np.concatenate([np.ravel(v) for v in
                                          (got if isinstance(got, tuple) else (got,))])
                    want = scale_out(y, s)
                    assert np.isfinite(got).all(), (b, k, check, got)
                    assert relative_error(got, want) <= 16 * u, (b, k, check, got, want)
    K.use_backend("numpy")


def test_huge_but_finite_inputs_give_finite_results():
    """plucker_from_points at |p| = 1e155 and instant_screw_axis at |omega| = 7.5e154, as a
    user types them: finite results."""
    p1 = np.array([0.3, -0.7, 1.1]) * 1e155
    omega = np.array([0.6, 0.0, 0.8]) * 7.5e154
    for b in _backends():
        K.use_backend(b)
        for check in (True, False):
            kappa = K.plucker_from_points(p1, 2 * p1 + 1e154, check=check)
            assert np.isfinite(kappa).all() and abs(np.linalg.norm(kappa[:3]) - 1) < 1e-15
            p0, pitch, pl = K.instant_screw_axis(omega, [1.0, 2.0, 3.0], [0.0, 1e155, 0.0],
                                                 check=check)
            assert np.allclose(pl[:3], [0.6, 0.0, 0.8], rtol=0, atol=1e-15), (b, check, pl)
            kappa32 = K.plucker_from_points(np.float32([1e20, 2e20, -3e20]),
                                            np.float32([2e20, 1e20, -1e20]), check=check)
            assert np.isfinite(kappa32).all(), (b, check, kappa32)
    K.use_backend("numpy")


def _specs():
    from rigidsym.derivations.kernels_spec import KERNELS

    return {k.name: k for k in KERNELS}


_SPECS = _specs()


def _nan_cases():
    from test_kernels_props import KERNELS, valid  # the table of every public kernel

    return KERNELS, valid


@pytest.mark.sample
@pytest.mark.parametrize("name", sorted(_nan_cases()[0]))
def test_one_nan_policy(name):
    """check=False, a NaN (or inf) in one input component: NaN in exactly the outputs that
    depend on it (an output array some component of which a perturbation of it moves: the
    moved components are NaN, the others NaN or as with the clean input; a component can
    hold the input with a coefficient that is zero in value, as the moment of an axis does)
    and every other output as with the clean input (to rounding: the sample is re-run in
    long double); the same NaN positions on C and NumPy; check=True keeps its ValueError.
    Guards against: C wrote NaN in the whole row, NumPy a finite e beside a NaN phi, and an inf
    input gave finite limits (e = f/||f|| = [0, 0, 1])."""
    table, valid = _nan_cases()
    call, specs = table[name]
    rng = np.random.default_rng(4)
    x = {s["name"]: valid(s, (), rng) for s in specs}
    branched = bool(_SPECS[name].branches) if name in _SPECS else False
    seen = {}
    for b in _backends():
        K.use_backend(b)
        outs = _outs(call(**x, check=False))
        clean = np.concatenate([np.ravel(v) for v in outs])
        owner = np.concatenate([np.full(v.size, j) for j, v in enumerate(outs)])
        for s in specs:
            for i in range(int(np.prod(s["tshape"], dtype=int))):
                a = np.array(x[s["name"]], dtype=float)
                a.flat[i] += 1e-3 * (1 + abs(a.flat[i]))
                moved = np.concatenate([np.ravel(v) for v in
                                        _outs(call(**{**x, s["name"]: a}, check=False))])
                moved = moved != clean
                dep = np.isin(owner, np.unique(owner[moved]))     # whole output arrays
                for bad in (np.nan, np.inf):
                    a = np.array(x[s["name"]], dtype=float)
                    a.flat[i] = bad
                    got = np.concatenate([np.ravel(v) for v in _outs(
                        call(**{**x, s["name"]: a}, check=False))])
                    label = (b, s["name"], i, bad)
                    assert np.isnan(got[moved]).all(), (label, got, moved)
                    same = np.abs(got - clean) <= 8 * U64 * np.abs(clean).max()
                    assert (same | np.isnan(got))[dep].all(), (label, got, clean)
                    # a NaN in an input of a branch condition leaves the branch unknown:
                    # NaN allowed in every output of a branched kernel (the log of SO(3)
                    # below pi/4 reads no diagonal entry, but its condition reads tr Q)
                    assert (same | (np.isnan(got) & branched))[~dep].all(), (
                        label, got, clean)
                    seen.setdefault((s["name"], i, bad), []).append(np.isnan(got))
                    with pytest.raises(ValueError, match=f"^{s['name']}: non-finite"):
                        call(**{**x, s["name"]: a})
    K.use_backend("numpy")
    for key, masks in seen.items():
        assert all(np.array_equal(masks[0], m) for m in masks), (key, masks)


def _outs(res):
    return [np.asarray(r) for r in (res if isinstance(res, tuple) else (res,))]


@pytest.mark.sample
@pytest.mark.filterwarnings("ignore:rigidsym.kernels. the NumPy backend runs on one thread")
@pytest.mark.parametrize("name", sorted(_nan_cases()[0]))
def test_check_false_is_check_true_on_valid_input(name):
    """check=False only skips validation: on valid input (a batch above MIN_PARALLEL, with
    rows of extreme magnitude) it returns what check=True returns, bit for bit, with out=
    and threads=2 too, on C and NumPy. Guards against: an overflowing row was NaN with check=True
    and on_singular="nan" but its IEEE values (e = [-0, 0, -0]) with check=False."""
    table, valid = _nan_cases()
    call, specs = table[name]
    rng = np.random.default_rng(11)
    n = 20000
    x = {s["name"]: valid(s, (n,), rng) for s in specs}
    for s in specs:                     # rows of extreme magnitude in the free arguments
        if s["kind"] == "any" and s["name"] not in ("angles", "m", "I_C"):
            x[s["name"]][:8] *= np.ldexp(1.0, 500) if s is specs[0] else np.ldexp(1.0, -500)
    nan = {} if name == "euler_rate_matrix" else {"on_singular": "nan"}   # never singular
    for b in _backends():
        K.use_backend(b)
        want = _outs(call(**x, **nan))
        for kw in ({}, {"threads": 2}):
            got = _outs(call(**x, check=False, **nan, **kw))
            for g, w in zip(got, want, strict=True):
                np.testing.assert_array_equal(g, w, err_msg=f"{b} {kw}")
        outs = tuple(np.empty_like(w) for w in want)
        got = call(**x, check=False, **nan, threads=2, out=outs if len(outs) > 1 else outs[0])
        for g, w in zip(_outs(got), want, strict=True):
            np.testing.assert_array_equal(g, w, err_msg=f"{b} out=")
    K.use_backend("numpy")
