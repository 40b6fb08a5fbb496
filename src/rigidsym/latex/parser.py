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

from dataclasses import dataclass, field
from functools import cache
from importlib import resources

import lark
import sympy as sp

from rigidsym.algebra.operators import Cross, Det, Vect
from rigidsym.latex.table import Glyph, lookup

__all__ = ["LatexError", "Relation", "Parsed", "parse_latex", "parser"]


class LatexError(ValueError):
    """LaTeX that cannot be read: a syntax error (with the position, a caret under the
    offending token and the constructs expected), an unknown macro (named), or a
    juxtaposition or sum whose shapes do not fit (a ``ValueError``).

    Attributes:
        construct: a short name of what could not be read (``"syntax"``, ``"unknown macro
            \\int"``, ``"shapes"``).
    """

    def __init__(self, message: str, construct: str = "syntax"):
        super().__init__(message)
        self.construct = construct


@dataclass(frozen=True)
class Relation:
    """One relation the LaTeX states: ``lhs op rhs`` (``op`` is ``=`` or ``≡``).

    Attributes:
        lhs, rhs: sympy scalars or matrix expressions of the same shape.
        op: ``"="`` or ``"equiv"``.
        chain: index of the ``=`` chain it belongs to; ``link`` its position in the chain.
        text: how it reads, in book notation (sympy's string form).
    """

    lhs: object
    rhs: object
    op: str
    chain: int
    link: int


@dataclass
class Parsed:
    """A parsed LaTeX statement.

    Attributes:
        chains: per ``=`` chain, the list of its expressions (``x = y = z`` gives three).
        ops: per chain, the relation symbols between them.
        relations: one :class:`Relation` per link of every chain, in order.
        readings: notes on how the text was read (a dropped time argument, a block row whose
            column separator was lost, an ignored condition).
        glyphs: the glyph-table rows used, by LaTeX key.
    """

    chains: list[list] = field(default_factory=list)
    ops: list[list[str]] = field(default_factory=list)
    relations: list[Relation] = field(default_factory=list)
    readings: list[str] = field(default_factory=list)
    glyphs: dict[str, Glyph] = field(default_factory=dict)

    def pairs(self):
        """Every pair ``(chain, i, j, E_i, E_j)`` with ``i < j`` of a chain: each is a
        relation the text states (``x = y = z`` states ``x = y``, ``x = z``, ``y = z``)."""
        for c, exprs in enumerate(self.chains):
            for i in range(len(exprs)):
                for j in range(i + 1, len(exprs)):
                    yield c, i, j, exprs[i], exprs[j]


# --------------------------------------------------------------------------- lexing
class _AlignedLayout:
    """Post-lexer: inside ``aligned`` (outside a matrix) ``&``, ``\\\\`` and a ``\\quad``
    right after ``&`` are layout; drop them (and the environment's delimiters)."""

    always_accept = ("AMP", "ROWSEP", "BEGIN_ALIGNED", "END_ALIGNED")

    def process(self, stream):
        aligned = matrix = 0
        after_amp = False
        for tok in stream:
            t = tok.type
            if t == "BEGIN_ALIGNED":
                aligned += 1
                continue
            if t == "END_ALIGNED":
                aligned -= 1
                continue
            if t == "BEGIN_MATRIX":
                matrix += 1
            elif t == "END_MATRIX":
                matrix -= 1
            if aligned and not matrix:
                if t in ("AMP", "ROWSEP"):
                    after_amp = t == "AMP"
                    continue
                if after_amp and tok.value.startswith(("\\quad", "\\qquad")):
                    after_amp = False
                    continue
            after_amp = False
            yield tok


@cache
def parser() -> lark.Lark:
    """The lark LALR(1) parser of ``grammar.lark`` (built once per process)."""
    text = resources.files("rigidsym.latex").joinpath("grammar.lark").read_text("utf-8")
    return lark.Lark(text, parser="lalr", lexer="contextual", postlex=_AlignedLayout(),
                     propagate_positions=False, maybe_placeholders=False)


# --------------------------------------------------------------------------- shapes
def _shape(x) -> tuple[int, int] | None:
    """``(rows, cols)`` of a matrix expression, ``None`` for a scalar."""
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        return int(x.shape[0]), int(x.shape[1])
    return None


