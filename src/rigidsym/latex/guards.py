"""What a reading may not guess: checks of a reader's LaTeX after it is
read, each a :class:`~rigidsym.core.errors.BadInput` (exit 2) that names the
symbol and the ``--let`` that settles it, never a does-not-hold resting on a convention.

- a relation whose two sides differ in shape while a symbol in it has the shape of the
  convention (no ``--let``, model, module or ``--book`` gave it): the symbol, its shape, a
  ``--let``;
- ``\\dot X`` that nothing declares beside an ``X`` of the statement: nothing says how ``X``
  depends on time, so ``\\dot X`` would be a free symbol unrelated to ``X``;
- ``c_1``, ``s_{12}``, ``\\hat\\omega`` that nothing declares: their meaning differs between the
  books (a cosine in Siciliano, a unit vector in Lynch-Park, a skew matrix in
  Murray-Li-Sastry);
- ``R(\\theta)`` with ``R`` applied to two different arguments, or with no model of ``R``, or
  to a symbol its model does not depend on.
"""

from __future__ import annotations

import re

from rigidsym.core.errors import BadInput
from rigidsym.latex.depends import names as _names
from rigidsym.latex.depends import through as _through
from rigidsym.latex.lets import kind_of
from rigidsym.latex.shapes import LatexError

__all__: list[str] = []

_DOT = re.compile(r"\\(dot|ddot)\{(.*)\}$")


def _words(shape) -> str:
    if not shape or tuple(shape) == (1, 1):
        return "a scalar"
    return f"a {shape[0]}-vector" if shape[1] == 1 else f"a {shape[0]}×{shape[1]} matrix"


def _kinds_for(shape) -> str:
    """The --let kinds of a shape, for a hint."""
    return {(3, 1): "vector, unit vector", (3, 3): "rotation, matrix, so(3)",
            (6, 1): "twist, wrench, 6-vector", (4, 4): "transform, se(3), 4x4 matrix",
            (1, 1): "scalar, angle"}.get(tuple(shape), f"{shape[0]}x{shape[1]} matrix")


def _same_shape(a, b) -> bool:
    """Two shapes alike, a scalar written (), None or (1, 1)."""
    def norm(x):
        x = tuple(x or ())
        return () if x == (1, 1) else x
    return norm(a) == norm(b)


def conventional_shapes(printed, free: list[str], glyphs: dict) -> None:
    """A relation whose sides differ in shape, with a free glyph in it: bad input."""
    from rigidsym.checking.deciding.explicit import UnknownShape, shape_of

    for rel in printed:
        try:
            sl, sr = shape_of(rel.lhs), shape_of(rel.rhs)
        except UnknownShape:
            continue
        if sl == sr:
            continue
        names = _names(rel.lhs) | _names(rel.rhs)
        # a free glyph may have cancelled as the sides were built (A^{-1} A is 1 for a
        # scalar A): then every free glyph of the statement is a suspect
        keys = [k for k in free if glyphs[k].name in names] or \
            [k for k in free if not glyphs[k].shape]
        if not keys:
            continue  # every shape declared: a slip, decided (does-not-hold, shape reason)
        k = keys[0]
        name = glyphs[k].name
        other = sr if name in _names(rel.lhs) else sl if name in _names(rel.rhs) else \
            sr if _same_shape(sl, glyphs[k].shape) else sl
        raise BadInput(
            f"--latex: the two sides differ in shape ({_words(sl)} = {_words(sr)}), and "
            f"{', '.join(keys)} {'has' if len(keys) == 1 else 'have'} the shape of the "
            f"convention ({k} {_words(glyphs[k].shape)}), which no --let declares: say what "
            f"{k} is, e.g. --let '{k}: KIND' (for {_words(other)}: {_kinds_for(other)}) or "
            f"--let '{k} = LATEX' (its model)")


