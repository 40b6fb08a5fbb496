"""The values of a reading's symbols: the ``--let`` models
and functions, each after those it mentions; each used glyph's value (a declared kind, a
module's model, a glyph-table row or definition, a free matrix of named entries); and the
models made explicit in dependency order, a cycle refused. Used by
:mod:`rigidsym.latex.statement`, which reads the LaTeX itself.
"""

from __future__ import annotations

import re

import sympy as sp

from rigidsym.algebra import symbols as _sym
from rigidsym.core.errors import BadInput
from rigidsym.latex.declgraph import glyph_keys, model_order
from rigidsym.latex.lets import Let, kind_of
from rigidsym.latex.periodic import periodic_angles
from rigidsym.latex.reader_glyphs import GlyphReader, glyph_symbol
from rigidsym.latex.shapes import UNDECLARED, LatexError, matrix_shape
from rigidsym.latex.table import Glyph

__all__: list[str] = []


def value_shape_words(shape) -> str:
    """A shape in a ``--let``'s words: ``scalar``, ``3-vector`` or ``3×3 matrix``."""
    if not shape:
        return "scalar"
    return f"{shape[0]}-vector" if shape[1] == 1 else f"{shape[0]}×{shape[1]} matrix"


#: an entry's key as the parser keys it: ``q_{0}``, ``n_{x}``, ``\\dot{\\epsilon}_{1}`` (the
#: rate of an entry), the letter in group 1 or 2
_ENTRY_KEY = re.compile(r"(?:\\dot\{(\\?[A-Za-z]+)\}|(\\?[A-Za-z]+))_\{(?:[0-9]|[xyz])\}")


def entry_vectors(mentioned: set[str], lets) -> set[str]:
    r"""The declared vectors (keys of ``lets``) of which ``mentioned`` names an entry or an
    entry's rate: ``q_{0}`` beside a --let of ``q`` or ``\mathbf{q}`` (the reader's
    :mod:`rigidsym.latex.entries`: a declared n-vector's entries 1 to n, a 4-vector's 0 to 4,
    a 3-vector's x, y, z; a model's shape is not known before it is read); a subscripted
    glyph a --let declares itself names no entry."""
    shapes = {x.key: (_kind_shape(x) if x.kind else None) for x in lets}
    out: set[str] = set()
    for k in mentioned - set(shapes):
        m = _ENTRY_KEY.fullmatch(k)
        if not m:
            continue
        letter, sub = m.group(1) or m.group(2), k.rsplit("_{", 1)[1][:-1]
        for v in {letter, f"\\mathbf{{{letter}}}", f"\\boldsymbol{{{letter}}}"} & set(shapes):
            n = shapes[v]
            if n is None or (sub in "xyz" and n == 3) or (sub.isdigit() and (
                    1 <= int(sub) <= n or (n == 4 and int(sub) == 0))):
                out.add(v)
    return out


def _kind_shape(x: Let) -> int:
    """The entries of the vector a --let's kind declares, 0 for no vector."""
    try:
        shape = kind_of(x.kind, x.text)[0]
    except BadInput:
        return 0
    return shape[0] if len(shape) == 2 and shape[1] == 1 else 0


def _is_function(x: Let) -> bool:
    return bool(x.params) and x.params != ("t",)  # X(t) = ...: a model in time


