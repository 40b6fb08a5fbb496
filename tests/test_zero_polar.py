"""The norm of a free 3-vector under sin/cos, written θu (rigidsym.zero.polar)."""

from __future__ import annotations

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
