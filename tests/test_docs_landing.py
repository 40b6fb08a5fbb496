"""The landing page docs/index.md reaches every page of docs/ in one click, as Markdown on
the repository page (no Sphinx needed; tests/test_docs.py checks the built HTML), and shows
no Sphinx directive there."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
INDEX = DOCS / "index.md"

#: a Markdown inline link's target: ``[text](target)``
LINK = re.compile(r"\]\(([^)\s]+)\)")


def _targets() -> list[str]:
    return LINK.findall(INDEX.read_text(encoding="utf-8"))


def test_every_docs_page_is_one_click_from_the_landing_page():
    linked = {t.partition("#")[0] for t in _targets()}
    pages = {p.name for p in DOCS.glob("*.md")
             if p.name != "index.md" and not p.name.startswith("_")}  # _*: sources
    assert len(pages) >= 20, pages      # the glob found the pages
    assert not pages - linked, f"not linked from docs/index.md: {sorted(pages - linked)}"


def test_the_landing_page_links_only_pages_that_exist():
    bad = [t for t in _targets() if not urlish(t) and not (DOCS / t.partition("#")[0]).is_file()]
    assert not bad, bad


def test_the_landing_page_shows_no_directive_on_the_repository_page():
    """A fenced ``{toctree}`` renders as a code block on GitHub; Sphinx's contents are added
    by docs/conf.py instead."""
    text = INDEX.read_text(encoding="utf-8")
    assert "```" not in text and "{toctree}" not in text.replace("<!--", "\0").split("\0")[0]
    assert "_index_toctree" in (DOCS / "conf.py").read_text(encoding="utf-8")


def urlish(target: str) -> bool:
    """Whether a link target leaves the docs (a scheme such as ``https:``)."""
    return bool(re.match(r"[a-z][a-z0-9+.-]*:", target))
