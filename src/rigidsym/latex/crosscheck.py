"""The rule of a verdict of ``check --latex`` needs the second semantics
(:mod:`rigidsym.numeval`) to agree. ``verified`` needs its residual to vanish at every
point (relative to the terms' size, :data:`VANISHES`); ``does-not-hold`` needs it to fail
somewhere (:data:`FAILS`). A disagreement is bad input naming the relation, its two sides
and the point, never a verdict; a construct the second semantics lacks is refused naming
it (:data:`REFUSE_UNCOVERED`).

This module is the boundary: it hands the second semantics lark's parse trees of the
statement and of every ``--let`` (NAME, parameters, model) and the KIND words, nothing of
the reader's meanings.
"""

from __future__ import annotations

import re

from rigidsym.core.errors import BadInput
from rigidsym.latex.lets import Let, declared_lets, read_lets
from rigidsym.latex.lexing import parsed_text, tree
from rigidsym.latex.shapes import LatexError
from rigidsym.numeval import Decl, NotCovered, residuals
from rigidsym.numeval.atpoint import residuals_at, subtree_values
from rigidsym.numeval.evaluator import text_of

__all__ = ["VANISHES", "FAILS", "AT_POINT", "POINTS", "REFUSE_UNCOVERED", "Disagreement",
           "cross_check", "given_point", "book_lets", "notation_lets", "decls_of"]

#: a residual at most this (relative to the terms) vanishes: the 50-digit evaluation's
#: rounding and the order-4 differences' truncation (h = 1e-10: 1e-40) are far below it
VANISHES = 1e-20
#: a residual at least this fails (a rounded point moves a true equation's residual by
#: about 1e-50, never by this)
FAILS = 1e-12
#: at the symbolic path's counterexample (its exact values rounded to 60 digits, evaluated
#: at 50), an equation that holds there has a relative residual of about 1e-48: one that
#: fails must exceed this bound, else the two semantics disagree
AT_POINT = 1e-30
#: the random points of each check (24 more, wider, before a does-not-hold is disagreed)
POINTS = 4
#: a construct the second semantics lacks: refused (True; it covers every verdict of the
#: corpus, the docs and the LaTeX tests) or the verdict given with a note (False)
REFUSE_UNCOVERED = True


class Disagreement(BadInput):
    """The two semantics disagree on a verdict: no verdict is given."""


def _side(t):
    """The right side of ``NAME = LATEX`` (or the left of ``NAME = 0``) in lark's tree."""
    chain = t.children[0]
    return [c for c in chain.children if not isinstance(c, str)]


def decls_of(lets: list[Let]) -> list[Decl]:
    """The ``--let``s as plain data: their NAME, parameters and model as parse trees."""
    out = []
    for x in lets:
        written = x.name
        timed = bool(re.search(r"\(\s*t\s*\)\s*$", written)) and not x.params
        if timed:  # X(t): KIND, a function of time
            written = re.sub(r"\(\s*t\s*\)\s*$", "", written)
        sides = _side(tree(f"{written} = {x.latex or 0}"))  # one parse: NAME and model
        name, body = sides[0], (sides[1] if x.latex else None)
        if name.data == "bracket" and name.children[0].data == "glyph":  # S&J's [C] = ...
            name = name.children[0]
        params = tuple(_side(tree(f"{p} = 0"))[0] for p in x.params)
        if x.latex and x.params == ("t",):  # X(t) = ...: a model in time
            params, timed = (), True
        out.append(Decl(name, params, x.kind, body, x.text, timed))
    return out


#: the glyph table's kinds of a plain shape (its rows carry no further constraint)
_ROW_KINDS = ("vector", "matrix", "scalar", "angle")


