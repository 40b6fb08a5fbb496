"""Names as the attitude books write them: superscript labels, an accent
over a subscripted letter either way, Hughes' ``\\epsilon^\\times``, font macros, a declared
``e`` before ``^``, functions beside their barred namesakes; an index range as a ``--let``
NAME refused naming the ``--let`` that settles it; no refusal ends in an empty "expected one
of:" and none leaks an exception's text."""

from __future__ import annotations

import numpy as np
import pytest
from test_check_latex import forget_latex_ids  # noqa: F401  (autouse fixture)

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex import LatexError


def _v(latex, let=None):
    return rigidsym.check_latex(latex, let=let, repairs=False).verdict


def test_the_truth_of_the_name_cases_by_numpy():
    """eps^x a = eps x a, and not a x eps; the shadow MRP's norm is 1/|sigma|."""
    rng = np.random.default_rng(63)
    eps, a, s = rng.normal(size=(3, 3))
    cpm = np.array([[0, -eps[2], eps[1]], [eps[2], 0, -eps[0]], [-eps[1], eps[0], 0]])
    assert np.allclose(cpm @ a, np.cross(eps, a))
    assert not np.allclose(cpm @ a, np.cross(a, eps))
    shadow = -s / (s @ s)
    assert np.isclose(np.linalg.norm(shadow) ** 2, 1 / (s @ s))
    assert not np.isclose(np.linalg.norm(shadow) ** 2, s @ s)


@pytest.mark.parametrize("latex, let, verdict", [
    # Hughes' cross-product matrix, braced or not (before: "unexpected \times")
    (r"\boldsymbol\epsilon^\times\mathbf{a} = \boldsymbol\epsilon\times\mathbf{a}", None,
     "verified"),
    (r"\boldsymbol\epsilon^{\times}\mathbf{a} = \mathbf{a}\times\boldsymbol\epsilon", None,
     "does-not-hold"),
    # a superscript label is part of the name (before: "unexpected 'S'")
    (r"\|\boldsymbol\sigma^S\|^2 = \frac{1}{\boldsymbol\sigma^T\boldsymbol\sigma}",
     [r"\boldsymbol\sigma^S = \frac{-\boldsymbol\sigma}{\boldsymbol\sigma^T\boldsymbol\sigma}"],
     "verified"),
    (r"\|\boldsymbol\sigma^{S}\|^2 = \boldsymbol\sigma^T\boldsymbol\sigma",
     [r"\boldsymbol\sigma^S = \frac{-\boldsymbol\sigma}{\boldsymbol\sigma^T\boldsymbol\sigma}"],
     "does-not-hold"),
    (r"\mathbf{x}^{(k)}\cdot\mathbf{x}^{(k)} = \|\mathbf{x}^{(k)}\|^2", None, "verified"),
    # \dot{\Omega}_1 is \dot{\Omega_1} (before: "\dot{\Omega_{1}} does not occur")
    (r"\dot{\Omega}_1 = a", [r"\dot{\Omega_1} = a"], "verified"),
    (r"\frac{d}{dt}\cos\theta_1 = -\dot\theta_1\sin\theta_1", [r"\theta_1(t): angle"],
     "verified"),
    (r"\frac{d}{dt}\cos\theta_1 = \dot{\theta_1}\sin\theta_1", [r"\theta_1(t): angle"],
     "does-not-hold"),
    # fonts that name (before: "unknown macro \mathtt", "\mathsf{R} (a font) cannot be read")
    (r"\mathtt{R}^T\mathtt{R} = I", [r"\mathtt{R}: rotation"], "verified"),
    (r"\mathsf{R}\mathsf{R} = I", [r"\mathsf{R}: rotation"], "does-not-hold"),
    # a left index before an accent (before: "unexpected \tilde (an accent)")
    (r"{}^{G}\tilde r_{C} + \mathbf{0} = {}^G\tilde{r}_C", [r"{}^{G}\tilde r_{C}: vector"],
     "verified"),
    (r"{}^{G}\tilde r_{C} = -{}^G\tilde{r}_C", [r"{}^{G}\tilde r_{C}: vector"], "does-not-hold"),
    # a declared e before ^ is its power (before: "unexpected '2'")
    (r"e^2 = \mathbf{e}^T\mathbf{e}", [r"e = |\mathbf{e}|"], "verified"),
    (r"e^2 = 2\mathbf{e}^T\mathbf{e}", [r"e = |\mathbf{e}|"], "does-not-hold"),
    # a function beside its barred namesake (before: "Q does not occur in the LaTeX")
    (r"Q(\mathbf{q}) = \bar Q(\mathbf{q})", [r"Q(\mathbf{q}) = \mathbf{q}\mathbf{q}^T",
                                             r"\bar Q(\mathbf{p}) = \mathbf{p}\mathbf{p}^T"],
     "verified"),
    (r"Q(\mathbf{q}) = \bar Q(\mathbf{q})", [r"Q(\mathbf{q}) = \mathbf{q}\mathbf{q}^T",
                                             r"\bar Q(\mathbf{p}) = \mathbf{p}^T\mathbf{p}I_3"],
     "does-not-hold"),
])
def test_a_name_of_the_books_reads_in_both_semantics(latex, let, verdict):
    r = rigidsym.check_latex(latex, let=let, repairs=False)
    assert r.verdict == verdict, (r.detail, r.model)
    assert any("numeric cross-check" in n for n in r.model), r.model


