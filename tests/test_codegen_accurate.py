"""The accuracy rewrites of the code generator (rigidsym.codegen.accuracy.rewrites): kept
only when measured more accurate, and only when the zero test decides them equal to the
declared formula."""

from __future__ import annotations

import pytest
import sympy as sp
from rigidsym.derivations.kernels_spec import KERNELS

from rigidsym.codegen.accuracy import rewrites as accurate
from rigidsym.codegen.accuracy import tan_half
from rigidsym.codegen.generator import _flatten
from rigidsym.codegen.spec import flat_symbols, input_symbols

BY = {k.name: k for k in KERNELS}


def _improve(name: str):
    k = BY[name]
    syms = input_symbols(k)
    sflat = [s for _, ss in flat_symbols(k) for s in ss]
    conds = [sp.lambdify(sflat, b.when(**syms), modules="math") for b in k.branches]
    flat = _flatten(k, k.build(**syms))
    return flat, *accurate.improve(k, "main", flat, syms, sflat, conds)


# the screw kernel compiled, measured and decided; quick: a rewrite kept only when the zero
# test decides it (test_fractions_in_cos_phi_merged_and_decided,
# test_an_unequal_rewrite_is_refused_by_the_zero_test)
@pytest.mark.slow
def test_skew_part_rewrite_is_kept_measured_and_decided():
    before, after, chosen = _improve("screw_of_displacement")
    # the axis point from the skew part (it replaces the declared grouping of p0,
    # 3 - tr Q with it, wholesale; the rule "1 - cos(phi) from the skew part" then finds
    # nothing left)
    assert [c.name for c in chosen] == ["the axis point from the skew part of Q"]
    c = chosen[0]
    assert c.decided in ("exact-cancel", "random-exact")
    assert c.after * accurate.GAIN <= c.before and c.points >= 10
    # the declared 3 - tr Q is gone from the program; the skew part divides instead
    assert any(e.has(sp.UnevaluatedExpr) for e in before)
    assert not any(e.has(sp.UnevaluatedExpr) for e in after)
    assert "zero test" in c.line() and "skew part" in c.line()


def test_nothing_to_gain_keeps_the_declared_outputs():
    before, after, chosen = _improve("rotation_from_natural_invariants")
    assert chosen == [] and after == before


def test_an_unequal_rewrite_is_refused_by_the_zero_test():
    Q = input_symbols(BY["screw_of_displacement"])["Q"]
    k = BY["screw_of_displacement"]
    sub = accurate._constrained(k, input_symbols(k))
    d = [Q[i, i] for i in range(3)]
    skew = sum((Q[i, j] - Q[j, i]) ** 2 for i, j in ((2, 1), (0, 2), (1, 0)))
    # skew = 4 sin^2 phi, 1 + tr Q = 2 (1 + cos phi): 3 - tr Q = skew / (1 + tr Q)
    assert accurate._decide([(3 - sum(d), skew / (1 + sum(d)))], sub) in (
        "exact-cancel", "random-exact")
    with pytest.raises(AssertionError, match="not equal to the declaration"):
        accurate._decide([(3 - sum(d), skew / (2 * (1 + sum(d))))], sub)  # off by 2


def test_powers_by_pow_not_under_a_quotient():
    """``1/(x sqrt x)`` rounds three times where ``pow`` rounds once, and the
    meter evaluated every form with sympy's printer (``pow``), so it saw no loss in the
    kernels' printing (wrench_axis' Jacobian 6.7 u where the textbook is 2 u). The rule
    writes the exponent as its float (printed ``pow``); a norm under a function keeps its
    rational powers, which the removable quotients read."""
    from rigidsym.codegen.backends.extension.printer import KernelCPrinter
    from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter

    f = sp.symbols("f0:3", real=True)
    T = sum(x**2 for x in f)
    out, parts = accurate.exact_powers([f[0] * T**sp.Rational(-3, 2), f[1] / T**2,
                                         f[2] / T], {"angles": []})
    assert out[0] == f[0] * sp.Pow(T, sp.Float(-1.5)) and out[1] == f[1] * sp.Pow(T, -2.0)
    assert out[2] == f[2] / T
    # sin(|f|)/|f|^3 of the same norm: a removable quotient, left alone
    assert accurate.exact_powers([f[0] * T**sp.Rational(-3, 2),
                                   sp.sin(sp.sqrt(T)) / T**sp.Rational(3, 2)],
                                  {"angles": []}) is None
    assert "pow(" in KernelCPrinter().doprint(out[0])
    assert "**(-1.5)" in KernelNumPyPrinter().doprint(out[0])
    # the meter evaluates the current form as printed: 1/(x sqrt x) is not pow's result
    assert "sqrt" in KernelNumPyPrinter().doprint(f[0] * T**sp.Rational(-3, 2))
    # the zero test reads the float exponent as the rational it is
    assert accurate._decide(parts, {}) == "exact-cancel"
    # an angle kernel: the half-angle rewrite comes after the measurement
    assert accurate.exact_powers(out, {"angles": [sp.Symbol("phi")]}) is None