def read_models(rd: GlyphReader, lets: list[Let], values: dict) -> set[str]:
    """The ``NAME = LATEX`` models into ``values`` and the ``NAME(params) = LATEX``
    functions into the reader, each after the models it mentions (any order of
    the ``--let``s reads the same); the glyphs they use."""
    mentions = {}
    for x in lets:
        if x.latex:
            try:
                mentions[x.key] = glyph_keys(x.latex) - set(x.param_keys)
            except LatexError:
                mentions[x.key] = set()  # the parse below says why
    # q_0 of R's model mentions the model q: q is read first (where that makes no cycle:
    # K's x_0 beside a model \mathbf{x} = K\mathbf{X} names no entry of it), and is used
    entry = {k: v | (entry_vectors(v, lets) - {k}) for k, v in mentions.items()}
    try:
        order = model_order(lets, entry)
        mentions = entry
    except BadInput:
        order = model_order(lets, mentions)
    occurs: set[str] = set()
    for x in order:
        occurs |= mentions[x.key] | set(x.param_keys)
        if _is_function(x):
            rd.add_function(x)
            _function_model(rd, x, values)
            continue
        if x.key.endswith("^{*}"):  # a starred NAME reads as a name of its own
            rd.over.setdefault(x.key, Glyph(x.key, "*", rd._name(x.key), (), "model", ""))
        rate_of = _rate_of(x.key)
        if rate_of in rd.over:  # --let '\\dot{X} = ...': the rate of X, its NAME
            rd.over.setdefault(x.key, Glyph(x.key, "*", rd._name(x.key), rd.over[rate_of].shape,
                                            "model", "--let model"))
        p = rd.parse(f"{x.name} = {x.latex}", f"--let '{x.text}'")
        if len(p.chains) != 1 or len(p.chains[0]) != 2:
            raise BadInput(f"--let '{x.text}': expected NAME = one expression")
        occurs |= set(p.glyphs) - {x.key}  # its own NAME is no occurrence
        rd.model_readings(x, p.readings)
        rhs = p.chains[0][1]
        g = Glyph(x.key, "*", rd._name(x.key), matrix_shape(rhs) or (), "model", "--let model")
        rd.over[x.key] = g
        rd.model_rhs[g.name] = rhs
        values[glyph_symbol(g)] = rhs
    return occurs


def _rate_of(key: str) -> str:
    """``X`` of a NAME ``\\dot{X}`` (the rate of X), else ``""``."""
    from rigidsym.latex.kinematics import rate_target

    return rate_target(key)


def _function_model(rd: GlyphReader, x: Let, values: dict) -> None:
    """A function of scalar parameters (``R(\\theta) = e^{[\\hat\\omega]\\theta}``) is
    also the model of its NAME (``R`` alone is ``R(θ)``); one of a
    vector or matrix is a function only (``S`` alone is refused)."""
    try:
        p = rd.parse(f"{x.name} = {x.latex}", f"--let '{x.text}'", record=False)
    except LatexError:
        return
    if any(p.glyphs.get(k) is None or p.glyphs[k].shape for k in x.param_keys) \
            or len(p.chains) != 1 or len(p.chains[0]) != 2:
        return
    rd.used.update(p.glyphs)
    rd.glyphs.update(p.glyphs)
    rhs = p.chains[0][1]
    g = Glyph(x.key, "*", rd._name(x.key), matrix_shape(rhs) or (), "model", "--let model")
    rd.over[x.key] = g
    rd.model_rhs[g.name] = rhs
    values[glyph_symbol(g)] = rhs


