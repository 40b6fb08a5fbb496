"""Grading a class from its exam folder: every student's answers against
the student's own key, a per-student, per-question CSV and a gradebook an LMS imports.

``grade_class(DIR, answers)`` reads ``DIR/key.json`` (written by
:func:`rigidsym.course.roster.class_exam`) and the answers (the filled ``answers.csv``: a
row per student, a column ``P<k>.<answer>`` per box; or a folder of ``<student>.json``
files ``{"P1.w_2": ...}``), read by the reader of ``--set``. It writes::

    DIR/grades.csv     a row per student and answer box: the problem, exercise, the box's
                       label, its weight, points and maximum, status (right, wrong,
                       missing, not graded), the slip named and the detail
    DIR/gradebook.csv  a row per student: id, email, the points of each problem and the
                       total (Moodle's grade import: map "ID number" or "Email address")

A box scores 1 when right, the spec's ``rounding_credit`` when rounded to fewer
significant figures than the tolerance asks (default: ``slip_credit``), the spec's
``slip_credit`` (default 0) when wrong by a named
slip, 0 when wrong otherwise or missing (blank or absent); a problem's points are its
``weight`` times the mean score of its boxes (partial credit). A student of the roster
whose answers no row or file matched is not graded: a line of the report, status ``not
graded`` in grades.csv and empty cells in gradebook.csv, never a zero.

Each student's grading is kept in the user cache, keyed by the student's key record, their
answers and the credits (and the digest of every source file): grading the class again
after one answer is fixed grades that student alone, and a grading interrupted goes on
from the students already graded. The slips along the way (the solution replayed with a
slip injected, :mod:`rigidsym.course.slips`) are tried only where the key's
``slips_along_the_way`` is true (the spec's policy, default true; a key without it, true);
their replays, the costly part of a wrong answer's judging, are then kept too
(:func:`rigidsym.course.grading.replayed_values`): those the class's STACK export solved
are read back.
"""

from __future__ import annotations

import csv
import functools
import io
import json
from pathlib import Path

import sympy as sp

from rigidsym.core.files import write_atomic
from rigidsym.course.worked import Solution, parameters, solve

__all__ = ["checked_weights", "grade_class", "key_value", "solution_of", "with_weights"]


def solution_of(rec: dict) -> Solution:
    """A key record's solution, rebuilt from its exact data and answers (no re-solve);
    a record of measured data (``tol`` set) is solved again, as the grader's slips read
    its steps."""
    if rec.get("tol") is not None:
        import dataclasses

        s = solve(rec["id"], tol=rec["tol"], **rec["data"])     # cached: copied, not changed
        return dataclasses.replace(s, answers={k: v for k, v in s.answers.items()
                                               if k in rec.get("asked", s.answers)})
    shapes = {p.name: p.shape for p in parameters(rec["id"])}
    data = {k: _value(v, shapes.get(k, ())) for k, v in rec["data"].items()}
    asked = rec.get("asked", list(rec["answers"]))
    answers = {k: _value(v, ()) for k, v in rec["answers"].items() if k in asked}
    return Solution(rec["id"], "", "", "", answers=answers, data=data, status="solved",
                    checks=[])


def _value(v, shape):
    if shape is None:                     # a choice (3.10's sequence): kept as text
        return v
    if isinstance(v, list):
        m = sp.Matrix([[key_value(x) for x in r] if isinstance(r, list) else
                       [key_value(r)] for r in v])
        return m
    return key_value(v)


@functools.lru_cache(maxsize=1 << 16, typed=True)   # typed: True and 1 read apart
def key_value(text: str | int | float | bool) -> sp.Basic:
    """One number of ``key.json`` (sympy's ``str`` of an exact value, as
    :func:`rigidsym.course.worked.to_json_value` writes it) read back: ``sympy.sympify``,
    kept (sympy values are immutable): a class's key is read by its Moodle and STACK
    exports and by the grader, the STACK export in workers forked after the Moodle export
    read it, and parsing a nested radical takes milliseconds.

    Raises:
        sympy.SympifyError: ``text`` is no expression.
    """
    return sp.sympify(text)


def _answers(path: str | Path, key: dict) -> tuple[dict[int, dict], list[str]]:
    """Students' answers by roster index, ``{i: {"P1.w_2": value}}``, and the report's
    lines: each answer set matched by student id, then by name (:mod:`.matching`); a file
    that cannot be read, matches no student or holds a box the exam does not have is a
    line of the report, and the class is still graded."""
    from rigidsym.course.answers import read_class_answers
    from rigidsym.course.matching import match_answers

    labelled, problems = read_class_answers(path)
    table = Path(path)
    # a CSV's data rows as a spreadsheet numbers them (the header is row 1)
    places = ([f"{label or 'a row with no name'} (row {k + 2} of {table.name})"
               for k, (label, _) in enumerate(labelled)] if table.suffix.lower() == ".csv"
              else None)
    matched, unmatched = match_answers(labelled, key["students"], places)
    problems += unmatched
    boxes = {f"P{p['problem']}.{a}" for r in key["students"] for p in r["problems"]
             for a in p["asked"]}
    out: dict[int, dict] = {}
    for i, (label, ans) in sorted(matched.items()):
        flat = {}
        for k, v in ans.items():
            if isinstance(v, dict):           # {"P1": {"w_2": ...}}
                flat.update({f"{k}.{a}": x for a, x in v.items()})
            elif k not in ("student", "name"):
                flat[k] = v
        bad = sorted(set(flat) - boxes)
        if bad:
            problems.append(f"{label}: not graded: {bad[0]!r} is no answer box of this exam "
                            f"(boxes are P<problem>.<answer>, as in answers.csv)")
            continue
        out[i] = flat
    return out, problems