def test_fractions_in_cos_phi_merged_and_decided():
    """sympy.diff of ``sin phi / (2 - 2 cos phi)`` (the cot(phi/2) of ``e_dot``)
    sums ``cos phi / (2 - 2 cos phi) - 2 sin^2 phi / (2 - 2 cos phi)^2``, which cancel;
    the rule merges the terms of one phi-free factor into their reduced fraction
    ``-1 / (2 - 2 cos phi)`` and leaves a sum it cannot shorten alone."""
    phi = sp.Symbol("phi", real=True)
    w, e = sp.symbols("w e", real=True)
    f = sp.diff(w * (1 - e**2) * sp.sin(phi) / (2 - 2 * sp.cos(phi)), phi)
    out, parts = accurate.angle_fractions([f, w * sp.cos(phi) + e], {"angles": [phi]})
    assert sp.count_ops(out[0]) < sp.count_ops(f) and not out[0].has(sp.sin(phi))
    assert sp.simplify(out[0] * (2 - 2 * sp.cos(phi)) + w * (1 - e**2)) == 0
    assert out[1] == w * sp.cos(phi) + e and len(parts) == 1
    k = BY["N_tilde_dot"]
    sub = {phi: accurate._constrained(k, input_symbols(k))[input_symbols(k)["phi"]]}
    assert accurate._decide(parts, sub) in ("exact-cancel", "random-exact")
    assert accurate.angle_fractions([w * sp.cos(phi) + e], {"angles": [phi]}) is None


def _ctx(name: str) -> tuple:
    k = BY[name]
    syms = input_symbols(k)
    ctx = {"rotations": [], "angles": [syms[a.name] for a in k.args if a.kind == "angle"],
           "kernel": k, "flat": {a.name: [syms[a.name]] if a.shape == () else
                                 list(syms[a.name]) for a in k.args}}
    return k, syms, _flatten(k, k.build(**syms)), ctx


# four kernels compiled; quick: test_fractions_in_cos_phi_merged_and_decided (a rewrite in
# cos phi, exact and decided)
@pytest.mark.slow
def test_tan_half_polynomial_exact_off_the_sphere_and_decided():
    """L_tilde_dot's fractions over ``1 + cos phi`` as the polynomial in ``t =
    tan(phi/2)`` they are, each coefficient homogenised in ``e`` (guards against: 6.3 u where the
    textbook is 2.3 u, tests/test_accuracy.py). Equal to the declaration everywhere, off
    the unit sphere too (the harness's unit vectors a few ulps off read the declared
    formula): checked exactly at a rational point with ``|e| != 1``, ``t = 1/2``."""
    k, syms, flat, ctx = _ctx("L_tilde_dot")
    out, parts = accurate.tan_half_polynomial(flat, ctx)
    phi, e = syms["phi"], list(syms["e"])
    assert len(parts) == 9 and not any(x.has(sp.cos(phi), sp.sin(phi)) for x in out)
    # tan(phi/2) = 1/2: sin phi = 4/5, cos phi = 3/5 (sin(phi/2) : cos(phi/2) = 1 : 2)
    at = {sp.sin(phi): sp.Rational(4, 5), sp.cos(phi): sp.Rational(3, 5),
          sp.sin(phi / 2): 1, sp.cos(phi / 2): 2,
          **dict(zip(e, [sp.Rational(1, 3), sp.Rational(-2, 5), sp.Rational(7, 4)],
                     strict=True)),
          **dict(zip(syms["omega"], [sp.Rational(3, 7), 5, sp.Rational(-1, 9)], strict=True))}
    for old, new in zip(flat, out, strict=True):
        assert old.xreplace(at) == new.xreplace(at)
        assert sp.sympify(new).xreplace(at).is_Rational
    # homogenised: e0^2 w + e1^2 w + 2 e2^2 w - w (cancels in floating point near |e| = 1)
    w = sp.Symbol("w")
    h = tan_half._homogenised(e[0]**2 * w + e[1]**2 * w + 2 * e[2]**2 * w - w, e)
    assert h == e[2]**2 * w + sp.Mul(w, sp.Add(*[x**2 for x in e], -1), evaluate=False)
    assert accurate._decide(parts, accurate._constrained(k, syms)) == "exact-cancel"
    # cheap to refuse: a divisor 1 - cos phi (N_tilde_dot), no unit vector or angle, and
    # L_tilde, whose half-angle program is t e already
    for name in ("N_tilde_dot", "L_tilde", "rotation_from_natural_invariants"):
        assert accurate.tan_half_polynomial(*_ctx(name)[2:]) is None, name