_RX = (r"\begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\phi & \sin\phi \\ 0 & -\sin\phi & \cos\phi "
       r"\end{bmatrix}")


@pytest.mark.parametrize("name", [r"R_{v2}^b", r"R^b_{v2}", r"R_v^{v1}", r"R_v^b"])
def test_a_function_named_with_a_superscript_frame_label_reads(name):
    """Beard & McLain's R_{v2}^b(phi) as a --let function (before: "the name 'R_{v2}^b'
    cannot be read: unexpected 'b'"), the label before or after the subscript; R(phi)
    R(-phi) = I, and not R(phi) R(phi) = I."""
    let = [r"\phi: angle", f"{name}(\\phi) = {_RX}"]
    assert _v(f"{name}(\\phi){name}(-\\phi) = I_3", let) == "verified"
    assert _v(f"{name}(\\phi){name}(\\phi) = I_3", let) == "does-not-hold"


def test_a_labelled_model_applied_to_itself_is_a_product_said_as_typed():
    """R_{v2}^b (R_{v2}^b)^T, R_{v2}^b a model: the application reading is dropped (a model
    never depends on itself), and no note or message names the reader's respelling."""
    let = [r"\phi: angle", f"R_{{v2}}^b = {_RX}"]
    r = rigidsym.check_latex(r"R_{v2}^b (R_{v2}^b)^T = I", let=let, repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)
    assert not any("^{(b)}" in m or "^(b)" in m for m in r.model), r.model
    assert _v(r"R_{v2}^b (R_{v2}^b) = I", let) == "does-not-hold"
    with pytest.raises(ValueError) as exc:  # a refusal names the label as typed
        _v(r"R_{v2}^b = \mathbf{a}", [*let, r"\mathbf{a}: vector"])
    assert "R_{v2}^b" in str(exc.value) and "(b)" not in str(exc.value), str(exc.value)


@pytest.mark.parametrize("rhs, verdict", [
    (r"\boldsymbol\omega\times(\boldsymbol\omega\times\mathbf{r}')", "verified"),
    (r"(\boldsymbol\omega\times\mathbf{r}')\times\boldsymbol\omega", "does-not-hold")])
def test_a_rate_accent_before_a_prime_is_the_rate_of_the_declared_primed_glyph(rhs, verdict):
    r"""Fowles & Cassiday's ``\ddot{\mathbf{r}}'`` beside a declared ``\mathbf{r}'(t)``: the
    acceleration of r' (before: a glyph of its own the cross-check refused, naming no
    --let to write)."""
    let = [r"\mathbf{r}'(t): vector", r"\boldsymbol\omega: vector",
           r"\dot{\mathbf{r}'} = \boldsymbol\omega\times\mathbf{r}'"]
    assert _v(rf"\ddot{{\mathbf{{r}}}}' = {rhs}", let) == verdict


