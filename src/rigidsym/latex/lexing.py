"""The lark side of the LaTeX reader: the LALR(1) parser of ``grammar.lark`` with its
post-lexer (layout inside ``aligned``), and what a parse returns (:class:`Parsed`)."""

from __future__ import annotations

import copy
import re
from dataclasses import dataclass, field
from functools import cache, lru_cache
from importlib import resources

import lark

from rigidsym.latex.rewrites import (
    argument_extents,
    mixed_products,
    multiple_angles,
    subscripts_first,
)

__all__ = ["Relation", "Parsed", "parser", "tree", "braced", "quoted", "bracket_key",
           "named_map_key", "OPERATOR_FONTS", "OPERATOR_NAMES", "operator_word"]

#: the upright fonts an operator's name is written in: ``\\operatorname{vect}``,
#: ``\\mathrm{vect}``, ``\\text{vect}``, ``\\textrm{vect}``, ``\\mbox{vect}`` ... all read as the
#: one operator (the grammar's ``OPNAME``, ``DIAG``, ``ATAN2``, ``CPM`` terminals)
OPERATOR_FONTS = ("operatorname", "operatorname*", "mathrm", "text", "textrm", "textnormal",
                  "textup", "mbox")
#: the operator names the reader knows in those fonts (vect: the axial vector of a matrix's
#: skew part, Angeles' vect(A); tr; det; diag; atan2; CPM: the cross-product matrix)
OPERATOR_NAMES = ("tr", "Tr", "trace", "vect", "det", "diag", "atan2", "Atan2", "CPM")
_OPERATOR_WORD = re.compile(r"\\[A-Za-z]+\*?\s*(?:\{\s*([A-Za-z0-9]+)\s*\})?")


