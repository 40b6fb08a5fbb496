"""``rigidsym show ID``: one equation explained in the terminal, in book notation.

Verdict and method; each member with its status; for a does-not-hold the failing member,
the cause and its evidence, the counterexample (the point, both sides there and the
residual) and the corrected form; the singular set. Lines fit the width (``COLUMNS``, else
the terminal's, else 100 when stdout is not a terminal) and are broken only between the
terms of a sum, the rows of a matrix or its entries, never inside a term when that can be
avoided.
"""

from __future__ import annotations

import os
import shutil
import sys

import sympy as sp

from rigidsym.checking.checker import Outcome
from rigidsym.latex.transcription import transcription_words
from rigidsym.printing import notation
from rigidsym.printing.labels import label_text
from rigidsym.registry.declarations import Rel, is_user_id
from rigidsym.report.counterexample import GLOSSARY_HINT, sides_of, text_lines, whose_symbols
from rigidsym.report.counterexample import wrap_at_spaces as _hard_wrap
from rigidsym.report.markdown import undecided_reasons
from rigidsym.report.numeric import numeric_sentence
from rigidsym.report.record import cause_sentence, counterexample_record, result_record

__all__ = ["explain", "output_width", "expr_lines", "repair_lines", "DEFAULT_WIDTH",
           "SHORT_LINES"]

#: width when stdout is not a terminal and ``COLUMNS`` is not set
DEFAULT_WIDTH = 100
#: the most lines of the short explanation (``show`` without ``--full``)
SHORT_LINES = 40
#: in the short explanation, a relation or a counterexample longer than this many lines is
#: summarised in one line that points at ``--full``
_SHORT_BLOCK = 3
#: the most continuation lines of the counterexample's residual in the short explanation
_SHORT_RESIDUAL = 5


def output_width() -> int:
    """``COLUMNS`` when set to a positive integer, else the terminal's width when stdout is
    a terminal, else :data:`DEFAULT_WIDTH`."""
    try:
        cols = int(os.environ.get("COLUMNS", ""))
        if cols > 0:
            return max(cols, 40)
    except ValueError:
        pass
    if sys.stdout.isatty():
        return max(shutil.get_terminal_size((DEFAULT_WIDTH, 24)).columns, 40)
    return DEFAULT_WIDTH


def _terms(expr) -> list:
    if isinstance(expr, sp.Add | sp.MatAdd):
        return list(expr.args)
    return [expr]


def expr_lines(expr, width: int, indent: str = "") -> list[str]:
    """``expr`` in book notation as lines no wider than ``width`` (where possible).

    A sum too wide for one line gets one term per line (``+``/``-`` leading), a matrix one
    row per line, then one entry per line; a single term still too wide is broken at
    spaces.
    """
    t = notation.text(expr)
    if len(indent) + len(t) <= width:
        return [indent + t]
    if isinstance(expr, sp.MatrixBase):
        rows = [notation.text(expr.row(i)) for i in range(expr.rows)]
        if all(len(indent) + len(r) + 2 <= width for r in rows):
            return [indent + ("[" if i == 0 else " ") + r[1:-1] + ("]" if i == expr.rows - 1
                                                                   else ";")
                    for i, r in enumerate(rows)]
        out = []
        for i in range(expr.rows):
            for j in range(expr.cols):
                out.append(f"{indent}[{i + 1},{j + 1}] =")
                out += expr_lines(expr[i, j], width, indent + "    ")
        return out
    if isinstance(expr, sp.BlockMatrix):
        out = []
        b = expr.blocks
        for i in range(b.rows):
            for j in range(b.cols):
                out.append(f"{indent}block [{i + 1},{j + 1}] =")
                out += expr_lines(b[i, j], width, indent + "    ")
        return out
    terms = _terms(expr)
    if len(terms) > 1:
        out = []
        for k, term in enumerate(terms):
            neg = notation.is_negative_term(term)
            body = -term if neg else term
            sign = ("- " if neg else "+ ") if k else ("-" if neg else "")
            sub = expr_lines(body, width, indent + "  ")
            out.append(indent + sign + sub[0].lstrip())
            out += sub[1:]
        return out
    if isinstance(expr, sp.MatMul | sp.Mul) and any(len(notation.text(a)) > width // 2
                                                   for a in expr.args):
        # a product with a long factor (a sum in parentheses): factors on their own lines
        out = [f"{indent}product of:"]
        for a in expr.args:
            out += expr_lines(a, width, indent + "    ")
        return out
    return _hard_wrap(t, width, indent)


