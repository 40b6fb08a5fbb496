"""A class graded to the end against an independent NumPy grader: every valid answer
right, every planted slip named, every student graded (two of one name, told apart by
id), and the LMS's grade equal to the gradebook's.

The class takes 3.2, 3.4, 3.6, 3.12 (weight 2) and 3.14, each student on drawn data. Each
box is answered with a member of its class of right answers, generated here from the
mathematics: (e, phi) or (-e, -phi) with the Plücker array's sign following e, plus
whole turns; any point of the screw axis; principal axes each with either sign, the
axis angle modulo pi; any rotation R with R [I]_A R^T = [I]_B (built from the
eigenvectors of both matrices); a truth typed as a word. Or it is left blank, slipped
(negated, or given in mm for m), or rounded to 2 significant figures. The test decides
each box's status and the gradebook's points itself, with no code of
``rigidsym.course`` past the files it reads (key.json, grades.csv, gradebook.csv,
stack.xml); the LMS's marks are computed from stack.xml by the independent reader of
tests/_stack_maxima.py and from gradebook.csv as Moodle's grade import reads it.
The default run grades three students on 3.14 and 3.6; a class of fifteen runs under ``slow``.
"""

from __future__ import annotations

import csv
import json
import math
import random

import numpy as np
import pytest
import sympy as sp

from rigidsym.cli import main

RTOL = 1e-3          # the documented tolerance: 0.1 % of the key's largest entry
SLIP, ROUNDING = 0.5, 0.25
BEHAVIOURS = ("right", "right", "right", "blank", "slip", "rounded")
#: the class of each declared box, as the exercises' statements give it
SIGN_GROUP = {"ex3.6": ("e", "phi", "axis_plucker")}
POINT_OF_AXIS = {"ex3.6": ("axis_point_p0", "e")}
ROTATION = {"ex3.14": ("Q_B_A", "I_A", "I_B")}
UNITS_M = {"ex3.2": ("P",), "ex3.6": ("axis_point_p0",)}


def _spec(problems) -> str:
    # the test's own grader names the final answer's slips; slips along the way (replays of
    # each student's solution) are tests/test_slips_along_the_way.py's
    out = [f'title = "Class"\nseed = 4\nslip_credit = {SLIP}\nrounding_credit = {ROUNDING}\n'
           'slips_along_the_way = false']
    for ex_id, weight in problems:
        out.append(f'[[problem]]\nexercise = "{ex_id}"\nvariants = 1\nweight = {weight}')
    return "\n".join(out) + "\n"


def _num(v):
    """A key.json value (sympy's text) as floats, NumPy; a truth as True or False."""
    if isinstance(v, list):
        return np.array([_num(x) for x in v], dtype=float)
    e = sp.sympify(v)
    if e in (sp.true, sp.false):
        return bool(e)
    return float(sp.N(e, 17))


def _near(a, b, scale):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= RTOL * scale + 1e-12))


def _scale(k):
    return max(float(np.max(np.abs(k))), 1e-300)


def _rotations(ia, ib):
    """Every R with R ia R^T = ib (distinct eigenvalues): V_b S V_a^T, det +1."""
    _, va = np.linalg.eigh(ia)
    _, vb = np.linalg.eigh(ib)
    out = []
    for s in np.array(np.meshgrid([1, -1], [1, -1], [1, -1])).T.reshape(-1, 3):
        r = vb @ np.diag(s) @ va.T
        if np.linalg.det(r) > 0:
            out.append(r)
    return out


