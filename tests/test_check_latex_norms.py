"""θ = ‖𝛉‖ beside the rotation vector 𝛉(t) (Forster et al.'s Ṙ = R [J_r θ̇]×): the scalar
and the vector share one name, and the reading that fails on it names both and the
renaming; renamed, the rate is derived by the chain rule and verified."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.registry import declarations as registry

RATE = r"\dot{\mathbf{R}} = \mathbf{R}[\mathbf{J}_r\dot{\boldsymbol\theta}]_\times"


def _lets(s: str) -> list[str]:
    return [r"\boldsymbol\theta(t): vector", s + r" = \|\boldsymbol\theta\|",
            r"\mathbf{R} = \mathbf{I} + \frac{\sin S}{S}[\boldsymbol\theta]_\times + "
            r"\frac{1 - \cos S}{S^2}[\boldsymbol\theta]_\times^2".replace("S", s),
            r"\mathbf{J}_r = \mathbf{I} - \frac{1 - \cos S}{S^2}[\boldsymbol\theta]_\times + "
            r"\frac{S - \sin S}{S^3}[\boldsymbol\theta]_\times^2".replace("S", s)]


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_a_scalar_and_a_vector_of_one_name_are_named_with_the_renaming():
    with pytest.raises(ValueError, match=r"\\boldsymbol\{\\theta\} and \\theta share the name "
                                         r"'theta' .*\\vartheta"):
        rigidsym.check_latex(RATE, let=_lets(r"\theta "), repairs=False)


@pytest.mark.slow
def test_renamed_the_rate_of_the_norm_is_derived_and_verified():
    r = rigidsym.check_latex(RATE, let=_lets(r"\vartheta "), repairs=False)
    assert r.verdict == "verified"
    slip = rigidsym.check_latex(RATE.replace(r"\mathbf{J}_r", r"\mathbf{J}_r^T"),
                                let=_lets(r"\vartheta "), repairs=False)
    # a free vector's norm under sin/cos: no exact counterexample, so never verified
    assert slip.verdict in ("does-not-hold", "undecided") and (slip.counterexample or
                                                               slip.detail)
