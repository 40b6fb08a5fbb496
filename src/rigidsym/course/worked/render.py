"""Rendering of a worked solution: terminal text, Markdown, HTML with MathML, LaTeX; JSON values.

The HTML is what a notebook shows (:meth:`Solution._repr_html_`): the Markdown rendering
converted by markdown-it-py, each formula through :func:`rigidsym.printing.mathml.latex_to_mathml`
(MathML Core, as the HTML report). The LaTeX (:meth:`Solution._repr_latex_`) is a
document fragment for nbconvert's LaTeX/PDF export.
"""

from __future__ import annotations

import html
import re
from typing import Protocol

import sympy as sp


class Solution(Protocol):
    """What the renderers read of a :class:`rigidsym.course.worked.Solution` (declared
    here so that this module does not import the one that imports it)."""

    id: str
    title: str
    statement: str
    citation: str
    given: dict
    steps: list
    answers: dict
    checks: list
    assumptions: list
    status: str
    extra: str
    reason: str
    floats: tuple

    @property
    def checked(self) -> bool: ...

__all__ = ["to_json_value", "solution_record", "render_text", "render_markdown",
           "render_html", "render_latex"]


def to_json_value(v):
    """A sympy value as JSON: ``str()`` that ``sympify`` reads back; matrices nested."""
    if isinstance(v, sp.MatrixBase):
        return [[str(x) for x in v.row(i)] for i in range(v.rows)]
    if isinstance(v, list | tuple):
        return [to_json_value(x) for x in v]
    if isinstance(v, str):
        return v
    return str(sp.sympify(v))


#: the statuses that end a solution before its answers, and how the renderers head them:
#: ill-posed (the data admit no answer, or more than one) and not solved (a case the
#: solver does not handle: a limit of the solver, not of the data)
ENDED = {"ill-posed": "Ill-posed", "not solved": "Not solved for these data"}


def solution_record(s) -> dict:
    """A solution as the JSON record of a schema-2 key: ``id``, ``status``, ``data`` (by
    parameter name, exact strings), ``tol``, ``answers`` (sympy values as strings),
    ``statements`` (answers in words), ``checks`` (name, passed, detail), ``checked``,
    ``assumptions`` and, when ill-posed, ``reason``."""
    rec = {"id": s.id, "status": s.status,
           "data": {k: to_json_value(list(v) if isinstance(v, sp.MatrixBase)
                                     and v.cols == 1 else v)
                    for k, v in getattr(s, "data", {}).items()},
           "tol": None if getattr(s, "tol", None) is None else str(s.tol),
           "answers": {k: to_json_value(v) for k, v in s.answers.items()
                       if not isinstance(v, str)},
           "statements": {k: v for k, v in s.answers.items() if isinstance(v, str)},
           "checks": [{"name": c.name, "passed": c.passed, "detail": c.detail}
                      for c in s.checks],
           "checked": s.checked, "assumptions": list(s.assumptions)}
    if s.reason:
        rec["reason"] = s.reason
    return rec


def _float_of(v) -> str:
    if isinstance(v, str) or isinstance(v, sp.Basic | sp.MatrixBase) and v.has(sp.Float):
        return ""
    try:
        if isinstance(v, sp.MatrixBase):
            if v.free_symbols or all(x.is_Integer for x in v):
                return ""
            return str(sp.N(v, 6).tolist())
        v = sp.sympify(v)
        if not isinstance(v, sp.Expr) or v.free_symbols or v.is_number is not True:
            return ""
        f = sp.N(v, 6)
        return "" if f == v else str(f)
    except (TypeError, ValueError, sp.SympifyError):
        return ""


#: with float data, an exact number printed longer than this is shown to 10 digits
_LONG = 24
LONG_NOTE = ("Float data: exact numbers longer than 24 characters are shown to 10 "
             "significant digits here; the exact values are in solution.answers.")


def _short(x):
    if isinstance(x, sp.Expr) and not x.free_symbols and x.is_number and len(str(x)) > _LONG:
        return sp.Float(sp.N(x, 10), 10)
    return x


def _shown(v):
    """``v`` for display: long exact numbers (entries too) as 10-digit floats."""
    if isinstance(v, sp.MatrixBase):
        return v.applyfunc(_short)
    return _short(v) if isinstance(v, sp.Expr) else v


def _view(s: Solution) -> Solution:
    """What the renderers show of ``s``: itself, or with float data a copy whose long
    exact numbers are shortened (exact rationals of binary fractions run to 30+ digits)."""
    if not getattr(s, "floats", ()):
        return s
    import copy
    v = copy.copy(s)
    v.given = {k: _shown(x) for k, x in s.given.items()}
    v.answers = {k: _shown(x) for k, x in s.answers.items()}
    v.steps = []
    for st in s.steps:
        st2 = copy.copy(st)
        st2.expr = _shown(st.expr)
        v.steps.append(st2)
    v.assumptions = [*s.assumptions, LONG_NOTE]
    return v


