"""The elementary functions of the generator's measurements and of the rule's textbook
yardstick (rigidsym.codegen.accuracy.elementary): correctly rounded, the C99 special values,
NumPy's dtypes, and never NumPy's per-CPU loops, which made generation depend on the machine.

The second evaluator is mpmath at 300 bits (its own code, not Arb's), rounded once.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from flint import ctx

from rigidsym.codegen.accuracy import elementary as E


def _exact(f, *args) -> float:
    with mpmath.workprec(300):
        v = f(*[mpmath.mpf(a) for a in args])
        return float(v)     # mpf -> float rounds to nearest, ties to even


def _arguments(rng, n):
    """Ordinary, tiny and huge magnitudes of both signs (huge: argument reduction)."""
    mag = np.concatenate([rng.uniform(-8, 8, n), rng.uniform(-1, 1, n) * 1e-9,
                          rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-300, 300, n)])
    return mag


@pytest.mark.parametrize(("name", "ref"), [("sin", mpmath.sin), ("cos", mpmath.cos),
                                           ("tan", mpmath.tan)])
def test_trigonometric_values_are_correctly_rounded(name, ref):
    x = _arguments(np.random.default_rng(7), 300)
    got = getattr(E, name)(x)
    bad = [(a, g) for a, g in zip(x.tolist(), got.tolist(), strict=True) if g != _exact(ref, a)]
    assert not bad, f"{name}: {len(bad)} not correctly rounded, e.g. {bad[:3]}"


def test_inverse_functions_and_pow_are_correctly_rounded():
    rng = np.random.default_rng(8)
    u = np.concatenate([rng.uniform(-1, 1, 400), 1 - 10.0 ** rng.uniform(-16, -1, 50)])
    for name, ref in (("arcsin", mpmath.asin), ("arccos", mpmath.acos)):
        got = getattr(E, name)(u).tolist()
        assert got == [_exact(ref, a) for a in u.tolist()], name
    y, x = _arguments(rng, 150), _arguments(rng, 150)
    assert E.arctan2(y, x).tolist() == [_exact(mpmath.atan2, a, b)
                                        for a, b in zip(y.tolist(), x.tolist(), strict=True)]
    b, e = rng.uniform(1e-3, 1e3, 400), rng.uniform(-4, 4, 400)
    e[:100] = np.round(e[:100])       # integer exponents take the exact rational path
    assert E.power(b, e).tolist() == [_exact(mpmath.power, p, q)
                                      for p, q in zip(b.tolist(), e.tolist(), strict=True)]


def test_c99_special_values():
    nan, inf = math.nan, math.inf
    assert math.copysign(1, E.sin(-0.0)) == -1 and math.copysign(1, E.tan(-0.0)) == -1
    assert np.isnan(E.sin(np.array([inf, -inf, nan]))).all()
    assert np.isnan(E.cos(inf)) and E.cos(-0.0) == 1.0
    assert np.isnan(E.arcsin(1.5)) and np.isnan(E.arccos(-1.000001))
    assert E.arccos(1.0) == 0.0 and E.arcsin(-0.0) == 0.0 and math.copysign(1, E.arcsin(-0.0)) == -1
    y = np.array([0.0, -0.0, 0.0, -0.0, 1.0, inf, inf, nan])
    x = np.array([1.0, 1.0, -1.0, -1.0, 0.0, inf, -inf, 1.0])
    want = [math.atan2(a, b) for a, b in zip(y.tolist(), x.tolist(), strict=True)]
    got = E.arctan2(y, x).tolist()
    assert [math.copysign(1, g) for g in got[:4]] == [math.copysign(1, w) for w in want[:4]]
    assert got[:7] == want[:7] and math.isnan(got[7])
    p = E.power(np.array([-2.0, -0.0, 0.0, -8.0, 2.0, nan, 1.0, 1e200]),
                np.array([3.0, -3.0, -2.0, 1 / 3, 0.0, 0.0, nan, 3.0]))
    assert p[0] == -8.0 and p[1] == -inf and p[2] == inf and np.isnan(p[3])
    assert p[4] == 1.0 and p[5] == 1.0 and p[6] == 1.0 and p[7] == inf


def test_dtypes_follow_numpy_and_float32_is_the_double_rounded_once():
    x32 = np.linspace(-3, 3, 101, dtype=np.float32)
    s = E.sin(x32)
    assert s.dtype == np.float32
    assert (s == E.sin(x32.astype(np.float64)).astype(np.float32)).all()
    assert E.power(x32, 1.5).dtype == np.float32          # a Python float stays weak
    assert E.power(x32, np.float64(1.5)).dtype == np.float64
    assert E.sin(np.arange(3)).dtype == np.float64
    assert isinstance(E.cos(0.25), np.float64) and E.sin(x32.reshape(1, 101)).shape == (1, 101)
    with pytest.raises(TypeError, match="expected real numbers"):
        E.sin(np.array([1j]))


def test_flint_precision_is_the_process_one_after_a_call():
    """Arb's working precision is global to the process (the exact engine uses it too)."""
    before = ctx.prec
    E.sin(np.random.default_rng(3).uniform(-1, 1, 50))
    E.arctan2(np.array([1.0]), np.array([3.0]))
    assert ctx.prec == before


def test_the_textbook_yardstick_never_calls_numpys_per_cpu_loops(monkeypatch):
    """rule.textbook in float32 and float64, with NumPy's sin, cos, arctan2, arcsin,
    arccos and power replaced by functions that fail: the yardstick of the rule and of the
    float32 plans is the same on every CPU only if it never reaches them."""
    from rigidsym.derivations.kernels_spec import KERNELS

    from rigidsym.codegen.accuracy import rule
    from rigidsym.codegen.spec import flat_symbols

    def refuse(*a, **k):
        raise AssertionError("NumPy's per-CPU loop called")

    kernel = next(k for k in KERNELS if k.name == "euler_angles_from_rotation_xyz")
    for name in ("sin", "cos", "arctan2", "arcsin", "arccos", "power"):
        monkeypatch.setattr(np, name, refuse)
    n = sum(len(ss) for _, ss in flat_symbols(kernel))
    cols = [np.full(4, 0.3)] * n
    for dt in (np.float32, np.float64):
        out = rule.textbook(kernel, cols, dt)
        assert out.shape[0] == 4
    monkeypatch.undo()


def test_measuring_printers_call_power_where_numpy_would_call_pow():
    x, y = sp.symbols("x y")
    pr = E.TEXTBOOK_PRINTER()
    assert pr.doprint(x**3) == "numpy.power(x, 3)"
    assert pr.doprint(x**y) == "numpy.power(x, y)"
    assert pr.doprint(x**2) == "x**2"                    # NumPy squares: one rounding
    assert E.KERNEL_PRINTER().doprint(x**sp.Rational(1, 3)) == "numpy.power(x, 1/3)"
    with pytest.raises(NotImplementedError, match="numpy.exp"):
        getattr(E.NUMPY, "exp")  # noqa: B009
    assert E.NUMPY.sqrt is np.sqrt
