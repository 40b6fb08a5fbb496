"""Scope as the books mean it and no internal error text in a message (items 3
and 4): a ``--let`` function's body sees its parameter *and every model built on it*
re-bound to the argument; a parameter that is also a model, with two readings left, is
refused naming both; an internal error is one line naming the construct."""

from __future__ import annotations

import numpy as np
import pytest
from test_check_latex import forget_latex_ids, run_cli  # noqa: F401  (autouse fixture, CLI helper)

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex import LatexError

U = [r"\mathbf{u}: vector", r"n = |\mathbf{u}|", r"F(\mathbf{u}) = n^2 I_3"]


def test_the_truth_of_the_scope_cases_by_numpy():
    """F(u) = |u|² 1 as a reader means it: F(2u) = 4F(u), and not 2F(u) nor 4F(2u)."""
    u = np.random.default_rng(62).normal(size=3)

    def f(x):
        return (x @ x) * np.eye(3)

    assert np.allclose(f(2 * u), 4 * f(u))
    assert not np.allclose(f(2 * u), 2 * f(u)) and not np.allclose(f(2 * u), 4 * f(2 * u))
    assert not np.allclose(f(2 * u), f(u))


@pytest.mark.parametrize("latex, verdict", [
    # before does-not-hold (the body's n stayed the global |u|: F(2u) = F(u))
    (r"F(2\mathbf{u}) = 4F(\mathbf{u})", "verified"),
    (r"F(2\mathbf{u}) = 2F(\mathbf{u})", "does-not-hold"),
    (r"F(2\mathbf{u}) = 4F(2\mathbf{u})", "does-not-hold"),
    # before verified (a false equation)
    (r"F(2\mathbf{u}) = F(\mathbf{u})", "does-not-hold"),
    (r"F(-\mathbf{u}) = F(\mathbf{u})", "verified"),
])
def test_a_model_built_on_the_parameter_is_rebound_at_the_argument(latex, verdict):
    r = rigidsym.check_latex(latex, let=U, repairs=False)
    assert r.verdict == verdict, (r.detail, r.model)


def test_the_rebinding_goes_through_models_of_models_and_read_as_says_it():
    lets = [r"\mathbf{u}: vector", r"n = |\mathbf{u}|", r"m = n^2",
            r"G(\mathbf{u}) = m\mathbf{u}\mathbf{u}^T"]
    r = rigidsym.check_latex(r"G(2\mathbf{u}) = 16G(\mathbf{u})", let=lets, repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)
    said = [n for n in r.model if "re-bound at the argument" in n]
    assert any(n.startswith("G(2 u)") and "m = " in n for n in said), r.model
    assert any(n.startswith("G(2 u)") and "n = " in n for n in said), r.model
    r = rigidsym.check_latex(r"G(2\mathbf{u}) = 4G(\mathbf{u})", let=lets, repairs=False)
    assert r.verdict == "does-not-hold"


@pytest.mark.parametrize("order", [[0, 1, 2], [2, 1, 0], [1, 2, 0]])
def test_the_rebinding_does_not_depend_on_the_let_order(order):
    r = rigidsym.check_latex(r"F(2\mathbf{u}) = 4F(\mathbf{u})", let=[U[i] for i in order],
                             repairs=False)
    assert r.verdict == "verified"


def test_a_parameter_that_is_also_a_model_with_two_readings_is_refused_naming_both():
    lets = [r"\mathbf{e}: unit vector; \theta: angle",
            r"\mathbf{g} = \tan\frac{\theta}{2}\mathbf{e}",
            r"R(\mathbf{g}) = \cos\theta\,I_3 + (1-\cos\theta)\mathbf{e}\mathbf{e}^T"
            r" - \sin\theta[\mathbf{e}]_\times"]
    with pytest.raises((BadInput, LatexError)) as exc:
        rigidsym.check_latex(r"R(-\mathbf{g}) = R(\mathbf{g})^T", let=lets)
    msg = str(exc.value)
    assert r"--let '\mathbf{g} = " in msg and "--let 'R(\\mathbf{g}) = " in msg, msg
    assert "two readings" in msg
    # at the model itself there is one reading: decided as before
    r = rigidsym.check_latex(r"R(\mathbf{g})R(\mathbf{g})^T = I_3", let=lets, repairs=False)
    assert r.verdict == "verified"


def test_an_internal_error_is_one_line_naming_the_construct(monkeypatch, capsys):
    from rigidsym.latex.transformer.chapter import LatexTransformer

    def broken(self, items):
        raise AttributeError("'Pow' object has no attribute 'is_commutative'")

    monkeypatch.setattr(LatexTransformer, "frac", broken, raising=True)
    with pytest.raises(LatexError) as exc:
        rigidsym.check_latex(r"\frac{a}{b} = a", let=["a: scalar; b: scalar"])
    assert "AttributeError" not in str(exc.value) and "is_commutative" not in str(exc.value)
    assert r"\frac" in str(exc.value) and "internal error" in str(exc.value)
    code, _, err = run_cli(capsys, "--latex", r"\frac{a}{b} = a", "--let", "a: scalar; b: scalar")
    assert code == 2 and "is_commutative" not in err and "Traceback" not in err, err


# ------------------------------------------------------------------ shapes are types
@pytest.mark.parametrize("latex, lets, shapes", [
    (r"Q\mathbf{e} = \phi", [r"Q: rotation; \mathbf{e}: unit vector; \phi: angle"],
     ("a 3-vector", "a scalar")),
    (r"Q = \mathbf{e}", [r"Q: rotation; \mathbf{e}: unit vector"],
     ("a 3×3 matrix", "a 3-vector")),
])
def test_sides_of_different_shapes_are_bad_input_naming_both(latex, lets, shapes, capsys):
    # before does-not-hold (exit 1), a verdict on no equation
    with pytest.raises(LatexError) as exc:
        rigidsym.check_latex(latex, let=lets)
    assert exc.value.construct == "shapes"
    assert all(s in str(exc.value) for s in shapes), str(exc.value)
    code, _, err = run_cli(capsys, "--latex", latex, *[a for x in lets for a in ("--let", x)])
    assert code == 2 and "differ in shape" in err


@pytest.mark.parametrize("latex, lets, verdict", [
    # before "noncommutative scalars in MatMul are not supported" (exit 2)
    (r"\det(Q)\,Q = Q", ["Q: rotation"], "verified"),
    (r"\det(Q)\,Q = 2Q", ["Q: rotation"], "does-not-hold"),
    (r"\det(\mathbf{M})\,\mathbf{M}^T = \mathbf{M}^T\det(\mathbf{M}^T)", [r"\mathbf{M}: matrix"],
     "verified"),
    (r"\mathrm{tr}(A)A\mathbf{x} = A\mathbf{x}\,\mathrm{tr}(A)", [r"A: matrix; \mathbf{x}: vector"],
     "verified"),
    (r"\mathrm{tr}(A)A = \mathrm{tr}(A^2)A", [r"A: matrix"], "does-not-hold"),
])
def test_a_scalar_function_of_a_matrix_times_a_matrix_reads(latex, lets, verdict):
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == verdict, r.detail