def time_derivatives(free: list[str], used: set[str], declared: dict,
                     no_derivative: bool = False) -> None:
    """``\\dot X`` free beside an ``X`` of the statement: bad input naming it; except, where
    the statement takes no derivative (``no_derivative``, :func:`takes_no_derivative`), the
    rate of an ``X`` declared a scalar or an angle: a value of its own at the instant, as
    free as ``X`` (Greenwood's ``\\omega^2 = \\dot\\psi^2 + ... + 2\\dot\\psi\\dot\\phi\\cos
    \\theta``)."""
    from rigidsym.latex.kinematics import rate_target

    for key in free:
        m = _DOT.match(key)
        # \dot{\omega}_{1}: the rate of \omega_{1}, as kinematics keys it (not \omega}_{1)
        accent, x = ("dot", rate_target(key)) if rate_target(key) else \
            (m.group(1), m.group(2)) if m else ("", "")
        # (a model X counts though only \dot X occurs: its rate, never a free symbol)
        if x and (x in used or getattr(declared.get(x), "latex", None)):
            if x in declared and declared[x].name.replace(" ", "").endswith("(t)"):
                # X(t): \dot X is its derivative (rigidsym.latex.transformer.book_notations)
                continue
            if no_derivative and accent == "dot" and x in declared \
                    and declared[x].kind.split(" in ")[0] in ("angle", "scalar"):
                continue
            how = "declared" if x in declared else "free"
            model = getattr(declared.get(x), "latex", None)
            if model and _TIME_IN.search(model):
                raise BadInput(_explicit_time(key, x, model))
            raise BadInput(
                f"--latex: {key} is the time derivative of {x} ({how}), but nothing says how "
                f"{x} depends on time, so {key} would be a free symbol unrelated to {x}: "
                f"declare {x} a function of time (--let '{x}(t): KIND'), give {key} a model "
                f"(--let '{key} = LATEX') or declare it as a symbol of its own "
                f"(--let '{key}: KIND')")


#: the plain letter t, the time, in a model's LaTeX (not in a macro, a word or a subscript)
_TIME_IN = re.compile(r"(?<![\\A-Za-z_{])t(?![A-Za-z])")
#: a glyph times t (Taylor's \Omega t): the rate of an angle of time
_RATE_T = re.compile(r"(\\[A-Za-z]+|[A-Za-z])(_\{[^{}]*\}|_[A-Za-z0-9])?\s*t(?![A-Za-z])")


def _explicit_time(key: str, x: str, model: str) -> str:
    """The refusal of ``\\dot X`` whose model is written in the time ``t`` itself (Taylor's
    ``\\omega_1 = \\omega_0\\cos\\Omega t``): a model's rate is read through the
    symbols declared functions of time, not through ``t``, so it says how to write one."""
    m = _RATE_T.search(model)
    angle = "\\vartheta" if "\\theta" in model else "\\theta"
    if m:
        rate = m.group(0)[:-1].strip()
        said = (f"--let '{angle}(t): angle' --let '\\dot{angle} = {rate}' --let '{x} = "
                f"{model[:m.start()] + angle + model[m.end():]}' ({rate} t is an angle of "
                f"time whose rate is {rate})")
    else:
        said = (f"--let '{angle}(t): angle' (or another function of time) with its rate "
                f"(--let '\\dot{angle} = ...'), and {x}'s model written in {angle}")
    return (f"--latex: {key} is the time derivative of {x}, whose model is written in the "
            f"time t itself; a model's rate is read through the symbols declared functions "
            f"of time, never through t, so {key} would be a free symbol unrelated to {x}: "
            f"write the model through a function of time, e.g. {said}; or give {key} its "
            f"model (--let '{key} = LATEX')")


