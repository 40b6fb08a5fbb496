"""Read the chapter's LaTeX into the declaration vocabulary's atoms and operators: the
LaTeX transformer :class:`LatexTransformer` (its rule families and their modules:
:mod:`rigidsym.latex.transformer`) and the chapter's own rules.

:func:`rigidsym.latex.reader.parse_latex` parses a LaTeX string with the lark grammar
``grammar.lark`` (LALR(1)) and this transformer builds, relation by relation, sympy
objects of :mod:`rigidsym.declare`'s vocabulary: book matrices (``MatrixSymbol``) and
scalars (real ``Symbol``) named by the glyph table (:mod:`rigidsym.latex.table`),
``Cross``, ``Det``, ``Cpm``, ``Vect``, ``Trace``, block matrices, transposes, inverses and
powers. Juxtaposition is a matrix product or a scalar
product according to the shapes; a shape that does not fit is an error, never a guess.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, Chap. 3 (its notation,
``../shared/NOTATION.md``).
"""

from __future__ import annotations

from dataclasses import dataclass

import lark
import sympy as sp

from rigidsym.algebra.operators import Det, Vect
from rigidsym.latex.lexing import Parsed, Relation, operator_word, parser
from rigidsym.latex.shapes import (
    LatexError,
    SizedZero,
    as_scalar,
    fit,
    loose,
    matrix_shape,
    shape_words,
    shaped_product,
    size_identity,
)
from rigidsym.latex.table import Glyph, lookup
from rigidsym.latex.transformer.book_notations import BookNotationRules, sup_word
from rigidsym.latex.transformer.extent import ArgumentExtentRules
from rigidsym.latex.transformer.glyphs import TIME, GlyphKey, GlyphRules
from rigidsym.latex.transformer.meanings import BracketCpm, MeaningRules
from rigidsym.latex.transformer.rigid_motions import RigidMotionRules

__all__ = ["LatexError", "Relation", "Parsed", "parser"]


