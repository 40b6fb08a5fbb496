"""A reader's LaTeX decided on what it means, never on a guess (issue 40, items 1, 2 and the
printing half of 5): a matrix word inside a product decided, every undecided verdict with its
reason in words, function application, sized identities, bad input naming the --let that
settles a conventional shape, the per-book notations."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.checking.deciding import registry
from rigidsym.cli import main

AB = "a: vector; b: vector"


@pytest.fixture(autouse=True)
def _forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.letting")


def _cli(capsys, *args) -> tuple[int, str, str]:
    code = main(["check", *args])
    out = capsys.readouterr()
    return code, out.out, out.err


# ------------------------------------------------------- item 2: a matrix word in a product
# each was undecided on main with "TypeError: unhashable type: 'MutableDenseMatrix'"
@pytest.mark.parametrize("latex, let, verdict", [
    (r"a^T \mathrm{CPM}(b) a = 0", AB, "verified"),
    (r"a^T \mathrm{CPM}(b) a = 1", AB, "does-not-hold"),
    (r"(a \times b) \cdot a = 0", AB, "verified"),
    (r"b^T [a] b = 0", AB, "verified"),
    (r"x^T [\hat\omega]^2 x = (\hat\omega^T x)^2 - x^T x", r"\hat\omega: unit vector; x: vector",
     "verified"),
    (r"w^T \mathrm{ad}_{V} V = 0", "V: twist; w: 6-vector", "verified"),
    (r"V^T \mathrm{ad}_{V}^T F = 0", "V: twist; F: wrench", "verified"),
    (r"(\mathrm{Ad}_{T} V)^T (\mathrm{Ad}_{T} V) = V^T V", "V: twist; T: transform",
     "does-not-hold"),  # Ad_T is no orthogonal matrix
])
def test_a_matrix_word_inside_a_product_is_decided(latex, let, verdict):
    r = rigidsym.check_latex(latex, let=[let])
    assert r.verdict == verdict, r.detail


@pytest.mark.parametrize("rhs, verdict", [("1", "verified"), ("2", "does-not-hold")])
def test_the_norm_of_a_unit_vector_is_one(rhs, verdict):
    # on main: undecided ("the rational function of an expression with |x| or a root"),
    # and = 2 undecided too (its counterexample's sqrt raised)
    r = rigidsym.check_latex(rf"\|\hat\omega\| = {rhs}", let=[r"\hat\omega: unit vector"])
    assert r.verdict == verdict, r.detail


def test_the_norm_of_a_rotated_unit_vector_and_of_a_free_vector():
    let = [r"\hat\omega: unit vector; R: rotation"]
    assert rigidsym.check_latex(r"\sqrt{(R\hat\omega)^T R\hat\omega} = 1", let=let).verdict \
        == "verified"
    # a free vector's norm is no rational function: undecided, never guessed
    assert rigidsym.check_latex(r"\|x\| = 1", let=["x: vector"]).verdict == "undecided"


def test_an_undecided_verdict_prints_its_reason(capsys):
    # on main the text said "Verdict: undecided" and nothing else about why
    code, out, _ = _cli(capsys, "--latex", r"\|x\| = 1", "--let", "x: vector")
    assert code == 3
    assert "Undecided: printed: irrational root at the sample point" in out
    code, out, _ = _cli(capsys, "--latex", r"\sin x = 2\sin(x/2)\cos(x/2)")
    assert code == 3 and "Undecided: printed: trig" in out


def test_the_reports_print_the_reason_of_an_undecided_member():
    from rigidsym.report.html import to_html
    from rigidsym.report.markdown import to_markdown

    r = rigidsym.check_latex(r"\|x\| = 1", let=["x: vector"])
    md = to_markdown([r], title="t", source="a test")
    assert "**undecided**" in md and "(why: irrational root at the sample point)" in md
    assert "<b>Undecided:</b> printed: irrational root at the sample point" in to_html(
        [r], title="t", source="a test")