@pytest.mark.parametrize("accent", [r"\tilde", r"\widetilde"])
def test_a_prime_after_an_accent_reads_inside_where_only_the_primed_glyph_is_declared(accent):
    r"""Nikravesh's tilde of omega', typed \tilde{\boldsymbol\omega}' (before: the glyph
    \tilde{\boldsymbol{\omega}}' of its own, the declared omega' "does not occur")."""
    let = [r"\boldsymbol\omega' = 2\mathbf{b}", r"\mathbf{b}: vector"]
    r = rigidsym.check_latex(f"{accent}{{\\boldsymbol\\omega}}'\\mathbf{{b}} = \\mathbf{{0}}",
                             let=let, repairs=False)
    assert r.verdict == "verified", (r.detail, r.model)   # (2b) x b = 0
    assert any(r"read as " + accent + r"{\boldsymbol\omega'}" in n for n in r.model), r.model
    slip = f"{accent}{{\\boldsymbol\\omega}}'\\mathbf{{b}} = \\mathbf{{b}}"
    assert _v(slip, let) == "does-not-hold"
    # the accented glyph declared itself: a name of its own, as typed
    own = [f"{accent}{{\\boldsymbol\\omega}}' = 2\\mathbf{{b}}", r"\mathbf{b}: vector"]
    assert _v(f"{accent}{{\\boldsymbol\\omega}}' = 2\\mathbf{{b}}", own) == "verified"


def test_a_declared_e_is_said_and_an_undeclared_e_stays_the_exponential():
    r = rigidsym.check_latex(r"e^2 = \mathbf{e}^T\mathbf{e}", let=[r"e = |\mathbf{e}|"],
                             repairs=False)
    assert any("e^: a power of the declared symbol e" in n for n in r.model), r.model
    assert _v(r"e^{[\mathbf{a}]_\times} = I_3 + [\mathbf{a}]_\times", None) != "verified"
    with pytest.raises(LatexError) as exc:
        _v(r"e^2 = \mathbf{e}^T\mathbf{e}")
    assert "--let 'e: scalar'" in str(exc.value)


def test_an_index_range_as_a_let_name_names_the_let_that_settles_it():
    with pytest.raises(BadInput) as exc:
        _v(r"\mathbf{q}_{1:3}^T\mathbf{q}_{1:3} = 1", [r"\mathbf{q}_{1:3}: vector"])
    msg = str(exc.value)
    assert r"entries 1 to 3 of \mathbf{q}" in msg and r"--let '\mathbf{q}: 4-vector'" in msg


@pytest.mark.parametrize("let", ["t: scalar", "t = 3"])
def test_a_let_of_t_says_t_is_time(let):
    """``t`` is the time every ``X(t)`` depends on: a ``--let`` of it says so and names
    another spelling (before: "expected one symbol as NAME", as if ``t`` were no glyph)."""
    with pytest.raises(BadInput) as exc:
        _v("x = t^2", [let])
    assert "t is time" in str(exc.value) and r"\tau" in str(exc.value), exc.value


#: refusals of the trial: none may leak an exception's text or end in an empty list
_REFUSED = [
    (r"{}^{G}\tilde r_{C} = 0", None),
    (r"\mathbf{a}^S_1 = x", None),
    (r"e^2 = 1", None),
    (r"\mathbf{Q}^T\mathbf{Q} = ", None),
    (r"\frac{d}{dt}\mathbf{C} = 0", [r"\mathbf{C} = [\mathbf{q}]_\times"]),
    (r"\dot{\mathbf{C}} = -[\boldsymbol\omega]_\times \mathbf{C}",
     [r"\mathbf{C} = I_3", r"\dot{\mathbf{q}} = \boldsymbol\omega"]),
    (r"\mathbf{q}_{1:3} = \mathbf{q}_{1:3}", [r"\mathbf{q}_{1:3}: vector"]),
    (r"\boldsymbol\epsilon^\times = \boldsymbol\epsilon^T", [r"\boldsymbol\epsilon: matrix"]),
    (r"\frac{d}{dt}e^{[\mathbf{q}]_\times} = 0", [r"\mathbf{q}(t): vector"]),
]
_LEAKS = ("Error:", "object has no attribute", "unhashable", "Traceback", "MutableDense",
          "MatrixSymbol", "MatMul", "MatAdd", "ImmutableDense", "ShapeError", "Mix of Matrix",
          "NoneType")


