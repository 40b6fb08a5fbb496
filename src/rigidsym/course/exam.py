"""Exam sets: a student handout and an answer key from a spec.

A spec (TOML, or the same as a dict) lists problems: an exercise with its data, or ``n``
random well-posed variants of an exercise drawn from the seed with readable exact numbers
(the exercise module's ``random_data(rng)``: Cayley rotations of small rationals, small
integers, short decimals)::

    title = "Quiz 3"
    seed = 7
    [[problem]]
    exercise = "3.19"
    data = { d = ["0.1", 0, 0] }
    [[problem]]
    exercise = "3.4"
    variants = 2

Written: ``handout.html`` (statement, data, a figure of the given data only, space for
each answer; a print stylesheet; nothing that gives an answer away), ``key.html`` (the
worked, checked solutions with their figures) and ``key.json`` (schema 2: data, answers,
checks). Deterministic for a spec and seed: no date, fixed SVG ids, seeded draws.
"""

from __future__ import annotations

import html
import json
import random
import types
from pathlib import Path

from rigidsym.core.files import write_atomic
from rigidsym.course.exam_text import answers_asked, box_label, task
from rigidsym.course.worked import (
    exercise_module,
    normalise_id,
    parameters,
    render_html,
    solution_record,
    solve,
)

__all__ = ["exam", "read_spec", "asked", "drawable", "variants_module"]

_DRAWS = 50
_STYLE = """
body { font-family: serif; max-width: 46em; margin: 2em auto; line-height: 1.4; }
table { border-collapse: collapse; margin: 0.5em 0; }
td, th { border: 1px solid #999; padding: 0.2em 0.6em; text-align: left; }
.answer { border: 1px dashed #777; min-height: 4em; margin: 0.4em 0 1em; padding: 0.3em; }
figure svg { max-width: 100%; height: auto; }
@media print {
  body { margin: 0; max-width: none; font-size: 11pt; }
  section.problem { page-break-after: always; }
  .answer { min-height: 7em; }
}
"""


def read_spec(spec) -> dict:
    """A spec from a TOML file path or a dict, checked.

    Raises:
        ValueError: unreadable TOML, no problems, a problem without ``exercise``, with
            both ``data`` and ``variants``, or ``variants`` for an exercise that draws none
            (the message names the problem); a problem's ``weight`` that is not a finite
            number >= 0, or every problem's 0; ``slips_along_the_way`` that is not a
            truth.
    """
    if not isinstance(spec, dict):
        import tomllib
        try:
            spec = tomllib.loads(Path(spec).read_text(encoding="utf-8"))
        except (OSError, tomllib.TOMLDecodeError) as exc:
            raise ValueError(f"spec: cannot read {spec}: {exc}") from None
    problems = spec.get("problem")
    from rigidsym.course.worked import EXERCISE_IDS

    example = f'exercise = "{EXERCISE_IDS[0][2:]}"'  # the book's first exercise
    if not isinstance(problems, list) or not problems:
        raise ValueError(f"spec: expected at least one [[problem]] with {example}")
    for k, p in enumerate(problems, 1):
        if not isinstance(p, dict) or "exercise" not in p:
            raise ValueError(f"spec: problem {k} has no exercise (e.g. {example})")
        ex_id = normalise_id(str(p["exercise"]))
        if "data" in p and "variants" in p:
            raise ValueError(f"spec: problem {k} gives both data and variants; one of them")
        if "variants" in p and ex_id not in drawable():
            drawn = [i[2:] for i in drawable()]
            raise ValueError(f"spec: problem {k}: exercise {ex_id[2:]} draws no random "
                             f"variants (those that do: {', '.join(drawn)}); give its data")
    _check_weights(problems)
    along = spec.get("slips_along_the_way", True)
    if not isinstance(along, bool):
        raise ValueError(f"spec: slips_along_the_way must be true or false, not {along!r}")
    return spec


def _check_weights(problems: list[dict]) -> None:
    """Each spec problem's ``weight`` (default 1) a finite number >= 0, not all of them 0.

    Raises:
        ValueError: the first problem whose weight is not so (named), or every weight 0.
    """
    import math

    for k, p in enumerate(problems, 1):
        w = p.get("weight", 1)
        if isinstance(w, bool) or not isinstance(w, int | float) or not math.isfinite(w) \
                or w < 0:
            raise ValueError(f"spec: problem {k}: weight must be a finite number >= 0 "
                             f"(weight = 2), not {w!r}")
    if all(p.get("weight", 1) == 0 for p in problems):
        raise ValueError("spec: at least one problem's weight must be positive (every "
                         "weight is 0)")


