"""Decide every relation of a document: its errata.

Each relation the declarations plan (:mod:`.declarations`) is decided by
:func:`rigidsym.api.check_latex_run` with exactly the declarations it uses, so its verdict
is the verdict of ``rigidsym check --latex`` with those ``--let``s. A relation with a
symbol nothing declares is not given a verdict (``not-checked``, naming the symbols); a
LaTeX the reader refuses is ``not-checked`` with the reader's message. Records are kept in
the verdict store (:mod:`.store`), so a re-run re-checks only what changed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from rigidsym.core.errors import BadInput
from rigidsym.documents import conventions, store
from rigidsym.documents.declarations import CONVENTION_LETS, Plan, omitted_lines, plan, rate_line
from rigidsym.documents.document import Document, read_document
from rigidsym.reading import Reading, load_reading, sidecar

__all__ = ["DocumentResult", "VERDICTS", "check_document", "decide", "exit_code"]

#: a relation's verdicts: the engine's, ``convention-dependent`` (holds under one
#: convention the document leaves open, not under another), ``definition``, ``not-checked``
VERDICTS = ("verified", "does-not-hold", "convention-dependent", "definition", "undecided",
            "not-checked")


@dataclass
class DocumentResult:
    """A document's errata.

    Attributes:
        document: the document read.
        reading: its reading file (``None`` if none).
        records: one record per relation, in reading order (:func:`decide`'s keys).
        conventions: the reading's conventions, each with whether ``check_latex`` uses it.
        stored: how many records came from the verdict store.
        seconds: the wall time of the run.
        omitted: the reading's lines no relation is given, each once: ``{"let",
            "reason", "labels"}`` (:func:`rigidsym.documents.declarations.reading_lets`).
    """

    document: Document
    reading: Reading | None
    records: list[dict] = field(default_factory=list)
    conventions: list[str] = field(default_factory=list)
    stored: int = 0
    seconds: float = 0.0
    omitted: list[dict] = field(default_factory=list)

    def counts(self) -> dict[str, int]:
        """How many relations have each verdict."""
        out = dict.fromkeys(VERDICTS, 0)
        for r in self.records:
            out[r["verdict"]] += 1
        return out


def exit_code(result: DocumentResult) -> int:
    """1 if a relation does not hold, else 3 if one is not decided (or holds under one
    convention the document leaves open and not another), else 0."""
    c = result.counts()
    if c["does-not-hold"]:
        return 1
    return 3 if c["undecided"] or c["not-checked"] or c["convention-dependent"] else 0


def _counterexample(r) -> str:
    ce = r.counterexample or {}
    return "; ".join(f"{s.get('latex') or s.get('symbol')} = {s.get('text')}"
                     for s in ce.get("symbols", []))


def decide(p: Plan, options: dict) -> dict:
    """The record of one relation's plan, decided with ``options`` (``notation``,
    ``repairs``, ``repair_seconds``, ``timeout``)."""
    r = p.relation
    rec = {"file": r.file, "line": r.line, "column": r.column, "display": r.display,
           "index": r.index, "label": r.label, "latex": r.latex, "op": r.op,
           "kind": {"decide": "identity", "definition": "definition",
                    "skip": "not-checked"}[p.action],
           "lets": list(p.lets), "verdict": None, "method": None, "read_as": None,
           "counterexample": None, "corrected": None, "corrected_latex": None,
           "cause": None, "reason": None, "free": [], "under": None, "point": None}
    if p.action == "skip":
        return rec | {"verdict": "not-checked", "reason": p.reason}
    if p.action == "definition":
        return rec | {"verdict": "definition", "method": "document definition",
                      "reason": f"defines {p.defines} for the relations after it"}
    t = time.monotonic()
    out = rec | _decided(p.checked or r.latex, p.lets, options)
    if p.checked:
        out["reason"] = out["reason"] or (
            f"the reading prints ({r.label}) as a relation and declares {r.lhs}: checked "
            f"as {p.checked}")
    return out | {"seconds": round(time.monotonic() - t, 3)}


def _decided(latex: str, lets: list[str], options: dict) -> dict:
    """The verdict fields of ``latex`` checked with ``lets`` (stored, or computed)."""
    k = store.key(latex, lets, options)
    got = store.get(k)
    if got is not None:
        return got | {"stored": True}
    out = _check(latex, lets, options)
    store.put(k, out)
    return out | {"stored": False}


def _check(latex: str, lets: list[str], options: dict) -> dict:
    """The verdict fields of ``latex`` with ``lets``; under each admissible convention
    where it uses one nothing fixes (:mod:`.conventions`)."""
    out, notes, refusal = _check_once(latex, lets, options)
    keys = conventions.open_in(notes, refusal, lets, options["notation"])
    if not keys:
        return out
    outs = [(combo, _check_once(latex, list(lets) + more, options)[0])
            for combo, more in conventions.choices(keys)]
    return conventions.combine(keys, outs)


def _read_as_rate(glyph) -> bool:
    """Whether the reader read a symbol the reading declares a rate (``\\ddot X: second rate
    of X``) as a time derivative: not where it stands in a model as a glyph of its own (its
    row's meaning :data:`rigidsym.latex.shapes.UNDECLARED`), where it would be any matrix
    and a counterexample could rest on a rate no motion has."""
    from rigidsym.latex.shapes import UNDECLARED

    return getattr(glyph, "meaning", UNDECLARED) != UNDECLARED


def _introduced(key: str, glyph, latex: str, lets: list[str]) -> bool:
    """Whether a free symbol is one the reader introduced, not one the document wrote: a
    rotation's or a transform's body velocity ``X_{w}`` (``\\dot X = X [X_w]`` of a function of
    time ``X(t)``, any velocity: the relation holds for every one or it does not) that
    neither the relation nor a declaration writes; never an undeclared symbol of the
    document (fails closed: a text that cannot be read counts as writing it)."""
    from rigidsym.latex import LatexError
    from rigidsym.latex.declgraph import glyph_keys
    from rigidsym.latex.printed_point import body_velocities

    if not body_velocities({key: glyph}):
        return False
    for text in (latex, *(t.split(":", 1)[0] if ":" in t and "=" not in t else t
                          for t in lets)):
        try:
            if key in glyph_keys(text.replace(":=", "=")):
                return False
        except (LatexError, ValueError):
            return False
    return True


def _check_once(latex: str, lets: list[str], options: dict) -> tuple[dict, list[str],
                                                                       str | None]:
    """The verdict fields, the reading's notes and the engine's refusal (or ``None``)."""
    from rigidsym.api import check_latex_run
    from rigidsym.latex import LatexError

    said = {}  # a reading's \dot{X}: rate of X: the rate check_latex reads for X(t)
    for t in lets:
        rl = rate_line(t)
        if rl is not None:
            said[rl[0]] = t
    lets = [t for t in lets if t not in said.values()]
    try:
        r, reading = check_latex_run(latex, lets, None, (), options["repairs"], None,
                                     options["notation"], options["repair_seconds"],
                                     options["timeout"])
    except LatexError as exc:
        return {"verdict": "not-checked", "method": "not read",
                "reason": f"a construct not read: {str(exc).splitlines()[0]}"}, [], None
    except BadInput as exc:
        return {"verdict": "not-checked", "method": "bad declarations",
                "reason": str(exc).splitlines()[0]}, [], str(exc)
    except Exception:  # noqa: BLE001 -- the reader's internal error: never a verdict
        return {"verdict": "not-checked", "method": "internal error",
                "reason": "an internal error while reading this relation (never a verdict)"
                }, [], None
    out = {"verdict": r.verdict, "method": r.method,
           "read_as": reading.text if reading is not None else None}
    free = [f for f in (reading.free if reading is not None else [])
            if not (f in said and _read_as_rate(reading.rows.get(f)))
            and not _introduced(f, reading.rows.get(f), latex, lets)]
    notes = list(reading.notes) if reading is not None else []
    if free:
        return out | {"verdict": "not-checked", "method": "undeclared symbols", "free": free,
                      "reason": "undeclared: " + ", ".join(free) + " (declare each in the "
                                "reading file or with --let; never guessed)"}, notes, None
    if r.verdict == "undecided":
        out["reason"] = r.cause or r.detail or "undecided"
    if r.verdict == "does-not-hold":
        out["counterexample"] = _counterexample(r)
        out["point"] = [{"latex": x.get("latex") or x.get("symbol"), "value": x.get("text")}
                        for x in (r.counterexample or {}).get("symbols", [])]
        reps = r.repairs or []
        if reps:
            out["corrected"] = reps[0].get("text")
            out["corrected_latex"] = reps[0].get("latex")
            out["cause"] = "; ".join(reps[0].get("edits", []))
        else:
            words = [s.get("words") for s in (r.repair_search or []) if s.get("words")]
            out["cause"] = "no repair found" + (f" ({words[0]})" if words else "")
    return out, notes, None


def check_document(path: str | Path, *, reading: str | Path | None = None,
                   lets: list[str] | tuple[str, ...] = (), notation: str | None = None,
                   repairs: bool = True, repair_seconds: float | None = 10.0,
                   timeout: float | str | None = "default",
                   progress: Callable[[str], None] | None = None) -> DocumentResult:
    """Decide every displayed relation of the document at ``path``.

    Args:
        path: a Markdown (``.md``) or LaTeX (``.tex``) document.
        reading: its reading file; ``None``: the sidecar ``X.reading.toml`` beside it if
            there is one (:func:`rigidsym.reading.sidecar`), else none.
        lets: more declarations, in ``--let``'s words (after the reading's).
        notation: a book's symbol table (as ``check_latex``'s ``notation``).
        repairs, repair_seconds, timeout: as :func:`rigidsym.check_latex`'s.
        progress: called with one line per display (``None``: silent).

    Returns:
        The :class:`DocumentResult`: one record per relation, in reading order.

    Raises:
        BadInput: a document or reading file that cannot be read, a declaration that
            cannot be read (each naming the file and line or key).
    """
    t0 = time.monotonic()
    doc = read_document(path)
    if reading is None and sidecar(path).is_file():
        reading = sidecar(path)
    rd = load_reading(reading) if reading is not None else None
    options = {"notation": notation, "repairs": repairs, "repair_seconds": repair_seconds,
               "timeout": timeout}
    result = DocumentResult(doc, rd)
    if rd is not None:
        for key, value in rd.conventions.items():
            used = (key, value) in CONVENTION_LETS
            result.conventions.append(f"{key} = {value}" + (
                f" (as --let '{CONVENTION_LETS[(key, value)]}')" if used else
                " (said back; no relation's check depends on it)"))
    plans = plan(list(doc.relations), rd, list(lets))
    if rd is not None:
        result.omitted = omitted_lines(rd, [r.label for r in doc.relations])
    by_display: dict[int, list[Plan]] = {}
    for p in plans:
        by_display.setdefault(p.relation.display, []).append(p)
    try:
        for d in doc.displays:
            t = time.monotonic()
            for p in by_display.get(d.number, []):
                rec = decide(p, options)
                result.stored += bool(rec.pop("stored", False))
                result.records.append(rec)
            if progress is not None:
                n = len(by_display.get(d.number, []))
                progress(f"display {d.number}/{len(doc.displays)} ({d.source.file}:{d.line}): "
                         f"{n} relation{'s' * (n != 1)}, {time.monotonic() - t:.1f} s")
    except KeyboardInterrupt:  # keep what was decided
        if progress is not None:
            progress(f"interrupted: {len(result.records)} of {len(plans)} relations decided")
    for key in conventions.CHOICES:
        n = sum(1 for rec in result.records
                if rec.get("under") and any(conventions.NAMES[(key, v)] in w
                                            for w in rec["under"] for v in
                                            conventions.CHOICES[key]))
        if n:
            result.conventions.append(
                f"{key}: not fixed by the document; {n} relation{'s' * (n != 1)} that "
                f"use{'s' * (n == 1)} it decided under each of "
                f"{', '.join(conventions.CHOICES[key])}")
    result.seconds = time.monotonic() - t0
    return result
