"""The certified numeric backing: balls that contain the exact values, enclosures that
certify, precision that rises where a ball is too wide, and the records that say so."""

from __future__ import annotations

import json
import random
import re
from fractions import Fraction

import flint
import pytest
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.algebra.primitives import rotation_from_natural_invariants
from rigidsym.algebra.symbols import angle, rotation, unit_vector, vector
from rigidsym.checking.deciding import balls
from rigidsym.core.settings import ENGINE
from rigidsym.zero import make_plan
from rigidsym.zero.program import unparametrised

pytestmark = pytest.mark.xdist_group("balls")  # its module fixtures built on one worker

e = unit_vector("be")
phi = angle("bphi")
R = rotation("bR")
v = vector("bv")


@settings(max_examples=examples(25), deadline=None)
@given(st.integers(0, 10**6))
def test_balls_contain_the_exact_rational_values(seed):
    # rational in the atoms: the exact value at a rational point is a Fraction
    exprs = [(R.T * R)[0, 1] + v[0] / (1 + v[1] ** 2), (R * v)[2] ** 3 - e[0] * v[2],
             sp.Rational(1, 3) * (e.T * e)[0] - sp.Rational(1, 3)]
    plan = make_plan(exprs)
    pt = balls.exact_point(plan, random.Random(seed))
    prog = unparametrised(exprs)
    vals = [flint.fmpq(pt[a].numerator, pt[a].denominator) for a in prog.leaves]
    with flint.ctx.workprec(balls.bits_of(30)):
        got = balls.run_balls(prog, vals)
    subs = {a: sp.Rational(pt[a].numerator, pt[a].denominator) for a in prog.leaves}
    for ball, x in zip(got, exprs, strict=True):
        exact = x.xreplace(subs)
        mid, rad = balls._exact(ball.mid()), balls._exact(ball.rad())
        assert abs(Fraction(int(exact.p), int(exact.q)) - mid) <= rad  # exactly, no rounding
        assert rad < Fraction(1, 10**25)


def test_exact_points_satisfy_the_constraints_exactly():
    plan = make_plan(list(R) + list(e))
    pt = balls.exact_point(plan, random.Random(7))
    Rv = sp.Matrix(3, 3, [sp.Rational(pt[x].numerator, pt[x].denominator) for x in R])
    ev = [pt[x] for x in e]
    assert Rv.T * Rv == sp.eye(3) and sum(x * x for x in ev) == 1


def test_a_true_identity_is_enclosed_and_certified():
    Q = rotation_from_natural_invariants(e, phi)
    lhs = list(Q.T * Q)
    rhs = list(sp.eye(3))
    b = balls.backing(lhs, rhs, make_plan(lhs + rhs), seed=5)
    assert b.points == ENGINE.numeric_points and b.excluded is None
    assert b.enclosure <= ENGINE.certified_bound and b.certified
    assert b.digits == ENGINE.numeric_digits


def test_a_false_identity_has_a_ball_that_excludes_zero():
    lhs, rhs = [sp.cos(phi) ** 2], [sp.sin(phi) ** 2]
    b = balls.backing(lhs, rhs, make_plan(lhs + rhs), seed=5)
    assert b.excluded is not None and not b.certified


def test_precision_rises_where_a_ball_is_too_wide():
    # 10^60 (cos^2 + sin^2) - 10^60 is 0, but at 50 digits its ball is 10^10 wide
    big = sp.Integer(10) ** 60
    x = sp.Symbol("bx", real=True)
    lhs = [x + big * (sp.cos(phi) ** 2 + sp.sin(phi) ** 2) - big]
    b = balls.backing(lhs, [x], make_plan(lhs + [x]), seed=3)
    assert b.digits > ENGINE.numeric_digits and b.raised == ENGINE.numeric_points
    assert b.certified


@settings(max_examples=examples(200), deadline=None)
@given(st.fractions(min_value=Fraction(1, 10**60), max_value=Fraction(10**30)))
def test_round_up_keeps_an_upper_bound_in_two_digits(x):
    r = balls.round_up(x)
    assert Fraction(r) >= x and len(f"{r:.1e}".split("e")[0].replace(".", "")) == 2
    assert Fraction(r) <= x * Fraction(11, 10) + Fraction(1, 10**80)


def _ball(text: str) -> tuple[Fraction, Fraction]:
    m = re.fullmatch(r"\[(-?[0-9.e+-]+) \+/- ([0-9.e+-]+)\]", text)
    assert m, text
    return Fraction(m.group(1)), Fraction(m.group(2))


@pytest.fixture(scope="module")
def r396e():
    from rigidsym.checking.checker import check
    from rigidsym.registry.declarations import load_all

    load_all()
    return check("3.96e")


def test_show_json_of_a_does_not_hold_is_certified_by_both_proofs(r396e):
    from rigidsym.report.record import result_record

    rec = json.loads(json.dumps(result_record(r396e)))  # what `show 3.96e --json` prints
    n = rec["numeric"]
    assert n["certified"] is True and 0 <= n["enclosure"] <= 1e-40
    mid, rad = _ball(n["printed_enclosure"])
    assert abs(mid) > rad  # 0 is not in the ball
    exact = sp.sympify(rec["counterexample"]["residual"])
    assert any(abs(Fraction(str(x)) - mid) <= rad for x in exact)  # the two proofs agree


def test_the_reports_state_the_backing(r396e):
    from rigidsym.report.html import to_html
    from rigidsym.report.markdown import to_markdown
    from rigidsym.report.record import to_json

    r = r396e
    page = to_html([r])
    assert "0 ∉ [" in page and "certified." in page and "enclosed in [−r, r]" in page
    assert "0 ∉ [" in to_markdown([r])
    doc = json.loads(to_json([r], timings=False))
    assert doc["python_flint"] == flint.__version__
    assert doc["equations"][0]["numeric"]["enclosure"] == 1e-40  # bounded: byte-stable


def test_numeric_sentence_is_one_helper():
    from rigidsym.report import html, markdown, show
    from rigidsym.report.numeric import numeric_sentence

    assert markdown.numeric_sentence is html.numeric_sentence is show.numeric_sentence \
        is numeric_sentence
    n = {"points": 10, "digits": 100, "max_residual": 1e-60, "seed": 1, "enclosure": 3.1e-45,
         "certified": True}
    words = numeric_sentence(n)
    assert "3.1e-45" in words and "100 digits (precision raised" in words
    assert numeric_sentence(dict(n, certified=False)).endswith("not certified.")


@pytest.mark.parametrize("digits", [10, 50, 400])
def test_bits_cover_the_digits(digits):
    assert 2 ** balls.bits_of(digits) > 10 ** (digits + 2)


def test_integer_powers_of_a_ball_around_zero_stay_finite():
    # python-flint's arb ** int is nan here; a residual that is 0 squares to a tiny ball
    x = flint.arb(0, 1e-50)
    assert balls._ipow(x, 2).is_finite() and balls.upper(balls._ipow(x, 3)) < Fraction(1, 10**149)
    assert not balls._ipow(x, -2).is_finite()  # 1/0 stays undefined
    assert balls._ipow(flint.arb(flint.fmpq(-3, 7)), 5).contains(flint.fmpq(-243, 16807))
