"""The rates of a vector's entries and numeval's zero rows: Greenwood's Euler-parameter rates
``\\dot\\epsilon_1 ... \\dot\\epsilon_4`` are the entries of the declared rate
``\\dot{\\boldsymbol\\epsilon}`` (Greenwood, Advanced Dynamics, the Euler parameters'
kinematic equations), and a zero row ``\\mathbf{0}^\\top`` under a column block is one row
high in the numeric semantics as in the symbolic one."""

from __future__ import annotations

from fractions import Fraction

import pytest

import rigidsym
from rigidsym.latex.respell import rate_entries
from rigidsym.registry import declarations as registry

RATE = (r"\dot{\boldsymbol\epsilon} = \frac{1}{2}\begin{bmatrix} \epsilon_4 & -\epsilon_3 & "
        r"\epsilon_2 \\ \epsilon_3 & \epsilon_4 & -\epsilon_1 \\ -\epsilon_2 & \epsilon_1 & "
        r"\epsilon_4 \\ -\epsilon_1 & -\epsilon_2 & -\epsilon_3\end{bmatrix}\boldsymbol\omega")
LETS = [r"\boldsymbol\epsilon: unit 4-vector", RATE, r"\boldsymbol\omega: vector"]
DOT4 = (r"\dot\epsilon_4 = S\frac{1}{2}"
        r"(\omega_1\epsilon_1 + \omega_2\epsilon_2 + \omega_3\epsilon_3)")


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_greenwoods_entry_rates_are_the_entries_of_the_declared_rate():
    r = rigidsym.check_latex(r"\dot\epsilon_1 = \frac{1}{2}(\omega_1\epsilon_4 - "
                             r"\omega_2\epsilon_3 + \omega_3\epsilon_2)", let=LETS, repairs=False)
    assert r.verdict == "verified", r.detail
    assert any(r"entry 1 of \dot{\boldsymbol{\epsilon}}" in n for n in r.model), r.model


def test_the_fourth_rate_and_its_sign_slip():
    r = rigidsym.check_latex(DOT4.replace("S", "-"), let=LETS, repairs=False)
    assert r.verdict == "verified", r.detail
    slip = rigidsym.check_latex(DOT4.replace("S", ""), let=LETS, repairs=False)
    assert slip.verdict == "does-not-hold" and slip.counterexample
    lhs, rhs = (Fraction(slip.counterexample[k]) for k in ("lhs", "rhs"))
    # the true rate is -(ω·ε_{1:3})/2 and the slip's side its negative: opposite, not equal
    assert lhs == -rhs and lhs != 0


def test_a_let_of_the_entry_rate_keeps_it_a_symbol_of_its_own():
    latex = r"\dot\epsilon_1 = x"
    out, lets, note = rate_entries(latex, LETS)
    assert out == r"\dot{\boldsymbol{\epsilon}}_{1:1} = x" and note
    own = rate_entries(latex, [*LETS, r"\dot\epsilon_1: scalar"])
    assert own[0] == latex and own[2] == ""
    # counted from 0 where the LaTeX writes an epsilon_0
    assert rate_entries(r"\dot\epsilon_0 = \epsilon_0", LETS)[0].startswith(
        r"\dot{\boldsymbol{\epsilon}}_{1:1}")


def test_a_zero_row_under_a_column_block_is_one_row_in_both_semantics():
    block = r"\begin{bmatrix}\mathbf{A} \\ \mathbf{0}^\top\end{bmatrix}^\top" \
            r"\begin{bmatrix}\mathbf{a}\\ 1\end{bmatrix}"
    r = rigidsym.check_latex(block + r" = \mathbf{A}^\top\mathbf{a}", repairs=False)
    assert r.verdict == "verified", r.detail
    slip = rigidsym.check_latex(block + r" = \mathbf{A}\mathbf{a}", repairs=False)
    assert slip.verdict == "does-not-hold" and slip.counterexample


E_T = r"\mathbf{e}(t): unit 4-vector"


@pytest.mark.parametrize("latex, verdict", [
    # Baruh's Euler parameters e_0 ... e_3 of a unit 4-vector of time: e · ė = 0
    (r"e_0\dot e_0 + e_1\dot e_1 + e_2\dot e_2 + e_3\dot e_3 = 0", "verified"),
    (r"e_0\dot e_0 + e_1\dot e_1 + e_2\dot e_2 = 0", "does-not-hold"),
    # counted from 1
    (r"e_1\dot e_1 + e_2\dot e_2 + e_3\dot e_3 + e_4\dot e_4 = 0", "verified"),
])
def test_the_rate_of_an_entry_of_a_vector_of_time_is_the_entry_of_its_rate(latex, verdict):
    r = rigidsym.check_latex(latex, let=[E_T], repairs=False)
    assert r.verdict == verdict, r.model
    assert any("of the rate of \\mathbf{e}" in n for n in r.model), r.model


#: Kane & Levinson's Euler parameters: a plain letter, \epsilon(t): unit 4-vector
EPS_T = r"\epsilon(t): unit 4-vector"


def test_the_entry_rates_of_a_plain_vector_of_time_are_the_entries_of_its_rate():
    out, _, note = rate_entries(r"\dot\epsilon_1 = x", [EPS_T])
    assert out == r"\dot{\epsilon}_{1:1} = x" and r"entry 1 of \dot{\epsilon}" in note


@pytest.mark.parametrize("latex, verdict", [
    (r"\epsilon_1\dot\epsilon_1 + \epsilon_2\dot\epsilon_2 + \epsilon_3\dot\epsilon_3 + "
     r"\epsilon_4\dot\epsilon_4 = 0", "verified"),
    pytest.param(r"\epsilon_1\dot\epsilon_1 + \epsilon_2\dot\epsilon_2 + "
                 r"\epsilon_3\dot\epsilon_3 = 0", "does-not-hold", marks=pytest.mark.slow),
])
def test_kanes_entry_rates_of_a_unit_4_vector_of_time_are_tangent(latex, verdict):
    r = rigidsym.check_latex(latex, let=[EPS_T], repairs=False)
    assert r.verdict == verdict, r.model
    assert any(r"entry 1 of \dot{\epsilon}" in n for n in r.model), r.model