def book_lets(rows: dict, lent: list | None = None) -> tuple[list[Let], list[str]]:
    """The glyph table's rows a ``--book`` reading used, as plain declarations the second
    semantics reads as it reads a ``--let``: a row of a plain shape its KIND (``angle``,
    ``scalar``, ``vector``/``N-vector``, ``matrix``/``RxC matrix``), a notational atom its
    definition (``\\mathbf{E} = \\mathrm{CPM}(\\mathbf{e})``). ``(lets, lent)``: ``lent``
    the glyphs a module lends (their meaning is the module's, not handed over)."""
    out, lent = [], list(lent or [])
    for key, g in rows.items():
        if g.kind == "module":
            lent.append(key)
            continue
        if g.kind == "notation" and g.definition:
            text = f"{key} = {g.definition}"
        elif g.kind in _ROW_KINDS:
            shape = tuple(g.shape or ())
            text = f"{key}: " + (
                g.kind if not shape or g.kind == "angle" else
                ("vector" if shape[0] == 3 else f"{shape[0]}-vector") if shape[1:] in ((), (1,))
                else "matrix" if shape == (3, 3) else f"{shape[0]}x{shape[1]} matrix")
        else:
            continue  # a --let, a --notation line, a free glyph: read as without --book
        out += read_lets([text])
    return out, lent


def notation_lets(latex: str, lets: list[Let], name: str, used=()) -> list[Let]:
    """The lines of the notation ``name`` that declare a glyph the LaTeX or a model
    mentions, or that the reading ``used`` (glyph keys: ``T`` of ``\\mathrm{Ad}_T``, a
    subscript the parse tree holds as a token), and no ``--let`` declares (its functions
    too), as plain declarations: the second semantics reads their NAME, KIND and LaTeX as
    it reads a ``--let``."""
    from rigidsym.latex.declgraph import glyph_keys
    from rigidsym.latex.notations import notation

    table = notation(name)
    own = {x.key for x in lets}
    out: list[Let] = []
    todo = [latex] + [x.latex for x in lets if x.latex]
    seen: set[str] = set()
    first = set(used)
    while todo:
        keys, first = glyph_keys(todo.pop()) | first, set()
        for key in keys - seen:
            seen.add(key)
            if key in own:
                continue
            x = next((f for f in table.functions if f.key == key), None) or table.let_for(key)
            if x is not None and x.key not in own:
                own.add(x.key)
                out.append(x)
                if x.latex:
                    todo.append(x.latex)
    return out


def cross_check(latex: str, let, verdict: str, *, notation=None, book=None,
                modules=(), at=None, symbols=None, statement=None, rows=None) -> str:
    """The second semantics' word on ``verdict``: a note for the reading.

    Args:
        latex: the statement's LaTeX.
        let: its ``--let`` declarations as given (:func:`~rigidsym.latex.lets.read_lets`).
        verdict: the symbolic path's verdict.
        notation: a book's notation: its lines for the glyphs used, read as ``--let``s.
        book, modules: a glyph table's section or modules lending symbols: the glyph
            table's rows the reading used (``rows``) are handed over as ``--let``s
            (:func:`book_lets`); a module's symbol is the reader's meaning, so a check that
            uses one is not cross-checked (said).
        at: the symbolic path's counterexample as plain data (:func:`given_point`), or
            ``None``: a does-not-hold must fail there too.
        symbols, statement: the reader's glyph key -> book symbol map and its statement
            (:class:`~rigidsym.latex.statement.Reading`): a ``verified`` the second
            semantics refutes is located at its point (the smallest subtree whose values
            differ); ``None``: not located.
        rows: the reading's glyph key -> :class:`~rigidsym.latex.table.Glyph` (where each
            glyph's meaning came from); needed with ``book`` or ``modules``.

    Returns:
        A note: what the second semantics found (or why it did not apply).

    Raises:
        Disagreement: the two semantics disagree (the relation, its sides, the point).
        BadInput: a construct the second semantics lacks, with :data:`REFUSE_UNCOVERED`.
    """
    if verdict not in ("verified", "does-not-hold"):
        return ""
    lent: list[str] = ["(no glyph rows given)"] if rows is None else []
    extra: list[Let] = []
    if book or modules:
        extra, lent = book_lets(rows or {}, lent)
    if lent:
        return (f"numeric cross-check: not applied ({', '.join(lent)}: a module's meaning, the "
                f"reader's)")
    try:
        lets = read_lets(let) + extra
        lets += declared_lets(latex, lets)
        if notation:
            lets += notation_lets(latex, lets, notation, used={
                k for k, g in (rows or {}).items() if g.kind != "free"})
        found = _at_some_points(tree(latex), decls_of(lets))
    except NotCovered as exc:
        if REFUSE_UNCOVERED:
            raise BadInput(f"--latex: the numeric cross-check does not evaluate {exc}, and a "
                           f"verdict of the symbolic path alone is not given") from None
        return (f"numeric cross-check: not covered ({exc}); the verdict rests on the exact "
                f"check")
    except (LatexError, BadInput):
        return "numeric cross-check: not covered (a declaration it cannot read)"
    except _EvaluationFailed as exc:  # at every point tried: fail closed
        raise BadInput(f"--latex: the numeric cross-check's evaluation fails at each of "
                       f"{RETRIES + 1} sets of random points ({exc}), and a verdict of the "
                       f"symbolic path alone is not given") from None
    worst = max(found, key=lambda r: r.relative)
    if verdict == "verified" and worst.relative > VANISHES:
        raise Disagreement(_words(worst, latex, "verified, but the numeric cross-check (mpmath,"
                                                 " 50 digits) finds the sides differ")
                           + _where_verified(worst, latex, lets, let, symbols, statement))
    if verdict == "does-not-hold" and worst.relative < FAILS:
        # a real that fails only beyond (-2, 2) (cos(θ/2) = √((1 + cos θ)/2) fails for
        # |θ| > π): more points, wider, before calling it a disagreement
        try:
            found = residuals(tree(latex), decls_of(lets), 24, seed=63, spread=4)
        except Exception:  # noqa: BLE001 -- a point it cannot evaluate: the first points'
            pass
    said = _at_counterexample(latex, lets, at, let, _point_of(at)) \
        if verdict == "does-not-hold" and at else ""
    for n in {r.reading for r in found}:  # each reading that type-checks fails somewhere
        mine = max((r for r in found if r.reading == n), key=lambda r: r.relative)
        if verdict == "does-not-hold" and mine.relative < FAILS:
            raise Disagreement(_words(mine, latex, "does-not-hold, but the numeric cross-check "
                                                    "(mpmath, 50 digits) finds the sides equal"
                                                    f" at {POINTS} random points"))
    return (f"numeric cross-check (mpmath, 50 digits, {POINTS} random points): "
            f"{'the sides agree' if verdict == 'verified' else 'the sides differ'} "
            f"(largest relative residual {float(worst.relative):.1e}){said}")


