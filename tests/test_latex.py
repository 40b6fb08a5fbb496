"""The reader of the chapter's LaTeX and the transcription check (issue 29)."""

from __future__ import annotations

import dataclasses

import pytest
import sympy as sp

from rigidsym.checking.deciding.registry import REGISTRY, Rel, load_all
from rigidsym.latex import LatexError, parse_latex
from rigidsym.latex.transcription import check_transcription


def test_rodrigues_parses_to_book_operators():
    p = parse_latex(r"\mathbf{Q} = \mathbf{e}\mathbf{e}^T + \cos\phi(\mathbf{1} - "
                    r"\mathbf{e}\mathbf{e}^T) + \sin\phi\,\mathbf{E}", "3.2")
    lhs, rhs = p.chains[0]
    assert lhs == sp.MatrixSymbol("Q", 3, 3)
    assert rhs.shape == (3, 3)
    assert sp.cos(sp.Symbol("phi", real=True)) in rhs.atoms(sp.cos)


def test_chain_gives_one_relation_per_link_and_pairs():
    p = parse_latex(r"\dot{\mathbf{p}} = \boldsymbol{\Omega}\mathbf{p} = "
                    r"\boldsymbol{\omega} \times \mathbf{p}", "3.3")
    assert len(p.relations) == 2 and len(list(p.pairs())) == 3


def test_unknown_macro_is_named_with_a_caret():
    with pytest.raises(LatexError) as exc:
        parse_latex(r"m = \int_{\mathcal{B}} \rho d\mathcal{B}")
    assert "\\int" in str(exc.value) and "^" in str(exc.value)


def test_syntax_error_has_position_and_expected():
    with pytest.raises(LatexError) as exc:
        parse_latex(r"\mathbf{a} = (\mathbf{b} + ")
    assert "position" in str(exc.value) and "expected" in str(exc.value)


def test_shapes_that_do_not_fit_are_an_error():
    with pytest.raises(LatexError, match="juxtaposition|shapes|sum"):
        parse_latex(r"\mathbf{a} = \mathbf{b}\mathbf{c}")


def _eq(eq_id):
    load_all()
    return REGISTRY[eq_id]


@pytest.mark.parametrize("eq_id", ["3.1", "3.4", "3.46", "3.82", "3.119b", "3.121"])
def test_book_declarations_are_machine_checked(eq_id):
    eq = _eq(eq_id)
    t = check_transcription(eq, eq.build())
    assert t["status"] == "machine-checked", t


def test_a_flipped_sign_in_printed_is_caught():
    eq = _eq("3.2")
    st = eq.build()
    r = st.printed[0]
    flipped = dataclasses.replace(st, printed=[Rel(r.lhs, -r.rhs, r.label)])  # a copy
    assert check_transcription(eq, st)["status"] == "machine-checked"
    t = check_transcription(eq, flipped)
    assert t["status"] == "differs" and t.get("counterexample")


def test_prose_and_integrals_are_not_parsed_with_their_construct():
    for eq_id, word in (("thm3.3.1", "prose"), ("3.123", "integral")):
        eq = _eq(eq_id)
        t = check_transcription(eq, eq.build())
        assert t["status"] == "not parsed" and word in t["construct"]