#: the width of a line of text output (the terminal's 100 columns of the house style)
WIDTH = 100
#: a symbol's internal prefix (``ex35_e_1``: unique among the registry's declarations)
_INTERNAL = re.compile(r"^(?:ex3\d*_|_+)(?=[A-Za-z])")


def display(v):
    """``v`` with the book's names: an exercise's internal prefix dropped from its
    symbols and functions (``ex35_e_1`` is shown as ``e_1``, ``ex39_e_1(t)`` as
    ``e_1(t)``); a Dummy shown by its name. Display only: the values are unchanged."""
    if not isinstance(v, sp.Basic | sp.MatrixBase):
        return v
    from sympy.core.function import AppliedUndef

    atoms = v.atoms(sp.Symbol, AppliedUndef)
    subs = {}
    for a in atoms:
        name = a.func.__name__ if isinstance(a, AppliedUndef) else a.name
        new = _INTERNAL.sub("", name)
        if isinstance(a, sp.Dummy):
            subs[a] = sp.Symbol(new, **a.assumptions0)
        elif new != name:
            subs[a] = (sp.Function(new)(*a.args) if isinstance(a, AppliedUndef)
                       else sp.Symbol(new, **a.assumptions0))
    return v.xreplace(subs) if subs else v


def _pretty(v, indent: int = 0, ascii_only: bool = False) -> str:
    """``v`` as lines of at most :data:`WIDTH` columns after ``indent``: sympy's 2-D
    form, or, when that is wider, a matrix entry by entry and an expression in one line,
    wrapped at its operators."""
    if isinstance(v, str):
        return _wrap(v, indent)
    v = display(v)
    text = sp.pretty(v, use_unicode=not ascii_only, wrap_line=False)
    if max(map(len, text.splitlines() or [""])) + indent <= WIDTH:
        return text
    if isinstance(v, sp.MatrixBase):
        out = []
        for i in range(v.rows):
            for j in range(v.cols):
                where = f"[{i + 1}]" if v.cols == 1 else f"[{i + 1}, {j + 1}]"
                out.append(_wrap(f"{where} = {sp.sstr(v[i, j])}", indent, hang=4))
        return "\n".join(out)
    return _wrap(sp.sstr(v), indent, hang=4)


def _wrap(text: str, indent: int, hang: int = 2) -> str:
    """``text`` filled to :data:`WIDTH` columns after ``indent``; continuation lines
    indented by ``hang`` more."""
    import textwrap

    lines = []
    for par in text.splitlines() or [""]:
        if len(par) + indent <= WIDTH:
            lines.append(par)
            continue
        lines += textwrap.wrap(par, width=WIDTH - indent, subsequent_indent=" " * hang,
                               break_on_hyphens=False) or [""]
    return "\n".join(lines)


def render_text(s: Solution, ascii_only: bool = False) -> str:
    """Terminal rendering: statement, given, numbered steps, answers, checks; every line
    at most :data:`WIDTH` columns, the symbols by their book names (:func:`display`).
    ``ascii_only``: sympy's ASCII forms, and the text's few non-ASCII letters (Plücker)
    spelled plainly, for a terminal without Unicode."""
    s = _view(s)
    out = [_wrap(f"Exercise {s.id[2:]}: {s.title}", 0), f"  {s.citation}", "",
           _wrap(s.statement, 0), ""]

    def block(v, indent: int) -> None:
        out.extend(" " * indent + ln for ln in _pretty(v, indent, ascii_only).splitlines())

    def line(text: str, indent: int, hang: int = 2) -> None:
        out.extend(" " * indent + ln for ln in _wrap(text, indent, hang).splitlines())

    if s.assumptions:
        out.append("Assumptions:")
        for a in s.assumptions:
            line(f"- {a}", 2)
        out.append("")
    if s.given:
        out.append("Given:")
        for k, v in s.given.items():
            line(f"{k} =", 2)
            block(v, 4)
        out.append("")
    out.append("Solution:")
    for i, st in enumerate(s.steps, 1):
        line(f"Step {i}. {st.name}: {st.why}", 2, 4)
        block(st.expr, 6)
    out.append("")
    if s.status in ENDED:
        line(f"{ENDED[s.status]}: {s.reason}", 0)
        out += ["", f"status: {s.status}; checked: false"]
        return _plain("\n".join(out)) if ascii_only else "\n".join(out)
    out.append("Answers:")
    for k, v in s.answers.items():
        f = _float_of(v)
        line(f"{k} =" + (f"   (~ {f})" if f else ""), 2, 4)
        block(v, 4)
    if s.extra:
        out.append("")
        line(s.extra, 0)
    out.append("")
    out.append("Machine checks:")
    for c in s.checks:
        line(f"[{'ok' if c.passed else 'FAIL'}] {c.name}: {c.detail}", 2, 4)
    out.append(f"\nstatus: {s.status}; checked: {str(s.checked).lower()}")
    return _plain("\n".join(out)) if ascii_only else "\n".join(out)


