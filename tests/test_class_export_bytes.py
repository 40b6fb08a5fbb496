"""A class's files are the same bytes however often and wherever they are written: the
exam (handouts, keys, key.json, answers.csv, moodle.xml, stack.xml) written in this process
and again by ``rigidsym exam`` in a fresh process under another PYTHONHASHSEED and an empty
cache, and the gradebook that ``rigidsym grade`` makes from each written key, are equal byte
for byte, and the gradebook's points are the weights given when the exam was made.

A small class (three students, one of them with accents; 3.1 drawn, whose axis and angle
STACK grades jointly, and 3.4 on its data) under ``slips_along_the_way``: the STACK export
then solves each slip's replay too. The class of 30 is ``tests/test_course_class.py``."""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from rigidsym.course.gradebook import grade_class, solution_of
from rigidsym.course.grading import key_array
from rigidsym.course.roster import class_exam

SPEC = """title = "Quiz"
seed = 11
slip_credit = 0.5
slips_along_the_way = true
[[problem]]
exercise = "3.1"
variants = 1
[[problem]]
exercise = "3.4"
data = {}
"""
ROSTER = "name,id\nAmy Ames,001\nZoë Müller,002\nBo Bell,003\n"
WEIGHTS = [2.0, 0.5]


def _files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def _answers(folder: Path, path: Path) -> None:
    """Amy every box right; Zoë problem 2 wrong (1.37 times the key: no slip); Bo problem
    1 blank."""
    key = json.loads((folder / "key.json").read_text(encoding="utf-8"))
    rows = []
    for i, r in enumerate(key["students"]):
        row = {"student": r["student"], "id": r["id"]}
        for p in r["problems"]:
            for a in p["asked"]:
                v = key_array(solution_of(p).answers[a])
                row[f"P{p['problem']}.{a}"] = "" if (i, p["problem"]) == (2, 1) else \
                    json.dumps((1.37 * v if (i, p["problem"]) == (1, 2) else v).tolist())
        rows.append(row)
    # every student's boxes (a drawn 3.1 asks for the line's intersection with one plane
    # or another), as answers.csv's columns
    cols = list(dict.fromkeys(c for row in rows for c in row))
    with path.open("w", encoding="utf-8", newline="") as f:
        w = csv.DictWriter(f, cols, restval="")
        w.writeheader()
        w.writerows(rows)


# slow (~9.5 s of CPU, most of it a second process on an empty cache): the quick
# tests/test_exam_weights.py checks what the weights put into key.json, moodle.xml, stack.xml
# and the gradebook, and tests/test_course.py the class's files
@pytest.mark.slow
def test_a_class_written_again_elsewhere_is_the_same_bytes_and_grades_the_same(tmp_path):
    (tmp_path / "quiz.toml").write_text(SPEC, encoding="utf-8")
    (tmp_path / "roster.csv").write_text(ROSTER, encoding="utf-8")
    here, there = tmp_path / "here", tmp_path / "there"
    class_exam(tmp_path / "quiz.toml", tmp_path / "roster.csv", here, weights=WEIGHTS)
    _answers(here, tmp_path / "filled.csv")
    # the same class made and graded by the command line in a fresh process: another hash
    # seed (dicts and sets of strings in another order) and an empty cache (every solve,
    # replay and figure made again, none read back from this process's)
    seed = "2" if os.environ.get("PYTHONHASHSEED") == "1" else "1"
    code = ("import sys; from rigidsym.cli import main; "
            f"a = main(['exam', {str(tmp_path / 'quiz.toml')!r}, '--students', "
            f"{str(tmp_path / 'roster.csv')!r}, '--out', {str(there)!r}, '--weights', "
            f"'2,0.5']); "
            f"b = main(['grade', {str(there)!r}, {str(tmp_path / 'filled.csv')!r}]); "
            "print('codes', a, b)")
    env = dict(os.environ, PYTHONHASHSEED=seed, RIGIDSYM_CACHE=str(tmp_path / "cache"))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=env, cwd=tmp_path, timeout=600)
    # the exam written (0), the class graded with wrong and missing boxes (1)
    assert "codes 0 1" in done.stdout, done.stdout + done.stderr
    grade_class(here, tmp_path / "filled.csv")
    mine, theirs = _files(here), _files(there)
    assert sorted(mine) == sorted(theirs)
    assert {"stack.xml", "moodle.xml", "key.json", "gradebook.csv", "grades.csv"} <= set(mine)
    differ = [name for name in mine if mine[name] != theirs[name]]
    assert differ == [], f"written again under PYTHONHASHSEED={seed}, these differ: {differ}"
    book = list(csv.DictReader(mine["gradebook.csv"].decode("utf-8-sig").splitlines()))
    # a problem's points are its weight times the share of its boxes right
    assert [(float(r["Problem 1"]), float(r["Problem 2"]), float(r["Total"])) for r in book] \
        == [(2.0, 0.5, 2.5), (2.0, 0.0, 2.0), (0.0, 0.5, 0.5)]
