"""Weights set when making a class's exam (``rigidsym exam SPEC --students ROSTER --weights
...``, ``class_exam(..., weights=)``, a spec problem's ``weight``): they go into key.json,
the Moodle and STACK exports and the gradebook (a problem's points are its weight), and
bad weights are refused, naming the argument, before anything is drawn."""

from __future__ import annotations

import csv
import json
import re

import pytest
from test_grade_weights import gradebook_points

from rigidsym.cli import main
from rigidsym.course.gradebook import grade_class, solution_of
from rigidsym.course.grading import key_array
from rigidsym.course.roster import class_exam

SPEC = {"title": "Quiz", "slip_credit": 0.5, "slips_along_the_way": False,
        "problem": [{"exercise": "3.4", "data": {}}, {"exercise": "3.4", "data": {}}]}
SPEC_TOML = """title = "Quiz"
slip_credit = 0.5
slips_along_the_way = false
[[problem]]
exercise = "3.4"
data = {}
[[problem]]
exercise = "3.4"
data = {}
weight = 4
"""


@pytest.fixture(scope="module")
def roster(tmp_path_factory):
    path = tmp_path_factory.mktemp("roster") / "roster.csv"
    path.write_text("name,id\nAmy Ames,001\nBo Bell,002\n", encoding="utf-8")
    return path


def _key(folder) -> dict:
    return json.loads((folder / "key.json").read_text(encoding="utf-8"))


def _weights(folder) -> list[list[float]]:
    """Each student's problems' weights as key.json keeps them."""
    return [[p["weight"] for p in r["problems"]] for r in _key(folder)["students"]]


def _marks(folder, name: str) -> list[float]:
    """Each question's maximum mark (``<defaultgrade>``) in an export, in order."""
    text = (folder / name).read_text(encoding="utf-8")
    return [float(x) for x in re.findall(r"<defaultgrade>([^<]*)</defaultgrade>", text)]


