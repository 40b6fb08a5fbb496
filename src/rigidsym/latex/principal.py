"""Undeclared ``I_1, I_2, I_3`` side by side: identities of sizes 1, 2, 3 by rule 6 of
docs/check-latex.md, or the principal moments of inertia, scalars of their own (Kasdin &
Paley's ``\\operatorname{diag}(I_1, I_2, I_3)``), a contested construct
(:data:`rigidsym.latex.contested.CONTESTED`, "principal moments").

Where an undeclared ``I_k`` (k a digit) stands beside an ``I_j`` of another digit inside one
``\\operatorname{diag}(...)`` or one matrix's entries (:func:`open_principal`), the statement
is read with them identities and again with them scalars (:func:`with_scalar_reading`, a
``--let`` each, so that both semantics read that reading from the declarations); a reading
that does not type-check is dropped, and where both decide and differ the answer is bad
input naming both (:func:`both_principal`).
"""

from __future__ import annotations

import re

from rigidsym.latex.respell import each_declaration

__all__ = ["open_principal", "with_scalar_reading", "both_principal"]

#: an identity sized by a digit subscript, plain or bold: I_1, I_{2}, \mathbf{I}_3
_SIZED_I = re.compile(r"(?<![\\A-Za-z])(\\mathbf\s*\{\s*I\s*\}|\\mathbf\s+I|I)\s*_\s*"
                      r"(?:\{\s*(\d)\s*\}|(\d))(?![\d}])")
#: the groups whose entries stand side by side: a diag's argument, a matrix's body
_GROUPS = re.compile(r"\\(?:operatorname|mathrm)\s*\{\s*diag\s*\}\s*(?:\\left)?\s*\(([^()]*)\)"
                     r"|\\begin\s*\{\s*[bpBvV]?matrix\s*\}(.*?)\\end\s*\{\s*[bpBvV]?matrix\s*\}",
                     re.DOTALL)
#: a declaration's NAME
_NAME = re.compile(r"\s*(?:\([^()]*\))?\s*[:=]")


def _key(m: re.Match) -> str:
    """The one spelling of a matched ``I_k``: ``I_{k}`` or ``\\mathbf{I}_{k}``."""
    base = "I" if m.group(1) == "I" else "\\mathbf{I}"
    return f"{base}_{{{m.group(2) or m.group(3)}}}"


def open_principal(latex: str, let: object) -> list[str]:
    """The undeclared ``I_k`` (spelt ``I_{k}``) that stand beside an ``I_j`` of another
    digit inside one ``\\operatorname{diag}(...)`` or one matrix of the LaTeX or a
    declaration, sorted; ``[]`` where there are none (or ``let`` is a value the reader
    refuses, which it says later).

    Args:
        latex: the LaTeX.
        let: the declarations, as :func:`rigidsym.latex.respell.declared_e`'s.
    """
    decls = each_declaration(let)
    if decls is None:
        return []
    declared = set()
    for d in decls:
        name = _NAME.split(d, maxsplit=1)[0].strip()
        m = _SIZED_I.fullmatch(name)
        if m:
            declared.add(_key(m))
    found: set[str] = set()
    for text in [latex, *decls]:
        for g in _GROUPS.finditer(text):
            keys = {_key(m) for m in _SIZED_I.finditer(g.group(1) or g.group(2) or "")}
            keys -= declared
            if len({k[-2] for k in keys}) > 1:
                found |= keys
    return sorted(found)


def with_scalar_reading(let: object, names: list[str]) -> list[str]:
    """``let`` with each of ``names`` (:func:`open_principal`) declared a scalar: the
    statement read with them principal moments of inertia."""
    return [*(each_declaration(let) or []), "; ".join(f"{k}: scalar" for k in names)]


def both_principal(first: str | None, other: str | None, names: list[str], notes: list[str],
                   why_first: str = "", why_other: str = "") -> None:
    """A statement with undeclared ``names`` (:func:`open_principal`) read both ways:
    ``first`` the verdict with them identities, ``other`` with them scalars, ``None`` where
    that reading does not type-check (``why_first``, ``why_other``: the reader's words).
    Where one verdict remains a note is appended to ``notes``.

    Raises:
        BadInput: the verdicts differ: the reading is the reader's to declare.
    """
    from rigidsym.core.errors import BadInput
    from rigidsym.latex.contested import construct

    c = construct("principal moments")
    identity, scalar = c.readings
    shown = ", ".join(names)
    head = f"{shown}: not declared"
    if first is not None and first == other:
        notes.append(f"{head}; read as {identity.means} ({identity.books}) and as "
                     f"{scalar.means} ({scalar.books}): both {first}")
        return
    if other is None or first is None:
        kept, dropped, verdict, why = (identity, scalar, first, why_other) if other is None \
            else (scalar, identity, other, why_first)
        notes.append(f"{head}; read as {kept.means} ({kept.books}): {verdict}; as "
                     f"{dropped.means}, the statement does not type-check ({why})")
        return
    raise BadInput(f"--latex: {shown} are read two ways by the books, as {identity.means} "
                   f"({identity.books}) or as {scalar.means} ({scalar.books}); nothing "
                   f"declares them, and the readings disagree (identities: {first}; scalars: "
                   f"{other}): say which, --let '"
                   + "; ".join(f"{k}: scalar" for k in names)
                   + "' for the principal moments, or a size written out for an identity "
                     "(I_{3\\times 3}, \\mathbf{1}_3)")
