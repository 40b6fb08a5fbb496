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
(its glyphs, and those of the models it uses, transitively): ``check_latex`` says back a
declaration of a symbol that does not occur, and refuses one spelt near a glyph it reads
by a default (:mod:`rigidsym.latex.unused`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

from rigidsym.core.errors import BadInput
from rigidsym.documents.conventions import CHOICES
from rigidsym.documents.relations import DEFINING, NOT_CHECKED, Relation
from rigidsym.reading import Reading, lets_for

__all__ = ["CONVENTION_LETS", "Plan", "omitted_lines", "plan", "rate_line",
           "reading_lets", "withheld"]

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
        checked: the LaTeX handed to the check when it is not the relation's own: ``LHS =
            RHS`` for one written with a defining symbol (``\\equiv``) whose left side the
            reading declares for a label it prints as a relation (a claim about that
            symbol); ``""`` otherwise.
    """

    relation: Relation
    action: str
    lets: list[str] = field(default_factory=list)
    reason: str = ""
    defines: str = ""
    let: str = ""
    checked: str = ""


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


_RATE = re.compile(r"(second )?rate of (.+)")


def reading_lets(reading: Reading, label: str | None) -> tuple[list[str], list[tuple[str, str]]]:
    """The reading's ``[[let]]`` lines for ``label`` in ``--let``'s words, and those a
    document's relation is not given, each with why.

    A line is given as written, except:

    - ``atoms_of`` (the glyph's values are another glyph's or a model name's): the model
      ``NAME = SOURCE`` (``d_0 = d0_axial``, ``[\\mathbf{o}]_{\\mathcal{F}} = \\mathbf{o}``),
      which says the same; a model array's entries (``s38_P_*``) are not given;
    - ``NAME: rate of X`` with NAME ``\\dot{X}`` (``second rate``: ``\\ddot{X}``): given as
      written, the rate ``--let`` reads for ``X(t)`` (:func:`rate_line`; the check is handed
      ``X(t)``'s line for it, not the rate's); a rate of another NAME is not given;
    - ``relation`` (the line holds for one relation of the id, a member of a family or a unit
      alternative): not given, the document's relations do not name the member;
    - ``particles`` (the integral over a body as a sum over point masses): not given;
    - a line ``--let`` cannot read (a NAME that is no symbol, ``\\|\\mathbf{v}\\|``): not
      given, with the reader's words.

    Returns:
        ``(lets, omitted)``: the lines given, and ``(line, reason)`` for each not given.
    """
    from rigidsym.latex.lets import model_names, respell_model_names

    texts = lets_for(reading, scope=label, id=label)
    names = model_names(texts)
    by_text = {x.let: x for x in reading.lets}
    given: list[str] = []
    omitted: list[tuple[str, str]] = []
    for t in texts:
        x = by_text[t]
        colon, eq = _top(t, ":"), _top(t, "=")
        kind = t[colon + 1:].strip() if colon >= 0 and (eq < 0 or colon < eq) else ""
        name = t[:colon].strip() if kind else ""
        if x.relation:
            omitted.append((t, f"it holds for one relation of ({label}), '{x.relation}', "
                               f"which the document's relations do not name"))
            continue
        if x.particles:
            omitted.append((t, "a body of point masses (particles): the integral over it as "
                               "the sum over them is not said by --let"))
            continue
        rate = _RATE.fullmatch(kind)
        if rate:
            if rate_line(t) is not None:  # \dot{X} of X(t): the rate --let reads
                given.append(t)
            else:
                dot = "\\ddot" if rate.group(1) else "\\dot"
                omitted.append((t, f"a rate named {name}, not {dot}{{{rate.group(2)}}}, is "
                                   f"not said by --let"))
            continue
        if x.atoms_of:
            if x.atoms_of.endswith("_*"):
                omitted.append((t, f"its values are the entries of the model's array "
                                   f"{x.atoms_of} (atoms_of), not said by --let"))
                continue
            t = _atoms_model(x)
        if _one_let(respell_model_names(t, names)) is None:
            omitted.append((t, _why_not(respell_model_names(t, names))))
            continue
        given.append(t)
    return given, omitted


def rate_line(text: str) -> tuple[str, str] | None:
    """``(key of \\dot{X}, key of X)`` for a reading's ``\\dot{X}: rate of X`` (``\\ddot{X}:
    second rate of X``): the rate ``--let`` reads for a function of time ``X(t)``, which
    ``check_latex`` lists among the symbols it was not told of; ``None`` for another line."""
    colon, eq = _top(text, ":"), _top(text, "=")
    if colon < 0 or 0 <= eq < colon:
        return None
    name, rate = text[:colon].strip(), _RATE.fullmatch(text[colon + 1:].strip())
    if rate is None:
        return None
    dot = "\\ddot" if rate.group(1) else "\\dot"
    if "".join(name.split()) != "".join(f"{dot}{{{rate.group(2)}}}".split()):
        return None
    one, of = _one_let(f"{name}: scalar"), _one_let(f"{rate.group(2)}: scalar")
    return (one.key, of.key) if one is not None and of is not None else None


def withheld(reading: Reading, label: str | None) -> dict[str, str]:
    """The glyphs no relation under ``label`` may be decided with, the reading's lines
    :func:`reading_lets` does not give it being left out: ``{key: the line}``, the line's
    symbol, or every glyph of a line whose NAME is no symbol (``\\|\\mathbf{f}\\| = W``,
    which constrains them)."""
    from rigidsym.latex.lets import model_names, respell_model_names

    names = model_names(lets_for(reading, scope=label, id=label))
    blocked: dict[str, str] = {}
    for t, _ in reading_lets(reading, label)[1]:
        text = respell_model_names(t, names)
        colon, eq = _top(text, ":"), _top(text, "=")
        cut = colon if colon >= 0 and (eq < 0 or colon < eq) else eq
        name = text[:cut].strip() if cut >= 0 else text
        one = _one_let(f"{name}: scalar")
        keys = {one.key} if one is not None else (
            (_keys(name) or set()) | (_keys(text[eq + 1:]) or set() if cut == eq else set()))
        for k in keys:
            blocked.setdefault(k, t)
    return blocked


def omitted_lines(reading: Reading, labels) -> list[dict]:
    """The reading's lines not given to the relations of ``labels`` (:func:`reading_lets`),
    each once with its reason and the labels, in the file's order."""
    out: dict[tuple[str, str], list[str]] = {}
    for label in dict.fromkeys(x for x in labels if x):
        for t, why in reading_lets(reading, label)[1]:
            out.setdefault((t, why), []).append(label)
    return [{"let": t, "reason": why, "labels": ls} for (t, why), ls in out.items()]


def _atoms_model(x) -> str:
    """The model a kind line with ``atoms_of`` is given as: ``NAME = SOURCE``."""
    if not x.atoms_of:
        return x.let
    return f"{x.let[:_top(x.let, ':')].strip()} = {x.atoms_of}"


def _top(text: str, ch: str) -> int:
    depth = 0
    for i, c in enumerate(text):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == ch and depth == 0:
            return i
    return -1


def _why_not(text: str) -> str:
    """Why ``--let`` does not read ``text`` (its own words)."""
    from rigidsym.latex import LatexError
    from rigidsym.latex.lets import read_lets

    try:
        read_lets([text])
    except (BadInput, LatexError, ValueError) as exc:
        return "--let does not read it: " + str(exc).splitlines()[0]
    return "--let does not read it"


def base_lets(reading: Reading | None, lets: list[str], label: str | None) -> list[str]:
    """The reading's declarations for ``label`` (its conventions first; the lines a
    document's relation is given, :func:`reading_lets`), then ``lets``."""
    out: list[str] = []
    if reading is not None:
        for key, value in reading.conventions.items():
            if (key, value) in CONVENTION_LETS:
                out.append(CONVENTION_LETS[(key, value)])
        out += reading_lets(reading, label)[0]
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


def _definitions(relations: list[Relation], declared,
                 printed_class=lambda label: None) -> tuple[list[Plan], list]:
    """The first pass of :func:`plan`: each relation skipped (an elision, a relation not
    checked, an empty side), a definition (``(index, key, let text, relation)`` in ``defs``)
    or a claim to decide, in document order. A relation whose label the reading prints as a
    relation (``printed_class``, its ``[classes]``) is a claim, never a definition."""
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
        if printed_class(r.label) == "relation":  # the reading: a relation, a claim
            plans.append(Plan(r, "decide", checked=f"{r.lhs} = {r.rhs}" if r.op in DEFINING
                              and x is not None and x.key in base else ""))
            continue
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


def _declared(texts: list[str], label, by_id: set, clashes: dict, pinned: dict) -> dict:
    """The glyphs the declarations ``texts`` of relation ``label`` declare: ``{glyph key:
    (the line, the glyph keys its model uses)}``; two lines read as one glyph go to
    ``clashes[label]``, a line the reading gives the label by its id to ``pinned[label]``.

    Raises:
        BadInput: a declaration that cannot be read.
    """
    from rigidsym.latex.lets import model_names, respell_model_names

    names = model_names(texts)
    kinds: dict = {}
    for t in texts:
        rl = rate_line(t)
        if rl is not None:  # \dot X of X(t): needs X(t)'s line
            kinds[rl[0]] = (t, {rl[1]})
            if t in by_id:
                pinned.setdefault(label, set()).add(rl[0])
            continue
        x = _one_let(respell_model_names(t, names))
        if x is None and ":" in t and t.split(":")[0].strip() in (
                "\\otimes", "\\odot", "tangent order"):
            kinds[t.split(":")[0].strip()] = (t, set())
            continue
        if x is None:
            raise BadInput(f"the declaration '{t}' cannot be read (reading file or --let)")
        if x.key in kinds:  # two lines the reader reads as one glyph: neither
            clashes.setdefault(label, {}).setdefault(x.key, [kinds[x.key][0]]).append(t)
            continue
        kinds[x.key] = (t, _keys(x.latex) or set() if x.latex else set())
        if t in by_id:
            pinned.setdefault(label, set()).add(x.key)
    return kinds


def _withheld_or_clashing(label, need: set, blocked: dict, clashes: dict, active: dict,
                          pinned) -> str | None:
    """Why relation ``label``, which needs the glyphs ``need``, is not checked: one of them
    has a line of the reading not given to it (``blocked``), or two lines read as one glyph
    (``clashes``) that the document's own definitions (``active``) do not settle; ``None``
    where neither."""
    cut = sorted(k for k in blocked if k in need)
    if cut:
        return (f"uses {cut[0]}, whose line of the reading for ({label}), "
                f"'{blocked[cut[0]]}', is not given (listed with why)")
    clash = sorted(k for k in clashes if k in need and (k not in active or k in pinned))
    if clash:
        lines = " and ".join(f"'{t}'" for t in clashes[clash[0]])
        return (f"the declarations {lines} are read as one glyph {clash[0]} for ({label}): "
                "which one it uses is not said")
    return None


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
    clashes: dict = {}  # label -> glyph key -> the lines that declare it
    pinned: dict = {}  # label -> the glyph keys the reading gives that label by its id
    by_id = {t for x in reading.lets if x.ids for t in (x.let, _atoms_model(x))} \
        if reading is not None else set()

    def declared(label):
        if label not in declared_cache:
            declared_cache[label] = _declared(split_lets(base_lets(reading, list(lets), label)),
                                              label, by_id, clashes, pinned)
        return declared_cache[label]

    held_cache: dict = {}

    def held(label):
        if label not in held_cache:
            held_cache[label] = withheld(reading, label) if reading is not None and label \
                else {}
        return held_cache[label]

    def printed_class(label):
        got = reading.ids.get(label) if reading is not None and label else None
        return got.cls if got is not None else None

    plans, defs = _definitions(relations, declared, printed_class)
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
        for k in pinned.get(r.label, ()):  # the reading's line for this label by its id wins
            if k in base:
                models[k] = base[k]
        blocked = held(r.label)
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
        why = _withheld_or_clashing(r.label, need, blocked, clashes.get(r.label, {}), active,
                                    pinned.get(r.label, ()))
        if why:
            plans[n] = Plan(r, "skip", reason=why)
            continue
        keep = [t for k, (t, _) in models.items()
                if k in need or k in ("\\otimes", "\\odot", "tangent order")]
        if p.action == "decide":
            p.lets = keep
        else:
            p.lets = [t for t in keep if not t.startswith(p.defines)]
    return plans
