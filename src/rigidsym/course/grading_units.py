"""Units on a student's answers when grading: an answer written with a unit
(``"25 mm"``, ``"30 deg"``, ``"1,0,2 cm"``) is converted to the answer's documented unit
(:func:`~.worked.units.answer_unit`) before it is compared, so any compatible unit grades
right; a bare number off by a unit's factor is named a unit slip, with the unit it was
most likely given in (pint, through :mod:`.worked.units`).
"""

from __future__ import annotations

import numpy as np

from rigidsym.course.worked.numbers import read_text
from rigidsym.course.worked.units import answer_factor, slipped_unit

__all__ = ["unit_off", "unit_slip"]


def unit_off(given, unit: str | None, where: str):
    """A student's answer with its written unit taken off: ``(value, factor to unit, the
    unit written or "")``; the entries of a list may each carry a unit (converted).

    Raises:
        ValueError: a unit on an answer with no single unit, or an incompatible one.
    """
    if isinstance(given, str) and _units_per_entry(given, unit, where):
        rows = [[x.strip() for x in row.split(",")] for row in given.split(";")]
        nested = [r if len(r) > 1 else r[0] for r in rows] if len(rows) > 1 else rows[0]
        seen: set = set()
        if len(rows) > 1 and all(len(r) == 1 for r in rows):
            nested = [[x] for x in nested]            # a column typed as rows: 1 m; 2 m
        return _entry_off(nested, unit, where, seen), 1.0, ", ".join(sorted(seen))
    if isinstance(given, str):
        return answer_factor(given, unit, where)
    if isinstance(given, list | tuple):
        seen: set = set()
        return [_entry_off(x, unit, where, seen) for x in given], 1.0, ", ".join(sorted(seen))
    return given, 1.0, ""


def _units_per_entry(text: str, unit: str | None, where: str) -> bool:
    """A vector or matrix typed as text with a unit on an entry before the last
    (``"0 mm, 0 mm, 75 mm"``): each entry carries its own unit."""
    entries = [x.strip() for row in text.split(";") for x in row.split(",")]
    if len(entries) < 2:
        return False
    for x in entries[:-1]:
        try:
            if answer_factor(x, unit, where)[2]:
                return True
        except ValueError:
            return False
    return False


def _entry_off(x, unit, where, seen: set):
    if isinstance(x, list | tuple):
        return [_entry_off(y, unit, where, seen) for y in x]
    if not isinstance(x, str):
        return x
    text, f, written = answer_factor(x, unit, where)
    if written:
        seen.add(written)
    if f == 1.0:
        return text
    try:
        return float(text) * f
    except ValueError:
        return float(read_text(text, where)[0]) * f


def unit_slip(word: str, value: np.ndarray, right: np.ndarray, unit: str | None,
              written: str) -> str:
    """The note naming a unit slip of a bare number that matched ``value`` (the right
    answer ``right`` edited by a ``"unit"`` or ``"degrees"`` slip), or ``""``."""
    if written or word not in ("unit", "degrees"):
        return ""
    ratio = _ratio(value, right)
    if word == "degrees":
        wrote = "deg given where rad" if ratio > 1 else "rad given where deg"
        return f"; a unit slip: {wrote} is expected (write the unit, e.g. '30 deg')"
    u = slipped_unit(ratio, unit)
    if not u:
        return "; a unit slip (a power of ten off)"
    return (f"; a unit slip: the number is in {u}, the answer in {unit} (write the unit "
            f"after the number, e.g. '... {u}')")


def _ratio(value: np.ndarray, right: np.ndarray) -> float:
    """The factor between an edited answer and the right one (at its largest entry)."""
    k = int(np.argmax(np.abs(right)))
    return float(value.reshape(-1)[k] / right.reshape(-1)[k])
