"""A class from a roster: an exam per student (name, seed, version printed; a
different variant of every drawn problem; no answer in the handout), one key, a Moodle XML
export; ``rigidsym grade`` on a filled answers CSV gives a per-student, per-box CSV
(points, weights, partial credit, blanks missing, the slip named) and a gradebook, and
exits 1 when any answer is wrong or missing, 0 when all are right.

The slips are planted from the exercise's physics here (Sec. 3.7's moment transfer and
the frame rotation), never read from the grader."""

from __future__ import annotations

import csv
import json
import re
import xml.dom.minidom

import numpy as np
import pytest
import sympy as sp

from rigidsym.cli import main
from tests.test_exam import _leaks

# one worker builds the class made by `exam` (module fixture `made`) for every test of this
# module (each worker that ran one of them built it again)
pytestmark = pytest.mark.xdist_group("course_class")

SPEC = """title = "Quiz 3"
seed = 11
slip_credit = 0.5
slips_along_the_way = true

[[problem]]
exercise = "3.19"
variants = 1
weight = 2

[[problem]]
exercise = "3.8"
variants = 1
"""
ROSTER = "name,id,email\nAmy Ames,1001,amy@example.org\nBob Burr,1002,\nCy Cole,1003,\n"


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    d = tmp_path_factory.mktemp("class")
    (d / "quiz.toml").write_text(SPEC)
    (d / "roster.csv").write_text(ROSTER)
    assert main(["exam", str(d / "quiz.toml"), "--students", str(d / "roster.csv"),
                 "--out", str(d / "out")]) == 0
    return d


def _key(made):
    return json.loads((made / "out" / "key.json").read_text())


def test_a_handout_per_student_with_name_seed_version_and_no_answer(made):
    key = _key(made)
    assert [r["student"] for r in key["students"]] == ["Amy Ames", "Bob Burr", "Cy Cole"]
    for r in key["students"]:
        page = (made / "out" / r["handout"]).read_text()
        assert r["student"] in page and f"Seed:</b> {r['seed']}" in page \
            and f"Version:</b> {r['version']}" in page
        assert not _leaks({"exercises": r["problems"]}, page)
        assert "replace the book" not in page and "100 mm" not in page   # stated once
        assert "[w]_2" in page and "P1.w_2" in page       # the book's symbol, the column
    assert len({r["version"] for r in key["students"]}) == 3
    assert len({r["seed"] for r in key["students"]}) == 3
    for k in range(2):        # every drawn problem differs between every two students
        drawn = [json.dumps(r["problems"][k]["data"], sort_keys=True) for r in
                 key["students"]]
        assert len(set(drawn)) == 3, k


def test_moodle_xml_has_a_cloze_question_per_student_and_problem(made):
    doc = xml.dom.minidom.parse(str(made / "out" / "moodle.xml"))
    qs = [q for q in doc.getElementsByTagName("question")
          if q.getAttribute("type") == "cloze"]
    assert len(qs) == 6
    key = _key(made)
    first = qs[0].getElementsByTagName("questiontext")[0].toxml()
    p = key["students"][0]["problems"][0]
    entries = sum(len(np.ravel(p["answers"][a])) for a in p["asked"])
    assert first.count(":NUMERICAL:=") == entries
    # Moodle's Cloze scoring, from its documented syntax {weight:NUMERICAL:=value:tol}: the
    # question's mark is the sum of its parts' weights, a part scores its weight when the
    # response is within tol. Every box weighs the same (the gradebook's mean of boxes),
    # so a right box and a blank box score as the gradebook scores them.
    for q in qs:
        text = q.getElementsByTagName("questiontext")[0].toxml()
        # a box of numbers is a NUMERICAL part per entry; a truth or reason box one
        # MULTICHOICE or SHORTANSWER part
        boxes = [re.findall(r"\{(\d+):(?:NUMERICAL|MULTICHOICE|SHORTANSWER):()([^}]+)\}",
                            para)
                 for para in text.split("<p>") if re.search(r"\{\d+:[A-Z]+:", para)]
        marks = [sum(int(w) for w, _, _ in b) for b in boxes]
        assert len(set(marks)) == 1, marks
        for blank in range(len(boxes)):        # one box blank, the others right
            got = sum(int(w) for k, b in enumerate(boxes) if k != blank for w, _, _ in b)
            assert got / sum(marks) == pytest.approx((len(boxes) - 1) / len(boxes))


def _floats(x) -> list:
    return np.array(sp.N(sp.Matrix(x), 17).tolist(), dtype=float).ravel().tolist()


def _typed(v) -> str:
    """A key's answer typed as --set reads data: rows split by ';'."""
    if isinstance(v, list) and v and isinstance(v[0], list):
        return ";".join(",".join(r) for r in v)
    return ",".join(v) if isinstance(v, list) else str(v)


def _write(path, rows):
    with path.open("w", newline="") as fh:
        csv.writer(fh).writerows(rows)


