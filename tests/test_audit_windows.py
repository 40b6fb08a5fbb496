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


def _scan(func, seed: int, regime: str = "Q: phi->0") -> V.Window:
    """The approach ``regime`` of the logarithm scanned with ``func`` as the user's."""
    tgt = target(OP)
    k = kernel_of(tgt.kernel)
    m = C.Member(tgt.forms[0], ())
    runner = W.Runner(func, m, k, tgt)

    def judge(pt, reg):
        return W.judge_point(tgt.kernel, reg, pt, np.float64, runner, tgt.antipodal)

    ap = next(a for a in V.approaches(k, seed) if a.regime == regime)
    return V.scan(ap, judge, seed)


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
    assert w.cause().endswith("a threshold branch")


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
