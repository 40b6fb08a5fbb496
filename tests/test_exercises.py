"""Exercises 3.1-3.21: every worked solution is solved and passes its own machine checks.

The checks are the exercises' independent verifications (the sound zero test, exact
algebraic arithmetic); these tests assert them and the CLI/JSON contract, not copied numbers.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp
from rigidsym.derivations.exercises import EXERCISE_IDS, normalise_id, solve

from rigidsym.cli import main
from rigidsym.course.worked import parameters, render_markdown, render_text, to_json_value


@pytest.mark.sample
@pytest.mark.parametrize("ex_id", EXERCISE_IDS)
def test_exercise_solved_and_checked(ex_id):
    s = solve(ex_id)
    assert s.id == ex_id
    assert s.status == "solved"
    assert s.checks, "an exercise needs at least one machine check"
    failed = [f"{c.name}: {c.detail}" for c in s.checks if not c.passed]
    assert not failed
    assert s.steps and s.answers and s.statement and s.citation
    assert f"Exercise {ex_id[2:]}" in render_text(s)
    assert render_markdown(s).startswith(f"## Exercise {ex_id[2:]}")


def test_normalise_id():
    assert normalise_id("3.10") == normalise_id("ex3.10") == normalise_id("3.010") == "ex3.10"
    for bad in ("3.22", "2.1", "x", "3.0"):
        with pytest.raises(ValueError):
            normalise_id(bad)


# every exercise solved; quick: the sample of test_exercise_solved_and_checked,
# test_cli_single_and_bad_input
@pytest.mark.slow
def test_cli_json_schema(tmp_path, capsys):
    path = tmp_path / "ex.json"
    assert main(["exercise", "--all", "--json", str(path)]) == 0
    doc = json.loads(path.read_text())
    assert doc["schema"] == 2 and "python_flint" in doc
    assert [e["id"] for e in doc["exercises"]] == EXERCISE_IDS
    for e in doc["exercises"]:
        assert e["status"] == "solved" and e["checked"] is True
        assert list(e["data"]) == [p.name for p in parameters(e["id"])]     # schema 2
        assert e["checks"] and all(c["passed"] for c in e["checks"])
        for v in e["answers"].values():
            for x in (sum(v, []) if isinstance(v, list) and v and isinstance(v[0], list)
                      else v if isinstance(v, list) else [v]):
                sp.sympify(x)  # every value reads back
    assert "21 / 21 solved" in capsys.readouterr().out


def test_cli_single_and_bad_input(capsys):
    assert main(["exercise", "3.8"]) == 0
    assert "Machine checks" in capsys.readouterr().out
    assert main(["exercise", "3.99"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rigidsym: error:")
    assert main(["exercise"]) == 0  # no id: the list of the exercises
    assert capsys.readouterr().out.count("\n  3.") == 21


# every exercise solved and rendered; quick: the sample of test_exercise_solved_and_checked renders
# its pages
@pytest.mark.slow
def test_report_hook(tmp_path):
    from rigidsym.cli.exercise import write_report
    write_report(tmp_path)
    text = (tmp_path / "exercises.md").read_text()
    assert "## Exercise 3.10" in text and "| ZXZ |" in text


def test_cli_student_data(tmp_path, capsys):
    assert main(["exercise", "3.4", "--parameters"]) == 0
    assert "n_1" in capsys.readouterr().out
    assert main(["exercise", "3.4", "--set", "f_2=1,1,1"]) == 1
    assert "Ill-posed: The measurements are not compatible" in capsys.readouterr().out
    data = tmp_path / "readings.json"
    data.write_text(json.dumps({"n_2": [-1.6667, -3.3333, 3.3333],
                                "f_2": [-1.3333, 1.3333, 0.6667]}))
    out = tmp_path / "out.json"
    assert main(["exercise", "3.4", "--data", str(data), "--json", str(out)]) == 0
    assert "least squares" in capsys.readouterr().out
    doc = json.loads(out.read_text())["exercises"][0]
    assert doc["status"] == "solved" and doc["checked"] and "residual" in doc["answers"]
    # the key's data, read back, give the key's answers (exact strings: no float drift)
    again = solve("ex3.4", tol=doc["tol"], **doc["data"])
    for k, v in doc["answers"].items():
        if isinstance(v, list):
            assert sp.Matrix(v) == again.answers[k]
        else:
            assert to_json_value(again.answers[k]) == v if k == "residual" else \
                sp.sympify(v) == again.answers[k]
    assert main(["exercise", "3.14", "--set", "I_B=[[1,0,0],[0,2,0],[0,0,4]]"]) == 1
    assert "not acceptable" in capsys.readouterr().out
    assert main(["exercise", "3.11", "--set", "a=0.05", "--set", "h=1/10"]) == 0
    assert "a (m) =\n    1/20" in capsys.readouterr().out


@pytest.mark.parametrize("argv", [
    ["exercise", "3.4", "--set", "n_3=1,2,3"],
    ["exercise", "3.4", "--set", "n_1"],
    ["exercise", "3.4", "--set", "n_1=1,2"],
    ["exercise", "3.4", "--data", "/nonexistent/data.json"],
    ["exercise", "3.2", "--tol", "0.1"],
    ["exercise", "--all", "--set", "n_1=1,2,3"],
])
def test_cli_bad_data_is_one_line_exit_2(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rigidsym: error:")
