"""The glyph rows of a reader's LaTeX: :class:`GlyphReader` parses
the LaTeX and the models of ``--let`` with one set of glyph overrides: the declarations'
kinds, the models' shapes, the rows of ``--book``, a module's symbols, the lines of
``--notation`` (used by :mod:`rigidsym.latex.statement`)."""

from __future__ import annotations

import re

import sympy as sp
from sympy.matrices.expressions.matexpr import MatrixElement

from rigidsym.core.errors import BadInput
from rigidsym.latex.declgraph import glyph_keys
from rigidsym.latex.entries import DECLARED_PARAM
from rigidsym.latex.hats import CAPITAL_READINGS, capital_point, hat_reading, is_capital
from rigidsym.latex.kinematics import rate_target
from rigidsym.latex.lets import KIND_WORDS, Let, kind_of, read_lets
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.shapes import LatexError, matrix_shape, name_from_key
from rigidsym.latex.table import Glyph, glyph_table, lookup
from rigidsym.latex.transformer.book_notations import TIMED

__all__: list[str] = []

#: the shape errors a vector where a 3 x 3 stands would mend: a sum, a juxtaposition, a
#: cross-product matrix (not ``|\mathbf{A}|``, refused as a determinant written so)
_VECTOR_USES = ("shapes do not fit", "no product fits", "expected a 3-vector")
#: a bold font in a glyph key (a vector or matrix by the books' convention)
_BOLD = re.compile(r"\\(?:mathbf|boldsymbol|bm)\b")


def _in(section: str, book: str) -> bool:
    return book == "3" or section == book or section.startswith(book + ".")


def _book_rows(key: str, book: str) -> list[Glyph]:
    """The rows of a glyph within a section's sub-sections (when none is on its chain)."""
    rows = [g for g in glyph_table() if g.latex == key and g.section != "*"
            and _in(g.section, book)]
    distinct = {(g.name, g.shape, g.kind, g.definition): g for g in rows}
    return list(distinct.values())


#: an identity sized by its digit subscript (rule 6), ``I_{3}``, ``\\mathbf{I}_{3}``: its digit
_SIZED_I = re.compile(r"(?:I|\\mathbf\{I\})_\{(\d)\}")


