"""The chapter as a document: ``rigidsym check`` on the chapter's page with its reading
never contradicts ``rigidsym verify`` where both decide, and agrees on at least as many ids
as measured (benchmarks/chapter_as_document.py, docs/check-documents.md, "The chapter as a
document"). Slow, and skipped where the chapter is absent (tests/_book.py): the whole page
costs minutes cold, so the thorough profile checks a seeded share of its sections (each
commit another, :func:`_profile.share`), the others' displays blanked (a relation whose
definition is blanked is then not decided or read as a definition, never given a verdict
from a guess), and the exhaustive profile the whole page with the floor of agreements."""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path

import pytest
from _book import READING, book_path, book_text
from _profile import PROFILE, share

ROOT = Path(__file__).resolve().parents[1]
#: at least this many ids agree (measured: benchmarks/results/chapter_as_document.json;
#: a floor below the count, which a faster or slower machine's time limits move)
AGREEING_AT_LEAST = 85


def _benchmark():
    spec = importlib.util.spec_from_file_location(
        "chapter_as_document", ROOT / "benchmarks" / "chapter_as_document.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


#: the share of the page's sections the thorough profile checks, and its time limit per
#: relation (CPU seconds)
SECTIONS_SHARE = 0.25
SHARE_TIMEOUT = 10
_SECTION = re.compile(r"^#+\s+(.*)$", re.M)
_DISPLAY = re.compile(r"\$\$.*?\$\$", re.S)


def _sections_kept(text: str, fraction: float) -> tuple[str, list[str]]:
    """The page with the displays outside a seeded share of its sections blanked (their lines
    kept empty, so that every place is the page's), and the sections kept."""
    heads = [(m.start(), m.group(1).strip()) for m in _SECTION.finditer(text)]

    def section(at: int) -> str:
        return next((h for s, h in reversed(heads) if s <= at), "")

    names = list(dict.fromkeys(section(m.start()) for m in _DISPLAY.finditer(text)))
    kept = set(share(names, fraction))
    return _DISPLAY.sub(lambda m: m.group(0) if section(m.start()) in kept else
                        "\n" * m.group(0).count("\n"), text), sorted(kept)


@pytest.mark.slow  # the thorough share: 37 s CPU at seed 0, 80 of 220 displays (whole: 220 s)
@pytest.mark.book
def test_the_chapter_as_a_document_never_contradicts_verify(tmp_path):
    from rigidsym.documents import check_document

    bench = _benchmark()
    whole = PROFILE == "exhaustive"
    if whole:
        page = book_path()
    else:
        text, kept = _sections_kept(book_text(), SECTIONS_SHARE)
        page = tmp_path / book_path().name
        page.write_text(text, encoding="utf-8")
    # the share under a shorter time limit per relation: one that needs longer is undecided
    # (never a verdict), and the share's cost stays bounded
    res = check_document(page, reading=READING, timeout="default" if whole else SHARE_TIMEOUT)
    verify = {e["id"]: e["verdict"] for e in json.loads(
        (ROOT / "generated" / "report" / "chapter3.json").read_text())["equations"]}
    got = bench.compare(res.records, verify)
    assert not got["disagree"], [(r["id"], r["verify"], r["document"])
                                 for r in got["disagree"]]
    if whole:
        assert len(got["agree"]) >= AGREEING_AT_LEAST
        # each reading line given to no relation is listed with why, never dropped
        assert res.omitted and all(x["reason"] and x["labels"] for x in res.omitted)
    else:  # the share decides some ids, and every relation of it is one of the page's
        assert got["agree"], kept
        assert all(x["reason"] and x["labels"] for x in res.omitted)
