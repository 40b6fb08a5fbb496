"""rigidsym audit writes each window where it is (docs/audit.md, "Windows where they are"):
in the variable the function takes (``|w| = 0.0157``, not ``pi - |w|`` far from pi), found
by a search of every decade and the points between on every approach the operation has
(a scalar angle's and a quaternion's too: a truncated series 1e3 x off at 3e-3, right at
1e-3 and 1e-2, is found on every seed), and a quaternion's sign named where it is the
library's convention (q and -q are the same rotation)."""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("flint")
sys.path.insert(0, str(Path(__file__).resolve().parent))
import audit_noise_examples as N  # noqa: E402

from rigidsym.auditing import audit as A  # noqa: E402
from rigidsym.auditing import conventions as C  # noqa: E402
from rigidsym.auditing import windows as V  # noqa: E402
from rigidsym.auditing import worst as W  # noqa: E402
from rigidsym.auditing.targets import target  # noqa: E402
from rigidsym.codegen.accuracy.harness.reference import kernel_of  # noqa: E402


def _approach(op: str, regime: str, var: str | None = None) -> V.Approach:
    k = kernel_of(target(op).kernel)
    return next(a for a in V.approaches(k, 0) if a.regime == regime
                and (var is None or a.var == var))


def _said(text: str, var: str) -> list[float]:
    return [float(v) for v in re.findall(re.escape(var) + r" = ([0-9.e+-]+)", text)] + [
        float(v) for v in re.findall(r"([0-9.e+-]+) < " + re.escape(var), text)] + [
        float(v) for v in re.findall(re.escape(var) + r" < ([0-9.e+-]+)", text)]


def test_a_window_far_from_pi_is_written_in_w():
    """liegroups' and pypose's Jacobians: a window at |w| ~ 0.016 was written "pi - |w| =
    0.995" (the approach's parameter, (pi - |w|) / pi)."""
    ap = _approach("rotation_vector_right_jacobian", "|w[0:3]| -> pi", "pi - |w|")
    w = V.Window(ap, 1 - 0.016 / math.pi, 40.0, None, lo=1 - 0.02 / math.pi,
                 hi=1 - 0.012 / math.pi)
    text = w.where()
    assert "pi - |w|" not in text
    lo, worst, hi = sorted(_said(text, "|w|"))
    assert abs(lo / 0.012 - 1) < 1e-2 and abs(worst / 0.016 - 1) < 1e-2 \
        and abs(hi / 0.02 - 1) < 1e-2, text
    # near pi, the distance to it, in radians (pi x, not x)
    near = V.Window(ap, 1e-3, 40.0, None, lo=5e-4, hi=2e-3)
    assert sorted(_said(near.where(), "pi - |w|")) == pytest.approx(
        [math.pi * 5e-4, math.pi * 1e-3, math.pi * 2e-3], rel=1e-2), near.where()
    # a jump near the far end is said in |w| too, with its side
    w.jump = (1 - 0.02 / math.pi, 40.0, 0.1)
    assert "at |w| = 0.02 " in w.cause() and "below it is the window's" in w.cause()


def test_every_operation_with_a_singular_set_has_an_approach():
    """A scalar angle and a unit quaternion are searched continuously too (they were swept
    at the decades alone: the window at 3e-3 fell between them)."""
    for op in ("rotation_from_natural_invariants", "rotation_from_euler_rodrigues"):
        assert {a.var for a in V.approaches(kernel_of(target(op).kernel), 0)} >= {
            "|phi|" if "natural" in op else "phi", "pi - |phi|" if "natural" in op
            else "pi - phi"}, op


def _scan(func, op, regime, seed):
    tgt = target(op)
    k = kernel_of(tgt.kernel)
    m = C.Member(tgt.forms[0], ())
    runner = W.Runner(func, m, k, tgt)

    def judge(pt, reg):
        return W.judge_point(tgt.kernel, reg, pt, np.float64, runner, tgt.antipodal)

    def screen(pts, reg):
        return W.screen_points(tgt.kernel, pts, np.float64, runner)

    ap = next(a for a in V.approaches(k, seed) if a.regime == regime)
    return V.scan_all(ap, judge, seed, screen)


@pytest.mark.parametrize("seed", [0, *(pytest.param(k, marks=pytest.mark.slow)
                                      for k in (1, 2, 3))])
def test_a_truncated_series_between_decades_is_found(seed):
    w = _scan(N.rotation_series_between_decades, "rotation_from_natural_invariants",
              "|phi| -> 0", seed)[0]
    # the error (phi^4 / 24 against 8 u (kappa + 1)) peaks at the window's top, 5e-3
    assert w.worst_ratio > 100 and 2.5e-3 < w.worst_x < 1e-2, w.where()
    assert 1e-3 < w.lo <= 2.1e-3 and 4.9e-3 < w.hi < 5.1e-3, w.where()
    # and the correct rotation has no window there
    ok = _scan(N.rotation_from_axis_angle, "rotation_from_natural_invariants",
               "|phi| -> 0", seed)[0]
    assert ok.worst_ratio < W.FIND, ok.where()


def test_a_quaternion_of_the_other_sign_is_named_as_the_convention():
    tgt = target("euler_rodrigues_from_rotation")
    m = C.Member(tgt.forms[0], ())
    said = A._sign_convention(A.as_numpy_callable(N.quaternion_negated), tgt, m, 0)
    assert "-q (r0 <= 0)" in said and "at each of 16" in said
    assert A._sign_convention(A.as_numpy_callable(N.quaternion), tgt, m, 0) == ""

    def mixed(Q):
        q = N.quaternion(Q)
        return q if Q[0, 1] > 0 else -q

    said = A._sign_convention(A.as_numpy_callable(mixed), tgt, m, 0)
    assert re.search(r"at \d+ of 16 ordinary inputs, the book's sign at the others", said)
