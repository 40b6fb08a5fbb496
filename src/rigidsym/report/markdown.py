"""The chapter report in Markdown (rendered by GitHub and GitLab), from schema-2 records.

The lean report (committed) carries the same content as the HTML report and no expanded
component dumps; ``full=True`` adds them (``chapter3-full.md``, never committed).
"""

from __future__ import annotations

import re

from rigidsym.checking.checker import Outcome
from rigidsym.core.settings import ENGINE
from rigidsym.latex.transcription import transcription_words
from rigidsym.printing.labels import label_text, latex_spans
from rigidsym.report.counterexample import markdown_lines, sides_of, whose_symbols
from rigidsym.report.numeric import numeric_sentence
from rigidsym.report.record import (
    CITATION,
    TITLE,
    cause_line,
    origin_shown,
    result_record,
    summary,
)
from rigidsym.report.repairs import markdown_errata, markdown_repairs

__all__ = ["to_markdown", "anchor", "sections", "how_checked", "numeric_words",
           "prose_markdown"]


def anchor(eq_id: str) -> str:
    """The anchor of an equation in the reports (``eq-3.96e``)."""
    return f"eq-{eq_id}"


def sections(records: list[dict]) -> list[tuple[str, list[dict]]]:
    """Records grouped by book section (``3.4.1`` -> ``3.4``), in book order."""
    out: dict[str, list[dict]] = {}
    for rec in records:
        out.setdefault(".".join(rec["section"].split(".")[:2]), []).append(rec)
    return list(out.items())


def _cell(text: str) -> str:
    return (text or "").replace("|", "\\|").replace("\n", " ")


def prose_markdown(text: str | None) -> str:
    """Running text of a declaration (evidence) for Markdown: LaTeX pieces as ``$...$``
    maths (rendered by GitHub, GitLab and the HTML page), ASCII mathematics in book
    notation (:func:`rigidsym.printing.labels.label_text`)."""
    return "".join(f"${p}$" if is_tex else label_text(p) for is_tex, p in latex_spans(text or ""))


def _code(text: str) -> str:
    return "`" + (text or "").replace("`", "'") + "`"


def undecided_reasons(rec: dict) -> list[str]:
    """Why a result is undecided, one line per undecided member (``relation 1: irrational
    root at the sample point``), or the check's own reason when no member got a status (a
    check that raised): printed by ``show``, ``check`` and the reports, never only in the
    JSON."""
    out = [f"{label_text(m['label']) or m['role']}: {m['detail'] or 'no reason recorded'}"
           for m in rec["members"] if m["status"] == "undecided"]
    if rec["verdict"] == "undecided" and not out:
        out = [rec["decision"] or "no reason recorded"]
    # the deciders' reasons quote sympy's strings: powers and roots as a reader writes them
    sup = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
    return [re.sub(r"\*\*(\d+)", lambda m: m.group(1).translate(sup),
                   why.replace("sqrt(", "√(")) for why in out]


def _members(rec: dict) -> list[str]:
    out = []
    for m in rec["members"]:
        who = [m["role"]] if m["role"] != "printed" else []
        who += [f"*{_cell(label_text(m['label']))}*"] if m["label"] else []
        how = f" ({m['method']})" if m["status"] in ("holds", "fails") and \
            m["method"] != rec["method"] else ""  # the verdict line names the common method
        form = f" {_code(m['text'])}" if m["text"] else " (long explicit form: see the full report)"
        why = f" (why: {m['detail'] or 'no reason recorded'})" \
            if m["status"] == "undecided" else ""
        out.append(f"- {' '.join(who) + ': ' if who else ''}**{m['status']}**{how}{form}{why}")
    if rec["verdict"] == "undecided" and not rec["members"]:
        out.append(f"- undecided: {undecided_reasons(rec)[0]}")
    return out


def numeric_words(n: dict) -> str:
    """The numeric backing in one sentence ("" when there is none), the usual points and
    precision left to the header (:func:`rigidsym.report.numeric.numeric_sentence`)."""
    return numeric_sentence(n, usual_stated=True)


def how_checked(rec: dict) -> str:
    """Model, singular set and numeric backing in one paragraph."""
    out = []
    if rec["model"]:
        out.append("Model: " + "; ".join(rec["model"]) + ".")
    if rec["singular"]:
        out.append(f"Singular set: {label_text(rec['singular'])}.")
    out.append(numeric_words(rec["numeric"]))
    return " ".join(x for x in out if x)


_EVIDENCE_WORDS = {"cofactors": "by cofactors", "identity": "by re-computation",
                   "counterexample": "an exact counterexample", "shape": "a shape mismatch",
                   "statement": "a statement"}


def certificate_words(field: dict | None) -> str:
    """A verdict's certification in one sentence (``""`` without one): its file, each
    relation's evidence (cofactors, re-computation, counterexample, shapes, statement) and
    whether certcheck re-checked it; ``field`` as
    :func:`rigidsym.checking.certifying.certificates.certificate_field` gives it."""
    if field is None:
        return ""
    if field["file"] is None:
        return f"Certificate: none ({field['why']})."
    ev = field["evidence"]
    kinds = ", ".join(f"{ev.count(k)} {_EVIDENCE_WORDS.get(k, k)}" for k in dict.fromkeys(ev))
    state = {True: "re-checked by certcheck", False: "certcheck REJECTED it",
             None: "not re-checked (certcheck not found)"}[field["rechecked"]]
    return (f"Certificate `{field['file']}` ({len(ev)} relation{'s' * (len(ev) != 1)}: "
            f"{kinds}); {state}.")


