"""What a reader sees of a symbol, as the book prints it: no LaTeX command as a word
((3.59)'s braces), a block-diagonal matrix as its blocks ((3.148)), the book's O₃₄ ((3.94)),
one subscript per letter (an entry of I_C is (I_C)₂₁), letter subscripts as subscripts in
HTML (M_A), and a reader's scalar K_1 never printed as the first entry of their vector K.
Each test guards against a defect of commit 3915e94."""

from __future__ import annotations

import re
import unicodedata
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

from rigidsym.cli import main
from rigidsym.printing import notation
from rigidsym.printing.labels import label_latex, label_text
from rigidsym.printing.names import book_latex, book_text
from rigidsym.registry import declarations as registry
from rigidsym.registry.declarations import REGISTRY, load_all

REPORT = Path(__file__).resolve().parents[1] / "generated" / "report"
#: a LaTeX subscript on a subscript: I_{C}_{21} is a TeX error ("double subscript")
_DOUBLE_SUB = re.compile(r"_\{[^{}]*\}_\{")


def _html_text(page: str) -> str:
    from tests.test_reader_names import html_text
    return html_text(page)


# ------------------------------------------------------------------------- (3.59)
def test_the_braced_terms_of_3_59_read_in_words_not_as_latex():
    load_all()
    st = REGISTRY["3.59"].build()
    texts = [r.label for r in st.printed + (st.corrected or [])] + [REGISTRY["3.59"].evidence]
    for t in texts:
        assert "underbrace" not in label_text(t), label_text(t)
        assert "underbrace" not in label_latex(t), label_latex(t)
    assert label_text("pdot_perp brace") == "braced ṗ⊥"
    assert label_latex("pdot_perp brace") == r"\text{braced } \dot{p}_{\perp}"
    md = (REPORT / "chapter3.md").read_text(encoding="utf-8")
    md = re.sub(r"\$\$.*?\$\$", " ", md, flags=re.S)   # the book's own LaTeX aside
    assert "underbrace" not in md
    assert "underbrace" not in _html_text((REPORT / "chapter3.html").read_text("utf-8"))


# ------------------------------------------------------------------------ (3.148)
def test_a_block_diagonal_matrix_reads_as_its_blocks():
    """The book prints block-diagonal matrices as their blocks ((3.138): [I, O; O, m1]);
    (3.148)'s corrected label said diag(I_C, O) beside [O, C - A; O, 1]."""
    assert label_text("J = diag(I_C, O), P = [C - A; 1]") == "J = [I_C, O; O, O], P = [C - A; 1]"
    assert label_text("W = diag(Omega, m 1)") == "W = [Ω, O; O, m 1]"
    assert "diag" not in label_latex("J = diag(I_C, O)")
    assert "x_{6}" not in label_latex("6x6 R = [O, C - A; O, 1]")   # a size, not x₆
    load_all()
    st = REGISTRY["3.148"].build()   # the label's [I_C, O; O, O] is the declaration's J
    J = sp.Matrix(st.model[sp.MatrixSymbol("J", 6, 6)])
    I_C = next(v for k, v in st.model.items() if getattr(k, "name", "") == "I_C")
    assert J[:3, :3] == sp.Matrix(I_C) and J[:3, 3:].is_zero_matrix and \
        J[3:, :].is_zero_matrix
    md = (REPORT / "chapter3.md").read_text(encoding="utf-8")
    assert "diag(" not in md and "J = [I_C, O; O, O], P = [C - A; 1]" in md
    assert "diag(" not in _html_text((REPORT / "chapter3.html").read_text("utf-8"))


# ------------------------------------------------------------------------- (3.94)
def test_zero_blocks_print_as_the_book_prints_them():
    """(3.94) prints [Ḟ, O; O₃₄, O] and (3.92) [Ḟ, O₄₃; O, O]: a non-square zero block
    carries its size, in text and LaTeX."""
    Z = sp.ZeroMatrix(3, 4)
    assert notation.text(Z) == "O₃₄" and notation.latex(Z) == r"\mathbf{O}_{34}"
    assert notation.text(sp.ZeroMatrix(3, 3)) == "O"
    load_all()
    for eq_id, block in (("3.94", r"\mathbf{O}_{34}"), ("3.92", r"\mathbf{O}_{43}")):
        assert block in REGISTRY[eq_id].latex   # the book's
        for r in REGISTRY[eq_id].build().printed:
            assert block in notation.latex(r.rhs), (eq_id, notation.latex(r.rhs))


