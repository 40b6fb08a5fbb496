"""rigidsym audit searches each approach to a singular set continuously: a window of error
between two decades (a truncated series used on 1e-3 < phi < 2.3e-3) is found on every
seed, with its upper end located to within 1 % as the threshold it is; a planted window of
any width >= 2x anywhere in [1e-14, 1] is found; the cause is said only where the error
jumps, else "cause not determined". Each scan judges about a hundred inputs."""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("flint")
sys.path.insert(0, str(Path(__file__).resolve().parent))
import audit_examples as X  # noqa: E402
from _profile import examples  # noqa: E402

from rigidsym.auditing import conventions as C  # noqa: E402
from rigidsym.auditing import windows as V  # noqa: E402
from rigidsym.auditing import worst as W  # noqa: E402
from rigidsym.auditing.targets import target  # noqa: E402
from rigidsym.codegen.accuracy.harness.reference import kernel_of  # noqa: E402

OP = "rotation_vector_from_rotation"


def _scan_all(func, seed: int, regime: str = "Q: phi->0") -> list[V.Window]:
    """The approach ``regime`` of the logarithm scanned with ``func`` as the user's, as the
    audit scans it (the lattice screened against rigidsym's kernel): every window."""
    tgt = target(OP)
    k = kernel_of(tgt.kernel)
    m = C.Member(tgt.forms[0], ())
    runner = W.Runner(func, m, k, tgt)

    def judge(pt, reg):
        return W.judge_point(tgt.kernel, reg, pt, np.float64, runner, tgt.antipodal)

    def screen(pts, reg):
        return W.screen_points(tgt.kernel, pts, np.float64, runner)

    ap = next(a for a in V.approaches(k, seed) if a.regime == regime)
    return V.scan_all(ap, judge, seed, screen)


def _scan(func, seed: int, regime: str = "Q: phi->0") -> V.Window:
    """The worst window of :func:`_scan_all`."""
    return _scan_all(func, seed, regime)[0]


def _phi(Q) -> float:
    s = np.linalg.norm(X.vee(Q))
    return math.atan2(s, (np.trace(Q) - 1) / 2)


def _planted(lo: float, hi: float):
    """The correct logarithm, off by 1e-6 (relative) where lo < pi - phi < hi: toward a
    half turn the logarithm's condition number is about 1, so that 1e-6 is past the bound
    everywhere (toward 0 it is 1/phi, and the bound at phi = 1e-13 is 1e-3). The window
    starts at 1e-14 or above: pi - phi of a rounded Q is known to about 2e-16, a tenth of
    a window at 1e-15."""
    def f(Q):
        w = X.log_atan2(Q)
        return w * (1 + 1e-6) if lo < math.pi - _phi(Q) < hi else w
    return f


@pytest.mark.parametrize("seed", range(6))
def test_the_truncated_series_window_between_decades_is_found_on_every_seed(seed):
    w = _scan(X.log_series_window, seed)
    assert w.worst_ratio > 1 and 1e-3 < w.worst_x < 2.3e-3 * 1.01, (w.worst_x, w.where())
    assert w.lo is not None and w.hi is not None and w.lo < w.hi
    assert w.evaluations <= 150
    # its upper end is the series' threshold, a jump located to within 1 %
    assert w.jump is not None and abs(w.jump[0] / 2.3e-3 - 1) < 0.01, w.cause()
    said = re.search(r"at phi = ([0-9.e+-]+) \(located to within 1 %", w.cause())
    assert said and abs(float(said.group(1)) / 2.3e-3 - 1) < 0.01, w.cause()
    assert "a threshold branch" in w.cause()
    # the series' error, phi^4 / 36 relative, over a bound 8 u (kappa + 1) with kappa ~ 1/phi
    # grows as phi^5 over the window: the slope measured on its samples
    assert w.slope is not None and 4.5 < w.slope < 5.5, w.slope


def test_a_correct_function_has_no_window_and_no_cause():
    w = _scan(X.log_atan2, 0)
    assert w.worst_ratio <= 1 and w.lo is None and w.cause() == "cause not determined"


def test_a_smooth_loss_has_no_threshold_named():
    """An error that grows smoothly (the arccos logarithm near a half turn) gets a window
    and a measured slope, not a threshold."""
    w = _scan(X.log_arccos, 0, "Q: phi->pi-")
    assert w.worst_ratio > 1 and w.jump is None
    assert "cause not determined" in w.cause()


def _inside(w: V.Window, lo: float, hi: float) -> bool:
    """The worst input, as rounded to float64, is inside the planted window as the planted
    function itself measures it (its pi - phi, computed from the rounded Q)."""
    _, rounded = W.truth_at(target(OP).kernel, w.worst.point, np.float64)
    return lo < math.pi - _phi(np.asarray(rounded[0]).reshape(3, 3)) < hi


