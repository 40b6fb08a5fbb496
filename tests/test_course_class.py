"""A class of 30: the exam for 30 students and the grading of a 30-row answers CSV; every
student's drawn problems differ; the grading exits 1 (some answers are wrong or blank) and
names a planted unit slip.
Slow: it draws and grades 120 problems."""

from __future__ import annotations

import csv
import json
import random

import numpy as np
import pytest
import sympy as sp

from rigidsym.cli import main

pytestmark = pytest.mark.slow

SPEC = """title = "Chapter 3 quiz"
seed = 5
[[problem]]
exercise = "3.19"
variants = 1
[[problem]]
exercise = "3.4"
variants = 1
[[problem]]
exercise = "3.11"
variants = 1
[[problem]]
exercise = "3.8"
variants = 1
"""


def _fl(v):
    if isinstance(v, list):
        return [_fl(x) for x in v]
    e = sp.sympify(v)
    return float(bool(e)) if e in (sp.true, sp.false) else float(e)


def test_thirty_students_made_and_graded(tmp_path, capsys):
    (tmp_path / "quiz.toml").write_text(SPEC)
    with (tmp_path / "roster.csv").open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "id"])
        w.writerows([f"Student {k:02d}", 2000 + k] for k in range(30))
    assert main(["exam", str(tmp_path / "quiz.toml"), "--students",
                 str(tmp_path / "roster.csv"), "--out", str(tmp_path / "c")]) == 0
    key = json.loads((tmp_path / "c" / "key.json").read_text())
    assert len(key["students"]) == 30
    for k in range(4):
        assert len({json.dumps(r["problems"][k]["data"], sort_keys=True)
                    for r in key["students"]}) == 30, k
    header = next(csv.reader((tmp_path / "c" / "answers.csv").open(encoding="utf-8-sig")))
    rng = random.Random(1)
    rows = [header]
    for r in key["students"]:
        ans = {}
        for p in r["problems"]:
            for a in p["asked"]:
                v, u = p["answers"][a], rng.random()
                ans[f"P{p['problem']}.{a}"] = (
                    "" if u < 0.1 else
                    json.dumps((np.array(_fl(v)) * 1000).tolist()) if u < 0.2 else
                    json.dumps((np.array(_fl(v)) * 3 + 1.7).tolist()) if u < 0.3 else
                    json.dumps(_fl(v)))
        rows.append([r["student"], r["id"]] + [ans[c] for c in header[2:]])
    with (tmp_path / "answers.csv").open("w", newline="") as fh:
        csv.writer(fh).writerows(rows)
    capsys.readouterr()
    assert main(["grade", str(tmp_path / "c"), str(tmp_path / "answers.csv")]) == 1
    out = capsys.readouterr().out
    assert ": unit" in out and ": missing" in out