def test_grading_a_class_names_slips_counts_blanks_and_exits_nonzero(made, capsys):
    d = made
    key = _key(made)
    header = next(csv.reader((d / "out" / "answers.csv").open(encoding="utf-8-sig")))
    right = {r["student"]: {f"P{p['problem']}.{a}": _typed(p["answers"][a])
                            for p in r["problems"] for a in p["asked"]}
             for r in key["students"]}
    ids = {r["student"]: r["id"] for r in key["students"]}
    assert header[:2] == ["student", "id"]
    _write(d / "right.csv", [header] + [[w, ids[w]] + [right[w][c] for c in header[2:]]
                                        for w in right])
    assert main(["grade", str(d / "out"), str(d / "right.csv")]) == 0
    capsys.readouterr()
    # Bob: 3.19 with Q for Q^T (n_2) and the offset typed in mm (f_2 right, w_2 blank);
    # 3.8 blank. Cy: no row at all (not graded, never a silent zero).
    def slipped(k):
        """Student k's n_2 with Q for Q^T, and with the offset d typed in mm."""
        p = key["students"][k]["problems"][0]
        n_S, f_S, dd = (sp.Matrix([sp.sympify(x) for x in p["data"][n]])
                        for n in ("n_S", "f_S", "d"))
        Q = sp.Matrix(p["data"]["Q"]).applyfunc(sp.sympify)
        return (Q * (n_S - dd.cross(f_S)),               # n_P = n_S - d x f (Sec. 3.7)
                Q.T * (n_S - (1000 * dd).cross(f_S)))
    amy = dict(right["Amy Ames"])
    amy["P1.n_2"] = json.dumps(_floats(slipped(0)[1]))
    bob_row = {"P1.n_2": json.dumps(_floats(slipped(1)[0])),
               "P1.f_2": right["Bob Burr"]["P1.f_2"]}
    _write(d / "class.csv", [header, ["Amy Ames", ""] + [amy[c] for c in header[2:]],
                             ["Bob Burr", ""] + [bob_row.get(c, "") for c in header[2:]]])
    assert main(["grade", str(d / "out"), str(d / "class.csv")]) == 11   # Cy: not graded
    captured = capsys.readouterr()
    out = captured.out
    assert "Cy Cole" in captured.err and "not graded" in captured.err
    assert "P1.n_2: transpose" in out and "P1.n_2: unit" in out
    rows = list(csv.DictReader((d / "out" / "grades.csv").open(encoding="utf-8-sig")))
    by = {(r["student"], r["problem"], r["answer"]): r for r in rows}
    assert by[("Bob Burr", "1", "n_2")]["slip"] == "transpose"
    assert "Q used for Q^T" in by[("Bob Burr", "1", "n_2")]["detail"]
    assert by[("Amy Ames", "1", "n_2")]["slip"] == "unit"
    assert "d typed in mm" in by[("Amy Ames", "1", "n_2")]["detail"]
    assert by[("Bob Burr", "1", "w_2")]["status"] == "missing"
    assert all(r["status"] == "not graded" for r in rows if r["student"] == "Cy Cole")
    # partial credit: problem 1 (weight 2, 3 boxes): Amy 2 right + a named slip at 0.5
    with (d / "out" / "gradebook.csv").open(encoding="utf-8-sig") as fh:   # a BOM: Excel
        book = {r["Full name"]: r for r in csv.DictReader(fh)}
    assert float(book["Amy Ames"]["Problem 1"]) == pytest.approx(2 * (2 + 0.5) / 3, abs=1e-3)
    assert float(book["Amy Ames"]["Total"]) == pytest.approx(2 * 2.5 / 3 + 1, abs=1e-3)
    assert float(book["Bob Burr"]["Problem 1"]) == pytest.approx(2 * 1.5 / 3, abs=1e-3)
    assert book["Cy Cole"]["Total"] == ""            # not graded: empty, not 0
    assert book["Amy Ames"]["ID number"] == "1001"
    # the exam's own answer files: a folder of <handout's stem>.json, {"P1": {...}}
    folder = d / "files"
    folder.mkdir()
    mine = {f"P{p['problem']}": {a: p["answers"][a] for a in p["asked"]}
            for p in key["students"][0]["problems"]}
    (folder / "Amy_Ames.json").write_text(json.dumps(mine))
    assert main(["grade", str(d / "out"), str(folder)]) == 12     # Bob, Cy: not graded
    rows = list(csv.DictReader((d / "out" / "grades.csv").open(encoding="utf-8-sig")))
    assert all(r["status"] == "right" for r in rows if r["student"] == "Amy Ames")
    assert book["Amy Ames"]["Email address"] == "amy@example.org"


def test_bad_rosters_and_answers(made, tmp_path, capsys):
    d = made
    (tmp_path / "r.csv").write_text("who\nx\n")
    assert main(["exam", str(d / "quiz.toml"), "--students", str(tmp_path / "r.csv"),
                 "--out", str(tmp_path / "o")]) == 2
    assert "'name'" in capsys.readouterr().err
    (tmp_path / "r.csv").write_text("name\nx\nx\n")
    assert main(["exam", str(d / "quiz.toml"), "--students", str(tmp_path / "r.csv"),
                 "--out", str(tmp_path / "o")]) == 2
    assert "twice" in capsys.readouterr().err
    # a row of no student, or with a box the exam lacks: reported, the class graded; each
    # student of the roster with no row graded: a line too (three here), never a zero
    _write(tmp_path / "a.csv", [["student", "P1.w_2"], ["Zed", "1"]])
    assert main(["grade", str(d / "out"), str(tmp_path / "a.csv")]) == 14
    err = capsys.readouterr().err
    assert "Zed: not graded: no student id or name" in err
    assert "Amy Ames (id 1001): not graded" in err
    _write(tmp_path / "a.csv", [["student", "P9.x"], ["Amy Ames", "1"]])
    assert main(["grade", str(d / "out"), str(tmp_path / "a.csv")]) == 14
    assert re.search(r"'P9.x' is no answer box", capsys.readouterr().err)
    assert main(["grade", str(tmp_path), str(tmp_path / "a.csv")]) == 2
