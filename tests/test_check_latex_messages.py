"""Messages that name the real cause: a statement whose sides differ in shape says "shape"
and both shapes (an identity that a product cancels to keeps its size, so micro Lie's
``M M^{-1} = I_4`` of a 3x3 M is not read as 4x4 = 4x4 and then refused by the numeric
cross-check), and an operator before a ``--let`` function's application
(``\\det J_r(\\mathbf{x})``) names the spelling that applies it to the function's value."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp

import rigidsym
from rigidsym.registry import declarations as registry

M_IS_R = [r"\mathbf{M} = \mathbf{R}", r"\mathbf{R}: rotation"]
J_R = [r"J_r(\mathbf{x}) = \mathbf{I} + [\mathbf{x}]_\times"]


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_a_3x3_equal_to_a_4x4_says_shape_and_both_shapes():
    with pytest.raises(ValueError) as exc:
        rigidsym.check_latex(r"\mathbf{M}\mathbf{M}^{-1} = \mathbf{I}_4", let=M_IS_R,
                             repairs=False)
    msg = str(exc.value)
    assert "differ in shape" in msg and "3×3" in msg and "4×4" in msg, msg
    assert "cross-check" not in msg, msg


def test_the_identity_of_its_own_size_verifies_and_a_slip_does_not_hold():
    r = rigidsym.check_latex(r"\mathbf{M}\mathbf{M}^{-1} = \mathbf{I}_3", let=M_IS_R,
                             repairs=False)
    assert r.verdict == "verified", r.detail
    slip = rigidsym.check_latex(r"\mathbf{M}\mathbf{M} = \mathbf{I}_3", let=M_IS_R,
                                repairs=False)
    assert slip.verdict == "does-not-hold" and slip.counterexample


def test_det_before_a_let_function_names_the_parenthesised_spelling():
    with pytest.raises(ValueError) as exc:
        rigidsym.check_latex(r"\det J_r(\mathbf{x}) = 1 + \mathbf{x}^T\mathbf{x}", let=J_R,
                             repairs=False)
    msg = str(exc.value)
    assert r"\det(J_{r}(\mathbf{x}))" in msg and "det of a scalar" not in msg, msg


def _det_of_one_plus_cpm(x) -> Fraction:
    a, b, c = x
    m = sp.Matrix([[1, -c, b], [c, 1, -a], [-b, a, 1]])
    return Fraction(str(m.det()))


def test_det_of_the_functions_value_verifies_and_its_slip_has_a_counterexample():
    # det(1 + [x]x) = 1 + x.x (the characteristic polynomial of a skew matrix at -1)
    r = rigidsym.check_latex(r"\det(J_r(\mathbf{x})) = 1 + \mathbf{x}^T\mathbf{x}", let=J_R,
                             repairs=False)
    assert r.verdict == "verified", r.detail
    slip = rigidsym.check_latex(r"\det(J_r(\mathbf{x})) = 1 + 2\mathbf{x}^T\mathbf{x}",
                                let=J_R, repairs=False)
    assert slip.verdict == "does-not-hold"
    pt = {k: Fraction(v) for k, v in slip.counterexample["point"].items()}
    x = [sp.Rational(str(pt[f"x_{i}"])) for i in (1, 2, 3)]
    lhs, rhs = (Fraction(slip.counterexample[k]) for k in ("lhs", "rhs"))
    norm2 = Fraction(str(sum(v * v for v in x)))
    assert lhs == _det_of_one_plus_cpm(x) and rhs == 1 + 2 * norm2 and lhs != rhs