def takes_no_derivative(latex: str, lets: list) -> bool:
    """No derivative anywhere in the statement: no ``--let`` of a function of time, no
    ``\\frac{d}{dt}``, ``\\partial`` or ``\\ddot``, and no ``\\dot`` over a glyph that a
    ``--let`` model names; then a rate is a value of its own at the instant."""
    from rigidsym.latex.declgraph import glyph_keys

    texts = [latex] + [x.latex for x in lets if x.latex]
    if any(x.name.replace(" ", "").endswith("(t)") for x in lets) or any(
            re.search(r"\\frac\s*\{\s*(?:d|\\partial)|\\partial|\\ddot", t) for t in texts):
        return False
    models = {x.key for x in lets if x.latex}
    try:
        keys = set().union(*(glyph_keys(t) for t in texts))
    except LatexError:
        return False
    dotted = (re.fullmatch(r"\\dot\{(.*)\}((?:_\{[^{}]*\})*)", k) for k in keys)
    return not any(m and m.group(1) + m.group(2) in models for m in dotted)


_TRIG_ABBREV = re.compile(r"([cs])_\{(\d+|\\[A-Za-z]+)\}$")
_HAT = re.compile(r"\\hat\{(.*)\}$")


def book_meanings(free: list[str]) -> None:
    """A free glyph whose meaning differs between the books (``c_1``, ``s_{12}``,
    ``\\hat\\omega``): bad input naming it and what settles it, never a free scalar."""
    trig = sorted(k for k in free if _TRIG_ABBREV.match(k))
    if trig:
        raise BadInput(
            f"--latex: {', '.join(trig)}: in Siciliano, Spong and Craig the cos and sin of "
            f"the joint angles the index names (c_{{12}} = cos(θ₁ + θ₂)), symbols of their "
            f"own elsewhere: say which, with --notation siciliano (spong, craig) or --let "
            f"'{trig[0]}: scalar' for each")
    for key in free:
        m = _HAT.match(key)
        if m:
            raise BadInput(
                f"--latex: {key} is a unit vector in Lynch-Park and Corke, the skew matrix of "
                f"{m.group(1)} in Murray-Li-Sastry: say which, with --let '{key}: unit "
                f"vector' (or another KIND), --notation lynch-park or --notation "
                f"murray-li-sastry")


_SUBSCRIPTED = re.compile(r"^(\\mathbf\{[A-Za-z]\}|\\boldsymbol\{\\?[A-Za-z]+\}|[A-Z])_")


def notation_bases(free: list[str], glyphs: dict, table) -> None:
    """A free glyph with a subscript whose letter the notation ``table`` declares a matrix
    (Spong's ``R`` a rotation, so ``R_{x}`` or ``R_{0,1}``): bad input naming it, never a
    free scalar by Angeles' convention, which that book does not follow (an undeclared
    ``R_x(\\alpha) R_z(\\beta)`` read as scalars would commute)."""
    if table is None:
        return
    for key in free:
        m = _SUBSCRIPTED.match(key)
        g = glyphs.get(key)
        if not m or g is None or g.shape:
            continue
        base = table.let_for(m.group(1))
        if base is None or not base.kind:
            continue
        shape = kind_of(base.kind, base.text)[0]
        if len(shape) == 2 and shape[1] > 1:
            raise BadInput(
                f"--latex: {key}: --notation {table.name} declares {m.group(1)} "
                f"'{base.kind}' but not {key}, which would be a free scalar: say what it "
                f"is, with --let '{key}: {base.kind}' (or another KIND) or a model "
                f"(--let '{key} = ...')")


