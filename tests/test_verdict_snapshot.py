"""The exact engine against the snapshot taken before python-flint (tests/data): the same
verdict for every id and member, no failure bound above the recorded one, and every
does-not-hold with an exact counterexample. The chapter's ids are held to it in
``test_registry.py`` (its results are computed once there); the example module here."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

DATA = Path(__file__).parent / "data"
SNAPSHOT = json.loads((DATA / "verdict_snapshot.json").read_text())
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "rotation_identities.py"


def assert_matches_snapshot(result, recorded: dict) -> None:
    """Verdict and member statuses equal; each member's failure bound no higher."""
    import sys

    sys.path.insert(0, str(DATA))
    from make_verdict_snapshot import record

    now = record(result)
    assert now["verdict"] == recorded["verdict"], (result.id, result.detail)
    assert len(now["members"]) == len(recorded["members"])
    for m, o in zip(now["members"], recorded["members"], strict=True):
        assert (m["role"], m["label"], m["status"]) == (o["role"], o["label"], o["status"])
        if m["bound"] is not None:  # an exact method has none: it beats any bound
            assert o["bound"] is not None and m["bound"] <= o["bound"], (result.id, m, o)
    if result.verdict == "does-not-hold":
        ce = result.counterexample
        assert ce and ce["point"] and ce["lhs"] != ce["rhs"]
        assert all("." not in v or "atan" in v for v in ce["point"].values())  # exact


@pytest.fixture(scope="module")
def example_results():
    import rigidsym

    return rigidsym.verify(modules=[EXAMPLE], cache=False)


def test_the_example_module_matches_the_snapshot(example_results):
    recorded = SNAPSHOT["examples/rotation_identities.py"]
    assert sorted(r.id for r in example_results) == sorted(recorded)
    for r in example_results:
        assert_matches_snapshot(r, recorded[r.id])
