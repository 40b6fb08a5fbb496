"""The notations of the field's books in a reader's LaTeX: transformer
rules of ``grammar.lark`` for constructs the chapter does not print, each read onto a word
of :mod:`rigidsym.declare` (never re-implemented here): :class:`BookNotationRules`, a mixin of the
LaTeX transformer :class:`rigidsym.latex.transformer.chapter.LatexTransformer`.

==========================================================  ====================================
LaTeX                                                       reading
==========================================================  ====================================
``X^\\top``, ``X^\\mathsf{T}``, ``X^{T}``, ``X^\\intercal``   the transpose
``x^\\wedge``, ``X^\\vee`` (MLS, Barfoot, Solà)                ``hat``, ``vee``; ``a \\wedge b`` is
                                                            refused (no exterior product)
``\\xi^\\curlywedge`` (Barfoot)                               ``ad`` of a 6-vector
``{}^B X_A^{*}``, ``{}^B X_A^{-T}`` (Featherstone)            the inverse transpose of a
                                                            ``spatial transform``; ``A^{-T}``
                                                            of another square matrix:
                                                            ``(A^{-1})^T``
``\\phi^*(\\mathbf{l})`` of another 6x6 matrix (Jain)         contested: Jain's transpose or
                                                            the dual (``contested``, "star");
                                                            ``\\mathcal{V}^*`` of a 6-vector
                                                            its transpose
``v \\times m``, ``v \\times^* f``, ``v\\times`` (RBDA 2.9)    crm, crf of a 6-vector; of a
                                                            3-vector before a matrix: CPM
``{}^A_B R``, ``{}^A\\mathbf{R}_B`` (Craig, Corke)             frame indices, part of the name
``\\left\\| x \\right\\|``, ``\\lVert x \\rVert``                  the norm of a vector expression
``\\left| x \\right|``                                         abs of a scalar, norm of a vector
``\\operatorname{diag}(a, b, c)``                             the diagonal (block) matrix
``\\cot``, ``\\sec``, ``\\csc``                                 cos/sin, 1/cos, 1/sin
``, R \\in SO(3)``, ``\\quad \\forall \\theta``                  a declaration (checked against
                                                            the ``--let`` kinds; noted)
==========================================================  ====================================
"""

from __future__ import annotations

import re

import lark
import sympy as sp

from rigidsym.algebra import rigid_motions
from rigidsym.algebra.operators import Cpm, Cross
from rigidsym.algebra.rigid_motions import LieOp
from rigidsym.latex import quaternions, tangent
from rigidsym.latex.kinematics import dot_key, explicit_rate
from rigidsym.latex.shapes import (
    LatexError,
    as_block,
    as_scalar,
    fit_blocks,
    matrix_shape,
    name_from_key,
    shape_words,
)
from rigidsym.latex.table import Glyph
from rigidsym.latex.transformer import products
from rigidsym.latex.transformer.meanings import STAR_POINT, alternatives

__all__: list[str] = []

#: how a --let NAME(t): KIND marks its glyph a function of time (read by d/dt and \\dot)
TIMED = ", a function of time t"
_TRANSPOSE = {"T", "\\top", "\\intercal", "\\mathsf{T}", "\\mathrm{T}"}
SETS = {"SO(3)": ((3, 3), "rotation"), "SE(3)": ((4, 4), "transform"),
        "so(3)": ((3, 3), "so(3)"), "se(3)": ((4, 4), "se(3)")}


def shape_words_of(shape) -> str:
    """A glyph's shape in words (``()``: a scalar)."""
    if not shape:
        return "a scalar"
    return f"a {shape[0]}-vector" if shape[1] == 1 else f"a {shape[0]}x{shape[1]} matrix"


def sup_word(sup: str) -> str:
    """A superscript in one spelling: ``T`` (every transpose), ``-T``, ``wedge``, ``vee``,
    ``curlywedge``, ``*``, or the integer as written."""
    s = "".join(sup.split())
    if s in _TRANSPOSE:
        return "T"
    if s.startswith("-") and s[1:] in _TRANSPOSE:
        return "-T"
    if s in ("*", "\\ast"):
        return "*"
    if s in ("\\wedge", "\\vee", "\\curlywedge", "\\times"):
        return s[1:]
    return s


