"""What a document declares and defines, relation by relation, in document order.

The declarations come once per document: its reading file (``notes.reading.toml`` beside
``notes.md``, :mod:`rigidsym.reading`) and the ``--let``s of the command line. What the
document itself defines becomes a model (a ``--let 'NAME = LATEX'``) for the relations
after it:

- a relation written with a defining symbol (``:=``, ``\\coloneqq``, ``\\triangleq``,
  ``\\equiv``, ``\\stackrel{\\text{def}}{=}``) whose left side is one symbol or a function of
  parameters (``S(\\mathbf{a})``);
- a relation ``=`` whose left side is one symbol that nothing declared and nothing defined
  before it.

A relation that uses a symbol the document defines only *after* it is refused, naming the
symbol and where its definition stands. Each relation is handed the declarations it uses
(its glyphs, and those of the models it uses, transitively): ``check_latex`` refuses a
declaration of a symbol that does not occur.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from rigidsym.core.errors import BadInput
from rigidsym.documents.conventions import CHOICES
from rigidsym.documents.relations import DEFINING, NOT_CHECKED, Relation
from rigidsym.reading import Reading, lets_for

__all__ = ["CONVENTION_LETS", "Plan", "plan"]

#: a reading file's conventions that ``check_latex`` takes, as the ``--let`` that says each
CONVENTION_LETS = {(key, value): let for key, values in CHOICES.items()
                   for value, let in values.items()}
#: the words of the elisions no verdict is given for
ELISIONS = ("\\cdots", "\\ldots", "\\dots", "\\vdots", "\\ddots", "\\dotsb", "\\dotsc",
            "\\dotsm")


@dataclass
class Plan:
    """What is done with one relation.

    Attributes:
        relation: the relation.
        action: ``decide`` (hand to ``check_latex``), ``definition`` (a model for what
            follows) or ``skip`` (no verdict: ``reason`` says why).
        lets: the declarations it is checked with (``decide``), in ``--let``'s words.
        reason: why it is skipped, naming the text.
        defines: the glyph key it defines (``definition``).
        let: the declaration it becomes (``definition``).
    """

    relation: Relation
    action: str
    lets: list[str] = field(default_factory=list)
    reason: str = ""
    defines: str = ""
    let: str = ""


@lru_cache(maxsize=4096)
def _glyphs(latex: str) -> frozenset[str] | None:
    """The glyph keys of ``latex`` (memoised: a document's models are asked for again by
    every relation after them), or ``None`` where it cannot be read."""
    from rigidsym.latex import LatexError
    from rigidsym.latex.declgraph import glyph_keys

    try:
        return frozenset(glyph_keys(latex))
    except (LatexError, ValueError):
        return None


def _keys(latex: str) -> set[str] | None:
    got = _glyphs(latex)
    return None if got is None else set(got)


@lru_cache(maxsize=4096)
def _one_let(text: str):
    """The :class:`rigidsym.latex.lets.Let` of ``text``, or ``None`` when its NAME is not
    one symbol (or a function of parameters); memoised."""
    from rigidsym.latex import LatexError
    from rigidsym.latex.lets import read_lets

    try:
        return read_lets([text])[0]
    except (BadInput, LatexError, ValueError, IndexError):
        return None


def base_lets(reading: Reading | None, lets: list[str], label: str | None) -> list[str]:
    """The reading's declarations for ``label`` (its conventions first), then ``lets``."""
    out: list[str] = []
    if reading is not None:
        for key, value in reading.conventions.items():
            if (key, value) in CONVENTION_LETS:
                out.append(CONVENTION_LETS[(key, value)])
        out += lets_for(reading, scope=label, id=label)
    return out + list(lets)


def _closure(used: set[str], models: dict[str, tuple[str, set[str]]]) -> set[str]:
    """``used`` and, transitively, the glyphs of the models of its glyphs."""
    todo, seen = list(used), set(used)
    while todo:
        k = todo.pop()
        for g in models.get(k, ("", set()))[1]:
            if g not in seen:
                seen.add(g)
                todo.append(g)
    return seen


