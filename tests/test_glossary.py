"""The words: one glossary, in the docs and in the package, that covers
the words of the verdicts and reports, whose links resolve, and that the HTML report and
``rigidsym show`` point to."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rigidsym.cli import main
from rigidsym.report import glossary

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "glossary.md"
TEMPLATES = ROOT / "src" / "rigidsym" / "report" / "templates"


def test_the_package_ships_the_docs_glossary_unchanged():
    assert glossary.text() == DOCS.read_text(encoding="utf-8"), \
        "copy docs/glossary.md to src/rigidsym/report/glossary.md"


@pytest.mark.parametrize("word", glossary.WORDS)
def test_every_word_of_the_glossary_list_has_an_entry(word):
    assert word in glossary.entries(), word
    assert len(glossary.entries()[word]) > 80


def test_entries_are_alphabetical_and_links_resolve():
    words = list(glossary.entries())
    assert words == sorted(words)
    slugs = {glossary.slug(w) for w in words}
    for w, body in glossary.entries().items():
        for target in re.findall(r"\]\(#([a-z0-9-]+)\)", body):
            assert target in slugs, (w, target)


def test_the_html_links_point_at_entries():
    anchors = {f"word-{glossary.slug(w)}" for w in glossary.entries()}
    for path in TEMPLATES.glob("*.j2"):
        for target in re.findall(r'href="#(word-[a-z0-9-]+)"', path.read_text()):
            assert target in anchors, (path.name, target)
    ids = [e["id"] for e in glossary.html_entries()]
    assert ids == [f"word-{glossary.slug(w)}" for w in glossary.entries()]
    assert all("](#" not in e["html"] for e in glossary.html_entries())


def test_glossary_command(capsys):
    assert main(["glossary", "random-exact"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("RANDOM-EXACT") and "Schwartz" in out and "](" not in out
    assert main(["glossary", "stereographic"]) == 0  # a word inside an entry finds it
    assert "PARAMETRISATION" in capsys.readouterr().out
    assert main(["glossary"]) == 0
    assert capsys.readouterr().out.count("\n\n") >= len(glossary.entries()) - 1


def test_the_words_of_a_does_not_hold_have_entries():
    """`show`, `verify` and the reports say "Cause:" and "Origin:" (an erratum, a slip of
    the text's conversion), `check --latex` "numeric cross-check": each has an entry."""
    for word in ("cause", "origin", "numeric cross-check"):
        assert word in glossary.entries(), word
    assert "erratum" in glossary.entries()["origin"]
    assert "slip" in glossary.entries()["origin"]