def drawable() -> list[str]:
    """The exercises that draw variants: their own ``random_data``, or the book's
    ``_variants`` module (3.6's data, the proofs' true-or-false statements).

    Returns:
        Their ids (``"ex3.1"``, ...), in the order of ``EXERCISE_IDS``.
    """
    from rigidsym.course.worked import EXERCISE_IDS
    more = set(variants_module().drawn())
    return [i for i in EXERCISE_IDS if hasattr(exercise_module(i), "random_data")
            or i in more]


def variants_module() -> types.ModuleType:
    """The book's module of variants for the exercises without ``random_data`` (loaded by
    its configured name: the machinery never imports the book).

    Returns:
        The module ``<exercises package>._variants``: ``draw(ex_id, rng)`` one variant of an
        exercise, ``drawn()`` the exercises it draws.
    """
    import importlib

    from rigidsym.core import config as _config
    return importlib.import_module(f"{_config.EXERCISES}._variants")


def _variant(ex_id: str, rng):
    """One variant of ``ex_id``: a solution on drawn data, or a drawn problem itself."""
    own = getattr(exercise_module(ex_id), "random_data", None)
    if own is not None:
        return solve(ex_id, **own(rng))
    got = variants_module().draw(ex_id, rng)
    return solve(ex_id, **got[1]) if isinstance(got, tuple) else got


def _problems(spec: dict, seed: int, taken: dict | None = None) -> list:
    """The solved problems, in order: data given, or drawn (well-posed, checked)."""
    return [s for s, _k in drawn_exercises(spec, seed, taken)]


def drawn_exercises(spec: dict, seed: int, taken: dict | None = None) -> list[tuple]:
    """``[(solution, spec problem number), ...]``: data given, or drawn well-posed and
    checked from ``seed``. ``taken`` (slot -> set of data keys drawn for other students)
    makes every draw differ from those before it: a repeat is drawn again."""
    out = []
    for k, p in enumerate(spec["problem"], 1):
        ex_id = normalise_id(str(p["exercise"]))
        if "variants" not in p:
            out.append((solve(ex_id, **p.get("data", {})), k))
            continue
        for v in range(int(p["variants"])):
            seen = taken.setdefault((k, v), set()) if taken is not None else set()
            s = None
            for attempt in range(2 * _DRAWS):
                if attempt == _DRAWS and s is not None:
                    seen.clear()       # its variants are spent (3.10 has 12): reuse them
                rng = random.Random(f"{seed}:{k}:{ex_id}:{v}" + (f":{attempt}" if attempt
                                                                 else ""))
                drawn = _variant(ex_id, rng)
                if drawn.status == "solved" and drawn.checked:
                    s = drawn
                    if variant_key(s) not in seen:
                        break
            else:
                raise ValueError(f"spec: problem {k}: no well-posed variant of "
                                 f"{ex_id[2:]} in {2 * _DRAWS} draws")
            seen.add(variant_key(s))
            out.append((s, k))
    for s, k in out:
        if s.status != "solved":
            raise ValueError(f"spec: problem {k} ({s.id[2:]}) is {s.status} on its data: "
                             f"{s.reason}")
    return out


def variant_key(s) -> str:
    """A drawn variant's answers as one string (equal answers, equal strings): a class
    draws each student's variant again while its answers repeat another student's, so that
    neighbours' answer keys differ (other data with the same answers count as a repeat)."""
    return repr(sorted((k, str(v)) for k, v in s.answers.items()))


def _svg(fig) -> str:
    """A figure as deterministic SVG, its text kept as text (so a test can read it)."""
    import io

    import matplotlib as mpl
    buf = io.StringIO()
    with mpl.rc_context({"svg.hashsalt": "rigidsym-exam", "svg.fonttype": "none"}):
        fig.savefig(buf, format="svg", metadata={"Date": None})
    text = buf.getvalue()
    return text[text.index("<svg"):]


def _no_ticks(fig):
    """No coordinate ticks on a handout's figure: a tick could read as an answer (the
    centroid at h/2 is a tick of the prism's z axis); without ticks or grid a 3-D figure
    also draws in about a third of the time (a class of 30 draws 90)."""
    for ax in fig.axes:
        ax.grid(False)
        for axis in ("xaxis", "yaxis", "zaxis"):
            if hasattr(ax, axis):
                getattr(ax, axis).set_ticks([])    # no tick at all: a third of the time
    return fig


