"""A class graded end to end against an independent NumPy grader.

The test builds a class from a roster saved as a European Excel would (a BOM, ``;``),
with names in several scripts and two students of one name; each student answers 3.1
with a random behaviour per box: right as the key writes it, right in an equivalent form
((-e, -phi) with the Plücker array negated, phi + 2 pi, written with a decimal comma),
blank, one slip, or rounded to 2 significant figures. Answer files are named as students
name them (the id, the name without accents, in lower case, decomposed as macOS writes
it), one is unreadable and one belongs to nobody. The grader's verdicts are compared
with what the test decides in NumPy: the rotation of (e, phi) by Rodrigues' formula
against the key's Q, the line of the Plücker array, the slip the test planted.
The default run grades a class of 4; the class of 40 runs under ``slow``.
"""

from __future__ import annotations

import csv
import json
import math
import random
import unicodedata

import numpy as np
import pytest
import sympy as sp

from rigidsym.cli import main

SPEC = """title = "Screws"
seed = 7
slip_credit = 0.5
rounding_credit = 0.75
[[problem]]
exercise = "3.1"
variants = 1
"""
NAMES = ["Zoë Müller", "Amy Ames", "Amy Ames", "山田 太郎", "José Ñúñez", "li wei",
         "Анна Иванова", "Ólafur Þórsson"]
BEHAVIOURS = ("right", "equivalent", "blank", "slip", "rounded")


def _fl(v):
    if isinstance(v, list):
        return np.array([_fl(x) for x in v], dtype=float)
    return float(sp.sympify(v))


def _rot(e, phi):
    """Rodrigues' formula (Angeles eq. 2.48), written here."""
    e = np.asarray(e, float).reshape(3)
    E = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    return np.eye(3) + math.sin(phi) * E + (1 - math.cos(phi)) * E @ E


def _file_name(rng, name, ident):
    """How a student names a file: the id, the name stripped of accents, in lower case,
    decomposed (NFD), with underscores."""
    plain = "".join(c for c in unicodedata.normalize("NFKD", name)
                    if not unicodedata.combining(c))
    return rng.choice([ident, plain, name.lower(), unicodedata.normalize("NFD", name),
                       name.replace(" ", "_")])


def _answers(rng, key, behaviour):
    """Student answers of one 3.1 problem (box -> value) and, per box, what the test
    expects: "right", "missing" or the slip planted (never right)."""
    e, phi, pl = key["e"].reshape(3), float(key["phi"]), key["plucker"].reshape(6)
    Q = key["Q"]
    out, expect = {}, {}
    for box, v in key.items():
        out[box], expect[box] = np.asarray(v).tolist(), "right"
    if behaviour == "equivalent":
        s, turns = rng.choice([(-1, 0), (-1, 1), (1, 1), (1, -1)])
        e2, phi2, pl2 = s * e, s * phi + 2 * math.pi * turns, s * pl
        assert np.allclose(_rot(e2, phi2), Q, atol=1e-9)           # the same rotation
        assert np.allclose(pl2[:3], e2) and np.allclose(pl2[3:], s * pl[3:])
        out.update(e=e2.tolist(), phi=f"{phi2:.9f}".replace(".", ","), plucker=pl2.tolist())
    elif behaviour == "blank":
        box = rng.choice(sorted(key))
        out[box], expect[box] = "", "missing"
    elif behaviour == "slip":
        box, slip = rng.choice([(b, w) for b, w in (
            ("Q", "transpose"), ("e", "sign"), ("phi", "degrees"), ("plucker", "order"),
            ("intersection_x=0", "unit"), ("intersection_z=0", "unit")) if b in key])
        v = np.asarray(key[box], float)
        edited = {"transpose": lambda: v.T, "sign": lambda: -v,
                  "degrees": lambda: v * 180 / math.pi,
                  "order": lambda: np.concatenate([v[3:], v[:3]]),
                  "unit": lambda: v * 1000}[slip]()
        if box == "Q":
            assert not np.allclose(edited, Q)          # Q is no symmetric half turn here
        out[box], expect[box] = edited.tolist(), "slip"
    elif behaviour == "rounded":
        box = rng.choice(["e", "plucker", "phi"])
        v = np.asarray(key[box], float)
        r = np.vectorize(lambda x: float(f"{x:.1e}"))(v)
        if np.allclose(r, v, rtol=1e-3, atol=0):
            return out, expect                         # rounding changed nothing
        out[box], expect[box] = r.tolist(), "slip"
    return out, expect