@pytest.mark.parametrize("latex, let", _REFUSED)
def test_a_refusal_names_its_construct_and_leaks_nothing(latex, let):
    with pytest.raises((BadInput, LatexError)) as exc:
        _v(latex, let)
    msg = str(exc.value)
    assert not any(w in msg for w in _LEAKS), msg
    assert not msg.rstrip().endswith("expected one of:"), msg


@pytest.mark.parametrize("latex, verdict", [
    (r"\mathbf{a}^S_1\cdot\mathbf{a}^S_1 = 1", "verified"),   # the label before the subscript
    (r"\mathbf{a}^S_1\cdot\mathbf{a}_1^S = 1", "verified"),   # both spellings, one glyph
    (r"\mathbf{a}^S_1\cdot\mathbf{a}^S_1 = 2", "does-not-hold"),
])
def test_a_label_before_a_subscript_is_the_same_glyph(latex, verdict):
    # \mathbf{a}^S_1 is TeX's \mathbf{a}_1^S (never refused: "unexpected '_'")
    assert _v(latex, [r"\mathbf{a}_1^S: unit vector"]) == verdict


def test_the_truth_of_the_spelling_cases_by_numpy():
    """Szeliski's v = v_par + cos(theta) v_perp + sin(theta) v_x is R v (Rodrigues), and with
    cos and sin swapped it is not; a point mass's inertia m (r^T r 1 - r r^T) annihilates r."""
    rng = np.random.default_rng(64)
    n, v, r = rng.normal(size=(3, 3))
    n /= np.linalg.norm(n)
    th, m = 0.7, 2.5
    N = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    R = np.eye(3) + np.sin(th) * N + (1 - np.cos(th)) * N @ N
    par, cross = n * (n @ v), np.cross(n, v)
    assert np.allclose(R @ v, par + np.cos(th) * (v - par) + np.sin(th) * cross)
    assert not np.allclose(R @ v, par + np.sin(th) * (v - par) + np.cos(th) * cross)
    inertia = m * ((r @ r) * np.eye(3) - np.outer(r, r))
    assert np.allclose(inertia @ r, 0) and not np.allclose(inertia @ n, 0)


_SZELISKI = [r"\hat{\mathbf{n}}: unit vector", r"\theta: angle", r"\mathbf{v}: vector",
             r"\mathbf{v}_\parallel = \hat{\mathbf{n}}(\hat{\mathbf{n}}\cdot\mathbf{v})",
             r"\mathbf{v}_\perp = \mathbf{v} - \mathbf{v}_\parallel",
             r"\mathbf{v}_\times = \hat{\mathbf{n}}\times\mathbf{v}",
             r"\mathbf{R} = \mathbf{I} + \sin\theta[\hat{\mathbf{n}}]_\times + (1 - \cos\theta)"
             r"[\hat{\mathbf{n}}]_\times^2"]


@pytest.mark.parametrize("latex, verdict", [
    (r"\mathbf{R}\mathbf{v} = \mathbf{v}_\parallel + \cos\theta\,\mathbf{v}_\perp + "
     r"\sin\theta\,\mathbf{v}_\times", "verified"),
    (r"\mathbf{R}\mathbf{v} = \mathbf{v}_\parallel + \sin\theta\,\mathbf{v}_\perp + "
     r"\cos\theta\,\mathbf{v}_\times", "does-not-hold"),
])
def test_a_declared_name_with_a_cross_subscript_is_a_name_of_its_own(latex, verdict):
    """Szeliski's v_\\times = n x v, declared by the reader, is a vector named v_\\times (not
    Eade's cross-product matrix [v]_\\times, which an undeclared v_\\times still reads as)."""
    assert _v(latex, _SZELISKI) == verdict


