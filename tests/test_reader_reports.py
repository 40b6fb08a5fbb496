"""What `show` says of a record: one bound per record, and nothing of a corrected form
that does not exist (issue 28, item 3)."""

from __future__ import annotations

import pytest
import sympy as sp

from rigidsym import Rel, Statement, acos, angle, equation, mat, trace, unit_vector
from rigidsym import rotation_from_natural_invariants as rodrigues
from rigidsym.checking.checker import check
from rigidsym.checking.deciding.registry import REGISTRY, load_all
from rigidsym.report.record import RESIDUAL_FLOOR, result_record
from rigidsym.report.show import explain


@pytest.fixture(autouse=True)
def _forget():
    yield
    for k in [k for k in REGISTRY if k.startswith("rr:")]:
        del REGISTRY[k]


def _show(r) -> str:
    st = REGISTRY[r.id].build()
    return explain(r, {"printed": st.printed, "claim": st.claims,
                       "corrected": st.corrected or []}, "test", 100)


def test_show_prints_the_records_bound_the_report_prints():
    # (3.59): show printed r ≤ 3.7e-51 where the HTML printed the record's floor 1e-40
    load_all()
    r = check("3.59", repairs=False)
    assert r.numeric["enclosure"] < RESIDUAL_FLOOR
    assert result_record(r, timings=False)["numeric"]["enclosure"] == RESIDUAL_FLOOR
    text = " ".join(_show(r).split())
    assert "r ≤ 1e-40" in text and "e-51" not in text


def test_show_says_nothing_of_a_corrected_form_that_does_not_exist():
    w, th, R = unit_vector("rr_w"), angle("rr_th"), mat("R")
    equation("rr:acos", "θ = acos((tr R − 1)/2) on (−π, π)", expected="does-not-hold")(
        lambda: Statement([Rel(th, acos((trace(R) - 1) / 2))], {R: rodrigues(w, th)}))
    r = check("rr:acos", repair_budget=5)
    assert r.verdict == "does-not-hold" and not r.repairs
    text = " ".join(_show(r).split())
    assert "corrected form's residual" not in text
    assert "0 ∉" in text and "certified" in text and "not certified" not in text
    assert sp.sympify(r.counterexample["residual"]) != 0
