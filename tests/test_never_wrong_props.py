"""Property-based tests of the accuracy rule: Hypothesis strategies for the regimes a user
meets with two points (nearly coincident points, |p2 - p1|/|p| from 1e-1 to 1e-12; a large
offset with a small difference; magnitudes from 1e-300 to 1e300), driving the rule "never
worse than the textbook formula" (error <= max(2 e_ref, 4 u) against a 50-digit
reference, e_ref the textbook formula's error in float64) and the agreement of C and NumPy.

The quick profile is derandomized (the README's test command); the ``slow`` one draws many
more examples.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym import kernels as K

U64 = 2.0**-53


@st.composite
def two_points(draw, max_exp: int = 150):
    """(p1, p2): a random direction at 10^k, and p2 = p1 + 10^(k - j) r (j = 0: points far
    apart; j up to 12: nearly coincident, the hard regime)."""
    k = draw(st.integers(-max_exp, max_exp))
    j = draw(st.integers(0, 12))
    f = st.floats(-1.0, 1.0, allow_nan=False).filter(lambda x: abs(x) > 1e-3)
    u = np.array([draw(f) for _ in range(3)])
    r = np.array([draw(f) for _ in range(3)])
    p1 = u * 10.0**k
    return p1, p1 + r * 10.0 ** (k - j)


def _ref_moment(p1, p2):
    with mpmath.workdps(50):
        a = [mpmath.mpf(float(x)) for x in p1]
        b = [mpmath.mpf(float(x)) for x in p2]
        d = [y - x for x, y in zip(a, b, strict=True)]
        n = mpmath.sqrt(sum(x * x for x in d))
        m = [a[1] * d[2] - a[2] * d[1], a[2] * d[0] - a[0] * d[2], a[0] * d[1] - a[1] * d[0]]
        return np.array([float(x / n) for x in m])


def _err(got, ref):
    return float(np.abs(got - ref).max() / np.abs(ref).max())


def _check_points(p1, p2):
    if np.array_equal(p1, p2):
        return
    ref = _ref_moment(p1, p2)
    if not np.abs(ref).max() > 0:
        return
    d = p2 - p1
    with np.errstate(all="ignore"):
        textbook = np.cross(p1, d / np.linalg.norm(d))
    e_ref = _err(textbook, ref) if np.isfinite(textbook).all() else np.inf
    allowed = max(2 * e_ref, 4 * U64)
    got = {}
    for b in ("numpy", "c"):
        if K.use_backend(b) != b:
            continue
        try:
            got[b] = K.plucker_from_points(p1, p2)[3:]
        finally:
            K.use_backend("numpy")
        assert _err(got[b], ref) <= allowed, (b, p1, p2, _err(got[b], ref) / U64, e_ref / U64)
    if len(got) == 2:
        assert _err(got["c"], got["numpy"]) <= allowed


@settings(max_examples=examples(60), deadline=None, derandomize=True)
@given(two_points())
def test_plucker_never_worse_than_textbook(pts):
    _check_points(*pts)


@settings(max_examples=examples(40), deadline=None, derandomize=True)
@given(two_points(max_exp=300))
def test_plucker_finite_over_the_range(pts):
    """1e-300..1e300: the moment is representable (|n| <= |p1|), so never an error and
    never a non-finite or wrong value: within 8 u of the reference (no textbook rule here:
    the textbook overflows or underflows)."""
    p1, p2 = pts
    if np.array_equal(p1, p2):
        return
    ref = _ref_moment(p1, p2)
    for b in ("numpy", "c"):
        if K.use_backend(b) != b:
            continue
        try:
            got = K.plucker_from_points(p1, p2, check=False)
        finally:
            K.use_backend("numpy")
        assert np.isfinite(got).all(), (b, p1, p2, got)
        if np.abs(ref).max() > 1e-290:           # a normal result, not gradual underflow
            assert _err(got[3:], ref) <= 8 * U64, \
                (b, p1, p2, _err(got[3:], ref) / U64)


@pytest.mark.xfail(strict=True, reason=(
    "open: found by a new search of test_plucker_long_profile: the moment of "
    "plucker_from_points 4.23 u off (C and NumPy alike) where the textbook is 1.41 u, past "
    "the rule's floor of 4 u by 6 % (docs/accuracy.md)"))
def test_plucker_point_past_the_rule():
    """The point a random search found past max(2 e_ref, 4 u); strict: the day the kernel
    is within the rule there, this fails and the entry goes."""
    p1 = np.array([float.fromhex(x) for x in ("-0x1.6000c4cce803dp-6", "-0x1.ae52be4203640p-1",
                                              "0x1.0000000000000p-1")])
    p2 = np.array([float.fromhex(x) for x in ("-0x1.4c7bb16d9d692p-1", "-0x1.86883427b0b7ep-1",
                                              "0x1.cafb2b3099bd2p-1")])
    _check_points(p1, p2)


@pytest.mark.slow
@settings(max_examples=3000, deadline=None)
@given(two_points(max_exp=300))
def test_plucker_long_profile(pts):
    p1, p2 = pts
    if max(np.abs(p1).max(), np.abs(p2).max()) < 1e150:
        _check_points(p1, p2)
    test_plucker_finite_over_the_range.hypothesis.inner_test(pts)
