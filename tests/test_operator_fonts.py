"""An operator's name in any upright font (``\\text{vect}``, ``\\mathrm{vect}``,
``\\operatorname{vect}``, ``\\textrm``, ``\\mbox`` ...) is the one operator: to both semantics
of the reader (the sympy transformer and numeval) and to a document's display splitter, which
keeps it an operand, while prose in ``\\text{ }`` still separates relations."""

from __future__ import annotations

import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.documents import check_document
from rigidsym.documents.displays import Display, Source
from rigidsym.documents.relations import split_display
from rigidsym.latex.lexing import OPERATOR_FONTS, OPERATOR_NAMES, tree
from rigidsym.latex.reader import parse_latex
from rigidsym.numeval import Decl, residuals
from rigidsym.registry import declarations as registry

_FONTS = st.sampled_from(OPERATOR_FONTS)
_PAD = st.sampled_from(["", " "])
#: each operator of a 3 x 3 matrix with the sign its transpose takes: tr(A^T) = tr(A),
#: det(A^T) = det(A), vect(A^T) = -vect(A)
_PARITY = {"tr": 1, "Tr": 1, "trace": 1, "det": 1, "vect": -1}


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _spelled(font: str, name: str, pad: str) -> str:
    return f"\\{font}{{{pad}{name}{pad}}}"


def _relations(body: str):
    d = Display(Source("t.tex", body), 1, body, 0, 1, "equation", None, {})
    return [(r.lhs, r.op, r.rhs) for r in split_display(d)]


# ------------------------------------------------------------------- the splitter
@settings(max_examples=examples(30), deadline=None)
@given(_FONTS, st.sampled_from(OPERATOR_NAMES), _PAD,
       st.sampled_from(["\\text{ for all } ", "\\text{and}", "\\mbox{ where }", ", "]))
def test_an_operator_in_any_font_is_an_operand_and_prose_still_separates(font, name, pad,
                                                                          prose):
    op = _spelled(font, name, pad)
    got = _relations(f"{op}(x) = y \\quad {prose} z = {op}(w)")
    assert got == [(f"{op}(x)", "=", "y"), ("z", "=", f"{op}(w)")]


def test_a_font_whose_argument_the_walker_does_not_take_is_read_alike():
    # pylatexenc reads \textnormal with no argument: the group after it decides
    assert _relations("\\textnormal{vect}(a) = b \\textnormal{ if } c = d") == \
        [("\\textnormal{vect}(a)", "=", "b"), ("c", "=", "d")]


# ------------------------------------------------------------ the two semantics
@settings(max_examples=examples(12), deadline=None)
@given(_FONTS, _FONTS, _PAD, st.sampled_from(sorted(_PARITY)))
def test_both_semantics_read_every_font_as_the_operator(f1, f2, pad, name):
    sign = "" if _PARITY[name] == 1 else "-"
    latex = f"{_spelled(f1, name, pad)}(\\mathbf{{A}}^T) = {sign}{_spelled(f2, name, '')}" \
            f"(\\mathbf{{A}})"
    plain = f"\\operatorname{{{name}}}(\\mathbf{{A}}^T) = {sign}\\operatorname{{{name}}}" \
            f"(\\mathbf{{A}})"
    got, want = parse_latex(latex, None).relations[0], parse_latex(plain, None).relations[0]
    assert (got.lhs, got.rhs) == (want.lhs, want.rhs)  # the same sympy expressions
    a = Decl(tree(r"\mathbf{A} = 0").children[0].children[0], (), "3x3 matrix", None,
             r"\mathbf{A}")
    holds = residuals(tree(latex), [a], 2)
    slip = residuals(tree(latex.replace("= -", "= ") if sign else
                          latex.replace("= ", "= -")), [a], 2)
    assert max(r.relative for r in holds) < 1e-30
    assert min(r.relative for r in slip) > 1e-3  # the sign is seen by the numbers too


# ------------------------------------------------------------------- documents
_MD = r"""# Axial vectors

Let $\mathbf{A}$ be any $3\times 3$ matrix and $\mathbf{Q}$ a rotation.

$$
\text{vect}(\mathbf{A}^T) = -\text{vect}(\mathbf{A}) \quad \text{for all } \mathbf{A}
$$

$$
\operatorname{tr}(\mathbf{Q}^T) = \mathrm{tr}(\mathbf{Q}), \qquad
\textrm{vect}(\mathbf{A} + \mathbf{A}^T) = \mbox{vect}(\mathbf{A})
$$
"""

_TEX = r"""\documentclass{article}
\begin{document}
The axial vector of $\mathbf{A}$ is
\begin{align}
\mathbf{w} &:= \operatorname{vect}(\mathbf{A}) \label{eq:def}\\
\mathbf{w} &= -\textnormal{vect}(\mathbf{A}^T) \label{eq:odd}\\
\text{vect}(\mathbf{Q}\mathbf{A}\mathbf{Q}^T) &= \mathbf{Q}\,\text{ vect }(\mathbf{A})
\label{eq:rot}
\end{align}
where $\mathbf{Q}$ is a rotation.
\end{document}
"""

_LETS = (r"\mathbf{A}: 3x3 matrix", r"\mathbf{Q}: rotation")


def test_a_markdown_document_decides_vect_written_with_text(tmp_path):
    (tmp_path / "notes.md").write_text(_MD)
    res = check_document(tmp_path / "notes.md", lets=_LETS, repairs=False)
    got = [(r["line"], r["verdict"]) for r in res.records]
    assert got == [(6, "verified"), (10, "verified"), (11, "does-not-hold")]
    assert res.records[0]["latex"] == r"\text{vect}(\mathbf{A}^T) = -\text{vect}(\mathbf{A})"


def test_a_latex_document_defines_and_decides_through_vect(tmp_path):
    (tmp_path / "notes.tex").write_text(_TEX)
    res = check_document(tmp_path / "notes.tex", lets=_LETS, repairs=False)
    got = [(r["label"], r["verdict"]) for r in res.records]
    assert got == [("eq:def", "definition"), ("eq:odd", "verified"), ("eq:rot", "verified")]
