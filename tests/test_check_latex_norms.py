"""θ = ‖𝛉‖ beside the rotation vector 𝛉(t) (Forster et al.'s Ṙ = R [J_r θ̇]×): the scalar
and the vector are two symbols (the scalar's name takes a trailing ``_``, printed θ), the
model θ is itself a function of time, and the rates are derived by the chain rule."""

from __future__ import annotations

from fractions import Fraction

import pytest

import rigidsym
from rigidsym.latex.transformer.book_notations import BookNotationRules
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


def test_theta_the_norm_beside_theta_of_t_the_rate_is_derived_and_verified():
    # Forster et al. (2017) (Ṙ = R [J_r θ̇]×) as printed: θ = ‖𝛉‖ beside 𝛉(t), no renaming
    r = rigidsym.check_latex(RATE, let=_lets(r"\theta "), repairs=False)
    assert r.verdict == "verified", r.detail


def test_the_rate_of_the_norm_by_the_chain_rule_and_its_slip():
    lets = _lets(r"\theta ")[:2]
    r = rigidsym.check_latex(r"\dot\theta = \frac{\boldsymbol\theta^T\dot{\boldsymbol\theta}}"
                             r"{\theta}", let=lets, repairs=False)
    assert r.verdict == "verified", r.detail
    slip = rigidsym.check_latex(r"\dot\theta = \boldsymbol\theta^T\dot{\boldsymbol\theta}",
                                let=lets, repairs=False)
    assert slip.verdict == "does-not-hold"
    pt = {k: Fraction(v) for k, v in slip.counterexample["point"].items()}
    th = [pt[f"theta_{i}"] for i in (1, 2, 3)]
    rate = [pt[f"thetadot_{i}"] for i in (1, 2, 3)]
    dot = sum(a * b for a, b in zip(th, rate, strict=True))
    norm2 = sum(a * a for a in th)
    lhs, rhs = (Fraction(slip.counterexample[k]) for k in ("lhs", "rhs"))
    # the sides at the point, computed here: the true rate θ·θ̇/‖θ‖ (squared, no root) on the
    # left, the slip's θ·θ̇ on the right, and they differ
    assert lhs ** 2 * norm2 == dot ** 2 and (lhs >= 0) == (dot >= 0)
    assert rhs == dot and lhs != rhs


def test_the_slip_of_the_rate_is_never_verified():
    # J_rᵀ (the left Jacobian) for J_r: the sides differ; the witness would need sin of an
    # irrational norm, so the answer is undecided with that reason, never verified
    slip = rigidsym.check_latex(RATE.replace(r"\mathbf{J}_r", r"\mathbf{J}_r^T"),
                                let=_lets(r"\theta "), repairs=False)
    assert slip.verdict != "verified"
    assert slip.verdict == "does-not-hold" or "the sides differ" in slip.detail, slip.detail


def test_an_internal_error_names_the_construct_and_the_lets_involved(monkeypatch):
    def broken(self, key):
        raise RuntimeError("a failure of the engine's own")

    monkeypatch.setattr(BookNotationRules, "model_rate", broken)
    with pytest.raises(ValueError) as exc:
        rigidsym.check_latex(RATE, let=_lets(r"\theta "), repairs=False)
    msg = str(exc.value)
    assert r"internal error at the construct '\\dot \\mathbf R'" in msg, msg
    for x in _lets(r"\theta ")[:3]:  # R's model and the models and kinds it mentions
        assert f"--let '{x}'" in msg, msg


@pytest.mark.slow
def test_renamed_the_rate_of_the_norm_is_derived_and_verified():
    r = rigidsym.check_latex(RATE, let=_lets(r"\vartheta "), repairs=False)
    assert r.verdict == "verified"
    slip = rigidsym.check_latex(RATE.replace(r"\mathbf{J}_r", r"\mathbf{J}_r^T"),
                                let=_lets(r"\vartheta "), repairs=False)
    # a free vector's norm under sin/cos: no exact counterexample, so never verified
    assert slip.verdict in ("does-not-hold", "undecided") and (slip.counterexample or
                                                               slip.detail)


def test_a_free_scalar_beside_a_free_vector_of_its_letter_is_a_scalar_of_its_own():
    # θ and 𝛉 with no --let: two quantities, the counterexample gives each its own value
    r = rigidsym.check_latex(r"\boldsymbol\theta^T\boldsymbol\theta = \theta^2", repairs=False)
    assert r.verdict == "does-not-hold"
    pt = {k: Fraction(v) for k, v in r.counterexample["point"].items()}
    scalar = [k for k in pt if not k.startswith("theta_") or k == "theta_"]
    assert len(scalar) == 1 and len(pt) == 4, pt
    vector = sum(pt[f"theta_{i}"] ** 2 for i in (1, 2, 3))
    assert Fraction(r.counterexample["residual"]) == vector - pt[scalar[0]] ** 2