def _definitions(relations: list[Relation], declared) -> tuple[list[Plan], list]:
    """The first pass of :func:`plan`: each relation skipped (an elision, a relation not
    checked, an empty side), a definition (``(index, key, let text, relation)`` in ``defs``)
    or a claim to decide, in document order."""
    plans: list[Plan] = []
    defs: list[tuple[int, str, str, Relation]] = []  # (index, key, let text, relation)
    for i, r in enumerate(relations):
        base = declared(r.label)
        if any(e in r.latex for e in ELISIONS):
            word = next(e for e in ELISIONS if e in r.latex)
            plans.append(Plan(r, "skip", reason=f"an elision ({word}) stands for terms not "
                                                f"written"))
            continue
        if r.op in NOT_CHECKED:
            plans.append(Plan(r, "skip", reason=NOT_CHECKED[r.op]))
            continue
        if not r.lhs or not r.rhs:
            plans.append(Plan(r, "skip", reason=f"a side is empty in '{r.latex}'"))
            continue
        text = f"{r.lhs} = {r.rhs}"
        x = _one_let(text)
        earlier = {k for _, k, _, _ in defs}
        if r.op in DEFINING:
            if x is None:
                if r.op == "\\equiv":  # identically equal: an identity
                    plans.append(Plan(r, "decide"))
                    continue
                plans.append(Plan(r, "skip", reason=f"the left side of the definition "
                                                    f"'{r.latex}' is not one symbol"))
                continue
        elif x is None or x.key in base or x.key in earlier:
            plans.append(Plan(r, "decide"))  # declared or defined before: a claim
            continue
        defs.append((i, x.key, text, r))
        plans.append(Plan(r, "definition", defines=x.key, let=text))
    return plans, defs


def plan(relations: list[Relation], reading: Reading | None = None,
         lets: list[str] | tuple[str, ...] = ()) -> list[Plan]:
    """What to do with each relation, in document order (:mod:`this module
    <.declarations>`).

    Args:
        relations: the document's relations, in reading order.
        reading: its reading file, or ``None``.
        lets: ``--let`` declarations of the command line (after the reading's).

    Raises:
        BadInput: a declaration of the reading or of ``lets`` that cannot be read.
    """
    from rigidsym.latex.lets import split_lets

    declared_cache: dict = {}

    def declared(label):
        if label not in declared_cache:
            texts = split_lets(base_lets(reading, list(lets), label))
            kinds = {}
            for t in texts:
                x = _one_let(t)
                if x is None and ":" in t and t.split(":")[0].strip() in (
                        "\\otimes", "\\odot", "tangent order"):
                    kinds[t.split(":")[0].strip()] = (t, set())
                    continue
                if x is None:
                    raise BadInput(f"the declaration '{t}' cannot be read (reading file or "
                                   f"--let)")
                kinds[x.key] = (t, _keys(x.latex) or set() if x.latex else set())
            declared_cache[label] = kinds
        return declared_cache[label]

    plans, defs = _definitions(relations, declared)
    # second pass: each relation's declarations, and definitions used before they stand
    for n, p in enumerate(plans):
        if p.action == "skip":
            continue
        r = p.relation
        at = n
        base = dict(declared(r.label))
        active = {}
        for i, key, text, _ in defs:
            if at <= i:
                break
            active[key] = (text, _keys(text.split("=", 1)[1]) or set())
        models = {**base, **active}
        target = p.let.split("=", 1)[1] if p.action == "definition" else r.latex
        used = _keys(target)
        if used is None:
            if p.action == "decide":
                p.lets = [t for t, _ in models.values()]  # check_latex names the error
            continue
        # by name, then place: a symbol the document defines twice later is named at its
        # first definition (Relations do not compare)
        later = sorted(((k, i, rel) for i, k, _, rel in defs
                        if at < i and k in used and k not in models and k != p.defines),
                       key=lambda x: x[:2])
        if later:
            k, _, rel = later[0]
            plans[n] = Plan(r, "skip", reason=f"uses {k}, which the document defines only "
                                              f"later, at {rel.place} (display {rel.display})")
            continue
        need = _closure(used, models)
        keep = [t for k, (t, _) in models.items()
                if k in need or k in ("\\otimes", "\\odot", "tangent order")]
        if p.action == "decide":
            p.lets = keep
        else:
            p.lets = [t for t in keep if not t.startswith(p.defines)]
    return plans
