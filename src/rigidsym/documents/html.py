"""A document's errata as one offline HTML page (``rigidsym check FILE --html OUT``).

The document's displays in order, each relation typeset in MathML with its verdict beside
it, the exact counterexample and the corrected form under a relation that does not hold,
the reason under one not checked. One file, inline CSS, no JavaScript, no network: MathML
Core renders natively; the LaTeX goes to MathML through the chapter report's path
(:func:`rigidsym.report.mathtext.math_or_text`, with its text fallback) and the page takes
the report's style sheet. Byte-identical from run to run for the same records.
"""

from __future__ import annotations

from functools import cache

from jinja2 import ChoiceLoader, Environment, PackageLoader, StrictUndefined

from rigidsym.documents.checking import VERDICTS, DocumentResult
from rigidsym.documents.report import summary
from rigidsym.report.mathtext import math_or_text

__all__ = ["as_html"]


@cache
def _env() -> Environment:
    loader = ChoiceLoader([PackageLoader("rigidsym.documents", "templates"),
                           PackageLoader("rigidsym.report", "templates")])
    return Environment(loader=loader, autoescape=True, undefined=StrictUndefined,
                       keep_trailing_newline=True)


def _view(rec: dict) -> dict:
    anchor = f"r-{rec['display']}-{rec['index']}"
    return {**rec, "anchor": anchor, "place": f"{rec['file']}:{rec['line']}",
            "mathml": math_or_text(rec["latex"], rec["latex"]),
            "corrected_mathml": math_or_text(rec["corrected_latex"], rec["corrected"])
            if rec.get("corrected") else None,
            "point": [{"mathml": math_or_text(p["latex"], p["latex"], display=False),
                       "value": p["value"]} for p in rec.get("point") or []]}


def as_html(res: DocumentResult) -> str:
    """The errata as a self-contained HTML page (:mod:`this module <.html>`).

    Returns:
        HTML text: the counts, the conventions said back, links to the relations that do
        not hold, then one section per display (anchor ``#display-N``) holding its
        relations (anchor ``#r-N-I``), each with its verdict and place.
    """
    views = [_view(r) for r in res.records]
    by: dict[int, list[dict]] = {}
    for v in views:
        by.setdefault(v["display"], []).append(v)
    displays = []
    for d in res.document.displays:
        rels = by.get(d.number, [])
        displays.append({"number": d.number, "place": f"{d.source.file}:{d.line}",
                         "label": d.label, "relations": rels,
                         "bad": any(r["verdict"] == "does-not-hold" for r in rels)})
    counts = [(v, n) for v, n in res.counts().items() if n]
    return _env().get_template("document.html.j2").render(
        document=str(res.document.path), summary=summary(res),
        reading=str(res.reading.path) if res.reading is not None else None,
        counts=counts, conventions=res.conventions, displays=displays,
        bad=[v for v in views if v["verdict"] == "does-not-hold"], verdicts=VERDICTS)
