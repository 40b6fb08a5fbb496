"""The LMS files an instructor imports score as the gradebook, on a quiz of 3.5, 3.9,
3.16 and 3.20 (weights 2, 1, 1, 1.5) for a generated class.

Each student answers each box at random: right, blank, all zero, a constant, negated (a
sign slip), a length in mm, random truths and reasons. ``moodle.xml`` is scored by a Cloze
scorer written here from Moodle's documented syntax (``{w:NUMERICAL:=v:tol~%n%v:tol}``,
``{w:MULTICHOICE:=a~b}``, ``{w:SHORTANSWER:=a~=b}``: each part its weight times the
fraction of the first answer the response matches; the question's mark their weighted
mean), sharing no code with the exporter; ``stack.xml`` by the independent Maxima reader of
tests/_stack_maxima.py. STACK's mark equals the gradebook's for every student and problem;
Moodle's for every problem whose numeric boxes of several entries are right or blank
(Moodle scores such a box entry by entry: docs/exams.md), slips of one-number boxes,
truths and reasons included. Each question carries its problem's statement (the proofs'
statements, with their symbols defined), never a datum of internal numbering.
"""

from __future__ import annotations

import csv
import html
import json
import random
import re

import numpy as np
import pytest
import sympy as sp

from rigidsym.course import class_exam, grade_class

_SPEC = {"title": "Quiz 3", "seed": 11, "slip_credit": 0.5, "rounding_credit": 0.5,
         "problem": [{"exercise": "3.5", "variants": 1, "weight": 2},
                     {"exercise": "3.9", "variants": 1, "weight": 1},
                     {"exercise": "3.16", "variants": 1, "weight": 1},
                     {"exercise": "3.20", "variants": 1, "weight": 1.5}]}


def _f(text) -> np.ndarray:
    v = sp.sympify(text) if not isinstance(text, list) else None
    if isinstance(text, list):
        return np.array([_f(x) for x in text], dtype=float)
    return np.array(float(bool(v)) if v in (sp.true, sp.false) else float(v))


def _typed(a: np.ndarray) -> str:
    return ", ".join(repr(float(x)) for x in np.ravel(a))


def _answer(rng, name: str, key: np.ndarray):
    """A student's answer to one box, as typed (text), and what the test calls it."""
    if name == "holds":
        t = [rng.choice(("true", "false")) for _ in range(key.size)]
        if rng.random() < 0.4:
            t = ["true" if x else "false" for x in np.ravel(key) > 0.5]
        return ", ".join(t), "truths"
    if name == "why":
        r = [str(rng.randint(1, 4)) for _ in range(key.size)]
        if rng.random() < 0.4:
            r = [str(int(x)) for x in np.ravel(key)]
        return ", ".join(r), "reasons"
    how = rng.choice(("right", "blank", "zero", "constant", "negated", "mm"))
    value = {"right": key, "zero": np.zeros_like(key), "constant": np.full(key.shape, 2.5),
             "negated": -key, "mm": key * 1000}.get(how)
    return ("" if value is None else _typed(value)), how


def _class(tmp_path, n: int, seed: int):
    roster = tmp_path / "roster.csv"
    roster.write_bytes(("\ufeffname;id\r\n" + "".join(
        f"Student {k};{k:05d}\r\n" for k in range(n))).encode())
    class_exam(_SPEC, roster, tmp_path / "c")
    key = json.loads((tmp_path / "c" / "key.json").read_text(encoding="utf-8"))
    rng = random.Random(seed)
    given: dict = {}
    how: dict = {}
    for r in key["students"]:
        for p in r["problems"]:
            for a in p["asked"]:
                text, what = _answer(rng, a, _f(p["answers"][a]))
                given[(r["id"], p["problem"], a)] = text
                how[(r["id"], p["problem"], a)] = what
    cols = [f"P{p['problem']}.{a}" for p in key["students"][0]["problems"] for a in p["asked"]]
    with (tmp_path / "answers.csv").open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, delimiter=";")
        w.writerow(["student", "id", *cols])
        for r in key["students"]:
            w.writerow([r["student"], r["id"], *[given[(r["id"], int(c[1:c.index(".")]),
                                                        c[c.index(".") + 1:])]
                                                  for c in cols]])
    grade_class(tmp_path / "c", tmp_path / "answers.csv")
    rows = list(csv.DictReader((tmp_path / "c" / "grades.csv").open(encoding="utf-8-sig")))
    return key, given, how, rows


def _points(rows, ident, problem) -> float:
    mine = [x for x in rows if x["id"] == ident and int(x["problem"]) == problem]
    return sum(float(x["points"]) for x in mine)


