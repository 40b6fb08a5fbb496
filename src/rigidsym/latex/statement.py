"""A reader's LaTeX statement made into a declaration: the LaTeX and its
``--let`` declarations read into a :class:`Statement` the checker decides like any other
(LaTeX in, verdict out: ``rigidsym check --latex``, :func:`rigidsym.check_latex`).

The ``--let`` declarations themselves (``NAME: KIND``, ``NAME = LATEX``) and what a reader's
modules lend are read by :mod:`rigidsym.latex.lets`; here they name the statement's glyphs.
With a book section the glyph table names the glyphs; otherwise a symbol no ``--let``
declares is free, its shape by the book's convention (bold lower-case a 3-vector, bold
capital a 3 x 3 matrix, anything else a scalar), and the reading says so.
"""

from __future__ import annotations

import hashlib
import itertools
import json
from dataclasses import dataclass, field

import sympy as sp

from rigidsym.core.errors import BadInput
from rigidsym.latex import guards
from rigidsym.latex.declgraph import glyph_keys
from rigidsym.latex.hats import no_hat_reading
from rigidsym.latex.kinematics import dot_key
from rigidsym.latex.lets import Let, declared_lets, lent, rated_lets, read_lets
from rigidsym.latex.reader_glyphs import GlyphReader
from rigidsym.latex.shapes import LatexError
from rigidsym.latex.transformer.extent import is_extent_point
from rigidsym.latex.transformer.meanings import alternatives, said
from rigidsym.latex.unused import defaulted_glyphs, unused_lets
from rigidsym.latex.values import (
    entry_vectors,
    glyph_values,
    read_models,
    resolve_models,
    value_shape_words,
)
from rigidsym.printing import notation
from rigidsym.registry.declarations import Rel, Statement

__all__ = ["Reading", "read_statement", "read_one", "said_choices", "latex_id", "check_book",
           "book_sections", "declare_latex"]


@dataclass
class Reading:
    """A reader's LaTeX read into a statement.

    Attributes:
        statement: the :class:`Statement` (printed relations in book symbols, the model).
        kind: ``identity`` or ``definition`` (every relation an ``\\equiv``).
        text: how it was read, in book notation (``"Qᵀ Q = 𝟏"``).
        notes: what the reading assumed: free symbols and their conventional shapes, glyph
            rows of the book, a module's models, the parser's own readings.
        free: the keys of the symbols nothing declares.
    """

    statement: Statement
    kind: str
    text: str
    notes: list[str] = field(default_factory=list)
    free: list[str] = field(default_factory=list)
    choices: dict = field(default_factory=dict)  # the choice taken at each choice point
    others: list = field(default_factory=list)  # the other readings that type-check
    dropped: list = field(default_factory=list)  # (choices, why) of those that do not
    eq: object = None  # its registered Equation (declare_latex)
    symbols: dict = field(default_factory=dict)  # glyph key (the LaTeX) -> book symbol's name
    rows: dict = field(default_factory=dict)  # glyph key -> its Glyph (where its meaning came)
    unused: tuple = ()  # the keys of the --lets it does not use (said back in its notes)



def latex_id(latex: str, lets: list[Let], book: str | None, modules,
             notation: str | None = None) -> str:
    """The id of a LaTeX check: ``latex:`` and a short hash of the input."""
    from rigidsym.latex import contested, quaternions, tangent

    # a --let 'tangent order: ...', '\otimes: JPL' or 'bracket cross: content' (taken out
    # of lets) joins the id
    said = [x for x in (tangent.declared(), quaternions.declared(), quaternions.layout(),
                        *contested.declared_texts()) if x]
    key = json.dumps([latex, [x.text for x in lets] + said, book,
                      [str(m) for m in modules or ()]] + ([notation] if notation else []))
    return "latex:" + hashlib.sha256(key.encode()).hexdigest()[:10]


def book_sections() -> list[str]:
    """The sections ``--book`` takes: the book's chapter, sections and subsections, those
    its declarations and its glyph table name (each with the sections above it), in book
    order."""
    from rigidsym.latex.table import glyph_table
    from rigidsym.registry.declarations import REGISTRY, is_user_id, load_all

    load_all()
    named = {eq.section for k, eq in REGISTRY.items() if not is_user_id(k)}
    named |= {g.section for g in glyph_table() if g.section != "*"}
    known = {".".join(s.split(".")[:n]) for s in named if s
             for n in range(1, len(s.split(".")) + 1)}
    return sorted(known, key=lambda s: tuple(int(x) for x in s.split(".") if x.isdigit()))


