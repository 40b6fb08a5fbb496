"""The checker's outcome for one id (:class:`Outcome`): plain data, the JSON row of
``rigidsym verify --json``: what :mod:`rigidsym.checking.checker` computes, kept apart from
how it is computed (the checker re-exports it: ``rigidsym.checking.checker.Outcome`` is this
class).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

__all__ = ["Outcome"]


@dataclass
class Outcome:
    """The checker's outcome for one id (the JSON row of ``rigidsym verify --json``).

    The public :class:`rigidsym.Result` is this with notebook display and the schema-2
    record (:mod:`rigidsym.api`, a layer above the checker).
    """

    id: str
    title: str
    kind: str
    verdict: str
    expected: str
    method: str
    printed_latex: str
    #: the expanded strings (printed, derived from first principles, corrected): ``None``
    #: when the check was asked not to print them (``check(..., expanded=False)``)
    printed: str | None
    derived: str | None
    corrected: str | None
    counterexample: dict | None
    cause: str | None
    numeric: dict
    seconds: float
    section: str = ""
    evidence: str | None = None
    detail: str = ""
    singular: str | None = None
    failing_member: str | None = None
    #: one record per member (printed, claim, corrected), see
    #: :func:`rigidsym.checking.deciding.records.member_record`
    members: list[dict] = field(default_factory=list)
    #: the model's atoms and their constraints, in words ("e: unit vector, ...")
    model: list[str] = field(default_factory=list)
    #: read from the verdict cache (a run field, like ``seconds``: not in written reports)
    cached: bool = False
    #: for a does-not-hold, the verified repairs of its failing members (schema-2 records,
    #: :func:`rigidsym.checking.repairing.records.repair_record`), at most ``ENGINE.keep``
    #: per member
    repairs: list[dict] = field(default_factory=list)
    #: what the repair search tried per failing member, and in words what it found
    repair_search: list[dict] = field(default_factory=list)
    #: where the correction comes from (:data:`rigidsym.checking.repairing.correction.CORRECTIONS`),
    #: ``None`` when nothing fails
    correction: str | None = None

    def as_json(self) -> dict:
        """Every field as a plain dict (the full record; the lean schema-2 row is
        :func:`rigidsym.report.record.result_record`)."""
        return asdict(self)