# ------------------------------------------------------------- subscripts, entries
def test_an_entry_of_a_subscripted_matrix_has_one_subscript():
    I_C = sp.MatrixSymbol("I_C", 3, 3)
    assert notation.text(I_C[1, 0]) == "(I_C)₂₁"
    assert notation.latex(I_C[1, 0]) == r"\left(\mathbf{I}_{C}\right)_{21}"
    assert book_text("I_C_21") == "(I_C)₂₁"
    assert not _DOUBLE_SUB.search(book_latex("I_C_21"))
    assert notation.text(sp.MatrixSymbol("a", 3, 1)[0, 0]) == "a₁"   # plain entries as before
    json_text = (REPORT / "chapter3.json").read_text(encoding="utf-8")
    assert not _DOUBLE_SUB.search(json_text.replace("\\\\", "\\")), "a double subscript"


def test_letter_subscripts_are_subscripts_in_html():
    """Unicode has no subscript capitals, so the text writes M_A; the HTML page sets the
    subscript as the MathML beside it does (labels, causes, repairs, code spans), and
    leaves code names, MathML and attributes alone."""
    from rigidsym.report.html import letter_subscripts as sub
    assert sub("<p>M_A - M_C</p>") == "<p>M<sub>A</sub> - M<sub>C</sub></p>"
    assert sub("<code>Ṡ_N = [Ḟ, O; O₃₄, O]</code>").startswith("<code>Ṡ<sub>N</sub> =")
    assert sub("<p>μ_i², s_wᵀ</p>") == "<p>μ<sub>i</sub>², s<sub>w</sub>ᵀ</p>"
    kept = ('<p>kernel plucker_transfer, ad_dual(V), p_L2</p><a href="#a_b">x</a>'
            "<math><mi>M_A</mi></math><pre>s_t</pre>")
    assert sub(kept) == kept
    page = (REPORT / "chapter3.html").read_text("utf-8")
    shown = re.sub(r"<math.*?</math>|<pre.*?</pre>", " ", page, flags=re.S)
    for name in ("M_A", "Ṡ_N", "I_C", "m_i"):
        assert name not in unicodedata.normalize("NFC", _html_text(shown)), name
    page = unicodedata.normalize("NFC", page)
    assert "M<sub>A</sub>" in page and "Ṡ<sub>N</sub>" in page



def test_the_exercises_page_sets_letter_subscripts_too():
    """The exercises HTML (Markdown through markdown_to_html) wrote I_C and I_xx with an
    underscore where the chapter page sets them as subscripts; an inline SVG figure keeps
    its text as drawn (no <sub> inside <svg>)."""
    from rigidsym.report.html import markdown_to_html
    svg = '<svg xmlns="http://www.w3.org/2000/svg"><text>p_C</text></svg>'
    page = markdown_to_html("I_C e_z = I_zz e_z, `I_C_per_kg_m2`\n\n![axis](f.svg)\n",
                            "t", {"f.svg": svg})
    assert "I<sub>C</sub> e<sub>z</sub> = I<sub>zz</sub> e<sub>z</sub>" in page
    assert "I_C_per_kg_m2" in page and "<text>p_C</text>" in page
    shown = (REPORT / "exercises.html").read_text("utf-8")
    # the page's sentences typeset their mathematics: I_C is a MathML subscript
    assert "<msub><mi>I</mi><mrow><mi>C</mi></mrow></msub>" in shown
    text = re.sub(r"<math\b.*?</math>|<svg\b.*?</svg>|<code>.*?</code>", " ", shown, flags=re.S)
    assert "I_C" not in text
    assert not re.search(r"<svg\b(?:(?!</svg>).)*<sub>", shown, flags=re.S)

# ------------------------------------------------------ a reader's K_1 and vector K
@pytest.fixture
def _forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_a_scalar_K_1_and_the_unit_vector_K_print_apart(capsys, _forget_latex_ids):
    # K_1 declared a scalar of its own (undeclared beside the vector K it is K's entry 1)
    code = main(["check", "--latex", r"K_1 = \mathbf{K}^T\mathbf{a}",
                 "--let", r"\mathbf{K}: unit vector", "--let", "K_1: scalar"])
    out = capsys.readouterr().out
    assert code == 1 and "Counterexample" in out
    block = out.split("Counterexample", 1)[1].split("left side", 1)[0]
    rows = dict(line.strip().split(" = ", 1) for line in block.splitlines()[1:]
                if " = " in line)
    assert len(rows) == len([x for x in block.splitlines()[1:] if " = " in x]), block
    assert {"K₁", "K", "a"} <= set(rows), block
    K = [Fraction(x) for x in rows["K"].split("≈")[0].strip(" []").split(";")]
    assert sum(x * x for x in K) == 1   # the vector K, a unit vector, exactly
    left = out.split("left side K₁ = ", 1)[1].split()[0]
    assert Fraction(rows["K₁"].split("≈")[0].strip()) == Fraction(left)   # the scalar