@pytest.mark.parametrize("rhs, verdict", [
    (r"\mathbf{0}", "verified"),
    (r"m\,\mathbf{r}", "does-not-hold"),
])
def test_a_thin_space_inside_parentheses_is_no_argument_comma(rhs, verdict):
    """m(r^T r\\, 1 - r r^T): the thin space \\, is spacing, not the comma of an application
    to two arguments (before: "unexpected ')' ... expected one of: , or \\quad")."""
    let = [r"m: scalar", r"\mathbf{r}: vector",
           r"\mathbf{J} = m(\mathbf{r}^T\mathbf{r}\,\mathbf{1} - \mathbf{r}\mathbf{r}^T)"]
    assert _v(r"\mathbf{J}\mathbf{r} = " + rhs, let) == verdict


@pytest.mark.parametrize("sub", [r"\bm{n}", *(pytest.param(s, marks=pytest.mark.slow) for s in (
    r"\mathbf{n}", r"\bm n", r"\boldsymbol{n}"))])
@pytest.mark.parametrize("sign, verdict", [("+", "verified"), ("-", "does-not-hold")])
def test_a_bold_letter_in_a_subscript_is_part_of_the_name(sub, sign, verdict):
    """Rotations.jl's R_{\\bm{n}}(\\theta), the rotation about n: a bold letter in a
    subscript is one name however it is spelt (before: "unexpected \\bm (a font)"); the
    model's Rodrigues form holds, its sign slip does not."""
    let = [r"\theta: angle", r"\mathbf{n}: unit vector",
           r"R_{\mathbf{n}}(x) = \exp(x [\mathbf{n}]_\times)"]
    rhs = (rf"\mathbf{{1}} + \sin\theta [\mathbf{{n}}]_\times {sign} "
           r"(1 - \cos\theta)[\mathbf{n}]_\times^2")
    assert _v(rf"R_{{{sub}}}(\theta) = " + rhs, let) == verdict


_JAZAR = [r"{}^G R_B(t): rotation", r"{}^G\omega_B: angular velocity of {}^G R_B"]


@pytest.mark.parametrize("index", [r"{}^G", pytest.param(r"{}^{G}", marks=pytest.mark.slow)])
@pytest.mark.parametrize("rhs, verdict", [
    (r"[{}^G\omega_B]_\times\,{}^G R_B", "verified"),       # Jazar (2010) ch. 7
    (r"{}^G R_B\,[{}^G\omega_B]_\times", "does-not-hold"),  # the body-frame order
    pytest.param(r"[{}^G\omega_B]_\times^T\,{}^G R_B", "does-not-hold", marks=pytest.mark.slow),
])
def test_the_dot_of_a_frame_indexed_rotation_is_its_rate(index, rhs, verdict):
    """Jazar's {}^G\\dot{R}_B is the rate of the declared {}^G R_B(t), in both semantics
    (before: the reader took it for a glyph of its own, the second semantics refused it), its
    index spelt either way; an undeclared rate stays a name of its own."""
    lets = [x.replace(r"{}^G", index, 1) for x in _JAZAR]
    assert _v(index + r"\dot{R}_B = " + rhs, lets) == verdict


_MHP = [r"R(t): rotation", r"\Omega: body angular velocity of R", r"\omega: vector",
        r"\hat{R}: rotation", r"\dot{\hat{R}} = \hat{R}(\Omega + \omega)_\times",
        r"\tilde{R} = \hat{R}^T R"]


@pytest.mark.parametrize("rhs, verdict", [
    (r"[\tilde{R}, \Omega_\times] - \omega_\times\tilde{R}", "verified"),
    pytest.param(r"[\tilde{R}, \Omega_\times] + \omega_\times\tilde{R}", "does-not-hold",
                 marks=pytest.mark.slow),
])
def test_the_dot_of_an_accented_model_is_its_rate(rhs, verdict):
    """Mahony-Hamel-Pflimlin's error R~ = R^^T R of a filter whose rate a --let gives
    (\\dot{\\hat{R}} = ...): \\dot{\\tilde{R}} is the model's time derivative (before: the
    accents were keyed \\hat\\dot{\\hat{R}}, the --let was 'not in the LaTeX', and the dot
    over an accented model was no rate)."""
    assert _v(r"\dot{\tilde{R}} = " + rhs, _MHP) == verdict


_GALLIER = [r"\mathbf{n}: unit vector", r"\theta: angle", r"B = \theta[\mathbf{n}]_\times",
            r"U: vector", r"V = I_3 + \frac{1 - \cos\theta}{\theta^2}B + "
            r"\frac{\theta - \sin\theta}{\theta^3}B^2"]