def applications(applied: dict, models: dict, glyphs: dict) -> None:
    """``R(\\theta)``: one argument per symbol, one its model depends on."""
    from rigidsym.printing import notation

    for key, args in applied.items():
        distinct = list(dict.fromkeys(args))
        if len(distinct) > 1:
            said = " and ".join(f"{key}({notation.text(a)})" for a in distinct)
            raise BadInput(f"--latex: {said}: {key} applied to {len(distinct)} different "
                           f"arguments; the reading has one {key} only: write each value as "
                           f"a symbol of its own with its model (--let 'R_1 = ...')")
        model = models.get(glyphs[key].name) if key in glyphs else None
        arg = distinct[0]
        if model is None:
            raise BadInput(f"--latex: {key}({notation.text(arg)}): {key} has no model, so how "
                           f"it depends on {notation.text(arg)} is unknown (read as {key} "
                           f"itself it would be a guess): give its model, e.g. --let "
                           f"'{key} = LATEX' in {notation.text(arg)}")
        # X(X ...): a model applied to an expression in itself never depends on it (a
        # model does not refer to itself), however the argument's own model reads
        if glyphs[key].name in _names(arg) or not (
                _names(arg) <= _through(model, models)
                or _through(arg, models) - set(models) & _through(model, models)):
            raise BadInput(f"--latex: {key}({notation.text(arg)}): the model of {key} does not "
                           f"depend on {notation.text(arg)}; write the model in "
                           f"{notation.text(arg)} (--let '{key} = ...')")


_ENTRY = re.compile(r"^([A-Z]|\\mathbf\{[A-Z]\}|\\boldsymbol\{\\?[A-Za-z]+\})_\{(\d)(\d)\}$")


def matrix_entries(free: list[str], glyphs: dict) -> None:
    """A free glyph ``A_{23}`` beside a square matrix ``A`` of the statement (declared, or a
    model): the books' entry (row 2, column 3; Shuster's Gibbs vector from ``A_{23} -
    A_{32}``), which the reader does not take from the indices; read as a symbol of its own
    it made such an equation undecided or, decided, false: bad input naming it."""
    for key in free:
        m = _ENTRY.match(key)
        g, base = glyphs.get(key), glyphs.get(m.group(1)) if m else None
        if m is None or g is None or g.shape or base is None or len(base.shape) != 2 \
                or base.shape[0] != base.shape[1] \
                or not all(1 <= int(d) <= base.shape[0] for d in m.groups()[1:]):
            continue
        i, j = m.group(2), m.group(3)
        raise BadInput(
            f"--latex: {key} beside the {base.shape[0]}x{base.shape[1]} matrix {m.group(1)}: "
            f"an entry written by its indices (row {i}, column {j}) is not read from "
            f"{m.group(1)}, and as a symbol of its own it would change the equation; write "
            f"the entry as \\mathbf{{e}}_{i}^T {m.group(1)}\\mathbf{{e}}_{j} with --let "
            f"'\\mathbf{{e}}_{i} = ...' (the unit vectors), or, if {key} is a symbol of its "
            f"own, --let '{key}: scalar'")


_ZERO = re.compile(r"(\\?[A-Za-z]+)_\{0\}$")


def zero_entries(free: list[str], glyphs: dict) -> None:
    """A free ``\\theta_0`` beside a vector ``\\boldsymbol\\theta`` declared by a kind (of 2 or
    more entries): Shabana's and Wittenburg's entries counted from 0 (``\\theta_1`` then is the
    second), or a symbol of its own; the reader counts entries from 1, so either reading
    could change the equation (a wrong verdict): bad input naming both."""
    for key in free:
        m = _ZERO.match(key)
        letter = m.group(1) if m else ""
        bold = f"\\boldsymbol{{{letter}}}" if letter.startswith("\\") else f"\\mathbf{{{letter}}}"
        for vkey in (bold, letter) if m else ():
            g = glyphs.get(vkey)
            if g is not None and g.kind == "let" and len(g.shape) == 2 and g.shape[1] == 1 \
                    and g.shape[0] > 1:  # a vector of a kind (a model's x_0 is H&Z's)
                raise BadInput(
                    f"--latex: {key} beside the declared {g.shape[0]}-vector {vkey}: its "
                    f"entries counted from 0, or a symbol of its own; the reader counts "
                    f"entries from 1, so say which: --let '{key}: scalar' (a symbol of its "
                    f"own, and each of its namesakes) or {vkey}_{{1:1}} for the first entry")
