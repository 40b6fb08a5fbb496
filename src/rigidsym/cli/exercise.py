"""``rigidsym exercise``: solve, vary and check the chapter's exercises; write notebooks.

``rigidsym exercise 3.4`` prints the worked solution on the book's data;
``--set n_1=0,0,5`` and ``--data FILE.json`` give other data (checked as
:func:`rigidsym.exercises.solve` checks them), ``--parameters`` lists them,
``--notebook PATH`` writes the exercise's notebook. The report hook (``exercises.md``,
``exercises.html`` and the figures) is :mod:`rigidsym.report.exercises`.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from rigidsym._io import write_atomic
from rigidsym.checking.worked import (
    EXERCISE_IDS,
    normalise_id,
    parameters,
    render_text,
    solve,
    to_json_value,
)
from rigidsym.report.exercises import svg_text, write_report

__all__ = ["add_arguments", "run", "to_json", "write_report", "svg_text", "parse_value"]

HELP = "solve chapter-3 exercises with computer algebra (worked solutions, machine-checked)"


def add_arguments(p) -> None:
    """Arguments of ``rigidsym exercise``."""
    p.add_argument("id", nargs="?", help="exercise id: 3.10 or ex3.10")
    p.add_argument("--all", action="store_true", help="solve all 21 exercises")
    p.add_argument("--json", help="write the results (schema 1) as JSON to this path")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="a datum of the exercise (repeatable): n_1=0,0,5 (a vector), "
                        "I_A='1,0,0;0,2,0;0,0,3' (a matrix, rows split by ;), a=0.05; "
                        "values are exact: 5/3, 0.1 (= 1/10), sqrt(3)/2")
    p.add_argument("--data", metavar="FILE.json",
                   help="the data as a JSON object {name: value}; JSON numbers with a "
                        "decimal point are floats, read as measurements; strings are exact")
    p.add_argument("--tol", help="tolerance of measured data (Exercises 3.4, 3.14, 3.19); "
                                 "given, it selects the least-squares path")
    p.add_argument("--parameters", action="store_true",
                   help="list the exercise's data (names, the book's values, shapes, units)")
    p.add_argument("--notebook", metavar="PATH",
                   help="write the exercise's Jupyter notebook (with the data given) to PATH")


def to_json(ids, data: dict | None = None) -> str:
    """The schema-1 JSON document for the exercises ``ids`` (``data`` for a single id).

    ``answers`` holds sympy values only (``str()`` that ``sympify`` reads back); answers
    stated in words (conditions, interpretations) go to ``statements``; an ill-posed
    solution has ``"status": "ill-posed"`` and its ``reason``.
    """
    items = []
    for i in ids:
        s = solve(i, **(data or {}))
        item = {"id": s.id, "status": s.status,
                "answers": {k: to_json_value(v) for k, v in s.answers.items()
                            if not isinstance(v, str)},
                "checked": s.checked, "assumptions": list(s.assumptions),
                "statements": {k: v for k, v in s.answers.items() if isinstance(v, str)}}
        if s.reason:
            item["reason"] = s.reason
        items.append(item)
    return json.dumps({"schema": 1, "exercises": items}, indent=2) + "\n"


def parse_value(ex_id: str, name: str, text: str):
    """The text of ``--set NAME=VALUE`` as the value :func:`solve` takes: a list of entry
    strings for a vector (``0,0,5``), a list of rows for a matrix (``1,0,0;0,2,0;0,0,3``
    or ``[[1,0,0],[0,2,0],[0,0,3]]``), the text itself for a scalar or a choice (an
    unknown name is left to :func:`solve`, which lists the exercise's parameters)."""
    try:
        shape = parameters(ex_id)[name].shape
    except KeyError:
        return text
    t = text.strip()
    if not shape:
        return t
    if len(shape) == 1:
        return [x.strip() for x in t.strip("[]").split(",")]
    rows = t.replace("],[", ";").replace("], [", ";").strip("[] ")
    return [[x.strip() for x in r.strip("[] ").split(",")] for r in rows.split(";")]


def _data(args, ex_id: str) -> dict:
    """The data of ``--data`` and ``--set`` (``--set`` wins), ``tol`` included."""
    data: dict = {}
    if args.data:
        try:
            loaded = json.loads(Path(args.data).read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise ValueError(f"--data: cannot read {args.data}: {exc}") from None
        if not isinstance(loaded, dict):
            raise ValueError(f"--data: expected a JSON object {{name: value}} in {args.data}")
        data.update(loaded)
    for item in args.set:
        name, sep, text = item.partition("=")
        if not sep or not name.strip():
            raise ValueError(f"--set: expected NAME=VALUE, got {item!r}")
        data[name.strip()] = parse_value(ex_id, name.strip(), text)
    if args.tol is not None:
        data["tol"] = args.tol
    return data


def _notebook(ex_id: str, path: str, data: dict) -> None:
    """Write the notebook: built with the data (nbformat), or copied from the package."""
    try:
        from rigidsym.exercises import write_notebook
        print(f"wrote {write_notebook(ex_id, path, **data)}")
    except ModuleNotFoundError as exc:
        if exc.name != "nbformat" or data:
            raise ValueError("--notebook with data needs nbformat: pip install "
                             "\"rigidsym[notebooks]\"") from None
        from importlib.resources import files

        from rigidsym.report.notebooks import file_name
        packaged = files("rigidsym.generated") / "notebooks" / file_name(ex_id)
        print(f"wrote {write_atomic(path, packaged.read_text(encoding='utf-8'))}")


def run(args) -> int:
    """Solve chapter-3 exercises with computer algebra (worked solutions, machine-checked)."""
    if args.all == bool(args.id):
        print("rigidsym: error: give one exercise id (e.g. 3.10) or --all", file=sys.stderr)
        return 2
    varied = args.set or args.data or args.tol is not None
    try:
        if args.all and (varied or args.notebook or args.parameters):
            raise ValueError("--set, --data, --tol, --parameters and --notebook take one "
                             "exercise id, not --all")
        ids = EXERCISE_IDS if args.all else [normalise_id(args.id)]
        if args.parameters:
            print(parameters(ids[0]))
            return 0
        data = {} if args.all else _data(args, ids[0])
        if args.notebook:
            _notebook(ids[0], args.notebook, data)
            return 0
        if args.json:
            write_atomic(args.json, to_json(ids, data))
        if args.all:
            return _run_all(ids)
        s = solve(ids[0], **data)
    except (ValueError, TypeError) as exc:
        print(f"rigidsym: error: {exc}", file=sys.stderr)
        return 2
    print(render_text(s))
    return 0 if s.checked else 1


def _run_all(ids) -> int:
    n_ok = 0
    for i in ids:
        s = solve(i)
        ok = s.status == "solved" and s.checked
        n_ok += ok
        print(f"{s.id:7s} {s.status:8s} checked={str(s.checked).lower():5s} {s.title}")
    print(f"{n_ok} / {len(ids)} solved and checked")
    return 0 if n_ok == len(ids) else 1
