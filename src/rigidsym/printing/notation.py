"""Book notation for people: sympy printers that write ``e·ω``, ``‖ω‖``, ``Eᵀ``, ``ṗ⊥``.

Declarations name atoms in ASCII (``omega``, ``e_dot``, ``norm_omega``, ``pdot_perp``,
``Trace(e.T*omega)`` for a dot product). These printers subclass sympy's ``StrPrinter``
and ``LatexPrinter`` (``_print_<Class>`` methods, no string surgery on the output) so that
``rigidsym show`` and the reports read as the book does.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.printing.latex import LatexPrinter
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

__all__ = ["is_negative_term", "book_group", "book_text", "book_latex", "text", "latex",
           "latex_relation",
           "BookStrPrinter", "BookLatexPrinter"]

_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "lam": "λ",
    "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "upsilon": "υ", "phi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π",
    "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
}
_ACCENTS = ("ddot", "dot", "tilde", "hat", "bar")
_COMBINING = {"dot": "\u0307", "ddot": "\u0308", "tilde": "\u0303", "hat": "\u0302",
              "bar": "\u0304"}
_SUB_TEXT = {"par": "∥", "perp": "⊥"}
_SUB_LATEX = {"par": r"\parallel", "perp": r"\perp"}
_SUBSCRIPT_DIGITS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
#: a declaration module's private prefix on atom names (``s34_adot``, ``sec342_vdot``)
_PRIVATE = re.compile(r"^(?:s|sec|ex)\d{2,}_")


def _parse(name: str) -> tuple[str, list[str], list[str], str]:
    """Split an ASCII atom name into (base, accents, subscripts, primes)."""
    name = _PRIVATE.sub("", name)
    primes = ""
    while name.endswith("'"):
        primes, name = primes + "'", name[:-1]
    tokens = [t for t in name.split("_") if t]
    while len(tokens) > 1 and tokens[-1] == "prime":
        primes, tokens = primes + "'", tokens[:-1]
    if not tokens:
        return name, [], [], primes
    base, rest = tokens[0], tokens[1:]
    accents: list[str] = []
    if base.startswith("norm") and len(base) > 4 and not rest:
        base = base[4:]
    m = re.fullmatch(r"([A-Za-z]+?)(\d{3,})", base)  # an equation tag (Fdot394): dropped
    if m:
        base = m.group(1)
    stripped = True
    while stripped:  # trailing accents glued to the base: adot, Ntildedot, u0dot
        stripped = False
        for acc in _ACCENTS:
            stem = base[:-len(acc)]
            if base.endswith(acc) and (stem in _GREEK or len(stem) == 1
                                       or re.fullmatch(r"[A-Za-z]+\d{1,2}|[A-Za-z]+(tilde|dot)",
                                                       stem)):
                base, accents = stem, [acc] + accents
                stripped = True
                break
    m = re.fullmatch(r"([A-Za-z]+?)(\d{1,2})", base)  # mu1, r0, u0: a subscript digit
    if m:
        base, rest = m.group(1), [m.group(2)] + rest
    subs = []
    for t in rest:
        if t in _ACCENTS:
            accents.append(t)
        else:
            subs.append(t)
    return base, accents, subs, primes


def book_text(name: str) -> str:
    """An atom's name in book notation as plain Unicode text.

    ``"omega" -> "ω"``, ``"e_dot" -> "ė"``, ``"pdot_perp" -> "ṗ⊥"``, ``"norm_omega" ->
    "‖ω‖"``, ``"s34_adot_1" -> "ȧ₁"`` (a module's private prefix dropped).
    """
    if name.startswith("norm_"):
        return f"‖{book_text(name[5:])}‖"
    base, accents, subs, primes = _parse(name)
    out = _GREEK.get(base, base)
    if len(out) == 1:
        out += "".join(_COMBINING[a] for a in accents)
    else:
        out += "".join("_" + a for a in accents)
    out += primes
    for s in subs:
        if s in _SUB_TEXT:
            out += _SUB_TEXT[s]
        elif s.isdigit():
            out += s.translate(_SUBSCRIPT_DIGITS)
        else:
            out += "_" + s
    return out


def book_group(name: str) -> str:
    """The book name of the vector or matrix an entry atom belongs to (``"s38_mu1"`` ->
    ``"μ"``, ``"e_1"`` -> ``"e"``, ``"Q_12"`` -> ``"Q"``)."""
    name = _PRIVATE.sub("", name)
    if re.search(r"_\d+$", name):
        return book_text(re.sub(r"_\d+$", "", name))
    return book_text(re.sub(r"(?<=[A-Za-z])\d+$", "", name))


def book_latex(name: str, bold: bool = False) -> str:
    """An atom's name in book notation as LaTeX (bold for vectors and matrices).

    ``book_latex("omega", bold=True) == r"\\boldsymbol{\\omega}"``,
    ``book_latex("pdot_perp", True) == r"\\dot{\\mathbf{p}}_{\\perp}"``.
    """
    if name.startswith("norm_"):
        return rf"\|{book_latex(name[5:], bold=True)}\|"
    base, accents, subs, primes = _parse(name)
    if base in _GREEK:
        core = "\\" + ("lambda" if base == "lam" else base)
        core = rf"\boldsymbol{{{core}}}" if bold else core
    elif len(base) == 1:
        core = rf"\mathbf{{{base}}}" if bold else base
    else:
        core = rf"\mathrm{{{base}}}"
    for a in accents:
        core = rf"\{a}{{{core}}}"
    core += primes
    if subs:
        core += "_{" + ",".join(_SUB_LATEX.get(s, s) for s in subs) + "}"
    return core


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


class BookStrPrinter(StrPrinter):
    """Plain-text printer in book notation (one line; products by juxtaposition)."""

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
        return "O"

    def _print_Transpose(self, expr):
        return self.parenthesize(expr.arg, PRECEDENCE["Pow"], strict=True) + "ᵀ"

    def _dot(self, a, b) -> str:
        return f"({self._print(a)}·{self._print(b)})"

    def _print_Trace(self, expr):
        d = _dot_operands(expr)
        return self._dot(*d) if d else f"tr({self._print(expr.arg)})"

    def _print_MatrixElement(self, expr):
        d = _dot_operands(expr)
        if d:
            return self._dot(*d)
        parent, i, j = expr.parent, expr.i, expr.j
        if isinstance(parent, sp.MatrixSymbol) and i.is_Integer and j.is_Integer:
            sub = str(i + 1) if parent.shape[1] == 1 else f"{i + 1}{j + 1}"  # book: 1-based
            return book_text(parent.name) + sub.translate(_SUBSCRIPT_DIGITS)
        return super()._print_MatrixElement(expr)

    def _print_Pi(self, expr):
        return "π"

    def _factor(self, x) -> str:
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

    def _print_MatAdd(self, expr):
        out = []
        # positive terms first: M_A - M_C, p - a (sympy's order gives -M_C + M_A)
        for i, t in enumerate(sorted(expr.args, key=is_negative_term)):
            neg = is_negative_term(t)
            s = self._print(-t if neg else t)
            out.append(("-" if neg else "") + s if i == 0 else (" - " if neg else " + ") + s)
        return "".join(out)

    def _print_Function(self, expr):
        if isinstance(expr, AppliedUndef):
            return book_text(expr.func.__name__)
        if isinstance(expr, sp.sin | sp.cos | sp.tan) and expr.args[0].is_Atom:
            return f"{expr.func.__name__} {self._print(expr.args[0])}"  # the book's cos φ
        return super()._print_Function(expr)

    def _print_Pow(self, expr, rational=False):
        b, e = expr.base, expr.exp
        if e == sp.S.Half:
            return f"√({self._print(b)})" if precedence(b) < PRECEDENCE["Atom"] else \
                f"√{self._print(b)}"
        if e.is_Integer and e > 0:
            return self.parenthesize(b, PRECEDENCE["Pow"], strict=True) + \
                str(e).translate(_SUPERSCRIPT)
        if e == -1:
            return "1/" + self.parenthesize(b, PRECEDENCE["Mul"])
        if e.is_Rational and e.is_negative:
            return "1/" + self._print(sp.Pow(b, -e, evaluate=False))
        return super()._print_Pow(expr, rational)

    def _print_MatPow(self, expr):
        e = expr.exp
        if e.is_Integer:
            return self.parenthesize(expr.base, PRECEDENCE["Pow"], strict=True) + \
                str(e).translate(_SUPERSCRIPT)
        return super()._print_MatPow(expr)

    def _print_Inverse(self, expr):
        return self.parenthesize(expr.arg, PRECEDENCE["Pow"], strict=True) + "⁻¹"

    def _print_Cross(self, expr):
        # the derivations' Cross(u, v) matrix expression (sympy's own _print_Cross is for
        # sympy.vector and would read attributes this class does not have)
        u, v = expr.args
        return f"{self._factor(u)} × {self._factor(v)}"

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


class BookLatexPrinter(LatexPrinter):
    """LaTeX printer in book notation: bold vectors and matrices, ``\\cdot`` for a dot
    product, ``\\|ω\\|`` for a norm, ``\\mathbf{1}``/``\\mathbf{O}``."""

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
        return r"\mathbf{O}"

    def _dot(self, a, b) -> str:
        return rf"\left({self._print(a)} \cdot {self._print(b)}\right)"

    def _print_Trace(self, expr):
        d = _dot_operands(expr)
        return self._dot(*d) if d else rf"\mathrm{{tr}}\left({self._print(expr.arg)}\right)"

    def _print_MatrixElement(self, expr):
        d = _dot_operands(expr)
        if d:
            return self._dot(*d)
        parent, i, j = expr.parent, expr.i, expr.j
        if isinstance(parent, sp.MatrixSymbol) and i.is_Integer and j.is_Integer:
            sub = str(i + 1) if parent.shape[1] == 1 else f"{i + 1}{j + 1}"  # book: 1-based
            return f"{book_latex(parent.name)}_{{{sub}}}"
        return super()._print_MatrixElement(expr)

    def _print_MatMul(self, expr):
        d = _dot_operands(expr)
        return self._dot(*d) if d else super()._print_MatMul(expr)

    def _print_MatAdd(self, expr):
        out = []
        # positive terms first: M_A - M_C, p - a (sympy's order gives -M_C + M_A)
        for i, t in enumerate(sorted(expr.args, key=is_negative_term)):
            neg = is_negative_term(t)
            s = self._print(-t if neg else t)
            out.append(("-" if neg else "") + s if i == 0 else (" - " if neg else " + ") + s)
        return "".join(out)

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
