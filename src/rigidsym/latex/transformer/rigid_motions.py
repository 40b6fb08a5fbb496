"""The vocabulary of rigid motions in a reader's LaTeX (on the words of the chapter): the
spellings of Lynch & Park, *Modern Robotics* (MR) and Murray, Li & Sastry (MLS), each read
onto a word of :mod:`rigidsym.declare` (never re-implemented here): :class:`RigidMotionRules`, a
mixin of the LaTeX transformer :class:`rigidsym.latex.transformer.chapter.LatexTransformer`.

=================================================  ==========================================
LaTeX                                              word
=================================================  ==========================================
``e^{X}``, ``\\exp(X)`` (X 3x3 or 4x4)              ``expm`` (MR (3.51), (3.88))
``\\log R`` (R 3x3)                                  ``logm``, principal branch (MR (3.53))
``\\arccos x``, ``\\cos^{-1} x``                      ``acos``, principal branch ``[0, pi]``
``\\operatorname{atan2}(y, x)``                      ``atan2``, principal branch ``(-pi, pi]``
``\\sqrt{x}``                                        ``sqrt``
``[\\omega]`` (a 3-vector), ``[\\mathcal{V}]`` (6)    ``hat``: so(3), se(3) (MR (3.30), (3.85))
``\\mathrm{Ad}_{T}``, ``\\mathrm{ad}_{V}``            ``Ad``, ``ad`` (MR (3.83), (8.38))
``\\frac{dX}{d\\theta}``, ``\\frac{d}{d\\theta} X``    ``diff(X, theta)``
=================================================  ==========================================

The bracket is read as ``hat`` only in a reader's LaTeX (``parse_latex(..., reader=True)``),
and only when it holds one symbol or one product of shape 3 x 1 or 6 x 1; a bracket holding
a sum, a scalar or a matrix groups. ``e`` is the exponential only as a plain italic ``e``
directly followed by ``^``.
"""

from __future__ import annotations

import lark
import sympy as sp

from rigidsym.algebra import rigid_motions
from rigidsym.latex import tangent
from rigidsym.latex.kinematics import expand_models
from rigidsym.latex.lexing import bracket_key, named_map_key
from rigidsym.latex.shapes import LatexError, as_scalar, matrix_shape, shape_words
from rigidsym.latex.transformer.meanings import alternatives, as_written
from rigidsym.latex.transformer.tilde import own_tilde

__all__: list[str] = []


def _content(items):
    """The non-token items of a rule (the operands)."""
    return [i for i in items if not isinstance(i, lark.Token)]