def check_book(book: str) -> str:
    """Validate a ``--book`` section: one of :func:`book_sections` (the chapter, a section,
    a subsection).

    Raises:
        BadInput: any other, naming a section and a subsection the book has.
    """
    known = book_sections()
    if not isinstance(book, str) or book.strip() not in known:
        such = [s for s in known if s.count(".") == 1][:1] + [
            s for s in known if s.count(".") == 2][:1]
        raise BadInput(f"--book: expected a section of the book such as "
                       f"{' or '.join(such) or 'its chapter'}, got {book!r}")
    return book.strip()


def read_statement(latex: str, lets: list[Let], book: str | None = None,
                   lend: dict | None = None, table=None) -> Reading:
    """Read a reader's LaTeX and its declarations into a :class:`Reading`: every reading
    of its choice points (``X(\\mathbf{y})``, ``X`` a model: a product or an application;
    ``[\\mathbf{a}]``: its hat or a bracket that groups; the first :data:`_MAX_POINTS` points)
    that type-checks, the first returned, the others in its
    ``others`` (the checker decides each, a verdict only when all agree).

    Args and Raises: as :func:`read_one`; when no reading type-checks, the first reading's
    error.
    """
    try:
        first = read_one(latex, lets, book, lend, table)
    except (LatexError, BadInput) as exc:
        if not getattr(exc, "choice_points", None):
            raise
        first, error, points = None, exc, exc.choice_points
    else:
        if not first.choices:
            return _typed(first)
        error, points = None, first.choices
    while True:
        kept, dropped, met = _readings(latex, lets, book, lend, table, first, points)
        # a point met only in a reading that failed (the second hat of \hat{u}v = -\hat{v}u,
        # reached once the first hat is a matrix): while no reading type-checks, its
        # readings are enumerated too; never once one has (the kept ones stay those decided)
        if kept or not met:
            break
        points = {**points, **met}
    if not kept:  # no reading type-checks: the first one's error, or its shapes refused
        hat = no_hat_reading(points, dropped)  # an undeclared hat: its meanings named
        if hat:
            raise BadInput(hat)
        if first is None:
            raise error
        return _typed(first)
    kept[0].others, kept[0].dropped = kept[1:], dropped
    for choices, why in dropped:
        kept[0].notes.append(f"not read as {said_choices(choices)}: {why}")
    return kept[0]


#: choice points enumerated (2**3 readings at most); more are refused, never decided on some
#: readings (q_1^2 + ... + q_4^2 = q^T q has 16, and any 8 of them could miss the one
#: meant)
_MAX_POINTS = 3


def _readings(latex, lets, book, lend, table, first, points):
    """``(kept, dropped, met)``: the readings of every combination of ``points``' readings
    that type-check, those that do not with why, and the choice points that the failing
    ones met beyond ``points``."""
    groups: dict[str, list[str]] = {}  # q_{1} of q, q_{2} of q: one notation, chosen together
    for k in sorted(points):
        groups.setdefault(_group(k), []).append(k)
    if len(groups) > _MAX_POINTS:
        raise BadInput(
            f"--latex: {len(groups)} constructs each read two ways ({', '.join(groups)}): "
            f"{2 ** len(groups)} readings, more than the {2 ** _MAX_POINTS} decided, and a "
            f"verdict on some of them would be a guess: settle some with a --let (a kind "
            f"for a vector's letter, a model or a function)")
    kept, dropped, met = [], [], {}
    for combo in itertools.product(*(alternatives(g[0]) for g in groups.values())):
        choices = {k: c for g, c in zip(groups.values(), combo, strict=True) for k in g}
        try:
            r = first if first is not None and choices == first.choices else read_one(
                latex, lets, book, lend, table, choices)
        except (LatexError, BadInput) as exc:
            dropped.append((choices, str(exc).splitlines()[0]))
            met.update({k: v for k, v in (getattr(exc, "choice_points", None) or {}).items()
                        if k not in points})
            continue
        why = _shape_slip(r)
        if why:
            dropped.append((choices, why))
            continue
        kept.append(r)
    return kept, dropped, met