def _class(tmp_path, n, seed):
    rng = random.Random(seed)
    names = [NAMES[k] if k < len(NAMES) else f"Student {k:02d}" for k in range(n)]
    roster = tmp_path / "roster.csv"
    with roster.open("w", newline="", encoding="utf-8-sig") as fh:
        w = csv.writer(fh, delimiter=";")
        w.writerow(["First name", "Surname", "ID number", "Email address"])
        for k, name in enumerate(names):
            first, _, last = name.partition(" ")
            w.writerow([first, last, f"s{3000 + k}", ""])
    (tmp_path / "quiz.toml").write_text(SPEC)
    assert main(["exam", str(tmp_path / "quiz.toml"), "--students", str(roster),
                 "--out", str(tmp_path / "c")]) == 0
    key = json.loads((tmp_path / "c" / "key.json").read_text(encoding="utf-8"))
    folder = tmp_path / "answers"
    folder.mkdir()
    expected, used, behaviours = {}, set(), {}
    for r in key["students"]:
        p = r["problems"][0]
        k = {a: _fl(p["answers"][a]) for a in p["asked"]}
        behaviour = rng.choice(BEHAVIOURS)
        ans, expect = _answers(rng, k, behaviour)
        duplicate = sum(x["student"] == r["student"] for x in key["students"]) > 1
        stem = r["id"] if duplicate else _file_name(rng, r["student"], r["id"])
        if stem in used:
            stem = r["id"]
        used.add(stem)
        (folder / f"{stem}.json").write_text(json.dumps({"P1": ans}, ensure_ascii=False),
                                             encoding="utf-8")
        expected[r["id"]] = expect
        behaviours[r["id"]] = (behaviour, ans)
    (folder / "broken.json").write_text("{not json")
    (folder / "Nobody Here.json").write_text(json.dumps({"P1": {}}))
    return key, expected, behaviours


def _grade_and_compare(tmp_path, key, expected, capsys):
    code = main(["grade", str(tmp_path / "c"), str(tmp_path / "answers")])
    err = capsys.readouterr().err
    assert code == 12, err                      # two files not graded, each on its line
    assert "broken.json: not graded" in err and "Nobody Here: not graded" in err
    rows = list(csv.DictReader((tmp_path / "c" / "grades.csv").open(encoding="utf-8-sig")))
    assert {r["id"] for r in rows} == {r["id"] for r in key["students"]}
    for r in rows:
        want = expected[r["id"]][r["answer"]]
        where = (r["student"], r["answer"], r["detail"])
        if want == "right":                     # 0 right answers graded wrong
            assert r["status"] == "right", where
        elif want == "missing":
            assert r["status"] == "missing" and r["note"].endswith("blank"), where
        else:                                   # every slip named, never full credit
            assert r["status"] == "wrong" and r["slip"], where
            assert float(r["points"]) < float(r["max_points"]), where
            credit = 0.75 if r["slip"] == "rounded" else 0.5    # the spec's policy
            assert float(r["points"]) == pytest.approx(credit * float(r["max_points"]),
                                                       rel=1e-4), where
    notes = list(csv.DictReader((tmp_path / "c" / "item_analysis.csv").open(encoding="utf-8-sig")))
    assert sum(int(n["count"]) for n in notes) == len(rows)
    return rows


def _cloze(xml_text: str, ident: str) -> list[list[list[tuple[float, float, float, int]]]]:
    """The Cloze parts of a student's problem 1, from Moodle's documented syntax
    ``{w:NUMERICAL:=value:tol~%n%value:tol}``: per box (a paragraph), per entry, the
    answers in order as (fraction, value, tol, w)."""
    import re

    q = xml_text.split(f"<idnumber>{ident}-P1</idnumber>")[0].rsplit("<question ", 1)[1]
    boxes = []
    for para in q.split("<p>"):
        parts = re.findall(r"\{(\d+):NUMERICAL:([^}]*)\}", para)
        if parts:
            boxes.append([[(100.0 if a.startswith("=") else float(a.split("%")[1]),
                            *map(float, a.lstrip("=").split("%")[-1].split(":")), int(w))
                           for a in re.split(r"~(?=%)", spec)] for w, spec in parts])
    return boxes


