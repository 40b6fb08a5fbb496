"""A class of 30 (issue 51's acceptance): the exam for 30 students and the grading of a
30-row answers CSV each take at most 60 s of CPU (this process and its workers) on the
2-core machine; every student's drawn problems differ; the grading exits 1 (some answers
are wrong or blank) and names a planted unit slip. Slow: it draws and grades 120
problems."""

from __future__ import annotations

import csv
import json
import random
import resource
import time

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


def _cpu() -> float:
    own, kids = (resource.getrusage(w) for w in (resource.RUSAGE_SELF,
                                                    resource.RUSAGE_CHILDREN))
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _fl(v):
    if isinstance(v, list):
        return [_fl(x) for x in v]
    e = sp.sympify(v)
    return float(bool(e)) if e in (sp.true, sp.false) else float(e)


def test_thirty_students_made_and_graded_within_a_minute_each(tmp_path, capsys):
    (tmp_path / "quiz.toml").write_text(SPEC)
    with (tmp_path / "roster.csv").open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "id"])
        w.writerows([f"Student {k:02d}", 2000 + k] for k in range(30))
    c0, t0 = _cpu(), time.perf_counter()
    assert main(["exam", str(tmp_path / "quiz.toml"), "--students",
                 str(tmp_path / "roster.csv"), "--out", str(tmp_path / "c")]) == 0
    made_cpu, made_wall = _cpu() - c0, time.perf_counter() - t0
    key = json.loads((tmp_path / "c" / "key.json").read_text())
    assert len(key["students"]) == 30
    for k in range(4):
        assert len({json.dumps(r["problems"][k]["data"], sort_keys=True)
                    for r in key["students"]}) == 30, k
    header = next(csv.reader((tmp_path / "c" / "answers.csv").open()))
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
        rows.append([r["student"]] + [ans[c] for c in header[1:]])
    with (tmp_path / "answers.csv").open("w", newline="") as fh:
        csv.writer(fh).writerows(rows)
    capsys.readouterr()
    c0, t0 = _cpu(), time.perf_counter()
    assert main(["grade", str(tmp_path / "c"), str(tmp_path / "answers.csv")]) == 1
    graded_cpu, graded_wall = _cpu() - c0, time.perf_counter() - t0
    out = capsys.readouterr().out
    assert ": unit" in out and ": missing" in out
    print(f"30 students: exam {made_cpu:.1f} s CPU ({made_wall:.1f} s wall), grading "
          f"{graded_cpu:.1f} s CPU ({graded_wall:.1f} s wall)")
    assert made_cpu <= 60 and graded_cpu <= 60