def _group(key: str) -> str:
    """The choice points read alike: the subscripts of one vector's letter (``q_{1} of q``,
    ``q_{2} of q``: all entries of q or all names, never some of each), else the point."""
    if is_extent_point(key):  # every argument extent of a statement: one book's habit
        return "argument extent"
    return "entries of " + key.split(" of ", 1)[1] if " of " in key else key


def said_choices(choices: dict) -> str:
    """The choices taken at a reading's choice points, in words (``"R(x) read as a product;
    ..."``), sorted by point, for its notes and the CLI."""
    return "; ".join(said(k, c) for k, c in sorted(choices.items()))


def _words(shape) -> str:
    """A side's shape in words (a 1x1 side is a scalar)."""
    return "a scalar" if tuple(shape) in ((1, 1), ()) else f"a {value_shape_words(shape)}"


def _typed(r: Reading) -> Reading:
    """``r`` when its sides have one shape; else bad input naming both shapes (
    shapes are types; a scalar equal to a vector is no equation to decide, and before it
    was does-not-hold)."""
    why = _shape_slip(r)
    if why:
        raise LatexError(f"{why} in '{r.text}': an equation's sides have one shape, "
                         f"so this is no verdict to give; say what each symbol is with a "
                         f"--let if a shape is not the one meant", "shapes")
    return r


def _shape_slip(r: Reading) -> str:
    """Why a reading does not type-check (sides of different shapes), or ``""``."""
    from rigidsym.checking.deciding.explicit import UnknownShape, shape_of

    for rel in r.statement.printed:
        try:
            sl, sr = shape_of(rel.lhs), shape_of(rel.rhs)
        except UnknownShape:
            continue
        if sl != sr:
            return (f"the two sides differ in shape ({_words(sl)} = {_words(sr)})")
    return ""


def read_one(latex: str, lets: list[Let], book: str | None = None,
             lend: dict | None = None, table=None, choices: dict | None = None) -> Reading:
    """Read a reader's LaTeX and its declarations into a :class:`Statement`.

    Args:
        latex: the LaTeX (one or more relations, ``=``/``\\equiv`` chains).
        lets: its declarations (:func:`read_lets`).
        book: a book section whose glyph-table rows name the glyphs, or ``None``.
        lend: symbols a module lends, by name: ``name -> (symbol, model value or None)``.
        table: a book's :class:`~rigidsym.latex.notations.Notation` (``--notation``),
            below the ``--let`` declarations.
        choices: how to read each choice point by key (``{"R": "apply"}``), the default
            (a product) for the others.

    Returns:
        The :class:`Reading`, its ``choices`` the choice taken at each point met.

    Raises:
        LatexError: LaTeX that cannot be read (position and caret; an unknown macro
            named; a juxtaposition that depends on an undeclared shape asks for a --let).
        BadInput: a --let naming a symbol that occurs nowhere, spelt near an undeclared
            glyph (:mod:`rigidsym.latex.unused`), an ambiguous book glyph, models that refer
            to each other in a cycle or whose shape differs from a use.
    """
    lend = lend or {}
    lets = list(lets) + declared_lets(latex, lets)  # ", R \\in SO(3)": a --let
    lets += rated_lets(lets)  # --let '\\dot{X} = ...' alone: X a function of time
    functions = _notation_functions(latex, lets, table)
    lets += functions
    rd = GlyphReader(lets, book, lend, table, _mentioned(latex, lets))
    rd.by_notation |= {x.key for x in functions}
    rd.choices = dict(choices or {})
    try:
        return _read(rd, latex, lets, lend, table)
    except (LatexError, BadInput) as exc:
        exc.choice_points = {k: rd.choices.get(k, alternatives(k)[0]) for k in rd.choice_points}
        raise


def _mentioned(latex: str, lets: list[Let]) -> frozenset[str]:
    """The glyph keys the LaTeX and the ``--let`` models mention (one that does not parse
    mentions none here: the parse proper says why)."""
    out: set[str] = set()
    for text in [latex] + [x.latex for x in lets if x.latex]:
        try:
            out |= glyph_keys(text)
        except LatexError:
            pass
    return frozenset(out)


