"""The tangent order of SE(3) as a declaration (``--let 'tangent order: translation first'``,
``--notation barfoot``/``sola``): the hat of a 6-vector, its vee, Ad, ad and the exponential
of se(3) read in the order declared by both semantics, and ``read as:`` naming the order on
every statement that uses one."""

from __future__ import annotations

import mpmath as mp
import pytest

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex import tangent
from rigidsym.numeval import values as V
from rigidsym.registry import declarations as registry

TF, AF = "tangent order: translation first", "tangent order: angular first"
M = [r"\mathbf{M} = \begin{bmatrix} \mathbf{R} & \mathbf{t} \\ \mathbf{0}^T & 1 \end{bmatrix}",
     r"\mathbf{R}: rotation", r"\mathbf{t}: vector"]
#: Ad of SE(3) as each order prints it: micro Lie / Barfoot (translation first), MR (angular)
AD = {TF: r"\mathbf{Ad}_{\mathbf{M}} = \begin{bmatrix} \mathbf{R} & [\mathbf{t}]_\times"
          r"\mathbf{R} \\ \mathbf{0} & \mathbf{R} \end{bmatrix}",
      AF: r"\mathbf{Ad}_{\mathbf{M}} = \begin{bmatrix} \mathbf{R} & \mathbf{0} \\ "
          r"[\mathbf{t}]_\times\mathbf{R} & \mathbf{R} \end{bmatrix}"}
#: ad of a 6-vector of parts rho (translation) and phi (rotation), in each order
AD_SMALL = {TF: (r"\boldsymbol\xi^\curlywedge = \begin{bmatrix} \boldsymbol\phi^\wedge & "
                 r"\boldsymbol\rho^\wedge \\ \mathbf{0} & \boldsymbol\phi^\wedge \end{bmatrix}",
                 r"\boldsymbol\xi = \begin{bmatrix} \boldsymbol\rho \\ \boldsymbol\phi "
                 r"\end{bmatrix}"),
            AF: (r"\boldsymbol\xi^\curlywedge = \begin{bmatrix} \boldsymbol\phi^\wedge & "
                 r"\mathbf{0} \\ \boldsymbol\rho^\wedge & \boldsymbol\phi^\wedge \end{bmatrix}",
                 r"\boldsymbol\xi = \begin{bmatrix} \boldsymbol\phi \\ \boldsymbol\rho "
                 r"\end{bmatrix}")}
#: Exp of SE(3): the rotation Exp(theta u) and the translation V rho (manif, Barfoot (7.83));
#: rho written phi w, so that the other order's rotation exp(phi [w]) is exact too
EXP_LETS = [r"\mathbf{u}: unit vector", r"\theta: angle", r"\mathbf{w}: unit vector",
            r"\phi: angle", r"\boldsymbol\rho = \phi\mathbf{w}",
            r"\mathbf{V} = \mathbf{I} + \frac{1 - \cos\theta}{\theta}[\mathbf{u}]_\times + "
            r"\frac{\theta - \sin\theta}{\theta}[\mathbf{u}]_\times^2"]
EXP = (r"\exp(\boldsymbol\tau^\wedge) = \begin{bmatrix} \exp(\theta[\mathbf{u}]_\times) & "
       r"\mathbf{V}\boldsymbol\rho \\ \mathbf{0}^T & 1 \end{bmatrix}")
TAU = {TF: r"\boldsymbol\tau = \begin{bmatrix} \boldsymbol\rho \\ \theta\mathbf{u} \end{bmatrix}",
       AF: r"\boldsymbol\tau = \begin{bmatrix} \theta\mathbf{u} \\ \boldsymbol\rho \end{bmatrix}"}


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _check(latex, lets, **kw):
    return rigidsym.check_latex(latex, let=lets, repairs=False, **kw)


def _order_said(r) -> list[str]:
    return [m for m in r.model if m.startswith("tangent order:")]


