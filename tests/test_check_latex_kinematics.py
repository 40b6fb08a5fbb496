"""Kinematic differential equations of the attitude books: ``\\dot C =
-[\\omega]_\\times C`` with ``C`` a model in parameters declared functions of time, their
rates declared (``--let '\\dot{\\mathbf{q}} = ...'``) or free, for classical and modified
Rodrigues parameters, Euler parameters and two Euler-angle sequences (Schaub & Junkins'
conventions: ``C = [BN]``, ``\\omega`` in B). Each family's truth is checked first by an
independent NumPy evaluation (a central difference along the rates); each family's one-edit
slip must be does-not-hold. None may be bad input (``\\dot{\\mathbf{q}}
does not occur``, ``d/dt of a 3x3 matrix built by Cpm``)."""

from __future__ import annotations

import numpy as np
import pytest
from test_check_latex import forget_latex_ids  # noqa: F401  (autouse fixture)

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex import LatexError

W = r"\boldsymbol\omega: vector"
R1 = (r"R_1(x) = \begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos x & \sin x \\ 0 & -\sin x & \cos x "
      r"\end{bmatrix}")
R2 = (r"R_2(x) = \begin{bmatrix} \cos x & 0 & -\sin x \\ 0 & 1 & 0 \\ \sin x & 0 & \cos x "
      r"\end{bmatrix}")
R3 = (r"R_3(x) = \begin{bmatrix} \cos x & \sin x & 0 \\ -\sin x & \cos x & 0 \\ 0 & 0 & 1 "
      r"\end{bmatrix}")
ANGLES = [r"\psi(t): angle", r"\theta(t): angle", r"\phi(t): angle"]
KDE = r"\dot{\mathbf{C}} = -[\boldsymbol\omega]_\times \mathbf{C}"

#: family -> (LaTeX, --lets, (text of the one-edit slip, its replacement))
FAMILIES = {
    "CRP": (KDE, [
        r"\mathbf{C} = \frac{(1 - \mathbf{q}^T\mathbf{q}) I_3 + 2\mathbf{q}\mathbf{q}^T"
        r" - 2[\mathbf{q}]_\times}{1 + \mathbf{q}^T\mathbf{q}}",
        r"\dot{\mathbf{q}} = \frac12 (I_3 + [\mathbf{q}]_\times + \mathbf{q}\mathbf{q}^T)"
        r"\boldsymbol\omega",
        r"\mathbf{q}(t): vector", W], ("I_3 + [", "I_3 - [")),
    "MRP": (KDE, [
        r"\mathbf{C} = I_3 + \frac{8[\boldsymbol\sigma]_\times^2 - 4(1 - \boldsymbol\sigma^T"
        r"\boldsymbol\sigma)[\boldsymbol\sigma]_\times}{(1 + \boldsymbol\sigma^T"
        r"\boldsymbol\sigma)^2}",
        r"\dot{\boldsymbol\sigma} = \frac14 \left((1 - \boldsymbol\sigma^T\boldsymbol\sigma)"
        r" I_3 + 2[\boldsymbol\sigma]_\times + 2\boldsymbol\sigma\boldsymbol\sigma^T\right)"
        r"\boldsymbol\omega",
        r"\boldsymbol\sigma(t): vector", W], ("+ 2\\boldsymbol\\sigma\\boldsymbol",
                                               "- 2\\boldsymbol\\sigma\\boldsymbol")),
    "Euler parameters": (r"\dot{\mathbf{A}} = -[\boldsymbol\omega]_\times \mathbf{A}", [
        r"\mathbf{A} = (\boldsymbol\beta_{4:4}^2 - \boldsymbol\beta_{1:3}^T\boldsymbol"
        r"\beta_{1:3}) I_3 + 2\boldsymbol\beta_{1:3}\boldsymbol\beta_{1:3}^T"
        r" - 2\boldsymbol\beta_{4:4}[\boldsymbol\beta_{1:3}]_\times",
        r"\dot{\boldsymbol\beta} = \frac12 \begin{bmatrix} \boldsymbol\beta_{4:4} I_3 + "
        r"[\boldsymbol\beta_{1:3}]_\times \\ -\boldsymbol\beta_{1:3}^T \end{bmatrix}"
        r"\boldsymbol\omega",
        r"\boldsymbol\beta(t): unit 4-vector", W], ("\\\\ -\\boldsymbol", "\\\\ \\boldsymbol")),
    "3-2-1 angles": (KDE, [
        r"\mathbf{C} = R_1(\phi) R_2(\theta) R_3(\psi)", R1, R2, R3,
        r"\boldsymbol\omega = \begin{bmatrix} \dot\phi - \dot\psi\sin\theta \\ \dot\theta"
        r"\cos\phi + \dot\psi\cos\theta\sin\phi \\ \dot\psi\cos\theta\cos\phi - \dot\theta"
        r"\sin\phi \end{bmatrix}", *ANGLES], ("\\dot\\phi - \\dot\\psi", "\\dot\\phi + "
                                              "\\dot\\psi")),
    "3-1-3 angles": (KDE, [
        r"\mathbf{C} = R_3(\psi) R_1(\theta) R_3(\phi)", R1, R3,
        r"\boldsymbol\omega = \begin{bmatrix} \dot\phi\sin\theta\sin\psi + \dot\theta\cos\psi"
        r" \\ \dot\phi\sin\theta\cos\psi - \dot\theta\sin\psi \\ \dot\phi\cos\theta + "
        r"\dot\psi \end{bmatrix}", *ANGLES], ("\\cos\\theta + \\dot\\psi",
                                              "\\cos\\theta - \\dot\\psi")),
    "3-2-1 angle rates": (KDE, [
        r"\mathbf{C} = R_1(\phi) R_2(\theta) R_3(\psi)", R1, R2, R3,
        r"\boldsymbol\omega = \begin{bmatrix} p \\ q \\ r \end{bmatrix}",
        r"\dot\psi = \frac{q\sin\phi + r\cos\phi}{\cos\theta}",
        r"\dot\theta = q\cos\phi - r\sin\phi",
        r"\dot\phi = p + (q\sin\phi + r\cos\phi)\tan\theta", *ANGLES],
        ("q\\cos\\phi - r", "q\\cos\\phi + r")),
}


