"""A class's CSVs as a spreadsheet and a roster with leading-zero ids meet them.

Every roster entry is graded or named: answer rows matched by id first, then by name; two
rows of one name without ids refused on one line naming both rows, the student then
listed as not graded (empty gradebook cells, never a zero); the answers template carries
an ``id`` column. The CSVs written (answers.csv, grades.csv, gradebook.csv) start with a
UTF-8 byte-order mark and quote every cell, so an id ``00042`` is one text field that
Python's csv and the project's own reader give back as ``00042``.
"""

from __future__ import annotations

import csv
import json

import pytest

from rigidsym.cli import main
from rigidsym.course.answers import read_table

# one worker builds the class and its CSV files (module fixtures) for every test of this
# module (each worker that ran one of them built it again)
pytestmark = pytest.mark.xdist_group("course_csv")

SPEC = 'title = "Q"\nseed = 3\n\n[[problem]]\nexercise = "3.5"\nvariants = 1\n'
ROSTER = "name,id\nAna Lima,00042\nBea Bo,00107\nCy Cole,00300\n"


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    d = tmp_path_factory.mktemp("csvclass")
    (d / "quiz.toml").write_text(SPEC)
    (d / "roster.csv").write_text(ROSTER)
    assert main(["exam", str(d / "quiz.toml"), "--students", str(d / "roster.csv"),
                 "--out", str(d / "out")]) == 0
    return d


def _rows(path):
    with path.open(encoding="utf-8-sig", newline="") as fh:
        return list(csv.DictReader(fh))


def _answers(made, rows):
    """An answers CSV as a spreadsheet writes it (BOM, ids as typed)."""
    key = json.loads((made / "out" / "key.json").read_text(encoding="utf-8"))
    right = {r["id"]: r["problems"][0]["answers"] for r in key["students"]}
    path = made / "filled.csv"
    with path.open("w", encoding="utf-8-sig", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["student", "id", "P1.d", "P1.p_star"])
        for name, ident, whose in rows:
            a = right[whose]
            w.writerow([name, ident, a["d"], json.dumps(a["p_star"])])
    return path


def _assert_excel_ready(path, ids):
    raw = path.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")
    text = raw.decode("utf-8-sig")
    for i in ids:
        assert f'"{i}"' in text, i
    got = {r["id"] if "id" in r else r["ID number"] for r in _rows(path)}
    assert set(ids) <= got
    mine = {r.get("id") or r.get("ID number") for r in read_table(path)}
    assert set(ids) <= mine


def test_template_has_an_id_column_quoted_with_its_leading_zeros(made):
    path = made / "out" / "answers.csv"
    assert list(_rows(path)[0])[:2] == ["student", "id"]
    _assert_excel_ready(path, ["00042", "00107", "00300"])
    assert [r["id"] for r in _rows(path)] == ["00042", "00107", "00300"]


def test_matched_by_id_then_name_and_every_student_graded_or_named(made, capsys):
    # Ana by a misspelt name and her id (the id wins), Bea by her id as Excel saves it
    # (no leading zeros), Cy by name alone
    table = _answers(made, [("Anna Lim", "00042", "00042"), ("Bea Bo", "107", "00107"),
                            ("Cy Cole", "", "00300")])
    assert main(["grade", str(made / "out"), str(table)]) == 0, capsys.readouterr().err
    book = {r["ID number"]: r for r in _rows(made / "out" / "gradebook.csv")}
    assert all(float(book[i]["Total"]) == 1 for i in ("00042", "00107", "00300"))
    _assert_excel_ready(made / "out" / "gradebook.csv", ["00042", "00107", "00300"])
    _assert_excel_ready(made / "out" / "grades.csv", ["00042", "00107", "00300"])


def test_two_rows_of_one_name_without_ids_are_refused_naming_both(made, capsys):
    table = _answers(made, [("Ana Lima", "", "00042"), ("Ana Lima", "", "00107"),
                            ("Bea Bo", "00107", "00107")])
    code = main(["grade", str(made / "out"), str(table)])
    err = capsys.readouterr().err
    assert code != 0
    refusal = next(line for line in err.splitlines() if "row 2 of filled.csv" in line)
    assert "row 3 of filled.csv" in refusal and "not graded" in refusal
    assert "Ana Lima (id 00042): not graded" in err and "Cy Cole (id 00300): not graded" in err
    book = {r["ID number"]: r for r in _rows(made / "out" / "gradebook.csv")}
    assert book["00042"]["Total"] == "" and book["00300"]["Total"] == ""   # not a zero
    assert float(book["00107"]["Total"]) == 1
    grades = _rows(made / "out" / "grades.csv")
    assert {r["status"] for r in grades if r["id"] == "00042"} == {"not graded"}