def _moodle_fraction(boxes, responses: list) -> float:
    """Moodle's Cloze mark of one question as a fraction: each part scores its weight
    times the first answer within tol (0 for a blank or none); a comma decimal is read as
    Moodle reads it in a comma locale."""
    got = total = 0.0
    for box, response in zip(boxes, responses, strict=True):
        flat = list(np.ravel(np.array(response, dtype=object))) if response != "" else []
        for k, answers in enumerate(box):
            total += answers[0][3]
            if k >= len(flat) or flat[k] in ("", None):
                continue
            x = float(str(flat[k]).replace(",", "."))
            got += answers[0][3] * next((f / 100 for f, v, tol, _ in answers
                                         if abs(x - v) <= tol), 0.0)
    return got / total


def _moodle_against_gradebook(tmp_path, key, rows, behaviours, expected) -> int:
    """Each student's Moodle mark (simulated from moodle.xml) against the gradebook's:
    equal for every student who answered every box as the key writes it or left it
    blank; returns how many students' grades differ (equivalent forms, slips, rounding:
    Moodle scores entry by entry, the gradebook box by box)."""
    xml_text = (tmp_path / "c" / "moodle.xml").read_text(encoding="utf-8")
    differ = 0
    for r in key["students"]:
        p = r["problems"][0]
        mine = [x for x in rows if x["id"] == r["id"]]
        book = sum(float(x["points"]) for x in mine) / sum(float(x["max_points"]) for x in mine)
        moodle = _moodle_fraction(_cloze(xml_text, r["id"]),
                                  [behaviours[r["id"]][1].get(a, "") for a in p["asked"]])
        behaviour = behaviours[r["id"]][0]
        as_written = behaviour in ("right", "blank") or behaviour == "rounded" and all(
            v == "right" for v in expected[r["id"]].values())   # rounding changed nothing
        if as_written:
            assert moodle == pytest.approx(book, abs=1e-9), (r["student"], moodle, book)
        else:                                   # a slip or an equivalent form in a box
            assert moodle < 1, (r["student"], behaviour)   # never full credit in Moodle
        differ += not moodle == pytest.approx(book, abs=1e-9)
    return differ


def _stack_against_gradebook(tmp_path, key, rows, behaviours) -> int:
    """Each student's mark in Moodle's STACK (stack.xml run by the independent reader of
    tests/_stack_maxima.py: its Maxima and its potential response trees) against the
    gradebook's: equal for every student, and each box's answer note the gradebook's
    status (right, blank, the slip's credit, rounded, wrong). The student types each
    number into STACK's boxes as written (a decimal comma retyped with a point, as
    STACK's validation asks). Returns how many students were compared."""
    from tests._stack_maxima import EMPTY, boxes, mark, question_tests, questions, run_maxima

    qs = questions((tmp_path / "c" / "stack.xml").read_text(encoding="utf-8"))
    for r in key["students"]:
        q = qs[f"{r['id']}-P1"]
        tests = question_tests(q)          # the question's own tests pass in the reader
        assert len(tests) >= 3 and all(ok for _, ok in tests), tests
        ta = run_maxima(q.findtext("questionvariables/text"), {})
        given = behaviours[r["id"]][1]
        responses = {}
        for box, (inp, kind) in boxes(q).items():
            v = given.get(box, "")
            if v == "" or v is None:
                responses[inp] = EMPTY
            elif kind == "matrix":          # the grid of the key's shape, entry by entry
                responses[inp] = np.array(_fl(v), dtype=float).reshape(ta[f"ta_{inp}"].shape)
            else:
                responses[inp] = float(str(v).replace(",", "."))
        got, notes = mark(q, responses)
        mine = [x for x in rows if x["id"] == r["id"]]
        book = sum(float(x["points"]) for x in mine) / sum(float(x["max_points"]) for x in mine)
        assert got == pytest.approx(book, abs=1e-5), (r["student"], got, book, notes)
        word = {"right": "right", "missing": "blank"}
        for x in mine:
            inp = boxes(q)[x["answer"]][0]
            want = word.get(x["status"]) or ("rounded" if x["slip"] == "rounded" else
                                             "slip" if x["slip"] else "wrong")
            assert notes[f"prt_{inp}"][1] == f"{x['answer']}: {want}", (r["student"], x)
    return len(key["students"])