def _cpm(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def _rot(axis, x):
    c, s = np.cos(x), np.sin(x)
    m = {1: [[1, 0, 0], [0, c, s], [0, -s, c]], 2: [[c, 0, -s], [0, 1, 0], [s, 0, c]],
         3: [[c, s, 0], [-s, c, 0], [0, 0, 1]]}[axis]
    return np.array(m)


def test_the_families_hold_by_numpy_and_their_slips_do_not():
    """The truth of each family (and of each slip) by NumPy, independent of rigidsym: the
    derivative of C along the rates, by a central difference, against -[w]x C."""
    rng = np.random.default_rng(63)
    w, eye, h = rng.normal(size=3), np.eye(3), 1e-6

    def residual(c_of, rate, x0):
        cd = (c_of(x0 + h * rate(x0)) - c_of(x0 - h * rate(x0))) / (2 * h)
        return np.abs(cd + _cpm(w) @ c_of(x0)).max()

    def crp(q):
        return ((1 - q @ q) * eye + 2 * np.outer(q, q) - 2 * _cpm(q)) / (1 + q @ q)

    def mrp(s):
        return eye + (8 * _cpm(s) @ _cpm(s) - 4 * (1 - s @ s) * _cpm(s)) / (1 + s @ s) ** 2

    def ep(b):
        e = b[:3]
        return (b[3] ** 2 - e @ e) * eye + 2 * np.outer(e, e) - 2 * b[3] * _cpm(e)

    def c321(x):
        return _rot(1, x[2]) @ _rot(2, x[1]) @ _rot(3, x[0])

    for sign, holds in ((1, True), (-1, False)):  # the slip flips one sign
        cases = [
            (crp, lambda q, s=sign: .5 * (eye + s * _cpm(q) + np.outer(q, q)) @ w, 3),
            (mrp, lambda v, s=sign: .25 * ((1 - v @ v) * eye + 2 * _cpm(v)
                                           + s * 2 * np.outer(v, v)) @ w, 3),
            (ep, lambda b, s=sign: .5 * np.vstack([b[3] * eye + _cpm(b[:3]),
                                                   -s * b[:3]]) @ w, 4),
            (c321, lambda x, s=sign: np.array([
                (np.sin(x[2]) * w[1] + np.cos(x[2]) * w[2]) / np.cos(x[1]),
                np.cos(x[2]) * w[1] - s * np.sin(x[2]) * w[2],
                w[0] + (np.sin(x[2]) * w[1] + np.cos(x[2]) * w[2]) * np.tan(x[1])]), 3)]
        for c_of, rate, n in cases:
            x0 = rng.normal(size=n)
            if n == 4:
                x0 /= np.linalg.norm(x0)
            assert (residual(c_of, rate, x0) < 1e-8) == holds


_SLOWER = {"MRP", "3-1-3 angles"}  # in the slow run only (the README's command stays short)


@pytest.mark.parametrize("family", [pytest.param(f, marks=pytest.mark.slow) if f in _SLOWER
                                    else f for f in sorted(FAMILIES)])
def test_a_kinematic_equation_is_verified_by_both_semantics(family):
    latex, lets, _ = FAMILIES[family]
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)
    assert any("numeric cross-check" in n and "agree" in n for n in r.model), r.model