def index_key(token: str) -> str:
    """The canonical spelling of a left index (``{}^A_B`` -> ``{}^{A}_{B}``); a calligraphic
    frame is its plain letter (``{}^{\\mathcal{A}}`` -> ``{}^{A}``)."""
    token = re.sub(r"\\mathcal\s*\{\s*([A-Za-z])\s*\}", r"\1", token)
    parts = dict(re.findall(r"([\^_])\s*(\{[^{}]*\}|[A-Za-z0-9])", token))
    out = "{}"
    for mark in ("^", "_"):
        if mark in parts:
            out += mark + "{" + parts[mark].strip("{}").strip() + "}"
    return out


def free_symbols_of(v) -> set:
    """The symbols and matrix symbols of a model's value."""
    if not isinstance(v, sp.Basic):
        return set()
    return set(v.atoms(sp.MatrixSymbol)) | set(v.atoms(sp.Symbol))


class BookNotationRules:
    """Transformer rules of the books' constructs (a mixin of ``LatexTransformer``,
    which provides ``_val``, ``_note``, ``glyphs``, ``overrides``, ``readings`` and ``made``)."""

    # ---- superscripts
    def book_power(self, x, sup: str):
        """``x^sup`` for the superscripts of the books; ``None`` for a power the chapter's
        rule reads (an integer, ``T``)."""
        if sup == "wedge":
            if matrix_shape(x) not in ((3, 1), (6, 1)):
                raise LatexError(f"^\\wedge of {shape_words(x)}: expected a 3-vector (its so(3) "
                                 f"matrix) or a 6-vector (its se(3) matrix)", "shapes")
            self._note("x^\\wedge: the hat, so(3) of a 3-vector, se(3) of a 6-vector "
                       "(MLS (2.4), Barfoot (7.7))")
            if matrix_shape(x) == (6, 1):
                self._note(tangent.said())
            return rigid_motions.hat(x, tangent.rigid_order())
        if sup == "times":  # Hughes' \epsilon^\times: the cross-product matrix
            if matrix_shape(x) != (3, 1):
                raise LatexError(f"^\\times of {shape_words(x)}: expected a 3-vector (its "
                                 f"cross-product matrix)", "shapes")
            self._note("x^\\times: the cross-product matrix [x]_\\times (Hughes)")
            return Cpm(x)
        if sup == "vee":
            if matrix_shape(x) not in ((3, 3), (4, 4)):
                raise LatexError(f"^\\vee of {shape_words(x)}: expected a 3x3 (so(3)) or 4x4 "
                                 f"(se(3)) matrix", "shapes")
            if matrix_shape(x) == (4, 4):
                self._note(tangent.said())
            return rigid_motions.vee(x, tangent.rigid_order())
        if sup == "curlywedge":
            if matrix_shape(x) != (6, 1):
                raise LatexError(f"^\\curlywedge of {shape_words(x)}: expected a 6-vector",
                                 "shapes")
            self._note(tangent.said())
            return rigid_motions.ad(x, tangent.rigid_order())
        if sup == "*" and matrix_shape(x) == (4, 1):  # a quaternion's conjugate
            self._note("q^*: the conjugate of a quaternion (its vector part negated); "
                       + quaternions.said())
            return sp.ImmutableMatrix(quaternions.conjugate(sp.Matrix(x)))
        if sup == "-T" and not self._spatial(x):
            return self._inverse_transpose(x)
        if sup == "*" and not self._spatial(x):
            return self._star(x)
        if sup in ("*", "-T"):
            spelt = "^{*}" if sup == "*" else "^{-T}"
            self._note(f"X{spelt}: the dual (inverse transpose) of a spatial transform "
                       f"(Featherstone (2.25))")
            return PluckerDual(x)
        return None

    def _star(self, x):
        """``X^*`` of anything but a quaternion or a declared spatial transform: of a 6x6
        matrix a contested construct (:mod:`rigidsym.latex.contested`, "star"): Jain's
        transpose (the adjoint of the rigid-body transformation operator, ``\\phi^*``) or
        Featherstone's dual ``(X^{-1})^T``, one choice point for every star of the
        statement unless a ``--let 'star: ...'`` settles it; of a 6-vector its transpose
        (Jain's ``\\mathcal{V}^*``, the only reading: the dual is of transforms). Anything
        else is refused naming what is expected."""
        s = matrix_shape(x)
        if s == (6, 1):
            self._note("v^*: the transpose of a 6-vector (Jain's adjoint, V^* f a power)")
            return x.T
        if s != (6, 6):
            raise LatexError(f"^{{*}} of {shape_words_of(s)}: expected a 4-vector (a quaternion's "
                             f"conjugate), a 6-vector (its transpose, Jain's V^*) or a 6x6 "
                             f"matrix (Jain's transpose or Featherstone's dual); write ^T for "
                             f"a transpose, or declare the starred name with a --let "
                             f"(--let 'X^{{*}}: matrix')", "shapes")
        # --let 'star: transpose' or 'star: dual'
        reading, how = self.contested_reading("star", STAR_POINT, alternatives(STAR_POINT))
        if reading == "dual":
            self._note(f"X^*: read as the dual (X^{{-1}})^T, Featherstone (2.25) ({how}: or "
                       f"the transpose, Jain's)")
            return self._inverse_transpose(x)
        self._note(f"X^*: read as the transpose X^T, Jain's φ^* ({how}: or the dual "
                   f"(X^{{-1}})^T, Featherstone's)")
        return x.T

    def _inverse_transpose(self, x):
        """``X^{-T}`` of a square matrix other than a spatial transform: ``(X^{-1})^T``, the
        inverse of the transpose (the same matrix: TeX's and every book's reading); of a
        scalar or a non-square matrix refused, never a power of a scalar."""
        s = matrix_shape(x)
        if s is None or s[0] != s[1] or s == (1, 1):
            raise LatexError(f"^{{-T}} of {shape_words(x)}: expected a square matrix (its inverse "
                             f"transpose, (X^{{-1}})^T)", "shapes")
        self._note("X^{-T}: the inverse transpose (X^{-1})^T")
        return (x.inv() if isinstance(x, sp.MatrixBase) else x.inverse()).T

    def _spatial(self, x) -> bool:
        if not isinstance(x, sp.MatrixSymbol) or matrix_shape(x) != (6, 6):
            return False
        g = next((g for g in self.glyphs.values() if g.name == x.name), None)
        return g is not None and "spatial transform" in (g.meaning or "")

    # ---- Featherstone's spatial cross products
    def cross(self, items):
        a, b = (self._val(i) for i in items)
        sa, sb = matrix_shape(a), matrix_shape(b)
        if sa == (3, 1) and sb == (3, 1):
            from rigidsym.algebra.operators import Cross

            return Cross(a, b)
        if sa in ((3, 1), (6, 1)) and sb is not None and sb[0] == sa[0]:
            return self._cross_matrix(a, dual=False) * b
        raise LatexError(f"\\times between {shape_words(a)} and {shape_words(b)}: expected two "
                         f"3-vectors (the cross product), two 6-vectors (Featherstone's "
                         f"spatial cross product) or a vector before a matrix", "shapes")

    def dot_cross(self, items):
        """``x \\cdot y \\times z`` (Goldstein's, Kane's triple product), by the shapes
        (rigidsym.latex.transformer.products, as the two below)."""
        return products.mixed(self, items, "dot")

    def cross_dot(self, items):
        return products.mixed(self, items, "cross")

    def dot_chain(self, items):
        return products.dot_chain(self, items)

    def cross_dual(self, items):
        a, b = (self._val(i) for i in _content(items))
        if matrix_shape(a) != (6, 1) or matrix_shape(b) is None or matrix_shape(b)[0] != 6:
            raise LatexError(f"\\times^* between {shape_words(a)} and {shape_words(b)}: "
                             f"expected two 6-vectors (Featherstone's v \\times^* f)", "shapes")
        return self._cross_matrix(a, dual=True) * b

    def commutator(self, items):
        """``[X, Y]``: the commutator ``XY - YX`` of two square matrices of one size (Hall
        (2015) Def. 2.21's bracket of matrices); of two 3-vectors the bracket of so(3) in
        vector form, ``x \\times y`` (Arnold (1989) sec. 26's ``[a, b]``, the vector product;
        the vee of the commutator of the hats, so both books' brackets agree); of two
        6-vectors it is refused naming what to write (the bracket of se(3) depends on the
        tangent order)."""
        a, b = (self._val(i) for i in _content(items))
        sa, sb = matrix_shape(a), matrix_shape(b)
        if sa is not None and sa == sb and sa[0] == sa[1]:
            self._note("[X, Y]: the commutator XY - YX")
            return a * b - b * a
        if sa == (3, 1) and sb == (3, 1):
            from rigidsym.algebra.operators import Cross

            self._note("[x, y] of two 3-vectors: the bracket of so(3), x \\times y (Arnold's "
                       "vector product; the vee of the commutator [x^\\wedge, y^\\wedge])")
            return Cross(a, b)
        if sa == (6, 1) and sa == sb:
            raise LatexError("[x, y] of two 6-vectors: the Lie bracket is not read (it depends "
                             "on the tangent order); write [x^\\wedge, y^\\wedge] (the "
                             "commutator of their hats: x^\\wedge y^\\wedge - y^\\wedge "
                             "x^\\wedge)", "shapes")
        raise LatexError(f"[X, Y] between {shape_words(a)} and {shape_words(b)}: the "
                         f"commutator XY - YX needs two square matrices of one size", "shapes")

    def cross_op(self, items):
        a, tok = self._val(items[0]), str(items[1])
        r = self._cross_matrix(a, dual="*" in tok)
        if "*" not in tok:  # [A x\wedge]: a contested bracket (RigidMotionRules.hat_bracket)
            self.made[r] = ("cross_op", (a, "\\wedge" if "wedge" in tok else "\\times"))
        return r

    def _cross_matrix(self, a, dual: bool):
        s = matrix_shape(a)
        if s == (3, 1) and not dual:
            self._note("r\\times: the cross-product matrix CPM(r)")
            return Cpm(a)
        if s == (6, 1):
            self._note("v\\times, v\\times^*: Featherstone's spatial cross products crm(v), "
                       "crf(v) = -crm(v)^T (RBDA (2.31)-(2.33))")
            return -rigid_motions.ad(a).T if dual else rigid_motions.ad(a)
        op = "\\times^*" if dual else "\\times"
        raise LatexError(f"{op} as an operator of {shape_words(a)}: expected a 6-vector (or a "
                         f"3-vector for \\times)", "shapes")

    def quaternion_inverse(self, x):
        """``q^{-1}`` of a 4-vector: its conjugate over its squared norm."""
        self._note("q^{-1}: the inverse of a quaternion, its conjugate over its squared norm "
                   "q^*/(q^T q); " + quaternions.said())
        return sp.ImmutableMatrix(quaternions.inverse(sp.Matrix(x)))

    def qprod(self, items):
        """``p \\otimes q``, ``p \\odot q``: the quaternion product of two 4-vectors in the
        declared convention (:mod:`rigidsym.latex.quaternions`)."""
        a, op, b = items[0], str(items[1]).strip(), items[2]
        a, b = self._val(a), self._val(b)
        if matrix_shape(a) != (4, 1) or matrix_shape(b) != (4, 1):
            raise LatexError(f"{op} between {shape_words(a)}{self._named(a)} and "
                             f"{shape_words(b)}{self._named(b)}: the quaternion product "
                             f"needs two 4-vectors (--let 'q: 4-vector', 'q: unit 4-vector')",
                             "shapes")
        self._note(quaternions.said())
        return sp.ImmutableMatrix(quaternions.product(sp.Matrix(a), sp.Matrix(b)))

    def wedge(self, items):
        raise LatexError("a \\wedge b: the exterior product is not read; write a^\\wedge b "
                         "for the hat of a times b, or a \\times b", "unknown macro \\wedge")

    # ---- norms, bars, diag
    def norm(self, items):
        x = self._val(_content(items)[0])
        if matrix_shape(x) is None or matrix_shape(x)[1] != 1:
            raise LatexError(f"\\|...\\| of {shape_words(x)}: expected a vector", "shapes")
        return sp.sqrt(as_scalar(x.T * x))

    def abs_bars(self, items):
        x = as_scalar(self._val(_content(items)[0]))
        if matrix_shape(x) is None:
            return sp.Abs(x)
        if matrix_shape(x)[1] == 1:
            self._note("|x| of a vector: its magnitude (Craig's |P|)")
            return sp.sqrt(as_scalar(x.T * x))
        raise LatexError(f"|...| of {shape_words(x)}: write \\det(...) for a determinant",
                         "shapes")

    def diag(self, items):
        xs = [self._val(i) for i in _content(items)]
        rows = [[x if i == j else 0 for j in range(len(xs))] for i, x in enumerate(xs)]
        if all(matrix_shape(x) is None for x in xs):
            return sp.ImmutableMatrix(rows)
        return self.matrix(rows)

    # ---- matrices (the chapter's, and a reader's [R d; 0 1] whose 0 is a block)
    def matrix(self, items):
        rows = [r for r in items if isinstance(r, list)]
        if self.reader and len(rows) > 1 and len({len(r) for r in rows}) == 1 \
                and all(matrix_shape(c) is None for r in rows for c in r):
            # a reader's matrix of scalars is one matrix, printed as one (Craig's R_K(theta),
            # read as 9 blocks of 1 x 1, was printed block by block; the chapter's parses
            # stay as recorded, tests/test_latex_parses.py)
            return sp.ImmutableMatrix([[self._val(c) for c in r] for r in rows])
        unit = frozenset()
        if self.reader and any(matrix_shape(c) for r in rows for c in r):  # [R d; 0 1]: 0 a block
            # a row of scalar zeros alone is one high ([B & U; 0 & 0]), its zeros sized
            # by their columns
            unit = frozenset(i for i, r in enumerate(rows)
                             if all(matrix_shape(c) is None and c == 0 for c in r))
            rows = [[_zero_cell(r) if c == 0 else c for c in r] for r in rows]
        cells = fit_blocks([[as_block(c) for c in row] for row in rows], unit)
        try:
            return sp.BlockMatrix(cells) if any(len(r) > 1 for r in cells) or len(cells) > 1 \
                else cells[0][0]
        except ValueError as exc:
            raise LatexError(f"a matrix whose blocks do not fit: {exc}", "shapes") from exc

    def row(self, items):
        return [self._val(i) for i in items if not isinstance(i, lark.Token)]

    # ---- d/dt of the symbols declared functions of time (--let 'X(t): KIND')
    def timed(self, key: str) -> bool:
        g = self.overrides.get(key)
        return g is not None and (g.meaning or "").endswith(TIMED)

    def velocity(self, key: str, value):
        """``\\dot X`` of a symbol declared a function of time: a rotation's or a transform's
        ``X [X_w]`` (``X_w`` free, introduced by the reader: the body angular velocity, or
        the body twist), else a free symbol of X's shape (``\\dot\\theta``)."""
        g = self.overrides[key]
        self.glyphs[key] = g
        dkey = dot_key(key)
        declared = self.overrides.get(dkey)
        if declared is not None and declared.kind == "model":  # --let '\dot{X} = ...'
            if tuple(declared.shape) != tuple(g.shape):
                raise LatexError(f"{dkey}, the rate of {key}, is {shape_words_of(declared.shape)}"
                                 f" by its --let; {key} is {shape_words_of(g.shape)}", "shapes")
            self.glyphs[dkey] = declared
            self._note(f"{dkey}: the rate of {key}, its --let model")
            return sp.MatrixSymbol(declared.name, *declared.shape) if declared.shape else \
                sp.Symbol(declared.name, real=True)
        if g.shape in ((3, 3), (4, 4)) and g.meaning.startswith(("rotation", "homogeneous")):
            n = 3 if g.shape == (3, 3) else 6
            # a name and a key no declaration of the reader's uses: their own
            # \mathbf{Q}_{w} stays theirs (sharing one symbol verified a false relation)
            taken = set(self.overrides) | {o.name for o in self.overrides.values()}
            mark = next(m for m in ("w", *(f"w{k}" for k in range(2, 99)))
                        if f"{g.name}_{m}" not in taken and f"{key}_{{{m}}}" not in taken)
            w = sp.MatrixSymbol(f"{g.name}_{mark}", n, 1)
            self.glyphs[f"{key}_{{{mark}}}"] = Glyph(f"{key}_{{{mark}}}", "*", w.name, (n, 1),
                                                      "free", "body velocity", "")
            what = "angular velocity" if n == 3 else "twist"
            named = (f"; --let '\\boldsymbol\\omega: angular velocity of {key}' declares a "
                     f"symbol of yours" if n == 3 else "")
            self._note(f"{dkey} = {g.name} [{w.name}]: the time derivative of a "
                       f"{g.meaning.split(',')[0]} ({w.name}: the body {what} of {g.name}, "
                       f"introduced by the reader, free{named})")
            return value * rigid_motions.hat(w)
        if dkey not in self.glyphs:
            self._note(f"{dkey}: the time derivative of {key} (a function of time, free)")
        d = sp.Symbol(f"{g.name}dot", real=True) if not g.shape else \
            sp.MatrixSymbol(f"{g.name}dot", *g.shape)
        self.glyphs[dkey] = Glyph(dkey, "*", d.name, g.shape, "free",
                                  f"the time derivative of {key}", "")
        if g.meaning.startswith("unit") and g.shape and g.shape[1] == 1:
            # a unit vector's rate is tangent, (1 - X X^T) v with v free (a free
            # rate would make X^T \dot X = 0 does-not-hold)
            self._note(f"{dkey} = (1 - {g.name} {g.name}^T) {d.name}: tangent to the unit "
                       f"sphere ({d.name} free)")
            return (sp.Identity(g.shape[0]) - value * value.T) * d
        if g.meaning.startswith("symmetric"):  # a symmetric matrix's rate is symmetric
            self._note(f"{dkey} = ({d.name} + {d.name}^T)/2: symmetric ({d.name} free)")
            return (d + d.T) / 2
        return d

    def models_of(self, names: set[str]) -> dict:
        """The models read so far whose values mention a symbol named in ``names``,
        directly or through another model, by name: their values (``Y = Z``,
        ``Z = (\\theta)`` depends on ``\\theta`` as ``\\theta`` does)."""
        out: dict = {}
        grew = True
        while grew:
            grew = False
            for name, v in getattr(self, "model_rhs", {}).items():
                if name not in out and name not in names and any(
                        a.name in names or a.name in out for a in free_symbols_of(v)):
                    out[name] = v
                    grew = True
        return out

    def time_derivative(self, x):
        """d/dt of an expression: the product rule over its matrix operations, the chain
        rule for scalars, each timed symbol's :meth:`velocity`; a symbol not declared a
        function of time is constant."""
        timed = {g.name: k for k, g in self.overrides.items() if self.timed(k)}
        if not timed:
            raise LatexError("d/dt: no symbol is declared a function of time; declare one "
                             "with --let 'X(t): KIND' (\\dot{X} is then its derivative)",
                             "unknown macro d/dt")
        self._note("d/dt: the product and chain rules over the symbols declared functions "
                   "of time")
        self._moving = self.models_of(set(timed))  # models of functions of time
        timed = {**timed, **self._free_rates(timed)}
        try:
            return self._ddt(x, timed)
        except (LatexError, TypeError, ValueError, AttributeError):
            # an operator the product rule does not cover ([x]_\times, a power, a norm, a
            # fraction, a function): entry by entry along the rates
            self._note("d/dt: taken entry by entry, the chain rule along the rates of the "
                       "functions of time")
            return explicit_rate(x, timed, self._moving, self._rate_of)

    def _free_rates(self, timed: dict) -> dict:
        """The free rates ``\\dot X`` of the scalar and vector functions of time (no --let
        model of the rate): each a function of time too, by its symbol's name -> the key
        of ``\\dot X`` (so that d/dt(θ̇ sin θ) keeps θ̈)."""
        out = {}
        for key in timed.values():
            g = self.overrides[key]
            dkey = dot_key(key)
            rate = self.overrides.get(dkey)
            if (rate is not None and rate.kind == "model") or (
                    g.shape in ((3, 3), (4, 4))
                    and g.meaning.startswith(("rotation", "homogeneous"))):
                continue
            out[f"{g.name}dot"] = dkey
        return out

    def _rate_of(self, key: str, value):
        """d/dt of the symbol ``value`` keyed ``key``: :meth:`velocity` of a function of
        time; of a free rate ``\\dot X`` (a key of :meth:`_free_rates`), the free symbol
        ``\\ddot X`` of X's shape (:meth:`second_rate`)."""
        if key in self.overrides:
            return self.velocity(key, value)
        return self.second_rate(next(k for k in self.overrides if dot_key(k) == key))

    def second_rate(self, key: str):
        """``\\ddot X`` of a function of time ``X`` keyed ``key`` whose rate is free: a
        free symbol of X's shape (a 4-vector's ``\\ddot{\\mathbf{q}}`` is a 4-vector,
        where the book's convention alone would make it a 3-vector)."""
        g = self.overrides[key]
        ddkey = "\\ddot" + dot_key(key)[len("\\dot"):]
        if ddkey in self.overrides:
            return self._symbol(ddkey, None)
        if ddkey not in self.glyphs:
            self._note(f"{ddkey}: the second time derivative of {key} (free)")
        name = name_from_key(ddkey)
        self.glyphs[ddkey] = Glyph(ddkey, "*", name, g.shape, "free",
                                   f"the second time derivative of {key}", "")
        return sp.MatrixSymbol(name, *g.shape) if g.shape else sp.Symbol(name, real=True)

    def model_rate(self, key: str):
        """``\\dot X`` of a model ``X`` built on functions of time (``--let 'C = ...'`` in
        ``\\mathbf{q}(t)``): d/dt of its value; ``None`` for any other X."""
        g = self.overrides.get(key)
        if g is None or g.kind != "model" or dot_key(key) in self.overrides:
            return None
        timed = {h.name: k for k, h in self.overrides.items() if self.timed(k)}
        if not timed or g.name not in self.models_of(set(timed)):
            return None
        self.glyphs[key] = g
        self._note(f"\\dot{{{key}}}: the time derivative of the model {key}")
        sym = sp.MatrixSymbol(g.name, *g.shape) if g.shape else sp.Symbol(g.name, real=True)
        return self.time_derivative(sym)

    def _ddt(self, x, timed):
        """d/dt of ``x``; a model whose value mentions a function of time (``--let 'Y =
        \\theta'``, ``\\theta(t)``) by its value's d/dt."""
        s = matrix_shape(x)
        if isinstance(x, sp.MatrixSymbol):
            if x.name in self._moving:  # a model of a function of time: its value's d/dt
                return self._ddt(self._moving[x.name], timed)
            return self._rate_of(timed[x.name], x) if x.name in timed else sp.ZeroMatrix(*s)
        if s is None and sp.sympify(x).atoms(sp.Trace):
            # a·b and aᵀ M b are 1×1 traces: d/dt of each trace is the trace of the d/dt of
            # its argument (product rule inside), the scalar around them by the chain rule
            traces = sorted(sp.sympify(x).atoms(sp.Trace), key=sp.default_sort_key)
            stand = {t: sp.Dummy(f"tr{i}") for i, t in enumerate(traces)}
            y = sp.sympify(x).xreplace(stand)
            out = self._ddt(y, timed)
            for t, d in stand.items():
                dt = self._ddt(t.arg, timed)
                if not isinstance(dt, sp.ZeroMatrix) and dt != 0:
                    out += sp.diff(y, d) * sp.Trace(dt)
            return out.xreplace({d: t for t, d in stand.items()})
        if s is None:
            syms = [a for a in sp.sympify(x).free_symbols if a.name in timed]
            if any(isinstance(a, sp.MatrixSymbol) for a in sp.sympify(x).free_symbols
                   if a.name in timed) or sp.sympify(x).atoms(sp.MatrixExpr):
                raise LatexError("d/dt of a scalar made of matrices: write the product out",
                                 "shapes")
            moving = [a for a in sp.sympify(x).free_symbols if a.name in self._moving]
            return sum((sp.diff(x, a) * self._rate_of(timed[a.name], a) for a in syms),
                       sp.Integer(0)) + sum(  # the chain rule through a scalar model
                (sp.diff(x, a) * self._ddt(self._moving[a.name], timed) for a in moving),
                sp.Integer(0))
        if isinstance(x, sp.MatAdd):
            return sp.MatAdd(*[self._ddt(a, timed) for a in x.args])
        if isinstance(x, sp.MatMul):
            terms = []
            for i, a in enumerate(x.args):
                da = self._ddt(a, timed)
                if da != 0 and not isinstance(da, sp.ZeroMatrix):
                    terms.append(sp.MatMul(*x.args[:i], da, *x.args[i + 1:]))
            return sp.MatAdd(*terms) if terms else sp.ZeroMatrix(*s)
        if isinstance(x, sp.Transpose):
            return self._ddt(x.arg, timed).T
        if isinstance(x, sp.Inverse):
            return -x * self._ddt(x.arg, timed) * x
        if isinstance(x, sp.MatrixBase):
            return x.applyfunc(lambda e: self._ddt(e, timed))
        if isinstance(x, Cross):  # the product rule: ȧ × b + a × ḃ
            a, b = x.args
            da, db = self._ddt(a, timed), self._ddt(b, timed)
            terms = [t for t, d in ((Cross(da, b), da), (Cross(a, db), db))
                     if not isinstance(d, sp.ZeroMatrix)]
            return sp.MatAdd(*terms) if terms else sp.ZeroMatrix(*s)
        if isinstance(x, sp.ZeroMatrix | sp.Identity):
            return sp.ZeroMatrix(*s)
        raise LatexError(f"d/dt of {shape_words(x)} built by {type(x).__name__}: write it as "
                         f"products and sums of the symbols", "shapes")

    # ---- a trailing declaration
    def declared(self, token: str):
        """``R \\in SO(3)``, ``\\forall \\theta``: a note; a set whose shape contradicts the
        symbol's is an error."""
        token = re.sub(r"\\q?quad\b", " ", token)
        text = " ".join(token.split())
        self._note(f"declaration: {text}")
        m = re.search(r"\\in\s*(SO\(3\)|SE\(3\)|so\(3\)|se\(3\))", token)
        if not m:
            return
        shape, kind = SETS[m.group(1)]
        names = re.sub(r"\\forall\b|\\in\b.*$", "", token).strip(" ,")
        names = re.sub(r"\\(boldsymbol|bm)\s*\{([A-Za-z])\}", r"\\mathbf{\2}", names)
        for k, g in self.glyphs.items():
            if k == names and g.shape != shape:
                has = f"{g.shape[0]}x{g.shape[1]}" if g.shape else "a scalar"
                raise LatexError(f"{text}: {k} is {has}; a {kind} is {shape[0]}x{shape[1]} "
                                 f"(--let '{k}: {kind}')", "shapes")


