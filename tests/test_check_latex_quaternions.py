"""The quaternion product as the estimation books print it: ``\\otimes`` (Solà, Trawny-
Roumeliotis) and ``\\odot`` (Kok-Hol-Schön) between 4-vectors, Hamilton's by default and
JPL's by declaration (``--let '\\otimes: JPL'``), ``q^*`` the conjugate; ``read as:`` names the
convention. Each identity is decided in its convention and does not hold, with a
counterexample, in the other."""

from __future__ import annotations

from fractions import Fraction

import mpmath as mp
import pytest

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.numeval import values as V
from rigidsym.registry import declarations as registry

PQ = [r"\mathbf{p}: 4-vector", r"\mathbf{q}: 4-vector"]
HAM, JPL = r"\otimes: Hamilton", r"\otimes: JPL"
#: Solà's (2017) (18) left matrix of p, scalar first (Hamilton)
SOLA_L = (r"\mathbf{P} = \begin{bmatrix} p_0 & -p_1 & -p_2 & -p_3 \\ p_1 & p_0 & -p_3 & p_2 "
          r"\\ p_2 & p_3 & p_0 & -p_1 \\ p_3 & -p_2 & p_1 & p_0 \end{bmatrix}")
#: Trawny & Roumeliotis' (2005) (9) left matrix of p, scalar last (JPL)
TRAWNY_L = (r"\mathbf{P} = \begin{bmatrix} p_4 & p_3 & -p_2 & p_1 \\ -p_3 & p_4 & p_1 & p_2 "
            r"\\ p_2 & -p_1 & p_4 & p_3 \\ -p_1 & -p_2 & -p_3 & p_4 \end{bmatrix}")
LEFT = r"\mathbf{p}\otimes\mathbf{q} = \mathbf{P}\mathbf{q}"


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _check(latex, lets):
    return rigidsym.check_latex(latex, let=lets, repairs=False)


def _said(r) -> list[str]:
    return [m for m in r.model if m.startswith("quaternion product:")]


@pytest.mark.parametrize("matrix, own, other", [(SOLA_L, HAM, JPL), (TRAWNY_L, JPL, HAM)])
def test_each_books_product_matrix_holds_in_its_convention_and_not_in_the_other(
        matrix, own, other):
    r = _check(LEFT, PQ + [matrix, own])
    assert r.verdict == "verified" and own.split(": ")[1] in _said(r)[0]
    r = _check(LEFT, PQ + [matrix, other])
    assert r.verdict == "does-not-hold" and r.counterexample
    assert other.split(": ")[1] in _said(r)[0]


def test_an_undeclared_convention_that_matters_is_asked_and_odot_is_the_same_product():
    # Trawny's left matrix (entries 1 to 4, nothing fixing the storage order) read with no
    # convention: JPL's verifies it, Hamilton's does not, so the reader asks, naming both
    # readings and each verdict; never a default
    for op in (r"\otimes", r"\odot"):
        with pytest.raises(BadInput, match=r"scalar first \(Solà.*: does-not-hold; JPL's ij = "
                           r"-k with the scalar last \(Trawny.*\): verified") as e:
            _check(LEFT.replace(r"\otimes", op), PQ + [TRAWNY_L])
        assert r"--let '\otimes: JPL'" in str(e.value) and "Trawny" in str(e.value)
    # Solà's, written in p_0 (entries counted from 0): the scalar first, Hamilton's, said
    r = _check(LEFT.replace(r"\otimes", r"\odot"), PQ + [SOLA_L])
    assert r.verdict == "verified" and "Hamilton's, the storage order fixed by the entry p_0" \
        in _said(r)[0], _said(r)


def test_a_statement_true_in_both_conventions_is_decided_and_said_so():
    r = _check(r"(\mathbf{p}\otimes\mathbf{q})^* = \mathbf{q}^*\otimes\mathbf{p}^*", PQ)
    assert r.verdict == "verified"
    assert any("each of the books' readings" in m and "each verified" in m
               for m in _said(r)), r.model