class RigidMotionRules:
    """Transformer rules of the ``vocab`` productions of ``grammar.lark`` (a mixin of
    ``LatexTransformer``, which provides ``_resolve``, ``_val``, ``glyphs``, ``readings``,
    ``made``, ``func`` and ``power``)."""

    def _operand(self, x):
        if isinstance(x, tuple):  # a bare base (e^x, \mathrm{Ad}_T): a glyph of its own
            x = self._resolve(x, [], None)
        return self._val(x)

    def _named(self, x) -> str:
        """The glyphs an operand is made of, by their LaTeX (for a message)."""
        names = {s.name for s in x.atoms(sp.Symbol, sp.MatrixSymbol)} \
            if isinstance(x, sp.Basic) else set()
        keys = sorted(k for k, g in self.glyphs.items() if g.name in names)
        return f" ({', '.join(keys)})" if keys else ""

    def _note(self, text: str):
        if text not in self.readings:
            self.readings.append(text)

    # ---- the exponential and the logarithm
    def exp_e(self, items):
        return self._exp(self._operand(_content(items)[0]), "e^{...}")

    def _exp(self, x, how):
        s = matrix_shape(x)
        if s == (1, 1):
            x, s = as_scalar(x), None
        if s is None:
            from rigidsym.printing import notation

            raise LatexError(f"{how} of the scalar {notation.text(x)}: a scalar exponential, "
                             f"which the engine does not decide exactly (its vocabulary has "
                             f"the matrix exponential of a 3x3 (so(3)) or 4x4 (se(3)) "
                             f"exponent only); write the value it takes where you know it "
                             f"(Jacobi's \\det e^{{X}} = e^{{\\operatorname{{tr}} X}} of X: "
                             f"so(3), tr X = 0: \\det e^{{X}} = 1)", "shapes")
        if s not in ((3, 3), (4, 4)):
            raise LatexError(f"{how} of {shape_words(x)}{self._named(x)}: expected a 3x3 (so(3)) "
                             f"or 4x4 (se(3)) exponent, e.g. [\\hat\\omega]\\theta with "
                             f"--let '\\hat\\omega: unit vector'", "shapes")
        self._note(f"{how}: the matrix exponential expm (MR (3.51), (3.88))")
        try:
            return rigid_motions.expm(x)
        except ValueError as exc:
            raise LatexError(f"{how}: {exc}", "shapes") from None

    def matfunc(self, items):
        name, x = str(items[0]), self._val(items[1])
        if name == "\\exp":
            return self._exp(x, "\\exp")
        if matrix_shape(x) != (3, 3):
            raise LatexError(f"\\log of {shape_words(x)}{self._named(x)}: expected a 3x3 "
                             f"rotation (the log of se(3) and the scalar log are not words "
                             f"of the vocabulary)", "shapes")
        self._note("\\log: the principal logarithm logm, theta in [0, pi], singular at "
                   "theta = 0 and pi (MR (3.53)-(3.54))")
        return rigid_motions.logm(x)

    # ---- scalar functions
    def func_power(self, items):
        name, sup, x = str(items[0]), items[1], items[2]
        if sup == "-1":
            fn = name.lstrip("\\")
            if fn == "cos":
                return self.func(["\\arccos", x])
            if fn == "tan":
                return self.func(["\\arctan", x])
            raise LatexError(f"{name}^{{-1}}: the inverse {fn} is not in the vocabulary; "
                             f"write \\arccos or \\operatorname{{atan2}}(y, x)",
                             f"unknown macro {name}^{{-1}}")
        if sup == "T":
            raise LatexError(f"{name}^T: expected a power of the function", "shapes")
        return self.power([self.func([name, x]), sup])

    def sqrt(self, items):
        x = as_scalar(self._val(items[0]))
        if matrix_shape(x) is not None:
            raise LatexError(f"\\sqrt of {shape_words(x)}{self._named(x)}: expected a scalar",
                             "shapes")
        return sp.sqrt(x)

    def atan2(self, items):
        y, x = (as_scalar(self._val(i)) for i in _content(items))
        if matrix_shape(y) is not None or matrix_shape(x) is not None:
            raise LatexError("atan2(y, x): expected two scalars", "shapes")
        return sp.atan2(y, x)

    # ---- Ad, ad and the hat
    def adjoint(self, items):
        word, x = str(items[0]), self._operand(_content(items)[0])
        big = "Ad" in word
        if big and self._rotation(x):  # SO(3): Ad_R = R (R [x]_x R^T = [R x]_x)
            self._note(f"{word}_{{R}} of a 3x3 rotation: R itself (the adjoint of SO(3), "
                       f"R [x]_x R^T = [R x]_x; Sola et al. (2018) Table)")
            return x
        want = (4, 4) if big else (6, 1)
        if matrix_shape(x) != want:
            what = "a 4x4 transform" if big else "a twist (6-vector)"
            if big and matrix_shape(x) == (3, 3):  # SO(3)'s Ad needs the rotation declared
                what += (" or a rotation built of glyphs declared rotations (--let "
                         "'\\mathbf{R}: rotation': Ad of SO(3) is R itself)")
            raise LatexError(f"{word}_{{...}} of {shape_words(x)}{self._named(x)}: expected "
                             f"{what} (declare it, e.g. --let 'T: transform' or "
                             f"--let '\\mathcal{{V}}: twist')", "shapes")
        self._note(tangent.said())
        order = tangent.rigid_order()
        return rigid_motions.Ad(x, order) if big else rigid_motions.ad(x, order)

    def _rotation(self, x) -> bool:
        """Whether ``x`` is a rotation by its construction: a glyph declared a rotation (a
        ``--let`` kind, a notation), or a product, transpose, inverse or integer power of
        such (micro Lie's ``Ad_{R^{-1}}``, ``Ad_{R_1 R_2}``: SO(3) is a group)."""
        if isinstance(x, sp.Transpose | sp.Inverse):
            return self._rotation(x.arg)
        if isinstance(x, sp.MatPow):
            return x.exp.is_integer is True and self._rotation(x.base)
        if isinstance(x, sp.MatMul):
            return all(self._rotation(a) for a in x.args)  # a scalar factor: no rotation
        if not isinstance(x, sp.MatrixSymbol) or x.shape != (3, 3):
            return False
        return any(g.name == x.name and str(g.meaning).startswith("rotation")
                   for g in self.glyphs.values())

    def hat_bracket(self, x):
        """``[x]``: the hat of one symbol or one product of shape 3 x 1 or 6 x 1, else
        ``x`` (the bracket groups). The hat of a product is a choice point (item
        2): the other reading, a bracket that groups the product ``[R\\mathbf{a}]``, is
        read too (``self.choices``) and kept where it type-checks. A bracket around one
        symbol groups nothing: it is the hat, by the rule."""
        from rigidsym.printing import notation

        v = self._val(x)
        own_tilde(self, x)  # [\tilde{x}]: Schaub & Junkins' matrix, no hat of a vector
        if matrix_shape(v) == (3, 3):
            return self._cross_bracket(v)
        if matrix_shape(v) not in ((3, 1), (6, 1)):
            return v
        how = self.made.get(v)
        if not (isinstance(v, sp.MatrixSymbol) or (how and how[0] == "mul")):
            return v
        key = f"[{notation.text(v)}]"
        if not isinstance(v, sp.MatrixSymbol):  # [R a]: a choice; [a] groups nothing
            self.choice_points.setdefault(key, alternatives(key))
        if self.choices.get(key) == "group":
            self._note(f"{key}: read as a bracket that groups the vector (a choice: or its "
                       f"so(3) (se(3)) matrix hat)")
            return v
        self._note("[x] of a 3-vector (6-vector) read as its so(3) (se(3)) matrix hat(x) "
                   "(MR (3.30), (3.85)); a bracket holding a sum, a scalar or a matrix "
                   "groups; write ( ) to group a vector, [x]_\\times for the hat")
        if matrix_shape(v) == (6, 1):
            self._note(tangent.said())
        # printed [x] as written (transformer.meanings)
        return as_written(rigid_motions.hat(v, tangent.rigid_order()))

    def _cross_bracket(self, v):
        """``[A\\mathbf{x}\\wedge]`` (``\\times``): a contested construct
        (:mod:`rigidsym.latex.contested`, "bracket cross"): the cross-product matrix of the
        content ``[(A x)]_×`` (Groves) or ``A [x]_×`` (the operator binds to the factor
        before it, Featherstone), a choice point read both ways. Any other 3 x 3 content
        groups."""
        from rigidsym.algebra.operators import Cpm
        from rigidsym.printing import notation

        how = self.made.get(v)
        if not how or how[0] != "mul":
            return v
        left, op = how[1]
        made = self.made.get(op)
        if not made or made[0] != "cross_op":
            return v
        x, tok = made[1]
        content = left * x
        if matrix_shape(content) != (3, 1):
            return v
        key = f"[{notation.text(left)} {notation.text(x)}{tok}]"
        reading, how = self.contested_reading("bracket cross", key, alternatives(key))
        if reading == "bind":
            self._note(f"{key}: read as {notation.text(left)} [{notation.text(x)}]_× ({how}: "
                       f"or the cross-product matrix of the content)")
            return v
        self._note(f"{key}: read as the cross-product matrix of the content "
                   f"[{notation.text(content)}]_× ({how}: or {notation.text(left)} "
                   f"[{notation.text(x)}]_×)")
        return Cpm(content)

    # ---- derivatives
    def deriv_op(self, items):
        var, x = _content(items)
        return self._diff(self._val(x), var)

    def deriv_frac(self, items):
        x, var = _content(items)
        return self._diff(self._val(x), var)

    def _diff(self, x, var):
        v = self._val(var)
        if not isinstance(v, sp.Symbol):
            raise LatexError(f"a derivative with respect to {shape_words(v)}{self._named(v)}: "
                             f"expected a scalar variable (d\\theta)", "shapes")
        if v.name == "t":  # of the symbols declared functions of time, X(t) (book_notations)
            return self.time_derivative(self._val(x))
        self._note("d/dv: the vocabulary's derivative diff(X, v) (\\dot{X} stays the time "
                   "derivative)")
        x = as_scalar(x)
        # a model in v: its value, its matrices immutable (a mutable one inside a
        # product is unhashable: \dot\phi \partial C/\partial\phi leaked it)
        x = expand_models(x, self.models_of({v.name}))
        out = rigid_motions.diff(x, v)
        return sp.ImmutableMatrix(out) if isinstance(out, sp.MatrixBase) else out

    # ---- glyphs
    def calbase(self, items):
        return ("cal", str(items[0]))

    def fontbase(self, items):  # \mathsf{R}: a plain letter's conventions, its own name
        return ("font", f"{items[0]}{{{items[1]}}}")

    def bracketbase(self, items):  # Sola's [\mathbf{q}]_L: a name, in one spelling
        return ("font", bracket_key(str(items[0])))

    def namedbase(self, items):  # Forster's \mathrm{Exp}, Kok's \exp_q: a name, one spelling
        return ("font", named_map_key(str(items[0])))

    def bare(self, items):
        return ("plain", str(items[0]))

    def indexed_accent(self, items):
        """``{}^{G}\\tilde r_{C}``: a left index before an accented letter, one name,
        keyed ``{}^{G}\\tilde{r}_{C}``."""
        from rigidsym.latex.transformer.book_notations import index_key

        base = ("plain", str(items[2].children[0])) if isinstance(items[2], lark.Tree) \
            else items[2]
        accent, pre = str(items[1]).strip(), index_key(str(items[0]))
        if accent in ("\\dot", "\\ddot") and all(isinstance(r, tuple) for r in items[3:]):
            # Jazar's {}^G\dot{R}_B: the rate of {}^G R_B where that is a function of time
            # (or a model); else a name of its own
            under = self._resolve(base, list(items[3:]), None, pre=pre)
            if self.timed(under.key) or (accent == "\\dot" and
                                         self.model_rate(under.key) is not None):
                return self.accented([items[1], under])
            self._unuse(under.key)
        return self._resolve(base, list(items[3:]), str(items[1]), pre=pre)

    def accented_bare(self, items):
        inner = self._resolve(items[1], [], None)
        return self.accented([items[0], inner, *items[2:]])
