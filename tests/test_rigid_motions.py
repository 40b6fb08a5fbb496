"""The vocabulary of rigid motions against numeric ground truth.

Each word's model is evaluated at random numbers and compared with what it must equal,
computed independently: scipy's ``expm`` for the exponentials, numpy's cross product,
inverse and the conjugation ``T [V] T^-1`` for hat, Ad and ad, central differences for
``diff``; and the principal branches of ``acos``/``atan2`` by the checker's verdicts.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

scipy_linalg = pytest.importorskip("scipy.linalg", reason="scipy is in the [test] extra")

from rigidsym import (  # noqa: E402  (after the skip)
    ORDERS,
    Ad,
    BadInput,
    Rel,
    Statement,
    acos,
    ad,
    ad_dual,
    angle,
    atan2,
    cpm,
    diff,
    equation,
    expm,
    hat,
    logm,
    mat,
    rotation_from_natural_invariants,
    trace,
    transform,
    transform_inverse,
    twist,
    unit_vector,
    vector,
    vee,
    wrench,
)
from rigidsym.checking.checker import check  # noqa: E402
from rigidsym.core import kinds as _kinds  # noqa: E402  (after the skip)
from rigidsym.registry.declarations import REGISTRY  # noqa: E402

w, th = unit_vector("rm_w"), angle("rm_th")
v = vector("rm_v")
rng = np.random.default_rng(28)


def _num(M, values: dict) -> np.ndarray:
    return np.array(sp.Matrix(M).xreplace(values).evalf(), dtype=float)


def _unit():
    x = rng.standard_normal(3)
    return x / np.linalg.norm(x)


def _values(wn, thn, vn=None):
    out = {a: sp.Float(x, 30) for a, x in zip(w, wn, strict=True)}
    out[th] = sp.Float(thn, 30)
    if vn is not None:
        out.update({a: sp.Float(x, 30) for a, x in zip(v, vn, strict=True)})
    return out


def _hat6(V):
    W = np.array([[0, -V[2], V[1]], [V[2], 0, -V[0]], [-V[1], V[0], 0]])
    return np.block([[W, V[3:].reshape(3, 1)], [np.zeros((1, 4))]])


@pytest.mark.parametrize("k", range(3))
def test_expm_of_so3_is_scipys(k):
    wn, thn = _unit(), rng.uniform(-3, 3)
    R = _num(expm(th * cpm(w)), _values(wn, thn))
    W = np.array(_num(cpm(w), _values(wn, thn)))
    np.testing.assert_allclose(R, scipy_linalg.expm(thn * W), atol=1e-12)


@pytest.mark.parametrize("k", range(3))
def test_expm_of_se3_is_scipys(k):
    wn, thn, vn = _unit(), rng.uniform(-3, 3), rng.standard_normal(3)
    S = sp.Matrix.vstack(w, v)
    T = _num(expm(th * hat(S)), _values(wn, thn, vn))
    np.testing.assert_allclose(T, scipy_linalg.expm(thn * _hat6(np.r_[wn, vn])), atol=1e-12)


@pytest.mark.parametrize("k", range(3))
def test_logm_is_scipys_on_the_principal_branch(k):
    wn, thn = _unit(), rng.uniform(0.1, 3.0)
    Rn = scipy_linalg.expm(thn * _hat6(np.r_[wn, 0, 0, 0])[:3, :3])
    np.testing.assert_allclose(_num(logm(sp.Matrix(Rn)), {}), scipy_linalg.logm(Rn).real,
                               atol=1e-10)


@pytest.mark.usefixtures("_forget")
def test_logm_of_rodrigues_is_theta_omega_on_either_range():
    # the log of the rotation by theta about w is theta [w] for theta in (-pi, pi) too:
    # R(theta, w) = R(-theta, -w), and acos's split covers both cases
    R, Om = mat("R"), mat("Om")
    for a in (angle("rm_tl", range="[0, pi]"), th):
        out = _verdict(f"rm:logm-{a}", [Rel(logm(R), a * Om)],
                       {R: rotation_from_natural_invariants(w, a), Om: cpm(w)})
        assert out.verdict == "verified", out.detail


def test_expm_of_a_pure_translation_and_a_free_axis():
    e = unit_vector("rm_e")
    S = sp.Matrix.vstack(sp.zeros(3, 1), e)
    T = expm(th * hat(S))
    assert T[:3, :3] == sp.eye(3) and T[:3, 3] == e * th
    # a free axis: the closed form in the norm theta = |w|, not Rodrigues'
    # unit-axis form (which would be false); against scipy's expm at a point
    R = expm(cpm(v))
    vn = {x: c for x, c in zip(v, (0.3, -1.1, 0.7), strict=True)}
    np.testing.assert_allclose(np.array(R.subs(vn), dtype=float),
                               scipy_linalg.expm(np.array(cpm(v).subs(vn), dtype=float)),
                               rtol=1e-14, atol=1e-14)


def test_hat_vee_transform_and_inverse():
    V = np.r_[rng.standard_normal(3), rng.standard_normal(3)]
    Vs = sp.Matrix(V)
    np.testing.assert_allclose(_num(hat(Vs), {}), _hat6(V))
    assert sp.Matrix(vee(hat(Vs))) == Vs
    x = rng.standard_normal(3)
    np.testing.assert_allclose(_num(hat(sp.Matrix(x)), {}) @ V[:3], np.cross(x, V[:3]))
    R = scipy_linalg.expm(_hat6(np.r_[_unit(), 0, 0, 0])[:3, :3])
    T = transform(sp.Matrix(R), sp.Matrix(x))
    np.testing.assert_allclose(_num(transform_inverse(T), {}), np.linalg.inv(_num(T, {})),
                               atol=1e-12)


def test_Ad_is_the_conjugation_and_ad_the_bracket():
    Tn = scipy_linalg.expm(_hat6(rng.standard_normal(6)))
    V1, V2 = rng.standard_normal(6), rng.standard_normal(6)
    AdT = _num(Ad(sp.Matrix(Tn)), {})
    np.testing.assert_allclose(_hat6(AdT @ V1), Tn @ _hat6(V1) @ np.linalg.inv(Tn),
                               atol=1e-12)  # MR (3.83)
    adV = _num(ad(sp.Matrix(V1)), {})
    bracket = _hat6(V1) @ _hat6(V2) - _hat6(V2) @ _hat6(V1)
    np.testing.assert_allclose(_hat6(adV @ V2), bracket, atol=1e-12)  # MR (8.38)
    F = rng.standard_normal(6)  # the dual: <ad*_V F, W> = -<F, ad_V W>
    np.testing.assert_allclose((_num(ad_dual(sp.Matrix(V1)), {}) @ F) @ V2,
                               -F @ (adV @ V2), atol=1e-12)


@pytest.mark.parametrize("order", sorted(ORDERS))
def test_every_order_is_the_same_operator_on_swapped_blocks(order):
    V = rng.standard_normal(6)
    Vo = np.r_[V[3:], V[:3]] if ORDERS[order] else V  # the twist written in that order
    P = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]]) \
        if ORDERS[order] else np.eye(6)
    Tn = sp.Matrix(scipy_linalg.expm(_hat6(rng.standard_normal(6))))
    np.testing.assert_allclose(_num(hat(sp.Matrix(Vo), order), {}), _hat6(V))
    np.testing.assert_allclose(_num(Ad(Tn, order), {}), P @ _num(Ad(Tn), {}) @ P, atol=1e-12)
    np.testing.assert_allclose(_num(ad(sp.Matrix(Vo), order), {}),
                               P @ _num(ad(sp.Matrix(V)), {}) @ P, atol=1e-12)
    with pytest.raises(ValueError, match="order: expected one of"):
        hat(sp.Matrix(V), "featherstone-ish")


def test_diff_is_the_central_difference():
    wn, thn, h = _unit(), 0.7, 1e-6
    W = _num(cpm(w), _values(wn, thn))
    d = _num(diff(expm(th * cpm(w)), th), _values(wn, thn))
    fd = (scipy_linalg.expm((thn + h) * W) - scipy_linalg.expm((thn - h) * W)) / (2 * h)
    np.testing.assert_allclose(d, fd, atol=1e-8)
    Om = mat("Om")
    assert diff(Om, th).shape == (3, 3)  # lazy on a book symbol
    with pytest.raises(ValueError, match="v: expected a sympy symbol"):
        diff(Om, 2)


def test_twist_and_wrench_rows_and_shapes():
    assert twist("V").shape == (6, 1) and wrench("F").shape == (6, 1)
    assert _kinds.for_spec("twist", (6,)).name == "twist"
    assert _kinds.for_spec("wrench", (6,)).name == "wrench"
    assert _kinds.for_spec("angle_0_pi", ()).check(np.array([4.0]), "t", 1e-12)
    with pytest.raises(ValueError, match="x: operands of shapes|hat"):
        hat(sp.Matrix([1, 2, 3, 4]))
    with pytest.raises(ValueError, match="range: expected one of"):
        angle("x", range="[0, 2pi)")


# ------------------------------------------------------------- principal branches, verdicts
@pytest.fixture
def _forget():
    yield
    for k in [k for k in REGISTRY if k.startswith("rm:")]:
        del REGISTRY[k]


def _verdict(eq_id, rels, model=None):
    equation(eq_id, eq_id)(lambda: Statement(rels, model or {}))
    return check(eq_id, repairs=False)


@pytest.mark.usefixtures("_forget")
def test_the_log_trace_formula_holds_on_0_pi_only():
    # MR (3.54): theta = acos((tr R - 1) / 2); false for theta < 0 (acos(cos t) = |t|)
    R = mat("R")
    tp = angle("rm_tp", range="[0, pi]")
    ok = _verdict("rm:acos-pi", [Rel(tp, acos((trace(R) - 1) / 2))],
                  {R: rotation_from_natural_invariants(w, tp)})
    assert ok.verdict == "verified"
    bad = _verdict("rm:acos-default", [Rel(th, acos((trace(R) - 1) / 2))],
                   {R: rotation_from_natural_invariants(w, th)})
    assert bad.verdict == "does-not-hold"
    assert bad.numeric["printed_enclosure"] and "0 ∉" not in bad.detail  # a ball excludes 0


@pytest.mark.usefixtures("_forget")
def test_atan2_of_a_scaled_sine_and_cosine():
    assert _verdict("rm:atan2", [Rel(th, atan2(3 * sp.sin(th), 3 * sp.cos(th)))]).verdict \
        == "verified"
    # a negative radius is the angle plus pi: no rewrite, and never verified
    assert _verdict("rm:atan2-neg", [Rel(th, atan2(-sp.sin(th), -sp.cos(th)))]).verdict \
        != "verified"


def test_matrix_functions_are_refused_with_the_word():
    with pytest.raises(BadInput, match="rigidsym.expm"):
        Rel(sp.exp(th * mat("Om")), mat("R"))


def test_every_word_prints_in_book_notation_and_mathml():
    from rigidsym.printing.mathml import latex_to_mathml
    from rigidsym.printing.notation import latex, text

    R, p, T, V, Om = mat("R"), sp.MatrixSymbol("p", 3, 1), sp.MatrixSymbol("T", 4, 4), \
        sp.MatrixSymbol("V", 6, 1), mat("Om")
    want = {hat(V): "[V]", vee(T): "vee(T)", transform(R, p): "T(R, p)",
            transform_inverse(T): "T⁻¹", Ad(T): "Ad(T)", ad(V): "ad(V)",
            ad_dual(V): "ad*(V)", expm(th * Om): "exp(rm_th Om)", diff(R, th): "dR/drm_th",
            logm(R): "log(R)"}
    for expr, shown in want.items():
        assert text(expr) == shown
        m = latex_to_mathml(latex(expr))
        assert m.startswith("<math") and "merror" not in m, shown
