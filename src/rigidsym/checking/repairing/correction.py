"""What a does-not-hold carries besides its exact counterexample: a correction and repairs.

**The verdict follows the counterexample.** A member with an exact counterexample does not
hold, whether or not a correction is known. A correction is additional evidence:

- a declared ``corrected=`` must verify; one that does not leaves the verdict
  ``undecided`` (the declaration itself is faulty, and the detail says so);
- with no ``corrected=``, the first repair the search finds for each failing member
  (:mod:`rigidsym.checking.repairing.repair`) serves as the corrected form, marked "found by
  search";
- with neither, the record says "no correction", with what was searched in the words of
  :func:`rigidsym.checking.repairing.records.search_record` (never a guess).

The repair search runs for every does-not-hold (``repairs=False`` turns it off); its
budget is the run's when given, else the declaration's, else
``ENGINE.repair_budget``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

from rigidsym.checking.deciding.records import member_record
from rigidsym.checking.repairing import deadline as deadline_
from rigidsym.checking.repairing import records as records_
from rigidsym.checking.repairing import repair
from rigidsym.core.settings import ENGINE
from rigidsym.registry.declarations import Rel

__all__ = ["Correction", "RepairSettings", "correct", "budget_of", "CORRECTIONS"]

#: the values of ``checker.Outcome.correction`` for a does-not-hold (or an undecided whose
#: declared correction fails)
CORRECTIONS = ("declared", "declared, does not verify", "found by search", "none",
               "none (search off)")


@dataclass(frozen=True)
class RepairSettings:
    """The run's repair settings: whether to search, and the budget (``None``: the
    declaration's, else the default)."""

    enabled: bool = True
    budget: int | None = None
    seconds: float | None = None  # a time limit of the search per statement


def budget_of(eq, settings: RepairSettings) -> int:
    """The candidates per failing member for ``eq`` under ``settings``."""
    if settings.budget is not None:
        return settings.budget
    own = getattr(eq, "repair_budget", None)
    return ENGINE.repair_budget if own is None else own


@dataclass
class Correction:
    """The correction of a does-not-hold.

    Attributes:
        kind: one of :data:`CORRECTIONS`.
        holds: False when a declared correction does not verify (then ``undecided``).
        detail: the words that follow the failure in the result's detail.
        backing: the relations the numeric check evaluates (the corrected form).
        members: member records of the corrected form.
        corrected: the corrected form as text (``checker.Outcome.corrected``), or ``None``.
        repairs: the repair records (schema 2), every failing member's, in member order.
        searches: what was searched per failing member.
    """

    kind: str
    holds: bool = True
    detail: str = ""
    backing: list = field(default_factory=list)
    members: list = field(default_factory=list)
    corrected: str | None = None
    repairs: list = field(default_factory=list)
    searches: list = field(default_factory=list)


def _declared_partner(label: str, n_printed: int, corrected: list[Rel]) -> list[Rel]:
    """The declared members a repaired member is compared with: the one of its label when
    the counts agree, else each (3.97b: one printed member, two corrected)."""
    same = [c for c in corrected if c.label == label]
    return same if same and len(corrected) == n_printed else list(corrected)


def _search(eq, st, rels, outs, seed, settings, decide) -> tuple[list, list, dict]:
    """Run the search for every failing member: ``(searches, repair records, first repair
    of each member label)``."""
    failing = [r for r, o in zip(rels, outs, strict=True) if o.zero is False]
    budget = budget_of(eq, settings)
    limit = settings.seconds or 0.0
    deadline = time.monotonic() + limit if settings.seconds else None
    searches, records, first = [], [], {}
    try:
        with deadline_.time_limit(deadline):  # a step past the deadline is stopped
            sh = repair.share(failing, rels, st.model, decide, seed)
            for rel in failing:
                s = repair.search_member(rel, sh, budget, deadline, limit)
                searches.append(records_.search_record(s, budget))
                for f in s.found[:ENGINE.keep]:
                    partners = _declared_partner(rel.label, len(st.printed),
                                                 st.corrected or [])
                    equal = deadline is None or time.monotonic() < deadline
                    equal = equal and any(repair.same_relation(
                        sh.generic, f.rel_sides, (c.lhs, c.rhs)) for c in partners)
                    records.append(records_.repair_record(f, rel, sh.pools.keep, equal))
                if s.found:
                    first[id(rel)] = s.found[0]
    except deadline_.Late:  # in the shared part or between members: the rest not searched
        for rel in failing[len(searches):]:
            s = repair.Search(member=rel.label, limit=limit, stopped="time")
            searches.append(records_.search_record(s, budget))
    return searches, records, first