# a class made, graded and exported; quick: test_grading_to_the_end.py::
# test_three_students_two_of_one_name_graded_to_the_end (a class to the gradebook) and
# test_lms_files_score_as_the_gradebook.py (Moodle and STACK score it as the gradebook)
@pytest.mark.slow
def test_a_class_of_four_graded_to_the_end(tmp_path, capsys):
    key, expected, behaviours = _class(tmp_path, 4, seed=1)
    rows = _grade_and_compare(tmp_path, key, expected, capsys)
    _moodle_against_gradebook(tmp_path, key, rows, behaviours, expected)
    assert _stack_against_gradebook(tmp_path, key, rows, behaviours) == 4
    handout = (tmp_path / "c" / "handouts" / "s3003.html").read_text(encoding="utf-8")
    assert "unit cube" not in handout and "0.1 %" in handout   # a cube of side 2; the tol
    assert (tmp_path / "c" / "keys" / "s3003.html").exists()
    assert "山田 太郎" in (tmp_path / "c" / "keys" / "s3003.html").read_text(encoding="utf-8")
    assert len({r["student"] for r in rows}) == 3         # two students named Amy Ames
    assert len({r["id"] for r in rows}) == 4


@pytest.mark.slow
def test_a_class_of_forty_graded_to_the_end(tmp_path, capsys):
    key, expected, behaviours = _class(tmp_path, 40, seed=2)
    rows = _grade_and_compare(tmp_path, key, expected, capsys)
    differ = _moodle_against_gradebook(tmp_path, key, rows, behaviours, expected)
    as_written = sum(b in ("right", "blank") for b, _ in behaviours.values())
    print(f"Moodle's Cloze mark differs from the gradebook's for {differ} of 40 students "
          f"({as_written} answered every box as written or blank)")
    assert differ <= 40 - as_written
    # STACK's trees grade linked boxes jointly: its mark is the gradebook's for all 40
    assert _stack_against_gradebook(tmp_path, key, rows, behaviours) == 40


def test_names_that_fold_alike_are_reported_not_guessed(tmp_path):
    from rigidsym.course.matching import fold, match_answers

    assert fold("Zoë_Müller") == fold("zoe muller") == "zoe muller"
    assert fold(unicodedata.normalize("NFD", "José Ñúñez")) == fold("Jose Nunez")
    students = [{"student": "Zoë Müller", "id": "1", "handout": "handouts/1.html"},
                {"student": "Zoe Muller", "id": "2", "handout": "handouts/2.html"},
                {"student": "Li Wei", "id": "3", "handout": "handouts/3.html"}]
    got, problems = match_answers([("zoe müller", {}), ("LI WEI", {}), ("2", {}),
                                   ("x", {"id": "1"})], students)
    assert set(got) == {0, 1, 2} and got[2][0] == "LI WEI" and got[0][0] == "x"
    assert len(problems) == 1 and "not guessed" in problems[0]


def _measured_31(rng, theta, axis, shift, side=2.0, places=6, bend=0.0):
    """3.1's vertices turned by Rodrigues' (axis, theta) and shifted, written to
    ``places`` decimals (one displaced vertex moved by ``bend`` m off the rigid motion)."""
    R = _rot(np.asarray(axis) / np.linalg.norm(axis), theta)
    P = {"A": np.zeros(3), "B": side * np.eye(3)[0], "D": side * np.eye(3)[1],
         "E": side * np.eye(3)[2]}
    data = {k: [int(round(x)) for x in v] for k, v in P.items()}   # exact: the cube
    for k, v in P.items():
        w = R @ v + shift + (bend * np.array([0, 0, 1.0]) if k == "E" else 0)
        data[f"{k}_prime"] = [f"{x:.{places}f}" for x in w]
    return R, data