@pytest.mark.slow
@pytest.mark.parametrize("convention", [HAM, JPL])
@pytest.mark.parametrize("latex, verdict", [
    (r"(\mathbf{p}\otimes\mathbf{q})^* = \mathbf{q}^*\otimes\mathbf{p}^*", "verified"),
    (r"(\mathbf{p}\otimes\mathbf{q})^* = \mathbf{p}^*\otimes\mathbf{q}^*", "does-not-hold"),
    (r"\mathbf{p}\otimes\mathbf{q} = \mathbf{q}\otimes\mathbf{p}", "does-not-hold"),
    (r"(\mathbf{p}\otimes\mathbf{q})\otimes\mathbf{r} = \mathbf{p}\otimes(\mathbf{q}\otimes"
     r"\mathbf{r})", "verified"),
])
def test_the_product_laws_and_their_slips_in_both_conventions(convention, latex, verdict):
    lets = PQ + ([r"\mathbf{r}: 4-vector"] if r"\mathbf{r}" in latex else [])
    r = _check(latex, lets + [convention])
    assert r.verdict == verdict
    if verdict == "does-not-hold":
        assert r.counterexample


@pytest.mark.parametrize("lets, match", [
    ([r"\otimes: Shuster"], "Hamilton"),
    ([HAM, JPL], "declared twice"),
])
def test_a_convention_no_word_names_or_two_are_refused(lets, match):
    with pytest.raises(BadInput, match=match):
        _check(LEFT, PQ + [SOLA_L] + lets)


def test_a_product_of_other_shapes_is_refused_naming_them():
    with pytest.raises(ValueError, match="two 4-vectors"):
        _check(r"\mathbf{a}\otimes\mathbf{b} = \mathbf{a}", [r"\mathbf{a}: vector",
                                                             r"\mathbf{b}: vector"])


def test_the_second_semantics_multiplies_the_units_by_its_own_table():
    # i j = k (Hamilton), i j = -k (JPL): the units written in each convention's layout
    mp.mp.dps = 30
    i_h, j_h, k_h = (mp.matrix([0, 1, 0, 0]), mp.matrix([0, 0, 1, 0]), mp.matrix([0, 0, 0, 1]))
    assert V.quaternion_product(i_h, j_h) == k_h
    i_j, j_j, k_j = (mp.matrix([1, 0, 0, 0]), mp.matrix([0, 1, 0, 0]), mp.matrix([0, 0, 1, 0]))
    with V.quaternion_convention(True):
        assert V.quaternion_product(i_j, j_j) == -k_j
        assert V.quaternion_conjugate(mp.matrix([1, 2, 3, 4])) == mp.matrix([-1, -2, -3, 4])
    assert V.quaternion_conjugate(mp.matrix([1, 2, 3, 4])) == mp.matrix([1, -2, -3, -4])


#: Trawny & Roumeliotis' (2005) (4) cross-product matrix, written out by hand
FLOOR = (r"\lfloor\boldsymbol\omega\times\rfloor = \begin{bmatrix} 0 & -\omega_3 & \omega_2 "
         r"\\ \omega_3 & 0 & -\omega_1 \\ -\omega_2 & \omega_1 & 0 \end{bmatrix}")
OMEGA_V = [r"\boldsymbol\omega: vector", r"\mathbf{v}: vector"]


@pytest.mark.parametrize("latex, lets, verdict", [
    (FLOOR, OMEGA_V[:1], "verified"),
    (FLOOR.replace(r"0 & -\omega_1", r"0 & \omega_1"), OMEGA_V[:1], "does-not-hold"),
    (r"\lfloor\boldsymbol\omega\times\rfloor\mathbf{v} = \boldsymbol\omega\times\mathbf{v}",
     OMEGA_V, "verified"),
    (r"\left\lfloor\boldsymbol\omega\times\right\rfloor\mathbf{v} = \mathbf{v}\times"
     r"\boldsymbol\omega", OMEGA_V, "does-not-hold"),
])
def test_trawnys_floor_brackets_are_the_cross_product_matrix(latex, lets, verdict):
    r = _check(latex, lets)
    assert r.verdict == verdict
    assert any(m.startswith(r"\lfloor") and "cross-product matrix" in m for m in r.model)
    if verdict == "does-not-hold":
        assert r.counterexample


def test_floor_brackets_without_a_cross_stay_unknown():
    from rigidsym.latex import LatexError

    with pytest.raises(LatexError, match="lfloor"):
        _check(r"\lfloor\theta\rfloor = \theta", [r"\theta: angle"])


def _bm(rows: str) -> str:
    return r"\begin{bmatrix} " + rows + r" \end{bmatrix}"


