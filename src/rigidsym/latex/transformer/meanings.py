"""Reading rules that choose between meanings in a reader's LaTeX: a
symbol before a parenthesised argument, a sized identity or zero (:class:`MeaningRules`, a
mixin of the LaTeX transformer :class:`rigidsym.latex.transformer.chapter.LatexTransformer`).
Each choice is written under ``read as:``; docs/check-latex.md lists every rule.

- ``R(\\theta)``, ``T(t)``, ``J(\\theta)``: a symbol that is not a scalar (declared by a
  ``--let``, a model or a module) before a parenthesised scalar is that symbol applied to
  it: the symbol itself, which depends on the argument as its model says. Any other
  ``x(...)`` is a product (``a(b + c)``, ``A(\\mathbf{x} + \\mathbf{y})``). A symbol applied
  to two different arguments is refused (:mod:`rigidsym.latex.statement`).
- ``[x]`` of a 3-vector (Lynch-Park's bracket): the cross-product matrix, printed ``[x]`` as
  written, never as the chapter's ``CPM(x)`` (:class:`BracketCpm`).
- ``I_3``, ``\\mathbf{I}_{3}``, ``\\mathbf{I}_{3\\times 3}``, ``\\mathbf{1}_3``: the identity of
  that size; ``I_n``, ``I``: the identity sized by its neighbours. ``0_{3\\times 3}``,
  ``0_{3}``: the zero matrix (vector) of that size. Any other subscript of ``I`` (the
  chapter's ``I_C``) is part of a name.
"""

from __future__ import annotations

import re

import sympy as sp

from rigidsym.algebra.operators import Cpm
from rigidsym.latex import contested
from rigidsym.latex.contested import readings_of
from rigidsym.latex.entries import BASE_READINGS, base_words, is_base_point
from rigidsym.latex.hats import CAPITAL_READINGS, HAT_READINGS
from rigidsym.latex.shapes import LatexError, SizedIdentity, SizedZero, as_scalar, matrix_shape
from rigidsym.latex.table import lookup
from rigidsym.latex.transformer.extent import extent_parts, is_extent_point

__all__: list[str] = []

#: the readings of each kind of choice point, the default first: a model
#: before a parenthesised non-scalar (``X(\\mathbf{y})``, keyed by ``X``), a bracket around a
#: 3-vector or 6-vector (``[\\mathbf{a}]``, keyed by ``[a]``): its hat or a grouping
ALTERNATIVES = {"apply": ("product", "apply"), "bracket": ("hat", "group"),
                "index": ("name", "entry"), "tilde": ("skew", "own"), "hat": HAT_READINGS,
                "base": BASE_READINGS, "double": ("cpm", "neg"), "shape": CAPITAL_READINGS,
                "cross": readings_of("bracket cross"), "star": readings_of("star"),
                "extent": readings_of("argument extent")}
#: the one choice point of every X^* of a 6x6 matrix in a statement (a book reads its stars
#: one way: Jain's transpose or Featherstone's dual; :mod:`rigidsym.latex.contested`, "star")
STAR_POINT = "X^*"


def is_cross_bracket(key: str) -> bool:
    """``[A x\\wedge]``, ``[A x\\times]``: a product before an ``x\\times`` inside a
    bracket (:mod:`rigidsym.latex.contested`, "bracket cross")."""
    return key.startswith("[") and key.endswith(("\\wedge]", "\\times]"))


def _kind(key: str) -> str:
    if key == "\\tilde":  # every tilde of a 3-vector (rigidsym.latex.transformer.tilde)
        return "tilde"
    if key == STAR_POINT:  # every X^* of a 6x6 matrix: Jain's transpose or the dual
        return "star"
    if is_extent_point(key):  # \cos\theta\phi: cos(θ) φ or cos(θ φ) (transformer.extent)
        return "extent"
    if key.endswith(" shape"):  # a free bold capital: 3x3 or a 3-vector (latex.hats)
        return "shape"
    if key.startswith("[["):  # Shuster's [[u]]: the cross-product matrix or its negative
        return "double"
    if is_cross_bracket(key):  # Groves' [C\omega\wedge]: the content's or C times
        return "cross"
    if is_base_point(key):  # a 4-vector's entries counted from 1 or 0 (latex.entries)
        return "base"
    if key.endswith(" hat"):  # an undeclared \hat{X} (rigidsym.latex.hats)
        return "hat"
    return "bracket" if key.startswith("[") else "index" if " of " in key else "apply"