def _rel_lines(rel: Rel, width: int, indent: str) -> list[str]:
    lhs = notation.text(rel.lhs)
    one = f"{indent}{lhs} = {notation.text(rel.rhs)}"
    if len(one) <= width:
        return [one]
    return [f"{indent}{lhs} ="] + expr_lines(rel.rhs, width, indent + "    ")


def _failing_text(r: Outcome) -> str | None:
    """The book text of the failing member (``ȧ∥ = (ȧ·ω)/‖ω‖²``), if it has one."""
    return next((m["text"] for m in r.members
                 if m["status"] == "fails" and m["role"] != "corrected"), None)


def _verdict_lines(r: Outcome, rec: dict, width: int) -> list[str]:
    """The verdict, its method and bound; an undecided one's reasons (in words,
    not only in the JSON)."""
    verdict = f"Verdict: {r.verdict}"
    if r.verdict != r.expected:
        verdict += f" (EXPECTED {r.expected})"
    verdict += f" · method: {r.method}"
    bound = rec["failure_bound"]
    if bound is not None and r.verdict != "does-not-hold":
        verdict += f" · failure probability <= {bound:.1e}"
    out = [verdict]
    if r.verdict == "undecided":
        for why in undecided_reasons(rec):
            out += _hard_wrap(f"Undecided: {label_text(why)}", width, "  ")
    return out


def explain(r: Outcome, rels: dict[str, list[Rel]], where: str, width: int,
            full: bool = False, ascii: bool = False) -> str:
    """The explanation printed by ``rigidsym show``.

    Args:
        r: the checker's result.
        rels: the statement's relations by role (``printed``, ``claim``, ``corrected``),
            in the order of ``r.members``.
        where: where the declaration lives (module, function, file); shown with ``full``.
        width: the line width to fit.
        full: everything (the expression trees, the repairs, the model, the numeric
            backing); else at most :data:`SHORT_LINES` lines: the members, the verdict,
            the counterexample, the cause and the corrected form, a relation too long for
            :data:`_SHORT_BLOCK` lines summarised in one.
        ascii: spelt in ASCII (``omega``, ``||a||``: :func:`rigidsym.printing.ascii.to_ascii`)
            before the lines are fitted, so that the spelling does not widen them.

    Returns:
        Text, no line wider than ``width`` unless a single unbreakable token is.
    """
    rec = result_record(r, timings=False)
    sec = f"Section {r.section}" if is_user_id(r.id) else f"Book: Sec. {r.section}"
    # where a user's own equation is declared is theirs to know; a book id's, with --full
    head = f"{sec} · {r.kind}" + (f" · declared in {where}"
                                  if full or is_user_id(r.id) else "")
    out = [f"({r.id}) {label_text(r.title)}", *_hard_wrap(head, width, "")]
    out += _verdict_lines(r, rec, width)
    bound = rec["failure_bound"]
    if full and rec.get("transcription"):  # the printed form checked against the LaTeX
        out += _hard_wrap(transcription_words(rec["transcription"]), width, "")
    out += [""]
    pools = {k: list(v) for k, v in rels.items()}
    blocks = {"printed": [], "claim": [], "corrected": []}
    for m in r.members:
        rel = pools[m["role"]].pop(0) if pools.get(m["role"]) else None
        head = f"  [{m['status']}] {label_text(m['label']) or m['role']}"
        if m["status"] in ("holds", "fails"):
            head += f" ({m['method']})"
        if rel is not None:
            body = _rel_lines(rel, width, "      ")
        elif m.get("text"):  # a corrected member found by the repair search
            body = _hard_wrap(m["text"], width, "      ")
        else:
            body = []
        if not full and len(body) > _SHORT_BLOCK:
            body = [f"      ({len(body)} lines of expression: rigidsym show {r.id} --full)"]
        blocks[m["role"]] += [head + ":"] + body
    titles = {"printed": "Members as printed:", "claim": "Claims it makes:",
              "corrected": "Corrected form (verified):"}
    for role in ("printed", "claim"):
        if blocks[role]:
            out += [titles[role]] + blocks[role] + [""]
    if r.verdict == "does-not-hold":
        fm = r.failing_member
        fails = f"member “{label_text(fm)}”" if fm else "the equation (its only member)"
        out += [f"Fails: {fails}", *_hard_wrap(label_text(cause_sentence(r)), width, "  "), ""]
        ce = counterexample_record(r.counterexample)
        if ce:
            lines = text_lines(ce, sides_of(_failing_text(r)), width, whose_symbols(r.id))
            out += (lines if full else _short_counterexample(lines, r.id)) + [""]
    if blocks["corrected"]:
        title = titles["corrected"]
        if r.correction == "found by search":
            title = "Corrected form (found by the repair search, verified):"
        if bound is not None:
            title = title[:-1] + f" (failure probability <= {bound:.1e}):"
        out += [title] + blocks["corrected"] + [""]
    if full:
        out += repair_lines(r, width)
    if r.singular:
        out += _hard_wrap(f"Singular set: {label_text(r.singular)}", width, "")
    if full and r.model:
        out += _hard_wrap("Model: " + "; ".join(r.model), width, "")
    # the record's numeric field: the one bound of every view (floored as in the report)
    if full and numeric_sentence(rec["numeric"]):
        out += _hard_wrap(numeric_sentence(rec["numeric"]), width, "")
    out += _hard_wrap(GLOSSARY_HINT, width, "")
    if ascii:
        out = _spelt(out, width)
    if not full:
        out = _fit_short(out, r.id, width)
    return "\n".join(out)


