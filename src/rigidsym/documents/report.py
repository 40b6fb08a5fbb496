"""A document's errata as text, JSON and Markdown.

The JSON (``rigidsym check FILE --json``) is one object: ``{"format": 1, "document",
"reading", "conventions", "counts", "seconds", "stored", "omitted", "relations": [...]}``,
one record per relation with the keys of :data:`FIELDS` (``docs/check-documents.md``);
``omitted`` lists the reading's lines no relation is given, each with why.
"""

from __future__ import annotations

import json

from rigidsym.documents.checking import VERDICTS, DocumentResult

__all__ = ["FIELDS", "as_json", "as_markdown", "as_text", "summary"]

#: the keys of a relation's record
FIELDS = ("file", "line", "column", "display", "index", "label", "latex", "op", "kind",
          "verdict", "method", "read_as", "counterexample", "corrected", "corrected_latex",
          "cause", "reason", "free", "under", "point", "lets", "seconds")
_WORDS = {"verified": "verified", "does-not-hold": "DOES NOT HOLD",
          "convention-dependent": "holds under one convention",
          "definition": "definition", "undecided": "undecided", "not-checked": "not checked"}


def summary(res: DocumentResult) -> str:
    """The report's first line: the document, its relations and displays, the counts."""
    c = res.counts()
    parts = [f"{c[v]} {_WORDS[v].lower()}" + ("s" if v == "definition" and c[v] != 1 else "")
             for v in VERDICTS if c[v]]
    return (f"{res.document.path}: {len(res.records)} relations in "
            f"{len(res.document.displays)} displays: {', '.join(parts) or 'none'}")


def _detail(rec: dict) -> list[str]:
    out = []
    if rec["verdict"] == "does-not-hold":
        out.append(f"counterexample: {rec['counterexample'] or '(none printed)'}")
        if rec["corrected"]:
            out.append(f"corrected: {rec['corrected']}   ({rec['cause']})")
        elif rec["cause"]:
            out.append(rec["cause"])
        if rec.get("under"):
            out.append(rec["reason"])
    elif rec["reason"] and (rec["verdict"] != "verified" or rec.get("under")):
        out.append(rec["reason"])
    return out


def as_text(res: DocumentResult) -> str:
    """One line per relation, grouped by display, each with ``FILE:LINE``."""
    lines = [summary(res)]
    if res.reading is not None:
        lines.append(f"reading: {res.reading.path}")
    lines += [f"convention: {c}" for c in res.conventions]
    lines += [f"reading line not given: {x['let']}  ({x['reason']}; for "
              f"{', '.join(x['labels'])})" for x in res.omitted]
    shown = None
    for rec in res.records:
        if rec["display"] != shown:
            shown = rec["display"]
            d = res.document.displays[shown - 1]
            lines.append(f"display {shown} ({d.source.file}:{d.line})")
        label = f" ({rec['label']})" if rec["label"] else ""
        lines.append(f"  {rec['file']}:{rec['line']}{label}  {rec['latex']}  "
                     f"{_WORDS[rec['verdict']]}")
        lines += [f"      {x}" for x in _detail(rec)]
    if res.stored:
        lines.append(f"({res.stored} of {len(res.records)} from the verdict store)")
    return "\n".join(lines)


def as_json(res: DocumentResult) -> str:
    """The errata as JSON (the module's schema)."""
    return json.dumps({
        "format": 1, "document": str(res.document.path),
        "reading": str(res.reading.path) if res.reading is not None else None,
        "conventions": res.conventions, "counts": res.counts(),
        "seconds": round(res.seconds, 3), "stored": res.stored, "omitted": res.omitted,
        "relations": [{k: rec.get(k) for k in FIELDS} for rec in res.records]},
        indent=1, ensure_ascii=False)


def _cell(text: str | None) -> str:
    return (text or "").replace("|", "\\|").replace("\n", " ")


def as_markdown(res: DocumentResult) -> str:
    """The errata as a Markdown table per display, the counterexample and the correction
    under a relation that does not hold."""
    out = [f"# Errata of `{res.document.path}`", "", summary(res), ""]
    out += [f"- convention: {c}" for c in res.conventions]
    out += [f"- reading line not given: `{x['let']}` ({x['reason']}; for "
            f"{', '.join(x['labels'])})" for x in res.omitted]
    shown = None
    for rec in res.records:
        if rec["display"] != shown:
            shown = rec["display"]
            d = res.document.displays[shown - 1]
            out += ["", f"## Display {shown} ({d.source.file}:{d.line})", "",
                    "| place | relation | verdict | detail |", "|---|---|---|---|"]
        out.append(f"| {rec['file']}:{rec['line']} | ${_cell(rec['latex'])}$ | "
                   f"{_WORDS[rec['verdict']]} | {_cell('; '.join(_detail(rec)))} |")
    return "\n".join(out) + "\n"