@pytest.mark.parametrize("corner, verdict", [
    ("1", "verified"), pytest.param("0", "does-not-hold", marks=pytest.mark.slow)])
def test_a_row_of_scalar_zeros_in_a_block_matrix_is_one_high(corner, verdict):
    """Gallier's exp [B U; 0 0] = [e^B VU; 0 1]: the row '0 & 0' under [B & U] is one high,
    each zero as wide as its column (before: sympy's raw 'not a block matrix' text)."""
    lhs = r"e^{\begin{bmatrix} B & U \\ 0 & 0 \end{bmatrix}}"
    rhs = rf"\begin{{bmatrix}} e^B & VU \\ 0 & {corner} \end{{bmatrix}}"
    assert _v(lhs + " = " + rhs, _GALLIER) == verdict


_VEX = [r"a: unit vector", r"\theta: angle",
        r"\tilde{R} = I_3 + \sin\theta\,[a]_\times + (1 - \cos\theta)[a]_\times^2",
        r"\mathrm{vex}(\mathbf{A}) = \mathbf{A}^\vee", r"H: matrix",
        r"\mathbb{P}_a(H) = \frac12(H - H^T)"]


@pytest.mark.parametrize("rhs, verdict", [
    (r"\sin\theta\,a", "verified"),
    pytest.param(r"\theta\,a", "does-not-hold", marks=pytest.mark.slow),
])
def test_an_upright_operator_name_and_a_blackboard_letter_are_names_a_let_defines(rhs,
                                                                                  verdict):
    """Mahony-Hamel-Pflimlin's vex(P_a(R~)) = sin(theta) a: \\mathrm{vex} is a function a
    --let defines, as \\mathrm{Exp} is, and \\mathbb{P}_a a name (before: 'unknown operator
    vex', 'unknown macro \\mathbb'); \\mathbb{I} is contested (test_check_latex_contested)."""
    assert _v(r"\mathrm{vex}(\mathbb{P}_a(\tilde{R})) = " + rhs, _VEX) == verdict


def test_an_undeclared_operator_name_says_how_to_declare_it():
    with pytest.raises(BadInput, match=r"the operator 'sgn' \(\\mathrm\{sgn\}\), which the "
                                       r"vocabulary does not have \(declare it: --let "
                                       r"'\\mathrm\{sgn\}"):
        _v(r"\mathrm{sgn}(x) = x", [r"x: scalar"])
    assert _v(r"\mathbb{I}\mathbf{a} = \mathbf{a}",
              [r"\mathbf{a}: vector", r"\mathbb{I}: identity"]) == "verified"


_MR = [r"\boldsymbol\Pi(t): vector",
       r"\dot{\boldsymbol\Pi} = \boldsymbol\Pi\times\boldsymbol\Omega",
       r"\boldsymbol\Omega = \mathbb{I}^{-1}\boldsymbol\Pi", r"I_1: scalar", r"I_2: scalar",
       r"I_3: scalar", r"\mathbb{I} = \operatorname{diag}(I_1, I_2, I_3)"]


@pytest.mark.parametrize("rhs, verdict", [
    (r"\frac12\boldsymbol\Pi\cdot\boldsymbol\Omega", "verified"),
    pytest.param(r"\frac12\boldsymbol\Pi\cdot\mathbb{I}\boldsymbol\Pi", "does-not-hold",
                 marks=pytest.mark.slow),
])
def test_a_declared_blackboard_i_is_the_name_not_the_identity(rhs, verdict):
    """Marsden & Ratiu's inertia tensor \\mathbb{I}, declared: the free rigid body's energy
    (1/2) Pi . Omega is conserved, (1/2) Pi . I Pi is not (before: 'expected one symbol as
    NAME, got \\mathbb{I}'); undeclared, \\mathbb{I} is read both ways, Chirikjian's identity
    and a name (test_check_latex_contested)."""
    lhs = r"\frac{d}{dt}\left(" + rhs + r"\right) = 0"
    assert _v(lhs, _MR) == verdict