@pytest.mark.slow
@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_its_one_edit_slip_does_not_hold(family):
    latex, lets, (a, b) = FAMILIES[family]
    slipped = [x.replace(a, b, 1) for x in lets]
    assert slipped != lets
    r = rigidsym.check_latex(latex, let=slipped, repairs=False)
    assert r.verdict == "does-not-hold", (r.detail, r.model)


def test_one_slip_in_the_default_run_does_not_hold():
    latex, lets, (a, b) = FAMILIES["CRP"]
    r = rigidsym.check_latex(latex, let=[x.replace(a, b, 1) for x in lets], repairs=False)
    assert r.verdict == "does-not-hold", (r.detail, r.model)


def test_a_declared_rate_makes_its_symbol_a_function_of_time():
    """``--let '\\dot{\\mathbf{q}} = ...'`` beside ``\\mathbf{q}: vector`` (no ``(t)``)."""
    latex, lets, _ = FAMILIES["CRP"]
    r = rigidsym.check_latex(latex, let=[x.replace("(t)", "") for x in lets], repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)
    assert any("the rate of \\mathbf{q}, its --let model" in n for n in r.model), r.model


def test_a_declared_rate_alone_makes_its_symbol_a_function_of_time():
    """No --let for q at all: q a function of time of its conventional shape (a 3-vector)."""
    latex, lets, _ = FAMILIES["MRP"]
    r = rigidsym.check_latex(latex, let=[x for x in lets if "(t)" not in x], repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)


def test_a_free_rate_leaves_the_kinematic_equation_false():
    """Without the rate's model, q̇ is free: Ċ = -[ω]C then fails (ω unrelated to q̇)."""
    latex, lets, _ = FAMILIES["CRP"]
    r = rigidsym.check_latex(latex, let=[x for x in lets if not x.startswith(r"\dot")],
                             repairs=False)
    assert r.verdict == "does-not-hold", (r.detail, r.model)