def test_31_on_data_given_to_six_decimals_is_solved_with_its_residual(capsys):
    from rigidsym import exercises as ex

    rng = np.random.default_rng(3)
    for _ in range(3):
        axis, theta = rng.normal(size=3), float(rng.uniform(0.3, 2.8))
        R, data = _measured_31(rng, theta, axis, rng.normal(size=3))
        s = ex.solve("3.1", **data)
        assert s.status == "solved", s.reason
        Q = np.array(sp.N(s.answers["Q"], 17).tolist(), dtype=float)
        assert np.allclose(Q, R, atol=1e-5)
        assert 0 < float(s.answers["residual"]) < 1e-5
        e = np.array(sp.N(s.answers["e"], 17).tolist(), dtype=float).reshape(3)
        assert np.allclose(_rot(e, float(sp.N(s.answers["phi"]))), R, atol=1e-5)
    _, bent = _measured_31(rng, 1.0, [1, 0, 0], np.zeros(3), bend=1e-3)
    assert ex.solve("3.1", **bent).status == "ill-posed"          # 1 mm off: not rigid
    assert ex.solve("3.1", tol="0.01", **bent).status == "solved"   # within a stated tol
    args = [f"--set={k}={','.join(map(str, v))}" for k, v in bent.items()]
    assert main(["exercise", "3.1", "--tol", "0.01", *args]) == 0
    assert "residual" in capsys.readouterr().out


def test_moodles_cloze_scoring_of_a_one_number_box_is_the_gradebooks():
    """Moodle's Cloze scoring simulated from its documented syntax ({w:NUMERICAL:=right:tol
    ~%n%other:tol}: the first answer within its tol gives its percentage of w) on the
    export of 3.5's distance d, against rigidsym's grade of the same response with the
    policy's slip and rounding credits: equal for a right, a negated, a degrees-free
    wrong and a rounded answer."""
    import re

    from rigidsym import exercises as ex
    from rigidsym.course.exam import asked
    from rigidsym.course.exam_text import box_label
    from rigidsym.course.grading import grade
    from rigidsym.course.roster import moodle_xml
    from rigidsym.course.worked import solution_record

    s = ex.solve("3.5")
    rec = dict(solution_record(s), problem=1, weight=1, asked=asked(s),
               labels={a: box_label(s.id, a) for a in asked(s)})
    key = {"slip_credit": 0.5, "rounding_credit": 0.75,
           "students": [{"student": "Amy", "problems": [rec]}]}
    text = moodle_xml("q", key)
    part = re.search(r"\{(\d+):NUMERICAL:=([^}]*)\}", text.split("distance d")[-1]).group(2)
    answers = [(100.0, *a.split(":")) for a in [part.split("~")[0]]] + \
        [(float(m), v, t) for m, v, t in re.findall(r"~%(\d+)%([^:~]+):([^~]+)", part)]

    def moodle(response):
        for pct, value, tol in answers:
            if abs(response - float(value)) <= float(tol):
                return pct / 100
        return 0.0

    d = float(sp.N(s.answers["d"]))
    compared = 0
    rounded = [float(f"{d:.{n - 1}e}") for n in (1, 2)]      # written here, not read
    for response in (d, -d, d * 1.7, d + 0.5, *rounded, -rounded[1]):
        g = next(g for g in grade(s, {"d": response}) if g.name == "d")
        ours = 1.0 if g.correct else {"sign": 0.5, "rounded": 0.75}.get(g.slip, 0.0)
        if g.slip not in (None, "sign", "rounded"):
            continue                       # a slip Moodle's export does not list
        assert moodle(response) == ours, (response, g.detail)
        compared += 1
    assert compared >= 5


@pytest.mark.parametrize("sep", [",", ";", "\t"])
def test_rosters_and_answer_tables_as_spreadsheets_save_them(tmp_path, sep):
    from rigidsym.course.answers import read_answers
    from rigidsym.course.roster import read_roster

    (tmp_path / "moodle.csv").write_text(
        sep.join(["First name", "Surname", "ID number", "Email address"]) + "\n" +
        sep.join(["Zoë", "Müller", "7", "z@x.org"]) + "\n" +
        sep.join(["Amy", "Ames", "8", ""]) + "\n" + sep.join(["Amy", "Ames", "9", ""]) + "\n",
        encoding="utf-8-sig")
    got = read_roster(tmp_path / "moodle.csv")
    assert [(r["name"], r["id"]) for r in got] == [("Zoë Müller", "7"), ("Amy Ames", "8"),
                                                  ("Amy Ames", "9")]
    (tmp_path / "plain.csv").write_text(f"id{sep}name\n1{sep}Li Wei\n", encoding="utf-8-sig")
    assert read_roster(tmp_path / "plain.csv") == [{"name": "Li Wei", "id": "1", "email": ""}]
    (tmp_path / "twice.csv").write_text(f"name{sep}id\nA{sep}1\nA{sep}1\n")
    with pytest.raises(ValueError, match="twice"):
        read_roster(tmp_path / "twice.csv")
    (tmp_path / "a.csv").write_text(f"student{sep}P1.phi\nZoë Müller{sep}\"2,0944\"\n",
                                    encoding="utf-8-sig")
    assert read_answers(tmp_path / "a.csv") == {"Zoë Müller": {"P1.phi": "2,0944"}}


