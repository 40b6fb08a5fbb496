"""The exercises in the report: ``exercises.md``, ``exercises.html`` and their figures.

Each exercise with a figure (its module's ``figure(solution)``) gets one SVG, drawn from
the solution's own answers on the book's data, written beside the pages and inlined in the
HTML (deterministic: fixed id salt, no date, text as paths).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from rigidsym.core.files import write_atomic
from rigidsym.course.worked import EXERCISE_IDS, exercise_module, render_markdown, solve

__all__ = ["write_report", "svg_text", "figure_file", "rendered"]

TITLE = "Chapter 3 exercises, solved with computer algebra"


def svg_text(fig) -> str:
    """The figure as SVG text, byte-identical from run to run (fixed id salt, no date)."""
    import io

    import matplotlib as mpl
    buf = io.StringIO()
    with mpl.rc_context({"svg.hashsalt": "rigidsym", "svg.fonttype": "path"}):
        fig.savefig(buf, format="svg", metadata={"Date": None})
    return buf.getvalue()


def figure_file(ex_id: str) -> str:
    """The figure's file name: ``ex3_04_figure.svg`` (``ex3_10_condition.svg``)."""
    mod = exercise_module(ex_id)
    k = int(ex_id.split(".")[1])
    return f"ex3_{k:02d}_{getattr(mod, 'FIGURE_NAME', 'figure')}.svg"


def _figure(s, figures: dict[str, str]) -> str:
    """Draw the figure of ``s`` into ``figures``; the Markdown image line ("" if none)."""
    draw = getattr(exercise_module(s.id), "figure", None)
    if draw is None or s.status != "solved":
        return ""
    fig = draw(s)
    name = figure_file(s.id)
    figures[name] = svg_text(fig)
    alt = (draw.__doc__ or "figure").strip().splitlines()[0].rstrip(".")
    return f"![Exercise {s.id[2:]}: {alt}]({name})"


def write_report(out_dir: Path) -> list[Path]:
    """Report hook: write ``exercises.md``, ``exercises.html`` (maths as MathML, figures
    inline) and one SVG per figure into ``out_dir``; return the paths written.

    The files are kept in the user cache under the keys of the solutions they render
    (:mod:`rigidsym.course.worked.solution_store`) and the package: while nothing changed
    they are written from there, nothing solved or drawn."""
    files = rendered()
    if files is None:
        files = _render()
        from rigidsym.core import cache as _cache

        _cache.put(_bundle_path(), json.dumps(files).encode())
    return [write_atomic(Path(out_dir) / name, text) for name, text in files.items()]


def _bundle_path() -> Path:
    from rigidsym.core import cache as _cache
    from rigidsym.course.worked import parameters, read_data, solution_store

    h = hashlib.sha256(b"exercise report 2\0")  # the keys name the package's digest
    for i in EXERCISE_IDS:
        d = read_data(parameters(i), {}, None)
        h.update(solution_store.path(i, exercise_module(i).__name__, d).name.encode())
    key = h.hexdigest()
    return _cache.folder("verdicts") / key[:2] / f"exercises-{key}.json"


def rendered() -> dict[str, str] | None:
    """The exercise report's files (``{name: text}``) as kept in the user cache, or
    ``None`` when something they depend on changed."""
    from rigidsym.core import cache as _cache

    data = _cache.get(_bundle_path())
    return None if data is None else json.loads(data)


def _render() -> dict[str, str]:
    """The exercise report's files, ``{name: text}`` in writing order (figures first)."""
    from rigidsym.report.html import markdown_to_html

    sols = [solve(i) for i in EXERCISE_IDS]
    parts = [f"# {TITLE}", "", "| exercise | status | checked |", "|---|---|---|"]
    parts += [f"| [{s.id}](#ex-{s.id[2:]}) | {s.status} | {str(s.checked).lower()} |"
              for s in sols]
    parts.append("")
    figures: dict[str, str] = {}
    for s in sols:
        parts.append(render_markdown(s, typeset=True))
        image = _figure(s, figures)
        if image:
            parts += [image, ""]
    text = "\n".join(parts)
    return {**figures, "exercises.md": text,
            "exercises.html": markdown_to_html(text, TITLE, figures)}
