"""Book notation for people: sympy printers that write ``e·ω``, ``‖ω‖``, ``Eᵀ``, ``ṗ⊥``.

Declarations name atoms in ASCII (``omega``, ``e_dot``, ``norm_omega``, ``pdot_perp``,
``Trace(e.T*omega)`` for a dot product). These printers subclass sympy's ``StrPrinter``
and ``LatexPrinter`` (``_print_<Class>`` methods, no string surgery on the output) so that
``rigidsym show`` and the reports read as the book does. Atom names in book notation come
from :mod:`rigidsym.printing.names`.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.printing.latex import LatexPrinter
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from rigidsym.printing.names import (
    SUBSCRIPT_DIGITS,
    SUPERSCRIPT,
    book_group,
    book_latex,
    book_text,
    has_subscript,
)

__all__ = ["is_negative_term", "bare_operand", "book_group", "book_text", "book_latex", "text",
           "latex",
           "latex_relation",
           "BookStrPrinter", "BookLatexPrinter"]

def _is_vector(x) -> bool:
    return getattr(x, "shape", None) is not None and len(x.shape) == 2 and x.shape[1] == 1


def is_negative_term(t) -> bool:
    """Whether a term of a sum prints with a leading minus (a matrix product's scalar too)."""
    if isinstance(t, sp.MatMul):
        c = sp.Mul(*[a for a in t.args if not isinstance(a, sp.MatrixExpr | sp.MatrixBase)])
        return bool(c.could_extract_minus_sign())
    return bool(t.could_extract_minus_sign())


def _dot_operands(x):
    """``(a, b)`` when ``x`` is the dot product ``a·b`` written ``a^T b`` (in a trace, an
    element [0, 0] or bare 1 x 1), else ``None``."""
    if isinstance(x, sp.Trace | MatrixElement):
        x = x.args[0]
    if isinstance(x, sp.MatMul):
        mats = [a for a in x.args if isinstance(a, sp.MatrixExpr)]
        if (len(mats) == 2 and len(x.args) == 2 and isinstance(mats[0], sp.Transpose)
                and _is_vector(mats[0].arg) and _is_vector(mats[1])):
            return mats[0].arg, mats[1]
    return None


def _is_cross(x) -> bool:
    """``x`` is the derivations' cross product (× binds like a product, and is no atom)."""
    return type(x).__name__ == "Cross" and isinstance(x, sp.MatrixExpr)



def bare_operand(x):
    """What ``x`` prints as, for its parentheses: the argument of a 1 x 1 trace that is no
    dot product (the printers write the reader's 1 x 1 product or sum as the scalar it is,
    without ``tr``), so ``(θ̇·θ + θ·θ̇)/(2 √(θ·θ))`` keeps the sum's parentheses; else ``x``."""
    if isinstance(x, sp.Trace) and tuple(x.arg.shape) == (1, 1) and not _dot_operands(x):
        return x.arg
    return x


def _one_group(text: str) -> bool:
    """``text`` is one parenthesised group (``(a·a)``, not ``(a) (b)``)."""
    if not (text.startswith("(") and text.endswith(")")):
        return False
    depth = 0
    for i, ch in enumerate(text):
        depth += (ch == "(") - (ch == ")")
        if depth == 0 and i < len(text) - 1:
            return False
    return True

class _BookNotation:
    """What the text and LaTeX printers share: a dot product written ``a^T b`` (in a trace
    or an element ``[0, 0]``) prints as ``a·b``, an entry of a book matrix symbol with its
    1-based subscript, a sum with its positive terms first. A printer supplies ``_dot``,
    ``_trace`` and ``_entry``."""

    def _print_Trace(self, expr):
        d = _dot_operands(expr)
        if d:
            return self._dot(*d)
        if tuple(expr.arg.shape) == (1, 1):  # a reader's 1×1 product: the scalar as written
            return self._print(expr.arg)     # (aᵀ CPM(b) a, not tr(aᵀ CPM(b) a))
        return self._trace(expr.arg)

    def _print_MatrixElement(self, expr):
        d = _dot_operands(expr)
        if d:
            return self._dot(*d)
        parent, i, j = expr.parent, expr.i, expr.j
        if isinstance(parent, sp.MatrixSymbol) and i.is_Integer and j.is_Integer:
            sub = str(i + 1) if parent.shape[1] == 1 else f"{i + 1}{j + 1}"  # book: 1-based
            return self._entry(parent.name, sub)
        return super()._print_MatrixElement(expr)

    def _print_MatrixSlice(self, expr):
        # an aligned block of a partitioned matrix in block notation, [M_A - M_C]₁₂ for
        # (M_A - M_C)[:3, 3:]: no Python slice reaches a reader
        sub = _block_index(expr)
        if sub is None:
            return super()._print_MatrixSlice(expr)
        return self._block(self._print(expr.parent), sub)

    def _print_MatAdd(self, expr):
        out = []
        # positive terms first: M_A - M_C, p - a (sympy's order gives -M_C + M_A)
        for i, t in enumerate(sorted(expr.args, key=is_negative_term)):
            neg = is_negative_term(t)
            s = self._print(-t if neg else t)
            out.append(("-" if neg else "") + s if i == 0 else (" - " if neg else " + ") + s)
        return "".join(out)


def _block_index(x) -> str | None:
    """``"12"`` for the block (1, 2) of equal square-or-column blocks that a slice
    ``x`` is (``"1"`` for a block of a column), ``None`` for any other slice."""
    (r0, r1, rs), (c0, c1, cs) = x.rowslice, x.colslice
    rows, cols = (int(n) for n in x.parent.shape)
    h, w = int(r1 - r0), int(c1 - c0)
    if rs != 1 or cs != 1 or h <= 0 or w <= 0 or r0 % h or c0 % w or rows % h or cols % w:
        return None
    if (rows, cols) == (h, w):
        return None
    i, j = int(r0) // h + 1, int(c0) // w + 1
    return str(i) if cols == w == 1 else f"{i}{j}"


class BookStrPrinter(_BookNotation, StrPrinter):
    """Plain-text printer in book notation (one line; products by juxtaposition)."""

    def parenthesize(self, item, level, strict=False):
        return super().parenthesize(bare_operand(item), level, strict)

    def _print_Symbol(self, expr):
        return book_text(expr.name)

    _print_MatrixSymbol = _print_Symbol

    def _print_Derivative(self, expr):
        base = expr.expr
        if isinstance(base, AppliedUndef) and len(expr.variables) <= 2:
            acc = "_dot" if len(expr.variables) == 1 else "_ddot"
            return book_text(base.func.__name__ + acc)
        return super()._print_Derivative(expr)

    def _print_Identity(self, expr):
        return "𝟏"  # bold, as the book: a plain 1 would read as a scalar

    def _print_ZeroMatrix(self, expr):
        r, c = expr.shape  # the book's O₃₄, O₄₃ (3.80b, 3.92) beside its square O
        return "O" if r == c or 1 in (r, c) else f"O{r}{c}".translate(SUBSCRIPT_DIGITS)

    def _print_Transpose(self, expr):
        if _is_cross(expr.arg):  # (a × b)ᵀ, not a × bᵀ
            return f"({self._print(expr.arg)})ᵀ"
        return self.parenthesize(expr.arg, PRECEDENCE["Pow"], strict=True) + "ᵀ"

    def _dot(self, a, b) -> str:
        a, b = (f"({self._print(x)})" if type(x).__name__ == "Cross" else self._print(x)
                for x in (a, b))  # (a × b)·a, not a × b·a
        return f"({a}·{b})"

    def _trace(self, arg) -> str:
        return f"tr({self._print(arg)})"

    def _entry(self, name: str, sub: str) -> str:
        head = f"({book_text(name)})" if has_subscript(name) else book_text(name)
        return head + sub.translate(SUBSCRIPT_DIGITS)  # (M_A)₁₂: one subscript per letter

    def _block(self, parent: str, sub: str) -> str:
        return f"[{parent}]{sub.translate(SUBSCRIPT_DIGITS)}"

    def _print_Pi(self, expr):
        return "π"

    def _factor(self, x) -> str:
        if _is_cross(x):  # R (a × b), not R a × b
            return f"({self._print(x)})"
        return self.parenthesize(x, PRECEDENCE["Mul"], strict=True)

    def _print_Mul(self, expr):
        coeff, rest = expr.as_coeff_Mul()
        sign = ""
        if coeff.is_negative:
            sign, coeff = "-", -coeff
        num, den = [], []
        for f in sp.Mul.make_args(rest):
            if f.is_Pow and f.exp.is_Rational and f.exp.is_negative:
                den.append(f.base if f.exp == -1 else sp.Pow(f.base, -f.exp, evaluate=False))
            elif f != 1:
                num.append(f)
        if coeff.is_Rational:
            n_s = [str(coeff.p)] if coeff.p != 1 else []
            d_s = [str(coeff.q)] if coeff.q != 1 else []
        else:
            n_s, d_s = [self._factor(coeff)], []
        n_s += [self._factor(f) for f in num]
        d_s += [self.parenthesize(f, PRECEDENCE["Mul"]) for f in den]
        out = " ".join(n_s) or "1"
        if d_s:
            out += "/" + (d_s[0] if len(d_s) == 1 else "(" + " ".join(d_s) + ")")
        return sign + out

    def _print_MatMul(self, expr):
        scal = [a for a in expr.args if not isinstance(a, sp.MatrixExpr | sp.MatrixBase)]
        mats = [a for a in expr.args if isinstance(a, sp.MatrixExpr | sp.MatrixBase)]
        d = _dot_operands(sp.MatMul(*mats)) if len(mats) == 2 else None
        body = [self._dot(*d)] if d else [self._factor(m) for m in mats]
        sign, head, den = "", [], ""
        if scal:
            c = sp.Mul(*scal)
            if c.could_extract_minus_sign():
                sign, c = "-", -c
            n, q = sp.fraction(c)
            if n != 1:
                head = [self._factor(n)]
            if q != 1:  # the book writes omega omega^T adot/||omega||^2
                den = "/" + self.parenthesize(q, PRECEDENCE["Mul"])
        return sign + " ".join(head + body) + den

    def _print_Function(self, expr):
        if isinstance(expr, AppliedUndef):
            return book_text(expr.func.__name__)
        if isinstance(expr, sp.sin | sp.cos | sp.tan) and expr.args[0].is_Atom:
            return f"{expr.func.__name__} {self._print(expr.args[0])}"  # the book's cos φ
        return super()._print_Function(expr)

    def _print_Abs(self, expr):
        return f"|{self._print(expr.args[0])}|"  # as the books write it, not Abs(x)

    def _print_Pow(self, expr, rational=False):
        b, e = expr.base, expr.exp
        if e == sp.S.Half:
            # √ binds to an atom only: √(aᵀ Rᵀ R a), never √aᵀ Rᵀ R a
            atom = b.is_Atom or isinstance(b, sp.MatrixSymbol)
            text = self._print(b)
            return f"√{text}" if atom and precedence(b) >= PRECEDENCE["Atom"] \
                or _one_group(text) else f"√({text})"
        if e.is_Integer and e > 0 and isinstance(b, sp.sin | sp.cos | sp.tan) \
                and b.args[0].is_Atom:  # the book's sin² θ: "sin θ²" read as sin(θ²)
            return f"{b.func.__name__}{str(e).translate(SUPERSCRIPT)} {self._print(b.args[0])}"
        if e.is_Integer and e > 0:
            return self.parenthesize(b, PRECEDENCE["Pow"], strict=True) + \
                str(e).translate(SUPERSCRIPT)
        if e == -1:
            return "1/" + self.parenthesize(b, PRECEDENCE["Mul"])
        if e.is_Rational and e.is_negative:
            return "1/" + self._print(sp.Pow(b, -e, evaluate=False))
        return super()._print_Pow(expr, rational)

    def _print_MatPow(self, expr):
        e = expr.exp
        if e.is_Integer:
            return self.parenthesize(expr.base, PRECEDENCE["Pow"], strict=True) + \
                str(e).translate(SUPERSCRIPT)
        return super()._print_MatPow(expr)

    def _print_Inverse(self, expr):
        return self.parenthesize(expr.arg, PRECEDENCE["Pow"], strict=True) + "⁻¹"

    def _print_Cross(self, expr):
        # the derivations' Cross(u, v) matrix expression (sympy's own _print_Cross is for
        # sympy.vector and would read attributes this class does not have)
        # a cross product operand of its own in parentheses: × is not associative, and
        # (a × b) × c and a × (b × c) both printed "a × b × c" before
        u, v = (self._factor(x) if _is_cross(x) else self.parenthesize(
            x, PRECEDENCE["Mul"], strict=False) for x in expr.args)  # (R a) × (R b)
        return f"{u} × {v}"

    def _print_BlockMatrix(self, expr):
        b = expr.blocks
        rows = [", ".join(self._print(b[i, j]) for j in range(b.cols)) for i in range(b.rows)]
        return "[" + "; ".join(rows) + "]"

    def _print_MatrixBase(self, expr):
        rows = [", ".join(self._print(expr[i, j]) for j in range(expr.cols))
                for i in range(expr.rows)]
        return "[" + "; ".join(rows) + "]"

    _print_ImmutableDenseMatrix = _print_MatrixBase
    _print_MutableDenseMatrix = _print_MatrixBase


class BookLatexPrinter(_BookNotation, LatexPrinter):
    """LaTeX printer in book notation: bold vectors and matrices, ``\\cdot`` for a dot
    product, ``\\|ω\\|`` for a norm, ``\\mathbf{1}``/``\\mathbf{O}``."""

    def parenthesize(self, item, level, is_neg=False, strict=False):
        return super().parenthesize(bare_operand(item), level, is_neg, strict)

    def _needs_mul_brackets(self, expr, first=False, last=False) -> bool:
        return super()._needs_mul_brackets(bare_operand(expr), first, last)

    def _print_Symbol(self, expr, style="plain"):
        return book_latex(expr.name, bold=False)

    def _print_MatrixSymbol(self, expr):
        return book_latex(expr.name, bold=True)

    def _print_Function(self, expr, exp=None):
        if isinstance(expr, AppliedUndef):
            s = book_latex(expr.func.__name__)
            return s if exp is None else f"{s}^{{{exp}}}"
        if isinstance(expr, sp.sin | sp.cos | sp.tan) and expr.args[0].is_Atom:
            head = rf"\{expr.func.__name__}" + (f"^{{{exp}}}" if exp is not None else "")
            return f"{head} {self._print(expr.args[0])}"  # the book's \cos \phi
        return super()._print_Function(expr, exp)

    def _print_Derivative(self, expr):
        base = expr.expr
        if isinstance(base, AppliedUndef) and len(expr.variables) <= 2:
            acc = "_dot" if len(expr.variables) == 1 else "_ddot"
            return book_latex(base.func.__name__ + acc)
        return super()._print_Derivative(expr)

    def _print_Identity(self, expr):
        return r"\mathbf{1}"

    def _print_ZeroMatrix(self, expr):
        r, c = expr.shape
        return r"\mathbf{O}" if r == c or 1 in (r, c) else rf"\mathbf{{O}}_{{{r}{c}}}"

    def _dot(self, a, b) -> str:
        a, b = (rf"\left({self._print(x)}\right)" if type(x).__name__ == "Cross" else self._print(x)
                for x in (a, b))
        return rf"\left({a} \cdot {b}\right)"

    def _trace(self, arg) -> str:
        return rf"\mathrm{{tr}}\left({self._print(arg)}\right)"

    def _entry(self, name: str, sub: str) -> str:
        if has_subscript(name):  # I_{C}_{21} is no LaTeX: (\mathbf{I}_{C})_{21}
            return rf"\left({book_latex(name, bold=True)}\right)_{{{sub}}}"
        return f"{book_latex(name)}_{{{sub}}}"

    def _block(self, parent: str, sub: str) -> str:
        return rf"\left[{parent}\right]_{{{sub}}}"

    def _print_MatMul(self, expr):
        d = _dot_operands(expr)
        return self._dot(*d) if d else super()._print_MatMul(expr)

    def _print_Cross(self, expr):  # the derivations' Cross(u, v), not sympy.vector's
        u, v = (self.parenthesize(a, PRECEDENCE["Mul"], strict=True) for a in expr.args)
        return rf"{u} \times {v}"

    def _print_BlockMatrix(self, expr):
        b = expr.blocks
        rows = [" & ".join(self._print(b[i, j]) for j in range(b.cols)) for i in range(b.rows)]
        return r"\begin{bmatrix} " + r" \\ ".join(rows) + r" \end{bmatrix}"


_TEXT = BookStrPrinter()
_LATEX = BookLatexPrinter({"mat_delim": "[", "mat_str": "matrix"})


def text(expr) -> str:
    """``expr`` (sympy) in book notation, one line of Unicode text."""
    return _TEXT.doprint(expr)


def latex(expr) -> str:
    """``expr`` (sympy) in book notation as LaTeX."""
    return _LATEX.doprint(expr)


def latex_relation(lhs, rhs, width: int = 50) -> str:
    """``lhs = rhs`` as LaTeX; a right side wider than ``width`` characters of text is set
    as aligned rows of whole terms (MathML Core does not break lines by itself).

    Args:
        lhs, rhs: sympy expressions.
        width: the width of a row, in characters of the plain-text rendering.

    Returns:
        LaTeX, ``\\begin{aligned}...\\end{aligned}`` when broken into rows.
    """
    head = latex(lhs)
    terms = list(rhs.args) if isinstance(rhs, sp.Add | sp.MatAdd) else [rhs]
    if len(terms) < 2 or len(text(rhs)) <= width:
        return f"{head} = {latex(rhs)}"
    terms.sort(key=is_negative_term)  # as the printers: positive terms first
    rows, row, used = [], [], 0
    for k, t in enumerate(terms):
        neg = is_negative_term(t)
        body = -t if neg else t
        piece = ("- " if neg else ("+ " if k else "")) + _LATEX.parenthesize(
            body, PRECEDENCE["Add"], strict=False)
        n = len(text(body)) + 3
        if row and used + n > width:
            rows.append(" ".join(row))
            row, used = [], 0
        row.append(piece)
        used += n
    rows.append(" ".join(row))
    body = r" \\ &\quad ".join(rows)
    return rf"\begin{{aligned}} {head} &= {body} \end{{aligned}}"