@pytest.mark.parametrize("printed", [TF, AF])
def test_ad_of_se3_holds_in_the_order_declared_and_not_in_the_other(printed):
    other = AF if printed == TF else TF
    r = _check(AD[printed], M + [printed])
    assert r.verdict == "verified" and printed.split(": ")[1] in _order_said(r)[0]
    r = _check(AD[printed], M + [other])
    assert r.verdict == "does-not-hold" and r.counterexample, r.verdict
    assert other.split(": ")[1] in _order_said(r)[0]


@pytest.mark.slow
@pytest.mark.parametrize("printed", [TF, AF])
def test_ad_of_a_6_vector_holds_in_the_order_declared_and_not_in_the_other(printed):
    other = AF if printed == TF else TF
    latex, xi = AD_SMALL[printed]
    assert _check(latex, [xi, printed]).verdict == "verified"
    r = _check(latex, [xi, other])
    assert r.verdict == "does-not-hold" and r.counterexample


@pytest.mark.slow
@pytest.mark.parametrize("printed", [TF, AF])
def test_exp_of_se3_holds_in_the_order_declared_and_not_in_the_other(printed):
    other = AF if printed == TF else TF
    assert _check(EXP, EXP_LETS + [TAU[printed], printed]).verdict == "verified"
    r = _check(EXP, EXP_LETS + [TAU[printed], other])
    assert r.verdict == "does-not-hold" and r.counterexample


@pytest.mark.parametrize("notation", ["barfoot", "sola"])
def test_the_books_that_fix_translation_first_set_it(notation):
    r = _check(AD[TF], M, notation=notation)
    assert r.verdict == "verified" and "translation first" in _order_said(r)[0]


# a property: every statement that uses an order says it under read as:, and which
XI, T = r"\boldsymbol\xi: 6-vector", r"\mathbf{T}: transform"
USES = [(r"\boldsymbol\xi^\wedge\boldsymbol\xi^\wedge = (\boldsymbol\xi^\wedge)^2", XI),
        (r"(\boldsymbol\xi^\wedge)^\vee = \boldsymbol\xi", XI),
        (r"\boldsymbol\xi^\curlywedge\boldsymbol\xi = \mathbf{0}", XI),
        (r"\mathrm{Ad}(\mathbf{T})\mathrm{Ad}(\mathbf{T}^{-1}) = \mathbf{1}", T),
        (r"\mathrm{ad}_{\boldsymbol\xi}\boldsymbol\xi = \mathbf{0}", XI),
        (r"[\boldsymbol\xi]^T[\boldsymbol\xi] = ([\boldsymbol\xi])^T[\boldsymbol\xi]", XI)]


@pytest.mark.parametrize("latex, let", USES)
@pytest.mark.parametrize("order", [None, TF, AF])
def test_read_as_names_the_order_on_every_statement_that_uses_one(latex, let, order):
    r = _check(latex, [let] + ([order] if order else []))
    said = _order_said(r)
    assert ("translation first" if order == TF else "angular first") in said[0], r.model
    assert r.verdict == "verified"
    if order is None:  # undeclared: read in both orders, said
        assert len(said) == 2 and "not declared" in said[1] and "both verified" in said[1]
    else:
        assert len(said) == 1, r.model


def test_an_undeclared_order_whose_two_readings_disagree_is_refused_naming_the_let():
    # manif's Ad of SE(3), typed with no order: true translation first, false angular first
    with pytest.raises(BadInput, match=r"two orders disagree .*--let 'tangent order: "):
        _check(AD[TF], M)


@pytest.mark.parametrize("latex, let", [
    (r"\mathbf{a}^\wedge\mathbf{a} = \mathbf{0}", r"\mathbf{a}: vector"),
    (r"\mathbf{Ad}_{\mathbf{R}} = \mathbf{R}", r"\mathbf{R}: rotation")])
def test_a_statement_with_no_6_vector_says_no_order(latex, let):
    r = _check(latex, [let])
    assert r.verdict == "verified" and not _order_said(r)


