"""Every declaration: computed verdict equals the recorded one; printed LaTeX is verbatim."""

from __future__ import annotations

import pytest

from rigidsym.checking.runner import run_checks
from rigidsym.registry.declarations import REGISTRY, load_all

load_all()
IDS = sorted(REGISTRY)
# one worker checks the chapter, for every test of this module that reads the results
# (every xdist worker that ran one of them checked the whole chapter again: 51 s of setup on
# each of two workers, side by side, against 26 s for one)
pytestmark = pytest.mark.xdist_group("registry_verdicts")


@pytest.fixture(scope="module")
def results(request):
    """The declarations this session's tests of the module read, checked once, in this
    process: every id where a test that reads the whole chapter runs (the thorough
    profile's report and snapshot), else the ids of the verdict family's seeded sample (the
    quick profile: the whole chapter costs about 60 s of CPU, a quarter of it about 15).
    One process: the suite runs on xdist workers already, one per core, so that a pool of
    two here ran three processes on two cores and paid its start-up and transport (about
    10 s of CPU) for no wall time; the pool's path is test_api.py's section33
    (``verify(jobs=2)``)."""
    mine = [i for i in request.session.items if i.module is request.module]
    if any(getattr(i, "originalname", "") in WHOLE for i in mine):
        ids = IDS
    else:
        ids = [i.callspec.params["eq_id"] for i in mine if "eq_id" in i.fixturenames
               and i.originalname == "test_computed_verdict_equals_recorded"]
    return {r.id: r for r in run_checks(ids, jobs=1, progress=False)}


#: the tests of the module that read every id's result (the thorough profile's)
WHOLE = ("test_committed_chapter_report_is_fresh",)


@pytest.mark.sample
@pytest.mark.parametrize("eq_id", IDS)
def test_computed_verdict_equals_recorded(eq_id, results):
    """The verdict the engine computes is the declared one, backed by its numeric check,
    and the same as the snapshot taken before python-flint (verdict, member statuses, no
    failure bound above the recorded one, an exact counterexample): the quick profile
    checks a seeded quarter of the chapter, the thorough one the rest."""
    from test_verdict_snapshot import SNAPSHOT, assert_matches_snapshot

    r = results[eq_id]
    assert_matches_snapshot(r, SNAPSHOT["chapter"][eq_id])
    assert r.verdict == r.expected, r.detail
    assert r.numeric["points"] >= 10 and r.numeric["digits"] >= 30
    if r.verdict == "does-not-hold":
        ce = r.counterexample
        assert ce and ce["point"] and ce["lhs"] != ce["rhs"]
        assert r.corrected and r.cause in ("conversion", "erratum", "unknown")
        res = r.numeric["printed_residual"]
        assert res == "shape mismatch" or res > 1e-12
    if r.verdict == "verified":
        assert r.numeric["max_residual"] < 1e-30


@pytest.mark.parametrize("eq_id", IDS)
def test_printed_latex_is_verbatim_from_the_chapter(eq_id, chapter_text):
    assert REGISTRY[eq_id].latex in chapter_text


def test_every_declaration_names_its_book_section():
    # the book's ids (IDS, taken at import); other tests add reader modules' ids to REGISTRY
    for eq in (REGISTRY[i] for i in IDS):
        assert eq.section.startswith("3."), eq.id
        assert eq.title and eq.latex


@pytest.mark.slow  # every id; the verdict family holds the quick profile's sample
def test_committed_chapter_report_is_fresh(results):
    """generated/report/chapter3.{md,json,html} equal what the current declarations produce
    (the report is deterministic: no timings, tiny residuals bounded)."""
    from pathlib import Path

    from rigidsym.registry.declarations import select
    from rigidsym.report.markdown import to_markdown
    from rigidsym.report.record import to_json

    folder = Path(__file__).resolve().parents[1] / "generated" / "report"
    if not (folder / "chapter3.md").exists():
        pytest.skip("no committed report in this checkout")
    rows = [results[i] for i in select(None, None)]
    assert (folder / "chapter3.md").read_text(encoding="utf-8") == to_markdown(rows), \
        "generated/report/chapter3.md is stale: run `rigidsym report`"
    assert (folder / "chapter3.json").read_text(encoding="utf-8") == \
        to_json(rows, timings=False), "generated/report/chapter3.json is stale"
    from rigidsym.report.html import to_html
    assert (folder / "chapter3.html").read_text(encoding="utf-8") == to_html(rows), \
        "generated/report/chapter3.html is stale: run `rigidsym report`"


def test_every_id_is_in_the_snapshot():
    """The snapshot holds the chapter's ids, no more, no fewer (each id's record is held
    by test_computed_verdict_equals_recorded)."""
    from test_verdict_snapshot import SNAPSHOT

    assert sorted(SNAPSHOT["chapter"]) == IDS
