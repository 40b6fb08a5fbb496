"""The norm of a free 3-vector under sin/cos, written θu (rigidsym.zero.polar)."""

from __future__ import annotations

import math
from fractions import Fraction

import sympy as sp

from rigidsym.zero.decide import decide_zero
from rigidsym.zero.polar import polar_norms

X = sp.symbols("x1 x2 x3", real=True)
N = sp.sqrt(sum(x**2 for x in X))


def test_a_trig_of_a_norm_is_decided_only_where_asked():
    # sin²|x| + cos²|x| = 1 and the Rodrigues coefficients: zero with polar=True; the
    # code generator's calls (polar=False) keep the undecided of before
    e = sp.sin(N)**2 + sp.cos(N)**2 - 1
    assert decide_zero([e], polar=True).zero is True
    assert decide_zero([e]).zero is None
    a, b = sp.sin(N) / N, (1 - sp.cos(N)) / N**2
    # (a|x|)^2 + (1 - b|x|^2)^2 = sin^2 + cos^2: the Rodrigues coefficients a, b themselves
    assert decide_zero([sp.expand(a**2 * N**2 + (1 - b * N**2)**2 - 1)], polar=True).zero is True


def test_a_false_relation_is_never_verified_and_says_why():
    r = decide_zero([sp.sin(N) / N - 1], polar=True)
    assert r.zero is None and "the norm of a free vector under sin/cos" in r.detail
    r = decide_zero([sp.cos(N) - sp.cos(2 * N)], polar=True)
    assert r.zero is None


def test_the_rewrite_is_refused_where_another_root_of_the_vector_is_left():
    assert polar_norms([sp.sin(N) - sp.sqrt(2 * X[0]**2 + X[1]**2 + X[2]**2)]) is None
    assert polar_norms([N - 1]) is None  # no trig of the norm: nothing to rewrite
    out, note = polar_norms([sp.sin(N) * X[0]])
    assert "= θ > 0" in note and not out[0].free_symbols & set(X)


# ---------------------------------------------------------------- a counterexample of rational norm
def _witness(lhs, rhs, seed=0):
    from rigidsym.checking.deciding.evidence import rational_norm_witness

    return rational_norm_witness(sp.Matrix([lhs]), sp.Matrix([rhs]), seed)


def test_a_false_relation_gets_a_point_of_rational_norm_whose_ball_excludes_0():
    from rigidsym.checking.deciding.balls import ball_at
    from rigidsym.zero.plan import make_plan

    for lhs, rhs in ((sp.sin(N) / N, 1), (sp.cos(N), sp.cos(2 * N)),
                     ((1 - sp.cos(N)) / N, (1 - sp.cos(N)) / N**2)):  # Eade's slip θ for θ²
        pt = _witness(lhs, rhs)
        assert pt is not None, (lhs, rhs)
        sq = sum(pt[x] ** 2 for x in X)
        root = Fraction(math.isqrt(sq.numerator), math.isqrt(sq.denominator))
        assert sq != 0 and root ** 2 == sq  # the norm is rational: every root is exact
        # the proof, redone: the residual's ball at that exact point excludes 0
        assert ball_at([lhs], [rhs], make_plan([lhs, rhs]), pt)[0]


def test_a_true_relation_never_gets_a_point_whose_ball_excludes_0():
    a, b = sp.sin(N) / N, (1 - sp.cos(N)) / N**2
    for lhs, rhs in ((sp.sin(N)**2 + sp.cos(N)**2, 1),
                     (sp.expand(a**2 * N**2 + (1 - b * N**2)**2), 1),
                     (sp.sin(2 * N), 2 * sp.sin(N) * sp.cos(N))):
        assert _witness(lhs, rhs) is None, lhs
    assert _witness(X[0] + 1, X[0]) is None  # no norm under sin/cos: not this search's


def test_the_zero_test_marks_a_polar_difference_and_only_that():
    r = decide_zero([sp.sin(N) / N - 1], polar=True)
    assert r.zero is None and "θ u" in r.polar_differs
    # the hint declares the vector itself, so it holds inside a --let function's body too
    assert "--let 'VECTOR = a u' in place of 'VECTOR: vector'" in r.detail
    assert decide_zero([sp.sin(N)**2 + sp.cos(N)**2 - 1], polar=True).polar_differs == ""


def test_the_exact_evaluator_keeps_sin_of_a_rational_norm_in_closed_form():
    from rigidsym.zero.exact import evaluate
    from rigidsym.zero.plan import make_plan

    e = sp.sin(N) / N + sp.cos(2 * N)
    pt = {X[0]: Fraction(2, 3), X[1]: Fraction(4, 3), X[2]: Fraction(4, 3)}  # norm 2
    got = evaluate(e, make_plan([e]), pt, lift=lambda v: v)
    assert got == sp.sin(2) / 2 + sp.cos(4)
