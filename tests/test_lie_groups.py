"""The Lie-group maps (derivations/lie_groups.py): every identity verified by the
chapter's checker through the polar parametrisation w = theta e, a slip refuted, and the
maps against independent numbers (scipy-free: a matrix exponential by its series in mpmath).

They guard against the identities being undecided ("trig of non-angle argument") and expm
refusing a non-unit exponent.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from rigidsym.checking.checker import check
from rigidsym.registry import usermodules

pytestmark = pytest.mark.xdist_group("lie_groups")

#: the ids whose check takes seconds (SE(3) with 7-10 parameters): slow
_SLOW = {"sola:log-exp-se3", "barfoot:se3-jl-inverse", "barfoot:se3-jl-definition"}
_FAST = ["sola:exp-so3", "sola:log-exp-so3", "sola:exp-log-so3", "sola:jl-definition",
         "sola:jr-definition", "sola:jl-jr", "sola:jl-R-jr", "sola:jl-w", "sola:jl-inverse",
         "sola:exp-se3", "barfoot:se3-jl-xi", "sola:quat-of-rotation", "sola:quat-product",
         "sola:log-so3-small", "sola:log-se3-small", "sola:jl-times", "barfoot:se3-q-block"]


@pytest.fixture(scope="module")
def module():
    return usermodules.load("rigidsym.derivations.lie_groups")


def test_every_id_is_listed(module):
    """Every id the module declares is checked here: a new one joins _FAST (or _SLOW). The
    list is written out, not read from the module at collection: loading the module there
    would register its ids in every worker before the tests that take the book's ids."""
    assert set(module.ids) == set(_FAST) | _SLOW, set(module.ids) ^ (set(_FAST) | _SLOW)


@pytest.mark.sample
@pytest.mark.parametrize("eq_id", _FAST)
def test_identity_verified(module, eq_id):
    out = check(eq_id, repairs=False, expanded=False)
    assert out.verdict == "verified", (eq_id, out.verdict)


@pytest.mark.slow
@pytest.mark.parametrize("eq_id", sorted(_SLOW))
def test_identity_verified_se3(module, eq_id):
    out = check(eq_id, repairs=False, expanded=False)
    assert out.verdict == "verified", (eq_id, out.verdict)


def test_slips_refuted(tmp_path):
    # J_l = J_r (a sign slip) and J_l = Exp(w)^T J_r: each a counterexample, exactly
    src = '''
import sympy as sp
from rigidsym import Rel, Statement, angle, equation, mat, unit_vector
from rigidsym.derivations import lie_maps as L
th, e = angle("theta", range="[0, pi]"), unit_vector("e")
w = th * e
Jl, Jr, R = mat("J_l"), mat("J_r"), mat("R")
M = {Jl: sp.ImmutableMatrix(L.rotation_vector_left_jacobian(w)),
     Jr: sp.ImmutableMatrix(L.rotation_vector_right_jacobian(w)),
     R: sp.ImmutableMatrix(L.rotation_from_rotation_vector(w))}

@equation("slip:jl-jr", "J_l = J_r", expected="does-not-hold")
def a():
    return Statement([Rel(Jl, Jr)], M)

@equation("slip:jl-RT-jr", "J_l = R^T J_r", expected="does-not-hold")
def b():
    return Statement([Rel(Jl, R.T * Jr)], M)
'''
    p = tmp_path / "lie_slips.py"
    p.write_text(src)
    usermodules.load(str(p))
    for i in ("slip:jl-jr", "slip:jl-RT-jr"):
        out = check(i, repairs=False, expanded=False)
        assert out.verdict == "does-not-hold", (i, out.verdict)