#: the non-ASCII letters of the exercises' own text, spelled plainly
_PLAIN = str.maketrans({"ü": "u", "é": "e", "°": " deg", "·": ".", "×": "x", "≤": "<=",
                        "≥": ">=", "−": "-", "–": "-", "—": "--", "’": "'", "…": "...",
                        "π": "pi", "ω": "omega", "θ": "theta", "φ": "phi", "ψ": "psi",
                        "η": "eta", "ε": "epsilon", "λ": "lambda", "ρ": "rho", "³": "^3",
                        "²": "^2", "₂": "_2", "₁": "_1"})


def _plain(text: str) -> str:
    return text.translate(_PLAIN)


def _latex(v) -> str:
    if isinstance(v, str):
        return v
    return f"$${sp.latex(v)}$$"


_REPORT_MARKS = ("[x]", "[ ]")


def render_markdown(s: Solution, *, level: int = 2, statement: bool = True,
                    checks: bool = True, marks: tuple[str, str] = _REPORT_MARKS,
                    typeset: bool = False) -> str:
    """Markdown rendering (LaTeX maths) for the report.

    ``level`` is the heading level; ``statement=False`` leaves out the quoted statement
    (a notebook shows it above), ``checks=False`` the machine checks; ``marks`` prefix
    passed and failed checks. ``typeset=True`` (the exercises page) writes the ASCII
    mathematics of the texts (reasons, assumptions, checks, names) as ``$...$`` LaTeX in
    book notation (:func:`rigidsym.printing.prose.prose_markdown`), as the chapter report
    typesets its formulas; otherwise the texts are as written.
    """
    from rigidsym.printing.prose import prose_latex_runs, prose_markdown

    def t(text: str) -> str:
        return prose_markdown(text) if typeset else text

    def key(k: str) -> str:   # a name that is a formula typeset, a code name as code
        runs = prose_latex_runs(k) if typeset else []
        return f"${runs[0][1]}$" if [m for m, _ in runs] == [True] else f"`{k}`"

    def value(v) -> str:   # a value given as a string is ASCII mathematics too
        return t(v) if isinstance(v, str) else _latex(v)

    s = _view(s)
    out = [f'{"#" * level} Exercise {s.id[2:]}: {t(s.title)} <a id="ex-{s.id[2:]}"></a>', "",
           f"*{s.citation}*", ""]
    if statement:
        out += [f"> {t(s.statement)}", ""]
    out += [f"**Status:** {s.status}; **checked:** {str(s.checked).lower()}", ""]
    if s.status in ENDED:
        out[-2:] = [f"**Status:** {s.status}: {t(s.reason)}", ""]
    if s.assumptions:
        out.append("**Assumptions**")
        out += [f"- {t(a)}" for a in s.assumptions] + [""]
    if s.given:
        out.append("**Given**")
        out += [f"- {key(k)} = {value(v)}"
                for k, v in s.given.items()] + [""]
    out.append("**Solution**")
    out.append("")
    for i, st in enumerate(s.steps, 1):
        out += [f"{i}. *{t(st.name)}*: {t(st.why)}", "", f"   {value(st.expr)}", ""]
    if s.status in ENDED:
        out += [f"**{ENDED[s.status]}:** {t(s.reason)}", ""]
        return "\n".join(out)
    out.append("**Answers**")
    out.append("")
    for k, v in s.answers.items():
        f = _float_of(v)
        out += [f"- {key(k)} = {value(v)}" + (f" ≈ `{f}`" if f else ""), ""]
    if s.extra:
        out += [_typeset_tables(s.extra) if typeset else s.extra, ""]
    if checks:
        out += ["**Machine checks**", ""]
        out += [f"- {marks[0] if c.passed else marks[1]} {t(c.name)}: {t(c.detail)}"
                for c in s.checks]
        out.append("")
    return "\n".join(out)


def _typeset_tables(extra: str) -> str:
    """The Markdown tables of a solution's extra text with their cells' ASCII mathematics
    (``| `cos(phi)` |``) as ``$...$`` LaTeX; other lines as written."""
    from rigidsym.printing.prose import prose_markdown

    out = []
    for line in extra.splitlines():
        if line.startswith("|") and not set(line) <= set("|-: "):
            cells = line.strip().strip("|").split("|")
            line = "| " + " | ".join(prose_markdown(c.strip().strip("`")) for c in cells) + " |"
        out.append(line)
    return "\n".join(out)