@pytest.mark.parametrize("latex, lets, verdict", [
    # d/dt through a cross-product matrix, a power, a fraction (before: "d/dt of a 3x3
    # matrix built by Cpm", "Mix of Matrix and Scalar symbols")
    (r"\frac{d}{dt}[\mathbf{q}]_\times = [\dot{\mathbf{q}}]_\times", [r"\mathbf{q}(t): vector"],
     "verified"),
    (r"\frac{d}{dt}[\mathbf{q}]_\times = [\mathbf{q}]_\times", [r"\mathbf{q}(t): vector"],
     "does-not-hold"),
    (r"\frac{d}{dt}\frac{1}{1+\mathbf{q}^T\mathbf{q}} = -\frac{2\mathbf{q}^T\dot{\mathbf{q}}}"
     r"{(1+\mathbf{q}^T\mathbf{q})^2}", [r"\mathbf{q}(t): vector"], "verified"),
    (r"\frac{d}{dt}\frac{1}{1+\mathbf{q}^T\mathbf{q}} = -\frac{\mathbf{q}^T\dot{\mathbf{q}}}"
     r"{(1+\mathbf{q}^T\mathbf{q})^2}", [r"\mathbf{q}(t): vector"], "does-not-hold"),
    (r"\frac{d}{dt}(\mathbf{R}[\mathbf{q}]_\times^2) = \dot{\mathbf{R}}[\mathbf{q}]_\times^2",
     [r"\mathbf{q}: vector", r"\mathbf{R}(t): rotation"], "verified"),
    # the chain rule through partials of a matrix model (Diebel's Euler-angle rates; before:
    # "an internal error at the construct ... (mul)", sympy's unhashable matrix)
    (r"\dot{\mathbf{C}} = \dot\phi\frac{\partial \mathbf{C}}{\partial\phi} + \dot\theta"
     r"\frac{\partial \mathbf{C}}{\partial\theta}", [r"\mathbf{C} = R_1(\phi)R_2(\theta)", R1, R2,
                                                   r"\phi(t): angle", r"\theta(t): angle"],
     "verified"),
    (r"\dot{\mathbf{C}} = \dot\phi\frac{\partial \mathbf{C}}{\partial\phi}",
     [r"\mathbf{C} = R_1(\phi)R_2(\theta)", R1, R2, r"\phi(t): angle", r"\theta(t): angle"],
     "does-not-hold"),
    # Siciliano's \dot R = S(\omega) R of an elementary rotation, S a --let function
    (r"\dot{R} = S(\boldsymbol\omega) R",
     [r"R = R_z(\theta)", r"R_z(x) = \begin{bmatrix} \cos x & -\sin x & 0 \\ \sin x & \cos x"
      r" & 0 \\ 0 & 0 & 1 \end{bmatrix}", r"S(\mathbf{a}) = [\mathbf{a}]_\times",
      r"\theta(t): angle", r"\boldsymbol\omega = \begin{bmatrix}0\\0\\\dot\theta\end{bmatrix}"],
     "verified"),
])
def test_d_dt_through_the_operators_of_a_model(latex, lets, verdict):
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == verdict, (r.detail, r.model)


def test_a_rate_of_another_shape_is_refused_naming_both():
    latex, lets, _ = FAMILIES["CRP"]
    lets = [x if not x.startswith(r"\dot") else r"\dot{\mathbf{q}} = \mathbf{q}^T"
            r"\boldsymbol\omega" for x in lets]
    with pytest.raises((BadInput, LatexError)) as exc:
        rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r"\dot{\mathbf{q}}" in str(exc.value) and "3-vector" in str(exc.value), exc.value


@pytest.mark.parametrize("latex, let, introduced, says", [
    (r"\frac{d}{dt}\left(\mathbf{C}^\mathsf{T}\mathbf{C}\right) = \mathbf{0}",
     r"\mathbf{C}(t): rotation", r"\mathbf{C}_{w}",
     "C_w: the body angular velocity of C, introduced by the reader"),
    (r"\frac{d}{dt}\cos\theta = -\dot\theta\sin\theta", r"\theta(t): angle",
     r"\dot{\theta}", r"\dot{\theta}: the time derivative of \theta"),
])
def test_a_rate_the_reader_introduces_is_said_as_what_it_is_not_as_the_users(latex, let,
                                                                              introduced, says):
    """The body velocity of a rotation declared a function of time, and a scalar's rate, are
    the reader's own symbols: the reading says what each is, and the list of the user's
    undeclared symbols ("free, no --let declares them") does not name them."""
    r = rigidsym.check_latex(latex, let=[let], repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)
    assert any(says in " ".join(n.split()) for n in r.model), r.model
    assert not any(n.startswith("free, no --let") and introduced in n for n in r.model), r.model


