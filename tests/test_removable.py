"""Removable singularities: the series and certificates of
codegen.removable.series, the rewrite of codegen.removable.singularities, and the generated
Lie-group kernels at |w| in {0, 1e-12, 1e-8, 1e-4, 1e-2, 1} against a 50-digit mpmath
reference.

Without the pass a reader's exponential map returns NaN (or raises) at w = 0 and its
Jacobian is 3.7e-9 off at |w| = 1e-8.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from rigidsym.codegen.removable.series import (
    WIDE_SERIES,
    NotRemovable,
    S,
    certify,
    series_of,
)
from rigidsym.codegen.removable.singularities import QuotientBase, rewrite

pytestmark = pytest.mark.xdist_group("removable")  # its module fixtures built on one worker

U = 2.0**-53
NORMS = [0.0, 1e-12, 1e-8, 1e-4, 1e-2, 1.0]


def test_series_exact_and_even():
    # sin s / s = 1 - t/6 + t^2/120 - ...; (1 - cos s)/s^2 = 1/2 - t/24 + ...
    assert series_of(sp.sin(S) / S).coeffs[:3] == (1, Fraction(-1, 6), Fraction(1, 120))
    assert series_of((1 - sp.cos(S)) / S**2).coeffs[:2] == (Fraction(1, 2), Fraction(-1, 24))
    c = series_of((S * sp.cos(S) - sp.sin(S)) / S**3).coeffs
    assert c[:2] == (Fraction(-1, 3), Fraction(1, 30))


def test_series_of_a_root():
    # the SE(3) log's g(s) = c(t) (t/s)^2 with s = sin t (c the inverse Jacobian's
    # coefficient 1/12 + t^2/720 + ..., t^2/s^2 = 1 + s^2/3 + ...): 1/12 + 7 s^2/240 + ...
    g = (2 * S - sp.asin(S) * (1 + sp.sqrt(1 - S**2))) / (2 * S**3)
    ser = series_of(g)
    assert ser.coeffs[:2] == (Fraction(1, 12), Fraction(7, 240)) and ser.rho == 0.5


@pytest.mark.parametrize("h", [sp.sin(S) / S**2, sp.cos(S) / S**2, sp.sin(S)])
def test_no_limit_or_odd_is_refused(h):
    with pytest.raises(NotRemovable):
        series_of(h)


@pytest.mark.parametrize("h", [sp.sin(S) / S, (1 - sp.cos(S)) / S**2,
                               pytest.param((S - sp.sin(S)) / S**3, marks=pytest.mark.slow),
                               pytest.param((S * sp.cos(S) - sp.sin(S)) / S**3,
                                            marks=pytest.mark.slow)])
def test_certificate_within_2u_and_checked_by_mpmath(h):
    cert = certify(h)
    # within 2u; within WIDE_SERIES where the switch moved up past a closed form that was
    # past WIDE_CLOSED at the first one ((s cos s - sin s)/s^3: 42 u at 1/2, 22 u at 1)
    assert cert.taylor64 <= (2 if h != (S * sp.cos(S) - sp.sin(S)) / S**3 else WIDE_SERIES)
    _horner_within(h, cert, max(2, cert.taylor64), 41)


def _horner_within(h, cert, bound: float, points: int) -> None:
    """The float64 Horner series against 50 digits on [0, t*]: within ``bound`` u."""
    cs = [float(c) for c in series_of(h).coeffs[:cert.order + 1]]
    f = sp.lambdify(S, h, "mpmath")
    mp.mp.dps = 50
    for t in np.linspace(0, cert.threshold, points)[1:]:
        p = 0.0
        for c in reversed(cs):
            p = c + t * p
        ref = f(mp.sqrt(mp.mpf(float(t))))
        assert abs(p - ref) <= bound * U * abs(ref), (t, p, ref)


@pytest.mark.slow
def test_a_derivative_quotient_switches_where_its_closed_form_is_accurate():
    """the derivative quotient (s cos s + 2 s - 3 sin s) / s^5 switches at 4, its series
    within 2.5 u there, checked against 50 digits: switched at t* = 2, where its closed form
    cancels (181 u bound), the SE(3) left Jacobian's Jacobian would be 9 u at |w|^2 just
    above 2, the textbook 3 u."""
    h = (S * sp.cos(S) + 2 * S - 3 * sp.sin(S)) / S**5
    cert = certify(h)
    assert cert.threshold == 4.0 and cert.closed64 < 64 and cert.taylor64 <= 2.5
    _horner_within(h, cert, cert.taylor64, 17)
    # a quotient whose closed form is good enough keeps its switch (sin s / s, (1-cos)/s^2)
    assert certify((1 - sp.cos(S)) / S**2).threshold == 1.0


def test_rewrite_finds_the_quotients_of_a_derivative():
    w = sp.Matrix(sp.symbols("w0:3", real=True))
    th = sp.sqrt((w.T * w)[0])
    e = sp.sin(th) / th * w[2]
    out = rewrite([sp.diff(e, w[0])])[0]
    assert not out.has(sp.sqrt(th**2)) and out.atoms(QuotientBase)
    # an output whose quotient has no limit is left as it was
    bad = sp.cos(th) / th**2
    assert rewrite([bad])[0] == bad


def _ref(fn, x):
    """The formula to 50 digits; at 0 the limit through a point 1e-30 away (the working
    precision grows with the cancellation in its quotients, 6 digits per decade of |w|)."""
    x = [mp.mpf(v) for v in x]
    if all(v == 0 for v in x):
        x = [mp.mpf("1e-30"), mp.mpf("2e-30"), mp.mpf("-1e-30")] + x[3:]
    mp.mp.dps = 60 + 6 * max(0, int(-mp.log10(max(abs(v) for v in x[:3]))) + 1)
    return fn(x)


@pytest.fixture(scope="module")
def maps():
    from rigidsym.derivations import lie_maps as L

    w = sp.Matrix(sp.symbols("w0:3", real=True))
    out = {}
    for name in ("rotation_from_rotation_vector", "rotation_vector_left_jacobian",
                 "rotation_vector_right_jacobian", "rotation_vector_left_jacobian_inverse"):
        M = getattr(L, name)(w)
        val = sp.lambdify(list(w), M, "mpmath")
        jac = sp.lambdify(list(w), sp.Matrix([[sp.diff(x, v) for v in w] for x in M]),
                          "mpmath")
        out[name] = (lambda x, f=val: f(*x), lambda x, f=jac: f(*x))
    return out


@pytest.mark.sample(fraction=0.5)
@pytest.mark.parametrize("name", ["rotation_from_rotation_vector",
                                  "rotation_vector_left_jacobian",
                                  "rotation_vector_right_jacobian",
                                  "rotation_vector_left_jacobian_inverse"])
def test_lie_kernels_smooth_at_zero(maps, name):
    from rigidsym import kernels

    fv, fj = maps[name]
    rng = np.random.default_rng(7)
    d = rng.normal(size=3)
    d /= np.linalg.norm(d)
    ws = np.array([n * d for n in NORMS])
    kv = getattr(kernels, name)(w=ws)
    kj = kernels.jacobian(name)(w=ws)
    val = kv if isinstance(kv, np.ndarray) else kv[0]
    for i, w in enumerate(ws):
        ref = np.array(mp.matrix(_ref(fv, w)).tolist(), dtype=float)
        assert np.all(np.isfinite(val[i]))
        np.testing.assert_array_less(np.abs(val[i] - ref), 4 * U * np.abs(ref).max() + 1e-300)
        jr = np.array(mp.matrix(_ref(fj, w)).tolist(), dtype=float).reshape(3, 3, 3)
        (out,) = kj[1]                     # (values, {output: {argument: jacobian}})
        got = np.asarray(kj[1][out]["w"][i]).reshape(3, 3, 3)
        assert np.all(np.isfinite(got))
        scale = np.abs(jr).max() + np.abs(ref).max()
        assert np.abs(got - jr).max() <= 8 * U * scale * 4, (name, w, np.abs(got - jr).max())


_READER = '''
"""A reader's exponential map, written as Angeles writes Rodrigues' formula in w = phi e:
Q = cos(t) 1 + (sin t / t) [w] + ((1 - cos t) / t^2) w w^T, t = |w|; and the derivative
of sin t / t along w, with its own quotient (t cos t - sin t) / t^3."""
import sympy as sp
from rigidsym.codegen.spec import Arg, Kernel, Out


def exp_reader(w):
    t = sp.sqrt((w.T * w)[0])
    W = sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    return sp.cos(t) * sp.eye(3) + sp.sin(t) / t * W + (1 - sp.cos(t)) / t**2 * w * w.T


def dsinc_reader(w):
    t = sp.sqrt((w.T * w)[0])
    return (t * sp.cos(t) - sp.sin(t)) / t**3 * w


KERNELS = [
    Kernel(name="exp_reader", summary="A reader's exp.", formula="Rodrigues in w",
           ids=(), sources=("exp_reader",), args=(Arg("w", (3,), "any", "rotation vector"),),
           outputs=(Out("Q", (3, 3), "rotation"),), build=lambda w: {"Q": exp_reader(w)}),
    Kernel(name="dsinc_reader", summary="d sinc.", formula="(t cos t - sin t)/t^3 w",
           ids=(), sources=("dsinc_reader",), args=(Arg("w", (3,), "any", "vector"),),
           outputs=(Out("g", (3,), ""),), build=lambda w: {"g": dsinc_reader(w)}),
]
'''


@pytest.mark.slow
def test_a_readers_exp_map_is_smooth_at_zero(tmp_path):
    import subprocess
    import sys

    from rigidsym import kernels

    (tmp_path / "reader_exp.py").write_text(_READER)
    out = tmp_path / "gen"
    r = subprocess.run([sys.executable, "-m", "rigidsym", "generate", "--module",
                        str(tmp_path / "reader_exp.py"), "--out", str(out), "--no-build"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    ns = kernels.load(out)
    d = np.array([0.6, -0.48, 0.64])
    for n in NORMS:
        w = n * d
        Q = ns.exp_reader(w=w)
        ref = np.eye(3) if n == 0 else _np_exp(w)
        assert np.all(np.isfinite(Q)) and np.abs(Q - ref).max() <= 4 * U
        J = ns.jacobian("exp_reader")(w=w) if hasattr(ns, "jacobian") else None
        if J is not None:
            assert np.all(np.isfinite(np.asarray(J[-1])))
        g = ns.dsinc_reader(w=w)
        assert np.all(np.isfinite(g))
        mp.mp.dps = 50
        t = mp.sqrt(sum(mp.mpf(float(x)) ** 2 for x in w))
        c = mp.mpf(-1) / 3 if n == 0 else (t * mp.cos(t) - mp.sin(t)) / t**3
        np.testing.assert_allclose(g, [float(c * mp.mpf(float(x))) for x in w],
                                   rtol=4 * U, atol=1e-300)


def _np_exp(w):
    mp.mp.dps = 50
    W = mp.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    return np.array(mp.expm(W).tolist(), dtype=float)


def test_a_quotient_call_pickles():
    # the generator's worker pool sends programs back pickled; the classes are made at run
    # time (found by `rigidsym generate --module` of the Lie kernels: PicklingError)
    import pickle

    from rigidsym.codegen.removable.singularities import quotient

    t = sp.Symbol("t")
    e = 2 * quotient(sp.sin(S) / S)(t) + quotient((1 - sp.cos(S)) / S**2)(t + 1)
    assert pickle.loads(pickle.dumps(e)) == e