def glyph_values(rd: GlyphReader, lend: dict, values: dict,
                  printed=()) -> tuple[list[str], list[str]]:
    """Each used glyph's value into ``values`` (a declared kind, a lent model, a glyph-table
    row or definition, a free matrix of named entries, an angle by its uses in ``printed``
    and the models: :mod:`rigidsym.latex.periodic`); the notes and the free glyphs."""
    notes, free, seen, free_, lent_ = [], [], set(), {}, []
    scalars = {(rd.over.get(k) or rd.glyphs[k]).name for k in rd.used
               if not (rd.over.get(k) or rd.glyphs[k]).shape}
    while rd.used - seen:  # a book definition read below may bring glyphs of its own
        key = min(rd.used - seen)
        seen.add(key)
        g = rd.over.get(key) or rd.glyphs.get(key)
        sym = glyph_symbol(g)
        if key in rd.declared:
            x = rd.declared[key]
            value = _fresh(kind_of(x.kind, x.text)[1], g.name, scalars) if x.kind else None
            if value is not None and value != sym:  # a free scalar stands for itself
                values[sym] = value
            continue
        if g.kind == "module":
            value = lend[g.name][1]
            if value is not None:
                values[sym] = value
            lent_.append(f"{key} ({value_shape_words(g.shape)}"
                         f"{', its model' if value is not None else ', free'})")
        elif g.kind == "free":
            free.append(key)
            if g.meaning == UNDECLARED:   # the reader's own (a rate) say what they are
                free_[key] = f"{key} ({value_shape_words(g.shape)})"
        else:  # a glyph-table row of --book
            notes.append(f"{key}: {g.meaning} ({g.name}, {value_shape_words(g.shape)}; "
                         f"glyph table, {g.section})")
            if g.kind == "angle":
                values[sym] = _sym.angle(g.name)
            elif g.definition:
                d = rd.parse(f"{key} = {g.definition}", f"the definition of {key}")
                values[sym] = d.chains[0][1]
        if g.shape and sym not in values:  # a free matrix of named entries (the zero test
            # takes atoms, not Q[0, 0]; and they read better in a counterexample)
            values[sym] = _fresh((lambda n, s=g.shape: _sym.vector(n, n=s[0])) if
                                 g.shape[1] == 1 else
                                 (lambda n, s=g.shape: _sym.matrix(n, *s)), g.name, scalars)
    angles = _periodic_angles(rd, free, values, printed, scalars)
    free_ = [f for k, f in free_.items() if k not in angles]
    notes += [f"{k}: an angle (no --let declares it): it occurs only in {', '.join(fs)}, at "
              f"integer multiples, so the relation has period 2π in {k} and deciding it for "
              f"{k} in (-π, π) decides it for every real {k}" if d == 1 else
              f"{k} = {d}\\psi_{{{k}}}, \\psi_{{{k}}} an angle (no --let declares {k}): it "
              f"occurs only in {', '.join(fs)}, at multiples of 1/{d}, so the relation has "
              f"period {2 * d}π in {k} and deciding it for \\psi_{{{k}}} in (-π, π), {k} in "
              f"(-{d}π, {d}π), decides it for every real {k}" for k, (fs, d) in angles.items()]
    if free_:
        notes.append("free, no --let declares them (shapes by the book's convention: bold "
                     "lower-case a 3-vector, bold capital 3×3, else a scalar): "
                     + ", ".join(free_))
    if lent_:
        notes.append("lent by --module: " + ", ".join(lent_))
    return notes, free


def _periodic_angles(rd: GlyphReader, free: list[str], values: dict, printed,
                     scalars: set[str]) -> dict[str, tuple[list[str], int]]:
    """The free scalar glyphs that are angles by their uses (:mod:`rigidsym.latex.periodic`),
    each with the trigonometric functions it occurs in and its multiple d of an angle; d
    times their angle atoms into ``values``."""
    syms = {glyph_symbol(rd.over.get(k) or rd.glyphs[k]): k for k in free
            if not (rd.over.get(k) or rd.glyphs[k]).shape}
    found = periodic_angles([*printed, *values.values()], syms)
    out = {}
    for sym, (fs, d) in found.items():
        # d > 1: the angle is a quantity of its own (ψ_θ), printed beside θ = d ψ_θ
        values[sym] = _fresh(_sym.angle, sym.name, scalars) if d == 1 else \
            d * _fresh(_sym.angle, f"psi_{sym.name}", scalars)
        out[syms[sym]] = (fs, d)
    return out


def _fresh(factory, name: str, scalars: set[str]):
    """``factory(name)``, its free entries renamed (``a_1`` -> ``a__1``) where one would be
    the same atom as a scalar of the LaTeX (``a_1`` beside ``\\mathbf{a}``): a free entry
    and a scalar glyph are independent quantities, never silently one."""
    value = factory(name)
    while hasattr(value, "free_symbols") and {
            s.name for s in value.free_symbols} & (scalars - {name}):
        name += "_"
        value = factory(name)
    return value


def resolve_models(values: dict, explicit) -> dict:
    """Models in book symbols made explicit, each after those it refers to."""
    done: dict = {}
    todo = dict(values)
    while todo:
        progress = False
        for sym, v in list(todo.items()):
            refs = {a for a in _atoms(v) if a in todo and a != sym}
            if refs:
                continue
            if sym in _atoms(v):
                raise BadInput(f"--let: the model of {sym} refers to {sym} itself")
            done[sym] = explicit(v, done) if isinstance(v, sp.Basic) else v
            del todo[sym]
            progress = True
        if not progress:
            names = ", ".join(str(s) for s in todo)
            raise BadInput(f"--let: the models of {names} refer to each other in a cycle")
    return done


def _atoms(v) -> set:
    if not isinstance(v, sp.Basic):
        return set()
    return set(v.atoms(sp.MatrixSymbol)) | {s for s in v.atoms(sp.Symbol)
                                           if type(s) is sp.Symbol}
