"""The ASCII mathematics of running text typeset: Markdown with ``$...$`` LaTeX.

The worked exercises explain their steps in short ASCII sentences, easy to type and to
read in a terminal: ``"cos(phi) = (tr Q - 1)/2."``, ``"The moment is least on the central
axis {f x n_O / ||f||^2 + lambda f}."``. A page that typesets its formulas (the exercises
page, like the chapter report) shows these as mathematics too: :func:`prose_markdown` finds
the runs of mathematics in such a sentence and writes each as inline LaTeX in book notation
(:func:`rigidsym.printing.names.book_latex`), which the page's Markdown converter turns into
MathML; the English words stay text.

What counts as mathematics is read token by token, as :func:`rigidsym.printing.labels
.label_latex` does: a name the book would print as a symbol (one letter, a Greek name, a
name with a subscript or an accent: ``p0``, ``n_O``, ``omega_dot``), a function applied
(``cos(phi)``, ``tr Q``, ``sqrt(3)``), operators between them, and brackets that hold no
English word. The article "a" before an English word stays a word.
"""

from __future__ import annotations

import re

from rigidsym.printing.labels import math_token
from rigidsym.printing.names import book_latex

__all__ = ["prose_markdown", "prose_latex_runs"]

_TOKEN = re.compile(r"""
  (?P<sp>\s+)
| (?P<num>\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)
| (?P<poss>'s\b)
| (?P<word>[A-Za-z][A-Za-z0-9_]*(?:'+(?![A-Za-z])|\*(?![A-Za-z(]))?)
| (?P<op><=|>=|!=|->|<-|-\+|\+-|\|\||\.\.\.|\.\.|[-+*/^_=<>|~.,;:()\[\]{}])
| (?P<other>.)""", re.X | re.S)

#: functions printed upright: LaTeX's own, or as an operator name
_FUNCTIONS = {"cos": r"\cos", "sin": r"\sin", "tan": r"\tan", "exp": r"\exp", "log": r"\log",
              "det": r"\det", "max": r"\max", "min": r"\min", "sum": r"\sum",
              "tr": r"\operatorname{tr}", "vect": r"\operatorname{vect}",
              "CPM": r"\operatorname{CPM}", "diag": r"\operatorname{diag}",
              "atan2": r"\operatorname{atan2}", "acos": r"\arccos", "asin": r"\arcsin",
              "rank": r"\operatorname{rank}", "sqrt": r"\sqrt", "adj": r"\operatorname{adj}",
              "cpm": r"\operatorname{cpm}"}
#: functions also applied without parentheses: ``tr Q``, ``cos phi``, ``sum w_i P_i``
_BARE = {"cos", "sin", "tan", "exp", "log", "det", "tr", "sum", "rank"}
_SYMBOLS = {"eps": r"\epsilon", "dt": r"\mathrm{d}t"}
_OPS = {"<=": r"\le", ">=": r"\ge", "!=": r"\ne", "->": r"\to", "<-": r"\leftarrow",
        "-+": r"\mp", "+-": r"\pm", "||": r"\|", "...": r"\ldots", "..": r"\ldots",
        "{": r"\{", "}": r"\}", "~": r"\sim", "*": r"\,"}
_OPEN, _CLOSE = "([{", ")]}"
#: the operators a formula may start or end with (a sign, a norm's bars, its brackets)
_LEADING = {"-", "||", "|", "(", "[", "{"}
_TRAILING = {"||", "|", ")", "]", "}"}


def _tokens(text: str) -> list[tuple[str, str]]:
    return [(m.lastgroup, m.group()) for m in _TOKEN.finditer(text)]


def _is_symbol(word: str) -> bool:
    core = word.rstrip("'*")
    base = core.split("_", 1)[0]
    return core in _SYMBOLS or math_token(core) or ("_" in core and math_token(base)
                                                    and core[len(base) + 1:].isalnum())


def _next(toks: list[tuple[str, str]], i: int, step: int = 1) -> tuple[str, str] | None:
    j = i + step
    while 0 <= j < len(toks) and toks[j][0] == "sp":
        j += step
    return toks[j] if 0 <= j < len(toks) else None


