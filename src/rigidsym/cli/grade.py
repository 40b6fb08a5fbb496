"""Grading on the command line: ``rigidsym grade DIR ANSWERS`` (a class, each student
against their own exam: :func:`run`) and ``rigidsym exercise ID [--data DATA.json] --grade
ANSWERS [--json]`` (one exercise's answers: :func:`grade_command`, which the exercise
command calls).

``ANSWERS`` is one student's JSON file ``{answer name: value}``; a folder of such files
(one per student, named by the file's stem); or a CSV file with a ``student`` column and
one column per answer name (a cell is a number, an exact string, or JSON nested lists).
One student prints a line per answer; a class prints one summary table (a row per
student: how many right, the slips named). ``--json`` prints (or writes to PATH)
``{"answers": [{"name", "correct", "slip", "expected", "detail"}]}`` for one student and
``{"students": [{"student", "answers": [...]}]}`` for a class. Every answer the
exercise asks is graded: one left out or blank is missing (and wrong). Exit 0 when every
answer of every student is right, 1 when any is wrong or missing, 2 bad input; ``rigidsym
grade`` exits 10 + n when n answer files were not graded (each reported on its own line:
unreadable, of no student of the roster, of two; the rest of the class is graded).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from rigidsym.core.files import write_atomic

__all__ = ["grade_command", "parse_weights", "read_answers", "add_arguments", "run", "HELP",
           "EXAMPLES"]

HELP = "grade a class: each student's answers against their own exam"
EXAMPLES = """\
  rigidsym grade class/ class/answers.csv    grades.csv and gradebook.csv in class/
  rigidsym grade class/ answers/             a folder of <id or name>.json answer files
  rigidsym grade class/ answers.csv --weights 1,1,1,2,1   other weights than the spec's
  (class/ as rigidsym exam SPEC --students roster.csv --out class/ wrote it)"""


def add_arguments(p) -> None:
    """Arguments of ``rigidsym grade``."""
    p.add_argument("dir", metavar="DIR", help="the class's exam folder (its key.json)")
    p.add_argument("answers", metavar="ANSWERS",
                   help="the filled answers CSV (a row per student, a column P<k>.<answer> "
                        "per box, as DIR/answers.csv) or a folder of <student>.json files")
    p.add_argument("--weights", metavar="W1,W2,...",
                   help="each problem's weight, comma separated, problem 1 first (e.g. "
                        "1,1,1,2,1), in place of the spec's weights kept in DIR/key.json "
                        "(the key is not changed)")


def run(args) -> int:
    """Grade the class: 0 every answer right, 1 any wrong or missing, 2 bad input, 3 a
    defect, 10 + n (at most 99) when n answer files or rows were not graded (each
    reported on its own line; the rest of the class is graded). Writes DIR/grades.csv,
    DIR/gradebook.csv and DIR/item_analysis.csv and prints a line per student."""
    from rigidsym.core import interrupts
    from rigidsym.course import grade_class

    try:
        done = grade_class(args.dir, args.answers, weights=parse_weights(args.weights))
    except (ValueError, TypeError) as exc:
        if interrupts.received():
            raise           # the interrupt in another form: rigidsym.cli.main says it
        print(f"rigidsym: error: {exc} (docs/exams.md describes the files)", file=sys.stderr)
        return 2
    except Exception as exc:  # noqa: BLE001 - a defect, never the code of a grade
        if interrupts.received():
            raise           # a worker pool cut short by Ctrl-C: rigidsym.cli.main says it
        print(f"rigidsym: internal error, please report: {type(exc).__name__}: {exc}",
              file=sys.stderr)
        return 3
    print(done["table"])
    print(f"wrote {done['grades']}\nwrote {done['gradebook']}\nwrote {done['items']}")
    for line in done["problems"]:
        print(f"rigidsym: {line}", file=sys.stderr)
    if done["problems"]:
        print(f"rigidsym: {len(done['problems'])} answer file(s) or row(s) not graded "
              f"(listed above); the rest of the class is graded", file=sys.stderr)
        return min(10 + len(done["problems"]), 99)
    return 0 if done["all_right"] else 1


def parse_weights(text: str | None) -> list[float] | None:
    """``--weights``'s text (``"1,1,2"``) as numbers; None when not given.

    Raises:
        ValueError: an entry that is not a number (the message names ``--weights``).
    """
    if text is None:
        return None
    out = []
    for part in text.split(","):
        try:
            out.append(float(part))
        except ValueError:
            raise ValueError(f"--weights: expected numbers separated by commas (1,1,2), "
                             f"not {part.strip()!r} in {text!r}") from None
    return out


def read_answers(path: str | Path) -> dict[str, dict]:
    """Students' answers, ``{student: {answer name: value}}``: as
    :func:`rigidsym.course.answers.read_answers` (imported when asked for)."""
    from rigidsym.course import read_answers as read

    return read(path)


def grade_command(solution, path: str, json_target: str | None) -> int:
    """Grade the answers at ``path`` against ``solution``; print (or write) the result.
    Returns 0 when every answer is right, 1 when any is wrong or missing (a script or a CI
    job can tell), after printing the grades either way."""
    from rigidsym.course import grade

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
        return _code(graded)
    if one:
        for g in next(iter(graded.values())):
            mark = "MISSING" if g["missing"] else \
                {True: "right", False: "WRONG", None: "not graded"}[g["correct"]]
            slip = f" [slip: {g['slip']}]" if g["slip"] else ""
            print(f"  {g['name']:28s} {mark}{slip}: {g['detail']}")
        return _code(graded)
    print(_table(solution.id, graded))
    return _code(graded)


def _code(graded: dict) -> int:
    """0 every answer right (or not graded by machine), 1 any wrong or missing."""
    return int(any(g["correct"] is False for gs in graded.values() for g in gs))


def _table(ex_id: str, graded: dict) -> str:
    """The class summary: a row per student, how many right, and the slips named."""
    names = sorted({g["name"] for gs in graded.values() for g in gs})
    width = max([len("student")] + [len(w) for w in graded])
    lines = [f"Exercise {ex_id[2:]}: {len(graded)} students, answers "
             f"{', '.join(names)}", f"  {'student':{width}s}  right  slips"]
    counts: dict[str, int] = {}
    for who, gs in graded.items():
        right = sum(g["correct"] is True for g in gs)
        slips = [f"{g['name']}: {'missing' if g['missing'] else g['slip'] or 'not a known slip'}"
                 for g in gs if g["correct"] is False]
        for g in gs:
            if g["correct"] is False and not g["missing"]:
                counts[g["slip"] or "not a known slip"] = counts.get(
                    g["slip"] or "not a known slip", 0) + 1
        lines.append(f"  {who:{width}s}  {right:>2d}/{len(gs):<2d}  {'; '.join(slips) or '-'}")
    if counts:
        lines.append("  slips in the class: " + ", ".join(
            f"{k} {v}" for k, v in sorted(counts.items(), key=lambda kv: -kv[1])))
    return "\n".join(lines)