#: more sets of random points (other seeds) tried where the evaluation fails at one (mpmath
#: at a singular matrix): a failure at every set refuses the verdict
RETRIES = 3


class _EvaluationFailed(Exception):
    """The second semantics' evaluation failed at every set of points tried."""


def _at_some_points(parsed, decls: list):
    """:func:`~rigidsym.numeval.random_points.residuals` at :data:`POINTS` random points, the
    first set whose evaluation does not fail (mpmath's own failure at a point, a singular
    matrix: another seed, up to :data:`RETRIES` more).

    Raises:
        NotCovered: a construct the second semantics lacks.
        _EvaluationFailed: the evaluation failed at every set, naming the failure.
    """
    failed = None
    for k in range(RETRIES + 1):
        try:
            return residuals(parsed, decls, POINTS, seed=62 + 101 * k)
        except (NotCovered, LatexError, BadInput):
            raise
        except Exception as exc:  # noqa: BLE001 -- a failure at a point: try others
            failed = exc
    what = str(failed).strip() or "no message"
    raise _EvaluationFailed(f"{type(failed).__name__}: {what}")


def given_point(counterexample: dict | None, statement, symbols: dict | None = None,
                rows: dict | None = None
                ) -> list | None:
    """The symbolic path's counterexample as plain data for the second semantics:
    ``[(LaTeX of a glyph, value)]``, a value a decimal string (60 digits) or rows of them.

    Args:
        counterexample: the symbolic path's (``point``: atom name -> exact value).
        statement: the statement it was found for (its ``model``: book symbol -> value in
            the atoms).
        symbols: the reader's map, glyph key (the LaTeX the user wrote, normalised) -> book
            symbol's name (:attr:`~rigidsym.latex.statement.Reading.symbols`): each glyph
            whose symbol the point fixes (a model's value there, or an atom itself) is given
            by its own LaTeX. Without it (or for a model symbol it does not name), a glyph
            is named by the book printer's LaTeX of its symbol.
        rows: the reading's glyph key -> glyph: which glyphs are the body velocities the
            reader introduced (:func:`~rigidsym.latex.printed_point.body_velocities`), never
            a user's glyph of the same spelling.

    Returns:
        The point (a :class:`GivenPoint`, the atoms kept beside it), or ``None`` when there
        is no point.
    """
    import sympy as sp

    from rigidsym.printing import notation as nt

    if not counterexample or not counterexample.get("point"):
        return None
    found = GivenPoint()
    found.atoms = dict(counterexample["point"])
    pt = {k: sp.sympify(v) for k, v in counterexample["point"].items()}
    by_name = {s.name: s for s in statement.model}

    def plain(v):
        v = sp.N(v, 60)
        if v.free_symbols or not (v.is_real or v.is_Matrix):
            raise ValueError("not a real number")
        return [[str(sp.N(x, 60)) for x in v.row(i)] for i in range(v.rows)] \
            if v.is_Matrix else str(v)

    def value(name):
        s = by_name.get(name)
        if s is None:
            return plain(pt[name]) if name in pt else None
        v = sp.sympify(statement.model[s])
        atoms = {a: pt[a.name] for a in getattr(v, "free_symbols", ()) if a.name in pt}
        try:
            return plain(v.subs(atoms))
        except (ValueError, TypeError, AttributeError, sp.SympifyError):
            return None  # a model the point does not fix: its glyph is drawn, and said so

    out, named = [], set()
    for key, name in (symbols or {}).items():
        v = value(name)
        if v is not None:
            out.append((key, v))
            named.add(name)
    out += _rates(out, symbols or {}, rows)
    held = set()
    for s in statement.model:
        v = sp.sympify(statement.model[s])
        held |= {a.name for a in getattr(v, "free_symbols", ()) if a.name in pt}
        if s.name not in named and value(s.name) is not None:
            out.append((nt.latex(s), value(s.name)))
    for name, v in pt.items():
        if name not in held and name not in named and name not in by_name:
            out.append((nt.latex(sp.Symbol(name)), str(sp.N(v, 60))))
    found.extend(out)
    return found