#: Solà's (2017) (18), (19): [q]_L and [q]_R, scalar first, written out by hand
SOLA_QL = _bm(r"q_0 & -q_1 & -q_2 & -q_3 \\ q_1 & q_0 & -q_3 & q_2 \\ q_2 & q_3 & q_0 & -q_1"
              r" \\ q_3 & -q_2 & q_1 & q_0")
SOLA_QR = _bm(r"q_0 & -q_1 & -q_2 & -q_3 \\ q_1 & q_0 & q_3 & -q_2 \\ q_2 & -q_3 & q_0 & q_1"
              r" \\ q_3 & q_2 & -q_1 & q_0")
#: Trawny & Roumeliotis' (2005) L(q) and R(p), scalar last, written out by hand
TRAWNY_QL = _bm(r"q_4 & q_3 & -q_2 & q_1 \\ -q_3 & q_4 & q_1 & q_2 \\ q_2 & -q_1 & q_4 & q_3"
                r" \\ -q_1 & -q_2 & -q_3 & q_4")
TRAWNY_PR = _bm(r"p_4 & -p_3 & p_2 & p_1 \\ p_3 & p_4 & -p_1 & p_2 \\ -p_2 & p_1 & p_4 & p_3"
                r" \\ -p_1 & -p_2 & -p_3 & p_4")


@pytest.mark.parametrize("latex, model, convention, verdict", [
    (r"[\mathbf{q}]_L\mathbf{p} = \mathbf{q}\otimes\mathbf{p}",
     r"[\mathbf{q}]_L = " + SOLA_QL, HAM, "verified"),
    (r"[\mathbf{q}]_L\mathbf{p} = \mathbf{q}\otimes\mathbf{p}",
     r"[\mathbf{q}]_L = " + SOLA_QL, JPL, "does-not-hold"),
    (r"[\mathbf q]_{L}\mathbf{p} = \mathbf{q}\otimes\mathbf{p}",  # one sign slipped
     r"[\mathbf{q}]_L = " + SOLA_QL.replace("q_0 & -q_3 & q_2", "q_0 & q_3 & q_2"), HAM,
     "does-not-hold"),
    (r"\mathbf{p}\otimes\mathbf{q} = [\mathbf{q}]_R\mathbf{p}",
     r"[\mathbf{q}]_R = " + SOLA_QR, HAM, "verified"),
    (r"\mathbf{p}\otimes\mathbf{q} = [\mathbf{q}]_R\mathbf{p}",
     r"[\mathbf{q}]_R = " + SOLA_QR, JPL, "does-not-hold"),
    (r"\mathbf{q}\otimes\mathbf{p} = [\mathbf{q}]_R\mathbf{p}",  # the sides' order slipped
     r"[\mathbf{q}]_R = " + SOLA_QR, HAM, "does-not-hold"),
    (r"\mathcal{L}(\mathbf{q})\mathbf{p} = \mathbf{q}\otimes\mathbf{p}",
     r"\mathcal{L}(\mathbf{q}) = " + TRAWNY_QL, JPL, "verified"),
    (r"\mathcal{L}(\mathbf{q})\mathbf{p} = \mathbf{q}\otimes\mathbf{p}",
     r"\mathcal{L}(\mathbf{q}) = " + TRAWNY_QL, HAM, "does-not-hold"),
    (r"\mathbf{q}\otimes\mathbf{p} = \mathcal{R}(\mathbf{p})\mathbf{q}",
     r"\mathcal{R}(\mathbf{p}) = " + TRAWNY_PR, JPL, "verified"),
    (r"\mathbf{q}\otimes\mathbf{p} = \mathcal{R}(\mathbf{p})\mathbf{q}",
     r"\mathcal{R}(\mathbf{p}) = " + TRAWNY_PR, HAM, "does-not-hold"),
])
def test_the_product_matrices_declared_by_name_hold_in_their_books_convention(
        latex, model, convention, verdict):
    r = _check(latex, PQ + [model, convention])
    assert r.verdict == verdict
    assert convention.split(": ")[1] in _said(r)[0]
    if verdict == "does-not-hold":
        assert r.counterexample


def test_a_bracket_name_no_let_declares_is_refused_naming_it():
    with pytest.raises(BadInput, match=r"\[\\mathbf\{q\}\]_\{L\}.*no --let declares"):
        _check(r"[\mathbf{q}]_L\mathbf{p} = \mathbf{q}\otimes\mathbf{p}", PQ)