class GlyphReader:
    """Parses the LaTeX and the models with one set of glyph overrides."""

    def __init__(self, lets: list[Let], book: str | None, lend: dict, notation=None,
                 mentioned: frozenset[str] = frozenset()):
        self.book, self.lend, self.notation = book, lend, notation
        self.mentioned = mentioned  # the glyph keys of the LaTeX and the models (for names)
        self.over: dict[str, Glyph] = {}
        self.declared: dict[str, Let] = {x.key: x for x in lets}
        # the plain glyphs beside a bold one of the same letter, named apart (:meth:`_name`)
        self.renamed = frozenset(k for k in mentioned if self._beside_bold(k))
        self.notes: list[str] = []
        self.used: set[str] = set()
        self.glyphs: dict[str, Glyph] = {}
        self.models: dict = {}  # the notation's models of the glyphs used
        self.model_rhs: dict = {}  # every model's value by its symbol's name (for d/dt)
        self.by_notation: set[str] = set()  # the glyphs the notation declares
        self.in_models: set[str] = set()  # the glyphs of the notation's models used
        self.functions: dict[str, Let] = {}  # the --let functions by key
        self.expanders: dict = {}  # key -> expand(args) for the parser
        self.choices: dict[str, str] = {}  # X(y): "product" or "apply"
        self.choice_points: dict[str, str] = {}  # the X(y) met, by key: the argument
        # a declared rate --let '\\dot{X} = ...' makes X a function of time
        rated = {rate_target(x.key) for x in lets if x.latex and not x.params}
        for x in lets + [x for x in (notation.lets if notation else ())
                         if x.kind and x.key not in self.declared]:
            if x.kind:
                self.declared.setdefault(x.key, x)
                if self.declared[x.key] is not x:
                    continue
                shape, _, words = kind_of(x.kind, x.text)
                if re.search(r"\(\s*t\s*\)\s*$", x.name) or x.key in rated:  # NAME(t)
                    words += TIMED
                self.over[x.key] = Glyph(x.key, "*", self._name(x.key), shape, "let", words)
                if x not in lets:
                    self.by_notation.add(x.key)

    def _name(self, key: str) -> str:
        """The symbol name of a declared glyph: its ``--book`` row's, else the plain name of
        its key. A plain glyph beside a bold one of the same letter that a ``--let``
        declares or the LaTeX or a model mentions (``\\theta = \\|\\boldsymbol\\theta\\|``
        beside ``\\boldsymbol\\theta(t)``, the rotation vector's angle) is named with a
        trailing ``_``, printed as the same glyph (:func:`rigidsym.printing.names.book_text`),
        so that the two stay two symbols wherever symbols are keyed by name (the models of
        functions of time, their rates)."""
        if self.book:
            g = lookup(key, self.book)
            if g is not None:
                return g.name
        return name_from_key(key) + ("_" if self._beside_bold(key) else "")

    def _beside_bold(self, key: str) -> bool:
        """Whether the plain glyph ``key`` has the plain name of a bold glyph that a
        ``--let`` declares or the LaTeX or a model mentions (``\\theta``,
        ``\\boldsymbol\\theta``: both ``theta``)."""
        name = name_from_key(key)
        return not _BOLD.search(key) and any(_BOLD.search(k) and name_from_key(k) == name
                                             for k in {*self.declared, *self.mentioned})

    def _extra(self, glyphs: dict) -> dict[str, Glyph]:
        """Rows the first reading could not know: a book row of a sub-section, a module's
        symbol of that name."""
        new = {}
        for key, g in glyphs.items():
            if key in self.over:
                continue
            x = self.notation.let_for(key) if self.notation and g.kind == "free" \
                and key not in self.declared else None
            if x is not None:  # a line of --notation: a kind, or a model in the book's notation
                new[key] = self._notation_glyph(x)
                continue
            if self.book and g.kind == "free":  # no row on the section's chain
                rows = _book_rows(key, self.book)
                if len(rows) > 1:
                    where = "; ".join(f"{r.name}, {r.meaning} ({r.section})" for r in rows)
                    raise BadInput(f"--book {self.book}: {key} is ambiguous there ({where}): "
                                   f"say which with --let '{key}: KIND' or a --book of one "
                                   f"sub-section")
                if rows:
                    new[key] = rows[0]
                    continue
            name = g.name
            if name in self.lend and g.kind == "free":
                sym, _ = self.lend[name]
                shape = tuple(sym.shape) if isinstance(sym, sp.MatrixSymbol) else ()
                new[key] = Glyph(key, "*", name, shape, "module", "lent by --module")
                continue
            if g.kind == "free" and key not in self.declared \
                    and self.choices.get(capital_point(key)) == "vector":
                self.choice_points[capital_point(key)] = CAPITAL_READINGS
                (v,) = read_lets([f"{key}: vector"])
                self.notes.append(f"{key}: read as a 3-vector (a bold capital no --let declares: "
                                  f"3×3 by the convention, which does not fit here; a choice)")
                new[key] = self._let_glyph(v, f"the reading '{v.text}'")
                continue
            x = hat_reading(key, self.choices, self.choice_points) \
                if g.kind == "free" and key not in self.declared else None
            if x is not None:  # an undeclared hat: a unit vector or a skew matrix (a choice)
                (v,) = read_lets([x[0]])
                self.notes.append(x[1])
                new[key] = self._let_glyph(v, f"the reading '{v.text}'", "a reading")
        return new

    def _notation_glyph(self, x: Let) -> Glyph:
        self.by_notation.add(x.key)
        return self._let_glyph(x, f"--notation {self.notation.name}: '{x.text}'")

    def _let_glyph(self, x: Let, what: str, meaning: str = "--notation") -> Glyph:
        """The glyph of a declaration the reader takes as a ``--let`` (a line of
        ``--notation``, a reading of an undeclared hat): its kind, or its model parsed."""
        self.declared[x.key] = x
        if x.kind:
            shape, _, words = kind_of(x.kind, x.text)
            return Glyph(x.key, "*", self._name(x.key), shape, "let", words)
        p = self.parse(f"{x.name} = {x.latex}", what)
        rhs = p.chains[0][1]
        self.in_models |= set(p.glyphs) - {x.key}
        g = Glyph(x.key, "*", self._name(x.key), matrix_shape(rhs) or (), "model", meaning)
        self.models[glyph_symbol(g)] = rhs
        self.model_rhs[g.name] = rhs
        return g

    def parse(self, text: str, what: str, over: dict | None = None, record: bool = True):
        """``text`` parsed with the overrides (``over`` on top of them: a function's
        parameters), the ``--let`` functions and the rows the first reading could not know;
        its glyphs recorded as used unless ``record`` is false."""
        for _ in range(4):
            try:
                p = parse_latex(text, self.book, {**self.over, **(over or {})}, reader=True,
                                functions=self.expanders, choices=self.choices,
                                models=self.model_rhs, renamed=self.renamed)
            except LatexError as exc:
                self.choice_points.update(getattr(exc, "choice_points", {}))
                # a glyph whose meaning a later row gives (a shape, or a --notation model that
                # makes R_3(\\psi) an application): read again with it
                extra = self._extra(exc.glyphs) if exc.construct in ("shapes", "apply") else {}
                extra = {k: g for k, g in extra.items() if k not in (over or {})}
                if extra:
                    self.over.update(extra)
                    continue
                if exc.construct == "shapes" and any(  # a free bold capital: a 3-vector too?
                        w in str(exc) for w in _VECTOR_USES):  # (not |A|: a det)
                    self.choice_points.update({capital_point(k): CAPITAL_READINGS
                                               for k, g in exc.glyphs.items() if g.kind == "free"
                                               and k not in (over or {}) and is_capital(k)
                                               and k not in self.declared})
                raise self._hint(exc, what) from None
            extra = {k: g for k, g in self._extra(p.glyphs).items() if k not in (over or {})}
            if not extra:
                self.choice_points.update(p.choice_points)
                if record:
                    self.used.update(p.glyphs)
                    self.glyphs.update(p.glyphs)
                return p
            self.over.update(extra)
        raise LatexError(f"{what}: the glyphs' shapes do not settle", "shapes")

    # ---- --let functions: S(\mathbf{a}) = [\mathbf{a}]_\times
    def add_function(self, x: Let) -> None:
        """Declare the ``--let`` function ``x`` (``NAME(params) = LATEX``): each application
        substitutes its arguments (:meth:`expand`)."""
        self.functions[x.key] = x
        self.expanders[x.key] = lambda args, x=x: self.expand(x, args)
        self.over.setdefault(x.key, Glyph(x.key, "*", self._name(x.key), (), "function",
                                          f"--let function of {', '.join(x.params)}"))

    def expand(self, x: Let, args: list):
        """``x`` applied to ``args``: its body read with each parameter of the argument's
        shape, the arguments substituted; ``(value, parameters)``."""
        from rigidsym.printing import notation

        call = f"{x.key}({', '.join(notation.text(a) for a in args)})"
        if len(args) != len(x.params):
            raise LatexError(f"{call}: {x.key} is a function of {len(x.params)} parameter"
                             f"{'s' if len(x.params) != 1 else ''} (--let '{x.text}'), "
                             f"applied to {len(args)}", "function")
        over, subs = {}, {}
        for pk, a in zip(x.param_keys, args, strict=True):
            shape = tuple(matrix_shape(a) or ())
            d = self.declared.get(pk)
            if d is not None and d.kind and tuple(kind_of(d.kind, d.text)[0]) != shape:
                raise LatexError(f"{call}: the parameter {pk} of {x.key} is declared "
                                 f"'{d.text}', the argument {notation.text(a)} is "
                                 f"{_shape_words(shape)}", "shapes")
            own = self.over.get(pk)  # a --let's vector of that name: its entries here too
            g = Glyph(pk, "*", f"{self._name(x.key)}⟨{self._name(pk)}⟩", shape, "param",
                      f"parameter of {x.key}" + (DECLARED_PARAM if own is not None and
                                                 own.kind in ("let", "model")
                                                 and tuple(own.shape) == shape else ""))
            over[pk] = g
            subs[glyph_symbol(g)] = a
        self._no_shadowed_model(x, args, call)
        rebound = self._rebind(x, over, call)
        p = self.parse(f"{x.name} = {x.latex}", f"--let '{x.text}'", over, record=False)
        for k, g in p.glyphs.items():
            if k not in over and k != x.key:
                self.used.add(k)
                self.glyphs[k] = g
                self.in_models.add(k)
        self.model_readings(x, p.readings)
        v = _replace_all(p.chains[0][1], rebound).xreplace(subs)
        for sym, rhs in rebound:
            self.notes.append(f"{call}: in the body of {x.key}, {sym.name.split('⟨')[1][:-1]}"
                              f" re-bound at the argument: {sym.name.split('⟨')[1][:-1]} = "
                              f"{notation.text(_replace_all(rhs, rebound).xreplace(subs))}")
        # an entry of a parameter (q_{4:4}) at an argument that is no symbol (-q, a bmatrix):
        # xreplace leaves (-q)[3, 0] unevaluated, which no later stage reads; index it now
        return v.replace(lambda e: isinstance(e, MatrixElement)
                         and not isinstance(e.parent, sp.MatrixSymbol),
                         lambda e: e.parent[e.i, e.j]), x.params

    def _mentions(self, key: str) -> set[str]:
        """The glyph keys the ``--let`` model or function ``key`` mentions, through the
        models it mentions (transitively), its own parameters left out."""
        from rigidsym.latex.declgraph import glyph_keys

        cache = self.__dict__.setdefault("_mention_cache", {})
        if key not in cache:
            cache[key] = set()  # a cycle is the declaration graph's to name
            x = self.declared[key]
            try:
                direct = glyph_keys(x.latex) - set(x.param_keys)
            except LatexError:
                direct = set()
            out = set(direct)
            for k in direct:
                if k != key and self._is_model(k):
                    out |= self._mentions(k)
            cache[key] = out
        return cache[key]

    def _is_model(self, key: str) -> bool:
        """``key`` is a ``--let NAME = LATEX`` model (no parameters, not a function)."""
        d = self.declared.get(key)
        return d is not None and bool(d.latex) and not d.params

    def _rebind(self, x: Let, over: dict, call: str) -> list:
        """Scope as the books mean it: every ``--let`` model the body of ``x`` mentions that
        is built (through any models) on a parameter of ``x`` is read again with the
        parameters bound (``n = |u|`` in ``F(u) = n^2 I_3``: at ``F(2u)``, ``n`` is
        ``|2u|``). Each such model is put in ``over`` as a glyph local to the application;
        returns ``[(local symbol, value)]`` in dependency order (a value mentions only
        parameters, globals and earlier local symbols)."""
        from rigidsym.latex.declgraph import model_order

        params = set(x.param_keys)
        used = {k for k in self._mentions(x.key) if self._is_model(k) and k not in params}
        built = [k for k in used if self._mentions(k) & params]
        if not built:
            return []
        lets = [self.declared[k] for k in built]
        order = model_order(lets, {k: self._mentions(k) for k in built})
        out = []
        for m in order:
            p = self.parse(f"{m.name} = {m.latex}", f"--let '{m.text}' (in {call})", over,
                           record=False)
            rhs = p.chains[0][1]
            g = Glyph(m.key, "*", f"{self._name(x.key)}⟨{self._name(m.key)}⟩",
                      matrix_shape(rhs) or (), "param", f"{m.key} at the argument of {x.key}")
            over[m.key] = g
            out.append((glyph_symbol(g), rhs))
        return out

    def _no_shadowed_model(self, x: Let, args: list, call: str) -> None:
        """A parameter that is also a ``--let`` model's NAME (``g = \\tan\\frac{\\theta}{2}
        \\mathbf{e}`` and ``R(\\mathbf{g}) = ...`` written in θ and e) applied at another
        argument: the body's θ, e can be the global ones or those of the argument (two
        readings): refused naming both declarations."""
        from rigidsym.printing import notation

        for pk, a in zip(x.param_keys, args, strict=True):
            if not self._is_model(pk):
                continue
            own = self.over.get(pk)
            if own is not None and a == glyph_symbol(own):
                continue  # at the model itself: one reading
            shared = self._mentions(pk) & self._mentions(x.key)
            if shared:
                m = self.declared[pk]
                raise BadInput(
                    f"{call}: the parameter {pk} of --let '{x.text}' is also the model "
                    f"--let '{m.text}', and the body uses {', '.join(sorted(shared))}, which "
                    f"{pk} is built on: at the argument {notation.text(a)} they can be the "
                    f"global ones or those of the argument (two readings): rename the "
                    f"parameter, or write the body in {pk} itself")

    def model_readings(self, x: Let, readings: list[str]) -> None:
        """The readings of a ``--let`` model, printed with the others (before, a
        bracket read inside a model was never said). Those of its own NAME are left out:
        the model is read as ``NAME = LATEX``, and the NAME there is no value read (Ginsberg's
        ``[I'] = [R][I][R]^T`` printed "I': the identity", the glyph before the
        declaration made it a name)."""
        for r in readings:
            if r.startswith(f"{x.key}: "):
                continue
            note = f"in --let '{x.text}': {r}"
            if note not in self.notes:
                self.notes.append(note)

    def _hint(self, exc: LatexError, what: str) -> LatexError:
        msg = str(exc)
        if what != "the LaTeX":
            msg = f"{what}: {msg}"
        # the user's free glyphs: never the reader's own (a rotation's body velocity)
        free = [k for k, g in exc.glyphs.items() if g.kind == "free" and k not in self.over
                and g.meaning != "body velocity"]
        if exc.construct == "shapes" and free:
            msg = (f"{msg.split(' (declare the shapes')[0]}; its meaning depends on the shape "
                   f"of {', '.join(free)}, which no --let declares: add e.g. --let "
                   f"'{free[0]}: KIND' (KIND one of {', '.join(KIND_WORDS)})")
        hats = [k for k in free if k.startswith("\\hat{")]
        if exc.construct == "shapes" and hats:  # the hat's two meanings first
            msg += (f"; {hats[0]} is a unit vector in Lynch-Park and Corke, the skew matrix of "
                    f"{hats[0][5:-1]} in Murray-Li-Sastry: say which, --notation "
                    f"murray-li-sastry or --let '{hats[0]} = [{hats[0][5:-1]}]_\\times'")
        sized = self._sized_identities() if exc.construct == "shapes" else ""
        if sized:  # what to write, in place of the general advice
            msg = msg.replace(" (declare the shapes, e.g. with the glyph table)", "") + sized
        fn = self.functions.get(getattr(exc, "function", None))
        if fn is not None:  # \det J_r(x): the function's own parameters in the advice
            msg = msg.replace(f"{fn.key}(...)", f"{fn.key}({', '.join(fn.params)})")
        if exc.construct == "internal":
            msg = msg.replace("; say it another way", self._lets_involved(exc.glyphs, what)
                              + "; say it another way")
        out = LatexError(msg, exc.construct)
        out.glyphs = exc.glyphs
        return out

    def _sized_identities(self) -> str:
        """The words naming the undeclared ``I_k`` of two digits or more read as identities
        of size k (rule 6) and the ``--let`` that makes them scalars of their own (Kasdin &
        Paley's principal moments in ``\\operatorname{diag}(I_1, I_2, I_3)``), or ``""``."""
        sized = sorted(k for k in self.mentioned if _SIZED_I.fullmatch(k)
                       and k not in self.declared and k not in self.over)
        if len({_SIZED_I.fullmatch(k).group(1) for k in sized}) < 2:
            return ""
        sizes = ", ".join(_SIZED_I.fullmatch(k).group(1) for k in sized)
        return (f"; {', '.join(sized)} are read as the identities of sizes {sizes} (no --let "
                f"declares them; I_3 is the 3×3 identity); for scalars of their own (the "
                f"principal moments of inertia) write --let '"
                + "; ".join(f"{k}: scalar" for k in sized) + "'")

    def _lets_involved(self, glyphs: dict, what: str) -> str:
        """The words naming the ``--let`` declarations behind the glyphs read up to an
        internal error, through the models they mention (``\\dot{\\mathbf{R}}`` of a model R
        written in θ: R's --let and θ's), or ``""``; the ``--let`` being read (``what``) is
        named already."""
        todo, seen = [k for k in glyphs if k in self.declared], set()
        while todo:
            key = todo.pop()
            if key in seen:
                continue
            seen.add(key)
            x = self.declared[key]
            try:
                todo += [k for k in glyph_keys(x.latex) if k in self.declared] if x.latex else []
            except LatexError:
                pass
        texts = [f"--let '{self.declared[k].text}'" for k in sorted(seen)
                 if f"--let '{self.declared[k].text}'" != what]
        return f" (the --let declarations involved: {', '.join(texts)})" if texts else ""


def _replace_all(v, rebound: list):
    """``v`` with every re-bound model's local symbol replaced by its value."""
    for sym, rhs in reversed(rebound):
        v = v.xreplace({sym: rhs})
    return v


def _shape_words(shape) -> str:
    if not shape:
        return "a scalar"
    return f"a {shape[0]}-vector" if shape[1] == 1 else f"a {shape[0]}×{shape[1]} matrix"


def glyph_symbol(g: Glyph):
    """The sympy symbol of glyph ``g``: a matrix symbol of its shape, or a real scalar symbol."""
    return sp.MatrixSymbol(g.name, *g.shape) if g.shape else sp.Symbol(g.name, real=True)