def _stack_question(ex_id: str):
    """One student's STACK question of ``ex_id`` on the book's data, the solution and
    its key as floats (answer name -> array)."""
    from rigidsym import exercises as ex
    from rigidsym.course.exam import asked
    from rigidsym.course.exam_text import box_label
    from rigidsym.course.stack_export import stack_xml
    from rigidsym.course.worked import solution_record
    from tests._stack_maxima import questions

    s = ex.solve(ex_id)
    rec = dict(solution_record(s), problem=1, weight=1, asked=asked(s),
               labels={a: box_label(s.id, a) for a in asked(s)})
    q = questions(stack_xml("q", {"slip_credit": 0.5, "rounding_credit": 0.75,
                                  "students": [{"student": "Amy", "id": "7",
                                                "problems": [rec]}]}))["7-P1"]
    k = {a: np.array(sp.N(v, 17).tolist(), dtype=float) if isinstance(v, sp.MatrixBase)
         else bool(v) if v in (sp.true, sp.false) else float(sp.N(v, 17))
         for a, v in s.answers.items() if a in asked(s)}
    return q, s, k


def _stack_equals_grade(q, s, k, forms) -> set:
    """Each form (box -> value over the key) scored by STACK's question and by grade():
    the same score per box; returns the answer notes seen."""
    from rigidsym.course.grading import grade
    from tests._stack_maxima import EMPTY, boxes, mark

    seen = set()
    for form in forms:
        answers = {**k, **form}
        got, notes = mark(q, {inp: answers[b] for b, (inp, _) in boxes(q).items()})
        graded = grade(s, {b: "" if isinstance(v, str) and v == EMPTY else
                           np.asarray(v).tolist() for b, v in answers.items()})
        ours = [1.0 if g.correct else 0.75 if g.slip == "rounded" else 0.5 if g.slip
                else 0.0 for g in graded]
        for g, score in zip(graded, ours, strict=True):
            inp = boxes(q)[g.name][0]
            assert notes[f"prt_{inp}"][0] == score, (form.keys(), g.name, g.note, notes)
            seen.add(notes[f"prt_{inp}"][1].split(": ")[-1])
        assert got == pytest.approx(sum(ours) / len(ours), abs=1e-12)
    return seen


def test_stack_grades_each_member_and_slip_of_31_as_the_gradebook():
    """3.1's STACK question (stack.xml) run by the independent reader, against rigidsym's
    grade of the same answers: members of the key's class made here by the group action
    ((e, phi) -> (-e, -phi) with the Plücker array negated, phi + 2 pi k), slips made here
    (transpose, one sign, degrees, order, mm for m), a blank box and a rounding: the
    same score per box, box by box."""
    from tests._stack_maxima import EMPTY

    q, s, k = _stack_question("3.1")
    e, phi, pl = k["e"], k["phi"], k["plucker"]
    forms = [
        {}, {"e": -e, "phi": -phi, "plucker": -pl}, {"phi": phi + 2 * math.pi},
        {"e": -e, "phi": 2 * math.pi - phi, "plucker": -pl},       # -phi + 2 pi
        {"Q": k["Q"].T}, {"e": -e}, {"phi": phi * 180 / math.pi},
        {"plucker": np.concatenate([pl[3:], pl[:3]])}, {"e": EMPTY, "plucker": -pl},
        {"phi": float(f"{phi:.1e}")}, {"intersection_x=0": k["intersection_x=0"] * 1000},
        {"e": -e, "phi": -phi}, {"plucker": pl * np.array([[1], [1], [1], [1], [1], [-1]])},
    ]
    assert _stack_equals_grade(q, s, k, forms) == {"right", "slip", "rounded", "blank"}
    from tests._stack_maxima import boxes, question_tests

    tests = question_tests(q)              # the key, all blank, each box negated alone
    assert [d for d, _ in tests][:2] == ["the key", "every box blank"]
    assert len(tests) == 2 + sum(bool(np.any(k[b])) for b in boxes(q))
    assert all(ok for _, ok in tests), tests


