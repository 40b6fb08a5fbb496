"""A free scalar that occurs only in sin, cos, tan, ... at rational multiples is d times an
angle (:mod:`rigidsym.latex.periodic`): the relation has period 2πd in it, so
deciding it for the angle on the zero test's (-π, π) decides it for every real value.
So ``\\sin 2\\theta = 2\\sin\\theta\\cos\\theta`` is decided without ``--let '\\theta:
angle'`` (not undecided on "trig of non-angle argument θ"), and a half angle is decided on
every real value, not on (-π, π) only. Where (-π, π) would be an assumption (a
bare occurrence) the symbol stays free and the reason names the fix."""

from __future__ import annotations

import pytest
from test_check_latex import forget_latex_ids, run_cli  # noqa: F401  (autouse fixture, CLI helper)

import rigidsym

ROT = (r"R = \cos\theta \mathbf{1} + \sin\theta [\mathbf{n}]_\times "
       r"+ (1-\cos\theta)\mathbf{n}\mathbf{n}^T")


@pytest.mark.parametrize("latex, lets, verdict", [
    (r"\sin 2\theta = 2\sin\theta\cos\theta", [], "verified"),
    (r"\sin 2\theta = 3\sin\theta\cos\theta", [], "does-not-hold"),
    (r"\cos(\alpha + \beta) = \cos\alpha\cos\beta - \sin\alpha\sin\beta", [], "verified"),
    (r"\cos(\alpha - \beta) = \cos\alpha\cos\beta - \sin\alpha\sin\beta", [],
     "does-not-hold"),
    (r"\tan(\theta + \pi) = \tan\theta", [], "verified"),
    # through a model: theta occurs in R's model only, inside cos and sin
    (r"\operatorname{tr}(R) = 1 + 2\cos\theta", [ROT, r"\mathbf{n}: unit vector"],
     "verified"),
    (r"\operatorname{tr}(R) = 2\cos\theta", [ROT, r"\mathbf{n}: unit vector"],
     "does-not-hold"),
])
def test_the_verdict_is_that_of_a_declared_angle(latex, lets, verdict):
    """Inferred or declared, the same verdict: nothing assumed beyond the LaTeX."""
    got = rigidsym.check_latex(latex, let=lets)
    declared = rigidsym.check_latex(latex, let=[*lets, r"\theta: angle"]
                                    if r"\theta" in latex or lets else
                                    [*lets, r"\alpha: angle; \beta: angle"])
    assert got.verdict == declared.verdict == verdict, got.detail


@pytest.mark.parametrize("latex, verdict", [
    (r"\tan\frac{\theta}{2} = \frac{\sin\theta}{1 + \cos\theta}", "verified"),
    (r"2\sin\frac{\theta}{2}\cos\frac{\theta}{2} = \sin\theta", "verified"),
    (r"\sin\frac{2\theta}{3} = 2\sin\frac{\theta}{3}\cos\frac{\theta}{3}", "verified"),
    # true on (-pi, pi) only: decided over theta = 2 psi, a whole period (-2 pi, 2 pi)
    (r"\cos\frac{\theta}{2} = \sqrt{\frac{1 + \cos\theta}{2}}", "does-not-hold"),
    (r"\sin\frac{\theta}{3} = \sin\theta", "does-not-hold"),
])
def test_a_fractional_multiple_is_decided_over_a_whole_period(latex, verdict):
    """theta at multiples of 1/d is d psi, psi an angle: a true identity verifies, and a
    relation that fails anywhere fails with an exact counterexample at which mpmath (50
    digits, from the counterexample's theta alone) finds the two sides apart."""
    import mpmath as mp
    import sympy as sp

    got = rigidsym.check_latex(latex)
    assert got.verdict == verdict, got.detail
    if verdict == "verified":
        return
    theta = next(s for s in got.counterexample["symbols"] if s["latex"] == r"\theta")
    mp.mp.dps = 50
    t = mp.mpf(str(sp.N(sp.sympify(theta["exact"]), 60)))
    sides = {
        r"\cos\frac{\theta}{2} = \sqrt{\frac{1 + \cos\theta}{2}}":
            (mp.cos(t / 2), mp.sqrt((1 + mp.cos(t)) / 2)),
        r"\sin\frac{\theta}{3} = \sin\theta": (mp.sin(t / 3), mp.sin(t)),
    }[latex]
    assert abs(sides[0] - sides[1]) > mp.mpf("1e-30"), (theta, sides)


@pytest.mark.parametrize("latex", [
    r"\theta\sin\theta = \theta\cos\theta",  # a bare occurrence
])
def test_where_the_range_would_be_an_assumption_the_symbol_stays_free(latex, capsys):
    code, out, _ = run_cli(capsys, "--latex", latex)
    out = " ".join(out.split())
    assert code == 3 and "an angle (no --let declares it)" not in out, out
    assert "trig of non-angle argument θ (an angle is a symbol declared so: --let 'NAME: " \
           "angle'" in out, out


def test_the_reading_is_printed(capsys):
    code, out, _ = run_cli(capsys, "--latex", r"\sin 2\theta = 2\sin\theta\cos\theta")
    out = " ".join(out.split())
    assert code == 0
    assert "read as: sin(2 θ) = 2 cos θ sin θ" in out, out
    assert r"\theta: an angle (no --let declares it): it occurs only in cos, sin" in out, out


@pytest.mark.parametrize("latex, verdict", [
    (r"\sin 2\theta = 2\sin\theta\cos\theta", "verified"),
    (r"a\sin 2\theta\cos\phi = 2a\sin\theta\cos\theta\cos\phi", "verified"),
    (r"\sin^2 2\theta = \frac{1 - \cos 4\theta}{2}", "verified"),
    (r"\cos 2\theta = 1 - 2\sin\theta", "does-not-hold"),   # the square left out
])
def test_a_multiple_angle_is_the_functions_argument(latex, verdict):
    """``\\sin 2\\theta`` is sin(2θ), as with parentheses (before: sin(2) θ, printed as
    ``θ sin 2`` and decided so: the first case was does-not-hold)."""
    got = rigidsym.check_latex(latex)   # theta, phi: angles by their uses (above)
    paren = rigidsym.check_latex(latex.replace(r"2\theta", r"(2\theta)")
                                 .replace(r"4\theta", r"(4\theta)"))
    assert got.verdict == paren.verdict == verdict, got.detail