class LatexTransformer(GlyphRules, MeaningRules, RigidMotionRules, BookNotationRules,
                       ArgumentExtentRules, lark.Transformer):
    """Tree -> sympy, in the declaration vocabulary (module docstring); ``reader``: a
    reader's LaTeX, ``[x]`` of a vector its hat (:mod:`rigidsym.latex.transformer.rigid_motions`),
    ``I`` the identity (:mod:`rigidsym.latex.transformer.meanings`); the glyphs' rules are
    :class:`~rigidsym.latex.transformer.glyphs.GlyphRules`."""

    def __init__(self, section: str, overrides: dict, block_rows: bool, reader: bool = False):
        super().__init__()
        self.section, self.overrides, self.block_rows = section, overrides, block_rows
        self.reader = reader
        self.readings: list[str] = []
        self.glyphs: dict[str, Glyph] = {}
        self.made: dict = {}  # result -> (how, parts): to re-read a bracket as a block row
        self.model_rhs: dict = {}  # the models read so far by name (d/dt differentiates them)

    # ---- numbers and groups
    def number(self, items):
        return sp.Rational(str(items[0]))

    def pi(self, _):
        return sp.pi

    def bracket(self, items):
        x = items[0]
        if self.block_rows:
            return self._block_row(x)
        if self.reader and type(value_of(x)) is BracketCpm:  # Shuster's [[u]]
            return self.double_bracket(value_of(x))
        return self.hat_bracket(x) if self.reader else value_of(x)

    def sized(self, items):
        x = items[1]
        if self.block_rows and "[" in str(items[0]):
            return self._block_row(x)
        if self.reader and "[" in str(items[0]) and type(value_of(x)) is BracketCpm:
            return self.double_bracket(value_of(x))
        return self.hat_bracket(x) if self.reader and "[" in str(items[0]) else value_of(x)

    def _val(self, x):
        return value_of(x)

    def _block_row(self, x):
        """``[A  v]`` whose column separator was lost in the conversion: a block row."""
        note = "read [...] as a block row: its column separator was lost in the conversion"
        if isinstance(x, _Pending):  # A + (c M) v or A - c v: shapes 3x3 and 3x1
            b = self.made.get(x.b)
            if b and b[0] == "mul" and matrix_shape(b[1][0]) == matrix_shape(x.a):
                left = x.a + b[1][0] if x.op == "add" else x.a - b[1][0]
                self.readings.append(note)
                return sp.BlockMatrix([[left, b[1][1]]])
            self.readings.append(note)
            return sp.BlockMatrix([[x.a, x.b if x.op == "add" else -x.b]])
        how = self.made.get(x)
        if how and how[0] == "mul":
            a, b = how[1]
            if matrix_shape(a) and matrix_shape(b) and matrix_shape(b)[1] == 1 \
                    and matrix_shape(a)[1] != 1:
                self.readings.append(note)
                return sp.BlockMatrix([[a, b]])
        return x

    # ---- arithmetic
    def add(self, items):
        a, b = (value_of(i) for i in items)
        return self._sum(a, b, "add")

    def sub(self, items):
        a, b = value_of(items[0]), items[1]
        if isinstance(b, _Brace):  # a - \underbrace{p + q}: a brace groups nothing
            how = self.made.get(b.body)
            if how and how[0] in ("add", "sub"):
                return self._sum(self._sum(a, how[1][0], "sub"), how[1][1], how[0])
        return self._sum(a, value_of(b), "sub")

    def _sum(self, a, b, op):
        sa, sb = matrix_shape(a), matrix_shape(b)
        if sa != sb and self.block_rows and sa and sb:
            return _Pending(a, b, op)
        if self.reader:
            a, b = size_identity(a, b, 0)
        a, b = fit(a, b, op)
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
        return -value_of(b)

    def mul(self, items):
        a, b = (value_of(i) for i in items)
        if b is TIME and matrix_shape(a) is not None or (b is TIME and isinstance(a, sp.Symbol)):
            self.readings.append("(t): a function of time")
            return a
        if self.reader:
            a, b = size_identity(a, b, 1)
        r = shaped_product(a, b)
        self.made[r] = ("mul", (a, b))
        return r

    def div(self, items):
        a, b = (value_of(i) for i in items)
        b = as_scalar(b)
        if matrix_shape(b) is not None:
            raise LatexError(f"division by {shape_words(b)}: expected a scalar denominator",
                             "shapes")
        return a / b

    def frac(self, items):
        return self.div(items)

    def dot(self, items):
        a, b = (value_of(i) for i in items)
        if matrix_shape(a) is None or matrix_shape(b) is None:
            return shaped_product(a, b)
        if matrix_shape(a) != matrix_shape(b) or matrix_shape(a)[1] != 1:
            raise LatexError(f"\\cdot between {shape_words(a)} and {shape_words(b)}: expected two "
                             f"vectors of one size", "shapes")
        return as_scalar(a.T * b)

    def power(self, items):
        if items[1] == "*" and isinstance(items[0], GlyphKey) \
                and items[0].key + "^{*}" in self.overrides:  # a starred name a --let
            self.glyphs.pop(items[0].key, None)  # declares: a symbol of its own
            return self._symbol(items[0].key + "^{*}", items[0].base)
        x, sup = value_of(items[0]), items[1]
        if sup != "T" and not sup.lstrip("-").isdigit():
            return self.book_power(x, sup)
        if sup == "T":
            if matrix_shape(x) is None:
                raise LatexError("^T of a scalar: expected a matrix or vector", "shapes")
            return x.T
        n = int(sup)
        if matrix_shape(x) is None:
            return x ** n
        if n == -1 and matrix_shape(x) == (4, 1):  # a quaternion's inverse
            return self.quaternion_inverse(x)
        if n == -1:
            return x.inverse() if not isinstance(x, sp.MatrixBase) else x.inv()
        if matrix_shape(x) == (1, 1):
            return as_scalar(x) ** n
        if matrix_shape(x)[0] != matrix_shape(x)[1]:  # \hat{u}^2 of a unit vector \hat{u}
            raise LatexError(f"^{n} of a {matrix_shape(x)[0]}x{matrix_shape(x)[1]} matrix: "
                             f"a power of a square matrix only", "shapes")
        return x ** n

    def sup(self, items):
        return sup_word(str(items[0]))

    def func(self, items):
        name, x = str(items[0]), value_of(items[1])
        _operator_of_function(name, items[1], getattr(self, "functions", {}))
        x = as_scalar(x) if "det" not in name else x
        fn = operator_word(name)
        fn = "tr" if fn in ("Tr", "trace") else fn
        if fn in ("sin", "cos", "tan"):
            return getattr(sp, fn)(x)
        if fn in ("cot", "sec", "csc"):  # in the sines and cosines the engine decides
            return {"cot": sp.cos(x) / sp.sin(x), "sec": 1 / sp.cos(x), "csc": 1 / sp.sin(x)}[fn]
        if fn == "arctan":
            return sp.atan(x)
        if fn == "arccos":
            return sp.acos(x)
        if fn == "det":  # of a scalar: never Det(R) of a scalar R
            if matrix_shape(x) is None or matrix_shape(x)[0] != matrix_shape(x)[1]:
                raise LatexError(f"det of {shape_words(x)}: expected a square matrix"
                                 f"{_applied_hint(fn, x)}", "shapes")
            return Det(x)
        if fn == "tr":
            if matrix_shape(x) is None or matrix_shape(x)[0] != matrix_shape(x)[1]:
                raise LatexError(f"tr of {shape_words(x)}: expected a square matrix"
                                 f"{_applied_hint(fn, x)}", "shapes")
            return sp.Trace(x)
        if fn == "vect":
            if matrix_shape(x) != (3, 3):
                raise LatexError(f"vect of {shape_words(x)}: expected a 3x3 matrix"
                                 f"{_applied_hint(fn, x)}", "shapes")
            return Vect(x)
        raise LatexError(f"unknown operator {name}", f"unknown macro {name}")

    def one_trace(self, items):
        x = value_of(items[-1])
        self.readings.append("\\mathbf{1tr}(X): 1 tr(X), the identity times the trace")
        return sp.Trace(x) * sp.Identity(matrix_shape(x)[0])

    def cpm(self, items):
        from rigidsym.algebra.operators import Cpm

        if len(items) == 3:  # \left[ a \right]_\times, \bigl[ a \bigr]_\times: TeX's [a]_\times
            if "[" not in str(items[0]) or "]" not in str(items[2]):
                raise LatexError(f"{items[0]} ... {items[2]}_\\times: expected the square "
                                 f"brackets of [a]_\\times (the cross-product matrix)",
                                 "syntax")
        x = value_of(items[-1] if not isinstance(items[0], lark.Token) else items[1])
        if matrix_shape(x) != (3, 1):
            raise LatexError(f"CPM of {shape_words(x)}: expected a 3-vector", "shapes")
        return Cpm(x)

    def frame(self, items):
        x, frame = value_of(items[0]), str(items[1])
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
        body, label = value_of(items[0]), value_of(items[1])
        self.braces.append((label, body))
        return _Brace(body)

    # ---- relations
    def chain(self, items):
        exprs = [value_of(i) for i in items if not isinstance(i, lark.Token)]
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
class _Brace:
    body: object