def _members(rng, ex_id, key, data):
    """A member of each box's class (name -> array or truth), drawn from the mathematics."""
    out = dict(key)
    if ex_id in SIGN_GROUP:
        e, phi, pl = SIGN_GROUP[ex_id]
        s = rng.choice((1.0, -1.0))
        out[e], out[pl] = s * key[e], s * key[pl]
        out[phi] = s * key[phi] + 2 * math.pi * rng.randint(-1, 1)
    if ex_id in POINT_OF_AXIS:
        p, d = POINT_OF_AXIS[ex_id]
        u = key[d].reshape(-1) / np.linalg.norm(key[d])
        out[p] = key[p] + rng.uniform(-2, 2) * u.reshape(key[p].shape)
    if ex_id == "ex3.12":
        for tag in ("wedge", "upper"):
            signs = np.array([rng.choice((1.0, -1.0)) for _ in range(3)])
            out[f"{tag}_principal_axes"] = key[f"{tag}_principal_axes"] * signs
            out[f"{tag}_axis_angle_from_y_rad"] = key[f"{tag}_axis_angle_from_y_rad"] + \
                math.pi * rng.randint(-1, 1)
    if ex_id in ROTATION:
        q, a, b = ROTATION[ex_id]
        out[q] = rng.choice(_rotations(data[a], data[b]))
    return out


def _in_class(ex_id, name, value, member, key, data):
    """Whether ``value`` for box ``name`` is right (the group's sign as ``member``'s)."""
    k = key[name]
    sc = _scale(k)
    if ex_id in SIGN_GROUP and name in SIGN_GROUP[ex_id]:
        e, phi, _ = SIGN_GROUP[ex_id]
        s = 1.0 if _near(member[e], key[e], 1.0) else -1.0
        if name == phi:
            w = (value - s * k + math.pi) % (2 * math.pi) - math.pi
            return _near(w, 0.0, sc)
        return _near(value, s * k, sc)
    if name == POINT_OF_AXIS.get(ex_id, ("",))[0]:
        d = key[POINT_OF_AXIS[ex_id][1]].reshape(-1)
        off = np.cross((value - k).reshape(-1), d / np.linalg.norm(d))
        return _near(off, np.zeros(3), sc)
    if name.endswith("_principal_axes"):
        return all(_near(value[:, j], k[:, j], sc) or _near(value[:, j], -k[:, j], sc)
                   for j in range(3))
    if name.endswith("_axis_angle_from_y_rad"):
        return _near((value - k + math.pi / 2) % math.pi - math.pi / 2, 0.0, sc)
    if name == ROTATION.get(ex_id, ("",))[0]:
        return any(_near(value, r, 1.0) for r in _rotations(*(data[x] for x in
                                                               ROTATION[ex_id][1:])))
    return _near(value, k, sc)


def _typed(v):
    """A value as a student types it in the answers CSV: a number, or rows ';' entries ','."""
    if isinstance(v, bool):
        return "true" if v else "false"
    a = np.asarray(v, dtype=float)
    if a.ndim == 0:
        return repr(float(a))
    if a.ndim == 2 and 1 not in a.shape:
        return "; ".join(", ".join(repr(float(x)) for x in r) for r in a)
    return ", ".join(repr(float(x)) for x in a.reshape(-1))


def _answer(rng, ex_id, name, member, key, data):
    """(what the student types, the expected status, the score, the value typed: an
    array, or None for a blank or a truth) for one box."""
    v, behaviour = member[name], rng.choice(BEHAVIOURS)
    if behaviour == "blank":
        return "", "missing", 0.0, None
    if isinstance(v, bool):
        if behaviour == "right":
            return _typed(v), "right", 1.0, None
        return _typed(not v), "wrong", 0.0, None
    if behaviour == "rounded":
        r = np.vectorize(lambda x: float(f"{x:.1e}"))(v)
        declared = ex_id in SIGN_GROUP or ex_id in POINT_OF_AXIS or ex_id in ROTATION or \
            ex_id == "ex3.12"
        if _in_class(ex_id, name, r, member, key, data):
            return _typed(r), "right", 1.0, r
        if not declared and np.any(v != 0):
            return _typed(r), "rounded", ROUNDING, r
        behaviour = "slip"
    if behaviour == "slip" and np.any(v != 0):
        unit = name in UNITS_M.get(ex_id, ())
        edited = v * 1000.0 if unit else -v
        if not _in_class(ex_id, name, edited, member, key, data):
            return _typed(edited), "slip", SLIP, edited
    return _typed(v), "right", 1.0, v


