"""Reports of checker results: the schema-2 record, JSON, and the chapter reports.

The record of one result (:func:`result_record`) is the single source of every output: the
JSON (``chapter3.json``, ``verify --json``), the Markdown (:mod:`rigidsym.report.markdown`), the
HTML (:mod:`rigidsym.report.html`) and ``rigidsym show``. The committed reports hold no
timings, so they are deterministic.
"""

from __future__ import annotations

import json
import re
from collections import Counter

import sympy as sp

from rigidsym.checking.checker import Outcome
from rigidsym.printing import notation
from rigidsym.registry.declarations import USER_CAUSE_DEFAULT, VERDICTS, is_user_id
from rigidsym.report.repairs import repair_fields

__all__ = ["summary", "cause_counts", "cause_line", "result_record", "to_json", "cause_words",
           "cause_sentence", "origin_shown", "UNATTRIBUTED",
           "page_reading", "failure_bound", "CITATION", "TITLE", "SCHEMA", "RESIDUAL_FLOOR",
           "document_header"]

CITATION = ("J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Springer, "
            "Chap. 3")
#: the title of the chapter's report (a user report is titled by its module)
TITLE = "Chapter 3 checked: verdicts"
#: version of the JSON record; 2 added per-member records, the model in words, the cause
#: class and the counterexample's residual and decimals, and moved expanded values to
#: ``full`` documents.
SCHEMA = 2

#: In the committed report a residual below this is shown as this bound: the last digits
#: of a 50-digit evaluation depend on evaluation order, which is not ours to fix.
RESIDUAL_FLOOR = 1e-40

#: the cause classes in words (``cause`` is the declared value, ``cause_class`` these words)
_CAUSE_CLASS = {"conversion": "a slip in the text's conversion (from the printed book to "
                              "text and LaTeX)",
                "erratum": "an erratum (the book's own error)"}
_BOUND = re.compile(r"P\(false zero\) <= ([0-9.]+E[-+]?\d+)")


def summary(results: list[Outcome]) -> dict[str, int]:
    """Counts per verdict (every verdict listed, zeros included)."""
    c = Counter(r.verdict for r in results)
    return {v: c.get(v, 0) for v in VERDICTS}


#: the does-not-hold counted by origin: the book's errata, the conversion's slips, and
#: those the declarations attribute to neither (a printed copy of the book decides)
CAUSE_KEYS = (("erratum", "errata of the book"),
              ("conversion", "slips of the text's conversion"),
              ("unattributed", "not attributed to the book or the conversion"))

#: the origin of a does-not-hold the declaration attributes to neither class
UNATTRIBUTED = "not a known slip of the text's conversion nor a known erratum"


def cause_counts(results: list[Outcome]) -> dict[str, int]:
    """The does-not-hold counted by origin: ``{"erratum": n, "conversion": n,
    "unattributed": n}`` (a user id's own cause counts as unattributed)."""
    c = Counter((r.cause if r.cause in ("erratum", "conversion") else "unattributed")
                for r in results if r.verdict == "does-not-hold")
    return {k: c.get(k, 0) for k, _ in CAUSE_KEYS}


def cause_line(results: list[Outcome]) -> str:
    """``4 errata of the book, 4 slips of the text's conversion, 3 not attributed to the
    book or the conversion`` (a zero count is left out, unless every count is zero)."""
    c = cause_counts(results)
    one = {"erratum": "erratum of the book", "conversion": "slip of the text's conversion",
           "unattributed": "not attributed to the book or the conversion"}
    parts = [f"{c[k]} {one[k] if c[k] == 1 else words}" for k, words in CAUSE_KEYS if c[k]]
    return ", ".join(parts or [f"0 {CAUSE_KEYS[0][1]}"])


def _transcription(r: Outcome) -> dict | None:
    """The printed form checked against the LaTeX, or ``None`` for an id that
    gives no LaTeX or is not registered: read from the user cache, computed only when no
    record is stored (:func:`rigidsym.latex.transcription.transcription_for`)."""
    from rigidsym.latex.transcription import transcription_for

    return transcription_for(r.id)


def transcription_extra():
    """The transcription records as the runner's work beside each verdict
    (:class:`rigidsym.checking.runner.Extra`): computed in the worker that builds the
    declaration, read from the user cache otherwise; never built again in the parent."""
    from rigidsym.checking.runner import Extra
    from rigidsym.latex.transcription import (
        cached_transcriptions,
        remember,
        transcription_for,
    )

    return Extra(missing=cached_transcriptions, compute=transcription_for, keep=remember)


def _bounded(x):
    return RESIDUAL_FLOOR if isinstance(x, float) and x < RESIDUAL_FLOOR else x


