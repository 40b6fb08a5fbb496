r"""The readings of the books' notations (``rigidsym.latex.hats``, ``rigidsym.latex.entries``,
Shuster's ``[[u]]``): each reading a book's notation allows is read, a verdict where the readings
that type-check agree, bad input naming the choice where they differ. The truths are the books' (a
unit quaternion's entries square to 1; ``[T]_\times`` annihilates ``T``), not the code's."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.core.errors import BadInput


def _check(latex, let=()):
    return rigidsym.check_latex(latex, let=list(let), repairs=False)


# ------------------------------------------------------------------ a free hat
def test_a_hat_that_only_a_skew_matrix_fits_is_the_skew_matrix():
    # Ma-Soatto-Kosecka-Sastry: E = T^ R, E^T T = 0 (a unit vector T^ times R does not fit)
    r = _check(r"E^T T = 0", [r"E = \widehat{T}R", "R: rotation", "T: vector"])
    assert r.verdict == "verified", r.detail
    assert any("read as the skew matrix" in n for n in r.model), r.model
    assert any(n.startswith("numeric cross-check") and "agree" in n for n in r.model), r.model
    assert _check(r"E T = 0", [r"E = \widehat{T}R", "R: rotation", "T: vector"]).verdict \
        == "does-not-hold"


def test_a_hat_that_only_a_unit_vector_fits_is_a_unit_vector():
    # Lynch-Park: [w^]^2 = w^ w^T - I for a unit w^; a plain omega is a scalar, no skew
    r = _check(r"[\hat\omega]^2 = \hat\omega\hat\omega^T - I_3")
    assert r.verdict == "verified", r.detail
    assert any("read as a unit vector of its own" in n for n in r.model), r.model
    assert _check(r"[\hat\omega]^2 = \hat\omega\hat\omega^T + I_3").verdict == "does-not-hold"


def test_a_hat_whose_two_readings_disagree_is_refused_naming_both_settlements():
    # x2^T T^ R x1 = 0: as a unit vector (x2 . T^) R x1 = 0 fails, as [T]x it holds
    with pytest.raises(BadInput) as e:
        _check(r"\mathbf{x}_2^T\widehat{T}R\mathbf{x}_1 = 0",
               ["R: rotation", "T: vector",
                r"\mathbf{x}_2 = \frac{\lambda_1 R\mathbf{x}_1 + T}{\lambda_2}"])
    msg = str(e.value)
    assert "the readings disagree" in msg
    assert r"--let '\hat{T}: unit vector'" in msg and "--notation murray-li-sastry" in msg
    r = _check(r"\mathbf{x}_2^T\widehat{T}R\mathbf{x}_1 = 0",
               ["R: rotation", "T: vector", r"\hat{T} = [T]_\times",
                r"\mathbf{x}_2 = \frac{\lambda_1 R\mathbf{x}_1 + T}{\lambda_2}"])
    assert r.verdict == "verified", r.detail


def test_two_hats_are_read_together_in_both_semantics():
    # MSKS: u^ v = -v^ u; each hat a choice point, the second met only past the first
    r = _check(r"\widehat{u}v = -\widehat{v}u", ["u: vector", "v: vector"])
    assert r.verdict == "verified", r.detail
    assert _check(r"\widehat{u}v = \widehat{v}u", ["u: vector", "v: vector"]).verdict \
        == "does-not-hold"


# ------------------------------------------------------------------ q_k of a --let's vector
UNIT4 = r"\mathbf{q}: unit 4-vector"


@pytest.mark.parametrize("latex, verdict", [
    (r"q_1^2 + q_2^2 + q_3^2 + q_4^2 = 1", "verified"),     # q_4: counted from 1, unique
    (r"q_0^2 + q_1^2 + q_2^2 + q_3^2 = 1", "verified"),     # q_0: counted from 0, unique
    (r"q_0^2 + q_1^2 + q_2^2 = 1", "does-not-hold"),        # from 0 only, a slip
    (r"q_1^2 + q_2^2 + q_3^2 = 1", "does-not-hold"),        # both counts: both fail
])
def test_a_4_vectors_subscripts_are_its_entries_counted_as_the_latex_allows(latex, verdict):
    r = _check(latex, [UNIT4])
    assert r.verdict == verdict, r.detail
    assert any("entry" in n and r"\mathbf{q}" in n for n in r.model), r.model


def test_a_4_vectors_count_that_changes_the_verdict_is_refused_naming_the_entry():
    # q_1^2 + q_2^2 + q_3^2 = 1 - q_4^2 (written \mathbf{q}_{4:4}): true counted from 1 only
    with pytest.raises(BadInput) as e:
        _check(r"q_1^2 + q_2^2 + q_3^2 = 1 - \mathbf{q}_{4:4}^2", [UNIT4])
    msg = str(e.value)
    assert "count its entries from 1 or from 0" in msg and r"\mathbf{q}_{1:1}" in msg, msg


def test_a_3_vectors_subscripts_are_its_entries_and_a_let_makes_a_symbol_of_its_own():
    r = _check(r"a_1^2 + a_2^2 + a_3^2 = \mathbf{a}^T\mathbf{a}", [r"\mathbf{a}: vector"])
    assert r.verdict == "verified", r.detail       # not refused as two readings
    own = _check(r"a_1^2 + a_2^2 + a_3^2 = \mathbf{a}^T\mathbf{a}",
                 [r"\mathbf{a}: vector", "a_1: scalar"])
    assert own.verdict == "does-not-hold", own.detail


def test_markley_crassidis_q4_reads_as_typed():
    xi = (r"\Xi(\mathbf{q}) = \begin{bmatrix} q_4 I_3 + [\mathbf{q}_{1:3}\times] \\ "
          r"-\mathbf{q}_{1:3}^T \end{bmatrix}")
    assert _check(r"\Xi^T(\mathbf{q})\mathbf{q} = \mathbf{0}_3", [xi, UNIT4]).verdict \
        == "verified"
    assert _check(r"\Xi^T(\mathbf{q})\Xi(\mathbf{q}) = I_3", [xi, UNIT4]).verdict == "verified"
    assert _check(r"\Xi^T(\mathbf{q})\Xi(\mathbf{q}) = 2I_3", [xi, UNIT4]).verdict \
        == "does-not-hold"


# ------------------------------------------------------------------ one notation per letter
DIEBEL = (r"R(\mathbf{q}) = \begin{bmatrix} q_0^2 + q_1^2 - q_2^2 - q_3^2 & 2q_1q_2 + 2q_0q_3 "
          r"& 2q_1q_3 - 2q_0q_2 \\ 2q_1q_2 - 2q_0q_3 & q_0^2 - q_1^2 + q_2^2 - q_3^2 & "
          r"2q_2q_3 + 2q_0q_1 \\ 2q_1q_3 + 2q_0q_2 & 2q_2q_3 - 2q_0q_1 & q_0^2 - q_1^2 - "
          r"q_2^2 + q_3^2 \end{bmatrix}")


def test_a_parameters_entries_are_the_free_vectors_entries_outside_the_body():
    # the body's q_i are its parameter's entries or symbols of their own; outside it the
    # same reading holds (names outside would make the readings disagree: refused)
    r = _check(r"R(\mathbf{q})^TR(\mathbf{q}) = (q_0^2 + q_1^2 + q_2^2 + q_3^2)^2 I_3", [DIEBEL])
    assert r.verdict == "verified", r.detail
    with pytest.raises(BadInput, match="the readings disagree"):  # q^T q: entries only
        _check(r"R(\mathbf{q})^TR(\mathbf{q}) = (q_0^2 + \mathbf{q}^T\mathbf{q})^2 I_3",
               [DIEBEL])


# ------------------------------------------------------------------ a free bold capital
def test_a_free_bold_capital_is_a_vector_only_where_its_3x3_does_not_fit():
    r = _check(r"\mathbf{a} + \mathbf{Y} = \mathbf{Y} + \mathbf{a}")  # 3-vector + 3x3: no
    assert r.verdict == "verified", r.detail
    assert any(r"\mathbf{Y}: read as a 3-vector" in n for n in r.model), r.model
    assert _check(r"\mathbf{a} + \mathbf{Y} = \mathbf{Y} - \mathbf{a}").verdict == "does-not-hold"
    r = _check(r"\mathbf{Y}\mathbf{a} = \mathbf{a}")  # the convention fits: no choice
    assert r.verdict == "does-not-hold" and not any("read as a 3-vector" in n for n in r.model)


def test_a_bold_subscripted_name_beside_a_declared_vector_stays_a_choice():
    # \mathbf{p}_1 is point 1 as often as an entry: of the two readings the entry (a
    # scalar = a 3-vector) does not type-check, so point 1, a vector of its own, is decided
    r = _check(r"\mathbf{p}_1 = R\mathbf{p}_2 + \mathbf{p}", [r"\mathbf{p}: vector", "R: rotation"])
    assert r.verdict == "does-not-hold", r.detail


def test_a_hat_met_only_once_another_is_a_matrix_is_read_both_ways_too():
    # Murray-Li-Sastry's \hat{u}v = -\hat{v}u, nothing declared: with the first hat a unit
    # vector the reading fails before the second hat is met; the second's readings are
    # enumerated once the first is the skew matrix (the statement was refused as "neither
    # reading fits"); only [u]x v = -[v]x u type-checks, and its slip does not hold
    ok = rigidsym.check_latex(r"\hat{\mathbf{u}}\mathbf{v} = -\hat{\mathbf{v}}\mathbf{u}",
                              repairs=False)
    assert ok.verdict == "verified"
    slip = rigidsym.check_latex(r"\hat{\mathbf{u}}\mathbf{v} = \hat{\mathbf{v}}\mathbf{u}",
                                repairs=False)
    assert slip.verdict == "does-not-hold"
