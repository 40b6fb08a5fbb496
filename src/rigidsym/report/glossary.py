"""The glossary (``docs/glossary.md``; a copy ships in the package): its entries by word,
for ``rigidsym glossary`` and the "Words" section of the HTML report."""

from __future__ import annotations

import re
from functools import cache
from importlib.resources import files

__all__ = ["text", "entries", "lookup", "slug", "html_entries", "WORDS"]

#: the words every output must be able to explain (a test checks the file)
WORDS = ("verdict", "member", "claim", "corrected form", "model", "parametrisation",
         "exact-cancel", "random-exact", "counterexample", "singular set", "repair",
         "found by search", "enclosure", "certified")


@cache
def text() -> str:
    """The glossary's Markdown, as shipped in the package."""
    return (files("rigidsym.report") / "glossary.md").read_text(encoding="utf-8")


def slug(word: str) -> str:
    """The anchor of an entry: ``"corrected form"`` -> ``"corrected-form"`` (as MkDocs and
    GitHub make heading anchors)."""
    return re.sub(r"[^a-z0-9-]+", "-", word.lower()).strip("-")


@cache
def entries() -> dict[str, str]:
    """``{word: Markdown text}`` in the file's order."""
    out: dict[str, str] = {}
    for block in re.split(r"^## ", text(), flags=re.M)[1:]:
        word, _, body = block.partition("\n")
        out[word.strip()] = body.strip()
    return out


def lookup(query: str) -> list[tuple[str, str]]:
    """The entries for ``query``: the word itself, else every entry that mentions it
    (``stereographic`` -> parametrisation). ``[]`` when none does."""
    q = query.strip().lower().replace("_", " ")
    found = [(w, t) for w, t in entries().items() if w.lower() == q or slug(w) == slug(q)]
    return found or [(w, t) for w, t in entries().items() if q in t.lower()]


def html_entries() -> list[dict]:
    """The entries for the HTML report's "Words" section: ``{"id", "word", "html"}``, the
    anchor ``word-<slug>``, the links between entries rewritten to those anchors."""
    from markdown_it import MarkdownIt

    md = MarkdownIt("commonmark")
    out = []
    for word, body in entries().items():
        body = re.sub(r"\]\(#([a-z0-9-]+)\)", r"](#word-\1)", body)
        out.append({"id": f"word-{slug(word)}", "word": word, "html": md.render(body)})
    return out
