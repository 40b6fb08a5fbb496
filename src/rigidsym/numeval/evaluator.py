"""The second semantics' tree walk: a relation's parse tree evaluated at random
points of the declared kinds, with mpmath at :data:`DIGITS` digits.

Scope: a glyph is looked up in the environment of its evaluation: a function's parameters
(bound to the arguments), then the ``--let`` models, each evaluated *in the environment
asking for it* (so, in a function's body, every model built on a parameter is re-bound to
the argument, and the others are the global ones), then the declared kinds and the free
symbols of the book's convention (bold lower-case a 3-vector, bold capital a 3 x 3 matrix,
anything else a scalar), each drawn once per point by :mod:`~rigidsym.numeval.sampler`.
Derivatives ``\\frac{d}{d\\theta}`` are central differences of order 4 at this precision.
Any construct not listed here raises :class:`NotCovered` naming it.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass

import lark
import mpmath as mp

from rigidsym.numeval import accents, conventions, entries, hats, motion, names, rates
from rigidsym.numeval import values as V
from rigidsym.numeval.names import glyph_key
from rigidsym.numeval.sampler import sample
from rigidsym.numeval.values import NotCovered

__all__ = ["DIGITS", "Decl", "Env", "Evaluator", "NotCovered", "Residual", "glyph_key", "text_of"]

#: working precision (decimal digits)
DIGITS = 50

#: the time t of the symbols declared functions of time
_TIME_TREE = lark.Tree("glyph", [lark.Tree("base", [lark.Token("LETTER", "t")])])
TIME = "glyph(base(t))"
_TRANSPOSE = {"T", "\\top", "\\intercal", "\\mathsf{T}", "\\mathrm{T}"}
_FUNCS = {"\\sin": mp.sin, "\\cos": mp.cos, "\\tan": mp.tan, "\\arctan": mp.atan,
          "\\arccos": mp.acos, "\\cot": mp.cot, "\\sec": mp.sec, "\\csc": mp.csc}
_INVERSES = {"\\sin": mp.asin, "\\cos": mp.acos, "\\tan": mp.atan}
_OPS = {"tr": V.trace, "Tr": V.trace, "trace": V.trace, "det": V.det, "vect": V.vect}
# an operator's token: \sin, \text{ vect }, \operatorname*{tr}, \textrm{det}, \mbox{Tr} ...
_OPERATOR_TOKEN = re.compile(r"\\[A-Za-z]+\*?\s*(?:\{\s*([A-Za-z0-9]+)\s*\})?")


def _operator_word(token: str) -> str:
    """The operator's word of a token (``\\text{ vect }`` -> ``vect``), else the token."""
    m = _OPERATOR_TOKEN.fullmatch(token.strip())
    return (m.group(1) or m.group(0).strip()[1:]) if m else token.strip()


@dataclass(frozen=True)
class Decl:
    """One ``--let`` as plain data: its NAME's parse tree (the glyph), its parameters' glyph
    trees, and a KIND (words) or a model's parse tree (the right side of ``NAME = LATEX``)."""

    name: object
    params: tuple = ()
    kind: str = ""
    body: object = None
    text: str = ""
    timed: bool = False


@dataclass
class Residual:
    """One relation at one point: the two sides, their difference's size relative to the
    terms' and the point (the sampled symbols by glyph)."""

    relation: int
    lhs: object
    rhs: object
    relative: object
    point: dict
    reading: int = 0
    unused: bool = False


def text_of(t) -> str:
    """A subtree's LaTeX tokens joined by spaces (a construct named in a message)."""
    if isinstance(t, lark.Token):
        return str(t)
    return " ".join(str(v) for v in t.scan_values(lambda v: isinstance(v, lark.Token)))


def _base_letter(t) -> tuple[str, bool, bool]:
    """``(letter, bold, plain)`` of a glyph (plain: no accent, subscript nor index)."""
    if t.data != "glyph":
        return "", False, False
    base = t.children[0]
    if not isinstance(base, lark.Tree) or base.data != "base":
        return "", False, False
    toks = [str(c) for c in base.children]
    bold = len(toks) == 2
    return toks[-1], bold, len(t.children) == 1


