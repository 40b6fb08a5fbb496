"""The chapter report and the exercises as self-contained HTML with MathML.

One file each, inline CSS, no JavaScript, no network: it opens from disk on an offline
machine, and MathML Core renders natively (Chromium >= 109, Firefox, Safari). Rendered from
the schema-2 records (:func:`rigidsym.report.record.result_record`) through Jinja2 templates
(``rigidsym/report/templates``); byte-identical from run to run.
"""

from __future__ import annotations

import html
import re
from functools import cache

import sympy as sp
from jinja2 import Environment, PackageLoader, StrictUndefined
from markupsafe import Markup

from rigidsym.checking.checker import Outcome
from rigidsym.latex.transcription import transcription_words
from rigidsym.printing import notation
from rigidsym.printing.labels import label_text, latex_spans, latex_text
from rigidsym.report.counterexample import html_view, sides_of, whose_symbols
from rigidsym.report.glossary import html_entries
from rigidsym.report.markdown import anchor, certificate_words, sections, undecided_reasons
from rigidsym.report.mathtext import math_or_text
from rigidsym.report.numeric import numeric_sentence
from rigidsym.report.record import (
    CITATION,
    TITLE,
    cause_line,
    origin_shown,
    result_record,
    summary,
)
from rigidsym.report.repairs import errata_rows, repairs_view

__all__ = ["to_html", "markdown_to_html", "math_or_text", "prose_html"]


@cache
def _env() -> Environment:
    return Environment(loader=PackageLoader("rigidsym.report", "templates"), autoescape=True,
                       undefined=StrictUndefined, keep_trailing_newline=True,
                       trim_blocks=False, lstrip_blocks=False)


def _value_mathml(text: str | None) -> Markup:
    """An exact value printed by sympy (``Matrix([[1/2], ...])``) as MathML."""
    if text is None:
        return Markup("<i>shapes differ</i>")
    try:
        v = sp.sympify(text)
    except (sp.SympifyError, SyntaxError, TypeError):
        return Markup(f"<code>{html.escape(text)}</code>")
    return math_or_text(notation.latex(v), text, display=False)


#: a letter subscript the Unicode text writes with an underscore (M_A, Ṡ_N: Unicode has no
#: subscript capitals); the page sets it as a subscript, as the MathML beside it does
_LETTER = r"(?:(?![\u00b2\u00b3\u00b9\u1d2c-\u1dbf\u2070-\u209f])[^\W\d_])"  # not ², ᵀ, ₁
_LETTER_SUB = re.compile(rf"(?<![\w\u0300-\u036f'])({_LETTER}[\u0300-\u036f]*'*)"
                         rf"_({_LETTER}{{1,2}})(?!{_LETTER}|[0-9_])")
#: what the subscript pass leaves alone: tags, MathML, inline SVG figures (no <sub> there),
#: code listings, the head
_NOT_TEXT = re.compile(r"(<math\b.*?</math>|<svg\b.*?</svg>|<pre\b.*?</pre>|<style\b.*?</style>|"
                       r"<title\b.*?</title>|<[^>]+>)", re.S)


def letter_subscripts(page: str) -> str:
    """``page`` (HTML) with the letter subscripts of its text in ``<sub>``: ``M_A`` ->
    ``M<sub>A</sub>`` in labels, causes, repairs and the book-notation ``<code>`` spans;
    names of code (``plucker_transfer``, ``ad_dual``) are never one letter and a
    subscript, so they stay as written."""
    return "".join(p if i % 2 else _LETTER_SUB.sub(r"\1<sub>\2</sub>", p)
                   for i, p in enumerate(_NOT_TEXT.split(page)))


def prose_html(text: str | None) -> Markup:
    """Running text of a declaration (evidence, a label) as HTML: its LaTeX pieces
    (``\\dot{\\boldsymbol{\\nu}}``) as inline MathML, its ASCII mathematics in book
    notation (:func:`rigidsym.printing.labels.label_text`), the rest escaped."""
    out = []
    for is_tex, piece in latex_spans(text or ""):
        out.append(str(math_or_text(piece, latex_text(piece), display=False)) if is_tex
                   else html.escape(label_text(piece)))
    return Markup("".join(out))


def _prose_view(rec: dict) -> dict:
    """The record's words for the page: evidence and labels in book notation."""
    ce = rec["counterexample"] or {}
    failing = next((m["text"] for m in rec["members"]
                    if m["status"] == "fails" and m["role"] != "corrected"), None)
    return {"evidence_html": prose_html(rec["evidence"]), "ce_sides": sides_of(failing),
            "failing_member_shown": label_text(rec["failing_member"] or ""),
            "title_shown": label_text(rec["title"]),
            "origin_shown": origin_shown(rec),
            "singular_shown": label_text(rec["singular"] or ""),
            "ce_member_shown": label_text(ce.get("member") or ""),
            "ce_whose": whose_symbols(rec["id"])}


