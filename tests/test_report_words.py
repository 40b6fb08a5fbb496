"""The reports in the book's notation: no raw LaTeX left as text in
the HTML, evidence with LaTeX as MathML, labels in book notation, the counterexample in book
symbols with the parametrisation folded away, and the glossary at the end of the page."""

from __future__ import annotations

import dataclasses
import html
import re
from pathlib import Path

import pytest

from rigidsym.checking.checker import check
from rigidsym.registry.declarations import load_all
from rigidsym.report.html import to_html
from rigidsym.report.markdown import to_markdown

pytestmark = pytest.mark.xdist_group("report_words")  # its module fixtures built on one worker

load_all()
ROOT = Path(__file__).resolve().parents[1]
COMMITTED = ROOT / "generated" / "report"
_COMMAND = re.compile(r"\\[a-zA-Z]+")


def raw_latex(page: str) -> list[str]:
    """Backslash commands in the page's text (outside tags, styles and scripts): LaTeX a
    reader would see as source. Code spans are left out: there LaTeX is what a reader types
    (the glossary's ``--let '\\mathbf{Q}: rotation'``)."""
    body = re.sub(r"<(style|script|code)\b.*?</\1>", " ", page, flags=re.S)
    text = html.unescape(re.sub(r"<[^>]+>", " ", body))
    return _COMMAND.findall(text)


@pytest.fixture(scope="module")
def latex_evidence():
    """(3.97c), its evidence given LaTeX as (3.77a)'s is written."""
    r = check("3.97c")
    return dataclasses.replace(r, evidence=r"\dot{\mathbf{v}} (v is the velocity) printed "
                               r"where \dot{\boldsymbol{\nu}} is meant: Ntilde acts on nu_dot")


def test_no_raw_latex_in_the_html(latex_evidence):
    page = to_html([latex_evidence])
    assert raw_latex(page) == []
    cause = page.split('<p class="cause">')[1].split("</p>")[0]
    assert cause.count("<math") == 2 and "Ñ" in cause and "Ntilde" not in cause


def test_no_raw_latex_in_the_committed_report():
    assert raw_latex((COMMITTED / "chapter3.html").read_text(encoding="utf-8")) == []
    assert raw_latex((COMMITTED / "exercises.html").read_text(encoding="utf-8")) == []


def test_markdown_evidence_latex_is_maths(latex_evidence):
    md = to_markdown([latex_evidence])
    row = next(line for line in md.splitlines() if line.startswith("| [(3.97c)]"))
    assert r"$\dot{\mathbf{v}}$" in row and "Ñ acts on ν̇" in row


def test_counterexample_in_book_symbols_with_the_point_folded(latex_evidence):
    page = to_html([latex_evidence])
    block = page.split(">Counterexample</a></b>")[1].split("How it was checked")[0]
    assert "<th>symbol</th>" in block
    assert '<details class="chosen"><summary>How the point was chosen</summary>' in block
    assert 'href="#word-parametrisation"' in block
    symbols = block.split("<details")[0]
    assert "of e" not in symbols and "tan(φ" not in symbols  # parametrisation folded away
    md = to_markdown([latex_evidence])
    assert "<details><summary>How the point was chosen</summary>" in md
    assert "| symbol | exact | decimal |" in md


def test_the_page_ends_with_the_words(latex_evidence):
    page = to_html([latex_evidence])
    assert '<h2 id="words">' in page and 'id="word-counterexample"' in page
    assert page.index('id="words"') > page.index('id="eq-3.97c"')