def _all_right(folder):
    """An answers CSV in which every box of every student is the key's value."""
    key = _key(folder)
    cols = [f"P{p['problem']}.{a}" for p in key["students"][0]["problems"] for a in p["asked"]]
    path = folder / "filled.csv"
    with path.open("w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "id", *cols])
        for r in key["students"]:
            w.writerow([r["student"], r["id"], *[
                json.dumps(key_array(solution_of(p).answers[a]).tolist())
                for p in r["problems"] for a in p["asked"]]])
    return path


def test_weights_given_to_class_exam_reach_the_key_the_exports_and_the_gradebook(
        roster, tmp_path):
    class_exam(SPEC, roster, tmp_path, weights=[3, 0.5])
    assert _weights(tmp_path) == [[3.0, 0.5]] * 2
    assert _marks(tmp_path, "stack.xml") == [3.0, 0.5] * 2
    assert _marks(tmp_path, "moodle.xml") == [3.0, 0.5] * 2
    # every box right: each problem scores its weight
    grade_class(tmp_path, _all_right(tmp_path))
    assert gradebook_points(tmp_path) == [(3.0, 0.5, 3.5)] * 2


# two class exams; quick: test_the_command_lines_weights_reach_the_key_and_the_gradebook
# (the spec's weights where none is given, then --weights replacing them)
@pytest.mark.slow
def test_the_specs_weight_serves_where_none_is_given_and_weights_replace_it(roster,
                                                                          tmp_path):
    spec = {**SPEC, "problem": [SPEC["problem"][0], {**SPEC["problem"][1], "weight": 2}]}
    class_exam(spec, roster, tmp_path / "spec")
    assert _weights(tmp_path / "spec") == [[1.0, 2.0]] * 2
    class_exam(spec, roster, tmp_path / "given", weights=[1, 0])
    assert _weights(tmp_path / "given") == [[1.0, 0.0]] * 2


def test_weights_are_one_per_problem_of_the_exam_not_per_spec_problem(roster, tmp_path):
    spec = {**SPEC, "problem": [{"exercise": "3.4", "variants": 2}]}
    with pytest.raises(ValueError, match="^weights: expected 2 numbers"):
        class_exam(spec, roster, tmp_path, weights=[1])
    class_exam(spec, roster, tmp_path, weights=[1, 5])
    assert _weights(tmp_path) == [[1.0, 5.0]] * 2


@pytest.mark.parametrize("weights, words", [
    ([1, 2, 3], "expected 2 numbers"), ([1], "expected 2 numbers"),
    ([1, -1], ">= 0"), ([float("nan"), 1], ">= 0"), ([float("inf"), 1], ">= 0"),
    ([0, 0], "positive"), (["one", 1], "expected 2 numbers"),
    ("1,2", "expected 2 numbers"), (2, "expected 2 numbers")])
def test_bad_weights_are_refused_by_keyword_before_anything_is_written(roster, tmp_path,
                                                                      weights, words):
    with pytest.raises(ValueError, match="^weights: ") as info:
        class_exam(SPEC, roster, tmp_path / "out", weights=weights)
    assert words in str(info.value)
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("weight, words", [
    (-1, "problem 2: weight must be a finite number >= 0"),
    ("two", "problem 2: weight must be a finite number >= 0"),
    (float("nan"), "problem 2: weight must be a finite number >= 0"),
    (True, "problem 2: weight must be a finite number >= 0")])
def test_a_bad_weight_in_the_spec_is_refused_naming_the_problem(roster, tmp_path, weight,
                                                               words):
    spec = {**SPEC, "problem": [SPEC["problem"][0], {**SPEC["problem"][1], "weight": weight}]}
    with pytest.raises(ValueError, match="^spec: ") as info:
        class_exam(spec, roster, tmp_path)
    assert words in str(info.value)


def test_a_spec_whose_weights_are_all_zero_is_refused(roster, tmp_path):
    spec = {**SPEC, "problem": [{**p, "weight": 0} for p in SPEC["problem"]]}
    with pytest.raises(ValueError, match="^spec: at least one problem's weight must be "
                                         "positive"):
        class_exam(spec, roster, tmp_path)


def test_the_command_lines_weights_reach_the_key_and_the_gradebook(roster, tmp_path,
                                                                   capsys):
    spec = tmp_path / "quiz.toml"
    spec.write_text(SPEC_TOML, encoding="utf-8")
    out = tmp_path / "class"
    assert main(["exam", str(spec), "--students", str(roster), "--out", str(out)]) == 0
    assert _weights(out) == [[1.0, 4.0]] * 2          # the spec's
    assert main(["exam", str(spec), "--students", str(roster), "--out", str(out),
                 "--weights", "2,0.25"]) == 0
    assert _weights(out) == [[2.0, 0.25]] * 2
    assert _marks(out, "stack.xml") == [2.0, 0.25] * 2
    capsys.readouterr()
    assert main(["grade", str(out), str(_all_right(out))]) == 0
    assert gradebook_points(out) == [(2.0, 0.25, 2.25)] * 2


@pytest.mark.parametrize("text, words", [
    ("1,two", "--weights: expected numbers separated by commas"),
    ("1,2,3", "weights: expected 2 numbers"), ("1,-1", "weights: each weight must be"),
    ("nan,1", "weights: each weight must be"), ("0,0", "weights: at least one weight")])
def test_the_command_line_refuses_bad_weights(roster, tmp_path, capsys, text, words):
    spec = tmp_path / "quiz.toml"
    spec.write_text(SPEC_TOML, encoding="utf-8")
    code = main(["exam", str(spec), "--students", str(roster), "--out",
                 str(tmp_path / "out"), f"--weights={text}"])
    assert code == 2
    assert words in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_weights_without_a_class_are_refused(tmp_path, capsys):
    spec = tmp_path / "quiz.toml"
    spec.write_text(SPEC_TOML, encoding="utf-8")
    assert main(["exam", str(spec), "--out", str(tmp_path / "out"), "--weights", "1,1"]) == 2
    assert "--weights: weights go with a class exam (--students" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()