def correct(eq, st, outs: list, seed: int, settings: RepairSettings, decide: Callable,
            combine: Callable, rel_text: Callable) -> Correction:
    """The correction and repairs of a statement some printed member or claim of which has
    an exact counterexample.

    Args:
        eq: the declaration (its ``repair_budget``).
        st: its statement.
        outs: the decisions of ``st.printed + st.claims``, in that order.
        seed: the id's seed.
        settings: the run's :class:`RepairSettings`.
        decide: the checker's ``decide_rel``.
        combine: the checker's combination of decisions, ``-> (zero, method, detail)``.
        rel_text: relations to text (``checker.Outcome.corrected``).
    """
    rels = st.printed + st.claims
    searches, records, first = [], [], {}
    if settings.enabled:
        try:
            searches, records, first = _search(eq, st, rels, outs, seed, settings, decide)
        except Exception:  # noqa: BLE001  a repair never changes a verdict; its text
            # is internal and never reaches a message
            searches = [{"member": "", "candidates": 0, "found": 0, "complete": False,
                         "undecidable": 0, "budget": budget_of(eq, settings),
                         "words": "the search stopped at an internal error (the "
                                  "verdict does not depend on it)"}]
    out = Correction(kind="none", repairs=records, searches=searches)
    if st.corrected:
        return _declared(out, st, seed, decide, combine)
    failing = [r for r, o in zip(rels, outs, strict=True) if o.zero is False]
    if settings.enabled and failing and all(id(r) in first for r in failing):
        return _found(out, rels, first, rel_text)
    if not settings.enabled:
        out.kind, out.detail = "none (search off)", "no corrected form declared (repair " \
                                                    "search off)"
        return out
    words = "; ".join(s["words"] + (f" for {s['member']!r}" if s["member"] else "")
                      for s in searches if not s["found"])
    out.detail = f"no correction declared or found: {words}"
    return out


def _declared(out: Correction, st, seed: int, decide: Callable, combine: Callable) -> Correction:
    couts = [decide(r, st.model, seed + 100 + i) for i, r in enumerate(st.corrected)]
    out.members = [member_record(r, "corrected", o)
                   for r, o in zip(st.corrected, couts, strict=True)]
    out.backing = list(st.corrected)
    cz, cm, cd = combine(couts)
    if not cz:
        out.kind, out.holds = "declared, does not verify", False
        out.detail = (f"the printed form does not hold (exact counterexample), and the "
                      f"declared corrected form did not verify ({cm}: {cd})")
    else:
        out.kind, out.detail = "declared", f"corrected form verified by {cm}"
    return out


def _found(out: Correction, rels: list, first: dict, rel_text: Callable) -> Correction:
    """The corrected form from the search: each failing member replaced by its first
    repair, the members that hold kept."""
    fixed = []
    for r in rels:
        f = first.get(id(r))
        fixed.append(f.rel if f is not None else r)
        if f is not None:
            rec = member_record(f.rel, "corrected",
                                repair.Decision(True, f.method, f.detail))
            rec["origin"] = "search"
            out.members.append(rec)
    out.kind, out.backing = "found by search", fixed
    out.corrected = rel_text([f.rel for f in first.values()])
    methods = sorted({f.method for f in first.values()})
    out.detail = f"corrected form found by search, verified by {', '.join(methods)}"
    return out