def render_html(s: Solution) -> str:
    """The solution as an HTML fragment, maths as MathML (what a notebook displays).

    Returns:
        HTML text: the Markdown rendering converted by markdown-it-py, each ``$$...$$``
        formula through :func:`latex_to_mathml` (a formula the converter rejects is shown
        as its LaTeX source in ``<code>``).
    """
    from markdown_it import MarkdownIt
    from mdit_py_plugins.dollarmath import dollarmath_plugin

    from rigidsym.printing.mathml import latex_to_mathml

    def render_math(content: str, opts: dict) -> str:
        display = opts.get("display_mode", False)
        try:
            m = latex_to_mathml(content, display=display)
        except ValueError:
            return f"<code>{html.escape(content)}</code>"
        # inline styles survive a notebook's sanitiser: a font with a MATH table (so that
        # brackets stretch), and block formulas beside their label, not centred
        return m.replace("<math ", f'<math style="{_MATH_STYLE}{_BLOCK_STYLE if display else ""}" ',
                         1)

    md = MarkdownIt("commonmark", {"html": True}).enable("table")
    md.use(dollarmath_plugin, double_inline=True, renderer=render_math)
    body = md.render(render_markdown(s, level=3, statement=False, checks=False))
    return f'<div class="rigidsym-solution">{body}{_checks_html(s)}</div>'


def _checks_html(s: Solution) -> str:
    """The machine checks folded under a one-line verdict (``<details>``)."""
    if not s.checks:
        return ""
    n = sum(c.passed for c in s.checks)
    items = "".join(f"<li>{'✓' if c.passed else '✗ FAILED:'} {html.escape(c.name)}: "
                    f"<small>{html.escape(c.detail)}</small></li>" for c in s.checks)
    return (f"<details><summary><b>Machine checks</b>: {n} of {len(s.checks)} passed"
            f"</summary><ul>{items}</ul></details>")


_MATH_STYLE = ("font-family: math, 'STIX Two Math', 'Latin Modern Math', 'STIX Math', "
               "'DejaVu Math TeX Gyre', serif;")
_BLOCK_STYLE = " display: inline-block; margin: 0.2em 0.6em; vertical-align: middle;"

_TEX_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
                "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}",
                "^": r"\textasciicircum{}"}


def _tex(text: str) -> str:
    return "".join(_TEX_SPECIAL.get(ch, ch) for ch in text)


def _tex_value(v) -> str:
    return _tex(v) if isinstance(v, str) else f"\\[{sp.latex(v)}\\]"


def render_latex(s: Solution) -> str:
    """The solution as a LaTeX fragment (``amsmath``), for nbconvert's LaTeX and PDF export.

    Text is escaped; values are sympy's LaTeX in display maths.
    """
    s = _view(s)
    out = [f"\\subsection*{{Exercise {s.id[2:]}: {_tex(s.title)}}}",
           f"\\textit{{{_tex(s.citation)}}}\\par", f"\\begin{{quote}}{_tex(s.statement)}"
           "\\end{quote}"]
    if s.assumptions:
        out += ["\\paragraph{Assumptions}", "\\begin{itemize}"]
        out += [f"\\item {_tex(a)}" for a in s.assumptions] + ["\\end{itemize}"]
    if s.given:
        out += ["\\paragraph{Given}", "\\begin{itemize}"]
        out += [f"\\item \\texttt{{{_tex(k)}}} = {_tex_value(v)}" for k, v in s.given.items()]
        out += ["\\end{itemize}"]
    out += ["\\paragraph{Solution}", "\\begin{enumerate}"]
    out += [f"\\item \\textit{{{_tex(st.name)}}}: {_tex(st.why)} {_tex_value(st.expr)}"
            for st in s.steps]
    out += ["\\end{enumerate}"]
    if s.status in ENDED:
        return "\n".join(out + [f"\\paragraph{{{ENDED[s.status]}}} {_tex(s.reason)}"])
    out += ["\\paragraph{Answers}", "\\begin{itemize}"]
    out += [f"\\item \\texttt{{{_tex(k)}}} = {_tex_value(v)}" for k, v in s.answers.items()]
    out += ["\\end{itemize}", "\\paragraph{Machine checks}", "\\begin{itemize}"]
    marks = {True: r"[$\checkmark$]", False: r"[$\times$]"}
    out += [f"\\item{marks[c.passed]} {_tex(c.name)}" for c in s.checks]
    return "\n".join(out + ["\\end{itemize}"])