def _word_kind(toks: list[tuple[str, str]], i: int) -> str:
    """``"F"`` a function applied, ``"M"`` a symbol, ``"P"`` an English word."""
    w = toks[i][1]
    nxt = _next(toks, i)
    applied = nxt is not None and (nxt[1] in ("(", "[", "^") or (
        w in _BARE and nxt[0] == "word" and (_is_symbol(nxt[1]) or nxt[1] in _FUNCTIONS)))
    if w in _FUNCTIONS and applied:
        return "F"
    if w in ("a", "A") and nxt and (nxt[0] == "num" or (
            nxt[0] == "word" and not _is_symbol(nxt[1]) and nxt[1] not in _FUNCTIONS)):
        return "P"   # the article
    return "M" if _is_symbol(w) else "P"


def _kinds(toks: list[tuple[str, str]]) -> list[str]:
    """One kind per token: M symbol, F function, N number, O operator, S space, P prose."""
    kinds = []
    for i, (g, t) in enumerate(toks):
        if g == "word":
            kinds.append(_word_kind(toks, i))
        elif g == "num":
            kinds.append("N")
        elif g == "sp":
            kinds.append("S")
        elif g == "op" and t in ",;:":
            kinds.append("P")   # a list's comma outside brackets: between formulas
        elif g == "op" and t == ".":
            kinds.append("O" if _dot_product(toks, i) else "P")
        elif g == "op":
            kinds.append("O")
        else:
            kinds.append("P")
    _bracket_groups(toks, kinds)
    return kinds


def _operand(tok: tuple[str, str] | None, opening: bool) -> bool:
    if tok is None:
        return False
    g, t = tok
    return (g == "word" and _is_symbol(t)) or g == "num" or t in ("...", "||") or \
        t in ((_OPEN + "|") if opening else (_CLOSE + "|"))


def _dot_product(toks: list[tuple[str, str]], i: int) -> bool:
    """``e.e``, ``a . b``, ``(e_i x e_j).p``: a dot between two operands, not a full stop."""
    before, after = _next(toks, i, -1), _next(toks, i)
    spaced = (i + 1 < len(toks) and toks[i + 1][0] == "sp")
    unspaced_before = i > 0 and toks[i - 1][0] != "sp"
    if spaced and unspaced_before:
        return False   # "... = 1. Then": a full stop
    return _operand(before, opening=False) and _operand(after, opening=True)


def _bracket_groups(toks: list[tuple[str, str]], kinds: list[str]) -> None:
    """Brackets holding an English word are prose (their inside is read on its own); the
    commas inside brackets of mathematics are mathematics (``[0, 1, 1]``)."""
    stack: list[int] = []
    for i, (_, t) in enumerate(toks):
        if t in _OPEN:
            stack.append(i)
        elif t in _CLOSE and stack:
            j = stack.pop()
            inside = range(j + 1, i)
            words = any(kinds[k] == "P" and toks[k][0] in ("word", "poss") for k in inside)
            # an item's letter, "(a) angle", "(a)-(b)": text
            item = (i == j + 2 and re.fullmatch("[a-e]", toks[j + 1][1]) is not None
                    and (j == 0 or toks[j - 1][1] == "-"))
            # an equation's number, "(3.133a)": text
            item = item or (i == j + 3 and toks[j + 1][0] == "num" and "." in toks[j + 1][1]
                            and toks[j + 2][0] == "word" and len(toks[j + 2][1]) == 1)
            if words or item:
                kinds[j] = kinds[i] = "P"
                if item:
                    kinds[j + 1:i] = ["P"] * (i - j - 1)
            else:
                for k in inside:
                    if toks[k][1] in ",;:":
                        kinds[k] = "O"
    for j in stack:
        kinds[j] = "P"   # unbalanced


def _runs(toks: list[tuple[str, str]], kinds: list[str]) -> list[tuple[bool, int, int]]:
    """(is_math, start, end) pieces: a run without a symbol or function is text."""
    out, i = [], 0
    while i < len(toks):
        j = i
        prose = kinds[i] == "P"
        while j < len(toks) and (kinds[j] == "P") == prose:
            j += 1
        if not prose:
            s, e = i, j
            while s < e and (kinds[s] == "S" or (kinds[s] == "O"
                                                  and toks[s][1] not in _LEADING)):
                s += 1
            while e > s and (kinds[e - 1] == "S" or (kinds[e - 1] == "O"
                                                      and toks[e - 1][1] not in _TRAILING)):
                e -= 1
            has_symbol = any(kinds[k] in "MF" or toks[k][1] in ("^", "||")
                             for k in range(s, e))
            out += [(False, i, s), (has_symbol, s, e), (False, e, j)]
        else:
            out.append((False, i, j))
        i = j
    return [r for r in out if r[1] < r[2]]