@pytest.mark.parametrize("latex, verdict", [
    (r"\dot{\mathbf{Q}} = \mathbf{Q}[\mathbf{Q}_{w}]_\times", "does-not-hold"),
    (r"\mathbf{Q}^T\dot{\mathbf{Q}} + \dot{\mathbf{Q}}^T\mathbf{Q} = \mathbf{0}", "verified"),
])
def test_a_users_glyph_spelt_as_the_readers_body_velocity_stays_the_users(latex, verdict):
    r"""A user's own ``\mathbf{Q}_{w}`` (any 3-vector) beside ``\mathbf{Q}(t)``: the reader's
    body velocity of Q takes another name, so ``\dot Q = Q [Q_w]_x`` does not hold for the
    user's free Q_w (one symbol for both verified it, and only the numeric cross-check
    stood in the way); an unused one is said back, never a near miss of the reader's own
    (beside the declared Q, of its letter, it is the shared line: noted and ignored)."""
    lets = [r"\mathbf{Q}(t): rotation", r"\mathbf{Q}_{w}: 3-vector"]
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == verdict, (r.detail, r.model)
    if verdict != "does-not-hold":  # unused: said back, and the reader's own never named
        assert any(m.startswith("not used: ") for m in r.model), r.model
        assert not any("w2" in m for m in r.model), r.model
        return
    point = r.counterexample["point"]  # the user's Q_w and the reader's differ at the point
    mine = [point[f"Q_w_{i}"] for i in (1, 2, 3)]
    assert mine != [point.get(f"Q_w2_{i}") for i in (1, 2, 3)], point


ARNOLD = [r"B(t): rotation", r"\Omega: body angular velocity of B", r"m: vector",
          r"M = B^{-1}m"]


def test_arnolds_bracket_of_two_3_vectors_is_the_cross_product():
    r"""Arnold's Euler equation ``\frac{dM}{dt} = [M, \Omega]`` (sec. 28; his ``[a, b]`` is the
    vector product, the bracket of so(3)) holds for ``m = BM`` constant; the factors swapped
    it does not, and the bracket is said back as read."""
    r = rigidsym.check_latex(r"\frac{dM}{dt} = [M, \Omega]", repairs=False, let=ARNOLD)
    assert r.verdict == "verified", r.detail
    assert any("bracket of so(3)" in m for m in r.model), r.model
    slip = rigidsym.check_latex(r"\frac{dM}{dt} = [\Omega, M]", repairs=False, let=ARNOLD)
    assert slip.verdict == "does-not-hold", slip.detail


def test_a_refusal_never_names_the_readers_own_body_velocity():
    r"""A bracket of two 6-vectors (not read: the bracket of se(3) depends on the tangent
    order) beside ``B(t)``: the refusal says what to write and never asks the user to
    declare ``B_{w}``, the body velocity the reader introduces for ``B(t)`` (a symbol the
    user did not write)."""
    with pytest.raises((BadInput, LatexError)) as exc:
        rigidsym.check_latex(r"\frac{d\mathbf{t}}{dt} = [\mathbf{t}, \mathbf{s}] + B\Omega",
                             repairs=False, let=[*ARNOLD, r"\mathbf{t}: twist",
                                                 r"\mathbf{s}: twist"])
    assert r"\wedge" in str(exc.value) and "B_{w}" not in str(exc.value), exc.value


# ---- a --let model used only through its rate or its entries (Lee's e_R, Hanson's q)
LEE = [r"R(t): rotation", r"R_d(t): rotation", r"\Omega: body angular velocity of R",
       r"\Omega_d: body angular velocity of R_d", r"e_R = \frac12(R_d^TR - R^TR_d)^\vee",
       r"e_\Omega = \Omega - R^TR_d\Omega_d"]


@pytest.mark.parametrize("sign, verdict", [("R^TR_d", "verified"),
                                           ("R_d^TR", "does-not-hold")])
def test_model_read_only_through_its_rate(sign, verdict):
    """``\\dot{e}_R`` of the model ``e_R`` (Lee, Leok & McClamroch): d/dt of the model, and
    the model used by it (never 'e_R does not occur', never a free rate)."""
    r = rigidsym.check_latex(rf"\dot{{e}}_R = \frac12(\operatorname{{tr}}[R^TR_d]I - {sign})"
                             r"e_\Omega", let=LEE, repairs=False)
    assert r.verdict == verdict