def _rates(given: list, symbols: dict, rows: dict | None) -> list:
    """``\\dot X`` of each function of time the point gives with its body velocity: the
    reader reads a rotation's (a transform's) rate as ``X [w]`` with ``w`` the glyph
    ``X_{w}`` it adds (:meth:`~rigidsym.latex.transformer.book_notations.BookNotations.
    velocity`; ``rows`` say which); the second semantics is handed the rate itself, a plain
    matrix."""
    import sympy as sp

    from rigidsym.algebra import rigid_motions
    from rigidsym.latex.printed_point import body_velocities

    values = dict(given)
    own = body_velocities(rows)
    out = []
    for key in symbols:
        w = values.get(own[key]) if key in own else None
        x = values.get(key)
        if w is None or not isinstance(x, list):
            continue
        X = sp.Matrix([[sp.Float(v, 60) for v in row] for row in x])
        W = rigid_motions.hat(sp.Matrix([[sp.Float(v, 60) for v in row] for row in w]))
        dot = sp.N(X * sp.Matrix(W), 60)
        out.append((f"\\dot{{{key}}}", [[str(dot[i, j]) for j in range(dot.cols)]
                                         for i in range(dot.rows)]))
    return out


def _bare(text: str) -> str:
    """A glyph's LaTeX without its font (the book's printer writes ``R`` as ``\\mathbf{R}``,
    ``\\hat\\omega`` as ``\\hat{\\boldsymbol{\\omega}}``), braces and spaces."""
    return re.sub(r"\\(mathbf|boldsymbol|bm|mathrm|mathit|mathsf|operatorname)|[{}\s\\]", "",
                  text)


def _written_glyphs(t, decls) -> dict:
    """The glyphs as the user wrote them (the statement's and the declarations' names), by
    :func:`_bare` text; two that read alike are left out (the printed name is then parsed
    as it stands)."""
    out: dict = {}
    trees = [d.name for d in decls if not d.timed] + [
        x for x in t.iter_subtrees() if x.data in ("glyph", "accented")]
    for x in trees:
        k = _bare(text_of(x))
        if k in out and out[k] is not None and text_of(out[k]) != text_of(x):
            out[k] = None
        elif k not in out:
            out[k] = x
    return out