def _sup(toks: list[tuple[str, str]], i: int) -> tuple[str, int]:
    """The superscript after ``^`` at ``i``: ``^(2k)`` -> ``^{2k}``, ``^-1`` -> ``^{-1}``."""
    j = i + 1
    if j < len(toks) and toks[j][1] == "(":
        depth, k = 0, j
        for k in range(j, len(toks)):
            depth += (toks[k][1] == "(") - (toks[k][1] == ")")
            if depth == 0:
                break
        return "^{" + _latex(toks[j + 1:k]) + "}", k + 1
    if j + 1 < len(toks) and toks[j][1] == "-":
        return "^{-" + _latex(toks[j + 1:j + 2]) + "}", j + 2
    return "^{" + _latex(toks[j:j + 1]) + "}", j + 1


def _atom(g: str, t: str) -> str:
    if g == "num":
        m = re.fullmatch(r"([\d.]+)[eE]([-+]?)(\d+)", t)
        return rf"{m[1]} \times 10^{{{m[2].replace('+', '')}{int(m[3])}}}" if m else t
    if g == "word":
        core = t.rstrip("'*")
        tail = t[len(core):]
        sym = _FUNCTIONS.get(core) or _SYMBOLS.get(core) or book_latex(core)
        return sym + ("^{*}" if tail == "*" else tail)
    return _OPS.get(t, t)


def _latex(toks: list[tuple[str, str]]) -> str:
    """A run of mathematical tokens as LaTeX."""
    out, i, times = [], 0, False
    while i < len(toks):
        g, t = toks[i]
        if g == "sp":
            i += 1
            continue
        if t in "^_" and g == "op":
            piece, i = _sup(toks, i)
            if out and out[-1].startswith(t + "{") and len(out) > 1:
                out[-2:] = ["{" + out[-2] + out[-1] + "}"]   # Omega^2^T: {Omega^{2}}^{T}
            out.append(t + piece[1:])
            continue
        if t == "sqrt" and _next(toks, i) == ("op", "("):
            inner, i = _sup(toks, i)   # the same balanced group, braced
            out.append(r"\sqrt{" + inner[2:-1] + "}")
            continue
        if t == "x" and not times and _operand(_next(toks, i, -1), False) \
                and _operand(_next(toks, i), True) and i > 0 and toks[i - 1][0] == "sp":
            out.append(r"\times")
            times = True
            i += 1
            continue
        if t == "." and g == "op":
            out.append(r"\cdot")
        elif g == "word" and t in _FUNCTIONS and _next(toks, i) is not None \
                and _next(toks, i)[0] == "word":
            out.append(_atom(g, t) + r"\,")   # tr Q, cos phi: a thin space, as TeX sets
        else:
            out.append(_atom(g, t))
        times = False
        i += 1
    return " ".join(out)


def prose_latex_runs(text: str) -> list[tuple[bool, str]]:
    r"""``text`` cut into ``(is_math, piece)``: a mathematical piece as LaTeX in book
    notation, a text piece as written.

    Example: ``"cos(phi) = (tr Q - 1)/2."`` -> ``[(True, r"\cos(\phi) = (\operatorname{tr}
    Q - 1)/2"), (False, ".")]``.
    """
    toks = _tokens(text)
    kinds = _kinds(toks)
    return [(m, _latex(toks[s:e]) if m else "".join(t for _, t in toks[s:e]))
            for m, s, e in _runs(toks, kinds)]


def prose_markdown(text: str) -> str:
    """``text`` with its mathematics as inline Markdown maths (``$...$``), for a page that
    typesets formulas (the exercises page).

    Args:
        text: a sentence of ASCII mathematics and English (a worked step's reason, an
            assumption, a check's name).

    Returns:
        Markdown text: each run of mathematics as ``$LaTeX$`` in book notation, the words as
        written. ``""`` for ``""``.
    """
    return "".join(f"${p}$" if m else p for m, p in prose_latex_runs(text or ""))