def test_a_renamed_vector_entry_never_prints_as_the_scalar():
    # latex.values._fresh names the entries of \mathbf{K} K__1.. beside a scalar K_1
    from rigidsym.report.record import _atom_text
    assert book_text("K__1") == "(K)₁" != book_text("K_1") == "K₁"
    assert book_latex("K__1") == r"\left(\mathbf{K}\right)_{1}"
    assert _atom_text("K__1") != _atom_text("K_1")


def test_a_cross_product_of_a_cross_product_keeps_its_parentheses():
    """× is not associative: (a × b) × c and a × (b × c) printed alike ("a × b × c") in the
    ``read as:`` line and the members would show a does-not-hold with two equal-looking
    sides."""
    from rigidsym.algebra.operators import Cross

    a, b, c = (sp.MatrixSymbol(n, 3, 1) for n in "abc")
    left, right = notation.text(Cross(Cross(a, b), c)), notation.text(Cross(a, Cross(b, c)))
    assert left == "(a × b) × c" and right == "a × (b × c)"
    assert notation.text(Cross(Cross(a, b), Cross(b, c))) == "(a × b) × (b × c)"
    # R (a × b) and (R a) × b, (a × b)ᵀ and a × bᵀ: each printed "R a × b", "a × bᵀ" before
    R = sp.MatrixSymbol("R", 3, 3)
    assert notation.text(R * Cross(a, b)) == "R (a × b)"
    assert notation.text(Cross(R * a, R * b)) == "(R a) × (R b)"
    assert notation.text(Cross(a, b).T * R) == "(a × b)ᵀ R"
    assert notation.text(Cross(a + b, c)) == "(a + b) × c"


def test_a_power_of_a_sine_is_printed_as_the_books_do():
    """(sin θ)² prints "sin² θ", never "sin θ²", which reads as sin(θ²)."""
    t = sp.Symbol("theta")
    assert notation.text(sp.sin(t) ** 2) == "sin² θ"
    assert notation.text(sp.sin(t ** 2)) == "sin(θ²)"
    assert notation.text(1 - sp.cos(t) ** 3) == "1 - cos³ θ"


def test_a_square_root_covers_its_whole_radicand():
    """‖R a‖ never prints "√aᵀ Rᵀ R a", where the root seems to cover aᵀ
    only. A radicand that is one group keeps its own parentheses, never doubled."""
    a, R = sp.MatrixSymbol("a", 3, 1), sp.MatrixSymbol("R", 3, 3)  # as the reader reads it
    assert notation.text(sp.sqrt(sp.Trace(a.T * R.T * R * a))) == "√(aᵀ Rᵀ R a)"
    assert notation.text(sp.sqrt(sp.Trace(a.T * a))) == "√(a·a)"
    x, y = sp.symbols("x y")
    assert notation.text(sp.sqrt(x)) == "√x"
    assert notation.text(sp.sqrt(x + y)) == "√(x + y)"
    assert notation.text(sp.sqrt(x * y)) == "√(x y)"
    assert notation.text(sp.Abs(x)) == "|x|" and notation.text(sp.Abs(x - y)) == "|x - y|"


def test_vec_and_underline_print_as_accents():
    """\\vec{a} and \\underline{a} print as accents, never "veca" and "underlinea"."""
    from rigidsym.latex.shapes import name_from_key
    from rigidsym.printing.names import book_latex, book_text

    assert book_text(name_from_key(r"\vec{a}")) == "a\u20d7"
    assert book_text(name_from_key(r"\underline{a}")) == "a\u0332"
    assert book_text(name_from_key(r"\vec{\omega}")) == "ω\u20d7"
    assert book_latex(name_from_key(r"\vec{a}")) == r"\vec{a}"
    assert book_text("avec") != book_text("a")   # never the plain letter


def test_greek_letters_inside_a_subscript_print_as_letters():
    """Spong's R_{z,\\theta+\\phi} prints its Greek letters, never "R_z,theta+phi"; a
    Latin subscript stays as written."""
    from rigidsym.latex.shapes import name_from_key
    from rigidsym.printing.names import book_text

    assert book_text(name_from_key(r"R_{z,\theta}")) == "R_z,θ"
    assert book_text(name_from_key(r"R_{z,\theta+\phi}")) == "R_z,θ+φ"
    assert book_text(name_from_key(r"v_{max}")) == "v_max"      # no Greek word in it
    assert book_text(name_from_key(r"x_{i+1}")) == "x_i+1"
