"""Weights given when grading (``rigidsym grade DIR ANSWERS --weights ...``): each
problem's points are its weight times the mean score of its boxes, the key is unchanged,
and bad weights are refused with the argument named."""

from __future__ import annotations

import csv
import json

import pytest

from rigidsym.cli.grade import parse_weights
from rigidsym.course.gradebook import grade_class, solution_of
from rigidsym.course.grading import key_array
from rigidsym.course.roster import class_exam

pytestmark = pytest.mark.xdist_group("grade_weights")  # its module fixtures built on one worker

SPEC = {"title": "Quiz", "slip_credit": 0.5, "slips_along_the_way": False,
        "problem": [{"exercise": "3.4", "data": {}}, {"exercise": "3.4", "data": {}}]}


@pytest.fixture(scope="module")
def graded_class(tmp_path_factory):
    """A class of two; every box of problem 1 the key's value, every box of problem 2
    1.37 times it (wrong, and no slip)."""
    tmp = tmp_path_factory.mktemp("weights")
    (tmp / "roster.csv").write_text("name,id\nAmy Ames,001\nBo Bell,002\n", encoding="utf-8")
    class_exam(SPEC, tmp / "roster.csv", tmp / "out")
    key = json.loads((tmp / "out" / "key.json").read_text(encoding="utf-8"))
    cols = [f"P{p['problem']}.{a}" for p in key["students"][0]["problems"] for a in p["asked"]]
    with (tmp / "answers.csv").open("w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "id", *cols])
        for r in key["students"]:
            w.writerow([r["student"], r["id"], *[
                json.dumps(((1.0 if p["problem"] == 1 else 1.37)
                            * key_array(solution_of(p).answers[a])).tolist())
                for p in r["problems"] for a in p["asked"]]])
    return tmp


def gradebook_points(folder) -> list[tuple[float, float, float]]:
    """Each student's (problem 1, problem 2, total) points in ``folder``'s gradebook.csv."""
    text = (folder / "gradebook.csv").read_text(encoding="utf-8-sig")
    return [(float(r["Problem 1"]), float(r["Problem 2"]), float(r["Total"]))
            for r in csv.DictReader(text.splitlines())]


@pytest.mark.parametrize("weights", [[3, 1], [1, 0], [0.5, 2]])
def test_a_problems_points_are_its_weight_given_when_grading(graded_class, weights):
    key_before = (graded_class / "out" / "key.json").read_bytes()
    grade_class(graded_class / "out", graded_class / "answers.csv", weights=weights)
    # problem 1 all right, problem 2 all wrong: the weight of problem 1, and 0
    assert gradebook_points(graded_class / "out") == [(weights[0], 0.0, weights[0])] * 2
    assert (graded_class / "out" / "key.json").read_bytes() == key_before


def test_without_weights_the_keys_weights_grade(graded_class):
    grade_class(graded_class / "out", graded_class / "answers.csv")
    assert gradebook_points(graded_class / "out") == [(1.0, 0.0, 1.0)] * 2


@pytest.mark.parametrize("weights, words", [
    ([1, 2, 3], "expected 2 numbers"), ([1], "expected 2 numbers"),
    ([1, -1], ">= 0"), ([float("nan"), 1], ">= 0"), ([0, 0], "positive"),
    (["one", 1], "expected 2 numbers")])
def test_bad_weights_are_refused_naming_the_argument(graded_class, weights, words):
    with pytest.raises(ValueError, match="^weights: ") as info:
        grade_class(graded_class / "out", graded_class / "answers.csv", weights=weights)
    assert words in str(info.value)


def test_the_command_lines_weights_read_as_numbers():
    assert parse_weights("1,1,2.5") == [1.0, 1.0, 2.5]
    assert parse_weights(None) is None
    with pytest.raises(ValueError, match="^--weights: .*'two'"):
        parse_weights("1,two")
