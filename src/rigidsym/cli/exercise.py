"""``rigidsym exercise``, and the exercise part of ``rigidsym report`` (``exercises.md``)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from rigidsym._io import write_atomic
from rigidsym.checking.worked import (
    EXERCISE_IDS,
    normalise_id,
    render_markdown,
    render_text,
    solve,
    to_json_value,
)

__all__ = ["add_arguments", "run", "to_json", "write_report"]

HELP = "solve chapter-3 exercises with computer algebra (worked solutions, machine-checked)"


def add_arguments(p) -> None:
    """Arguments of ``rigidsym exercise``."""
    p.add_argument("id", nargs="?", help="exercise id: 3.10 or ex3.10")
    p.add_argument("--all", action="store_true", help="solve all 21 exercises")
    p.add_argument("--json", help="write the results (schema 1) as JSON to this path")


def to_json(ids) -> str:
    """The schema-1 JSON document for the exercises ``ids``.

    ``answers`` holds sympy values only (``str()`` that ``sympify`` reads back); answers
    stated in words (conditions, interpretations) go to ``statements``.
    """
    items = []
    for i in ids:
        s = solve(i)
        items.append({"id": s.id, "status": s.status,
                      "answers": {k: to_json_value(v) for k, v in s.answers.items()
                                  if not isinstance(v, str)},
                      "checked": s.checked, "assumptions": list(s.assumptions),
                      "statements": {k: v for k, v in s.answers.items() if isinstance(v, str)}})
    return json.dumps({"schema": 1, "exercises": items}, indent=2) + "\n"


def run(args) -> int:
    """Solve chapter-3 exercises with computer algebra (worked solutions, machine-checked)."""
    if args.all == bool(args.id):
        print("rigidsym: error: give one exercise id (e.g. 3.10) or --all", file=sys.stderr)
        return 2
    try:
        ids = EXERCISE_IDS if args.all else [normalise_id(args.id)]
    except ValueError as exc:
        print(f"rigidsym: error: {exc}", file=sys.stderr)
        return 2
    if args.json:
        write_atomic(args.json, to_json(ids))
    if args.all:
        n_ok = 0
        for i in ids:
            s = solve(i)
            ok = s.status == "solved" and s.checked
            n_ok += ok
            print(f"{s.id:7s} {s.status:8s} checked={str(s.checked).lower():5s} {s.title}")
        print(f"{n_ok} / {len(ids)} solved and checked")
        return 0 if n_ok == len(ids) else 1
    s = solve(ids[0])
    print(render_text(s))
    return 0 if s.checked else 1


def svg_text(fig) -> str:
    """The figure as SVG text, byte-identical from run to run (fixed id salt, no date)."""
    import io

    import matplotlib as mpl
    buf = io.StringIO()
    with mpl.rc_context({"svg.hashsalt": "rigidsym", "svg.fonttype": "path"}):
        fig.savefig(buf, format="svg", metadata={"Date": None})
    return buf.getvalue()


def write_report(out_dir: Path) -> list[Path]:
    """Report hook: write ``exercises.md``, ``exercises.html`` (maths as MathML, the figure
    inline) and the Exercise 3.10 figure (SVG) into ``out_dir``; return the paths."""
    from rigidsym.report.html import markdown_to_html

    out_dir = Path(out_dir)
    parts = ["# Chapter 3 exercises, solved with computer algebra", ""]
    rows = ["| exercise | status | checked |", "|---|---|---|"]
    sols = [solve(i) for i in EXERCISE_IDS]
    rows += [f"| [{s.id}](#ex-{s.id[2:]}) | {s.status} | "
             f"{str(s.checked).lower()} |" for s in sols]
    parts += rows + [""]
    import importlib

    from rigidsym import _config
    condition_figure = importlib.import_module(f"{_config.EXERCISES}.ex3_10").condition_figure
    figures: dict[str, str] = {}
    written: list[Path] = []

    def keep(fig, path: Path) -> None:
        figures[path.name] = svg_text(fig)
        written.append(write_atomic(path, figures[path.name]))

    parts += [condition_figure(out_dir, keep), ""]
    parts += [render_markdown(s) for s in sols]
    text = "\n".join(parts)
    written.append(write_atomic(out_dir / "exercises.md", text))
    written.append(write_atomic(out_dir / "exercises.html", markdown_to_html(
        text, "Chapter 3 exercises, solved with computer algebra", figures)))
    return written