def _spelt(lines: list[str], width: int) -> list[str]:
    """``lines`` spelt in ASCII, each one the spelling made wider than ``width`` broken again
    at its spaces, kept at its indentation."""
    from rigidsym.printing.ascii import to_ascii

    out = []
    for line in (x for text in lines for x in to_ascii(text).split("\n")):
        body = line.lstrip(" ")
        out += [line] if len(line) <= width else \
            _hard_wrap(body, width, line[:len(line) - len(body)])
    return out


def _short_counterexample(lines: list[str], eq_id: str) -> list[str]:
    """The counterexample's point and sides, each entry cut to its first line but the
    residual (where the sides differ), whose exact rows are kept up to
    :data:`_SHORT_RESIDUAL` more lines; without how the point was chosen (``--full``
    keeps it)."""
    entries: list[list[str]] = []
    for line in lines:
        if line.lstrip().startswith("How the point was chosen"):
            break
        if line.startswith("    ") and entries:  # a continuation of the entry above
            entries[-1].append(line)
        else:
            entries.append([line])
    out, cut = [], False
    for head, *rest in entries:
        if head.startswith("  residual"):  # its exact rows; the decimals beneath, --full
            rest = rest[:next((k for k, x in enumerate(rest) if x.lstrip().startswith("≈")),
                              len(rest))]
        if not rest or (head.startswith("  residual") and len(rest) <= _SHORT_RESIDUAL):
            out += [head, *rest]
        else:
            out.append(head + " …")
            cut = True
    if cut:
        out.append(f"  (… : the entry goes on; rigidsym show {eq_id} --full)")
    return out


def _fit_short(out: list[str], eq_id: str, width: int) -> list[str]:
    """At most :data:`SHORT_LINES` lines: the excess is cut at the end of the members and
    counterexample blocks, keeping the cause, and a last line points at ``--full``."""
    more = _hard_wrap(f"More (the expression trees, the repairs, the model): rigidsym show "
                      f"{eq_id} --full", width, "")
    if len(out) + len(more) <= SHORT_LINES:
        return out + more
    tail = _hard_wrap(f"{len(out) - SHORT_LINES + 1} more lines: rigidsym show {eq_id} "
                      f"--full", width, "")
    return out[:SHORT_LINES - len(tail)] + tail


def repair_lines(r: Outcome, width: int) -> list[str]:
    """The repairs of a does-not-hold, in book notation with each edited
    subterm in ``⟦…⟧``: per failing member, what was searched and each repair kept, with
    its method, failure bound and whether it is the declared correction."""
    if not r.repair_search and r.correction is None:
        return []
    out = ["Repairs (the smallest edits that make a failing member hold, each verified; "
           "⟦…⟧ marks the edited subterm):"]
    out = _hard_wrap(out[0], width, "")
    if r.correction is not None:
        out += _hard_wrap(f"Correction: {r.correction}", width, "  ")
    for s in r.repair_search:
        who = f"member “{label_text(s['member'])}”" if s["member"] else "the equation"
        out += _hard_wrap(f"{who}: {s['words']}", width, "  ")
        mine = [x for x in r.repairs if x["member"] == s["member"]]
        for k, x in enumerate(mine, 1):
            tags = [x["method"]]
            if x["failure_bound"] is not None:
                tags.append(f"failure probability <= {x['failure_bound']:.1e}")
            if x["equals_declared"]:
                tags.append("the declared correction")
            out += _hard_wrap(f"{k}. {'; then '.join(x['edits'])} ({', '.join(tags)})",
                              width, "    ")
            out += _hard_wrap(x["text"], width, "       ")
    return out + [""]