def _entry(rec: dict, full: bool) -> list[str]:
    out = [f'### ({rec["id"]}) {label_text(rec["title"])} <a id="{anchor(rec["id"])}"></a>',
           ""]
    how = rec["method"]
    if rec["failure_bound"] is not None and rec["verdict"] != "does-not-hold":
        how += f", P(false zero) ≤ {rec['failure_bound']:.1e}"
    line = f"Sec. {rec['section']} · {rec['kind']} · **{rec['verdict']}** · {how}"
    if rec["verdict"] == rec["kind"] == "definition":
        line = f"Sec. {rec['section']} · **definition**"
    out += [line, "",
            f"$${rec['printed_latex']}$$", ""]
    if rec.get("transcription"):  # what the text reads, machine-checked
        out += [f"*{transcription_words(rec['transcription'])}*", ""]
    ms = rec["members"]
    if not (len(ms) == 1 and ms[0]["status"] == "holds" and not ms[0]["label"]):
        out += _members(rec) + [""]  # one unlabelled member that holds: the line above says it
    if rec["verdict"] == "does-not-hold":
        fm = rec["failing_member"]
        fails = f"member *{_cell(label_text(fm))}*" if fm else "the equation (one member)"
        why = prose_markdown(rec["evidence"]).rstrip()
        stop = "" if why.endswith((".", "?", "!")) else "."
        origin = origin_shown(rec)
        out += [f"Fails: {fails}. Cause: {why}{stop}"
                + (f" Origin: **{origin}**." if origin else ""), ""]
        if rec["counterexample"]:
            failing = next((m["text"] for m in rec["members"] if m["status"] == "fails"
                            and m["role"] != "corrected"), None)
            out += markdown_lines(rec["counterexample"], sides_of(failing),
                                  whose_symbols(rec["id"]))
    out += markdown_repairs(rec)
    out += [how_checked(rec), ""]
    if rec.get("certificate"):
        out += [certificate_words(rec["certificate"]), ""]
    if full:
        out += ["Transcribed:", "", "```", rec["printed"], "```", "",
                "Derived from first principles:", "", "```", rec["derived"], "```", ""]
        if rec["corrected"]:
            out += ["Corrected (expanded):", "", "```", rec["corrected"], "```", ""]
    return out


def _source_paragraph(source: str | None) -> str:
    if source is not None:
        return f"Source: {source}. Generated by `rigidsym report`; not edited by hand."
    return (f"Source: {CITATION}. Each equation is quoted singly with its number; the report "
            "is generated by `rigidsym report` and is not edited by hand. The same content "
            "with rendered mathematics: `chapter3.html`. Every verdict is backed by ball "
            f"arithmetic (python-flint `arb`) at {ENGINE.numeric_points} seeded points that "
            f"satisfy the constraints, from {ENGINE.numeric_digits} digits up: each equation "
            "gives the "
            "certified enclosure of its residual.")


def to_markdown(results: list[Outcome], full: bool = False, *, title: str = TITLE,
                source: str | None = None, certified: dict | None = None) -> str:
    """The report: summary, equations that do not hold, then every equation.

    Args:
        results: checker results in book order (or a user module's declaration order).
        full: add each equation's expanded values (``chapter3-full.md``).
        title: the document's title (default the chapter's).
        source: where the declarations come from, in words (``"the user module
            notes"``); ``None`` for the book (its citation and how it was checked).
        certified: id -> its certificate field (``rigidsym report --certificates``):
            each entry then says how its verdict is certified and whether certcheck
            re-checked it; ``None``: nothing on certificates.

    Returns:
        Markdown text, deterministic (no timings).
    """
    recs = [dict(result_record(r, timings=False, full=full),
                 certificate=(certified or {}).get(r.id)) for r in results]
    s = summary(results)
    out = [f"# {title}", "", _source_paragraph(source), "",
           "| verdict | count |", "|---|---|"]
    out += [f"| {v} | {n} |" for v, n in s.items()]
    out += [f"| **total** | {len(results)} |", ""]
    if s["does-not-hold"]:
        out += [f"{s['does-not-hold']} do not hold as printed: {cause_line(results)}.", ""]
    bad = [r for r in recs if r["verdict"] == "does-not-hold"]
    if bad:
        out += ["## Equations that do not hold as printed", "",
                "| id | title | failing member | cause | origin |", "|---|---|---|---|---|"]
        out += [f"| [({r['id']})](#{anchor(r['id'])}) | {_cell(label_text(r['title']))} | "
                f"{_cell(label_text(r['failing_member']) or 'the equation')} | "
                f"{_cell(prose_markdown(r['evidence']))} | {origin_shown(r)} |" for r in bad]
        out.append("")
    out += markdown_errata(recs, anchor)
    off = [r for r in recs if r["verdict"] != r["expected"]]
    if off:
        out += ["## Verdicts that differ from the recorded expectation", ""]
        out += [f"- ({r['id']}): computed {r['verdict']}, expected {r['expected']}: "
                f"{r['decision']}" for r in off]
        out.append("")
    groups = sections(recs)
    out += ["## Contents", ""]
    out += [f"- Section {sec}: " + ", ".join(f"[({r['id']})](#{anchor(r['id'])})" for r in rs)
            for sec, rs in groups]
    out.append("")
    for sec, rs in groups:
        out += [f"## Section {sec}", ""]
        for rec in rs:
            out += _entry(rec, full)
    return "\n".join(out) + "\n"
