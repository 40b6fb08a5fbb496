"""``rigidsym exercise ID [--data DATA.json] --grade ANSWERS [--json]``: grade answers.

``ANSWERS`` is one student's JSON file ``{answer name: value}``; a folder of such files
(one per student, named by the file's stem); or a CSV file with a ``student`` column and
one column per answer name (a cell is a number, an exact string, or JSON nested lists).
One student prints a line per answer; a class prints one summary table (a row per
student: how many right, the slips named). ``--json`` prints (or writes to PATH)
``{"answers": [{"name", "correct", "slip", "expected", "detail"}]}`` for one student and
``{"students": [{"student", "answers": [...]}]}`` for a class.
"""

from __future__ import annotations

import csv
import json
import sys
from pathlib import Path

from rigidsym._io import write_atomic

__all__ = ["grade_command", "read_answers"]


def read_answers(path: str | Path) -> dict[str, dict]:
    """Students' answers: ``{student: {answer name: value}}`` from a JSON file (the
    student is its stem), a folder of them, or a CSV file.

    Raises:
        ValueError: a path that is missing or unreadable, a file that is not a JSON object,
            or a CSV without a ``student`` column (the message names the file).
    """
    p = Path(path)
    if p.is_dir():
        files = sorted(p.glob("*.json"))
        if not files:
            raise ValueError(f"--grade: no *.json answer files in the folder {p}")
        return {f.stem: _json_answers(f) for f in files}
    if p.suffix.lower() == ".csv":
        return _csv_answers(p)
    return {p.stem: _json_answers(p)}


def _json_answers(f: Path) -> dict:
    try:
        doc = json.loads(f.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ValueError(f"--grade: cannot read {f}: {exc}") from None
    if not isinstance(doc, dict):
        raise ValueError(f"--grade: expected a JSON object {{answer name: value}} in {f}")
    return doc


def _csv_answers(f: Path) -> dict[str, dict]:
    try:
        with f.open(newline="", encoding="utf-8") as fh:
            rows = list(csv.DictReader(fh))
    except (OSError, csv.Error, UnicodeDecodeError) as exc:
        raise ValueError(f"--grade: cannot read {f}: {exc}") from None
    if not rows or "student" not in rows[0]:
        raise ValueError(f"--grade: {f} needs a header row with a 'student' column and one "
                         f"column per answer name")
    out = {}
    for r in rows:
        who = r.pop("student")
        out[who] = {k: _cell(v) for k, v in r.items() if k and v not in ("", None)}
    return out


def _cell(text: str):
    t = text.strip()
    if t.startswith("["):
        try:
            return json.loads(t)
        except ValueError:
            return t
    return t


def grade_command(solution, path: str, json_target: str | None) -> int:
    """Grade the answers at ``path`` against ``solution``; print (or write) the result.
    Returns 0 (graded; wrong answers are the students', not an error)."""
    from rigidsym.exercises import grade

    students = read_answers(path)
    graded = {who: [g.as_dict() for g in grade(solution, ans)] for who, ans in
              students.items()}
    one = len(graded) == 1 and not Path(path).is_dir() and Path(path).suffix != ".csv"
    if json_target:
        doc = {"answers": next(iter(graded.values()))} if one else \
            {"students": [{"student": w, "answers": a} for w, a in graded.items()]}
        text = json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
        if json_target == "-":
            sys.stdout.write(text)
        else:
            write_atomic(json_target, text)
            print(f"wrote {json_target}")
        return 0
    if one:
        for g in next(iter(graded.values())):
            mark = {True: "right", False: "WRONG", None: "not graded"}[g["correct"]]
            slip = f" [slip: {g['slip']}]" if g["slip"] else ""
            print(f"  {g['name']:28s} {mark}{slip}: {g['detail']}")
        return 0
    print(_table(solution.id, graded))
    return 0


def _table(ex_id: str, graded: dict) -> str:
    """The class summary: a row per student, how many right, and the slips named."""
    names = sorted({g["name"] for gs in graded.values() for g in gs})
    width = max([len("student")] + [len(w) for w in graded])
    lines = [f"Exercise {ex_id[2:]}: {len(graded)} students, answers "
             f"{', '.join(names)}", f"  {'student':{width}s}  right  slips"]
    counts: dict[str, int] = {}
    for who, gs in graded.items():
        right = sum(g["correct"] is True for g in gs)
        slips = [f"{g['name']}: {g['slip'] or 'not a known slip'}" for g in gs
                 if g["correct"] is False]
        for g in gs:
            if g["correct"] is False:
                counts[g["slip"] or "not a known slip"] = counts.get(
                    g["slip"] or "not a known slip", 0) + 1
        lines.append(f"  {who:{width}s}  {right:>2d}/{len(gs):<2d}  {'; '.join(slips) or '-'}")
    if counts:
        lines.append("  slips in the class: " + ", ".join(
            f"{k} {v}" for k, v in sorted(counts.items(), key=lambda kv: -kv[1])))
    return "\n".join(lines)
