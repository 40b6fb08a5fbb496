"""Plain-data records the checker attaches to a result: members and the model in words.

Kept apart from :mod:`rigidsym.checking.checker` (which decides) because these only describe: book
notation for each member (:mod:`rigidsym.printing.notation`) and the constraints of the atoms.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import TIME, constraint_of
from rigidsym.checking.deciding.explicit import entries_of
from rigidsym.core import kinds as _kinds
from rigidsym.printing import notation

__all__ = ["member_record", "model_words", "printed_latex", "MEMBER_TEXT_LIMIT",
           "MEMBER_LATEX_LIMIT"]


#: member texts longer than this are not kept: such a member is an explicit component
#: matrix (a formula function applied entry by entry), not book notation
MEMBER_TEXT_LIMIT = 400
#: the same for the LaTeX of a member (LaTeX spends about three characters per symbol)
MEMBER_LATEX_LIMIT = 1200


def member_record(rel, role: str, out) -> dict:
    """A member of a statement as plain data.

    Args:
        rel: the relation (:class:`rigidsym.registry.declarations.Rel`).
        role: ``printed``, ``claim`` or ``corrected``.
        out: its decision (``zero``, ``method``, ``detail`` attributes), or ``None`` for a
            member that a definition introduces.

    Returns:
        ``{"role", "label", "status", "method", "detail", "text", "latex"}``: status is
        ``holds``, ``fails``, ``undecided`` or ``defines``; ``text`` (book notation,
        Unicode) and ``latex`` are ``None`` when longer than :data:`MEMBER_TEXT_LIMIT`
        and :data:`MEMBER_LATEX_LIMIT`.
    """
    if out is None:
        status, method, detail = "defines", "definition", ""
    else:
        status = {True: "holds", False: "fails", None: "undecided"}[out.zero]
        method, detail = out.method, out.detail
    # every atom prints as one character at least: past a limit, printing is not needed to
    # know that the form is too long to keep (most of the time of a member record)
    atoms = _atoms(rel.lhs, MEMBER_LATEX_LIMIT + 1) + _atoms(rel.rhs, MEMBER_LATEX_LIMIT + 1)
    try:
        text = "" if atoms + 3 > MEMBER_TEXT_LIMIT else \
            f"{notation.text(rel.lhs)} = {notation.text(rel.rhs)}"
        tex = "" if atoms + 3 > MEMBER_LATEX_LIMIT else \
            notation.latex_relation(rel.lhs, rel.rhs)
    except Exception:  # noqa: BLE001  describing a member must never change a verdict
        text = tex = ""
    return {"role": role, "label": rel.label, "status": status, "method": method,
            "detail": detail,
            "text": text if 0 < len(text) <= MEMBER_TEXT_LIMIT else None,
            "latex": tex if 0 < len(tex) <= MEMBER_LATEX_LIMIT else None}


def printed_latex(members: list[dict]) -> str:
    """The LaTeX of a user's equation as printed, from its printed members (a user id
    declares no ``latex=``): every member whose book notation was kept (at most
    :data:`MEMBER_TEXT_LIMIT` characters, so a form of 160 is always shown), ``""`` when a
    member's was not."""
    tex = [m["latex"] for m in members if m["role"] == "printed"]
    return r",\quad ".join(tex) if tex and all(tex) else ""


def _atoms(x, cap: int) -> int:
    """Occurrences of symbols, functions of time and their derivatives in ``x`` (counted up
    to ``cap``): a lower bound on the length of its text and of its LaTeX."""
    n, stack = 0, [x]
    while stack and n < cap:
        y = stack.pop()
        if isinstance(y, sp.Symbol | sp.MatrixSymbol | AppliedUndef | sp.Derivative):
            n += 1
        elif isinstance(y, sp.MatrixBase):
            stack.extend(y)
        elif isinstance(y, sp.Basic):
            stack.extend(y.args)
    return n


def model_words(exprs) -> list[str]:
    """The atoms of explicit expressions grouped by constraint, in words.

    Returns:
        Sorted lines such as ``"e: unit vector, stereographic"``, then one ``"free: a, ω"``
        line, then ``"along a motion (...)"`` when atoms depend on time.
    """
    try:
        return _model_words(exprs)
    except Exception:  # noqa: BLE001  a description must never change a verdict
        return []


def _leaf_atoms(exprs) -> set:
    """The symbols and functions of time in ``exprs`` (``atoms(Symbol, AppliedUndef)``),
    each shared subtree visited once: the explicit models repeat large subexpressions,
    which ``atoms`` walks again at every occurrence."""
    seen, out = set(), set()
    stack = [sp.sympify(e) for e in exprs]
    while stack:
        y = stack.pop()
        if y in seen:
            continue
        seen.add(y)
        if isinstance(y, sp.Symbol | AppliedUndef):
            out.add(y)
        else:
            stack.extend(y.args)
    return out


def _model_words(exprs) -> list[str]:
    groups, free, timed_any = {}, set(), False
    for a in _leaf_atoms(e for x in exprs for e in entries_of(x)):
        if a == TIME:
            continue
        timed = isinstance(a, AppliedUndef)
        timed_any |= timed
        name = a.func.__name__ if timed else a.name
        c = constraint_of(a)  # carried by the atom (rigidsym.algebra.symbols), not its name
        if c is not None:
            groups[c.name] = c.kind
        else:
            free.add(notation.book_group(name))
    out = sorted(f"{notation.book_text(n)}: {_kinds.get(k).words}" for n, k in groups.items())
    if free:
        out.append("free: " + ", ".join(sorted(free)))
    if timed_any:
        out.append("along a motion (derivatives as jets)")
    return out