def alternatives(key: str) -> tuple[str, str]:
    """The readings of the choice point ``key``, the default first."""
    return ALTERNATIVES[_kind(key)]


def said(key: str, choice: str) -> str:
    """One choice in words: ``R(...) applied``, ``[a] the hat``, ``a_{1} of \\mathbf{a}
    its entry``."""
    if _kind(key) == "bracket":
        return f"{key} {'a bracket that groups' if choice == 'group' else 'the hat'}"
    if _kind(key) == "cross":
        return f"{key} " + ("A [x]_× (x× binds to the factor before it)" if choice == "bind"
                            else "the cross-product matrix of its content")
    if _kind(key) == "extent":
        head, arg, run = extent_parts(key)
        gap = " " if arg[-1:].isalpha() and run[:1].isalpha() else ""
        spelt = f"{head}({arg}{gap}{run})" if choice == "product" else f"{head}({arg}){run}"
        return f"{head}{arg}{gap}{run} read as {spelt}"
    if _kind(key) == "star":
        return ("each X^* of a 6x6 matrix " + ("the dual (X^{-1})^T (Featherstone)"
                                              if choice == "dual" else
                                              "the transpose X^T (Jain)"))
    if _kind(key) == "tilde":
        return ("each \\tilde{x} of a 3-vector " + ("a vector of its own" if choice == "own"
                                                    else "its cross-product matrix [x]_\\times"))
    if _kind(key) == "shape":
        return f"{key[:-6]} {'a 3-vector' if choice == 'vector' else 'a 3×3 matrix'}"
    if _kind(key) == "double":
        return f"{key} {'-' if choice == 'neg' else ''}[{key[2:-2]}]_×"
    if _kind(key) == "base":
        return base_words(key, choice)
    if _kind(key) == "hat":
        hat = key[:-4]
        return (f"{hat} the skew matrix of {hat[5:-1]}" if choice == "skew" else
                f"{hat} a unit vector of its own")
    if _kind(key) == "index":
        name, vec = key.split(" of ", 1)
        k = name.rsplit("_{", 1)[-1].rstrip("}")
        return f"{name} {f'entry {k} of {vec}' if choice == 'entry' else 'a symbol of its own'}"
    return f"{key}(...) {'applied' if choice == 'apply' else 'a product'}"



class BracketCpm(Cpm):
    """A reader's ``[x]`` of a 3-vector: the cross-product matrix (the chapter's ``CPM(x)``,
    MR's ``[x]``), printed back as the reader wrote it."""

    def doit(self, **hints):
        return as_written(super().doit(**hints))

    def _sympystr(self, printer):
        return f"[{printer._print(self.args[0])}]"

    def _latex(self, printer):
        return rf"\left[{printer._print(self.args[0])}\right]"


def as_written(h):
    """The hat ``h`` of a reader's bracket, printed back as a bracket."""
    return BracketCpm(*h.args) if type(h) is Cpm else h


# f, f_1, g', h_{ij}: a function's letter; a plain capital (R_x, Q, T_{01}; not I, the
# identity) is the books' matrix function R_x(\alpha), which read as scalars would commute
_FUNCTION_LETTER = re.compile(r"(?:[fgh]|[A-HJ-Z])(?:_|'|$)")
_TIME = sp.Symbol("t", real=True)  # the plain letter t (rigidsym.latex.transformer.chapter)
_PRIMED = re.compile(r"(.+?)('+)$")  # f', f'': Lagrange's derivative of a function f
_SIZE = re.compile(r"(\d)(?:\\times\s*(\d))?")