def data_table(s) -> str:
    if not len(parameters(s.id)):
        return ""
    rows = []
    for p in parameters(s.id):
        v = s.data[p.name]
        shown = (("[" + ", ".join(str(x) for x in v) + "]") if getattr(v, "cols", 0) == 1
                 else str(v.tolist()) if hasattr(v, "tolist") else str(v))
        rows.append(f"<tr><td><code>{html.escape(p.name)}</code></td><td><code>"
                    f"{html.escape(shown)}</code></td><td>{html.escape(p.unit)}</td><td>"
                    f"{html.escape(p.meaning)}</td></tr>")
    return ("<table><thead><tr><th>datum</th><th>value</th><th>unit</th><th>meaning</th>"
            "</tr></thead><tbody>" + "".join(rows) + "</tbody></table>")


def handout_page(title: str, body: str) -> str:
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
            f"{html.escape(title)}</title><style>{_STYLE}</style></head><body>\n"
            f"<h1>{html.escape(title)}</h1>\n{body}\n</body></html>\n")


def handout_text(title: str, sols: list, head: str = "", columns: bool = False) -> str:
    """The handout: per problem the task on the student's data (stated once), the data,
    a figure of the given data only, and a box per answer labelled in the book's words
    (``columns``: with the answer's column in the class's answers CSV)."""
    parts = []
    for k, s in enumerate(sols, 1):
        mod = exercise_module(s.id)
        draw = getattr(mod, "given_figure", None)
        fig = f"<figure>{_svg(_no_ticks(draw(s)))}</figure>" if draw else ""
        parts.append(
            f"<section class=\"problem\"><h2>Problem {k}: {html.escape(mod.TITLE)}</h2>"
            f"<p>{html.escape(task(s.id, s.statement))} <small>(after "
            f"{html.escape(s.citation)})</small></p>{data_table(s)}{fig}"
            f"<h3>Your answers</h3>{_boxes(s, k, columns)}</section>")
    from rigidsym.course.exam_text import ANSWER_FORMAT

    how = f"<p class=\"how\"><small>{html.escape(ANSWER_FORMAT)}</small></p>\n"
    return handout_page(title, head + how + "\n".join(parts))


def _boxes(s, k: int, columns: bool) -> str:
    """A box per answer asked, labelled in the book's words and symbols."""
    out = []
    for n in asked(s):
        col = f" <small>(column <code>P{k}.{html.escape(n)}</code>)</small>" if columns \
            else ""
        out.append(f"<p><b>{html.escape(box_label(s.id, n))}</b>{col}</p>"
                   f"<div class=\"answer\"></div>")
    return "".join(out)


def asked(s) -> list[str]:
    """The answers a handout asks for: the solution's answers that are values (an answer
    in words is read by the instructor, not boxed)."""
    from rigidsym.course.grading import gradeable

    only = answers_asked(s.id)
    return [n for n, v in s.answers.items() if not isinstance(v, str) and gradeable(v)
            and (only is None or n in only)]


def _key_html(title: str, sols: list) -> str:
    parts = []
    for k, s in enumerate(sols, 1):
        draw = getattr(exercise_module(s.id), "figure", None)
        fig = f"<figure>{_svg(draw(s))}</figure>" if draw else ""
        parts.append(f"<section class=\"problem\"><h2>Problem {k}</h2>{data_table(s)}"
                     f"{render_html(s)}{fig}</section>")
    return handout_page(f"{title}: answer key", "\n".join(parts))


def exam(spec, out_dir: str | Path, seed: int | None = None) -> dict[str, Path]:
    """Write an exam set: ``handout.html``, ``key.html`` and ``key.json`` in ``out_dir``.

    Args:
        spec: a TOML file path, or the same as a dict (see the module docstring).
        out_dir: the folder to write (made if missing).
        seed: the draw's seed (default: the spec's ``seed``, else 0).

    Returns:
        ``{"handout": path, "key_html": path, "key_json": path}`` (written atomically).

    Raises:
        ValueError: a bad spec, bad data, or a problem ill-posed on its data.
        TypeError: bad data (as :func:`rigidsym.exercises.solve`).
    """
    import matplotlib
    matplotlib.use("Agg", force=False)
    from rigidsym.report.record import document_header

    spec = read_spec(spec)
    seed = int(spec.get("seed", 0) if seed is None else seed)
    title = str(spec.get("title", "Rigid-body mechanics: exercises"))
    sols = _problems(spec, seed)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    key = {**document_header(), "title": title, "seed": seed,
           "exercises": [dict(solution_record(s), problem=k) for k, s in enumerate(sols, 1)]}
    return {"handout": write_atomic(out / "handout.html", handout_text(title, sols)),
            "key_html": write_atomic(out / "key.html", _key_html(title, sols)),
            "key_json": write_atomic(out / "key.json", json.dumps(key, indent=2,
                                                                  ensure_ascii=False) + "\n")}