def _notation_functions(latex: str, lets: list[Let], table) -> list[Let]:
    """The functions of the notation ``table`` (``R_X(\\theta) = ...``) whose NAME the LaTeX,
    a ``--let``'s model or a function so taken mentions, and no ``--let`` declares: read as
    that ``--let`` would be (Diebel's ``R_{123}(\\phi,\\theta,\\psi) = R_1(\\phi)\\ldots``
    given by ``--let`` takes the table's ``R_1(\\alpha)``)."""
    if table is None or not table.functions:
        return []
    own = {x.key for x in lets}
    out: list[Let] = []
    todo, seen = [latex] + [x.latex for x in lets if x.latex], set()
    while todo:
        try:
            used = glyph_keys(todo.pop()) - seen
        except LatexError:
            continue  # the parse proper says why
        seen |= used
        for x in table.functions:
            if x.key in used and x.key not in own:
                own.add(x.key)
                out.append(x)
                todo.append(x.latex or "")
    return out


def _read(rd: GlyphReader, latex: str, lets: list[Let], lend: dict, table) -> Reading:
    """:func:`read_one`'s body."""
    from rigidsym.checking.deciding.explicit import EXPLICIT_CACHE, explicit

    values: dict = {}  # book symbol -> value in book symbols (resolved below)
    occurs = read_models(rd, lets, values)
    models = {sym.name: v for sym, v in values.items()}  # the --let models, for R(\theta)
    parsed = rd.parse(latex, "the LaTeX")
    values.update(rd.models)
    models.update({sym.name: v for sym, v in rd.models.items()})
    occurs |= set(parsed.glyphs) | rd.in_models
    undeclared = sorted(k for k in occurs if k.startswith("[") and k not in {x.key for x in lets}
                        and getattr(rd.glyphs.get(k), "meaning", "") != "body velocity")
    if undeclared:  # Sola's [q]_L: a matrix of its own, which nothing else defines
        k = undeclared[0]
        raise BadInput(f"--latex: {k} (a bracket with a letter subscript, Solà's [\\mathbf{{q}}]_L "
                       f"and [\\mathbf{{q}}]_R) is a name of its own that no --let declares: "
                       f"declare its model, e.g. --let '{k} = \\begin{{bmatrix}} ... "
                       f"\\end{{bmatrix}}', or its kind, --let '{k}: 4x4 matrix'")
    # an angle of which only \dot X occurs is used (Greenwood's psi), and so is a model
    # (Lee's e_R, read only as \dot{e}_R: the model's rate) and a vector whose entries alone
    # occur (q_0 ... q_3 of Hanson's q in R's model)
    occurs |= entry_vectors(occurs, lets)
    unused = [x for x in lets if x.key not in occurs and not ((x.latex or x.kind.split(
        " in ")[0] in ("angle", "scalar")) and dot_key(x.key) in occurs)]
    defaulted = defaulted_glyphs(occurs, {x.key for x in lets}, rd,
                                 rd.notes + list(parsed.readings))
    # the glyphs a --let names with a kind or a model of their own (a rate's line, Wie's
    # \dot q_1 = ..., leaves q_1 undeclared: its letter's unused --let stays refused)
    own_names = {x.key for x in lets if not x.key.startswith(("\\dot{", "\\ddot{"))}
    unused_notes = unused_lets(unused, defaulted, [k for k in parsed.glyphs if getattr(
        rd.glyphs.get(k), "meaning", "") != "body velocity"],  # the user's glyphs only
        occurring=[k for k in occurs if getattr(rd.glyphs.get(k), "meaning", "")
                   != "body velocity" and k not in own_names])
    notes, free = glyph_values(rd, lend, values,
                                [e for chain in parsed.chains for e in chain])
    notes += unused_notes
    unused_keys = tuple(x.key for x in unused)
    if table is not None and rd.by_notation & rd.used:
        notes.insert(0, f"--notation {table.name} ({table.title}): " + "; ".join(
            rd.declared[k].text for k in sorted(rd.by_notation & rd.used)))
    glyphs = {**rd.glyphs, **rd.over}
    models.update({name: v for name, (_, v) in lend.items() if v is not None})
    guards.applications(parsed.applied, models, glyphs)
    guards.zero_entries(free, glyphs)  # before: theta_0 makes its rate free too
    guards.time_derivatives(free, rd.used, rd.declared,
                            guards.takes_no_derivative(latex, lets))
    guards.book_meanings(free)
    guards.notation_bases(free, glyphs, table)
    guards.matrix_entries(free, glyphs)
    model = resolve_models(values, explicit)
    EXPLICIT_CACHE.clear()
    printed, kind = _relations(parsed)
    guards.conventional_shapes(printed, free, glyphs)
    defines = tuple(r.lhs.name for r in printed) if kind == "definition" else ()
    text = "; ".join(f"{notation.text(r.lhs)} {'≡' if kind == 'definition' else '='} "
                     f"{notation.text(r.rhs)}" for r in printed)
    notes += list(dict.fromkeys(rd.notes + parsed.readings))  # each reading once
    st = Statement(printed, model, defines=defines, from_latex=True)
    # the glyphs read (a --notation's kinds are all overrides, used or not)
    used = {k: g for k, g in glyphs.items() if k in rd.glyphs or k in rd.used}
    return Reading(st, kind, text, notes, free,
                   choices={k: rd.choices.get(k, alternatives(k)[0]) for k in rd.choice_points},
                   symbols={k: g.name for k, g in used.items() if g.name}, rows=used,
                   unused=unused_keys)


