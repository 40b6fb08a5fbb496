"""The schema-2 record: per-member status, cause class, counterexample with its residual."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
import sympy as sp

from rigidsym.checking.checker import check
from rigidsym.registry.declarations import REGISTRY, load_all
from rigidsym.report.record import SCHEMA, result_record, to_json

# one worker builds the chapter's checked records (module fixture) for every test of this
# module (each worker that ran one of them built it again)
pytestmark = pytest.mark.xdist_group("report_schema")

load_all()
IDS = ["3.1", "3.59", "3.96e", "3.75"]


@pytest.fixture(scope="module")
def results():
    return {i: check(i) for i in IDS}


def test_every_member_has_a_status(results):
    for i, r in results.items():
        rec = result_record(r)
        st = REGISTRY[i].build()
        n = len(st.printed) + len(st.claims) + (len(st.corrected or [])
                                                 if r.verdict == "does-not-hold" else 0)
        assert len(rec["members"]) == n, i
        for m in rec["members"]:
            assert m["status"] in ("holds", "fails", "undecided", "defines")
            assert m["role"] in ("printed", "claim", "corrected")
        if r.verdict == "verified":
            assert all(m["status"] == "holds" for m in rec["members"])


def test_only_the_wrong_brace_of_3_59_fails(results):
    rec = result_record(results["3.59"])
    failing = [m["label"] for m in rec["members"] if m["status"] == "fails"]
    assert failing == ["pdot_perp brace"] == [rec["failing_member"]]
    assert all(m["status"] == "holds" for m in rec["members"] if m["role"] == "corrected")
    assert rec["cause_class"] == "not a known slip of the text's conversion nor a known erratum"
    assert "unknown" not in rec["evidence"] and "wrong sign" in rec["evidence"]


def test_counterexample_residual_is_left_minus_right(results):
    ce = result_record(results["3.96e"])["counterexample"]
    lhs, rhs, res = (sp.sympify(ce[k]) for k in ("lhs", "rhs", "residual"))
    assert res == lhs - rhs and res != sp.zeros(3, 3)
    worst = max(abs(x) for x in res)
    assert sp.Rational(ce["residual_max_abs"]) == worst
    for p in ce["point"]:
        if p["decimal"]:
            exact = sp.sympify(p["exact"])
            assert abs(float(exact) - float(p["decimal"])) <= 1e-7 * max(1, abs(float(exact)))
    assert ce["point"][0]["book"] == "e₁"  # book names, not atom names


def test_point_satisfies_the_constraint(results):
    """e is a unit vector at the counterexample point (the model's constraint holds)."""
    pt = {p["book"]: p["exact"] for p in result_record(results["3.96e"])["counterexample"]
          ["point"]}
    assert sum(Fraction(pt[f"e{c}"]) ** 2 for c in "₁₂₃") == 1


def test_lean_json_round_trips_and_drops_dumps(results):
    doc = json.loads(to_json(list(results.values()), timings=False))
    assert doc["schema"] == SCHEMA == 2
    for row in doc["equations"]:
        assert "seconds" not in row and "derived" not in row and "printed" not in row
    full = json.loads(to_json(list(results.values()), full=True))
    assert all("derived" in row and "seconds" in row for row in full["equations"])


def test_definition_members_define(results):
    rec = result_record(results["3.75"])
    assert rec["verdict"] == "definition"
    assert {m["status"] for m in rec["members"] if m["role"] == "printed"} == {"defines"}