def _as_scalar(x):
    """A 1 x 1 matrix as its entry (the book's ``e^T d`` is a scalar)."""
    s = _shape(x)
    if s == (1, 1):  # lazily: indexing a symbolic product builds a sum (slow)
        return x[0, 0] if isinstance(x, sp.MatrixBase) else sp.Trace(x)
    return x


def _words(x) -> str:
    s = _shape(x)
    return "a scalar" if s is None else f"a {s[0]}x{s[1]} matrix"


_TIME = sp.Symbol("t", real=True)  # the plain letter t: time, the argument of p(t)


class _Build(lark.Transformer):
    """Tree -> sympy, in the declaration vocabulary (see the module docstring)."""

    def __init__(self, section: str, overrides: dict, block_rows: bool):
        super().__init__()
        self.section, self.overrides, self.block_rows = section, overrides, block_rows
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
        return ("sub", "".join(str(i) for i in items))

    def times(self, _):
        return "\\times "

    def slash(self, _):
        return "/"

    def calsub(self, items):
        return "\\mathcal{" + str(items[0]) + "}" + (str(items[1]) if len(items) > 1 else "")

    def _key(self, base, rest, accent=None) -> str:
        kind, letter = base
        core = {"bold": f"\\mathbf{{{letter}}}" if not letter.startswith("\\")
                else f"\\boldsymbol{{{letter}}}",
                "plain": letter, "zero": "\\mathbf{0}", "one": "\\mathbf{1}"}[kind]
        if accent:
            core = f"{accent}{{{core}}}"
        for r in rest:
            if isinstance(r, tuple):
                core += "_{" + r[1] + "}"
            else:
                core += str(r)
        return core

    def glyph(self, items):
        return self._resolve(items[0], items[1:], None)

    def accented(self, items):
        accent, inner = str(items[0]), items[1]
        if not isinstance(inner, _GlyphKey):
            raise LatexError(f"{accent} over an expression: expected a glyph", "accent")
        base, rest = inner.base, list(inner.rest) + list(items[2:])
        self.glyphs.pop(inner.key, None)  # only the accented glyph is a symbol here
        return self._resolve(base, rest, (inner.accent or "") + accent if inner.accent
                             else accent, inner)

    def arrow(self, items):
        key = f"\\overrightarrow{{{items[0]}}}"
        return self._symbol(key, None)

    def _resolve(self, base, rest, accent, inner=None):
        if inner is not None:  # an accent over a glyph that has its own sub/primes
            key = f"{accent}{{{inner.key}}}" + "".join(
                "_{" + r[1] + "}" if isinstance(r, tuple) else str(r)
                for r in rest[len(inner.rest):])
        else:
            key = self._key(base, rest, accent)
        kind = base[0]
        if kind == "zero":
            return _GlyphKey(key, base, rest, accent, sp.ZeroMatrix(3, 1))
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
        return _GlyphKey(key, base, rest, accent, self._symbol(key, base))

    def _symbol(self, key, base):
        g = self.overrides.get(key) or lookup(key, self.section)
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
        return _value(x)

    def sized(self, items):
        x = items[1]
        if self.block_rows and "[" in str(items[0]):
            return self._block_row(x)
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
        a, b = _fit(a, b, op)
        r = a + b if op == "add" else a - b
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

    def cross(self, items):
        a, b = (_value(i) for i in items)
        if _shape(a) != (3, 1) or _shape(b) != (3, 1):
            raise LatexError(f"\\times between {_words(a)} and {_words(b)}: expected two "
                             f"3-vectors", "shapes")
        return Cross(a, b)

    def dot(self, items):
        a, b = (_value(i) for i in items)
        if _shape(a) is None or _shape(b) is None:
            return _product(a, b)
        if _shape(a) != _shape(b) or _shape(a)[1] != 1:
            raise LatexError(f"\\cdot between {_words(a)} and {_words(b)}: expected two "
                             f"vectors of one size", "shapes")
        return _as_scalar(a.T * b)

    def power(self, items):
        x, sup = _value(items[0]), items[1]
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
        return str(items[0])

    def norm(self, items):
        x = _value(items[0])
        if _shape(x) is None or _shape(x)[1] != 1:
            raise LatexError(f"\\|...\\| of {_words(x)}: expected a vector", "shapes")
        return sp.sqrt(_as_scalar(x.T * x))

    def func(self, items):
        name, x = str(items[0]), _value(items[1])
        x = _as_scalar(x) if "det" not in name else x
        fn = name.split("{")[-1].rstrip("}").lstrip("\\")
        if fn in ("sin", "cos", "tan"):
            return getattr(sp, fn)(x)
        if fn == "arctan":
            return sp.atan(x)
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
            g = lookup(f"[{key}]_{{\\mathcal{{{frame}}}}}", self.section)
            name = g.name if g else f"{s.name}_{frame}"
            swap[s] = sp.MatrixSymbol(name, *s.shape)
        return x.xreplace(swap)

    def underbrace(self, items):
        body, label = _value(items[0]), _value(items[1])
        self.braces.append((label, body))
        return _Brace(body)

    def matrix(self, items):
        rows = [r for r in items if isinstance(r, list)]
        cells = _fit_blocks([[_as_block(c) for c in row] for row in rows])
        try:
            return sp.BlockMatrix(cells) if any(len(r) > 1 for r in cells) or len(cells) > 1 \
                else cells[0][0]
        except ValueError as exc:
            raise LatexError(f"a matrix whose blocks do not fit: {exc}", "shapes") from exc

    def row(self, items):
        return [_value(i) for i in items if not isinstance(i, lark.Token)]

    # ---- relations
    def chain(self, items):
        exprs = [_value(i) for i in items if not isinstance(i, lark.Token)]
        ops = ["equiv" if "equiv" in str(t) else "=" for t in items
               if isinstance(t, lark.Token) and t.type == "RELOP"]
        return ("chain", exprs, ops)

    def start(self, items):
        for t in items:
            if isinstance(t, lark.Token):  # "\\text{for } phi \\neq 0": a side condition
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