def cause_words(r: Outcome) -> tuple[str, str]:
    """The origin of a does-not-hold and its cause: what is wrong, as the declaration says.

    Returns:
        ``(origin, cause)``: origin is ``a slip in the text's conversion (...)``, ``an
        erratum (...)``, a user's own class, or :data:`UNATTRIBUTED`; cause is the
        declared evidence (for a conversion slip followed by its page reading), else the
        checker's decision. ``("", "")`` for any other verdict.
    """
    if r.verdict != "does-not-hold":
        return "", ""
    known = r.evidence or r.detail
    if r.cause in _CAUSE_CLASS:
        reading = page_reading(r) if r.cause == "conversion" else ""
        if reading and not known.rstrip().endswith((".", "?", "!")):
            known = known.rstrip() + "."
        return _CAUSE_CLASS[r.cause], known + reading
    if is_user_id(r.id):  # a user's own words for the class, if any
        own = r.cause not in (None, "", "unknown", USER_CAUSE_DEFAULT)
        return (r.cause if own else UNATTRIBUTED), known
    return UNATTRIBUTED, known


def cause_sentence(r: Outcome) -> str:
    """One line for a reader: ``Cause: <what is wrong>. Origin: <erratum, slip of the
    conversion, or neither known>.`` (a user's equation: its own class, if it declares one);
    ``""`` for any other verdict than does-not-hold."""
    origin, why = cause_words(r)
    if not origin:
        return ""
    why = why.rstrip()
    said = f"Cause: {why}{'' if why.endswith(('.', '?', '!')) else '.'}"
    if is_user_id(r.id) and origin == UNATTRIBUTED:  # the book's classes: not a user's
        return said
    return f"{said} Origin: {origin}."


def origin_shown(rec: dict) -> str:
    """The origin a page prints for a record: its ``cause_class``, but nothing for a user's
    equation the book's classes do not fit (one that declares no class of its own)."""
    cls = rec.get("cause_class") or ""
    return "" if is_user_id(rec["id"]) and cls == UNATTRIBUTED else cls


def page_reading(r: Outcome) -> str:
    """For a conversion slip, one sentence on its declared page reading (a conjecture about
    the printed page, the source being a converted text), as decided in
    the book's reading (:func:`rigidsym.checking.certifying.certificates.page_reading`):
    ``verified`` only where every corrected member of ``r`` holds; ``""`` for an undecided
    reading."""
    from rigidsym.checking.certifying.certificates import page_reading as decided_reading

    decided = decided_reading(r.id)
    corrected = [m for m in r.members if m.get("role") == "corrected"]
    head = (" The page reading: the declared reading of the printed page (a conjecture, the "
            "source being a converted text)")
    if decided.startswith("verified: ") and corrected and \
            all(m.get("status") == "holds" for m in corrected):
        return f"{head} is verified: {decided.removeprefix('verified: ')}."
    if decided.startswith("its own erratum: "):
        return f"{head} is its own erratum: {decided.removeprefix('its own erratum: ')}."
    return ""


def failure_bound(r: Outcome) -> float | None:
    """The largest Schwartz-Zippel failure probability bound behind the verdict, if any."""
    texts = [r.detail] + [m["detail"] for m in r.members if m["status"] == "holds"]
    found = [float(x) for t in texts for x in _BOUND.findall(t or "")]
    return max(found) if found else None


def _decimal(value: str) -> str:
    try:
        v = sp.sympify(value)
        if v.is_Integer:
            return str(v)
        return f"{float(sp.N(v, 17)):.8g}" if v.is_number else ""
    except (sp.SympifyError, TypeError):
        return ""


def _atom_text(name: str) -> str:
    """An atom's ``sstr`` (``Derivative(e_1(t), t)``, ``phi(t)``, ``s34_adot_1``) in book
    notation."""
    m = re.fullmatch(r"Derivative\((\w+)\(t\), (?:t, 2|\(t, 2\))\)", name)
    if m:
        return notation.book_text(m.group(1) + "_ddot")
    m = re.fullmatch(r"Derivative\((\w+)\(t\), t\)", name)
    if m:
        return notation.book_text(m.group(1) + "_dot")
    m = re.fullmatch(r"(\w+)\(t\)", name)
    return notation.book_text(m.group(1) if m else name)