def _view(rec: dict) -> dict:
    v = dict(rec, anchor=anchor(rec["id"]),
             printed_mathml=math_or_text(rec["printed_latex"], rec["printed_latex"]),
             numeric_text=numeric_sentence(rec["numeric"]),
             transcription_text=transcription_words(rec.get("transcription")))
    v["undecided"] = undecided_reasons(rec) if rec["verdict"] == "undecided" else []
    v["members"] = [dict(m, mathml=math_or_text(m["latex"], m["text"]),
                         label_shown=label_text(m["label"])) for m in rec["members"]]
    v.update(_prose_view(rec))
    v["failing_text"] = next((m["text"] for m in rec["members"]
                              if m["status"] == "fails" and m["role"] != "corrected"), None)
    ce = rec["counterexample"]
    if ce:
        v["ce"] = dict(ce, lhs_mathml=_value_mathml(ce["lhs"]),
                       rhs_mathml=_value_mathml(ce["rhs"]),
                       residual_mathml=_value_mathml(ce.get("residual")),
                       residual_max_abs=ce.get("residual_max_abs"),
                       residual_max_abs_decimal=ce.get("residual_max_abs_decimal"),
                       view=html_view(ce, math_or_text))
    else:
        v["ce"] = None
    v["repair_groups"] = repairs_view(rec)
    return v


def to_html(results: list[Outcome], *, title: str = TITLE, source: str | None = None,
            certified: dict | None = None) -> str:
    """The report as one self-contained HTML page.

    Args:
        results: checker results in book order (or a user module's declaration order).
        title: the page's title (default the chapter's).
        source: where the declarations come from, in words (``"the user module
            notes"``); ``None`` for the book (its citation and the exercises' page).
        certified: id -> its certificate field, as for
            :func:`rigidsym.report.markdown.to_markdown`.

    Returns:
        HTML text: summary counts, the equations that do not hold (each linking to its
        entry), a table of contents by section, then one entry per equation with the anchor
        ``#eq-<id>``.
    """
    views = [dict(_view(result_record(r, timings=False)),
                  certificate_text=certificate_words((certified or {}).get(r.id)).replace("`", ""))
             for r in results]
    s = summary(results)
    return letter_subscripts(_env().get_template("chapter3.html.j2").render(
        causes=cause_line(results) if s["does-not-hold"] else "", n_bad=s["does-not-hold"],
        title=title, source=source, citation=CITATION.replace("*", ""),
        counts=list(s.items()), total=len(results),
        bad=[v for v in views if v["verdict"] == "does-not-hold"],
        off=[v for v in views if v["verdict"] != v["expected"]],
        groups=sections(views), errata=errata_rows(views), words=html_entries()))


def markdown_to_html(text: str, title: str, figures: dict[str, str] | None = None) -> str:
    """A Markdown document with ``$...$``/``$$...$$`` maths as one self-contained page.

    Converted by markdown-it-py with its dollar-math plugin, each formula through
    :func:`latex_to_mathml`; an image whose source is a key of ``figures`` is replaced by
    that SVG text, inline (so the page needs no other file).

    Args:
        text: Markdown.
        title: the page title.
        figures: image source -> SVG document text.

    Returns:
        HTML text.
    """
    from markdown_it import MarkdownIt
    from mdit_py_plugins.dollarmath import dollarmath_plugin

    figures = figures or {}

    def render_math(content: str, opts: dict) -> str:
        return str(math_or_text(content, content, display=opts.get("display_mode", False)))

    # html: the anchors <a id="ex-3.10"> of our own Markdown pass through
    md = MarkdownIt("commonmark", {"html": True}).enable("table")
    md.use(dollarmath_plugin, double_inline=True, renderer=render_math)
    default_image = md.renderer.rules.get("image")

    def image(renderer, tokens, idx, options, env):
        src = tokens[idx].attrGet("src")
        if src in figures:
            svg = figures[src]
            svg = svg[svg.index("<svg"):]  # drop the XML prolog and doctype: inline SVG
            alt = html.escape(tokens[idx].content or "")
            return f'<figure role="img" aria-label="{alt}">{svg}</figure>'
        return default_image(tokens, idx, options, env)

    md.add_render_rule("image", image)
    body = letter_subscripts(md.render(text))
    return _env().get_template("page.html.j2").render(title=title, body=Markup(body))