def _default_glyph(key: str, base) -> Glyph:
    """A glyph the table does not list: bold lower-case a 3-vector, bold capital a 3x3
    matrix, anything else a scalar; named after its LaTeX."""
    shape: tuple = ()
    if base and base[0] == "bold":
        letter = base[1].lstrip("\\")
        shape = (3, 3) if letter[0].isupper() else (3, 1)
    return Glyph(key, "*", _name_from_key(key), shape, "free", "(not in the glyph table)", "")


def _name_from_key(key: str) -> str:
    import re

    s = re.sub(r"\\(mathbf|boldsymbol|mathcal)\{([^}]*)\}", r"\2", key)
    s = re.sub(r"\\(dot|ddot|tilde|hat|bar)\{([^}]*)\}", lambda m: m.group(2) + m.group(1), s)
    s = s.replace("\\", "").replace("{", "").replace("}", "")
    return s


def _fit(a, b, op):
    a, b = _as_scalar(a), _as_scalar(b)
    if _shape(a) != _shape(b):
        if _shape(a) is None and a == 0:
            return sp.ZeroMatrix(*_shape(b)), b
        if _shape(b) is None and b == 0:
            return a, sp.ZeroMatrix(*_shape(a))
        word = "sum" if op == "add" else "difference"
        raise LatexError(f"a {word} of {_words(a)} and {_words(b)}: shapes do not fit",
                         "shapes")
    return a, b


def _product(a, b):
    sa, sb = _shape(a), _shape(b)
    if sa is None or sb is None:
        return a * b
    if sa[1] == sb[0]:
        r = a * b
        return r
    if sa == (1, 1):
        return _as_scalar(a) * b
    if sb == (1, 1):
        return a * _as_scalar(b)
    raise LatexError(f"juxtaposition of {_words(a)} and {_words(b)}: no product fits "
                     f"(declare the shapes, e.g. with the glyph table)", "shapes")


def _as_block(c):
    if _shape(c) is None:
        return sp.ImmutableMatrix([[c]])
    return c


def _fit_blocks(cells: list[list]) -> list[list]:
    """Size the zero and identity blocks (``\\mathbf{O}``, ``\\mathbf{0}``, ``\\mathbf{1}``)
    from the other blocks of their row and column: the book writes them unsized."""
    def loose(c):
        return isinstance(c, sp.ZeroMatrix | sp.Identity)

    def first(sizes):  # a sized block, else an identity's (square) size
        sizes = list(sizes)
        return next((n for n, c in sizes if not loose(c)),
                    next((n for n, c in sizes if isinstance(c, sp.Identity)), None))

    heights = [first((_shape(c)[0], c) for c in row) for row in cells]
    ncol = max(len(r) for r in cells)
    widths = [first((_shape(r[j])[1], r[j]) for r in cells if j < len(r))
              for j in range(ncol)]
    out = []
    for i, row in enumerate(cells):
        new = []
        for j, c in enumerate(row):
            if loose(c) and heights[i] and widths[j] and _shape(c) != (heights[i], widths[j]):
                if isinstance(c, sp.Identity) and heights[i] != widths[j]:
                    raise LatexError("an identity block that is not square", "shapes")
                c = (sp.ZeroMatrix(heights[i], widths[j]) if isinstance(c, sp.ZeroMatrix)
                     else sp.Identity(heights[i]))
            new.append(c)
        out.append(new)
    return out