#: the inverse written out by hand, the conjugate over the squared norm: scalar first
#: (Solà (2017) (24)) and scalar last (Trawny & Roumeliotis (2005) (13))
INV_FIRST = (r"\mathbf{q}^{-1} = \frac{1}{q_0^2 + q_1^2 + q_2^2 + q_3^2}\begin{bmatrix} q_0 "
             r"\\ -q_1 \\ -q_2 \\ -q_3 \end{bmatrix}")
INV_LAST = (r"\mathbf{q}^{-1} = \frac{1}{q_1^2 + q_2^2 + q_3^2 + q_4^2}\begin{bmatrix} -q_1 "
            r"\\ -q_2 \\ -q_3 \\ q_4 \end{bmatrix}")


@pytest.mark.parametrize("latex, lets, verdict", [
    (INV_FIRST, [HAM], "verified"),
    (INV_FIRST, [JPL], "does-not-hold"),
    (INV_LAST, [JPL], "verified"),
    (INV_LAST, [HAM], "does-not-hold"),
    (INV_LAST.replace("q_3^2 + q_4^2}", "q_3^2 + q_4}"), [JPL], "does-not-hold"),
])
def test_the_inverse_of_a_quaternion_in_each_convention(latex, lets, verdict):
    r = _check(latex, [r"\mathbf{q}: 4-vector"] + lets)
    assert r.verdict == verdict
    assert any(m.startswith("q^{-1}: the inverse of a quaternion") for m in r.model)
    if verdict == "does-not-hold":
        assert r.counterexample


@pytest.mark.parametrize("kind, verdict", [("unit 4-vector", "verified"),
                                           ("4-vector", "does-not-hold")])
def test_the_inverse_is_the_conjugate_of_a_unit_quaternion_only(kind, verdict):
    r = _check(r"\mathbf{q}^{-1} = \mathbf{q}^*", [rf"\mathbf{{q}}: {kind}"])
    assert r.verdict == verdict


@pytest.mark.parametrize("latex, verdict", [
    (r"\mathbf{q}^{-1}\otimes\mathbf{q}\otimes\mathbf{p} = \mathbf{p}", "verified"),
    (r"(\mathbf{p}\otimes\mathbf{q})^{-1} = \mathbf{q}^{-1}\otimes\mathbf{p}^{-1}", "verified"),
    (r"(\mathbf{p}\otimes\mathbf{q})^{-1} = \mathbf{p}^{-1}\otimes\mathbf{q}^{-1}",
     "does-not-hold"),
])
@pytest.mark.parametrize("convention", [HAM, JPL])
def test_the_inverse_laws_in_both_conventions(latex, verdict, convention):
    r = _check(latex, PQ + [convention])
    assert r.verdict == verdict


def _notation(latex, lets, notation):
    return rigidsym.check_latex(latex, let=lets, notation=notation, repairs=False)


def test_the_jpl_notation_declares_jpls_product():
    # Trawny's L(q), written by hand, scalar last: JPL's under the notation, asked without
    lets = PQ + [r"\mathbf{L} = " + TRAWNY_QL]
    latex = r"\mathbf{L}\mathbf{p} = \mathbf{q}\otimes\mathbf{p}"
    r = _notation(latex, lets, "jpl")
    assert r.verdict == "verified" and "JPL" in _said(r)[0]
    with pytest.raises(BadInput, match=r"JPL's ij = -k with the scalar last \(Trawny.*\): "
                       r"verified"):
        _notation(latex, lets, None)
    r = _notation(latex, lets + [HAM], "jpl")  # a --let wins over the table
    assert r.verdict == "does-not-hold" and "Hamilton" in _said(r)[0]


@pytest.mark.parametrize("latex, verdict", [
    # Trawny & Roumeliotis (2005): the cross-product matrix of a rotated vector, and its slip
    (r"\lfloor\mathbf{C}\mathbf{x}\times\rfloor = \mathbf{C}\lfloor\mathbf{x}\times\rfloor"
     r"\mathbf{C}^T", "verified"),
    (r"\lfloor\mathbf{C}\mathbf{x}\times\rfloor = \mathbf{C}^T\lfloor\mathbf{x}\times\rfloor"
     r"\mathbf{C}", "does-not-hold"),
])
def test_floor_brackets_of_a_bold_vector_and_a_product(latex, verdict):
    r = _check(latex, [r"\mathbf{C}: rotation", r"\mathbf{x}: vector"])
    assert r.verdict == verdict
    assert any(m.startswith(r"\lfloor") and "cross-product matrix" in m for m in r.model)


