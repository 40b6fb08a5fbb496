"""What a handout says: each exercise's task stated once on the student's data (no book
numbers to be replaced), and each answer box named in the book's words and symbols.

The words are the book's data, ``handout.toml`` beside its exercises (the package
:data:`rigidsym.core.config.EXERCISES`): the tasks paraphrase the chapter's exercises
(Angeles, Sec. 3.9) without their numbers (the numbers are the student's, in the data table
under the task); a box label says what the answer is, in the book's symbols (``[Q]_1``,
``p*``, ``[w]_2``), its shape, unit and, for a list, its order; the answer's column name in
the class's answers CSV follows it. The file is read once and checked key by key (fail
closed: an unknown key is an error naming it).
"""

from __future__ import annotations

import tomllib
from functools import cache
from importlib import resources

from rigidsym.core import config as _config
from rigidsym.core.errors import BadInput

__all__ = ["ANSWER_FORMAT", "task", "box_label", "answers_asked", "handout_words", "lms_statement"]

#: the file of the exercises' words, in the exercises' package
HANDOUT = "handout.toml"
_KEYS = {"task": str, "asked": list, "boxes": dict, "parts": dict, "part_boxes": dict,
         "boxes_of": str, "box_stems": list}


@cache
def handout_words() -> dict[str, dict]:
    """What the book's exercises' ``handout.toml`` says of each exercise.

    Returns:
        ``{exercise id: {"task": str, "asked": [names], "boxes": {name: label}, "parts":
        {part: words}, "part_boxes": {name: label}, "boxes_of": id, "box_stems": [{"stem":
        ..., "words": ...}]}}``, each key present where the file gives it (read once).

    Raises:
        BadInput: the file does not parse, a key it does not know, a value of the wrong
            type, a label that is not a string (each naming the file and the key).
    """
    where = f"{_config.EXERCISES}/{HANDOUT}"
    try:
        doc = tomllib.loads(resources.files(_config.EXERCISES).joinpath(HANDOUT)
                            .read_text("utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise BadInput(f"{where}: cannot read it ({exc})") from None
    if set(doc) - {"exercise"} or not isinstance(doc.get("exercise", {}), dict):
        raise BadInput(f"{where}: expected [exercise.\"ID\"] tables only")
    out = {}
    for ex_id, entry in doc.get("exercise", {}).items():
        here = f"{where}: [exercise.{ex_id!r}]"
        for key, value in entry.items():
            if key not in _KEYS:
                raise BadInput(f"{here}: unknown key {key!r}; expected "
                               f"{', '.join(sorted(_KEYS))}")
            if not isinstance(value, _KEYS[key]):
                raise BadInput(f"{here} {key}: expected a {_KEYS[key].__name__}")
        tables = [entry.get(k, {}) for k in ("boxes", "parts", "part_boxes")]
        strings = [*entry.get("asked", []), *(v for t in tables for v in t.values()),
                   *(x.get(k) for x in entry.get("box_stems", []) for k in ("stem", "words"))]
        if not all(isinstance(x, str) and x for x in strings) or not all(
                isinstance(x, dict) and set(x) == {"stem", "words"}
                for x in entry.get("box_stems", [])):
            raise BadInput(f"{here}: every name and label must be a non-empty string, each "
                           f"box_stems entry a stem and its words")
        out[ex_id] = entry
    return out


def answers_asked(ex_id: str) -> tuple[str, ...] | None:
    """The answers a handout asks of ``ex_id`` (``None``: every answer that is a value)."""
    got = handout_words().get(ex_id, {}).get("asked")
    return None if got is None else tuple(got)


#: the boxes of a true-or-false variant (any exercise)
TRUE_OR_FALSE = {"holds": "true or false, for (i), (ii), (iii) in order (3: true, false, "
                          "...)",
                 "why": "the number of the reason, for (i), (ii), (iii) in order (3: 1 to 4)"}

#: what every handout says about writing an answer (the grader's reading and tolerance)
ANSWER_FORMAT = (
    "How to write an answer: a number with a decimal point (1.25) or exact (sqrt(3)/2, "
    "2*pi/3); a vector as its entries separated by commas (1, 0, 2); a matrix row by row, "
    "rows separated by ';' (1, 0, 0; 0, 1, 0; 0, 0, 1); true or false as true or false. "
    "Units: as each box says (m, rad, kg m^2); another unit is read when written after the "
    "number ('25 mm', '30 deg'). An answer is right within 0.1 % of the largest entry of "
    "the right answer: give at least 4 significant figures. An axis and angle may be given "
    "as (e, phi) or (-e, -phi), an angle plus any whole number of turns, with the Plücker "
    "array of the same sign as e; a point of an axis may be any point of it; principal "
    "axes each with either sign; a rotation asked by a property it has (Q [I]_A Q^T = "
    "[I]_B) may be any rotation that has it.")


def task(ex_id: str, statement: str) -> str:
    """The task of ``ex_id`` on the data below; the solution's own statement where the
    exercise has no numbers to replace (a proof, a true-or-false)."""
    return handout_words().get(ex_id, {}).get("task", statement)


def box_label(ex_id: str, name: str) -> str:
    """The label of the answer box ``name`` of ``ex_id``: the book's symbol and words (its
    ``boxes``; in a solution in parts, the part's words and the box's; a name of a family,
    its stem's words), else the name in words."""
    words = handout_words()
    entry = words.get(ex_id, {})
    got = entry.get("boxes", {}).get(name) or TRUE_OR_FALSE.get(name)
    if got:
        return got
    if "parts" in entry:
        tag, _, rest = name.partition("_")
        inner = entry.get("part_boxes", {}).get(rest) or words.get(
            entry.get("boxes_of", ""), {}).get("boxes", {}).get(rest)
        if inner:
            return f"{entry['parts'].get(tag, tag)}: {inner}"
    for x in entry.get("box_stems", []):
        if name.startswith(x["stem"]):
            return x["words"] + name[len(x["stem"]):]
    return name.replace("_", " ")


def lms_statement(p: dict) -> str:
    """A problem's statement as an LMS question shows it (HTML): the task the handout
    states (kept in the key record as ``task``: a proof's true-or-false statements in the
    book's notation, with its symbols defined) and the student's data, each datum named as
    the handout's table names it (no datum of a drawn statement's internal numbering)."""
    import html

    from rigidsym.course.worked import exercise_module, parameters

    mod = exercise_module(p["id"])
    text = p.get("task") or task(p["id"], getattr(mod, "STATEMENT", ""))
    names = {q.name for q in parameters(p["id"])}
    data = [f"<li>{html.escape(k)} = {html.escape(_shown(v))}</li>"
            for k, v in p["data"].items() if k in names]
    return f"<p>{html.escape(text)}</p>" + (f"<ul>{''.join(data)}</ul>" if data else "")


def _shown(v) -> str:
    """A datum as the handout shows it: ``[1, -1/20, 0]``."""
    if isinstance(v, list):
        return "[" + ", ".join(_shown(x) for x in v) + "]"
    return str(v)