def _written_tree(key: str, written: dict):
    """The glyph ``key`` (a reader's key or a printer's LaTeX) as the user wrote it (by
    :func:`_bare` text, as given or as parsed: ``{}^{A}`` is ``{}^A``), else as parsed."""
    parsed = _side(tree(f"{key} = 0"))[0]
    return written.get(_bare(key)) or written.get(_bare(text_of(parsed))) or parsed


def _at_counterexample(latex: str, lets, at, lets_text=(), pt=None) -> str:
    """A does-not-hold at the symbolic path's counterexample ``at``: each reading's
    residual must exceed :data:`AT_POINT` there (else :class:`Disagreement`, naming the
    side whose values differ where the point gives them). A point the second semantics
    cannot map (a glyph it does not give) falls back to the random points, said."""
    try:
        decls, t = decls_of(lets), tree(latex)
        written = _written_glyphs(t, decls)
        given = [(_written_tree(k, written), v) for k, v in at]
        found, drawn = residuals_at(t, decls, given)
    except Exception:  # noqa: BLE001 -- a point it cannot read or evaluate: fall back, said
        return ("; the symbolic path's counterexample could not be mapped onto it: checked at "
                "random points only")
    if drawn:
        return (f"; the symbolic path's counterexample does not give {', '.join(drawn[:4])}: "
                f"checked at random points only")
    for n in {r.reading for r in found}:
        mine = max((r for r in found if r.reading == n), key=lambda r: r.relative)
        if mine.relative <= AT_POINT:
            where = _where_they_differ(t, parsed_text(latex), decls, given, lets_text, pt)
            raise Disagreement(_words(mine, latex, "does-not-hold, but at its counterexample "
                                                    "the numeric cross-check (mpmath, 50 digits) "
                                                    "finds the sides equal") + where)
    worst = min(found, key=lambda r: r.relative)
    return (f"; it fails at the symbolic path's counterexample too (relative residual "
            f"{float(worst.relative):.1e})")


def _where_verified(worst, latex: str, lets, let, symbols, statement) -> str:
    """A ``verified`` refuted at the second semantics' point ``worst.point`` (glyph LaTeX ->
    value): the smallest subtree whose two values differ there (:func:`_where_they_differ`),
    the point handed to the symbolic side as its atoms through the reader's ``symbols`` (a
    symbol whose model is an atom or a matrix of atoms). "" when it cannot be located."""
    import mpmath as mp
    import sympy as sp

    if not symbols or statement is None:
        return ""
    by_bare: dict = {}
    for key, name in symbols.items():
        by_bare.setdefault(_bare(key), []).append(name)
    by_name = {s.name: s for s in statement.model}
    pt, given = {}, []
    try:
        for text, v in worst.point.items():
            names = by_bare.get(_bare(text), [])
            if len(names) != 1 or isinstance(v, tuple):
                continue  # two glyphs that read alike, or a motion: not handed over
            rows = [[mp.nstr(x, 60) for x in row] for row in v.tolist()] \
                if hasattr(v, "rows") else [[mp.nstr(v, 60)]]
            value = sp.Matrix(rows)  # of strings: the 60 digits kept
            plain = rows if hasattr(v, "rows") else rows[0][0]
            model = by_name.get(names[0])
            atoms = sp.Matrix(statement.model[model]) if model is not None and getattr(
                statement.model[model], "is_Matrix", False) else sp.Matrix(
                [[model if model is not None else sp.Symbol(names[0])]])
            if atoms.shape != value.shape or not all(a.is_Symbol for a in atoms):
                continue
            pt.update({a.name: x for a, x in zip(atoms, sum(rows, []), strict=True)})
            given.append((text, plain))
        decls, t = decls_of(lets), tree(latex)
        written = _written_glyphs(t, decls)
        given = [(_written_tree(k, written), v) for k, v in given]
    except Exception:  # noqa: BLE001 -- a point it cannot hand over: not located
        return ""
    return _where_they_differ(t, parsed_text(latex), decls, given, let, pt)