def operator_word(token: str) -> str:
    """An operator token's word: ``\\sin`` -> ``sin``, ``\\text{ vect }`` -> ``vect``,
    ``\\operatorname*{tr}`` -> ``tr`` (any other text as written, stripped)."""
    m = _OPERATOR_WORD.fullmatch(token.strip())
    if not m:
        return token.strip()
    return m.group(1) or m.group(0).strip()[1:]


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
        applied: the non-scalar symbols read as applied to a parenthesised scalar
            (``R(\\theta)``), by LaTeX key: the arguments (``rigidsym.latex.transformer.meanings``).
        choice_points: the symbols ``X`` of ``X(y)`` that no rule reads (a model applied to
            no scalar: a product or an application), by key: the argument.
    """

    chains: list = field(default_factory=list)
    ops: list = field(default_factory=list)
    relations: list = field(default_factory=list)
    readings: list = field(default_factory=list)
    glyphs: dict = field(default_factory=dict)
    applied: dict = field(default_factory=dict)  # R(\theta): key -> arguments (meanings)
    choice_points: dict = field(default_factory=dict)  # X(y) product or application

    def pairs(self):
        """Every pair ``(chain, i, j, E_i, E_j)`` with ``i < j`` of a chain: each is a
        relation the text states (``x = y = z`` states ``x = y``, ``x = z``, ``y = z``)."""
        for c, exprs in enumerate(self.chains):
            for i in range(len(exprs)):
                for j in range(i + 1, len(exprs)):
                    yield c, i, j, exprs[i], exprs[j]


_MACRO = re.compile(r"\\[A-Za-z]+")


class _AlignedLayout:
    """Post-lexer: inside ``aligned`` (outside a matrix) ``&``, ``\\\\`` and a ``\\quad``
    right after ``&`` are layout; drop them (and the environment's delimiters)."""

    always_accept = ("AMP", "ROWSEP", "BEGIN_ALIGNED", "END_ALIGNED")
    text = ""  #: the input being parsed (set by :func:`tree`): where each macro ends

    def process(self, stream):
        aligned = matrix = 0
        after_amp = False
        for tok in stream:
            t = tok.type
            if _MACRO.fullmatch(tok.value) and self.text[tok.end_pos:tok.end_pos + 1].isalpha():
                raise _Glued(tok.start_pos)  # \sinh is no \sin h, \cdots no \cdot s
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


class _Glued(Exception):
    """A grammar literal that is only the start of a longer macro of the input."""

    def __init__(self, pos: int):
        super().__init__(pos)
        self.pos = pos


@cache
def parser() -> lark.Lark:
    """The lark LALR(1) parser of ``grammar.lark`` (built once per process; its LALR
    analysis kept in the user cache, ``<cache root>/latex/``, by lark's own ``cache=``: keyed
    by the grammar's and lark's hash, a stale or unreadable file is rebuilt and rewritten)."""
    from rigidsym.core import cache as _cache

    text = resources.files("rigidsym.latex").joinpath("grammar.lark").read_text("utf-8")
    where = _cache.folder("latex")
    try:
        where.mkdir(parents=True, exist_ok=True)
        kept = {"cache": str(where / "grammar.lark.cache")}
    except OSError:  # a read-only home: build it every time
        kept = {}
    return lark.Lark(text, parser="lalr", lexer="contextual", postlex=_AlignedLayout(),
                     propagate_positions=True, maybe_placeholders=False, **kept)


# ---- the input as TeX reads it, and errors that quote it
# pylatexenc's latexwalker is the tokenizer here: it knows where a macro ends (\cot\frac is
# two macros) and what TeX takes as a macro's argument (\frac\theta2). It runs only where it
# is needed (an unbraced argument, an error): over all 181 strings of the chapter it costs
# 0.19 s, +24 % of the benchmark's parse time, beyond the lexer's 1.2x time budget.
_ARGS = {"frac": 2, "dfrac": 2, "tfrac": 2, "sqrt": 1}
_UNBRACED = re.compile(r"\\[dt]frac(?![A-Za-z])|\\frac(?![A-Za-z])\s*([^\s{]|\{[^{}]*\}\s*[^\s{])"
                       r"|\\sqrt(?![A-Za-z])\s*[^\s{\[]")
_CONSTRUCTS = [
    (re.compile(r"\\(left|right|[bB]igg?[lr]?)$"), "a delimiter"),
    (re.compile(r"\\(alpha|beta|gamma|delta|epsilon|varepsilon|zeta|eta|theta|vartheta|"
                r"iota|kappa|lambda|mu|nu|xi|pi|rho|varrho|sigma|tau|upsilon|phi|varphi|"
                r"chi|psi|omega|Gamma|Delta|Theta|Lambda|Xi|Pi|Sigma|Upsilon|Phi|Psi|"
                r"Omega)$"), "a Greek letter"),
    (re.compile(r"\\(mathbf|boldsymbol|bm|mathcal|mathsf|mathfrak|mathrm|operatorname|text)$"),
     "a font"),
    (re.compile(r"\\(hat|dot|ddot|tilde|bar|vec|underline|check|breve|mathring)$"),
     "an accent"),
    (re.compile(r"\\(sin|cos|tan|cot|sec|csc|arccos|arcsin|arctan|exp|log|ln|det)$"),
     "a function"),
    (re.compile(r"\\[dt]?frac$"), "a fraction"),
    (re.compile(r"\\(begin|end)$"), "an environment"),
    (re.compile(r"\\(wedge|vee|times|cdot|otimes|circ)$"), "a product"),
    (re.compile(r"\\(int|iint|oint|sum|prod)$"), "an integral or sum"),
]


_BRACKET_NAME = re.compile(r"\[\s*(?:(\\(?:mathbf|boldsymbol|bm|bar|hat|tilde|breve|check|mathring)"
                           r"(?![A-Za-z]))\s*)?\{?\s*(\\?[A-Za-z]+)\s*\}?\s*\]"
                           r"\s*_\s*\{?\s*([A-Za-z])\s*\}?")


def bracket_key(token: str) -> str:
    """The one spelling of a bracket name (the grammar's ``BRACKET_NAME``):
    ``[\\mathbf q]_L``, ``[\\boldsymbol{q}]_{L}`` -> ``[\\mathbf{q}]_{L}``; ``[q]_R`` ->
    ``[q]_{R}``."""
    m = _BRACKET_NAME.fullmatch(token.strip())
    if not m:
        return "".join(token.split())
    font, atom, sub = m.groups()
    if font in ("\\mathbf", "\\boldsymbol", "\\bm"):  # as the glyph keys write bold
        font = "\\boldsymbol" if atom.startswith("\\") else "\\mathbf"
    return f"[{font}{{{atom}}}]_{{{sub}}}" if font else f"[{atom}]_{{{sub}}}"


_NAMED_MAP = re.compile(r"\\(?:mathrm|operatorname)\s*\{\s*([A-Za-z](?:[A-Za-z0-9]|\\_)+)\s*\}"
                        r"|\\(exp|log)\s*_\s*\{?\s*(\\?[A-Za-z]+)\s*\}?")


def named_map_key(token: str) -> str:
    """The one spelling of a named map (the grammar's ``NAMED_MAP``): ``\\operatorname{Exp}``,
    ``\\mathrm{ Exp }`` -> ``\\mathrm{Exp}`` (``\\mathrm{vex}`` alike); ``\\exp_q``,
    ``\\exp_{q}`` -> ``\\exp_{q}``."""
    m = _NAMED_MAP.fullmatch(token.strip())
    if not m:
        return "".join(token.split())
    if m.group(1):
        return f"\\mathrm{{{m.group(1)}}}"
    return f"\\{m.group(2)}_{{{m.group(3)}}}"


def braced(latex: str) -> str:
    """The LaTeX with TeX's unbraced macro arguments braced (``\\frac\\theta2`` ->
    ``\\frac{\\theta}{2}``, ``\\sqrt2`` -> ``\\sqrt{2}``; ``\\dfrac``, ``\\tfrac`` ->
    ``\\frac``), as pylatexenc's latexwalker reads each argument; anything else as written."""
    if not _UNBRACED.search(latex):
        return latex
    from pylatexenc.latexwalker import LatexWalker, LatexWalkerError

    w = LatexWalker(latex, tolerant_parsing=False)
    out, pos = [], 0
    try:
        while pos < len(latex):
            tok = w.get_token(pos, environments=False)
            out.append(latex[pos:tok.pos])
            end = tok.pos + tok.len
            if tok.tok == "macro" and tok.arg in _ARGS and not latex[end:].lstrip().startswith(
                    "["):
                args = []
                for _ in range(_ARGS[tok.arg]):
                    _, p, n = w.get_latex_expression(end)
                    text = latex[p:p + n]
                    if text in ("=", "&", "\\\\", "}", ",", "^", "_"):  # no argument there
                        return latex
                    args.append(braced(text[1:-1] if text.startswith("{") else text))
                    end = p + n
                out.append(("\\sqrt" if tok.arg == "sqrt" else "\\frac")
                           + "".join("{" + a + "}" for a in args))
            else:
                out.append(latex[tok.pos:end])
            pos = end
    except LatexWalkerError:  # the end of the input, or LaTeX it cannot read: as written
        out.append(latex[pos:])
    return "".join(out)


def quoted(latex: str, pos: int) -> tuple[str, str]:
    """The token of ``latex`` at ``pos`` as written, with its boundaries (``\\cot``, not
    ``\\cotfrac``; ``\\left\\|``), and the construct it is (``"a delimiter"``, ``""``)."""
    from pylatexenc.latexwalker import LatexWalker, LatexWalkerError

    w = LatexWalker(latex, tolerant_parsing=True)
    try:
        tok = w.get_token(pos, environments=False)
    except LatexWalkerError:
        return latex[pos:pos + 1], ""
    if tok.tok != "macro":
        return latex[tok.pos:tok.pos + max(tok.len, 1)].strip() or latex[pos:pos + 1], ""
    text = "\\" + tok.arg
    if tok.arg in ("left", "right") or re.fullmatch(r"[bB]igg?[lr]?", tok.arg):
        m = re.match(r"\s*(\\[A-Za-z]+|\\.|.)", latex[tok.pos + len(text):])
        text += m.group(1) if m else ""
    if tok.arg in ("operatorname", "mathrm", "text", "mathbf", "boldsymbol", "mathsf",
                   "mathfrak"):
        m = re.match(r"\s*\{[^{}]*\}", latex[tok.pos + len(text):])
        text += m.group(0).strip() if m else ""
    construct = next((c for r, c in _CONSTRUCTS if r.match("\\" + tok.arg)), "a macro")
    return text, construct


def caret(text: str, pos: int, width: int = 1) -> str:
    """The input with carets under ``width`` characters from ``pos``."""
    return f"  {text}\n  {' ' * pos}{'^' * max(width, 1)}"


# \left( ... \right), \bigl( ... \bigr): parentheses TeX only draws taller, read as ( ... ) so
# that R_z\left(\alpha\right) is the application R_z(\alpha) (not a product of a free scalar
# R_z, under which R_z\left(0\right)a = 0 would verify)
_SIZED_PAREN = re.compile(r"(?:\\left|\\[bB]igg?l)\s*\(|(?:\\right|\\[bB]igg?r)\s*\)")


_CHAIN_TOKENS = re.compile(r"\\[{}]|\\\\|\\left\s*\S|\\right\s*\S|\\[a-zA-Z]+"
                           r"|[-+=&,|(){}\[\]]")


def cross_chains(text: str) -> str | None:
    """The first ``a \\times b \\times c``: two cross products in one term with no
    parentheses between them, or ``None``. The cross product is not associative and the
    books mean either grouping (a x (b x c) in the triple product), so such a chain has no
    one reading; lark's grammar would read it from the left, unsaid (so that
    a x b x c = b(a.c) - c(a.b) would come out does-not-hold)."""
    depth, count, start = 0, {}, {}
    for m in _CHAIN_TOKENS.finditer(text):
        tok = m.group(0)
        if tok == "\\times" and not re.match(r"\s*\^", text[m.end():]) \
                and not re.search(r"[_^]\s*\{?\s*$", text[:m.start()]):
            # not v\times^*, [a]_\times, Hughes' a^\times, a^{\times}
            count[depth] = count.get(depth, 0) + 1
            if count[depth] == 2:
                return text[start.get(depth, 0):m.end()].strip() + " ..."
        elif tok in "([{" or tok in ("\\{",) or tok.startswith("\\left"):
            depth += 1
            count[depth], start[depth] = 0, m.end()
        elif tok in ")]}" or tok in ("\\}",) or tok.startswith("\\right"):
            depth = max(depth - 1, 0)  # the group is one operand of the term it closes into
        elif tok in "-+=&,|" or tok == "\\\\":
            count[depth], start[depth] = 0, m.end()
    return None


def parsed_text(latex: str) -> str:
    """The text :func:`tree` parses (unbraced arguments braced, sized parentheses plain):
    a subtree's ``meta.start_pos``/``end_pos`` index it (its source span)."""
    return _SIZED_PAREN.sub(lambda m: m.group(0)[-1], braced(latex))


#: the parse trees :func:`tree` keeps (a check reads each ``--let`` and side about 7 times:
#: for the glyphs' keys, the declarations' graph, each reading and the numeric cross-check)
TREES_KEPT = 512


def tree(latex: str):
    """lark's parse tree of the LaTeX (its unbraced arguments braced, :func:`braced`), or a
    ``LatexError`` that quotes the offending token with its boundaries, puts carets under it
    and names the construct: ``unknown macro \\foo at position 13``, ``unexpected \\theta
    (a Greek letter) at position 9``.

    The tree is a function of the text alone: the last :data:`TREES_KEPT` are kept, and each
    call returns its own copy (a sixth of a parse's time), so that a reader who changes the
    tree changes no other reader's."""
    return copy.deepcopy(_kept_tree(parser(), latex))


@lru_cache(maxsize=TREES_KEPT)
def _kept_tree(grammar: lark.Lark, latex: str):
    """:func:`tree`'s parse by ``grammar`` (:func:`parser`: a new parser, a new key), kept;
    an error is raised again on every call, never kept."""
    from rigidsym.latex.shapes import LatexError

    text = parsed_text(latex)
    chain = cross_chains(text)
    if chain:
        raise LatexError(f"{chain}: two cross products with no parentheses between them; the "
                         f"cross product is not associative, so write (a \\times b) \\times c "
                         f"or a \\times (b \\times c)", "cross chain")
    _AlignedLayout.text = text
    try:
        return argument_extents(
            multiple_angles(subscripts_first(mixed_products(grammar.parse(text)))), text)
    except _Glued as exc:
        token, construct = quoted(text, exc.pos)
        raise LatexError(f"unknown macro {token} at position {exc.pos}:\n"
                         f"{caret(text, exc.pos, len(token))}", f"unknown macro {token}") from None
    except lark.UnexpectedCharacters as exc:
        pos = exc.pos_in_stream
        rest = text[pos:]
        named = re.match(r"\\(operatorname|mathrm|text)\s*\{\s*([^}]*?)\s*\}", rest)
        if named:
            raise LatexError(f"unknown operator {named.group(2)!r} "
                             f"(\\{named.group(1)}{{{named.group(2)}}}) at position {pos}:\n"
                             f"{caret(text, pos, len(named.group(0)))}",
                             f"unknown macro {named.group(0)}") from None
        token, construct = quoted(text, pos)
        if token.startswith("\\"):
            what = f"unknown macro {token}" if construct == "a macro" else \
                f"{token} ({construct}) cannot be read here"
            if construct == "an integral or sum":  # the reason
                what += (": rigidsym decides algebraic identities and does not integrate or "
                         "sum (an integral's closed form is yours to give: name the integral "
                         "and give its value as a --let model, e.g. --let '\\mathbf{J} = "
                         "...')")
            raise LatexError(f"{what} at position {pos}:\n{caret(text, pos, len(token))}",
                             f"unknown macro {token}") from None
        raise LatexError(f"unexpected {rest[:1]!r} at position {pos}:\n{caret(text, pos)}",
                         "syntax") from None
    except lark.UnexpectedToken as exc:
        pos = exc.token.start_pos if exc.token.start_pos is not None else len(text)
        expected = _expected(exc.expected)
        if exc.token.type == "$END":
            what, width = "end of input", 1
        else:
            token, construct = quoted(text, pos)
            token = token if token.startswith("\\") else str(exc.token)
            what = f"{token} ({construct})" if construct else repr(str(exc.token))
            width = len(token)
        raise LatexError(f"unexpected {what} at position {pos}:\n{caret(text, pos, width)}"
                         f"{_expected_line(expected, text[:pos])}"
                         f"{_frame_label_line(text[:pos], str(exc.token))}", "syntax") from None
    except lark.UnexpectedEOF as exc:
        raise LatexError(f"unexpected end of input{_expected_line(_expected(exc.expected), text)}",
                         "syntax") from None


def _expected_line(expected: str, before: str) -> str:
    """What the parser expected, as the message's last line; never an empty list (
    the construct is named instead), with the reason where the text before says it (a
    plain ``e^`` is the exponential)."""
    line = f"\n  expected one of: {expected}" if expected else \
        "\n  (nothing can follow here: the construct before it is complete)"
    if re.search(r"(?<![\\A-Za-z{])e\s*\^\s*$", before):
        line += ("\n  e^ is the exponential e^{...}; for a power of a symbol e, declare it "
                 "(--let 'e: scalar' or its model) and e^2 is its square")
    return line


#: a glyph (or a bracket around one) before ``^{``: Zipfel's ``T^{``, ``[T]^{``
_BEFORE_LABEL = re.compile(r"(\[[^\[\]]*\]|\\(?:mathbf|boldsymbol|bm)\s*(?:\{\s*\\?[A-Za-z]+\s*\}"
                           r"|\\[A-Za-z]+|[A-Za-z])|\\[A-Za-z]+|(?<![\\A-Za-z])[A-Za-z])\s*\^\s*\{\s*$")


def _frame_label_line(before: str, token: str) -> str:
    """Where the parser stops at a superscript of capitals (Zipfel's ``T^{BL}``,
    ``[T]^{BL}``): the line that says it is a frame label, part of a name a ``--let``
    declares, and the ``--let`` to write; else ``""``."""
    m = _BEFORE_LABEL.search(before)
    if not m or not re.fullmatch(r"[A-Z]{2,}", token):
        return ""
    name = f"{''.join(m.group(1).split())}^{{{token}}}"
    letter = re.sub(r"\\(?:mathbf|boldsymbol|bm)|[^A-Za-z]", "", m.group(1))
    kind = "vector" if letter[:1].islower() else "rotation"
    return (f"\n  a superscript of capitals is a frame label (Zipfel's T^{{BL}}, [T]^{{BL}}), "
            f"part of a name that a --let declares: e.g. --let '{name}: {kind}' (or its "
            f"model, --let '{name} = ...')")


_TERMINALS = {"LETTER": "a letter", "GREEK": "a Greek letter", "NUMBER": "a number",
              "RELOP": "= or \\equiv", "BOLD": "\\mathbf", "ACCENT": "an accent",
              "FUNC": "a function (\\sin ...)", "BEGIN_MATRIX": "\\begin{bmatrix}",
              "LEFT_OPEN": "\\left(", "RIGHT_CLOSE": "\\right)", "LEFT_NORM": "\\left\\|",
              "RIGHT_NORM": "\\right\\|", "LEFT_ABS": "\\left|", "RIGHT_ABS": "\\right|",
              "SUBATOM": "a subscript", "SUPTOKEN": "a superscript", "_SEP": ", or \\quad",
              "SUPLABEL": "a superscript label (^S)", "PRIMES": "a prime",
              "SUBRANGE": "a range of entries (1:3)", "SUBSIGN": "+ or -",
              "LEFT_INDEX": "a left index ({}^A)", "BIG_OPEN": "\\bigl(",
              "BIG_CLOSE": "\\bigr)", "TIMES_POST": "\\times", "TIMES_DUAL": "\\times^*",
              "DFRAC": "\\frac{d}{d...}", "EXP_E": "e^", "SUPCONTENT": "a superscript",
              "_ARGS_OPEN": "(", "DECLARE": "a declaration (\\in SO(3))",
              "CONDITION": "\\text{for ...}"}


_FIRST = {"LETTER", "GREEK", "NUMBER", "BOLD", "RELOP", "ACCENT", "FUNC", "SUPTOKEN",
          "SUBATOM", "BEGIN_MATRIX", "_SEP", "LEFT_OPEN", "LEFT_NORM"}


def _expected(names) -> str:
    """What the parser expected, in the LaTeX a reader writes (a literal as written, a
    class of tokens in words), not the grammar's terminal names."""
    out = []
    names = [n for n in names if n not in _AlignedLayout.always_accept] or list(names)
    for n in sorted(names, key=lambda n: (n not in _FIRST, n)):  # the common classes first
        try:
            pattern = parser().get_terminal(n).pattern
        except KeyError:
            pattern = None
        word = _TERMINALS.get(n) or (pattern.value if isinstance(
            pattern, lark.lexer.PatternStr) else None)
        if word and word not in out and word not in ("\\$", "|"):  # rare: said last if ever
            out.append(word)
    return ", ".join(out[:10]) + (" ..." if len(out) > 10 else "")
