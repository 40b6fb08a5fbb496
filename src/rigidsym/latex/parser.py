"""Read the chapter's LaTeX into the declaration vocabulary's atoms and operators.

:func:`parse_latex` parses a LaTeX string with the lark grammar ``grammar.lark`` (LALR(1))
and builds, relation by relation, sympy objects of :mod:`rigidsym.declare`'s vocabulary:
book matrices (``MatrixSymbol``) and scalars (real ``Symbol``) named by the glyph table
(:mod:`rigidsym.latex.table`), ``Cross``, ``Det``, ``Cpm``, ``Vect``, ``Trace``, block
matrices, transposes, inverses and powers. Juxtaposition is a matrix product or a scalar
product according to the shapes; a shape that does not fit is an error, never a guess.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, Chap. 3 (its notation,
``../shared/NOTATION.md``).
"""

from __future__ import annotations

from dataclasses import dataclass

import lark
import sympy as sp

from rigidsym.algebra.operators import Det, Vect
from rigidsym.latex.bookrules import BookRules, index_key, sup_word
from rigidsym.latex.lexing import Parsed, Relation, parser
from rigidsym.latex.meaning import MeaningRules
from rigidsym.latex.shapes import (
    LatexError,
    SizedZero,
    _as_scalar,
    _default_glyph,
    _fit,
    _product,
    _shape,
    _size_identity,
    _words,
    loose,
)
from rigidsym.latex.table import Glyph, lookup
from rigidsym.latex.vocab import VocabRules

__all__ = ["LatexError", "Relation", "Parsed", "parser"]


_TIME = sp.Symbol("t", real=True)  # the plain letter t: time, the argument of p(t)


