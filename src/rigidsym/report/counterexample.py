"""The counterexample of a does-not-hold in the book's own symbols, for every output.

The record's ``counterexample`` (:func:`rigidsym.report.record.counterexample_record`)
carries ``symbols`` (each book symbol of the failing member, and the statement's other
scalars and vectors the point fixes, exact then decimal) and ``chosen`` (how the point was
chosen: the parametrisation in one sentence and its variables). This module lays them out
for ``rigidsym show`` (text), the Markdown report and the HTML report; the older ``point``
list (the parametrisation variables one by one) is the fallback when there are no symbols.
"""

from __future__ import annotations

import html

import sympy as sp
from markupsafe import Markup

from rigidsym.checking.deciding.point_values import decimal_text
from rigidsym.printing import notation
from rigidsym.printing.labels import label_text
from rigidsym.registry.declarations import is_user_id

__all__ = ["sides_of", "text_lines", "markdown_lines", "html_view", "GLOSSARY_HINT",
           "whose_symbols"]

#: where the words of a verdict are explained (docs/glossary.md in the source tree)
GLOSSARY_HINT = ("Words (verdict, member, model, parametrisation, counterexample, ...): "
                 "rigidsym glossary WORD")


def whose_symbols(eq_id: str) -> str:
    """Whose symbols a counterexample is in: ``"the book's"`` for the book's ids, ``"the
    equation's own"`` for a reader's (namespace:name), whose symbols are the reader's."""
    return "the equation's own" if is_user_id(eq_id) else "the book's"


def sides_of(member_text: str | None) -> tuple[str, str]:
    """``("ȧ∥", "(ȧ·ω)/‖ω‖²")`` from a member's book text ``"ȧ∥ = (ȧ·ω)/‖ω‖²"``; empty
    strings when the member has no short text."""
    if not member_text or " = " not in member_text:
        return "", ""
    lhs, rhs = member_text.split(" = ", 1)
    return (lhs, rhs) if len(lhs) <= 40 and len(rhs) <= 60 else ("", "")


def _value_text(exact: str) -> str:
    try:
        return notation.text(sp.sympify(exact))
    except (sp.SympifyError, SyntaxError, TypeError):
        return exact


def _rows(text: str) -> list[list[str]]:
    """The entries of a matrix printed ``[a, b; c, d]`` (numbers only), row by row."""
    return [r.split(", ") for r in text.strip()[1:-1].split("; ")]


def _grid(name: str, text: str, dec: str, width: int, indent: str) -> list[str] | None:
    """A matrix with more than one column, one row per line, columns aligned, its
    decimals beneath the same way: after ``name = `` when that fits ``width``, else below
    a line ``name =``; ``None`` when neither fits."""
    if not (text.startswith("[") and "; " in text and ", " in text):
        return None
    blocks = [_rows(text)] + ([_rows(dec)] if dec else [])
    for head, lead in ((f"{name} = ", []), ("  ", [f"{indent}{name} ="])):
        out, pad = list(lead), indent + ("    " if lead else "")
        for k, rows in enumerate(blocks):
            w = [max(len(r[j]) for r in rows) for j in range(len(rows[0]))]
            first = head if k == 0 else "≈ ".rjust(max(len(head), 2))
            for i, r in enumerate(rows):
                out.append(pad + (first if i == 0 else " " * len(first))
                           + ("[" if i == 0 else " ")
                           + ", ".join(x.rjust(w[j]) for j, x in enumerate(r))
                           + ("]" if i == len(rows) - 1 else ";"))
        if all(len(line) <= width for line in out):
            return out
    return None


def _symbol_lines(s: dict, width: int, indent: str) -> list[str]:
    dec = s.get("decimal") if s.get("decimal") != s["text"] else ""
    grid = _grid(s["symbol"], s["text"], dec or "", width, indent)
    if grid is not None:
        return grid
    line = f"{s['symbol']} = {s['text']}"
    if dec:
        line += f"   ≈ {dec}"
    if "cos" in s:
        line += f";  cos {s['symbol']} = {s['cos']}, sin {s['symbol']} = {s['sin']}"
    return _wrap(line, width, indent)


def _decimals(exact: str) -> str:
    try:
        v = sp.sympify(exact)
        return decimal_text(v) if all(sp.sympify(e).is_number for e in
                                      (v if isinstance(v, sp.MatrixBase) else [v])) else ""
    except (sp.SympifyError, SyntaxError, TypeError, ValueError):
        return ""


def _value_lines(name: str, exact: str, width: int) -> list[str]:
    """``name = value   ≈ decimals`` of an exact value (sympy's string); a matrix row by
    row with its decimals beneath."""
    text, dec = _value_text(exact), _decimals(exact)
    grid = _grid(name, text, dec, width, "  ")
    if grid is not None:
        return grid
    return _wrap(f"{name} = {text}" + (f"   ≈ {dec}" if dec else ""), width, "  ")


def wrap_at_spaces(text: str, width: int, indent: str, hang: str = "  ") -> list[str]:
    """``text`` as lines of at most ``width`` (where a word allows), broken at spaces only
    (a value's entries are separated by ``", "`` and ``"; "``), each line after the first
    indented by ``indent + hang``; also ``show``'s last resort for a term wider than the line.
    """
    out, line = [], indent
    for word in text.split(" "):
        if len(line) + len(word) + 1 > width and line.strip():
            out.append(line.rstrip())
            line = indent + hang
        line += word + " "
    out.append(line.rstrip())
    return out


def _wrap(text: str, width: int, indent: str) -> list[str]:
    return wrap_at_spaces(text, width, indent, "    ")


