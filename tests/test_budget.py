"""The default run's size is a decision, and no check is lost when tests move to ``slow``
(issue 54 item 4).

- Every node id collected before issue 54 moved tests to ``slow``
  (``tests/data/test_ids_before_issue54.txt``, ``-m ''``, without the extras) is still
  collected: the default run and the ``slow`` run together select each of them.
- The default run (``-m 'not slow'``) selects at most the number of tests without the
  ``extra`` mark that docs/testing.md records: growing past it fails until the page says so.
  The tests of an extra are left out of the count, so the figure is the same with the
  README's ``[test]`` install and with every extra (a developer's machine, .ci/run).

Both look at what this process collected (conftest.py's ``COLLECTED``) and skip when it was
not the whole of tests/ (one file, ``-k``).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import COLLECTED

ROOT = Path(__file__).resolve().parents[1]
BEFORE = ROOT / "tests" / "data" / "test_ids_before_issue54.txt"
#: ids of BEFORE no longer collected, each with where its check went (a decision on record)
ACCOUNTED = ROOT / "tests" / "data" / "test_ids_accounted.txt"
TESTING = ROOT / "docs" / "testing.md"
#: the sentence of docs/testing.md that records the budget
BUDGET = re.compile(r"The default run selects at most \*\*(\d[\d,]*) tests\*\* without")


def _whole():
    if not COLLECTED.get("whole"):
        pytest.skip("this run did not collect the whole of tests/")


def test_every_test_of_before_issue_54_is_still_collected():
    _whole()
    before = set(BEFORE.read_text(encoding="utf-8").splitlines()) - {""}
    now = set(COLLECTED["all"])
    accounted = dict(line.split("\t", 1) for line in ACCOUNTED.read_text(encoding="utf-8")
                     .splitlines() if line and not line.startswith("#"))
    lost = sorted(before - now - accounted.keys())
    assert not lost, (f"{len(lost)} tests collected before issue 54 are gone (a check removed "
                      f"or renamed; say where it went in {ACCOUNTED.name}): {lost[:20]}")
    # a renamed test must exist under its new name; a reason names where the check went
    gone = sorted(new for new in accounted.values() if new.startswith("tests/") and "::" in new
                  and " " not in new.split("]")[-1] and new not in now)
    assert not gone, f"{ACCOUNTED.name} names tests that are not collected: {gone}"


def test_the_default_run_stays_within_its_recorded_size():
    _whole()
    if COLLECTED.get("markexpr") != "not slow":
        pytest.skip("not the default run (-m 'not slow')")
    found = BUDGET.search(TESTING.read_text(encoding="utf-8"))
    assert found, f"docs/testing.md no longer records the default run's size ({BUDGET.pattern})"
    budget = int(found.group(1).replace(",", ""))
    n = len(COLLECTED["core"])
    assert n <= budget, (f"the default run selects {n} tests without the `extra` mark, more "
                         f"than the {budget} "
                         "docs/testing.md records: move exhaustive variants to `slow`, or "
                         "update the page with the new figure and its measured time")


def test_the_budget_reads_a_run_as_a_run_is_collected():
    # the ids this process sees are node ids of real files (the rule above compares like
    # with like: no '@group' suffix of --dist loadgroup left on them)
    ids = COLLECTED.get("all") or []
    assert ids and all("::" in i and not re.search(r"@\w+$", i) for i in ids), ids[:5]
