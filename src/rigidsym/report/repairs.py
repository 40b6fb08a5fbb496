"""The repairs of the equations that do not hold, in every output.

The schema-2 record gains three keys (:func:`repair_fields`): ``correction`` (where the
corrected form comes from), ``repairs`` (the verified repairs kept, each with the edits in
words, the repaired member and the printed member in book notation with the edited subterm
marked, its method, failure bound and whether it equals the declared correction) and
``repair_search`` (what was searched per failing member, in words that never guess).

Marks: the text forms put the edited subterm in ``⟦…⟧``; the LaTeX forms in ``\\boxed{…}``,
which the HTML turns into a MathML ``<mrow class="rigidsym-edit">`` around the subterm
(latex2mathml has no class syntax; it converts ``\\boxed`` into ``<menclose>``, which MathML
Core does not render anyway, so every ``menclose`` of a repair is rewritten).
"""

from __future__ import annotations

import html
import re

from markupsafe import Markup

from rigidsym.printing.labels import label_latex, label_text
from rigidsym.printing.mathml import latex_to_mathml

__all__ = ["repair_fields", "marked_mathml", "repairs_view", "errata_rows",
           "markdown_repairs", "markdown_errata", "EDIT_CLASS"]

#: the CSS class of an edited subterm's MathML
EDIT_CLASS = "rigidsym-edit"
_OPEN = re.compile(r'<menclose notation="box">')


def repair_fields(r) -> dict:
    """The repair keys of a result's schema-2 record."""
    return {"correction": r.correction, "repairs": r.repairs,
            "repair_search": r.repair_search}


def marked_mathml(latex: str | None, fallback: str | None) -> Markup:
    """MathML of a repair's LaTeX with each ``\\boxed`` subterm as
    ``<mrow class="rigidsym-edit">``; the text in ``<code>`` when it does not convert."""
    try:
        m = latex_to_mathml(latex, display=True) if latex else None
    except ValueError:  # a form the converter rejects: its text instead
        m = None
    if m is None:
        return Markup(f"<code>{html.escape(fallback or '(not shown: too long)')}</code>")
    m = _OPEN.sub(f'<mrow class="{EDIT_CLASS}">', m).replace("</menclose>", "</mrow>")
    return Markup(m)


def _member_words(member: str) -> str:
    return f"member “{label_text(member)}”" if member else "the equation"


def repairs_view(rec: dict) -> list[dict]:
    """Per failing member: ``{"member", "words", "repairs"}``, each repair with the printed
    and the repaired MathML side by side."""
    out = []
    for s in rec.get("repair_search") or []:
        reps = [dict(x, printed_mathml=marked_mathml(x["printed_latex"], x["printed_text"]),
                     repaired_mathml=marked_mathml(x["latex"], x["text"]))
                for x in rec["repairs"] if x["member"] == s["member"]]
        out.append({"member": s["member"], "who": _member_words(s["member"]),
                    "words": s["words"], "repairs": reps})
    return out


def errata_rows(recs: list[dict]) -> list[dict]:
    """One row per failing member of each does-not-hold: the repairs found (the first in
    words), whether one equals the declared correction, and what was searched."""
    rows = []
    for rec in recs:
        if rec["verdict"] != "does-not-hold":
            continue
        for s in rec.get("repair_search") or []:
            reps = [x for x in rec["repairs"] if x["member"] == s["member"]]
            first = "; then ".join(reps[0]["edits"]) if reps else ""
            more = s["found"] - 1 if reps else 0
            declared = "—" if not reps or rec.get("correction") != "declared" else \
                ("yes" if any(x["equals_declared"] for x in reps) else "no")
            rows.append({"id": rec["id"], "member": s["member"] or "the equation",
                         "member_shown": label_text(s["member"]) or "the equation",
                         "member_mathml": _label_mathml(s["member"]),
                         "first": first, "more": more, "declared": declared,
                         "words": s["words"], "text": reps[0]["text"] if reps else ""})
    return rows


def _label_mathml(label: str) -> Markup | None:
    """A member's label as inline MathML (never ASCII in the HTML table)."""
    if not label:
        return None
    try:
        return Markup(latex_to_mathml(label_latex(label), display=False))
    except ValueError:  # a label the converter rejects: its book-notation text
        return Markup(html.escape(label_text(label)))


def _cell(text: str) -> str:
    return (text or "").replace("|", "\\|").replace("\n", " ")


def _code(text: str) -> str:
    return "`" + (text or "").replace("`", "'") + "`"


def markdown_repairs(rec: dict) -> list[str]:
    """The repairs of one entry, in Markdown (empty when nothing was searched)."""
    if not rec.get("repair_search"):
        return []
    out = [f"Repairs (correction: {rec['correction']}; ⟦…⟧ marks the edited subterm):", ""]
    for g in repairs_view_text(rec):
        out.append(f"- {g['who']}: {g['words']}")
        for x in g["repairs"]:
            tags = [x["method"]]
            if x["failure_bound"] is not None:
                tags.append(f"P(false zero) ≤ {x['failure_bound']:.1e}")
            if x["equals_declared"]:
                tags.append("the declared correction")
            out.append(f"  - {_cell('; then '.join(x['edits']))} ({', '.join(tags)}): "
                       f"{_code(x['text'])}")
    return out + [""]


def repairs_view_text(rec: dict) -> list[dict]:
    """:func:`repairs_view` without the MathML (for the Markdown and ``show``)."""
    return [{"member": s["member"], "who": _member_words(s["member"]), "words": s["words"],
             "repairs": [x for x in rec["repairs"] if x["member"] == s["member"]]}
            for s in rec.get("repair_search") or []]


def markdown_errata(recs: list[dict], anchor) -> list[str]:
    """The errata table of the report: every failing member of every does-not-hold."""
    rows = errata_rows(recs)
    if not rows:
        return []
    out = ["## Errata: the smallest repairs", "",
           "For every member that does not hold, the repair search tried single edits, then "
           "pairs, of the printed form (signs, terms, coefficients, transposes, factor order, "
           "sin/cos, symbols, factors), each candidate decided by the zero test. *Equals the "
           "declared* says whether a repair is, with the book symbols left unsubstituted, the "
           "corrected form the declaration gives. Where none was found, the table says what "
           "was searched: \"no repair within 2 edits\" only when every single edit and pair "
           "was tried.", "",
           "| id | member | first repair | more | equals the declared | searched |",
           "|---|---|---|---|---|---|"]
    out += [f"| [({r['id']})](#{anchor(r['id'])}) | {_cell(r['member_shown'])} | "
            f"{_cell(r['first']) or '—'} | {r['more'] or ''} | {r['declared']} | "
            f"{_cell(r['words'])} |" for r in rows]
    return out + [""]
