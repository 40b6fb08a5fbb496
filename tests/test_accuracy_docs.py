"""The accuracy tables of docs/accuracy.md and benchmarks/RESULTS.md are the shipped data's.

They were written by hand from a run and went stale: after the data was re-measured (seeds
0-3, own sin/cos) the docs still said `exponential_coordinates_left_jacobian_inverse` was
3.12e13 u off where the data says 3.68 u, and `L_matrix` 10.7 u on C where it is 5.15 u.
Now `python benchmarks/accuracy.py --docs derivations/kernels_accuracy.json` writes them,
and this test fails when a table and the data disagree."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import _accuracy_tables as T  # noqa: E402

DATA = json.loads((ROOT / "derivations" / "kernels_accuracy.json").read_text("utf-8"))


@pytest.mark.parametrize("rel", sorted(T.DOC_TABLES))
def test_the_tables_are_the_datas(rel):
    text = (ROOT / rel).read_text(encoding="utf-8")
    want = T.synced(ROOT, DATA)[rel]
    assert text == want, (f"{rel}: a table differs from derivations/kernels_accuracy.json; "
                          "run python benchmarks/accuracy.py --docs "
                          "derivations/kernels_accuracy.json")


def test_the_summary_counts_the_rule_and_the_acceptance():
    # Two made-up rows: one within the rule, one past it with err / e_ref = 3.
    row = {"err_u": 1.0, "rule": 0.5, "vs_ref": 0.0, "vs_ref_where": ""}
    bad = {"err_u": 9.0, "rule": 1.5, "vs_ref": 3.0, "vs_ref_where": "random"}
    data = {"a": {"float64": {"backends": {"c": row}}},
            "b": {"float64": {"backends": {"c": bad}}}}
    assert T.summary_table(data).splitlines()[2] == "| float64 | C | 2 | 1 | 1: `b` 3 |"


def test_a_missing_marker_is_an_error():
    with pytest.raises(ValueError, match="rule-all"):
        T.replace_marked("no markers here\n", "rule-all", "x")