#: Trawny & Roumeliotis (2005) (1): a unit quaternion's vector part and scalar part
QBAR = [r"\bar{q}: unit 4-vector"]


@pytest.mark.parametrize("latex, verdict", [
    (r"\bar{q}_{1:3}^T\bar{q}_{1:3} + \bar{q}_{4:4}^2 = 1", "verified"),
    (r"\bar{q}_{1:3}^T\bar{q}_{1:3} = 1", "does-not-hold"),
    (r"\bar{q}_{1:3}\times\bar{q}_{1:3} = \mathbf{0}", "verified"),
])
def test_a_range_of_an_accented_vector_is_its_entries_in_both_semantics(latex, verdict):
    r = _check(latex, QBAR)
    assert r.verdict == verdict
    assert any(m.startswith(r"\bar{q}_{1:3}: entries 1 to 3 of \bar{q}") for m in r.model)
    if verdict == "does-not-hold":
        q = [Fraction(r.counterexample["point"][f"qbar_{i}"]) for i in (1, 2, 3, 4)]
        assert sum(x * x for x in q) == 1 and q[3] != 0  # a unit 4-vector, its scalar part
        # left side, computed here: the squared norm of the vector part, 1 - q4^2
        assert Fraction(r.counterexample["lhs"]) == 1 - q[3] ** 2


def test_a_range_of_an_undeclared_accented_glyph_asks_for_that_glyph():
    with pytest.raises(ValueError, match=r"entries of \\bar\{q\}, which is no vector .*"
                                         r"--let '\\bar\{q\}: 4-vector'"):
        _check(r"\bar{q}_{1:3}^T\bar{q}_{1:3} = 1", [])


@pytest.mark.parametrize("lets, verdict", [([], None), ([JPL], "verified"), ([HAM], None),
                                           ([r"\otimes: Hamilton, scalar last"], "verified"),
                                           ([r"\otimes: JPL, scalar first"], None)])
def test_the_inverse_stored_scalar_last_is_asked_until_a_layout_is_declared(lets, verdict):
    """The conjugate over the norm written with the scalar last: true under JPL's and under
    Hamilton's rule with the scalar last (Szeliski, Eigen), false with the scalar first; with
    nothing declared the readings disagree and the reader is asked."""
    if verdict is None and not lets:
        with pytest.raises(BadInput, match=r"Hamilton's ij = k with the scalar last \(Szeliski"):
            _check(INV_LAST, [r"\mathbf{q}: 4-vector"])
        return
    r = _check(INV_LAST, [r"\mathbf{q}: 4-vector"] + lets)
    assert r.verdict == (verdict or "does-not-hold"), (lets, r.verdict)


HANSON_R = (r"R(q) = \begin{bmatrix} q_0^2 + q_1^2 - q_2^2 - q_3^2 & 2q_1q_2 - 2q_0q_3 & "
            r"2q_1q_3 + 2q_0q_2 \\ 2q_1q_2 + 2q_0q_3 & q_0^2 - q_1^2 + q_2^2 - q_3^2 & 2q_2q_3 - "
            r"2q_0q_1 \\ 2q_1q_3 - 2q_0q_2 & 2q_2q_3 + 2q_0q_1 & q_0^2 - q_1^2 - q_2^2 + q_3^2 "
            r"\end{bmatrix}")
HANSON = [r"q: unit 4-vector", r"p: unit 4-vector", HANSON_R]


def test_hansons_star_is_the_quaternion_product_asked_undeclared():
    """Hanson's ``q \\star p`` reads as ``\\otimes``: where the three readings disagree it is
    asked, naming the --let; the norm identity holds under all three."""
    with pytest.raises(BadInput, match=r"\\star\) is read two ways"):
        rigidsym.check_latex(r"R(q\star p) = R(q)R(p)", let=HANSON, repairs=False)
    r = rigidsym.check_latex(r"|q\star p| = |q||p|", let=["q: 4-vector", "p: 4-vector"],
                             repairs=False)
    assert r.verdict == "verified"


@pytest.mark.parametrize("right, verdict", [("R(q)R(p)", "verified"),
                                            ("R(p)R(q)", "does-not-hold")])
def test_hansons_star_decided_once_declared(right, verdict):
    r = rigidsym.check_latex(rf"R(q\star p) = {right}", let=[*HANSON, r"\star: Hamilton"],
                             repairs=False)
    assert r.verdict == verdict