def _words(r, latex: str, what: str) -> str:
    """The disagreement in words: the relation as the reader wrote it (its two sides' own
    LaTeX, not the parser's tokens), its residual and the point, each value on one line
    (never the tokens joined by spaces, ``F 2 \\mathbf u``, nor a vector's value over
    several lines)."""
    text, pairs = parsed_text(latex), []
    for ch in (c for c in tree(latex).iter_subtrees_topdown() if c.data == "chain"):
        sides = [text[s.meta.start_pos:s.meta.end_pos].strip() if not s.meta.empty
                 else text_of(s) for s in ch.children if not isinstance(s, str)]
        pairs += [(sides[0], x) for x in sides[1:]]
    said = " = ".join(pairs[r.relation - 1]) if 0 < r.relation <= len(pairs) else latex
    point = "; ".join(f"{k} = {_one_line(v, r.point.get('t'))}"
                      for k, v in list(r.point.items())[:6])
    return (f"--latex: the symbolic path says {what} (relation {r.relation}: {said}; "
            f"relative residual {float(r.relative):.1e}{'; at ' + point if point else ''}): "
            f"the exact check and the numeric cross-check disagree, so no verdict; say the "
            f"equation another way or report it")


def _one_line(v, t=None) -> str:
    """A sampled value on one line: a scalar to 6 digits, a vector ``(a, b, c)``, a matrix
    ``[[a, b], [c, d]]``; a function of time's motion, its value at the point's ``t``."""
    import mpmath as mp

    from rigidsym.numeval import motion

    if isinstance(v, tuple):  # (kind, coefficients...): a declared X(t)
        return _one_line(motion.at(v, t)) + " at that t" if t is not None else \
            f"a {v[0]} motion"
    if not hasattr(v, "rows"):
        return mp.nstr(v, 6)
    rows = [[mp.nstr(v[i, j], 6) for j in range(v.cols)] for i in range(v.rows)]
    if v.cols == 1:
        return "(" + ", ".join(x[0] for x in rows) + ")"
    return "[" + ", ".join("[" + ", ".join(x) + "]" for x in rows) + "]"


def _point_of(at) -> dict:
    """The counterexample's atoms (name -> exact), carried beside the plain point."""
    return getattr(at, "atoms", {}) or {}


class GivenPoint(list):
    """:func:`given_point`'s plain point, with the symbolic path's atoms (name -> exact
    string) kept for locating a disagreement on the symbolic side."""

    atoms: dict = {}


def _where_they_differ(t, text: str, decls, given, let, pt: dict, limit: int = 40) -> str:
    """The smallest parse subtree (by its source text) whose two values differ at the
    point: this semantics' value and the symbolic reader's (the subtree read alone with the
    same ``--let``s, its model substituted and evaluated at the point's atoms). "" when no
    subtree of at most ``limit`` is found to differ (the point then is not a counterexample
    in either)."""
    import mpmath as mp
    import sympy as sp

    from rigidsym.checking.deciding.explicit import explicit
    from rigidsym.latex.statement import declare_latex

    spans = {text[x.meta.start_pos:x.meta.end_pos].strip(): x for x in t.iter_subtrees()
             if x.data not in ("start", "chain") and not x.meta.empty}
    spans = dict(sorted(spans.items(), key=lambda kv: len(kv[0]))[:limit])
    subs = list(spans.values())
    mine = subtree_values(decls, given, subs)
    for (src, _x), v in zip(spans.items(), mine, strict=True):
        if v is None:
            continue
        try:
            eq, _ = declare_latex(f"{src} = {src}", let)
            st = eq.build()
            e = sp.sympify(explicit(st.printed[0].lhs, st.model))
            atoms = {a: sp.sympify(pt[a.name]) for a in e.free_symbols if a.name in pt}
            if len(atoms) < len(e.free_symbols):
                continue
            e = sp.N(e.subs(atoms), 60)
            theirs = [e] if not e.is_Matrix else list(e)
            ours = [v] if not hasattr(v, "rows") else [v[i, j] for i in range(v.rows)
                                                         for j in range(v.cols)]
            if len(ours) != len(theirs):
                return f"; the subtree {src} differs in shape between the two"
            with mp.workdps(50):
                gap = max(abs(mp.mpf(str(a)) - b) for a, b in zip(theirs, ours, strict=True))
                size = max([mp.mpf(1)] + [abs(b) for b in ours])
        except Exception:  # noqa: BLE001 -- a fragment the reader does not read alone
            continue
        if gap / size > AT_POINT:
            return (f"; the smallest subtree whose two values differ there: {src} "
                    f"(relative gap {float(gap / size):.1e})")
    return ""
