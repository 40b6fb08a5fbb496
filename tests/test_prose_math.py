"""The ASCII mathematics of the exercises' sentences typeset: runs of mathematics
become inline LaTeX in book notation, which the page's converter turns into MathML; the
English words stay text. (The whole page in a browser: tests/test_browser.py.)"""

from __future__ import annotations

import pytest

from rigidsym.printing.mathml import latex_to_mathml
from rigidsym.printing.prose import prose_latex_runs, prose_markdown


def _math(text: str) -> list[str]:
    return [p for m, p in prose_latex_runs(text) if m]


def _text(text: str) -> str:
    return "".join(p for m, p in prose_latex_runs(text) if not m)


def test_the_angle_step_of_exercise_3_1_is_one_formula_and_a_full_stop():
    runs = prose_latex_runs("cos(phi) = (tr Q - 1)/2.")
    assert [m for m, _ in runs] == [True, False] and runs[1][1] == "."
    tex = runs[0][1]
    assert r"\cos" in tex and r"\phi" in tex and r"\operatorname{tr}" in tex
    mathml = latex_to_mathml(tex, display=False)
    assert "merror" not in mathml and "&#x003D5;" in mathml   # φ, as the book prints it


def test_english_words_stay_text_and_symbols_between_them_are_formulas():
    s = "Both moments are normal to e, so e is parallel to n_A x n_B."
    assert _math(s) == ["e", "e", r"n_{A} \times n_{B}"]
    assert "Both moments are normal to" in _text(s) and "is parallel to" in _text(s)


def test_the_article_a_is_a_word_and_a_symbol_a_is_a_symbol():
    assert _math("a point whose moment about O is the line's") == ["O"]
    assert _math("A rotation preserves n.f") == [r"n \cdot f"]
    assert _math("a x (b x c) = (a.c) b - (a.b) c") == [
        r"a \times ( b \times c ) = ( a \cdot c ) b - ( a \cdot b ) c"]


def test_a_full_stop_is_not_a_dot_product():
    assert _math("d = ||n||. Then e.e = 1.") == [r"d = \| n \|", r"e \cdot e = 1"]


@pytest.mark.parametrize("text", ["Eq. (3.18) and Eq. (3.133a)", "(a) angle", "(a)-(b) hold",
                                  "22 closed algebraic entries are 0 (minimal polynomial)"])
def test_numbers_item_letters_and_equation_numbers_stay_text(text):
    assert prose_markdown(text) == text


def test_brackets_with_words_inside_are_text_their_formulas_typeset():
    out = prose_markdown("e = vect(Q)/sin(phi) (a column of Q + 1 for a half turn).")
    assert out.startswith(r"$e = \operatorname{vect} ( Q ) / \sin ( \phi )$ (a column of $Q + 1$")
    assert out.endswith("for a half turn).")


def test_superscripts_take_their_group_and_stack_as_tex_allows():
    assert _math("||omega||^(2(k-1)) omega omega^T") == [
        r"\| \omega \| ^{2 ( k - 1 )} \omega \omega ^{T}"]
    (tex,) = _math("tr(Omega_dot Omega^2^T) = 0")
    assert "merror" not in latex_to_mathml(tex, display=False)   # no double superscript


def test_every_formula_of_the_exercise_sentences_converts_to_mathml():
    sentences = ["p0 + lambda e with the i-th coordinate zero (planes x = 0, y = 0, z = 0)",
                 "The moment is least (parallel to f) on the central axis "
                 "{f x n_O / ||f||^2 + lambda f}.",
                 "x is principal; the y-z block's eigenvalues (I_yy + I_zz)/2 -+ "
                 "sqrt(((I_yy - I_zz)/2)^2 + I_yz^2); sorted, smallest first.",
                 "P(false zero) <= 1.77E-120, det W != 0, k >= 1, W^-1 omega, p* x e = n"]
    for s in sentences:
        pieces = _math(s)
        assert pieces, s
        for tex in pieces:
            assert "merror" not in latex_to_mathml(tex, display=False), tex
    assert r"\sqrt{" in " ".join(_math(sentences[2]))