def _caret(text: str, pos: int) -> str:
    return f"  {text}\n  {' ' * pos}^"


def parse_latex(latex: str, section: str = "*", overrides: dict | None = None,
                block_rows: bool = False) -> Parsed:
    """Parse a LaTeX statement into relations of book symbols.

    Args:
        latex: the LaTeX (one or more relations separated by ``,``, ``\\quad`` or
            ``\\text{or}``; ``=``/``\\equiv`` chains; ``aligned`` blocks).
        section: the book section whose glyph-table rows name the glyphs (``"3.4.2"``);
            ``"*"``: only the section-free rows.
        overrides: glyph rows by LaTeX key that take precedence (a per-id note's).
        block_rows: read a bracket ``[A v]`` whose column separator was lost (the
            conversion's slip in (3.77b-d), (3.97a-c)) as a block row.

    Returns:
        A :class:`Parsed`.

    Raises:
        LatexError: unparseable LaTeX (position, caret, expected constructs), an unknown
            macro (named) or shapes that do not fit.
    """
    if not isinstance(latex, str) or not latex.strip():
        raise LatexError(f"latex: expected a non-empty LaTeX string, got {latex!r}")
    try:
        tree = parser().parse(latex)
    except lark.UnexpectedCharacters as exc:
        pos = exc.pos_in_stream
        rest = latex[pos:]
        if rest.startswith("\\"):
            macro = "\\" + "".join(ch for ch in rest[1:].split("{")[0].split(" ")[0]
                                   if ch.isalpha())
            raise LatexError(f"unknown macro {macro} at position {pos}:\n"
                             f"{_caret(latex, pos)}", f"unknown macro {macro}") from None
        raise LatexError(f"unexpected {rest[:1]!r} at position {pos}:\n{_caret(latex, pos)}",
                         "syntax") from None
    except lark.UnexpectedToken as exc:
        pos = exc.token.start_pos if exc.token.start_pos is not None else len(latex)
        expected = ", ".join(sorted(exc.expected)[:8])
        what = "the end" if exc.token.type == "$END" else repr(str(exc.token))
        raise LatexError(f"unexpected {what} at position {pos}:\n{_caret(latex, pos)}\n"
                         f"  expected one of: {expected}", "syntax") from None
    except lark.UnexpectedEOF as exc:
        raise LatexError(f"unexpected end of input; expected one of: "
                         f"{', '.join(sorted(exc.expected)[:8])}", "syntax") from None
    build = _Build(section, overrides or {}, block_rows)
    build.braces = []
    try:
        stmts = build.transform(tree)
    except lark.exceptions.VisitError as exc:
        if isinstance(exc.orig_exc, LatexError):
            raise exc.orig_exc from None
        raise LatexError(f"cannot read {latex!r}: {exc.orig_exc}", "shapes") from None
    out = Parsed(readings=build.readings, glyphs=build.glyphs)
    for st in stmts:
        _, exprs, ops = st
        exprs = [_as_scalar(_value(e)) for e in exprs]
        sized = next((_shape(e) for e in exprs if _shape(e)
                      and not isinstance(e, sp.ZeroMatrix)), None)
        exprs = [sp.ZeroMatrix(*sized) if isinstance(e, sp.ZeroMatrix) and sized else e
                 for e in exprs]  # "= \mathbf{0}": the zero of the other side's shape
        out.chains.append(exprs)
        out.ops.append(ops)
    for label, body in build.braces:  # an underbrace whose label is a symbol: a member
        if isinstance(label, sp.Symbol | sp.MatrixSymbol):
            out.chains.append([label, _as_scalar(body)])
            out.ops.append(["="])
            out.readings.append(f"underbrace: {label} is a member of its own")
    for c, exprs in enumerate(out.chains):
        for k in range(len(exprs) - 1):
            out.relations.append(Relation(exprs[k], exprs[k + 1], out.ops[c][k], c, k))
    return out
