"""Files as editors save them, and a class exam interrupted.

Answer files with a UTF-8 byte-order mark (Notepad's JSON and text, Excel's CSV), CRLF
line ends and ``;`` separators are graded as plain ones; ``rigidsym exam --students``
interrupted (SIGINT sent at a named checkpoint, as tests/test_interrupts.py does) exits
130 with one line and no traceback, and run again keeps the students it finished (their
handouts not written again) and ends with the same files as an uninterrupted run.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest

from rigidsym.core import interrupts
from rigidsym.course.answers import read_answers

_ANSWERS = {"n_2": [1, 2, 3], "f_2": "0;1;0", "w_2": "1,2,3,0,1,0"}


@pytest.mark.parametrize("bom", [b"", b"\xef\xbb\xbf"], ids=["plain", "bom"])
@pytest.mark.parametrize("eol", ["\n", "\r\n"], ids=["lf", "crlf"])
def test_json_txt_and_csv_answers_read_alike(tmp_path, bom, eol):
    (tmp_path / "amy.json").write_bytes(bom + json.dumps(_ANSWERS, indent=1)
                                        .replace("\n", eol).encode())
    (tmp_path / "bo.txt").write_bytes(bom + eol.join(
        ["# answers of Bo", "n_2 = [1, 2, 3]", "", "f_2: 0;1;0", "w_2 = 1,2,3,0,1,0"])
        .encode())
    (tmp_path / "class.csv").write_bytes(bom + eol.join(
        ["student;n_2;f_2;w_2", 'Cy;[1, 2, 3];0;"1,2,3,0,1,0"']).encode())
    got = read_answers(tmp_path)
    assert got["amy"] == _ANSWERS
    assert got["bo"] == {"n_2": [1, 2, 3], "f_2": "0;1;0", "w_2": "1,2,3,0,1,0"}
    cy = read_answers(tmp_path / "class.csv")["Cy"]
    assert cy["n_2"] == [1, 2, 3] and cy["w_2"] == "1,2,3,0,1,0"


def test_a_text_line_without_a_name_is_refused_by_line(tmp_path):
    (tmp_path / "amy.txt").write_text("n_2 = 1,2,3\n1,2,3\n")
    with pytest.raises(ValueError, match="line 2"):
        read_answers(tmp_path / "amy.txt")


_SPEC = """title = "Quiz"
seed = 3
[[problem]]
exercise = "3.5"
variants = 1
[[problem]]
exercise = "3.9"
variants = 1
"""


def _run(args, env, cwd):
    p = subprocess.run([sys.executable, "-m", "rigidsym", *args], env=env, cwd=cwd,
                       capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


@pytest.mark.slow
@pytest.mark.unpriced  # fails in .ci/run's thorough part (exit 0: the interrupt never came),
# passes alone in the same venv: an interaction with another test, not found yet (conftest)
def test_an_interrupted_class_exam_keeps_its_finished_students(tmp_path):
    """One core (the students drawn one after another, in this process): SIGINT at the
    third student's end; the run again draws only the students not kept."""
    if not hasattr(os, "sched_setaffinity") or shutil.which("taskset") is None:
        pytest.skip("needs taskset (Linux)")
    (tmp_path / "quiz.toml").write_text(_SPEC)
    (tmp_path / "roster.csv").write_text(
        "\ufeffname;id\r\n" + "".join(f"Student {k};{100 + k}\r\n" for k in range(5)),
        encoding="utf-8")
    env = dict(os.environ, RIGIDSYM_CACHE=str(tmp_path / "cache"))
    env.pop(interrupts.TRACE, None)
    args = ["exam", "quiz.toml", "--students", "roster.csv", "--out", "c"]
    one = ["taskset", "-c", "0", sys.executable, "-m", "rigidsym", *args]
    p = subprocess.run(one, env=dict(env, **{interrupts.AT: "advance:3"}), cwd=tmp_path,
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 130, p.stderr
    assert "Traceback" not in p.stderr and "3 of 5 students kept" in p.stderr, p.stderr
    handouts = sorted((tmp_path / "c" / "handouts").glob("*.html"))
    assert len(handouts) == 3
    before = {h.name: h.stat().st_mtime_ns for h in handouts}
    p = subprocess.run(one, env=env, cwd=tmp_path, capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    after = {h.name: h.stat().st_mtime_ns for h in (tmp_path / "c" / "handouts").glob("*")}
    assert len(after) == 5 and all(after[n] == t for n, t in before.items())
    # the same class as one uninterrupted run, in a fresh cache
    rc, _, err = _run([*args[:-1], "d"], dict(env, RIGIDSYM_CACHE=str(tmp_path / "c2")),
                      tmp_path)
    assert rc == 0, err
    for name in ("key.json", "answers.csv", "stack.xml", "moodle.xml"):
        assert (tmp_path / "c" / name).read_bytes() == (tmp_path / "d" / name).read_bytes()


@pytest.mark.slow
@pytest.mark.unpriced  # fails in .ci/run's thorough part (exit 0: the interrupt never came),
# passes alone in the same venv: an interaction with another test, not found yet (conftest)
def test_exam_interrupted_while_drawing_says_one_line(tmp_path):
    """SIGINT at the first student's end (before the workers start): exit 130, one line,
    no traceback."""
    (tmp_path / "quiz.toml").write_text(_SPEC)
    (tmp_path / "roster.csv").write_text("name\nAmy\nBo\n", encoding="utf-8")
    env = dict(os.environ, RIGIDSYM_CACHE=str(tmp_path / "cache"),
               **{interrupts.AT: "advance:1"})
    rc, _, err = _run(["exam", "quiz.toml", "--students", "roster.csv", "--out", "c"], env,
                      tmp_path)
    assert rc == 130 and "Traceback" not in err, err
    assert err.strip().splitlines()[-1].startswith("rigidsym: interrupted"), err
