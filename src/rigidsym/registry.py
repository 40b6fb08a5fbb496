"""The equation registry: one declaration per numbered equation of the book.

A declaration is a function in ``derivations/`` decorated with :func:`equation`. It returns a
:class:`Statement`: the printed equation transcribed member by member in the book's symbols
(garbles included), the *model* (first-principles values of those symbols, derived
independently of the printed form), and, when the printed form does not hold, the
corrected form. The verdict is never typed in: the checker computes it; the *expected*
verdict sits next to the declaration as data so that a regression flips loudly.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from typing import Any

__all__ = [
    "Rel",
    "Statement",
    "Equation",
    "equation",
    "REGISTRY",
    "KINDS",
    "VERDICTS",
    "CAUSES",
    "SECTIONS",
    "parse_id",
    "section_of",
    "load_all",
    "select",
    "BadInput",
]

KINDS = ("identity", "definition", "claim")
VERDICTS = ("verified", "definition", "does-not-hold", "undecided")
CAUSES = ("conversion", "erratum", "unknown")
#: Book sections that hold numbered equations or claims.
SECTIONS = ("3.2", "3.3", "3.4", "3.5", "3.6", "3.7", "3.8")

_ID = re.compile(r"^(3\.\d+[a-e]?|(thm|cor|caveat)3\.\d+(\.\d+)?|ex3\.\d+)$")


class BadInput(ValueError):
    """Bad user input (CLI exit code 2)."""


@dataclass(frozen=True)
class Rel:
    """One equality ``lhs = rhs`` to decide (sympy expressions, matrices or matrix expressions).

    ``label`` names the member (``"d_P"``, ``"second member"``) in reports.
    """

    lhs: Any
    rhs: Any
    label: str = ""


@dataclass
class Statement:
    """What a declaration returns.

    Attributes:
        printed: the book's statement as printed, one :class:`Rel` per member, in book
            symbols (``MatrixSymbol``/``Symbol``). A chain ``x = y = z`` gives ``(x, y)`` and
            ``(x, z)``; a garbled symbol is a fresh symbol, never silently repaired.
        model: first-principles values of the book symbols (``symbol -> explicit value``),
            derived without the printed form; substituted before deciding.
        derived: the first-principles value of the quantity (for display and codegen).
        corrected: the corrected form (same conventions as ``printed``), required when the
            printed form does not hold; it must itself verify.
        defines: names of the symbols a definition introduces.
        claims: extra relations a definition or claim asserts that must hold (e.g. the unit
            norm of a direction just defined).
    """

    printed: list[Rel]
    model: dict = field(default_factory=dict)
    derived: Any = None
    corrected: list[Rel] | None = None
    defines: tuple[str, ...] = ()
    claims: list[Rel] = field(default_factory=list)


@dataclass(frozen=True)
class Equation:
    """A registered declaration (metadata plus the builder of its :class:`Statement`)."""

    id: str
    title: str
    section: str
    kind: str
    latex: str
    expected: str
    build_fn: Callable[[], Statement]
    cause: str | None = None
    evidence: str | None = None
    singular: str | None = None
    module: str = ""
    function: str = ""

    def build(self) -> Statement:
        """The statement, built once per run (derivations can be expensive)."""
        return _build(self.id)


REGISTRY: dict[str, Equation] = {}


@cache
def _build(eq_id: str) -> Statement:
    st = REGISTRY[eq_id].build_fn()
    if not isinstance(st, Statement):
        raise TypeError(f"declaration {eq_id} returned {type(st).__name__}, not Statement")
    return st


def section_of(eq_id: str) -> str:
    """The book section (``"3.2"`` … ``"3.8"``) an id belongs to, from the registry."""
    return ".".join(REGISTRY[eq_id].section.split(".")[:2])


def equation(eq_id: str, title: str, *, section: str, latex: str, kind: str = "identity",
             expected: str | None = None, cause: str | None = None,
             evidence: str | None = None, singular: str | None = None):
    """Register a declaration under its book id.

    Args:
        eq_id: the id as printed (``"3.6a"``, ``"thm3.2.1"``).
        title: a short title.
        section: the book (sub)section, e.g. ``"3.2.1"``.
        latex: the printed LaTeX, verbatim from the chapter (a test checks it occurs there).
        kind: ``identity``, ``definition`` or ``claim``.
        expected: the verdict the checker is expected to compute (data, not the verdict);
            defaults to ``definition`` for a definition and ``verified`` otherwise.
        cause: for an expected ``does-not-hold``: ``conversion``, ``erratum`` or ``unknown``.
        evidence: one line of evidence for the cause.
        singular: the singular set of the formula, in words (``"phi = 0"``).

    Raises:
        ValueError: for a malformed or duplicate id, or an unknown kind/verdict/cause.
    """
    if not _ID.match(eq_id):
        raise ValueError(f"eq_id: malformed book id {eq_id!r}")
    if kind not in KINDS:
        raise ValueError(f"kind: expected one of {KINDS}, got {kind!r}")
    if expected is None:
        expected = "definition" if kind == "definition" else "verified"
    if expected not in VERDICTS:
        raise ValueError(f"expected: expected one of {VERDICTS}, got {expected!r}")
    if expected == "does-not-hold" and (cause not in CAUSES or not evidence):
        raise ValueError(f"{eq_id}: a does-not-hold needs a cause in {CAUSES} and evidence")

    def deco(fn):
        if eq_id in REGISTRY:
            raise ValueError(f"equation {eq_id} is declared twice "
                             f"({REGISTRY[eq_id].module}.{REGISTRY[eq_id].function})")
        REGISTRY[eq_id] = Equation(eq_id, title, section, kind, latex, expected, fn, cause,
                                   evidence, singular, fn.__module__, fn.__qualname__)
        return fn

    return deco


def load_all() -> dict[str, Equation]:
    """Import every derivations module (which registers its declarations)."""
    import rigidsym.derivations  # noqa: F401  (import registers)

    return REGISTRY


def _sort_key(eq_id: str):
    m = re.match(r"^(?:thm|cor|caveat)?3\.(\d+)(?:\.(\d+))?([a-e]?)$", eq_id)
    if eq_id.startswith(("thm", "cor", "caveat")):
        sec = REGISTRY[eq_id].section if eq_id in REGISTRY else "3.9"
        return (int(sec.split(".")[1]), 1, eq_id)
    return (int(section_of(eq_id).split(".")[1]) if eq_id in REGISTRY else 99, 0,
            int(m.group(1)), m.group(3))


def parse_id(text: str) -> str:
    """Normalise a user-given id (``"(3.16)"``, ``"eq3.16"`` -> ``"3.16"``).

    Raises:
        BadInput: if the text is not a book id.
    """
    t = text.strip().strip("()")
    if t.lower().startswith("eq"):
        t = t[2:]
    if not _ID.match(t):
        raise BadInput(f"id: expected a book id like 3.16, 3.96e or thm3.2.1, got {text!r}")
    return t


def parse_section(text: str) -> str:
    """Validate a section argument (``"3.2"`` … ``"3.8"``)."""
    if text not in SECTIONS:
        why = {"3.1": " (the introduction holds no equations)",
               "3.9": " (the exercises are run by `rigidsym exercise`)"}.get(text, "")
        raise BadInput(f"section: expected one of {', '.join(SECTIONS)}, got {text!r}{why}")
    return text


def select(ids: list[str] | None = None, sections: list[str] | None = None) -> list[str]:
    """Resolve ids (an id without a letter means all its parts) and sections to sorted ids.

    Raises:
        BadInput: for an unknown id or section, or an id that holds no equation.
    """
    load_all()
    out: set[str] = set()
    for raw in ids or []:
        i = parse_id(raw)
        if i in REGISTRY:
            out.add(i)
            continue
        parts = [k for k in REGISTRY if re.fullmatch(re.escape(i) + "[a-e]", k)]
        if not parts:
            raise BadInput(f"id: {i} holds no declared equation (known: 3.1 ... 3.148 and "
                           f"claims such as thm3.2.1)")
        out.update(parts)
    for s in sections or []:
        s = parse_section(s)
        out.update(k for k in REGISTRY if section_of(k) == s)
    if not ids and not sections:
        out.update(REGISTRY)
    return sorted(out, key=_sort_key)