_GINSBERG = [r"[R]: rotation", r"\{\omega\}: vector", r"[I]: symmetric matrix",
             r"[I'] = [R][I][R]^T", r"\{\omega'\} = [R]\{\omega\}"]


@pytest.mark.parametrize("rhs, verdict", [
    (r"\frac{1}{2}\{\omega\}^T[I]\{\omega\}", "verified"),
    pytest.param(r"\frac{1}{2}\{\omega\}^T[I']\{\omega\}", "does-not-hold",
                 marks=pytest.mark.slow),
])
def test_declared_column_braces_are_the_glyph_inside(rhs, verdict):
    """Ginsberg's {omega} (the column of omega's components), declared: the kinetic energy
    is the same in either basis, [I'] = [R][I][R]^T (before: 'unknown macro \\{'); undeclared,
    \\{ stays unread (a set's braces in other books)."""
    lhs = r"\frac{1}{2}\{\omega'\}^T[I']\{\omega'\} = "
    r = rigidsym.check_latex(lhs + rhs, let=_GINSBERG, repairs=False)
    assert r.verdict == verdict
    # the model's own NAME [I'] is no identity read (before: "in --let '[I'] = ...': I':
    # the identity (no --let declares I')")
    assert not any("the identity" in line for line in r.model), r.model
    if verdict == "verified":
        with pytest.raises((BadInput, LatexError), match=r"unknown macro \\\{"):
            _v(lhs + rhs, [x.replace(r"\{\omega\}: vector", r"\omega: vector")
                           for x in _GINSBERG])


@pytest.mark.parametrize("latex, verdict", [
    (r"[\mathbf{Q}]_{Xx}^T[\mathbf{Q}]_{Xx} = \mathbf{1}", "verified"),
    (r"[\mathbf{Q}]_{Xx}[\mathbf{Q}]_{Xx} = \mathbf{1}", "does-not-hold"),
])
def test_a_bracketed_name_with_a_word_subscript_is_one_name(latex, verdict):
    """Curtis' direction cosine matrix ``[\\mathbf{Q}]_{Xx}`` (from frame X to x) is one name,
    as Solà's ``[\\mathbf{q}]_L`` is: its ``--let`` declares it (a parse error before, with no
    hint of what to write)."""
    r = rigidsym.check_latex(latex, let=[r"[\mathbf{Q}]_{Xx}: rotation"], repairs=False)
    assert r.verdict == verdict, r.detail


@pytest.mark.parametrize("accent, mark, bold", [(r"\mathring", "\u030a", False),
                                                (r"\mathring", "\u030a", True),
                                                (r"\breve", "\u0306", False),
                                                (r"\check", "\u030c", True)])
def test_a_naming_accent_is_a_glyph_of_its_own(accent, mark, bold):
    r"""Horn's ``\mathring{q}`` (like ``\bar``, ``\breve``, ``\check``) names a glyph of its own,
    never an operator: declared, it reads in both semantics, printed with its own mark; Horn's
    rule that the product with a common factor scales the dot product holds, its slip (the
    factor on the other side of one product) does not (before: "unknown macro")."""
    def g(x):
        return f"{accent}{{\\mathbf{{{x}}}}}" if bold else f"{accent}{{{x}}}"
    let = [f"{g('q')}: 4-vector; {g('p')}: 4-vector; {g('r')}: 4-vector"]
    q, p, r = g("q"), g("p"), g("r")
    out = rigidsym.check_latex(f"({q}\\otimes {p})\\cdot({q}\\otimes {r}) = ({q}\\cdot {q})"
                               f"({p}\\cdot {r})", let=let, repairs=False)
    assert out.verdict == "verified", out.detail
    assert any("q" + mark in line for line in out.model), out.model
    assert _v(f"({q}\\otimes {p})\\cdot({r}\\otimes {q}) = ({q}\\cdot {q})({p}\\cdot {r})",
              let) == "does-not-hold"
    # the accented glyph is not its letter: q and the accented q are two names
    plain = r"\mathbf{q}" if bold else "q"
    assert _v(f"{q} = {plain}", [*let, f"{plain}: 4-vector"]) == "does-not-hold"