def test_rate_of_a_model_in_explicit_time_is_refused_not_free():
    """``\\dot\\omega_1`` of ``--let '\\omega_1 = \\omega_0\\cos\\Omega t'``: the reader takes
    d/dt only along the declared functions of time, so it is refused, never a free scalar
    unrelated to the model (which would decide a wrong verdict)."""
    with pytest.raises(BadInput, match=r"time derivative of \\omega_\{1\}"):
        rigidsym.check_latex(r"\dot\omega_1 = -\omega_0\Omega\sin\Omega t",
                             let=[r"\Omega: scalar", r"\omega_1 = \omega_0\cos\Omega t"],
                             repairs=False)


Q_R = (r"R = \begin{bmatrix} q_0^2 + q_1^2 - q_2^2 - q_3^2 & 2q_1q_2 - 2q_0q_3 & 2q_1q_3 + "
       r"2q_0q_2 \\ 2q_1q_2 + 2q_0q_3 & q_0^2 - q_1^2 + q_2^2 - q_3^2 & 2q_2q_3 - 2q_0q_1 \\ "
       r"2q_1q_3 - 2q_0q_2 & 2q_2q_3 + 2q_0q_1 & q_0^2 - q_1^2 - q_2^2 + q_3^2 \end{bmatrix}")


@pytest.mark.parametrize("sign, verdict", [("+", "verified"), ("-", "does-not-hold")])
def test_model_vector_used_only_through_its_entries(sign, verdict):
    """Hanson's ``q`` model, used only as ``q_0 ... q_3`` in R's model: read first (R after
    it), its entries counted from 0 as written, and used."""
    r = rigidsym.check_latex(
        rf"R = \cos\theta\,I_3 + (1 - \cos\theta)\hat{{\mathbf{{n}}}}\hat{{\mathbf{{n}}}}^T "
        rf"{sign} \sin\theta[\hat{{\mathbf{{n}}}}]_\times",
        let=[r"\hat{\mathbf{n}}: unit vector", r"\theta: angle",
             r"q = \begin{bmatrix} \cos\frac{\theta}{2} \\ \hat{\mathbf{n}}\sin\frac{\theta}{2}"
             r" \end{bmatrix}", Q_R], repairs=False)
    assert r.verdict == verdict


# ---- a dot over a glyph with a subscript and a capital label: Savage's \dot{C}_B^I
SAVAGE = [r"\boldsymbol\phi(t): vector", r"\phi = |\boldsymbol\phi|",
          r"C_B^I = I + \frac{\sin\phi}{\phi}(\boldsymbol\phi\times) + \frac{1 - \cos\phi}"
          r"{\phi^2}(\boldsymbol\phi\times)(\boldsymbol\phi\times)",
          r"\boldsymbol\omega_{IB}^B: vector"]
BORTZ = (r"\dot{{\boldsymbol\phi}} = \boldsymbol\omega_{{IB}}^B {} \frac12\boldsymbol\phi\times"
         r"\boldsymbol\omega_{{IB}}^B + \frac{{1}}{{\phi^2}}\left(1 - \frac{{\phi\sin\phi}}"
         r"{{2(1 - \cos\phi)}}\right)\boldsymbol\phi\times(\boldsymbol\phi\times"
         r"\boldsymbol\omega_{{IB}}^B)")


@pytest.mark.parametrize("sign, verdict", [("+", "verified"), ("-", "does-not-hold")])
def test_dot_over_a_labelled_glyph(sign, verdict):
    """``\\dot{C}_B^I``: the rate of the model ``C_B^I`` (the label part of the name), in both
    semantics; ``C_B^I(\\boldsymbol\\omega\\times)`` a product (C's model does not depend on
    omega, so no application is read by either)."""
    r = rigidsym.check_latex(r"\dot{C}_B^I = C_B^I(\boldsymbol\omega_{IB}^B\times)",
                             let=[*SAVAGE, BORTZ.format(sign)], repairs=False)
    assert r.verdict == verdict