def text_lines(ce: dict, sides: tuple[str, str], width: int,
               whose: str = "the book's") -> list[str]:
    """The counterexample for the terminal: book symbols, both sides, the residual, then
    how the point was chosen (folded under its own heading).

    Args:
        ce: the record's ``counterexample``.
        sides: the failing member's two sides in book notation (:func:`sides_of`).
        width: the line width to fit (breaks at spaces).
        whose: whose symbols these are (:func:`whose_symbols`).
    """
    out = _wrap(f"Counterexample, in {whose} symbols (exact; decimals after ≈):", width, "")
    if ce.get("symbols"):
        for s in ce["symbols"]:
            out += _symbol_lines(s, width, "  ")
    else:  # no description: the parametrisation variables themselves
        for p in ce["point"]:
            dec = f"   ≈ {p['decimal']}" if p["decimal"] and p["decimal"] != p["exact"] else ""
            out += _wrap(f"{p['book']} = {_value_text(p['exact'])}{dec}", width, "  ")
    left, right = sides
    out += _value_lines(f"left side{' ' + left if left else ''}", ce["lhs"], width)
    out += _value_lines(f"right side{' ' + right if right else ''}", ce["rhs"], width)
    res = ce.get("residual")
    if res is None:
        out.append("  residual (left - right): none, the two sides have different shapes")
    else:
        out += _value_lines("residual (left - right)", res, width)
    chosen = ce.get("chosen") or {}
    if chosen.get("text") or chosen.get("params"):
        out += _wrap("How the point was chosen (the zero test's parametrisation):", width,
                     "  ")
        if chosen.get("text"):
            out += _wrap(chosen["text"], width, "    ")
        row = "; ".join(f"{p['name']} = {p['exact']}" for p in chosen.get("params", []))
        if row:
            out += _wrap(row, width, "    ")
    return out


def _cell(text: str) -> str:
    return (text or "").replace("|", "\\|").replace("\n", " ")


def markdown_lines(ce: dict, sides: tuple[str, str], whose: str = "the book's") -> list[str]:
    """The counterexample in Markdown: a table of the book symbols (exact, decimal), both
    sides and the residual, and a folded ``<details>`` "How the point was chosen"."""
    head = (f"Counterexample (an exact point, in {whose} symbols"
            + (f"; member *{_cell(label_text(ce['member']))}*" if ce.get("member") else "")
            + "):")
    out = [head, ""]
    if ce.get("symbols"):
        out += ["| symbol | exact | decimal |", "|---|---|---|"]
        for s in ce["symbols"]:
            dec = s.get("decimal") or ""
            if "cos" in s:
                dec += f"; cos {s['symbol']} = {s['cos']}, sin {s['symbol']} = {s['sin']}"
            out.append(f"| {_cell(s['symbol'])} | `{_cell(s['text'])}` | {_cell(dec)} |")
    else:
        out += ["| atom | exact | decimal |", "|---|---|---|"]
        out += [f"| {_cell(p['book'])} | `{_cell(p['exact'])}` | {p['decimal']} |"
                for p in ce["point"]]
    left, right = sides
    out += ["", "Both sides there, and the residual (left minus right):", "", "```",
            f"left  {left + ' ' if left else ''}= {_value_text(ce['lhs'])}",
            f"right {right + ' ' if right else ''}= {_value_text(ce['rhs'])}"]
    if ce.get("residual") is not None:
        out += [f"left - right = {_value_text(ce['residual'])}", "```", "",
                f"Largest residual entry: {ce['residual_max_abs']} "
                f"(≈ {ce['residual_max_abs_decimal']}).", ""]
    else:
        out += ["```", "", "The two sides have different shapes.", ""]
    chosen = ce.get("chosen") or {}
    if chosen.get("text") or chosen.get("params"):
        out += ["<details><summary>How the point was chosen</summary>", "",
                chosen.get("text", ""), ""]
        out += [f"- {_cell(p['name'])} = `{p['exact']}`" for p in chosen.get("params", [])]
        out += ["", "</details>", ""]
    return out


def _decimal_latex(dec: str) -> str:
    """The decimals of a value (``[0.5; 0.25]``, ``0.78``) as LaTeX, a matrix laid out
    like its exact value."""
    if not dec.startswith("["):
        return dec
    rows = _rows(dec)
    return (r"\begin{bmatrix}" + r" \\ ".join(" & ".join(r) for r in rows)
            + r"\end{bmatrix}")


def html_view(ce: dict, math) -> dict:
    """Template data for the HTML counterexample: ``symbols`` rows (name, exact value and
    decimals as MathML), ``chosen`` (text and rows). ``math(latex, fallback, display)``
    converts LaTeX to MathML (:func:`rigidsym.report.html.math_or_text`)."""
    rows = []
    for s in ce.get("symbols") or []:
        try:
            exact = math(notation.latex(sp.sympify(s["exact"])), s["text"], False)
        except (sp.SympifyError, SyntaxError, TypeError):
            exact = Markup(f"<code>{html.escape(s['text'])}</code>")
        name = math(s["latex"], s["symbol"], False) if s.get("latex") else s["symbol"]
        dec = s.get("decimal") or ""
        trig = f"cos {s['symbol']} = {s['cos']}, sin {s['symbol']} = {s['sin']}" \
            if "cos" in s else ""
        rows.append({"name": name, "exact": exact, "trig": trig,
                     "decimal": math(_decimal_latex(dec), dec, False) if dec else ""})
    chosen = ce.get("chosen") or {}
    return {"symbols": rows, "chosen_text": chosen.get("text", ""),
            "chosen_params": chosen.get("params", [])}
