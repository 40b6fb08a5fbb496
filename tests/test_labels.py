"""Book notation throughout the terminal: ASCII labels and evidence
in the book's Unicode, LaTeX pieces of running text rendered, ``--ascii`` for terminals
without Unicode, and the book operators printed as operators."""

from __future__ import annotations

import unicodedata

import pytest
import sympy as sp

from rigidsym.algebra.operators import Cpm, Vect
from rigidsym.checking.deciding.explicit import explicit
from rigidsym.declare import cpm, mat, trace, vec, vect
from rigidsym.printing import notation
from rigidsym.printing.ascii import to_ascii
from rigidsym.printing.labels import label_text, latex_spans, latex_text
from rigidsym.registry.declarations import REGISTRY, load_all

load_all()


@pytest.mark.parametrize("ascii_, book", [
    ("adot . omega/||omega||^2", "ȧ·ω/‖ω‖²"),
    ("Ntilde vdot", "Ñ v̇"),
    ("F~ = N~", "F̃ = Ñ"),
    ("x = [u; (A - C)^T u]: x^T (M_A - M_C) x = -m ||u x (a - c)||^2",
     "x = [u; (A - C)ᵀ u]: xᵀ (M_A - M_C) x = -m ‖u × (a - c)‖²"),
    ("rank 2 for phi != 0", "rank 2 for φ ≠ 0"),
    ("U U^-1 = 1", "U U⁻¹ = 1"),
    ("the upper-left block is the 3x4 rate", "the upper-left block is the 3x4 rate"),
])
def test_label_text(ascii_, book):
    assert label_text(ascii_) == unicodedata.normalize("NFC", book)


def test_english_words_are_left_alone():
    words = ("normal that what block parallel the theta-free note dot product pitch times "
             "inverse kernel point minimum moment e.g. i.e. symmetric involution")
    for w in words.split():
        if w not in ("theta-free",):
            assert label_text(w) == w, w


# building every statement costs about 17 s: a seeded quarter of the ids in the quick run,
# every id in the thorough one (each id's labels are its own declaration's words)
@pytest.mark.sample(fraction=0.25)
@pytest.mark.parametrize("eq_id", sorted(REGISTRY))
def test_every_label_and_evidence_reads_in_book_notation(eq_id):
    leftovers = ("omega", "adot", "Ntilde", "||", "^T", "phi ", "_dot")
    eq = REGISTRY[eq_id]
    texts = [eq.evidence or "", eq.title, eq.singular or ""]
    st = eq.build()
    texts += [r.label for r in st.printed + st.claims + (st.corrected or [])]
    for t in texts:
        shown = label_text(t)
        for bad in leftovers:
            assert bad not in shown, (eq.id, t, shown)


def test_latex_in_running_text():
    text = r"\dot{\mathbf{v}} (v is the velocity) printed where \dot{\boldsymbol{\nu}} is meant"
    spans = latex_spans(text)
    assert [p for tex, p in spans if tex] == [r"\dot{\mathbf{v}}", r"\dot{\boldsymbol{\nu}}"]
    assert "".join(p for _, p in spans) == text
    assert latex_text(r"\dot{\boldsymbol{\nu}}") == "ν\u0307"
    assert "\\" not in label_text(text)


def test_ascii_is_plain_ascii_and_readable():
    for book, plain in [("ȧ∥ = (ȧ·ω)/‖ω‖²", "adot_par = (adot.omega)/||omega||^2"),
                        ("Ñ v̇ ≈ 0.5", "N~ vdot ~ 0.5"), ("q₁₂ = √21/4", "q_12 = sqrt(21)/4"),
                        ("U⁻¹ U = 𝟏", "U^-1 U = 1")]:
        assert to_ascii(book) == plain


def test_show_ascii_prints_only_ascii(capsys):
    from rigidsym.cli import main
    assert main(["show", "3.16", "--ascii"]) == 0
    out = capsys.readouterr().out
    assert out.isascii() and "phi" in out and "e e^T" in out


def test_operators_print_as_operators_and_evaluate():
    Q, w, O = mat("Q"), vec("omega"), mat("Omega")
    assert notation.text(trace(Q)) == "tr(Q)"
    assert notation.text(cpm(w) * w) == "CPM(ω) ω"
    assert notation.text(vect(O)) == "vect(Ω)"
    assert isinstance(cpm(w), Cpm) and isinstance(vect(O), Vect)
    wv = sp.ImmutableMatrix([1, 2, 3])
    Ov = sp.ImmutableMatrix([[0, -3, 2], [3, 0, -1], [-2, 1, 0]])
    model = {w: wv, O: Ov, Q: sp.ImmutableMatrix(sp.eye(3))}
    assert explicit(cpm(w) * w, model) == sp.zeros(3, 1)       # ω × ω = 0
    assert explicit(vect(O), model) == wv                       # vect(CPM(ω)) = ω
    assert explicit(trace(Q), model) == 3
    assert explicit(cpm(w), model) == cpm(sp.Matrix(wv))        # the same as explicit
    assert cpm(sp.Matrix([1, 2, 3])).shape == (3, 3) and not isinstance(
        cpm(sp.Matrix([1, 2, 3])), Cpm)                         # explicit stays explicit
