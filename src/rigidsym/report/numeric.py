"""The numeric backing of a verdict in one sentence: the single wording that ``rigidsym
show``, the Markdown and the HTML reports print (from the record's ``numeric`` field).
"""

from __future__ import annotations

from rigidsym.checking.checker import NUMERIC_DIGITS, NUMERIC_POINTS
from rigidsym.report.record import RESIDUAL_FLOOR

__all__ = ["numeric_sentence"]


def numeric_sentence(n: dict, usual_stated: bool = False) -> str:
    """The numeric backing of a record in one sentence ("" when there is none).

    Args:
        n: the record's ``numeric`` field (schema 2: ``points``, ``digits``,
            ``max_residual``, ``seed``).
        usual_stated: the document already states the usual points and precision
            (:data:`~rigidsym.checking.checker.NUMERIC_POINTS`,
            :data:`~rigidsym.checking.checker.NUMERIC_DIGITS`), so only departures from
            them are named.

    Returns:
        ``"Numeric backing: 10 points at 50 digits, max relative residual < 1e-40 (seed
        42)."``; with ``usual_stated``, ``"Numeric residual < 1e-40."``. A residual at or
        below :data:`~rigidsym.report.record.RESIDUAL_FLOOR` is shown as ``< 1e-40``.
    """
    res = n.get("max_residual")
    if res is None:
        return ""
    shown = f"< {RESIDUAL_FLOOR:.0e}" if res <= RESIDUAL_FLOOR else f"{res:.1e}"
    if usual_stated:
        usual = (n["points"], n["digits"]) == (NUMERIC_POINTS, NUMERIC_DIGITS)
        extra = "" if usual else f" ({n['points']} points, {n['digits']} digits)"
        return f"Numeric residual {shown}{extra}."
    return (f"Numeric backing: {n['points']} points at {n['digits']} digits, max relative "
            f"residual {shown} (seed {n['seed']}).")
