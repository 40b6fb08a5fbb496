"""Reading students' answers: one JSON or text file, a folder of them, or a CSV of a class.

A value is a number, an exact string (``"sqrt(3)/2"``), nested JSON lists, or a string
the grader splits as ``--set`` splits data (``"0,0,1;1,0,0;0,1,0"``); a blank is kept
blank, and the grader counts it missing.

Files are read as editors save them: UTF-8 with or without a byte-order mark (Notepad,
Excel), lines ending in LF or CRLF; a CSV's separator ``,``, ``;`` or a tab. A text file
(``.txt``) holds one answer a line, ``name = value`` (or ``name: value``); blank lines and
lines starting with ``#`` are skipped.
"""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

__all__ = ["read_answers", "read_class_answers", "read_table"]


def read_answers(path: str | Path) -> dict[str, dict]:
    """Students' answers: ``{student: {answer name: value}}`` from a JSON file (the
    student is its stem), a folder of them, or a CSV file.

    Raises:
        ValueError: a path that is missing or unreadable, a file that is not a JSON object,
            or a CSV without a ``student`` column (the message names the file).
    """
    p = Path(path)
    if p.is_dir():
        files = _answer_files(p)
        return {f.stem: _file_answers(f) for f in files}
    if p.suffix.lower() == ".csv":
        return _csv_answers(p)
    return {p.stem: _file_answers(p)}


def _answer_files(p: Path) -> list[Path]:
    """The ``*.json`` and ``*.txt`` answer files of a folder, sorted by name.

    Raises:
        ValueError: there are none.
    """
    files = sorted([*p.glob("*.json"), *p.glob("*.txt")])
    if not files:
        raise ValueError(f"--grade: no *.json (or *.txt) answer files in the folder {p}")
    return files


def _file_answers(f: Path) -> dict:
    """One student's answers from a JSON or a text file (by its suffix)."""
    return _txt_answers(f) if f.suffix.lower() == ".txt" else _json_answers(f)


def _json_answers(f: Path) -> dict:
    try:
        doc = json.loads(f.read_text(encoding="utf-8-sig"))     # a BOM (Notepad) skipped
    except (OSError, ValueError) as exc:
        raise ValueError(f"--grade: cannot read {f}: {exc}") from None
    if not isinstance(doc, dict):
        raise ValueError(f"--grade: expected a JSON object {{answer name: value}} in {f}")
    return doc


def _txt_answers(f: Path) -> dict:
    """A text file of ``name = value`` lines (or ``name: value``), as :mod:`.answers`
    describes.

    Raises:
        ValueError: an unreadable file, or a line with neither ``=`` nor ``:`` (the
            message names the file and the line number).
    """
    try:
        text = f.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"--grade: cannot read {f}: {exc}") from None
    out: dict = {}
    for n, line in enumerate(text.splitlines(), 1):
        t = line.strip()
        if not t or t.startswith("#"):
            continue
        sep = "=" if "=" in t else ":" if ":" in t else None
        if sep is None:
            raise ValueError(f"--grade: {f}, line {n}: expected 'name = value', got {t!r}")
        name, _, value = t.partition(sep)
        out[name.strip()] = _cell(value)
    return out


def read_table(f: Path, what: str = "--grade") -> list[dict]:
    """The rows of a CSV as spreadsheets save it: UTF-8 with or without a BOM (Excel), the
    separator ``,``, ``;`` or a tab found by :class:`csv.Sniffer` (a European Excel writes
    ``;``); header names stripped.

    Raises:
        ValueError: an unreadable file (the message names it).
    """
    try:
        text = f.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"{what}: cannot read {f}: {exc}") from None
    head = "\n".join(text.splitlines()[:5])
    try:
        dialect = csv.Sniffer().sniff(head, delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel
    try:
        rows = list(csv.DictReader(io.StringIO(text, newline=""), dialect=dialect))
    except csv.Error as exc:
        raise ValueError(f"{what}: cannot read {f}: {exc}") from None
    return [{(k or "").strip(): v for k, v in r.items() if k is not None} for r in rows]


def _csv_answers(f: Path) -> dict[str, dict]:
    """A CSV's answer sets by student; two rows of one name (with their ids) are kept
    apart, each under ``name (id)``."""
    rows = _csv_rows(f)
    names = [label for label, _ in rows]
    out = {}
    for label, answers in rows:
        key = label
        if names.count(label) > 1 and answers.get("id"):
            key = f"{label} ({answers['id']})"
        out[key] = answers
    return out


def _csv_rows(f: Path) -> list[tuple[str, dict]]:
    """A CSV's rows as ``[(student, answers)]``, in file order, none merged: a row's
    ``id`` cell (when the file has an ``id`` column beside ``student``) is the
    ``"id"`` entry of its answers, the student id the row declares."""
    rows = read_table(f)
    cols = {k.lower(): k for k in (rows[0] if rows else {})}
    who_col = cols.get("student") or cols.get("name") or cols.get("id")
    if not rows or who_col is None:
        raise ValueError(f"--grade: {f} needs a header row with a 'student' (or 'id') column "
                         f"and one column per answer name")
    out = []
    id_col = cols.get("id") if who_col != cols.get("id") else None
    for r in rows:
        who = (r.pop(who_col) or "").strip()
        ident = (r.pop(id_col) or "").strip() if id_col else ""
        answers = {k: _cell(v) for k, v in r.items() if k and v not in ("", None)}
        if ident:
            answers["id"] = ident
        out.append((who or ident, answers))
    return out


def read_class_answers(path: str | Path) -> tuple[list[tuple[str, dict]], list[str]]:
    """A class's answers, each file on its own: ``([(label, answers), ...], problems)``;
    ``label`` is a JSON file's stem or a CSV row's student (every row on its own: two
    students of one name stay two, told apart by their ``id`` cells); a file that cannot
    be read is a line of ``problems`` (the rest of the class is still read).

    Raises:
        ValueError: a path that is neither a folder of JSON files nor a readable CSV or
            JSON file (nothing of the class can be read).
    """
    p = Path(path)
    if p.is_dir():
        out, problems = [], []
        for f in _answer_files(p):
            try:
                out.append((f.stem, _file_answers(f)))
            except ValueError as exc:
                problems.append(f"{f.name}: not graded: {exc}")
        return out, problems
    if p.suffix.lower() == ".csv":
        return _csv_rows(p), []
    return list(read_answers(p).items()), []


def _cell(text: str):
    t = text.strip()
    if t.startswith("["):
        try:
            return json.loads(t)
        except ValueError:
            return t
    return t