@settings(max_examples=examples(2))
@given(centre=st.floats(-14, -0.31), width=st.floats(math.log10(2), 1.0))
def test_a_planted_window_anywhere_is_found(centre, width):
    lo = 10.0 ** centre
    hi = min(lo * 10.0 ** width, 1.0)
    w = _scan(_planted(lo, hi), 0, "Q: phi->pi-")
    assert w.worst_ratio > 1 and _inside(w, lo, hi), (lo, hi, w.where())


@pytest.mark.slow
@settings(max_examples=40)
@given(centre=st.floats(-14, -0.31), width=st.floats(math.log10(2), 1.0),
       seed=st.integers(0, 1000))
def test_a_planted_window_anywhere_is_found_on_any_seed(centre, width, seed):
    lo = 10.0 ** centre
    hi = min(lo * 10.0 ** width, 1.0)
    w = _scan(_planted(lo, hi), seed, "Q: phi->pi-")
    assert w.worst_ratio > 1 and _inside(w, lo, hi), (lo, hi, w.where())


def _phi_rounded(w: V.Window) -> float:
    """phi of the worst input as rounded to float64 (as the user's function sees it)."""
    _, rounded = W.truth_at(target(OP).kernel, w.worst.point, np.float64)
    return _phi(np.asarray(rounded[0]).reshape(3, 3))


def _two_windows(Q):
    """The arccos window on 1e-3 < phi < 2.3e-3 and, past it on the same approach, a
    larger one: a relative error of 1e-9 on 1e-2 < phi < 3e-2 (about 1e4 x the bound)."""
    w = X.log_arccos_window(Q)
    return w * (1 + 1e-9) if 1e-2 < _phi(Q) < 3e-2 else w


@pytest.mark.parametrize("seed", [0, pytest.param(1, marks=pytest.mark.slow),
                                  pytest.param(2, marks=pytest.mark.slow)])
def test_a_window_beside_a_larger_one_is_found_with_its_ends(seed):
    """Each window of an approach is refined and reported, not the worst alone: the arccos
    window (its error ~ u / (8 u phi), 10 to 150 x the bound) beside a larger one."""
    ws = [w for w in _scan_all(_two_windows, seed) if w.worst_ratio > 1]
    assert len(ws) == 2, [w.where() for w in ws]
    big, small = ws
    assert 1e-2 / 1.05 < big.lo < big.hi < 3e-2 * 1.05 and big.worst_ratio > 1e3
    assert 1e-3 / 1.05 < small.lo < small.hi < 2.3e-3 * 1.05, small.where()
    assert small.hi / small.lo > 2.3 / 1.2 and 1e-3 < _phi_rounded(small) < 2.3e-3
    assert 10 < small.worst_ratio < 1e3


def _planted_near_0(lo: float, hi: float):
    """The correct logarithm where lo < phi < hi off by 100 times the bound 8 u (kappa + 1)
    (toward 0 kappa ~ 1/phi: a relative 100 * 8 u (1 + 1/phi), 89 at phi = 1e-15), exact
    elsewhere."""
    u = 2.0**-53

    def f(Q):
        w, phi = X.log_atan2(Q), _phi(Q)
        return w * (1 + 100 * 8 * u * (1 + 1 / phi)) if lo < phi < hi else w
    return f


def _found(lo: float, hi: float, seed: int) -> None:
    """The planted window is the worst window found on ``Q: phi->0``: its ends within a
    factor 2 of the planted ones, its worst inside it."""
    ws = [w for w in _scan_all(_planted_near_0(lo, hi), seed) if w.worst_ratio > 1]
    assert len(ws) == 1, (lo, hi, [w.where() for w in ws])
    w = ws[0]
    assert lo / 2 <= w.lo and w.hi <= hi * 2, (lo, hi, w.where())
    assert w.lo <= lo * 2 and hi / 2 <= w.hi, (lo, hi, w.where())
    assert lo < _phi_rounded(w) < hi and w.lo <= w.worst_x <= w.hi, (lo, hi, w.where())


@settings(max_examples=examples(2), deadline=None)
@given(width=st.floats(math.log10(2), 3.0), at=st.floats(0.0, 1.0))
def test_a_planted_window_near_0_is_found_with_its_ends(width, at):
    """A window [a, W a], W >= 2, a log-uniform in [1e-15, 1 / W]: found, its ends within a
    factor 2, its worst inside (seed 0; every seed in the slow run)."""
    lo = 10.0 ** (-15 + at * (15 - width))
    _found(lo, lo * 10.0 ** width, 0)


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(width=st.floats(math.log10(2), 3.0), at=st.floats(0.0, 1.0),
       seed=st.integers(0, 1000))
def test_a_planted_window_near_0_is_found_with_its_ends_on_any_seed(width, at, seed):
    lo = 10.0 ** (-15 + at * (15 - width))
    _found(lo, lo * 10.0 ** width, seed)