def test_small_angle_log_slips_refuted(tmp_path):
    """The SE(3) log's small-angle branch (the kernel's, below pi/4), verified as
    sola:log-se3-small (guards against: declared nowhere, only in generated code): a slip in its
    g (1 - sqrt(1 - s^2) for 1 + ...) is a counterexample, and asin(sin theta) is theta only
    below a quarter turn: on [0, pi] the claim is not verified."""
    src = '''
import sympy as sp
from rigidsym import Rel, Statement, angle, equation, unit_vector, vector
from rigidsym.declare import rotation_from_natural_invariants, vect
from rigidsym.derivations import lie_maps as L
b, th, e, v = angle("beta", range="[0, pi]"), angle("theta", range="[0, pi]"), \\
    unit_vector("e"), vector("v")
R = rotation_from_natural_invariants(e, b / 2)
u = vect(R)
s = sp.sqrt((u.T * u)[0])
T = sp.Matrix.vstack(sp.Matrix.hstack(R, v), sp.Matrix([[0, 0, 0, 1]]))
xi = sp.Matrix.vstack(b / 2 * e, L.rotation_vector_left_jacobian_inverse(b / 2 * e) * v)
a = sp.asin(s) / s
g = (2 * s - sp.asin(s) * (1 - sp.sqrt(1 - s**2))) / (2 * s**3)
up = u.cross(v)
X, Y = sp.MatrixSymbol("X", 6, 1), sp.MatrixSymbol("Y", 6, 1)
x, y = sp.Symbol("x", real=True), sp.Symbol("y", real=True)

@equation("slip:log-se3-small-g", "g slipped", expected="does-not-hold")
def a1():
    return Statement([Rel(X, Y)], {X: sp.ImmutableMatrix(sp.Matrix.vstack(
        a * u, v - a / 2 * up + g * u.cross(up))), Y: sp.ImmutableMatrix(xi)})

@equation("slip:asin-sin", "asin(sin theta) = theta on [0, pi]", expected="does-not-hold")
def a2():
    return Statement([Rel(x, y)], {x: sp.asin(sp.sin(th)), y: th})
'''
    p = tmp_path / "lie_small_slips.py"
    p.write_text(src)
    usermodules.load(str(p))
    assert check("slip:log-se3-small-g", repairs=False, expanded=False).verdict == \
        "does-not-hold"
    assert check("slip:asin-sin", repairs=False, expanded=False).verdict != "verified"


def test_norm_of_a_default_range_angle_is_split():
    # w = phi e with phi on (-pi, pi): sqrt(w^T w) = |phi|, not phi; a claim |w| = phi is
    # refuted (phi < 0), |w|^2 = phi^2 verified
    from rigidsym.checking.deciding.branches import cases
    from rigidsym.declare import angle, unit_vector

    phi, e = angle("phi"), unit_vector("e")
    w = phi * e
    th = sp.sqrt(sum(x**2 for x in w))
    alts = cases(th, phi)
    assert len(alts) == 2
    assert {sp.simplify(a[2] - a[3]) == 0 for a in alts} == {True, False}


def _expm_series(W, n=60):
    """exp(W) by its power series, 50 digits (independent of every closed form)."""
    W = mp.matrix(W)
    out, term = mp.eye(W.rows), mp.eye(W.rows)
    for k in range(1, n):
        term = term * W / k
        out += term
    return out


def _hat6(xi):
    w, v = xi[:3], xi[3:]
    return [[0, -w[2], w[1], v[0]], [w[2], 0, -w[0], v[1]], [-w[1], w[0], 0, v[2]],
            [0, 0, 0, 0]]


def test_maps_match_the_series_exponential():
    from rigidsym.derivations import lie_maps as L

    mp.mp.dps = 50
    rng = np.random.default_rng(3)
    xs = sp.symbols("x0:6", real=True)
    X = sp.Matrix(xs)
    T = sp.lambdify(xs, L.transform_from_exponential_coordinates(X), "mpmath")
    for _ in range(3):
        xi = [mp.mpf(float(x)) for x in rng.normal(size=6)]
        ref = _expm_series(_hat6(xi))
        got = mp.matrix(T(*xi))
        assert mp.mnorm(ref - got, 1) < mp.mpf(10) ** -40
