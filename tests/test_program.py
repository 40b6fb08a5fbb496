"""The straight-line programs under the zero test: the same values as the tree walker, and a
rational function whose numerator vanishes exactly for the identities."""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import pytest
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.algebra.primitives import cpm, rotation_from_natural_invariants
from rigidsym.algebra.symbols import TIME, angle, rotation, unit_vector, vector
from rigidsym.zero import evaluate, make_plan
from rigidsym.zero.decide import random_point
from rigidsym.zero.program import POW, parametrised, run_exact, run_rational

e = unit_vector("pe")
phi = angle("pphi")
th = angle("pth", TIME)
R = rotation("pR")
v = vector("pv")
Q = rotation_from_natural_invariants(e, phi)

#: expressions with every kind of node the exact evaluator treats
EXPRS = [
    (Q.T * Q)[0, 1] + sp.Rational(3, 7) * e[2] ** 3,
    sp.tan(phi / 2) * sp.cos(3 * phi) - sp.sec(phi + sp.pi / 2) / (1 + e[0] ** 2),
    sp.cot(2 * phi) + sp.csc(phi / 3) * sp.sin(phi - sp.pi),
    phi * sp.cos(phi) ** 2 - (R * v)[1] / (2 + v[0] ** 2),
    (cpm(v) * R).trace() * th.diff(TIME, 2) + sp.cos(th) * th.diff(TIME),
    sp.Abs(v[0] - v[1]) * (e[1] + 1) ** -2,
]


def _point(plan, seed):
    return random_point(plan, random.Random(seed))


@settings(max_examples=examples(20), deadline=None)
@given(st.integers(0, 10**6))
def test_program_values_equal_the_tree_walker(seed):
    plan = make_plan(EXPRS)
    prog = parametrised(EXPRS, plan)
    pt = _point(plan, seed)
    try:
        want = [evaluate(x, plan, pt) for x in EXPRS]
    except ZeroDivisionError:
        with pytest.raises(ZeroDivisionError):
            run_exact(prog, [flint.fmpq(pt[p].numerator, pt[p].denominator)
                             for p in plan.params])
        return
    got = run_exact(prog, [flint.fmpq(pt[p].numerator, pt[p].denominator)
                           for p in plan.params])
    assert [Fraction(int(g.p), int(g.q)) for g in got] == want


def test_shared_subexpressions_are_computed_once():
    x = sp.Symbol("px", real=True)
    big = (x + 1) ** 7
    prog = parametrised([big + x, big * x, big], make_plan([big, x]))
    pows = [k for k, op in enumerate(prog.ops) if op[0] == POW]
    assert len(pows) == 1 and prog.outputs[2] == pows[0] and len(set(prog.outputs)) == 3


def _fraction(expr):
    plan = make_plan([expr])
    prog = parametrised([expr], plan)
    ctx = flint.fmpq_mpoly_ctx.get([f"x{i}" for i in range(len(plan.params))], "degrevlex")
    return plan, prog, run_rational(prog, ctx)[0]


@pytest.mark.parametrize("expr", [
    (Q.T * Q - sp.eye(3))[1, 2],
    (R * cpm(v) * R.T - cpm(R * v))[0, 2],
    sp.cos(3 * phi) - (4 * sp.cos(phi) ** 3 - 3 * sp.cos(phi)),
    sp.tan(phi / 2) - sp.sin(phi) / (1 + sp.cos(phi)),
])
def test_identities_have_a_zero_numerator(expr):
    _, _, (num, den) = _fraction(expr)
    assert num.is_zero() and not den.is_zero()


@pytest.mark.parametrize("expr", [
    (Q.T * Q)[1, 1] - sp.Rational(1, 10**9) * e[0] - 1,
    sp.tan(phi / 2) - sp.sin(phi) / (1 - sp.cos(phi)),
    (R * v)[0] - v[0],
])
def test_non_identities_keep_a_numerator_that_matches_the_points(expr):
    plan, prog, (num, den) = _fraction(expr)
    assert not num.is_zero()
    for seed in range(3):  # num/den is the expression: the same value at rational points
        pt = _point(plan, seed)
        vals = [flint.fmpq(pt[p].numerator, pt[p].denominator) for p in plan.params]
        assert num(*vals) / den(*vals) == run_exact(prog, vals)[0]