def _relations(parsed) -> tuple[list[Rel], str]:
    """One relation per ``=`` or ``\\equiv`` of each chain; ``"definition"`` when every one
    is an ``\\equiv`` with a bare symbol on the left, else ``"identity"``."""
    printed, kinds = [], []
    for c, exprs in enumerate(parsed.chains):
        for k in range(1, len(exprs)):
            label = "" if len(parsed.chains) == 1 and len(exprs) == 2 else \
                f"relation {len(printed) + 1}"
            printed.append(Rel(exprs[0], exprs[k], label))
            kinds.append(parsed.ops[c][k - 1])
    kind = "definition" if all(o == "equiv" for o in kinds) and all(
        isinstance(r.lhs, sp.Symbol | sp.MatrixSymbol) for r in printed) else "identity"
    return printed, kind


def declare_latex(latex: str, let=None, *, book: str | None = None, modules=(),
                  notation: str | None = None):
    """Read a reader's LaTeX and register it as the user id ``latex:<hash>``.

    Args:
        latex: the LaTeX.
        let: its declarations (:func:`read_lets`).
        book: a section of the chapter whose glyph table names the glyphs, or ``None``.
        modules: user modules that lend their symbols and models (:func:`lent`).
        notation: a book's notation (``"lynch-park"``; :data:`rigidsym.latex.notations.
            NOTATIONS`): what its symbols are, below the ``let`` declarations.

    Returns:
        ``(equation, reading)``: the registered
        :class:`~rigidsym.registry.declarations.Equation` and the :class:`Reading`.

    Raises:
        LatexError: LaTeX that cannot be read.
        BadInput: a bad declaration, section or module (see :func:`read_lets`,
            :func:`read_statement`).
    """
    from rigidsym.registry.declarations import REGISTRY, equation

    if not isinstance(latex, str) or not latex.strip():
        raise BadInput(f"latex: expected a non-empty LaTeX string, got {latex!r}")
    from rigidsym.latex.notations import notation as _notation

    lets = read_lets(let)
    book = check_book(book) if book is not None else None
    table = _notation(notation) if notation is not None else None
    reading = read_statement(latex, lets, book, lent(modules), table)
    eq_id = latex_id(latex, lets, book, modules, table.name if table else None)
    n = len(reading.statement.printed)
    title = "a relation read from LaTeX" if n == 1 else f"{n} relations read from LaTeX"

    for n, r in enumerate([reading, *reading.others]):
        r_id = eq_id if n == 0 else f"{eq_id}.r{n + 1}"  # another reading
        equation(r_id, title, section=f"book {book}" if book else "latex", latex=latex,
                 kind=r.kind)(lambda st=r.statement: st)
        r.eq = REGISTRY[r_id]
    return REGISTRY[eq_id], reading