def _sign_group(ex_id, got, key):
    """A sign group judged jointly, as the documented rule says: the group's sign is the
    one under which most of the typed pieces are right (the key's on a tie); a piece
    right only under the other sign is that sign's slip. ``got``: name -> (text,
    status, score, value), changed in place."""
    e, phi, pl = SIGN_GROUP[ex_id]

    def right(n, value, s):
        k = key[n]
        if n == phi:
            return _near((value - s * k + math.pi) % (2 * math.pi) - math.pi, 0.0, _scale(k))
        return _near(value, s * k, _scale(k))

    typed = {n: got[n][3] for n in (e, phi, pl) if got[n][3] is not None}
    count = {s: sum(right(n, v, s) for n, v in typed.items()) for s in (1.0, -1.0)}
    s = -1.0 if count[-1.0] > count[1.0] else 1.0
    for n, v in typed.items():
        if right(n, v, s):
            got[n] = (got[n][0], "right", 1.0, v)
        elif right(n, v, -s):
            got[n] = (got[n][0], "slip", SLIP, v)       # -(s k): the sign slip


def _make_class(tmp_path, problems, names):
    (tmp_path / "quiz.toml").write_text(_spec(problems))
    roster = tmp_path / "roster.csv"
    with roster.open("w", newline="", encoding="utf-8-sig") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "id", "email"])
        w.writerows([n, f"{k:05d}", ""] for k, n in enumerate(names))
    assert main(["exam", str(tmp_path / "quiz.toml"), "--students", str(roster),
                 "--out", str(tmp_path / "c")]) == 0
    return json.loads((tmp_path / "c" / "key.json").read_text(encoding="utf-8"))