_ZIPFEL = ["[T]^{IB}(t): rotation", "[T]^{BI} = ([T]^{IB})^T",
           r"\boldsymbol\omega^{BI}: body angular velocity of [T]^{IB}",
           r"[\Omega^{BI}]^B = [\boldsymbol\omega^{BI}]_\times"]


@pytest.mark.parametrize("rhs, verdict", [(r"-[\Omega^{BI}]^B[T]^{BI}", "verified"),
                                          (r"-[T]^{BI}[\Omega^{BI}]^B", "does-not-hold")])
def test_a_declared_frame_pair_label_is_part_of_the_name(rhs, verdict):
    r"""Zipfel's ``[T]^{BL}``, ``[\Omega^{BI}]^B``, ``\boldsymbol\omega^{BI}``: where a --let
    declares the name, two capitals (and a bracket's capital) are its frame label, never a
    power; the notes name them as typed (before: "unexpected 'BI'")."""
    r = rigidsym.check_latex(r"\frac{d}{dt}[T]^{BI} = " + rhs, let=_ZIPFEL, repairs=False)
    assert r.verdict == verdict, r.detail
    said = " ".join(m for m in r.model if isinstance(m, str))
    assert "[T]^{IB}" in said and "(IB)" not in said, r.model


def test_a_frame_pair_label_refusal_says_what_to_write_and_quotes_the_let_as_typed():
    """Undeclared, ``T^{BL}`` is refused with the --let that names it; a refusal about a
    respelt --let (a body angular velocity's model) quotes the --let as the user typed it."""
    with pytest.raises((BadInput, LatexError), match=r"--let 'T\^\{BL\}: rotation'"):
        _v(r"T^{BL}T^{BL} = \mathbf{1}")
    bad = [_ZIPFEL[0].replace("rotation", "vector"), *_ZIPFEL[1:]]
    with pytest.raises((BadInput, LatexError)) as exc:
        _v(r"\frac{d}{dt}[T]^{BI} = -[\Omega^{BI}]^B[T]^{BI}", bad)
    msg = str(exc.value)
    assert "vee" not in msg.split(":")[0] and "(IB)" not in msg, msg
    assert r"--let '\boldsymbol\omega^{BI}: body angular velocity of [T]^{IB}'" in msg, msg


_KP = [r"\mathbf{C}(t): rotation", r"{}^{A}\boldsymbol\omega^{B}: angular velocity of \mathbf{C}"]


@pytest.mark.parametrize("latex, verdict", [
    (r"\dot{\mathbf{C}} = [{}^{\mathcal{A}}\boldsymbol\omega^{\mathcal{B}}]_\times\mathbf{C}",
     "verified"),
    (r"\dot{\mathbf{C}} = \mathbf{C}[{}^{\mathcal{A}}\boldsymbol\omega^{B}]_\times",
     "does-not-hold"),
])
def test_a_calligraphic_frame_in_an_index_or_label_is_its_letter(latex, verdict):
    r"""Kasdin & Paley's ``{}^{\mathcal{A}}\boldsymbol\omega^{\mathcal{B}}`` is the name
    ``{}^{A}\boldsymbol\omega^{B}`` (a calligraphic frame in a left index or a label is its
    plain letter, in both semantics; before: "unexpected '}' at position 1"): C's rate is
    [omega]_x C with omega its (space) angular velocity."""
    assert _v(latex, _KP) == verdict


def test_moments_read_as_identities_are_named_with_the_let_that_settles_them():
    r"""Rule 6 reads ``I_2``, ``I_3`` as identities; where their shapes do not fit, the refusal
    names them and the --let that makes them scalars (before: 'no product fits', naming
    neither), which decides the statement."""
    let = [r"\mathbf{x}: vector"]
    with pytest.raises((BadInput, LatexError)) as exc:
        _v(r"I_2\mathbf{x} = I_3\mathbf{x}", let)
    said = "I_{2}: scalar; I_{3}: scalar"
    assert "I_{2}, I_{3} are read as the identities" in str(exc.value), str(exc.value)
    assert f"--let '{said}'" in str(exc.value), str(exc.value)
    assert _v(r"I_2\mathbf{x} = I_3\mathbf{x}", [*let, said]) == "does-not-hold"
