"""The chapter as a document: ``rigidsym check`` on the chapter's page with its reading
never contradicts ``rigidsym verify`` where both decide, and agrees on at least as many ids
as measured (benchmarks/chapter_as_document.py, docs/check-documents.md, "The chapter as a
document"). Slow (the whole page, minutes cold; the verdict store makes a re-run quick) and
skipped where the chapter is absent (tests/_book.py)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest
from _book import READING, book_path

ROOT = Path(__file__).resolve().parents[1]
#: at least this many ids agree (measured: benchmarks/results/chapter_as_document.json;
#: a floor below the count, which a faster or slower machine's time limits move)
AGREEING_AT_LEAST = 65


def _benchmark():
    spec = importlib.util.spec_from_file_location(
        "chapter_as_document", ROOT / "benchmarks" / "chapter_as_document.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.slow
@pytest.mark.book
@pytest.mark.unpriced  # about 210 s cold (the benchmark's record): not yet priced in .ci/run
def test_the_chapter_as_a_document_never_contradicts_verify():
    from rigidsym.documents import check_document

    bench = _benchmark()
    res = check_document(book_path(), reading=READING)
    verify = {e["id"]: e["verdict"] for e in json.loads(
        (ROOT / "generated" / "report" / "chapter3.json").read_text())["equations"]}
    got = bench.compare(res.records, verify)
    assert not got["disagree"], [(r["id"], r["verify"], r["document"])
                                 for r in got["disagree"]]
    assert len(got["agree"]) >= AGREEING_AT_LEAST
    # each reading line given to no relation is listed with why, never dropped
    assert res.omitted and all(x["reason"] and x["labels"] for x in res.omitted)