def test_ad_of_so3_is_the_rotation_itself_in_both_semantics():
    # manif's Ad_R = R; of a matrix no --let declares a rotation it is still refused
    assert _check(r"\mathbf{Ad}_{\mathbf{R}}[\mathbf{x}]_\times\mathbf{Ad}_{\mathbf{R}}^T = "
                  r"[\mathbf{R}\mathbf{x}]_\times", [r"\mathbf{R}: rotation",
                                                     r"\mathbf{x}: vector"]).verdict == \
        "verified"
    with pytest.raises(ValueError, match="4x4 transform"):
        _check(r"\mathbf{Ad}_{\mathbf{A}} = \mathbf{A}", [r"\mathbf{A}: matrix"])


@pytest.mark.parametrize("let, match", [
    ("tangent order: sideways", "translation first"),
    ([TF, AF], "declared twice"),
])
def test_an_order_no_word_names_or_two_orders_are_refused(let, match):
    lets = [let] if isinstance(let, str) else let
    with pytest.raises(BadInput, match=match):
        _check(AD[TF], M + lets)


@pytest.mark.parametrize("text", ["translation first", "linear first", "[\\rho;\\theta]",
                                  "[\\boldsymbol\\rho, \\boldsymbol\\theta]", "[v;\\omega]"])
def test_the_books_spellings_of_translation_first(text):
    _, order, said = tangent.split_setting([f"tangent order: {text}", "x: scalar"], None)
    assert order == tangent.TRANSLATION and said.endswith(text)


def test_the_second_semantics_orders_its_own_definitions():
    # numeval's hat, vee, Ad and ad under [v; w] are its [w; v] ones conjugated by the swap
    mp.mp.dps = 30
    x = mp.matrix([1, 2, 3, 4, 5, 6])
    sw = mp.matrix([4, 5, 6, 1, 2, 3])
    T = mp.matrix([[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]])
    with V.tangent_order(True):
        hat_tf, vee_tf = V.hat(x), V.vee(V.hat(x))
        ad_tf, Ad_tf = V.small_adjoint(x), V.adjoint(T)
    assert hat_tf == V.hat(sw) and vee_tf == x
    P = mp.zeros(6, 6)
    for i in range(6):
        P[i, (i + 3) % 6] = 1
    assert ad_tf == P * V.small_adjoint(sw) * P and Ad_tf == P * V.adjoint(T) * P
    # Featherstone's spatial cross product keeps its own order [w; v]
    with V.tangent_order(True):
        featherstone = V.spatial_cross(x)
    assert featherstone == V.small_adjoint(x)


ROTATIONS = [r"\mathbf{R}: rotation", r"\mathbf{R}_1: rotation", r"\mathbf{R}_2: rotation"]


@pytest.mark.parametrize("latex, lets, verdict", [
    # micro Lie (Solà et al. 2018): Ad of SO(3) is R, so Ad_{R^-1} = R^T and Ad is a
    # homomorphism; each with its slip
    (r"\mathbf{Ad}_{\mathbf{R}^{-1}} = \mathbf{R}^T", ROTATIONS[:1], "verified"),
    (r"\mathbf{Ad}_{\mathbf{R}^{-1}} = \mathbf{R}", ROTATIONS[:1], "does-not-hold"),
    (r"\mathbf{Ad}_{\mathbf{R}_1\mathbf{R}_2} = \mathbf{Ad}_{\mathbf{R}_1}"
     r"\mathbf{Ad}_{\mathbf{R}_2}", ROTATIONS[1:], "verified"),
    (r"\mathbf{Ad}_{\mathbf{R}_1\mathbf{R}_2} = \mathbf{Ad}_{\mathbf{R}_2}"
     r"\mathbf{Ad}_{\mathbf{R}_1}", ROTATIONS[1:], "does-not-hold"),
])
def test_ad_of_a_rotation_built_of_rotations_is_that_rotation(latex, lets, verdict):
    r = _check(latex, lets)
    assert r.verdict == verdict
    assert verdict == "verified" or r.counterexample


def test_ad_of_a_3x3_that_is_no_rotation_by_construction_is_refused_naming_rotations():
    with pytest.raises(ValueError, match=r"4x4 transform or a rotation .*--let "
                                         r"'\\mathbf\{R\}: rotation'"):
        _check(r"\mathbf{Ad}_{2\mathbf{R}} = 2\mathbf{R}", ROTATIONS[:1])
