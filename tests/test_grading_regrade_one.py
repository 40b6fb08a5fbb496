"""A fixed answer regrades that student alone: grading a class again grades only the
students whose answers changed, and writes what a grading from scratch writes."""

from __future__ import annotations

import csv
import json

import pytest

import rigidsym.course.grading as grading
from rigidsym.course.gradebook import grade_class, solution_of
from rigidsym.course.grading import key_array
from rigidsym.course.roster import class_exam

SPEC = {"title": "Quiz", "slip_credit": 0.5,
        "problem": [{"exercise": "3.4", "data": {}}]}


def _answers(path, key, wrong: set[str]):
    """The answers CSV: every box the key's value, each box of the students in ``wrong``
    1.37 times it (wrong, and no slip)."""
    cols = [f"P{p['problem']}.{a}" for p in key["students"][0]["problems"] for a in p["asked"]]
    with path.open("w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "id", *cols])
        for r in key["students"]:
            f = 1.37 if r["student"] in wrong else 1.0
            row = [json.dumps((f * key_array(solution_of(p).answers[a])).tolist())
                   for p in r["problems"] for a in p["asked"]]
            w.writerow([r["student"], r["id"], *row])


@pytest.fixture
def a_class(tmp_path):
    (tmp_path / "roster.csv").write_text("name,id\nAmy Ames,001\nBo Bell,002\n",
                                         encoding="utf-8")
    class_exam(SPEC, tmp_path / "roster.csv", tmp_path / "out")
    return tmp_path, json.loads((tmp_path / "out" / "key.json").read_text(encoding="utf-8"))


def test_a_fixed_answer_regrades_that_student_alone(a_class, monkeypatch):
    tmp, key = a_class
    log = tmp / "graded.log"                 # the graders may be forked workers
    real = grading.grade

    def counted(solution, answers, *args, **kwargs):
        with log.open("a", encoding="utf-8") as f:
            f.write(json.dumps(answers, sort_keys=True, default=repr) + "\n")
        return real(solution, answers, *args, **kwargs)

    def calls() -> int:
        return len(log.read_text(encoding="utf-8").splitlines()) if log.exists() else 0

    monkeypatch.setattr(grading, "grade", counted)
    _answers(tmp / "answers.csv", key, {"Bo Bell"})
    first = grade_class(tmp / "out", tmp / "answers.csv")
    assert "Bo Bell" in first["table"] and not first["all_right"]
    n_first = calls()
    assert n_first == 2                      # one problem each: every student graded

    _answers(tmp / "answers.csv", key, set())       # Bo's answers fixed
    again = grade_class(tmp / "out", tmp / "answers.csv")
    assert calls() == n_first + 1             # Bo alone graded again
    assert again["all_right"]
    kept = (tmp / "out" / "grades.csv").read_bytes()

    # the same files as a grading from scratch (the kept students' rows included)
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp / "empty-cache"))
    fresh = grade_class(tmp / "out", tmp / "answers.csv")
    assert calls() == n_first + 1 + 2
    assert (tmp / "out" / "grades.csv").read_bytes() == kept
    assert fresh["table"] == again["table"]