class _Build(MeaningRules, VocabRules, BookRules, lark.Transformer):
    """Tree -> sympy, in the declaration vocabulary (module docstring); ``reader``: a
    reader's LaTeX, ``[x]`` of a vector its hat, ``I`` the identity (``latex/vocab.py``)."""

    def __init__(self, section: str, overrides: dict, block_rows: bool, reader: bool = False):
        super().__init__()
        self.section, self.overrides, self.block_rows = section, overrides, block_rows
        self.reader = reader
        self.readings: list[str] = []
        self.glyphs: dict[str, Glyph] = {}
        self.made: dict = {}  # result -> (how, parts): to re-read a bracket as a block row

    # ---- glyphs
    def base(self, items):
        if len(items) == 2:
            bold, letter = items
            return ("bold", str(letter))
        return ("plain", str(items[0]))

    def zero(self, _):
        return ("zero", "0")

    def one(self, _):
        return ("one", "1")

    def subscript(self, items):
        parts = [str(i) for i in items]  # a space after a Greek letter before a letter
        return ("sub", "".join(p + " " if p.startswith("\\") and p[-1].isalpha() and
                               k + 1 < len(parts) and parts[k + 1][:1].isalpha() else p
                               for k, p in enumerate(parts)))

    def times(self, _):
        return "\\times "

    def slash(self, _):
        return "/"

    def calsub(self, items):
        return "\\mathcal{" + str(items[0]) + "}" + (str(items[1]) if len(items) > 1 else "")

    def _key(self, base, rest, accent=None, pre="") -> str:
        kind, letter = base
        core = {"bold": f"\\mathbf{{{letter}}}" if not letter.startswith("\\")
                else f"\\boldsymbol{{{letter}}}",
                "plain": letter, "zero": "\\mathbf{0}", "one": "\\mathbf{1}",
                "cal": f"\\mathcal{{{letter}}}"}[kind]
        if accent:
            core = f"{accent}{{{core}}}"
        core = pre + core
        for r in rest:
            if isinstance(r, tuple):
                core += "_{" + r[1] + "}"
            else:
                core += str(r)
        return core

    def glyph(self, items):
        if isinstance(items[0], lark.Token) and items[0].type == "LEFT_INDEX":
            return self._resolve(items[1], items[2:], None, pre=index_key(str(items[0])))
        return self._resolve(items[0], items[1:], None)

    def accented(self, items):
        accent, inner = str(items[0]), items[1]
        if not isinstance(inner, _GlyphKey):
            raise LatexError(f"{accent} over an expression: expected a glyph", "accent")
        base, rest = inner.base, list(inner.rest) + list(items[2:])
        if accent == "\\dot" and not items[2:] and self.timed(inner.key):  # d/dt of X(t)
            return self.velocity(inner.key, inner.value)
        self.glyphs.pop(inner.key, None)  # only the accented glyph is a symbol here
        return self._resolve(base, rest, (inner.accent or "") + accent if inner.accent
                             else accent, inner)

    def arrow(self, items):
        key = f"\\overrightarrow{{{items[0]}}}"
        return self._symbol(key, None)

    def _resolve(self, base, rest, accent, inner=None, pre=""):
        if inner is not None:  # an accent over a glyph that has its own sub/primes
            key = f"{accent}{{{inner.key}}}" + "".join(
                "_{" + r[1] + "}" if isinstance(r, tuple) else str(r)
                for r in rest[len(inner.rest):])
        else:
            key = self._key(base, rest, accent, pre)
        kind = base[0]
        if rest and isinstance(rest[-1], tuple) and ":" in rest[-1][1] and inner is None:
            return self._slice(key, base, rest, accent, pre)
        sized = self._sized(key, base, rest, accent)  # I, I_3, \mathbf{1}_3 (latex.meaning)
        if sized is not None:
            return _GlyphKey(key, base, rest, accent, sized)
        if kind == "zero":
            z = None if accent else self.sized_zero(key, rest)
            return _GlyphKey(key, base, rest, accent, z if z is not None
                             else sp.ZeroMatrix(3, 1))
        if kind == "one":
            n = 3
            for r in rest:
                if isinstance(r, tuple) and "times" in r[1]:
                    n = int(r[1].split("\\times")[0])
            return _GlyphKey(key, base, rest, accent, sp.Identity(n))
        if kind == "bold" and base[1] == "O" and not accent:
            rows = cols = 3
            for r in rest:
                if isinstance(r, tuple) and r[1].isdigit() and len(r[1]) == 2:
                    rows, cols = int(r[1][0]), int(r[1][1])
            return _GlyphKey(key, base, rest, accent, sp.ZeroMatrix(rows, cols))
        if kind == "plain" and base[1] == "t" and not rest and not accent:
            return _GlyphKey(key, base, rest, accent, _TIME)
        if accent in ("\\vec", "\\underline") and kind == "plain":  # vector fonts
            base = ("bold", base[1])
        return _GlyphKey(key, base, rest, accent, self._symbol(key, base))

    def _slice(self, key, base, rest, accent, pre):
        """``\\mathbf{q}_{1:3}``: entries 1 to 3 (counted from 1, both included) of the
        vector ``\\mathbf{q}`` (issue 52, item 4); of a scalar or matrix refused."""
        lo, hi = (int(n) for n in rest[-1][1].replace(" ", "").split(":"))
        vkey = self._key(base, rest[:-1], accent, pre)
        v = self._symbol(vkey, base)
        shape = getattr(v, "shape", None)
        if not shape or shape[1] != 1 or shape[0] == 1:
            raise LatexError(f"{key}: a range of entries of {vkey}, which is no vector "
                             f"({_words(v)}); declare it, e.g. --let '{vkey}: 4-vector'",
                             "shapes")
        if not 1 <= lo <= hi <= shape[0]:
            raise LatexError(f"{key}: entries {lo} to {hi} of {vkey}, a {shape[0]}-vector",
                             "shapes")
        if lo == hi:  # q_{4:4}: one entry, a scalar
            self.readings.append(f"{key}: entry {lo} of {vkey}")
            return _GlyphKey(key, base, rest, accent, v[lo - 1, 0])
        self.readings.append(f"{key}: entries {lo} to {hi} of {vkey}")
        return _GlyphKey(key, base, rest, accent,
                         sp.ImmutableMatrix([[v[i, 0]] for i in range(lo - 1, hi)]))

    def _symbol(self, key, base):
        g = self.overrides.get(key)
        if g is None and self.section is not None:  # None: no glyph table (a reader's LaTeX)
            g = lookup(key, self.section)
        if g is None:
            g = _default_glyph(key, base)
        self.glyphs[key] = g
        if g.shape == ():
            return sp.Symbol(g.name, real=True)
        if g.kind == "row":  # a per-id note: the text's vector stands for its row
            self.readings.append(f"{key} read as the row {g.name}^T (per-id note)")
            return sp.MatrixSymbol(g.name, *g.shape).T
        return sp.MatrixSymbol(g.name, *g.shape)

    # ---- numbers and groups
    def number(self, items):
        return sp.Rational(str(items[0]))

    def pi(self, _):
        return sp.pi

    def bracket(self, items):
        x = items[0]
        if self.block_rows:
            return self._block_row(x)
        return self.hat_bracket(x) if self.reader else _value(x)

    def sized(self, items):
        x = items[1]
        if self.block_rows and "[" in str(items[0]):
            return self._block_row(x)
        return self.hat_bracket(x) if self.reader and "[" in str(items[0]) else _value(x)

    def _val(self, x):
        return _value(x)

    def _block_row(self, x):
        """``[A  v]`` whose column separator was lost in the conversion: a block row."""
        note = "read [...] as a block row: its column separator was lost in the conversion"
        if isinstance(x, _Pending):  # A + (c M) v or A - c v: shapes 3x3 and 3x1
            b = self.made.get(x.b)
            if b and b[0] == "mul" and _shape(b[1][0]) == _shape(x.a):
                left = x.a + b[1][0] if x.op == "add" else x.a - b[1][0]
                self.readings.append(note)
                return sp.BlockMatrix([[left, b[1][1]]])
            self.readings.append(note)
            return sp.BlockMatrix([[x.a, x.b if x.op == "add" else -x.b]])
        how = self.made.get(x)
        if how and how[0] == "mul":
            a, b = how[1]
            if _shape(a) and _shape(b) and _shape(b)[1] == 1 and _shape(a)[1] != 1:
                self.readings.append(note)
                return sp.BlockMatrix([[a, b]])
        return x

    # ---- arithmetic
    def add(self, items):
        a, b = (_value(i) for i in items)
        return self._sum(a, b, "add")

    def sub(self, items):
        a, b = _value(items[0]), items[1]
        if isinstance(b, _Brace):  # a - \underbrace{p + q}: a brace groups nothing
            how = self.made.get(b.body)
            if how and how[0] in ("add", "sub"):
                return self._sum(self._sum(a, how[1][0], "sub"), how[1][1], how[0])
        return self._sum(a, _value(b), "sub")

    def _sum(self, a, b, op):
        sa, sb = _shape(a), _shape(b)
        if sa != sb and self.block_rows and sa and sb:
            return _Pending(a, b, op)
        if self.reader:
            a, b = _size_identity(a, b, 0)
        a, b = _fit(a, b, op)
        r = a + b if op == "add" else a - b
        if type(r) is sp.ZeroMatrix and not (loose(a) and loose(b)):
            # R w - R w cancels to sympy's ZeroMatrix, which the chain would resize like a
            # written \mathbf{0}: its operands fixed its shape (= 0_{3x3} is a shape slip)
            r = SizedZero(*r.shape)
        self.made[r] = (op, (a, b))
        return r

    def neg(self, items):
        b = items[0]
        if isinstance(b, _Brace):  # -\underbrace{p + q} is -p + q
            how = self.made.get(b.body)
            if how and how[0] in ("add", "sub"):
                return self._sum(-how[1][0], how[1][1], how[0])
        return -_value(b)

    def mul(self, items):
        a, b = (_value(i) for i in items)
        if b is _TIME and _shape(a) is not None or (b is _TIME and isinstance(a, sp.Symbol)):
            self.readings.append("(t): a function of time")
            return a
        if self.reader:
            a, b = _size_identity(a, b, 1)
        r = _product(a, b)
        self.made[r] = ("mul", (a, b))
        return r

    def div(self, items):
        a, b = (_value(i) for i in items)
        b = _as_scalar(b)
        if _shape(b) is not None:
            raise LatexError(f"division by {_words(b)}: expected a scalar denominator",
                             "shapes")
        return a / b

    def frac(self, items):
        return self.div(items)

    def dot(self, items):
        a, b = (_value(i) for i in items)
        if _shape(a) is None or _shape(b) is None:
            return _product(a, b)
        if _shape(a) != _shape(b) or _shape(a)[1] != 1:
            raise LatexError(f"\\cdot between {_words(a)} and {_words(b)}: expected two "
                             f"vectors of one size", "shapes")
        return _as_scalar(a.T * b)

    def power(self, items):
        if items[1] == "*" and isinstance(items[0], _GlyphKey) \
                and items[0].key + "^{*}" in self.overrides:  # a starred name a --let
            self.glyphs.pop(items[0].key, None)  # declares (issue 52): a symbol of its own
            return self._symbol(items[0].key + "^{*}", items[0].base)
        x, sup = _value(items[0]), items[1]
        if sup != "T" and not sup.lstrip("-").isdigit():
            return self.book_power(x, sup)
        if sup == "T":
            if _shape(x) is None:
                raise LatexError("^T of a scalar: expected a matrix or vector", "shapes")
            return x.T
        n = int(sup)
        if _shape(x) is None:
            return x ** n
        if n == -1:
            return x.inverse() if not isinstance(x, sp.MatrixBase) else x.inv()
        if _shape(x) == (1, 1):
            return _as_scalar(x) ** n
        return x ** n

    def sup(self, items):
        return sup_word(str(items[0]))

    def func(self, items):
        name, x = str(items[0]), _value(items[1])
        x = _as_scalar(x) if "det" not in name else x
        fn = name.split("{")[-1].rstrip("}").lstrip("\\")
        fn = "tr" if fn in ("Tr", "trace") else fn
        if fn in ("sin", "cos", "tan"):
            return getattr(sp, fn)(x)
        if fn in ("cot", "sec", "csc"):  # in the sines and cosines the engine decides
            return {"cot": sp.cos(x) / sp.sin(x), "sec": 1 / sp.cos(x), "csc": 1 / sp.sin(x)}[fn]
        if fn == "arctan":
            return sp.atan(x)
        if fn == "arccos":
            return sp.acos(x)
        if fn == "det":
            return Det(x)
        if fn == "tr":
            if _shape(x) is None or _shape(x)[0] != _shape(x)[1]:
                raise LatexError(f"tr of {_words(x)}: expected a square matrix", "shapes")
            return sp.Trace(x)
        if fn == "vect":
            if _shape(x) != (3, 3):
                raise LatexError(f"vect of {_words(x)}: expected a 3x3 matrix", "shapes")
            return Vect(x)
        raise LatexError(f"unknown operator {name}", f"unknown macro {name}")

    def one_trace(self, items):
        x = _value(items[-1])
        self.readings.append("\\mathbf{1tr}(X): 1 tr(X), the identity times the trace")
        return sp.Trace(x) * sp.Identity(_shape(x)[0])

    def cpm(self, items):
        from rigidsym.algebra.operators import Cpm

        x = _value(items[-1] if not isinstance(items[0], lark.Token) else items[1])
        if _shape(x) != (3, 1):
            raise LatexError(f"CPM of {_words(x)}: expected a 3-vector", "shapes")
        return Cpm(x)

    def frame(self, items):
        x, frame = _value(items[0]), str(items[1])
        swap = {}
        for s in x.atoms(sp.MatrixSymbol):
            key = next((k for k, g in self.glyphs.items() if g.name == s.name), None)
            if key is None:
                continue
            g = (lookup(f"[{key}]_{{\\mathcal{{{frame}}}}}", self.section)
                 if self.section is not None else None)
            name = g.name if g else f"{s.name}_{frame}"
            swap[s] = sp.MatrixSymbol(name, *s.shape)
        return x.xreplace(swap)

    def underbrace(self, items):
        body, label = _value(items[0]), _value(items[1])
        self.braces.append((label, body))
        return _Brace(body)

    # ---- relations
    def chain(self, items):
        exprs = [_value(i) for i in items if not isinstance(i, lark.Token)]
        ops = ["equiv" if "equiv" in str(t) else "=" for t in items
               if isinstance(t, lark.Token) and t.type == "RELOP"]
        return ("chain", exprs, ops)

    def start(self, items):
        for t in items:
            if isinstance(t, lark.Token) and t.type == "DECLARE":
                self.declared(str(t))
            elif isinstance(t, lark.Token):  # "\\text{for } phi \\neq 0": a side condition
                self.readings.append(f"side condition not checked: {t}")
        return [i for i in items if not isinstance(i, lark.Token)]


@dataclass(frozen=True)
class _GlyphKey:
    key: str
    base: tuple
    rest: list
    accent: str | None
    value: object


@dataclass(frozen=True)
class _Brace:
    body: object


@dataclass(frozen=True)
class _Pending:
    a: object
    b: object
    op: str


def _value(x):
    if isinstance(x, _GlyphKey):
        return x.value
    if isinstance(x, _Brace):
        return x.body
    if isinstance(x, _Pending):
        raise LatexError(f"a sum of {_words(x.a)} and {_words(x.b)}: shapes do not fit",
                         "shapes")
    return x

