"""rigidsym audit audits the derivative of a differentiable function too (docs/audit.md,
"Gradients"): a JAX function's ``jax.jacfwd`` against the book's derivative along each
tangent direction at the same inputs; a wrong gradient behind a right value (a NaN from the
unselected branch of a ``where`` at w = 0; a ``stop_gradient`` on the axis) is a finding,
the double ``where`` passes, and a NumPy function has no derivative audited. ``extra``: JAX
is the [jax] extra."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("flint")
pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
sys.path.insert(0, str(Path(__file__).resolve().parent))
import audit_jax_examples as G  # noqa: E402

from rigidsym import audit  # noqa: E402
from rigidsym.auditing import conventions as C  # noqa: E402
from rigidsym.auditing import gradients as D  # noqa: E402
from rigidsym.auditing import report  # noqa: E402
from rigidsym.auditing.targets import target  # noqa: E402

pytestmark = pytest.mark.extra

EXP = "rotation_from_rotation_vector"


def _checks(func, regimes=("random", "w[0:3] = 0", "|w[0:3]| -> 0")):
    tgt = target(EXP)
    m = C.Member(tgt.forms[0], ())
    pts = [p for p in D.gradient_points(tgt, m, 0) if p[0] in regimes]
    return D.check_gradients(func, tgt, m, "jax", pts)


def test_the_book_derivative_is_the_formulas_across_w_0():
    """At w = 0 (the formula undefined there, sin(t)/t) the derivative of exp along e_k
    is the cross-product matrix of e_k: the difference across the removable singularity."""
    ders = D.book_derivatives(target(EXP).kernel, [[0, 0, 0]])
    assert len(ders) == 3
    for k, (_, _, der) in enumerate(ders):
        E = np.zeros(3)
        E[k] = 1.0
        want = np.cross(np.eye(3), E).T        # [e_k]x, row-major
        assert np.allclose(der, (-want).ravel(), atol=1e-30) or np.allclose(
            der, want.ravel(), atol=1e-30), der
        assert np.allclose(der.reshape(3, 3), -der.reshape(3, 3).T, atol=1e-30)


def test_a_correct_derivative_passes():
    cs = _checks(G.exp_correct)
    assert cs and all(c.err <= c.tol for c in cs), [(c.regime, c.err) for c in cs]


def test_a_nan_gradient_at_zero_is_found_there_alone():
    cs = _checks(G.exp_nan_gradient_at_zero)
    bad = {c.regime for c in cs if not c.err <= c.tol}
    assert bad == {"w[0:3] = 0"}, [(c.regime, c.err) for c in cs]


def test_a_stop_gradient_on_the_axis_is_found_everywhere():
    cs = _checks(G.exp_stop_gradient_axis, ("random",))
    assert cs and all(c.err > 0.1 for c in cs), [(c.regime, c.err) for c in cs]


def test_numpy_functions_have_no_derivative_to_audit():
    assert D.differentiable(lambda w: np.linalg.norm(w) * np.eye(3), [np.ones(3)], "jax") == ""
    assert D.differentiable(G.exp_correct, [np.ones(3)], "jax") == "jax"


@pytest.mark.slow
def test_the_audit_reports_the_wrong_gradient():
    rep = audit(G.exp_stop_gradient_axis, EXP, search=False)
    assert rep.gradients["framework"] == "jax" and rep.gradients["wrong"]
    f = [f for f in rep.findings if f.kind == "gradient"]
    assert f and f[0].severity == "error" and "where the value is right" in f[0].text
    assert "gradient" in report.markdown(rep)
    ok = audit(G.exp_correct, EXP, search=False)
    assert ok.gradients["checked"] > 5 and not ok.gradients["wrong"]
    assert not [f for f in ok.findings if f.kind == "gradient"]