def grade_class(out_dir: str | Path, answers: str | Path,
                weights: list[float] | None = None) -> dict:
    """Grade every student of the exam in ``out_dir`` on ``answers``; write the CSVs.

    Args:
        out_dir: the folder :func:`rigidsym.course.roster.class_exam` wrote.
        answers: the filled answers CSV, or a folder of one JSON file per student.
        weights: each problem's weight, in the problems' order (problem 1 first), in
            place of the spec's ``weight`` kept in ``key.json`` (which is not changed);
            default: the key's.

    Returns:
        ``{"grades": path, "gradebook": path, "table": str (a line per student),
        "all_right": bool (every box of every student right)}``.

    Raises:
        ValueError: no ``key.json`` in ``out_dir``, unreadable answers, a student not in
            the key, a column ``P<k>.<name>`` that is no box of the exam, or ``weights``
            not one finite number >= 0 per problem with a positive sum (the message names
            ``weights``).
    """
    folder = Path(out_dir)
    try:
        key = json.loads((folder / "key.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ValueError(f"DIR: cannot read {folder / 'key.json'} (write it with rigidsym "
                         f"exam SPEC --students ROSTER --out DIR): {exc}") from None
    if "students" not in key:
        raise ValueError(f"DIR: {folder / 'key.json'} is the key of a single exam; grade it "
                         f"with rigidsym exercise ID --grade")
    if weights is not None:
        key = with_weights(key, weights)
    given, problems = _answers(answers, key)
    credit = (float(key.get("slip_credit", 0)),
              float(key.get("rounding_credit", key.get("slip_credit", 0))))
    from rigidsym.course.forked import forked_map

    n_problems = max(len(r["problems"]) for r in key["students"])
    for i, r in enumerate(key["students"]):
        if i not in given:
            problems.append(f"{r['student']}" + (f" (id {r['id']})" if r.get("id") else "")
                            + ": not graded: no answer row or file matched this student alone "
                              "(their gradebook cells are left empty)")
    along = bool(key.get("slips_along_the_way", True))   # absent: a key of before the policy
    done = forked_map(lambda i: _student_kept(key["students"][i], given.get(i), credit,
                                              along), len(key["students"]))
    rows = [row for d in done for row in d[0]]
    book = [d[1] for d in done]
    lines = [d[2] for d in done]
    all_right = all(d[3] for d in done)
    grades = _csv([["student", "id", "version", "problem", "exercise", "answer", "label",
                    "max_points", "points", "status", "slip", "detail", "note"], *rows])
    gradebook = _csv([["ID number", "Email address", "Full name",
                       *[f"Problem {k}" for k in range(1, n_problems + 1)], "Total"], *book])
    return {"grades": write_atomic(folder / "grades.csv", grades),
            "gradebook": write_atomic(folder / "gradebook.csv", gradebook),
            "items": write_atomic(folder / "item_analysis.csv", _items(rows)),
            "table": f"{key['title']}: {len(key['students'])} students\n" + "\n".join(lines),
            "all_right": all_right, "problems": problems}


def with_weights(key: dict, weights: list[float]) -> dict:
    """The class key with each problem's ``weight`` replaced by ``weights[k - 1]`` (problem
    ``k``), for every student; ``key`` itself is not changed.

    Raises:
        ValueError: ``weights`` is not one finite number >= 0 per problem of the exam, or
            they are all 0 (the message names ``weights`` and the count expected).
    """
    w = checked_weights(weights, max(len(r["problems"]) for r in key["students"]))
    students = [{**r, "problems": [{**p, "weight": w[p["problem"] - 1]}
                                   for p in r["problems"]]} for r in key["students"]]
    return {**key, "students": students}


def checked_weights(weights: list[float], n: int) -> list[float]:
    """``weights`` as ``n`` floats, one per problem of an exam (problem 1 first): what
    ``rigidsym exam --weights`` and ``rigidsym grade --weights`` accept.

    Raises:
        ValueError: ``weights`` is not ``n`` finite numbers >= 0 (a text, a count other
            than ``n``, a negative, an infinite or a NaN entry), or every one is 0 (the
            message starts ``weights:`` and names the count expected).
    """
    import math

    try:
        if isinstance(weights, str | bytes):
            raise TypeError("a text")
        w = [float(x) for x in weights]
    except (TypeError, ValueError):
        raise ValueError(f"weights: expected {n} numbers, one per problem, not "
                         f"{weights!r}") from None
    if len(w) != n:
        raise ValueError(f"weights: expected {n} numbers, one per problem of the exam "
                         f"(problem 1 first), not {len(w)}")
    bad = [x for x in w if not math.isfinite(x) or x < 0]
    if bad:
        raise ValueError(f"weights: each weight must be a finite number >= 0, not {bad[0]!r}")
    if sum(w) <= 0:
        raise ValueError("weights: at least one weight must be positive (every weight is 0)")
    return w


def _items(rows: list) -> str:
    """Item analysis: how many boxes of each exercise got each answer note."""
    counts: dict[tuple, int] = {}
    for r in rows:
        ex_id, note = r[4], r[-1].split(": ", 1)[-1]
        counts[(ex_id, r[5], note)] = counts.get((ex_id, r[5], note), 0) + 1
    return _csv([["exercise", "answer", "note", "count"],
                 *[[*k, n] for k, n in sorted(counts.items(), key=lambda kv: (
                     [int(x) for x in kv[0][0].split(".")], kv[0][1], -kv[1]))]])


def _student_kept(r: dict, ans: dict | None, credit: tuple[float, float],
                  along: bool = True) -> tuple:
    """:func:`_student`, kept in the user cache by the student's key record, answers and
    credits (and every source file's digest): grading the class again after one answer
    is fixed, or after an interrupt, grades only the students whose answers changed or
    who were not graded yet."""
    import hashlib
    import pickle

    from rigidsym.core import cache as _cache
    from rigidsym.core import sources as _sources

    h = hashlib.sha256()
    for part in ("graded 1", _sources.package_digest(), _sources.environment(),
                 json.dumps([r, ans, list(credit), along], sort_keys=True, default=repr)):
        h.update(part.encode() + b"\0")
    key = h.hexdigest()
    where = _cache.folder("verdicts") / key[:2] / f"graded-{key}.pickle"
    blob = _cache.get(where)
    if blob is not None:
        try:
            kept = pickle.loads(blob)
        except Exception:  # noqa: BLE001 -- an entry of another version: graded again
            kept = None
        if isinstance(kept, tuple) and len(kept) == 4:
            return kept
    out = _student(r, ans, credit, along)
    _cache.put(where, pickle.dumps(out))
    return out


def _student(r: dict, ans: dict | None, credit: tuple[float, float],
             along: bool = True) -> tuple:
    """One student graded: (rows of grades.csv, the gradebook's row, the summary line,
    every box right); ``ans`` None: no answers matched, nothing graded (status ``not
    graded``, the gradebook's cells empty)."""
    from rigidsym.course.grading import grade

    if ans is None:
        rows = [[r["student"], r["id"], r["version"], p["problem"], p["id"][2:], a,
                 p["labels"].get(a, a), "", "", "not graded", "",
                 "no answers matched this student", f"{p['id'][2:]}/{a}: not graded"]
                for p in r["problems"] for a in p["asked"]]
        book = [r["id"], r["email"], r["student"], *["" for _ in r["problems"]], ""]
        return rows, book, f"  {r['student']:24s} not graded: no answers", False

    rows, per_problem, wrong, all_right = [], [], [], True
    for p in r["problems"]:
        k = p["problem"]
        mine = {a: ans.get(f"P{k}.{a}") for a in p["asked"]}
        graded = [g for g in grade(solution_of(p), mine, replay=along)
                  if g.correct is not None or g.note == "ambiguous"]
        share = p["weight"] / max(len(graded), 1)
        total = 0.0
        for g in graded:
            score = 1.0 if g.correct else credit[1] if g.slip == "rounded" else \
                credit[0] if g.slip else 0.0
            total += share * score
            status = "right" if g.correct else "missing" if g.missing else \
                "ambiguous" if g.correct is None else "wrong"
            all_right &= status == "right"
            if status != "right":
                wrong.append(f"P{k}.{g.name}: " + ((g.slip or status) if status == "wrong"
                                                   else status))
            rows.append([r["student"], r["id"], r["version"], k, p["id"][2:], g.name,
                         p["labels"].get(g.name, g.name), f"{share:.6g}",
                         f"{share * score:.6g}", status, g.slip or "", g.detail,
                         f"{p['id'][2:]}/{g.name}: {g.note}"])
        per_problem.append(total)
    book = [r["id"], r["email"], r["student"], *[f"{x:.4g}" for x in per_problem],
            f"{sum(per_problem):.4g}"]
    out_of = sum(p["weight"] for p in r["problems"])
    line = (f"  {r['student']:24s} {sum(per_problem):6.3g} / {out_of:<4g} "
            f"{'; '.join(wrong) or 'all right'}")
    return rows, book, line, all_right


def _csv(rows: list) -> str:
    """The rows as CSV text with a UTF-8 byte-order mark, so that Excel reads the names'
    accents right (Moodle's grade import and :func:`~.answers.read_table` skip it), and
    every cell quoted, so that an id such as ``00042`` is one text field to every CSV
    reader (Python's :mod:`csv`, Moodle's import, LibreOffice's "quoted field as text")."""
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n", quoting=csv.QUOTE_ALL).writerows(rows)
    return "\ufeff" + buf.getvalue()
