"""LaTeX -> MathML Core: the gaps of latex2mathml are closed on the book's own LaTeX."""

from __future__ import annotations

import re
import unicodedata

import pytest

from rigidsym.printing.mathml import bold_char, latex_to_mathml
from rigidsym.registry.declarations import REGISTRY, load_all

load_all()

#: what MathML Core would show wrongly or as source: an ignored mathvariant, an `&` as text,
#: a backslash command as an identifier or operator, an error element.
_DEFECTS = re.compile(r'mathvariant="(?!normal")[^"]*"|<m[ion]>&(amp;)?</m[ion]>'
                      r"|<m[ion][^>]*>\\[a-zA-Z]+|<merror")


def _text(mathml: str) -> str:
    return "".join(re.findall(r">([^<]+)<", mathml))


@pytest.mark.parametrize("eq_id", sorted(REGISTRY))
def test_every_printed_equation_converts_cleanly(eq_id):
    m = latex_to_mathml(REGISTRY[eq_id].latex)
    assert m.startswith("<math") and 'display="block"' in m
    assert not _DEFECTS.search(m), _DEFECTS.search(m).group(0)


def test_aligned_becomes_a_table_without_text_ampersands():
    m = latex_to_mathml(r"\begin{aligned} a &= b \\ &= c \end{aligned}")
    assert "&" not in _text(m).replace("&#x", "")
    assert m.count("<mtr>") == 2 and "<mtable" in m


def test_bracket_after_row_break_is_a_bracket():
    # (3.75): "\\ [\sin(\phi/2)]\mathbf{e}" once raised InvalidAlignmentError
    m = latex_to_mathml(r"\begin{bmatrix} [\sin(\phi/2)]\mathbf{e} \\ [x] \end{bmatrix}")
    assert m.count("<mtr>") == 2 and _text(m).count("[") == 2


@pytest.mark.parametrize("latex, name", [
    (r"\mathbf{1}", "MATHEMATICAL BOLD DIGIT ONE"),
    (r"\mathbf{0}", "MATHEMATICAL BOLD DIGIT ZERO"),
    (r"\mathbf{e}", "MATHEMATICAL BOLD SMALL E"),
    (r"\mathbf{\omega}", "MATHEMATICAL BOLD SMALL OMEGA"),
    (r"\boldsymbol{\omega}", "MATHEMATICAL BOLD ITALIC SMALL OMEGA"),
    (r"\boldsymbol{\Omega}", "MATHEMATICAL BOLD ITALIC CAPITAL OMEGA"),
    (r"\mathcal{F}", "SCRIPT CAPITAL F"),
])
def test_bold_and_script_become_unicode_characters(latex, name):
    m = latex_to_mathml(latex, display=False)
    assert 'display="inline"' in m
    assert "mathvariant" not in m.replace('mathvariant="normal"', "")
    chars = [c for c in unicodedata.normalize("NFC", _unescape(_text(m))) if not c.isspace()]
    assert [unicodedata.name(c) for c in chars] == [name]


def _unescape(s: str) -> str:
    import html
    return html.unescape(s)


@pytest.mark.parametrize("style, word", [("bold", "BOLD"), ("bold-italic", "BOLD ITALIC")])
def test_bold_char_names_agree_with_unicode(style, word):
    letters = ("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
               "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩαβγδεζηθικλμνξοπρστυφχψω")
    for c in letters:
        b = bold_char(c, style)
        plain = unicodedata.name(c).replace("LATIN ", "").replace("GREEK ", "")
        plain = plain.replace(" LETTER", "")
        assert unicodedata.name(b) == f"MATHEMATICAL {word} {plain}", c
    assert bold_char("+") == "+"


def test_unknown_command_is_text_not_an_identifier():
    m = latex_to_mathml(r"\foo x")
    assert not re.search(r"<mi>\\foo", m) and "<mtext>\\foo</mtext>" in m


def test_sympy_latex_converts():
    import sympy as sp
    x = sp.Symbol("omega_1")
    m = latex_to_mathml(sp.latex(sp.Matrix([[sp.sqrt(x) / 2, sp.atan(x)], [x**2, 0]])))
    assert not _DEFECTS.search(m) and m.count("<mtr>") == 2


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="latex"):
        latex_to_mathml(None)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="latex"):
        latex_to_mathml(r"\begin{bmatrix} a")