#: Taylor (2005) ch. 10, the free symmetric top: a model in the time t itself
TOP = r"\lambda_1\dot\omega_1 - (\lambda_2 - \lambda_3)\omega_2\omega_3 = 0"
TOP_LETS = [r"\lambda_2 = \lambda_1",
            r"\Omega = \frac{(\lambda_3 - \lambda_1)\omega_3}{\lambda_1}",
            r"\omega_1 = \omega_0\cos\Omega t", r"\omega_2 = \omega_0\sin\Omega t"]


def test_the_rate_of_a_model_in_t_itself_is_refused_saying_what_to_write():
    import re

    with pytest.raises(ValueError, match=r"written in the time t itself") as e:
        rigidsym.check_latex(TOP, let=TOP_LETS, repairs=False)
    said = re.findall(r"--let '([^']*)'", str(e.value))[:3]
    assert said == [r"\theta(t): angle", r"\dot\theta = \Omega", r"\omega_{1} = \omega_0\cos\theta"]
    # what it says, written for both models, decides the statement and its slip
    lets = [x.replace(r"\Omega t", r"\theta") for x in TOP_LETS] + said[:2]
    assert rigidsym.check_latex(TOP, let=lets, repairs=False).verdict == "verified"
    slip = [x.replace(r"= \omega_0\sin", r"= -\omega_0\sin") for x in lets]
    assert rigidsym.check_latex(TOP, let=slip, repairs=False).verdict == "does-not-hold"


# quick: the accented vector's entry (the case that was refused); the plain one thorough
@pytest.mark.parametrize("q, rhs, verdict", [
    (r"\bar{q}", "2a", "verified"), (r"\bar{q}", "3a", "does-not-hold"),
    pytest.param(r"\boldsymbol\beta", "2a", "verified", marks=pytest.mark.slow),
    pytest.param(r"\boldsymbol\beta", "3a", "does-not-hold", marks=pytest.mark.slow)])
def test_an_entry_of_a_vector_follows_its_declared_rate_accented_or_not(q, rhs, verdict):
    r"""``a = \bar{q}_{1:1}`` with ``\dot{\bar{q}} = 2\bar{q}``: both semantics move the entry
    along the declared rate (the second moved an accented vector's entry along a random
    motion of its own, and refused Wen & Kreutz-Delgado's true kinematic equation as a
    disagreement while any slip of it passed its cross-check)."""
    r = rigidsym.check_latex(rf"\dot{{a}} = {rhs}", repairs=False, let=[
        rf"{q}(t): 4-vector", rf"\dot{{{q}}} = 2{q}", rf"a = {q}_{{1:1}}"])
    assert r.verdict == verdict, r.detail
    assert "the sides" in r.model[-1], r.model


def test_the_second_rate_of_a_rotation_needs_its_angular_velocitys_rate():
    r"""``\ddot{\mathbf{Q}}`` of a rotation ``\mathbf{Q}(t)``: with no rate of its angular
    velocity it is refused saying what to declare (it was a free matrix: the true
    tr(Q'' Q^T + Q' Q'^T) = 0 came out does-not-hold, and only the cross-check stood in the
    way); with the rate declared, decided both ways."""
    true = r"\mathrm{tr}(\ddot{\mathbf{Q}}\mathbf{Q}^T + \dot{\mathbf{Q}}\dot{\mathbf{Q}}^T) = 0"
    with pytest.raises((BadInput, LatexError)) as exc:
        rigidsym.check_latex(true, let=[r"\mathbf{Q}(t): rotation"], repairs=False)
    assert r"\boldsymbol\omega(t): vector" in str(exc.value), exc.value
    rate = [r"\mathbf{Q}(t): rotation", r"\boldsymbol\omega(t): vector",
            r"\dot{\mathbf{Q}} = \mathbf{Q}[\boldsymbol\omega]_\times"]
    assert rigidsym.check_latex(true, let=rate, repairs=False).verdict == "verified"
    slip = r"\mathrm{tr}(\ddot{\mathbf{Q}}\mathbf{Q}^T) = 0"
    assert rigidsym.check_latex(slip, let=rate, repairs=False).verdict == "does-not-hold"
