"""Reading students' answers: one JSON file, a folder of them, or a CSV of a class.

A value is a number, an exact string (``"sqrt(3)/2"``), nested JSON lists, or a string
the grader splits as ``--set`` splits data (``"0,0,1;1,0,0;0,1,0"``); a blank is kept
blank, and the grader counts it missing.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

__all__ = ["read_answers"]


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