@pytest.mark.slow
def test_stack_grades_a_point_of_the_axis_and_its_slips_as_the_gradebook():
    """3.6's STACK question: the axis's point anywhere on the axis (p0 + t e, made here),
    with (-e, -phi) and the Plücker array negated, is right; the point scaled by 1000 (mm
    for m), off the axis, negated, and e's slips score as grade() scores them."""
    q, s, k = _stack_question("3.6")
    e, phi, p0, pl = k["e"], k["phi"], k["axis_point_p0"], k["axis_plucker"]
    forms = [{}, {"axis_point_p0": p0 + 0.37 * e}, {"axis_point_p0": p0 - 2.5 * e},
             {"e": -e, "phi": -phi, "axis_plucker": -pl, "axis_point_p0": p0 + 1.1 * e},
             {"axis_point_p0": p0 * 1000}, {"axis_point_p0": -p0},
             {"axis_point_p0": p0 + np.array([[0.0], [0.0], [0.01]])},
             {"e": -e}, {"phi": phi * 180 / math.pi}, {"Q": k["Q"].T}]
    assert {"right", "slip"} <= _stack_equals_grade(q, s, k, forms)


def test_stack_grades_truths_as_the_gradebook():
    """3.18's truth box in STACK (a boolean input): the key's truth right, the other one
    wrong, blank blank, as grade() scores them; the question's own tests pass."""
    from tests._stack_maxima import EMPTY, boxes, question_tests

    q, s, k = _stack_question("3.18")
    truths = [b for b in boxes(q) if boxes(q)[b][1] == "boolean"]
    assert truths
    forms = [{}, *[{b: not k[b]} for b in truths], *[{b: EMPTY} for b in truths]]
    assert _stack_equals_grade(q, s, k, forms) >= {"right", "wrong", "blank"}
    assert all(ok for _, ok in question_tests(q))


@pytest.mark.slow
def test_stack_grades_an_angle_modulo_pi_as_the_gradebook():
    """3.12's angles of its principal axes (defined modulo pi) in STACK: alpha + pi,
    alpha - 2 pi right; degrees, the sign, a rounding and alpha + pi/2 scored as grade()
    scores them, each exported box; the principal axes (each column up to its sign):
    columns negated right, transposed, in mm, rounded scored as grade() scores them."""
    from rigidsym.course.grading import grade
    from tests._stack_maxima import boxes, mark, question_tests

    q, s, k = _stack_question("3.12")
    bx = boxes(q)
    angles = [b for b in bx if "angle" in b]
    assert len(angles) == 2 and "wedge_principal_axes" in bx
    forms = [{}] + [{b: v} for b in angles for v in (
        k[b] + math.pi, k[b] - 2 * math.pi, k[b] * 180 / math.pi, -k[b],
        float(f"{k[b]:.1e}"), k[b] + math.pi / 2)]
    axes = k["wedge_principal_axes"]
    signs = np.array([-1.0, 1.0, -1.0])
    forms += [{"wedge_principal_axes": v} for v in (
        axes * signs, (axes * signs).T, axes * signs * 1000,
        np.vectorize(lambda x: float(f"{x:.1e}"))(axes * signs))]
    for form in forms:
        answers = {**k, **form}
        _, notes = mark(q, {inp: answers[b] for b, (inp, _) in bx.items()})
        graded = {g.name: g for g in grade(s, {b: np.asarray(v).tolist()
                                               for b, v in answers.items()})}
        for b, (inp, _) in bx.items():
            g = graded[b]
            score = 1.0 if g.correct else 0.75 if g.slip == "rounded" else \
                0.5 if g.slip else 0.0
            assert notes[f"prt_{inp}"][0] == score, (b, form.keys(), g.note, notes)
    assert all(ok for _, ok in question_tests(q))