@dataclass(frozen=True)
class _Pending:
    a: object
    b: object
    op: str


def _operator_of_function(name: str, node, functions: dict) -> None:
    """An operator written before a ``--let`` function's application with no parentheses of
    its own (``\\det J_r(\\mathbf{x})``): the operator's argument is one primary, so it
    would take the glyph ``J_r`` alone and the parentheses would multiply; refused with the
    spelling that applies it to the function's value, ``\\det(J_r(\\mathbf{x}))``.

    Raises:
        LatexError: construct ``function``, its ``function`` attribute the glyph's key (the
            reader writes the function's parameters into the advice)."""
    key = getattr(node, "key", None)
    op = operator_word(name)
    if key is None or key not in functions or op not in ("det", "tr", "Tr", "trace", "vect"):
        return  # (a sine takes a scalar glyph as it is)
    exc = LatexError(
        f"{name} {key}(...) reads as {name} of the glyph {key} alone, times the "
        f"parentheses, and {key} is a --let function, not a matrix: an operator takes one "
        f"primary, so a function's value goes inside the operator's parentheses: write "
        f"{name}({key}(...))", "function")
    exc.function = key
    raise exc


def _applied_hint(fn: str, x) -> str:
    """Where an operator met a scalar: the reading that a reader most often meant (``\\det
    J(x)`` reads as ``(\\det J)(x)``: the operator takes the glyph, the parentheses
    multiply)."""
    if matrix_shape(x) is not None:
        return ""
    return (f"; the value of a matrix function goes in parentheses, \\{fn}(F(x)), and an "
            f"undeclared glyph is a scalar (--let 'NAME: KIND')")


def value_of(x):
    """The value a transformer's node stands for: a glyph's value, a brace's body, ``x``
    itself otherwise.

    Raises:
        LatexError: a sum whose shapes did not fit, left pending until now (``shapes``)."""
    if isinstance(x, GlyphKey):
        return x.value
    if isinstance(x, _Brace):
        return x.body
    if isinstance(x, _Pending):
        raise LatexError(f"a sum of {shape_words(x.a)} and {shape_words(x.b)}: shapes do not fit",
                         "shapes")
    return x