class Env:
    """An environment: bindings (a function's parameters), a parent, the declarations and
    the point's sampled values (shared by every environment of one point)."""

    def __init__(self, decls: dict, point: dict, rng: random.Random, binds=None,
                 parent: Env | None = None, depth: int = 0, free: bool | None = None):
        self.decls, self.point, self.rng = decls, point, rng
        self.free = point.setdefault(" free", True) if free is None else free
        point[" free"] = self.free
        self.binds, self.parent, self.depth = dict(binds or {}), parent, depth
        self.memo: dict = {}
        self.names = point.setdefault("", {})  # glyph key -> its LaTeX, for messages

    def lookup(self, key: str, tree):
        if key in self.binds:
            return self.binds[key]
        d = self.decls.get(key)
        if d is not None:
            self.point.setdefault(" used", set()).add(key)
        if d is not None and d.body is not None and not d.params:
            if key not in self.memo:
                if self.depth > 40:
                    raise NotCovered(f"the models around {text_of(tree)} (nested too deep)")
                busy = self.point.setdefault(" evaluating", set())  # the models being read
                busy.add(key)
                try:
                    self.memo[key] = Evaluator(self).value(d.body)
                finally:
                    busy.discard(key)
            return self.memo[key]
        if d is not None and d.params:
            raise NotCovered(f"the --let function {text_of(tree)} without its arguments")
        if d is not None and d.timed and d.kind:  # X(t): KIND, its motion at this t
            if key not in self.point:
                self.point[key] = motion.curve(d.kind, self.rng)
                self.names[key] = text_of(tree)
            return motion.at(self.point[key], V.scalar(self.lookup(TIME, _TIME_TREE)))
        if key not in self.point:
            self.point[key] = self._draw(key, tree, d)
            self.names[key] = text_of(tree)
        return self.point[key]

    def _draw(self, key: str, tree, d):
        if d is not None and d.kind:
            return sample(d.kind, self.rng)
        if key == TIME:  # the time of the functions of time, whatever the notation
            return sample("scalar", self.rng)
        letter, bold, plain = _base_letter(names.unlabelled(tree))  # sigma^S: as sigma
        if not self.free:
            raise NotCovered(f"the glyph {text_of(tree)}, which no declaration names (a "
                             f"notation's meaning)")
        if not letter or not plain and not names.decorated_name(tree):
            named = tree.children[0] if isinstance(tree, lark.Tree) and tree.children else None
            if isinstance(named, lark.Tree) and named.data == "namedbase":
                text = "".join(text_of(tree).split())
                word = text[text.find("{") + 1:-1]
                raise NotCovered(f"the operator {word!r} ({text}), which the vocabulary does "
                                 f"not have (declare it: --let '{text}(x) = ...')")
            raise NotCovered(f"the undeclared glyph {text_of(tree)}")
        if bold and letter.islower():
            return sample("vector", self.rng)
        if bold and letter.isupper():  # 3x3 by the convention; a 3-vector where it fails
            said = self.point.get(" choices", {})  # a choice only where the first failed
            if said.get(" capitals", True):
                self.point.setdefault(" met", {})[f"shape {text_of(tree)}"] = ("matrix", "vector")
            return sample(said.get(f"shape {text_of(tree)}", "matrix"), self.rng)
        return sample("scalar", self.rng)