class MeaningRules:
    """Transformer rules of a reader's choices (a mixin of ``LatexTransformer``, which
    provides ``mul``, ``power``, ``_val``, ``reader``, ``overrides``, ``section``, ``glyphs``,
    ``_note``)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.applied: dict[str, list] = {}
        self.functions: dict = {}  # key -> expand(args) -> (value, params): --let functions
        self.choices: dict[str, str] = {}  # key -> one of its alternatives
        self.choice_points: dict[str, tuple] = {}  # key -> its alternatives, the default first

    def contested_reading(self, construct: str, key: str, readings: tuple) -> tuple[str, str]:
        """The reading of one use of a contested construct (:mod:`rigidsym.latex.contested`)
        and how it was settled, for the ``read as:`` note.

        Args:
            construct: the construct's key in ``CONTESTED`` (``"star"``).
            key: this use's choice point (``self.choices``).
            readings: its readings, the first read where nothing settles it.

        Returns:
            ``(reading, how)``: the reading a ``--let`` declared (``how`` says so), else the
            choice point's, which is registered so that the statement is decided under each.
        """
        settled = contested.declared(construct)
        if settled is not None:
            return settled, f"declared by --let '{construct}: ...'"
        self.choice_points.setdefault(key, readings)
        return self.choices.get(key, readings[0]), "a choice"

    def apply_many(self, items):
        """``glyph ( a, b, ... )`` with an optional power: a ``--let`` function of several
        parameters, never a product."""
        f, sup = items[0], (items[-1] if isinstance(items[-1], str) else None)
        args = [as_scalar(self._val(a)) for a in (items[1:-1] if sup is not None else items[1:])]
        if f.key not in self.functions:
            raise LatexError(f"{f.key}({', '.join(['...'] * len(args))}): {f.key} is applied to "
                             f"{len(args)} arguments but no --let declares it a function: "
                             f"--let '{f.key}(a, b, ...) = LATEX'", "function")
        v = self._expand(f.key, args)
        return self.power([v, sup]) if sup is not None else v

    def apply_pre_many(self, items):
        r"""``X^S(a, b)``, the power written before the arguments (Markley & Crassidis'
        ``A^T(\mathbf{e}, \vartheta)``): the power of the ``--let`` function's value, as
        ``X(a, b)^S``."""
        if not hasattr(items[0], "key"):
            raise LatexError("a power before a list of arguments, (...)^S(a, b): only a --let "
                             "function's name takes arguments", "function")
        return self.apply_many([items[0], *items[2:], items[1]])

    def _expand(self, key, args):
        from rigidsym.printing import notation

        v, params = self.functions[key](args)
        said = ", ".join(f"{p} = {notation.text(a)}" for p, a in zip(params, args, strict=True))
        self._note(f"{key}({', '.join(notation.text(a) for a in args)}): the --let function "
                   f"{key}({', '.join(params)}) at {said}")
        return v

    def _derivative(self, key, n, arg):
        """``f'(x)``, ``f''(x)``: the n-th derivative of the ``--let`` function ``f`` of one
        scalar parameter, at ``arg`` (Lagrange's notation, as the books write it)."""
        from rigidsym.algebra import rigid_motions
        from rigidsym.printing import notation

        s, written = sp.Dummy("s", real=True), key + "'" * n
        try:
            v, params = self.functions[key]([s])
        except LatexError as exc:
            if "parameter" not in str(exc):
                raise
            raise LatexError(f"{written}(...): a prime is the derivative of a function of one "
                             f"parameter; {key} has more: write the derivative as its own "
                             f"--let function", "function") from None
        self.glyphs.pop(written, None)  # not a symbol of its own: f, the function, is used
        if key in self.overrides:
            self.glyphs[key] = self.overrides[key]
        a = notation.text(arg)
        self._note(f"{written}({a}): derivative {n} of the --let function "
                   f"{key}({params[0]}), at {params[0]} = {a}")
        for _ in range(n):
            v = rigid_motions.diff(v, s)
        return v.subs(s, arg)

    def apply(self, items):
        """``glyph ( expr )`` with an optional power after the parenthesis."""
        f, arg, sup = items[0], items[1], (items[2] if len(items) > 2 else None)
        if getattr(f, "key", None) in self.functions:  # a --let function
            v = self._expand(f.key, [as_scalar(self._val(arg))])
            return self.power([v, sup]) if sup is not None else v
        primed = _PRIMED.match(getattr(f, "key", None) or "")
        if primed and primed.group(1) in self.functions:  # f'(x) of a --let f(x) = ...
            v = self._derivative(primed.group(1), len(primed.group(2)),
                                 as_scalar(self._val(arg)))
            return self.power([v, sup]) if sup is not None else v
        fv, x = self._val(f), as_scalar(self._val(arg))
        if self.reader and matrix_shape(fv) is not None and matrix_shape(x) is not None \
                and getattr(self.overrides.get(f.key), "kind", None) == "model":
            if isinstance(x, sp.MatrixSymbol) or not self._of_scalars(f):
                return self._choose(f, fv, x, arg, sup)  # R(\mathbf{q}): a label, maybe
            self._note(f"{f.key}(...): the product, {f.key}'s model holding no vector or "
                       f"matrix to apply the expression to")  # H&Z's K'(R X + t)
            return self.mul([f, self.power([arg, sup]) if sup is not None else arg])
        if self.reader and matrix_shape(x) is None and x is not _TIME \
                and self._modelless_vector(f, fv):
            from rigidsym.printing import notation

            a = notation.text(x)  # n (n . v), b (a . c): the books' scalar multiple
            self._note(f"{f.key}({a}): the product {f.key} {a}, not {f.key} applied to {a} "
                       f"({f.key} is a vector without a model, so no function of {a})")
            if sup is not None:
                arg = self.power([arg, sup])
            return self.mul([f, arg])
        if self.reader and matrix_shape(fv) is not None and matrix_shape(x) is None \
                and x is not _TIME:
            from rigidsym.printing import notation

            self.applied.setdefault(f.key, []).append(x)
            a = notation.text(x)
            self._note(f"{f.key}({a}): {f.key} applied to {a}, not a product ({f.key} is no "
                       f"scalar): {f.key} itself, depending on {a} as its model says")
            return self.power([fv, sup]) if sup is not None else fv
        if self.reader and self._function_letter(f):
            from rigidsym.printing import notation

            raise LatexError(
                f"{f.key}({notation.text(x)}): {f.key} is a function in the books (f, g, h, "
                f"R_x(α), Q(t)) but nothing defines it here; read as the product {f.key} "
                f"({notation.text(x)}) the verdict would rest on a guess: say which, with "
                f"--let '{f.key}(x) = ...' (a function) or --let '{f.key}: scalar' (the "
                f"product)", "apply")
        if sup is not None:  # a(b + c)^2: the power binds to the parenthesis
            arg = self.power([arg, sup])
        return self.mul([f, arg])

    def apply_pre(self, items):
        r"""``X^S(y)``, the power written before the argument (``R_z^T(\alpha)``,
        Siciliano's ``\boldsymbol{R}_z^T(\varphi)``, ``R^{-1}(\theta)``): where ``X(y)``
        is an application (a ``--let`` function, a symbol that is no scalar applied to a
        scalar, a function letter), the power of its value, as ``X(y)^S``; otherwise the
        product ``X^S y`` (``a^2(b + c)``, ``R^T(\mathbf{a} - \mathbf{b})``). Always the
        product would make ``R_z^T(0)\mathbf{a} = \mathbf{0}`` verify. A power after the
        parenthesis (``a^2(b + c)^2``) is the argument's in the product, the value's in the
        application (``R^T(\theta)^2``)."""
        f, sup, arg, *last = items
        fv, x = self._val(f), as_scalar(self._val(arg))
        key = getattr(f, "key", None)  # None: no glyph, ((a + b)^2 (c + d)), a product
        applied = key in self.functions or (
            key is not None and
            self.reader and matrix_shape(x) is None and x is not _TIME and (
                self._function_letter(f)
                or (matrix_shape(fv) is not None and not self._modelless_vector(f, fv)
                    and self._may_depend(f, x))))
        if applied:
            value = self.apply([f, arg, sup])
            return self.power([value, *last]) if last else value
        return self.mul([self.power([f, sup]), self.power([arg, *last]) if last else arg])

    def _may_depend(self, f, x) -> bool:
        r"""Whether ``f`` applied to ``x`` could be read: ``f`` has no model (refused as an
        application, :func:`rigidsym.latex.guards.applications`) or a model that depends on
        ``x``. A model that does not is a factor (MLS' ``\hat\omega^2(1 - \cos\theta)``)."""
        from rigidsym.latex.depends import names, through

        g = self.overrides.get(f.key) or self.glyphs.get(f.key)
        model = self.model_rhs.get(g.name) if g is not None else None
        return model is None or bool(names(x) & through(model, self.model_rhs))

    def _function_letter(self, f) -> bool:
        """``f`` is a free glyph (no ``--let``, model, module, book row or notation line)
        written with the letter f, g or h: ``f(\\mathbf{a} + \\mathbf{b})`` is a function
        there, which the product reading would make linear (it would verify ``f(a + b) = f(a) +
        f(b)``)."""
        key = getattr(f, "key", None)
        g = self.overrides.get(key) or self.glyphs.get(key)
        return g is not None and g.kind == "free" and _FUNCTION_LETTER.match(key) is not None

    def _modelless_vector(self, f, fv) -> bool:
        r"""``f`` is a vector (n x 1, n > 1) that no model, module or book defines: a free
        glyph or one a ``--let`` gives a kind only. Applied to a scalar it could only be
        refused (no model says how it depends on it; ``guards.applications``), so the one
        reading that types is the product (``\mathbf{n}(\mathbf{n}\cdot\mathbf{v})`` in
        Rodrigues' formula, ``\mathbf{b}(\mathbf{a}\cdot\mathbf{c})``), said under
        ``read as:``. A matrix keeps the refusal (``R(\theta)`` without a model: the
        books mean an application)."""
        shape = matrix_shape(fv)
        g = self.overrides.get(getattr(f, "key", None)) or self.glyphs.get(getattr(f, "key", None))
        return shape is not None and shape[1] == 1 and shape[0] > 1 and g is not None \
            and g.kind in ("let", "free") and g.name not in self.model_rhs

    def _of_scalars(self, f) -> bool:
        r"""``f``'s ``--let`` model is a matrix of scalars only (H&Z's calibration ``K'``):
        applied to a vector expression (no symbol, which could be a label: ``R(\mathbf{q})``
        written in ``q_0 ... q_3``) it would drop it, so no application is read."""
        rhs = self.model_rhs.get(getattr(self.overrides.get(f.key), "name", None))
        return isinstance(rhs, sp.MatrixBase) and not any(
            isinstance(s, sp.MatrixSymbol) for s in rhs.free_symbols)

    def _choose(self, f, fv, x, arg, sup):
        """``X(\\mathbf{y})``, ``X`` a model without parameters, ``\\mathbf{y}`` no scalar:
        a product ``X y`` or ``X`` applied to ``y``; no rule settles it.
        The reading follows ``self.choices[key]`` (``"product"`` unless told): the reader
        reads the statement once per choice and keeps those that type-check
        (:mod:`rigidsym.latex.statement`), the checker decides each."""
        from rigidsym.printing import notation

        how = self.choices.get(f.key, "product")
        self.choice_points.setdefault(f.key, alternatives(f.key))
        a = notation.text(x)
        if how == "apply":
            self.applied.setdefault(f.key, []).append(x)
            self._note(f"{f.key}({a}): read as {f.key} applied to {a} (a choice: or the "
                       f"product {f.key} {a})")
            return self.power([fv, sup]) if sup is not None else fv
        self._note(f"{f.key}({a}): read as the product {f.key} {a} (a choice: or {f.key} "
                   f"applied to {a})")
        if sup is not None:
            arg = self.power([arg, sup])
        return self.mul([f, arg])

    def double_bracket(self, h):
        r"""Shuster's ``[[\mathbf{u}]]`` (``h``, the hat the inner bracket read): the
        cross-product matrix ``[u]_\times`` or its negative, a choice point. His
        survey (1993) defines it with the sign of its passive attitude matrix, and the two
        readings of the books disagree on that sign (the corpus's note: the negative, his
        (57)), so neither is guessed: where both give one verdict (``[[u]]^2``, every even
        power) it is decided, else refused naming the choice (never as an
        "unknown bracket")."""
        from rigidsym.printing import notation

        u = h.args[0]
        key = f"[[{notation.text(u)}]]"
        self.choice_points.setdefault(key, alternatives(key))
        if self.choices.get(key) == "neg":
            self._note(f"{key}: read as -[{notation.text(u)}]_× (a choice: or "
                       f"[{notation.text(u)}]_×)")
            return sp.MatMul(-1, Cpm(u))
        self._note(f"{key}: read as [{notation.text(u)}]_× (a choice: or its negative)")
        return Cpm(u)

    def _sized(self, key, base, rest, accent):
        """An identity or zero the subscript sizes (module docstring), else ``None``."""
        kind, letter = base
        if not self.reader or accent or key in self.overrides:
            return None
        if self.section is not None and lookup(key, self.section) is not None:
            return None
        subs = [r[1] for r in rest if isinstance(r, tuple)]
        if letter.lstrip("\\") != "I" and kind != "one" or len(rest) > 1:
            return None
        if not subs or subs == ["n"]:  # sized by its neighbours
            if kind == "one":
                return None
            self._note(f"{key}: the identity (no --let declares {key}), sized by its "
                       f"neighbours")
            return sp.Identity(3)
        m = _SIZE.fullmatch(subs[0].replace(" ", ""))
        if m is None:
            return None  # I_C: a name
        n, k = int(m.group(1)), int(m.group(2) or m.group(1))
        if n != k:
            raise LatexError(f"{key}: an identity that is not square", "shapes")
        self._note(f"{key}: the {n}×{n} identity")
        return SizedIdentity(n)

    def sized_zero(self, key, rest):
        """``\\mathbf{0}_{3\\times 3}``, ``\\mathbf{0}_3``: the zero of the size written
        (its subscript read as ``0_{3\\times 3}``'s), else ``None`` (a loose zero that
        its neighbours size). A written size is never resized: ``\\omega =
        \\mathbf{0}_{3\\times 3} + \\omega`` is a shape error, not a verified identity."""
        subs = [r[1] for r in rest if isinstance(r, tuple)]
        if len(subs) != 1 or len(rest) != 1:
            return None
        m = _SIZE.fullmatch(subs[0].replace(" ", ""))
        if m is None:
            return None
        rows, cols = int(m.group(1)), int(m.group(2) or 1)
        self._note(f"{key}: the {rows}×{cols} zero")
        return SizedZero(rows, cols)

    def sized_number(self, items):
        """``0_{3\\times 3}``, ``0_3``: a zero of that size."""
        num, sub = str(items[0]), items[1][1].replace(" ", "")
        m = _SIZE.fullmatch(sub)
        if num != "0" or m is None:
            raise LatexError(f"{num}_{{{sub}}}: a subscript of a number is read only as the "
                             f"size of a zero (0_{{3\\times 3}}, 0_3)", "subscript")
        rows, cols = int(m.group(1)), int(m.group(2) or 1)
        self._note(f"0_{{{sub}}}: the {rows}×{cols} zero")
        return SizedZero(rows, cols)