# ---------------------------------------------------------------- Moodle, as documented
def _cloze_question(xml_text: str, ident: str) -> str:
    q = xml_text.split(f"<idnumber>{ident}</idnumber>")[0].rsplit("<question ", 1)[1]
    return html.unescape(q)


def _parts(question: str) -> list[tuple[str, list[tuple[str, int, str]]]]:
    """Per box paragraph: ``(label, [(type, weight, answers text), ...])``."""
    out = []
    for para in re.findall(r"<p>(.*?)</p>", question, re.S):
        parts = re.findall(r"\{(\d+):(NUMERICAL|MULTICHOICE|SHORTANSWER):([^}]*)\}", para)
        if parts:
            out.append((para.split(":")[0], [(t, int(w), a) for w, t, a in parts]))
    return out


def _fraction(kind: str, answers: str, response: str) -> float:
    if response.strip() == "":
        return 0.0
    for a in answers.split("~"):
        frac = 1.0 if a.startswith("=") else float(a.split("%")[1]) / 100 if \
            a.startswith("%") else 0.0
        body = a.lstrip("=")
        body = body.split("%", 2)[2] if body.startswith("%") else body
        if kind == "NUMERICAL":
            v, tol = (float(x) for x in body.split(":"))
            if abs(float(response) - v) <= tol:
                return frac
        elif body.strip().lower() == response.strip().lower():
            return frac
    return 0.0


def _moodle_mark(question: str, responses: list[str]) -> float:
    got = total = 0.0
    boxes = _parts(question)
    assert len(boxes) == len(responses)
    for (_, parts), response in zip(boxes, responses, strict=True):
        entries = [response] if parts[0][0] != "NUMERICAL" else \
            ([x.strip() for x in response.split(",")] if response else [""] * len(parts))
        for (kind, w, answers), r in zip(parts, entries, strict=True):
            total += w
            got += w * _fraction(kind, answers, r)
    return got / total


# ---------------------------------------------------------------- STACK, by the reader
def _stack_mark(q, ta: dict, given: dict) -> float:
    from tests._stack_maxima import EMPTY, boxes, mark

    responses = {}
    for box, (inp, kind) in boxes(q).items():
        text = given[box]
        if text == "":
            responses[inp] = EMPTY
            continue
        vals = [1.0 if x.strip() == "true" else 0.0 if x.strip() == "false" else float(x)
                for x in text.split(",")]
        responses[inp] = np.array(vals).reshape(ta[f"ta_{inp}"].shape) \
            if kind == "matrix" else vals[0]
    return mark(q, responses)[0]


def _check_class(tmp_path, n, seed) -> dict:
    from tests._stack_maxima import questions, run_maxima

    key, given, how, rows = _class(tmp_path, n, seed)
    moodle = (tmp_path / "c" / "moodle.xml").read_text(encoding="utf-8")
    stack = questions((tmp_path / "c" / "stack.xml").read_text(encoding="utf-8"))
    seen = {"moodle": 0, "stack": 0, "slip": 0}
    for r in key["students"]:
        for p in r["problems"]:
            ident = f"{r['id']}-P{p['problem']}"
            book = _points(rows, r["id"], p["problem"]) / p["weight"]
            mine = {a: given[(r["id"], p["problem"], a)] for a in p["asked"]}
            q = stack[ident]
            ta = run_maxima(q.findtext("questionvariables/text"), {})
            assert _stack_mark(q, ta, mine) == pytest.approx(book, abs=1e-6), (ident, mine)
            seen["stack"] += 1
            text = _cloze_question(moodle, ident)
            assert "statements = [" not in text and "statements =" not in text
            if p["id"] != "ex3.5":
                assert "Symbols:" in text and "(i)" in text, ident
            several = [a for a in p["asked"] if _f(p["answers"][a]).size > 1
                       and a not in ("holds", "why")]
            if all(how[(r["id"], p["problem"], a)] in ("right", "blank") for a in several):
                got = _moodle_mark(text, [mine[a] for a in p["asked"]])
                assert got == pytest.approx(book, abs=1e-6), (ident, mine, got, book)
                seen["moodle"] += 1
            seen["slip"] += any(x["slip"] for x in rows if x["id"] == r["id"]
                                and int(x["problem"]) == p["problem"])
    return seen


def test_moodle_and_stack_score_a_class_as_the_gradebook(tmp_path):
    seen = _check_class(tmp_path, 3, seed=4)
    assert seen["stack"] == 12 and seen["moodle"] >= 6 and seen["slip"] >= 1, seen


@pytest.mark.slow
def test_moodle_and_stack_score_a_class_of_24_as_the_gradebook(tmp_path):
    seen = _check_class(tmp_path, 24, seed=5)
    assert seen["stack"] == 96 and seen["moodle"] >= 48, seen
