"""The repair search's records (schema 2): one per repair found and one per member searched,
in words that never guess."""

from __future__ import annotations

import re

from rigidsym.checking.repairing import mutate
from rigidsym.checking.repairing.repair import Found, Search
from rigidsym.core.settings import ENGINE
from rigidsym.printing import notation
from rigidsym.registry.declarations import Rel

__all__ = ["repair_record", "search_record"]

_BOUND = re.compile(r"P\(false zero\) <= ([0-9.]+E[-+]?\d+)")


def _bound(detail: str) -> float | None:
    found = [float(x) for x in _BOUND.findall(detail or "")]
    return max(found) if found else None


def repair_record(f: Found, printed: Rel, keep: set, equals_declared: bool) -> dict:
    """The schema-2 record of one repair.

    Returns:
        ``{"member", "edits", "kinds", "text", "latex", "printed_text", "printed_latex",
        "method", "failure_bound", "equals_declared"}``: ``edits`` in words and ``kinds``
        (:data:`rigidsym.checking.repairing.mutate.KINDS`); ``text``/``latex`` are the
        repaired member in book notation with each edited subterm marked (``⟦…⟧``,
        ``\\boxed{…}``), and
        ``printed_text``/``printed_latex`` the printed member with the subterms the edits
        change marked.
    """
    lm, rm = mutate.apply_edits(printed, f.edits, "marked", keep)
    lp, rp = mutate.apply_edits(printed, f.edits, "printed", keep)
    return {"member": printed.label, "edits": [mutate.describe(e) for e in f.edits],
            "kinds": [e.kind for e in f.edits],
            "text": f"{notation.text(lm)} = {notation.text(rm)}",
            "latex": notation.latex_relation(lm, rm),
            "printed_text": f"{notation.text(lp)} = {notation.text(rp)}",
            "printed_latex": notation.latex_relation(lp, rp),
            "method": f.method, "failure_bound": _bound(f.detail),
            "equals_declared": equals_declared}


def search_record(s: Search, budget: int) -> dict:
    """What was searched for one member, in words that never guess.

    Returns:
        ``{"member", "candidates", "found", "complete", "undecidable", "budget",
        "words"}``: ``words`` is "no repair within 2 edits" only when every single edit and
        pair of the vocabulary was tried (and says how many of them the zero test cannot
        decide, such as an odd power of ``‖ω‖``), else "none in the first N candidates".
    """
    n = len(s.found)
    if n:
        kind = "one-edit" if s.depth == 1 else "two-edit"
        words = (f"{n} {kind} repair{'s' if n > 1 else ''} found in {s.candidates} "
                 f"candidates" + (f" ({ENGINE.keep} kept)" if n > ENGINE.keep else ""))
    elif s.complete:
        words = (f"no repair within 2 edits ({s.candidates} candidates: every single edit "
                 f"and pair of the vocabulary"
                 + (f"; {s.undecidable} of them beyond the zero test" if s.undecidable
                    else "") + ")")
    else:
        words = f"none in the first {s.candidates} candidates"
        if s.stopped == "full tests":
            words += f" ({ENGINE.full_tests} full zero tests spent)"
        if s.stopped == "time":
            words = (f"search stopped after {s.limit:g} s, {s.candidates} candidates tried "
                     f"(--repair-seconds)")
    return {"member": s.member, "candidates": s.candidates, "found": n,
            "complete": s.complete, "undecidable": s.undecidable, "budget": budget,
            "words": words}
