"""Every docs reference a generated file cites resolves: the templates of
every target and the committed generated folders name ``docs/X.md`` (a file that exists),
``docs/X.md#anchor`` or ``docs/X.md, "Heading"`` (a heading of that file: the anchor
GitHub makes from its text)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
DOCS = REPO / "docs"
#: where generated text comes from (the templates) and where it is committed (examples/cpp's
#: C folder is the same templates' output as examples/c's)
SOURCES = [REPO / "src" / "rigidsym" / "codegen", REPO / "generated" / "c",
           REPO / "examples" / "c" / "rigidsym_c"]
SUFFIXES = {".j2", ".h", ".c", ".hpp", ".txt", ".md", ".in", ".pc"}
REF = re.compile(r'docs/([\w.-]+\.md)(?:#([\w-]+)|,\s*"([^"]+)")?')


def github_anchor(heading: str) -> str:
    """The anchor GitHub gives a Markdown heading: its text lower-cased, inline code marks
    and punctuation other than ``-`` and ``_`` dropped, spaces as ``-``."""
    text = re.sub(r"[`*]", "", heading.strip()).lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page: Path) -> set[str]:
    """The anchors of the headings of Markdown ``page`` (outside fenced code)."""
    out, fenced = set(), False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and (m := re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)):
            out.add(github_anchor(m.group(1)))
    return out


def references() -> list[tuple[str, str, str | None]]:
    """``(where, page, anchor or None)`` of every docs reference in the generated text."""
    refs = []
    for root in SOURCES:
        for f in sorted(root.rglob("*")):
            if f.suffix not in SUFFIXES or not f.is_file():
                continue
            text = f.read_text(encoding="utf-8", errors="replace")
            for m in REF.finditer(text):
                frag = m.group(2) or (github_anchor(m.group(3)) if m.group(3) else None)
                line = text.count("\n", 0, m.start()) + 1
                refs.append((f"{f.relative_to(REPO)}:{line}", m.group(1), frag))
    return refs


def test_the_anchor_is_githubs():
    """The slug rule on headings of the shapes docs/ uses (GitHub's documented rule)."""
    assert github_anchor("float and double") == "float-and-double"
    assert github_anchor("C++") == "c"
    assert github_anchor("How it is measured (`benchmarks/accuracy.py`)") == \
        "how-it-is-measured-benchmarksaccuracypy"
    assert github_anchor("Never worse than the textbook formula or a peer") == \
        "never-worse-than-the-textbook-formula-or-a-peer"


def test_generated_text_cites_docs():
    """The scan sees the references the C templates are known to make (it cannot pass
    vacuously)."""
    refs = references()
    assert any(p == "c-api.md" and a == "compiler-flags" for _, p, a in refs), refs[:5]
    assert len({w.split(":")[0] for w, _, _ in refs}) >= 5


@pytest.mark.parametrize("page", sorted({p for _, p, _ in references()}))
def test_every_cited_docs_page_and_section_exists(page):
    """Each page cited exists, and each section cited of it is one of its headings."""
    path = DOCS / page
    where = [w for w, p, _ in references() if p == page]
    assert path.is_file(), f"docs/{page} does not exist (cited at {where[0]})"
    have = anchors(path)
    bad = [f"{w}: #{a}" for w, p, a in references() if p == page and a and a not in have]
    assert not bad, f"docs/{page} has no such section: {bad}"