class PluckerDual(LieOp):
    """``X^*`` of a spatial transform ``X = [E 0; B E]`` (E a rotation; Featherstone
    (2.25)): ``X^{-T} = [E, -E Bᵀ E; 0, E]``, the inverse by the blocks, exact for the kind
    and no 6x6 inversion for the engine; printed as the reader wrote it, ``X*``."""
    label, tex = "dual", r"\mathrm{dual}"

    @classmethod
    def shape_of(cls, shapes):
        if tuple(shapes) != ((6, 6),):
            raise ValueError(f"X^*: an operand of shape {shapes} is no spatial transform")
        return (6, 6)

    def value(self, X):
        E, B = sp.Matrix(X)[:3, :3], sp.Matrix(X)[3:, :3]
        inv = sp.zeros(6, 6)
        inv[:3, :3], inv[3:, 3:], inv[3:, :3] = E.T, E.T, -E.T * B * E.T
        return inv.T

    def _sympystr(self, printer):
        return f"{printer._print(self.args[0])}*"


def _content(items):
    return [i for i in items if not isinstance(i, lark.Token)]


def _zero_cell(row: list):
    """A reader's scalar ``0`` in a block matrix: a zero block its neighbours size, except in
    a row of zeros only (Eade's se(3) matrix ``[\\omega_\\times u; \\mathbf{0} 0]``), where it is
    the 1 x 1 zero that gives the row its height (the bold zero then a row of zeros)."""
    zeros_only = all(c == 0 or type(c) is sp.ZeroMatrix for c in row) and \
        any(type(c) is sp.ZeroMatrix for c in row)
    return sp.ImmutableMatrix([[0]]) if zeros_only else sp.ZeroMatrix(1, 1)
