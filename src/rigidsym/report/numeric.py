"""The numeric backing of a verdict in one sentence: the single wording that ``rigidsym
show``, the Markdown and the HTML reports print (from the record's ``numeric`` field).
"""

from __future__ import annotations

from rigidsym.core.settings import ENGINE
from rigidsym.report.record import RESIDUAL_FLOOR

__all__ = ["numeric_sentence"]


def _bound(r: float) -> str:
    # a committed record holds the floor for anything below it (its digits would depend on
    # the working precision, not on the mathematics): print it as the round number it is
    return f"{r:.0e}" if r == RESIDUAL_FLOOR else f"{r:.1e}"


def numeric_sentence(n: dict, usual_stated: bool = False) -> str:
    """The numeric backing of a record in one sentence ("" when there is none).

    Args:
        n: the record's ``numeric`` field (schema 2: ``points``, ``digits``,
            ``max_residual``, ``seed``, ``enclosure``, ``certified``, and for a
            does-not-hold ``printed_residual`` and ``printed_enclosure``).
        usual_stated: the document already states the usual points and precision, so
            only departures from them are named.

    Returns:
        For example ``"Numeric backing (ball arithmetic, seed 42): residual enclosed in
        [−r, r] at 10 points, r ≤ 1e-40; certified."``; for a does-not-hold it starts
        with ``"0 ∉ [3.73 ± 3.3e-10], the printed form's residual ball at the
        counterexample"``. A record without ``enclosure`` (written before the balls) gets
        the former words: the max relative residual.
    """
    if n.get("max_residual") is None and n.get("enclosure") is None:
        return ""
    if "enclosure" not in n:  # an older record: mpmath midpoints only
        return (f"Numeric backing: {n['points']} points at {n['digits']} digits, max relative "
                f"residual {_bound(n['max_residual'])} (seed {n['seed']}).")
    parts = []
    ball = n.get("printed_enclosure")
    if ball:
        shown = ball.replace("+/-", "±")
        parts.append(f"0 ∉ {shown}, the printed form's residual ball at the counterexample")
    if n.get("enclosure") is not None:
        whose = "the corrected form's residual" if ball else "residual"
        parts.append(f"{whose} enclosed in [−r, r] at {n['points']} points, "
                     f"r ≤ {_bound(n['enclosure'])}")
    how = [] if usual_stated else [f"seed {n['seed']}"]
    if not usual_stated or n["digits"] != ENGINE.numeric_digits:
        raised = " (precision raised where a ball was too wide)" \
            if n["digits"] > ENGINE.numeric_digits else ""
        how.append(f"{n['digits']} digits{raised}")
    if usual_stated and n["points"] != ENGINE.numeric_points:
        how.append(f"{n['points']} points")
    verdict = "certified" if n.get("certified") else "not certified"
    head = "Numeric backing (ball arithmetic" + (f", {', '.join(how)}" if how else "") + ")"
    return f"{head}: {'; '.join(parts)}; {verdict}." if parts else f"{head}: {verdict}."