def counterexample_record(ce: dict | None) -> dict | None:
    """The counterexample with book names, decimals, the residual and its largest entry;
    ``symbols`` (the book symbols of the failing member there, exact and decimal) and
    ``chosen`` (how the point was chosen) as :mod:`rigidsym.checking.deciding.counterexample` gave
    them."""
    if not ce:
        return None
    point = [{"atom": k, "book": _atom_text(k), "exact": v, "decimal": _decimal(v)}
             for k, v in ce["point"].items()]
    out = {"member": ce.get("member", ""), "point": point, "lhs": ce["lhs"], "rhs": ce["rhs"],
           # the book's symbols there and how the point was chosen
           # (rigidsym.checking.deciding.counterexample)
           "symbols": ce.get("symbols", []), "chosen": ce.get("chosen")}
    res = ce.get("residual")
    if res is not None:
        out["residual"] = res
        entries = sp.sympify(res)
        entries = list(entries) if isinstance(entries, sp.MatrixBase) else [entries]
        # exact rationals, or closed forms where a bare angle enters (4 atan(2/3))
        worst = max((abs(sp.sympify(x)) for x in entries), key=lambda x: float(sp.N(x, 30)))
        out["residual_max_abs"] = str(worst)
        out["residual_max_abs_decimal"] = _decimal(str(worst))
    else:
        out["residual"] = None
    return out


def result_record(r: Outcome, timings: bool = True, full: bool = False) -> dict:
    """The schema-2 record of one result (plain data, JSON-ready).

    Args:
        r: a checker result.
        timings: keep ``seconds``; ``False`` (committed reports) drops it and bounds tiny
            residuals by :data:`RESIDUAL_FLOOR`, so that the record is byte-stable.
        full: add the expanded first-principles values (``printed``, ``derived``,
            ``corrected`` as sympy strings), which can be hundreds of kilobytes.

    Returns:
        A dict with the keys documented in the README ("JSON schema 2").
    """
    cls, why = cause_words(r)
    numeric = dict(r.numeric)
    if not timings:
        numeric["max_residual"] = _bounded(numeric.get("max_residual"))
        if "enclosure" in numeric:
            numeric["enclosure"] = _bounded(numeric["enclosure"])
    rec = {
        "id": r.id, "title": r.title, "section": r.section, "kind": r.kind,
        "verdict": r.verdict, "expected": r.expected, "method": r.method,
        "failure_bound": failure_bound(r), "decision": r.detail,
        "printed_latex": r.printed_latex, "members": r.members,
        "failing_member": r.failing_member,
        "cause": r.cause if r.verdict == "does-not-hold" else None,
        "cause_class": cls or None, "evidence": why or None,
        "counterexample": counterexample_record(r.counterexample),
        "singular": r.singular, "model": r.model, "numeric": numeric,
        # the printed form checked against the LaTeX (additive to schema 2)
        "transcription": _transcription(r),
    }
    rec.update(repair_fields(r))  # correction, repairs, repair_search
    if timings:
        rec["seconds"] = r.seconds
        rec["cached"] = getattr(r, "cached", False)
    if full:
        rec.update(printed=r.printed, derived=r.derived, corrected=r.corrected)
    return rec


def document_header() -> dict:
    """The head of a schema-2 document: ``{"schema": 2, "python_flint": version}`` (the
    library of the exact engine and of the ball-arithmetic backing)."""
    from rigidsym.checking.deciding.balls import flint_version

    return {"schema": SCHEMA, "python_flint": flint_version()}


def to_json(results: list[Outcome], timings: bool = True, full: bool = False) -> str:
    """The JSON document ``{"schema": 2, "python_flint": ..., "equations": [...],
    "summary": {...}}``.

    ``timings=False`` (the committed report) drops the seconds and bounds tiny residuals;
    ``full=True`` adds the expanded values (``chapter3-full.json``).
    """
    rows = [result_record(r, timings=timings, full=full) for r in results]
    return dumps({**document_header(), "equations": rows, "summary": summary(results),
                  "does_not_hold_by_cause": cause_counts(results)}) + "\n"


def dumps(doc, indent: int = 0) -> str:
    """``doc`` as JSON, one member per line, indented by one space per level, but a list or
    an object of plain values (a member record, a point of a counterexample, a
    transcription's match) on one line: the same document as ``json.dumps(doc,
    indent=1)``, a tenth shorter (``chapter3.json`` under 400 KB with the transcription
    records)."""
    inner = (doc.values() if isinstance(doc, dict) else doc) \
        if isinstance(doc, dict | list) else None
    if inner is None or not any(isinstance(v, dict | list) for v in inner):
        return json.dumps(doc, ensure_ascii=False)
    pad = " " * (indent + 1)
    if isinstance(doc, dict):
        items = [f"{pad}{json.dumps(k, ensure_ascii=False)}: {dumps(v, indent + 1)}"
                 for k, v in doc.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    items = [pad + dumps(v, indent + 1) for v in doc]
    return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"