def _answer_class(tmp_path, key, seed):
    """The answers CSV (the template's columns: student, id, P<k>.<box>) and, per student
    id and box, the expected (status, score); per id, the typed values by box."""
    rng = random.Random(seed)
    with (tmp_path / "c" / "answers.csv").open(encoding="utf-8-sig") as fh:
        header = next(csv.reader(fh))
    assert header[:2] == ["student", "id"]
    rows, expected, typed = [header], {}, {}
    for r in key["students"]:
        cells = {}
        for p in r["problems"]:
            k = {a: _num(p["answers"][a]) for a in p["asked"]}
            data = {n: np.array(_num(v), dtype=float) for n, v in p["data"].items()
                    if isinstance(v, list)}
            member = _members(rng, p["id"], k, data)
            got = {a: _answer(rng, p["id"], a, member, k, data) for a in p["asked"]}
            if p["id"] in SIGN_GROUP:
                _sign_group(p["id"], got, k)
            for a, (text, status, score, _) in got.items():
                cells[f"P{p['problem']}.{a}"] = text
                expected[(r["id"], p["problem"], a)] = (status, score)
        typed[r["id"]] = cells
        rows.append([r["student"], r["id"]] + [cells.get(c, "") for c in header[2:]])
    with (tmp_path / "answers.csv").open("w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows(rows)
    return expected, typed


def _check_grades(tmp_path, key, expected):
    """grades.csv against the test's statuses; gradebook.csv against the test's points."""
    rows = list(csv.DictReader((tmp_path / "c" / "grades.csv").open(encoding="utf-8-sig")))
    assert len(rows) == len(expected)
    for x in rows:
        status, score = expected[(x["id"], int(x["problem"]), x["answer"])]
        where = (x["student"], x["id"], x["exercise"], x["answer"], x["detail"])
        if status in ("slip", "rounded"):
            assert x["status"] == "wrong" and (x["slip"] == "rounded") == \
                (status == "rounded") and x["slip"], where
        else:
            assert x["status"] == status, where
        assert float(x["points"]) == pytest.approx(score * float(x["max_points"]),
                                                   rel=1e-5, abs=1e-9), where   # 6 digits
    book = {r["ID number"]: r for r in
            csv.DictReader((tmp_path / "c" / "gradebook.csv").open(encoding="utf-8-sig"))}
    assert set(book) == {r["id"] for r in key["students"]}
    for r in key["students"]:
        total = 0.0
        for p in r["problems"]:
            scores = [expected[(r["id"], p["problem"], a)][1] for a in p["asked"]]
            mine = p["weight"] * sum(scores) / len(scores)
            assert float(book[r["id"]][f"Problem {p['problem']}"]) == \
                pytest.approx(mine, abs=1e-3), (r["student"], p["id"])
            total += mine
        assert float(book[r["id"]]["Total"]) == pytest.approx(total, abs=1e-3)
    return rows, book


def _lms_against_gradebook(tmp_path, key, book, typed) -> int:
    """Each student's mark in the LMS: STACK's (stack.xml, read by tests/_stack_maxima.py)
    for each problem, and Moodle's grade import of gradebook.csv (the "ID number"
    column mapped, each "Problem k" column a grade item): both the gradebook's."""
    from tests._stack_maxima import EMPTY, boxes, mark, questions, run_maxima

    qs = questions((tmp_path / "c" / "stack.xml").read_text(encoding="utf-8"))
    compared = 0
    for r in key["students"]:
        for p in r["problems"]:
            q = qs[f"{r['id']}-P{p['problem']}"]
            ta = run_maxima(q.findtext("questionvariables/text"), {})
            responses = {}
            for box, (inp, kind) in boxes(q).items():
                text = typed[r["id"]].get(f"P{p['problem']}.{box}", "")
                if text == "":
                    responses[inp] = EMPTY
                elif kind == "boolean":
                    responses[inp] = text == "true"
                elif kind == "matrix":
                    vals = [float(x) for row in text.split(";") for x in row.split(",")]
                    responses[inp] = np.array(vals).reshape(ta[f"ta_{inp}"].shape)
                else:
                    responses[inp] = float(text)
            assert len(boxes(q)) == len(p["asked"]), (p["id"], q.findtext("questiontext"))
            got, notes = mark(q, responses)
            want = float(book[r["id"]][f"Problem {p['problem']}"]) / p["weight"]
            assert got == pytest.approx(want, abs=1e-3), (r["student"], p["id"], notes)
        compared += 1
    return compared


def _run(tmp_path, problems, names, seed, capsys):
    key = _make_class(tmp_path, problems, names)
    expected, typed = _answer_class(tmp_path, key, seed)
    capsys.readouterr()
    code = main(["grade", str(tmp_path / "c"), str(tmp_path / "answers.csv")])
    err = capsys.readouterr().err
    assert code in (0, 1), err                 # every student graded, none left out
    rows, book = _check_grades(tmp_path, key, expected)
    assert _lms_against_gradebook(tmp_path, key, book, typed) == len(names)
    return key, rows


def test_three_students_two_of_one_name_graded_to_the_end(tmp_path, capsys):
    key, rows = _run(tmp_path, [("3.14", 1)], ["María García", "María García", "Zoë Müller"],
                     seed=2, capsys=capsys)
    assert {x["id"] for x in rows} == {"00000", "00001", "00002"}
    notes = [x["note"] for x in rows]
    assert any("equivalent" in n for n in notes), notes    # another rotation, right


@pytest.mark.slow
def test_a_class_graded_to_the_end(tmp_path, capsys):
    """Eight students (two of one name, accented, Greek and Vietnamese names), five
    problems: the exam's cost grows with the class (the solves and figures of each
    student), so eight keep the slow run's share near a minute; the quick run grades three, and
    tests/test_course_class.py makes and grades a class of thirty."""
    names = ["María García", "María García", "Zoë Müller", "Nguyễn Văn An",
             "Αλέξανδρος Παπαδόπουλος"] + [f"Student {k:02d}" for k in range(3)]
    key, rows = _run(tmp_path, [("3.2", 1), ("3.4", 1), ("3.6", 1), ("3.12", 2), ("3.14", 1)],
                     names, seed=5, capsys=capsys)
    for k in range(5):       # every student's own data
        assert len({json.dumps(r["problems"][k]["data"], sort_keys=True)
                    for r in key["students"]}) == len(names)
    for r in key["students"]:
        p = r["problems"][4]
        assert p["data"]["I_A"] != p["data"]["I_B"]


@pytest.mark.slow      # a class of thirty made and graded: about 90 s of CPU
def test_a_class_of_thirty_the_lms_marks_as_the_gradebook(tmp_path, capsys):
    """Thirty students on the five problems (the spec sets no slips along the way), each
    box a member of its class, blank, slipped or rounded: the gradebook is
    the test's own grader's, and STACK's mark of every problem of every student (stack.xml
    read by the independent reader) and Moodle's import of gradebook.csv are the
    gradebook's, 30 of 30."""
    names = ["María García", "María García", "Zoë Müller", "Nguyễn Văn An",
             "Αλέξανδρος Παπαδόπουλος"] + [f"Student {k:02d}" for k in range(25)]
    key, rows = _run(tmp_path, [("3.2", 1), ("3.4", 1), ("3.6", 1), ("3.12", 2), ("3.14", 1)],
                     names, seed=6, capsys=capsys)
    assert len(key["students"]) == 30 and key["slips_along_the_way"] is False
    assert {x["status"] for x in rows} >= {"right", "wrong", "missing"}


def test_rows_of_one_name_are_two_students_or_a_stated_refusal(tmp_path):
    """Two CSV rows of one name: told apart by their id cells (an id without its leading
    zeros, as a spreadsheet writes it, included); without ids, each row is refused
    with a line naming the roster's ids, never merged into one student."""
    from rigidsym.course.answers import read_class_answers
    from rigidsym.course.matching import match_answers

    students = [{"student": "María García", "id": "00007"},
                {"student": "María García", "id": "00012"},
                {"student": "Zoë Müller", "id": "00013"}]
    table = tmp_path / "a.csv"
    table.write_text("student,id,P1.x\nMaría García,00012,1\nMaría García,7,2\n"
                     "Zoë Müller,,3\n", encoding="utf-8")
    labelled, problems = read_class_answers(table)
    assert len(labelled) == 3 and not problems
    got, problems = match_answers(labelled, students)
    assert not problems
    assert (got[1][1]["P1.x"], got[0][1]["P1.x"], got[2][1]["P1.x"]) == ("1", "2", "3")
    table.write_text("student,P1.x\nMaría García,1\nMaría García,2\n", encoding="utf-8")
    got, problems = match_answers(read_class_answers(table)[0], students)
    assert not got and len(problems) == 2
    assert all("00007" in p and "00012" in p for p in problems)


def test_moodles_cloze_scores_a_truth_typed_as_labelled():
    """A true-or-false box in moodle.xml is a Cloze MULTICHOICE of the two words its
    label names: Moodle's mark (the chosen option's fraction, "=" the right one) for
    `true` and `false` is the gradebook's for the same word."""
    import re

    from rigidsym import exercises as ex
    from rigidsym.course.exam import asked
    from rigidsym.course.exam_text import box_label
    from rigidsym.course.grading import grade
    from rigidsym.course.roster import moodle_xml
    from rigidsym.course.worked import solution_record

    s = ex.solve("3.14")
    rec = dict(solution_record(s), problem=1, weight=1, asked=asked(s),
               labels={a: box_label(s.id, a) for a in asked(s)})
    text = moodle_xml("q", {"students": [{"student": "Amy", "problems": [rec]}]})
    para = text.split("acceptable?")[1].split("</p>")[0]
    options = re.search(r"\{\d+:MULTICHOICE:([^}]*)\}", para).group(1).split("~")
    for word in ("true", "false"):
        moodle = 1.0 if f"={word}" in options else 0.0
        assert word in options or f"={word}" in options
        g = next(g for g in grade(s, {"acceptable": word}) if g.name == "acceptable")
        assert moodle == (1.0 if g.correct else 0.0), (word, options)