class Evaluator:
    """Evaluates parse subtrees in one :class:`Env`."""

    def __init__(self, env: Env):
        self.env = env

    def value(self, t):
        if isinstance(t, lark.Token):
            raise NotCovered(f"the token {t}")
        rule = getattr(self, "r_" + t.data, None)
        if rule is None:
            raise NotCovered(f"the construct {text_of(t)!r} ({t.data})")
        return rule(t)

    def _kids(self, t):
        return [c for c in t.children if isinstance(c, lark.Tree)]

    # ---- sums and products
    def r_add(self, t):
        a, b = self._kids(t)
        return V.add(self.value(a), self.value(b))

    def r_sub(self, t):
        a, b = self._kids(t)
        return V.add(self.value(a), V.neg(self.value(b)))

    def r_neg(self, t):
        return V.neg(self.value(self._kids(t)[0]))

    def r_mul(self, t):
        a, b = self._kids(t)
        return V.mul(self.value(a), self.value(b))

    def r_div(self, t):
        a, b = self._kids(t)
        return self._divide(self.value(a), self.value(b), t)

    def r_frac(self, t):
        return self.r_div(t)

    def _divide(self, a, b, t):
        b = V.scalar(b)
        if V.is_matrix(b) or isinstance(b, V.Eye | V.Zero):
            raise NotCovered(f"a division by a matrix in {text_of(t)!r}")
        if b == 0:
            raise NotCovered(f"a division by 0 in {text_of(t)!r}")
        return V.mul(a, 1 / b)

    def r_cross(self, t):
        a, b = self._kids(t)
        a, b = self.value(a), self.value(b)
        if V.shape(V.scalar(a)) == (6, 1):  # Featherstone's spatial cross product (2.31)
            return V.mul(V.spatial_cross(a), b)
        if V.shape(V.scalar(a)) == (3, 1) and V.shape(b) == (3, 3):  # r\times E: (r×) E
            return V.mul(V.hat(a), b)
        return V.cross(a, b)

    def r_dot_cross(self, t):
        """``a \\cdot b \\times c``: the triple product a·(b×c) (a scalar a: a (b×c))."""
        a, b, c = (self.value(k) for k in self._kids(t))
        return V.dot(a, V.cross(b, c))

    def r_cross_dot(self, t):
        """``a \\times b \\cdot c``: (a×b)·c (a scalar c: (a×b) c)."""
        a, b, c = (self.value(k) for k in self._kids(t))
        return V.dot(V.cross(a, b), c)

    def r_dot_chain(self, t):
        """``a \\cdot s \\cdot b``: the scalars' product times the scalar product of the
        (at most two) vectors."""
        vals = [V.scalar(self.value(k)) for k in self._kids(t)]
        vecs = [v for v in vals if V.is_matrix(v)]
        if len(vecs) > 2 or any(v.cols != 1 for v in vecs):
            raise NotCovered(f"a chain of dots {text_of(t)!r}")
        out = mp.mpf(1)
        for v in vals:
            if not V.is_matrix(v):
                out = out * v
        if len(vecs) == 2:
            return out * V.dot(vecs[0], vecs[1])
        return V.mul(out, vecs[0]) if vecs else out

    def r_cross_dual(self, t):
        a, b = self._kids(t)
        return V.mul(V.spatial_cross(self.value(a), dual=True), self.value(b))

    def r_qprod(self, t):
        a, b = self._kids(t)
        return V.quaternion_product(self.value(a), self.value(b))

    def r_cross_op(self, t):
        a = self.value(self._kids(t)[0])
        dual = "*" in str(t.children[-1]) or "ast" in str(t.children[-1])
        if V.shape(V.scalar(a)) == (3, 1) and not dual:
            return V.hat(a)
        return V.spatial_cross(a, dual=dual)

    def r_dot(self, t):
        a, b = self._kids(t)
        return V.dot(self.value(a), self.value(b))

    # ---- groups
    def r_paren(self, t):
        return self.value(self._kids(t)[0])

    def r_sized(self, t):
        inner = self._kids(t)[0]
        if "[" in str(t.children[0]):
            return self._bracket(inner)
        return self.value(inner)

    def r_commutator(self, t):
        """``[X, Y]``: XY - YX of two square matrices of one size; of two 3-vectors the
        bracket of so(3), the cross product (Arnold's ``[a, b]``)."""
        a, b = (self.value(k) for k in self._kids(t))
        if V.shape(V.scalar(a)) == (3, 1) and V.shape(V.scalar(b)) == (3, 1):
            return V.cross(a, b)
        if not (V.is_matrix(a) and V.is_matrix(b)) or a.rows != a.cols \
                or (a.rows, a.cols) != (b.rows, b.cols):
            raise NotCovered(f"a commutator of no two square matrices in {text_of(t)!r}")
        return V.add(V.mul(a, b), V.neg(V.mul(b, a)))

    def r_bracket(self, t):
        return self._bracket(self._kids(t)[0])

    def _bracket(self, inner):
        """``[x]``: the hat of a 3- or 6-vector (the books' cross-product matrix); around
        more than one symbol (``[R\\mathbf{a}]``) a choice with a bracket that groups (the
        readings whose sides have one shape are kept)."""
        kids = self._kids(inner) if getattr(inner, "data", None) == "mul" else []
        if len(kids) == 2 and getattr(kids[1], "data", None) == "cross_op" and not any(
                c in str(kids[1].children[-1]) for c in ("*", "ast")):
            return self._bracket_cross(kids[0], kids[1], inner)
        v = V.scalar(self.value(inner))
        if V.is_matrix(v) and v.cols == 1 and v.rows in (3, 6):
            if inner.data in ("glyph", "accented", "accented_bare"):
                return V.hat(v)
            return V.hat(v) if self.choose(f"bracket {text_of(inner)}",
                                            ("hat", "group")) == "hat" else v
        return v

    def _bracket_cross(self, left, op, inner):
        """``[A\\mathbf{x}\\wedge]``: the hat of the content ``A x`` or ``A x^∧``
        (:data:`rigidsym.numeval.conventions.BRACKET_CROSS`), a choice point; a content that
        is no 3-vector leaves the product ``A x^∧``."""
        a = self.value(left)
        x = V.scalar(self.value(self._kids(op)[0]))
        content = V.scalar(V.mul(a, x)) if V.shape(x) == (3, 1) else None
        if content is None or V.shape(content) != (3, 1):
            return V.mul(a, self.value(op))
        key = conventions.choice_key("bracket cross", text_of(inner))
        how = conventions.settled("bracket cross") or self.choose(key, conventions.BRACKET_CROSS)
        if how == "content":
            return V.hat(content)
        return V.mul(a, V.hat(x))

    def choose(self, key: str, options: tuple[str, ...]) -> str:
        """The reading taken at the choice point ``key`` (its first option unless the
        enumeration of :func:`residuals` says otherwise); the point recorded as met."""
        self.env.point.setdefault(" met", {})[key] = options
        return self.env.point.get(" choices", {}).get(key, options[0])

    # ---- powers
    def r_power(self, t):
        base, sup = t.children[0], t.children[1]
        if glyph_key(t) in self.env.decls:  # a starred NAME declared of its own
            return self.env.lookup(glyph_key(t), t)
        return self._raise(self.value(base), sup, t)

    def _raise(self, v, sup, t):
        s = str(sup.children[0]).replace(" ", "")
        if s in _TRANSPOSE:
            return V.transpose(v)
        if s in ("-T", "-\\top", "-\\mathsf{T}", "-\\mathrm{T}"):
            return V.transpose(V.inverse(v))
        if s in ("*", "\\ast") and V.shape(V.scalar(v)) == (4, 1):  # a quaternion's q^*
            return V.quaternion_conjugate(v)
        if s in ("*", "\\ast"):
            return self._star(v, t)
        if s in ("\\wedge", "\\times"):  # Hughes' a^\times too
            return V.hat(v)
        if s == "\\vee":
            return V.vee(v)
        if s == "\\curlywedge":  # Barfoot's xi^curlywedge: ad of a 6-vector
            return V.small_adjoint(v)
        try:
            n = int(s)
        except ValueError:
            raise NotCovered(f"the power {s} in {text_of(t)!r}") from None
        if n == -1 and V.shape(V.scalar(v)) == (4, 1):  # a quaternion's q^{-1}
            return V.quaternion_inverse(v)
        if n == -1:
            return V.inverse(v)
        return V.power(v, n)

    def _star(self, v, t):
        """``X^*`` of no quaternion: of a declared ``spatial transform`` Featherstone's dual
        ``X^{-T}``; of another 6x6 matrix a choice point
        (:data:`rigidsym.numeval.conventions.STAR`: Jain's transpose or the dual), one for
        every star of the statement; of a 6-vector its transpose (Jain's ``V^*``)."""
        v = V.scalar(v)
        if V.shape(v) == (6, 1):
            return V.transpose(v)
        if not V.is_matrix(v) or (v.rows, v.cols) != (6, 6):
            raise NotCovered(f"the star of a value that is no 6-vector nor 6x6 matrix in "
                             f"{text_of(t)!r}")
        base = t.children[0]
        d = self.env.decls.get(glyph_key(base)) if isinstance(base, lark.Tree) else None
        if d is not None and d.kind == "spatial transform":  # Featherstone's, by its kind
            return V.transpose(V.inverse(v))
        key = conventions.choice_key("star", "X^*")
        how = conventions.settled("star") or self.choose(key, conventions.STAR)
        return V.transpose(V.inverse(v)) if how == "dual" else V.transpose(v)

    # ---- primaries
    def r_number(self, t):
        return mp.mpf(str(t.children[0]))

    def r_pi(self, t):
        return +mp.pi

    def r_label_first(self, t):  # \mathbf{a}^S_1, read as \mathbf{a}_1^S
        return self.r_glyph(names.canonical(t))

    def r_glyph(self, t):
        kids = t.children
        if len(kids) == 1 and isinstance(kids[0], lark.Tree) and kids[0].data in ("zero",
                                                                                 "one"):
            return V.Zero() if kids[0].data == "zero" else V.Eye()
        key = glyph_key(t)
        if key in self.env.decls or key in self.env.binds or self._bound_in_parents(key):
            return self.env.lookup(key, t)
        special = self._special(t)
        if special is not None:
            return special
        entries = self._entries(t)
        if entries is not None:
            return entries
        return self.env.lookup(key, t)

    def r_accented(self, t):
        return self._declared_only(names.canonical(t))

    r_accented_bare = r_arrow = r_indexed_accent = r_accented

    def r_base(self, t):  # Ad_T: a bare base
        return self.r_glyph(lark.Tree("glyph", [t]))

    r_calbase = r_fontbase = r_base

    def _declared_only(self, t):
        key = glyph_key(t)
        if key in self.env.decls or key in self.env.binds:
            return self.env.lookup(key, t)
        ranged = entries.range_under_accent(t)
        if ranged is not None:  # \bar{q}_{1:3}: entries of the declared \bar{q}
            whole, lo, hi = ranged
            v = self._declared_only(whole)
            if not V.is_matrix(v) or v.cols != 1 or not 1 <= lo <= hi <= v.rows:
                raise NotCovered(f"the entries {text_of(t)}")
            return v[lo - 1] if lo == hi else mp.matrix([v[i] for i in range(lo - 1, hi)])
        accent, inner = str(t.children[0]), None
        if accent in ("\\dot", "\\ddot") and len(t.children) == 2:
            inner = t.children[1]
            if inner.data == "bare":
                inner = lark.Tree("glyph", [lark.Tree("base", list(inner.children))])
        elif t.data == "indexed_accent" and str(t.children[1]).strip() in ("\\dot", "\\ddot"):
            # Jazar's {}^G\dot{R}_B: the rate of the declared {}^G R_B(t)
            index, accent, base, *rest = t.children
            accent, inner = str(accent).strip(), lark.Tree("glyph", [index, base, *rest])
        if inner is not None:
            d = self.env.decls.get(glyph_key(inner))
            if d is not None and (d.timed or rates.is_model(d)):  # or of a model
                v = self._derivative(inner, _TIME_TREE, t)
                if accent == "\\dot":
                    return v
                return self._derivative(lark.Tree("accented", [lark.Token("ACCENT", "\\dot"),
                                                               inner]), _TIME_TREE, t)
        if (v := accents.undeclared_accent(self, t, key)) is not None:  # ~a, a rate
            return v
        hat = hats.undeclared_hat(self, t, key, text_of(t))  # two readings
        if hat is not None:
            return hat
        raise NotCovered(f"the undeclared glyph {text_of(t)} (an accent's meaning is the "
                         f"reader's)")

    def _bound_in_parents(self, key: str) -> bool:
        return False  # a body sees its own parameters and the globals only (lexical scope)

    def _special(self, t):
        """A plain ``I`` (the identity, sized by its neighbours), ``I_3``, ``I_{3\\times 3}``,
        ``I_n``."""
        kids = t.children
        if kids and isinstance(kids[0], lark.Tree) and kids[0].data in ("zero", "one") \
                and len(kids) == 2 and isinstance(kids[1], lark.Tree):
            dims = _dims(kids[1])  # \mathbf{1}_{3\times 3}, \mathbf{0}_{1\times 3}
            if dims is None:
                return None
            if kids[0].data == "zero":
                single = len([c for c in kids[1].children if isinstance(c, lark.Token)]) == 1
                return V.Zero() if single else mp.zeros(*dims)
            return mp.eye(dims[0]) if dims[0] == dims[1] else None
        letter, bold, plain = _base_letter(t)
        if letter == "O" and bold and plain:
            return V.Zero()  # the books' bold O: a zero block
        if letter != "I":
            return None
        if plain:
            return V.Eye()
        sub = t.children[1]
        if not isinstance(sub, lark.Tree) or sub.data != "subscript":
            return None
        toks = [str(c) for c in sub.children if isinstance(c, lark.Token)]
        if toks == ["n"]:
            return V.Eye()
        dims = _dims(sub)
        return V.Eye(dims[0]) if dims and dims[0] == dims[1] else None

    def _entries(self, t):
        """``q_{1:3}``, ``q_4`` of a declared ``\\mathbf{q}``: :mod:`~rigidsym.numeval.entries`."""
        return entries.entries_of(self, t, _base_letter, text_of)

    def r_norm(self, t):
        return V.norm(self.value(self._kids(t)[0]))

    def r_abs_bars(self, t):
        return V.norm(self.value(self._kids(t)[0]))

    def r_sqrt(self, t):
        v = V.scalar(self.value(self._kids(t)[0]))
        if V.is_matrix(v) or isinstance(v, V.Eye | V.Zero):
            raise NotCovered(f"the square root of a matrix in {text_of(t)!r}")
        return mp.sqrt(v)

    def r_func(self, t):
        name = str(t.children[0])
        v = self.value(self._kids(t)[0])
        return self._func(name, v, t)

    def _func(self, name, v, t):
        if name in _FUNCS:
            v = V.scalar(v)
            if V.is_matrix(v) or isinstance(v, V.Eye | V.Zero):
                raise NotCovered(f"{name} of a matrix in {text_of(t)!r}")
            return _FUNCS[name](v)
        word = _operator_word(name)
        if word in _OPS:
            return _OPS[word](v)
        raise NotCovered(f"the operator {name}")

    def r_arg_extent(self, t):
        """``\\sin\\omega t``: a function whose argument has no parentheses, then factors
        (:func:`rigidsym.latex.rewrites.argument_extents`). The leading scalar factors may
        continue the argument: a choice point
        (:data:`rigidsym.numeval.conventions.ARGUMENT_EXTENT`) where there is one; a vector
        or matrix ends the run."""
        texts = [str(c) for c in t.children[3::2]]
        inner, factors = t.children[2], [self.value(c) for c in t.children[4::2]]
        kids = list(inner.children)
        arg = self.value(kids[-1])
        run = 0
        if _scalar_value(arg):
            while run < len(factors) and _scalar_value(factors[run]):
                run += 1
        how = "factor"
        if run:
            key = conventions.choice_key(
                "argument extent", " ".join([str(t.children[0]), str(t.children[1]),
                                             *texts[:run]]))
            how = conventions.settled("argument extent") or self.choose(
                key, conventions.ARGUMENT_EXTENT)
        if how == "product":
            for f in factors[:run]:
                arg = V.mul(arg, f)
            factors = factors[run:]
        v = self._function_of(lark.Tree(inner.data[len("extent_"):], kids), arg)
        for f in factors:
            v = V.mul(v, f)
        return v

    def _function_of(self, f, arg):
        """The function node ``f`` (``func``, ``func_power``, ``matfunc``) of the value
        ``arg`` in place of its own argument's."""
        rule = {"func": self.r_func, "func_power": self.r_func_power,
                "matfunc": self.r_matfunc}[f.data]
        saved, self.value = self.value, lambda c: arg if c is f.children[-1] else saved(c)
        try:
            return rule(f)
        finally:
            del self.value

    def r_func_power(self, t):
        name, sup = str(t.children[0]), t.children[1]
        if str(sup.children[0]).replace(" ", "") == "-1" and name in _INVERSES:
            v = None
        else:
            v = self._func(name, self.value(t.children[2]), t)
        s = str(sup.children[0]).replace(" ", "")
        if s == "-1" and name in _INVERSES:  # \cos^{-1} x: arccos x
            x = V.scalar(self.value(t.children[2]))
            if V.is_matrix(x) or isinstance(x, V.Eye | V.Zero):
                raise NotCovered(f"{name}^{{-1}} of a matrix")
            return _INVERSES[name](x)
        if not s.isdigit():
            raise NotCovered(f"the power {s} of {name}")
        return V.power(v, int(s))

    def r_cpm(self, t):
        return V.hat(self.value(self._kids(t)[0]))

    def r_exp_e(self, t):
        return V.expm(self.value(self._kids(t)[0]))

    def r_matfunc(self, t):
        v = self.value(self._kids(t)[0])
        return V.expm(v) if "exp" in str(t.children[0]) else V.logm(v)

    def r_atan2(self, t):
        y, x = (V.scalar(self.value(k)) for k in self._kids(t))
        return mp.atan2(y, x)

    def r_adjoint(self, t):
        v = self.value(self._kids(t)[0])
        return V.small_adjoint(v) if "ad" in str(t.children[0]) and "Ad" not in str(
            t.children[0]) else V.adjoint(v)

    def r_diag(self, t):
        vals = [self.value(k) for k in self._kids(t)]
        vals = [mp.eye(v.n) * v.c if isinstance(v, V.Eye) and v.n else v for v in vals]
        if not any(V.is_matrix(v) and (v.rows, v.cols) != (1, 1) for v in vals):
            return mp.diag([V.scalar(v) for v in vals])
        if not all(V.is_matrix(v) and v.rows == v.cols or not V.is_matrix(v)
                   and not isinstance(v, (V.Eye, V.Zero)) for v in vals):
            raise NotCovered("diag of a vector or of a block whose size is not given")
        # square blocks (I_2 beside I_1, a scalar a 1x1 block): the block-diagonal matrix
        blocks = [v if V.is_matrix(v) else mp.matrix([[v]]) for v in vals]
        n = sum(b.rows for b in blocks)
        out, at = mp.zeros(n, n), 0
        for b in blocks:
            for i in range(b.rows):
                for j in range(b.cols):
                    out[at + i, at + j] = b[i, j]
            at += b.rows
        return out

    def r_sized_number(self, t):
        n = str(t.children[0])
        toks = [str(c) for c in t.children[1].children if isinstance(c, lark.Token)]
        if n != "0" or not toks or not all(x.isdigit() for x in toks):
            raise NotCovered(f"the sized number {text_of(t)}")
        rows = int(toks[0])
        cols = int(toks[1]) if len(toks) > 1 else 1
        return mp.zeros(rows, cols)

    # ---- matrices written out
    def r_matrix(self, t):
        rows = [[self.value(e) for e in self._kids(r)] for r in self._kids(t)]
        return V.assemble(rows, text_of(t))

    # ---- applications
    def r_apply(self, t):
        f, arg = t.children[0], t.children[1]
        sup = t.children[2] if len(t.children) > 2 else None
        if sup is not None and not self._applies(f, arg):  # c(a + b)^2: c times the power
            return V.mul(self.value(f), self._raise(self.value(arg), sup, t))
        v = self._call(f, [arg], t)
        return self._raise(v, sup, t) if sup is not None else v

    def _applies(self, f, arg) -> bool:
        """``f(arg)`` is an application: a --let function, or a model (or a function of
        time) at a scalar glyph."""
        d = self.env.decls.get(glyph_key(f))
        if d is None:
            return False
        if d.params:
            return True
        return (d.body is not None or d.timed) and isinstance(arg, lark.Tree) \
            and arg.data == "glyph" and not V.is_matrix(V.scalar(self.value(arg)))

    def r_apply_many(self, t):
        kids = self._kids(t)
        sup = kids[-1] if kids[-1].data == "sup" else None
        args = kids[1:-1] if sup is not None else kids[1:]
        v = self._call(kids[0], args, t, many=True)
        return self._raise(v, sup, t) if sup is not None else v

    def r_apply_pre_many(self, t):  # A^T(\mathbf{e}, \vartheta): A(e, θ)^T
        f, sup, *args = self._kids(t)
        return self._raise(self._call(f, args, t, many=True), sup, t)

    def r_apply_pre(self, t):  # a^2(b + c)^2: a last power is the argument's in a product
        post, sup, arg, *last = t.children
        if isinstance(post, lark.Tree) and self._applies(post, arg):  # R^T(\theta)
            v = self._raise(self._call(post, [arg], t), sup, t)
            return self._raise(v, last[0], t) if last else v
        a = self.value(arg)
        return V.mul(self._raise(self.value(post), sup, t),
                     self._raise(a, last[0], t) if last else a)

    def _call(self, f, args, t, many: bool = False):
        key = glyph_key(f)
        d = self.env.decls.get(key)
        if d is None and not many:
            primed = self._primed(f, args[0], t)  # f'(x) of a --let function f(x)
            if primed is not None:
                return primed
        if d is not None and d.body is not None and not d.params and not many:
            # R(\theta) of a model R: the model itself, as the books write its variable
            if isinstance(args[0], lark.Tree) and args[0].data == "glyph":
                arg = self.value(args[0])
                if not V.is_matrix(V.scalar(arg)) and not isinstance(arg, V.Eye | V.Zero):
                    return self.value(f)
            if self._depends(d, args[0]) and self.choose(
                    f"apply {key}", ("product", "apply")) == "apply":
                return self.value(f)  # X(\mathbf{y}): X itself, applied
        if d is None or not d.params:
            if many:
                raise NotCovered(f"{text_of(f)} applied to several arguments")
            if d is not None and d.timed and glyph_key(args[0]) == TIME:
                return self.value(f)  # X(t) of a function of time: X at t
            return V.mul(self.value(f), self.value(args[0]))  # a product, as written
        if len(args) != len(d.params):
            raise NotCovered(f"{text_of(t)}: {len(args)} arguments of a function of "
                             f"{len(d.params)}")
        return self._apply_values(d, [self.value(a) for a in args], t)

    def _depends(self, d, arg) -> bool:
        """The model ``d`` may depend on the argument ``arg`` of ``X(arg)``: the glyphs its
        body mentions and those of ``arg``, each through the models they mention (all the
        way down), meet, or a kind relates a glyph to another (``body angular velocity of
        R``); else ``X(arg)`` is only the product, as the books write a model that is no
        function of ``arg``."""
        def mentioned(t) -> set[str]:
            return {glyph_key(sub) for sub in (t.iter_subtrees() if isinstance(t, lark.Tree)
                                               else ())
                    if sub.data in ("glyph", "accented", "accented_bare", "label_first")}

        def through(keys: set[str]) -> set[str] | None:  # None: a kind relates glyphs
            seen, todo = set(), set(keys)
            while todo:
                k = todo.pop()
                seen.add(k)
                m = self.env.decls.get(k)
                if m is not None and " of " in m.kind:
                    return None
                if m is not None and m.body is not None:
                    todo |= mentioned(m.body) - seen
            return seen

        mine = through(mentioned(d.body) - {glyph_key(d.name)})
        theirs = through(mentioned(arg))
        return mine is None or theirs is None or bool(mine & theirs)

    def _apply_values(self, d, vals, t):
        """The function ``d`` at the argument values ``vals``."""
        self.env.point.setdefault(" used", set()).add(glyph_key(d.name))
        binds = {glyph_key(p): v for p, v in zip(d.params, vals, strict=True)}
        # lexical scope, a fresh environment per application: the globals and the
        # parameters; every model is evaluated again in it, so those built on a parameter
        # see the argument
        env = Env(self.env.decls, self.env.point, self.env.rng, binds, None,
                  self.env.depth + 1)
        if env.depth > 40:
            raise NotCovered(f"{text_of(t)}: applications nested too deep")
        return Evaluator(env).value(d.body)

    def _primed(self, f, arg, t):
        """Lagrange's ``f'(x)``, ``f''(x)`` of a --let function of one parameter: its
        derivative at the argument, by central differences of order 4."""
        if not isinstance(f, lark.Tree) or f.data != "glyph":
            return None
        primes = [c for c in f.children if isinstance(c, lark.Token) and c.type == "PRIMES"]
        if len(primes) != 1:
            return None
        bare = lark.Tree("glyph", [c for c in f.children if c is not primes[0]])
        d = self.env.decls.get(glyph_key(bare))
        if d is None or len(d.params) != 1:
            return None
        n = len(str(primes[0]))
        x0 = V.scalar(self.value(arg))
        if V.is_matrix(x0) or n > 2:
            raise NotCovered(f"the derivative {text_of(t)!r}")
        h = mp.mpf(10) ** (-DIGITS // 5)
        if n == 1:
            f_ = [_explicit(self._apply_values(d, [x0 + k * h], t)) for k in (-2, -1, 1, 2)]
            return _combine(f_, [1, -8, 8, -1], 12 * h)
        f_ = [_explicit(self._apply_values(d, [x0 + k * h], t)) for k in (-2, -1, 0, 1, 2)]
        return _combine(f_, [-1, 16, -30, 16, -1], 12 * h * h)

    # ---- derivatives
    def r_deriv_frac(self, t):
        kids = self._kids(t)
        return self._derivative(kids[0], kids[1], t)

    def r_deriv_op(self, t):
        kids = self._kids(t)
        return self._derivative(kids[1], kids[0], t)

    def _derivative(self, expr, var, t):
        key = glyph_key(var)
        d = self.env.decls.get(key)
        if key == TIME and rates.declared(self.env.decls, glyph_key):
            return rates.time_derivative(self, expr, glyph_key, DIGITS)
        if d is not None and (d.body is not None or d.params):
            raise NotCovered(f"a derivative by the model {text_of(var)}")
        x0 = V.scalar(self.value(var))
        if V.is_matrix(x0):
            raise NotCovered(f"a derivative by the vector {text_of(var)}")
        h = mp.mpf(10) ** (-DIGITS // 5)

        def at(x):
            env = Env(self.env.decls, self.env.point, self.env.rng,
                      {**self.env.binds, key: x}, None, self.env.depth + 1)
            return _explicit(Evaluator(env).value(expr))

        f = [at(x0 + k * h) for k in (-2, -1, 1, 2)]
        return _combine(f, [1, -8, 8, -1], 12 * h)


def _scalar_value(v) -> bool:
    """``v`` is a scalar value (a 1x1 matrix counts): it may continue a function's argument."""
    v = V.scalar(v)
    return not (V.is_matrix(v) or isinstance(v, V.Eye | V.Zero))


def _dims(sub) -> tuple[int, int] | None:
    """The size a subscript writes: ``_3`` (3 x 3 or a 3-vector's 3 x 1 where a zero),
    ``_{3\\times 3}``, ``_{1\\times 3}``; ``None`` for anything else."""
    if not isinstance(sub, lark.Tree) or sub.data != "subscript":
        return None
    toks = [str(c) for c in sub.children if isinstance(c, lark.Token)]
    times = [c for c in sub.children if isinstance(c, lark.Tree) and c.data == "times"]
    if all(x.isdigit() for x in toks) and (len(toks), len(times)) in ((1, 0), (2, 1)):
        return (int(toks[0]), int(toks[-1]))
    return None


def _explicit(v):
    if isinstance(v, V.Eye | V.Zero):
        raise NotCovered("the derivative of an unsized identity or zero")
    return v


def _combine(vals, coeffs, den):
    out = None
    for v, c in zip(vals, coeffs, strict=True):
        term = v * c
        out = term if out is None else out + term
    return out / den
