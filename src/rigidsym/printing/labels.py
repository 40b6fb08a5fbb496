"""Book notation for the short ASCII texts declarations write: member labels and evidence.

A declaration labels a member ``"adot . omega/||omega||^2"`` and states evidence as
``"the trailing factor omega is missing"``: plain ASCII, easy to type. Printed next to the
member itself (``ȧ∥ = (ȧ·ω)/‖ω‖²``) that mixes two notations on one line, so
:func:`label_text` rewrites the *mathematical* tokens of such a text in the book's Unicode
notation (the same names as :func:`rigidsym.printing.notation.book_text`) and leaves every
English word alone: only Greek letter names, names with an accent or a subscript
(``adot``, ``e_dot``, ``Ntilde``, ``N~``, ``r0``, ``a_par``, ``I_C``) and the ASCII
operators ``||x||``, ``^T``, ``^2``, `` . `` and `` x `` (a cross product between two
operands) are rewritten. LaTeX commands (``\\dot{\\mathbf{v}}``) become Unicode text
(:func:`latex_text`) where a text output cannot render them.
"""

from __future__ import annotations

import re
import unicodedata

from rigidsym.printing.names import GREEK, book_latex, book_text

__all__ = ["label_text", "label_latex", "latex_text", "latex_spans", "math_token"]

_COMBINING = {"dot": "\u0307", "ddot": "\u0308", "tilde": "\u0303", "hat": "\u0302",
              "bar": "\u0304", "mathring": "\u030a", "breve": "\u0306", "check": "\u030c"}
_SUP = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
_STEM = r"(?:[A-Za-z]|" + "|".join(sorted(GREEK, key=len, reverse=True)) + ")"
#: a token that is mathematics however it is read (never an English word)
_MATH_TOKEN = re.compile(
    rf"^(?:{_STEM}(?:dot|ddot|tilde)"                    # adot, Ntilde, omegadot
    rf"|{_STEM}\d{{1,2}}(?:dot)?"                         # r0, p2, u0dot
    rf"|(?:{_STEM}|{_STEM}(?:dot|ddot|tilde)|{_STEM}\d{{1,2}})"
    rf"(?:_(?:dot|ddot|tilde|hat|bar|par|perp|\d{{1,2}}|[A-Za-z]{{1,2}}))+"  # a_dot, I_C
    rf"|{'|'.join(GREEK)})'*$")
_TOKEN = re.compile(r"(?<![A-Za-z0-9_])[A-Za-z][A-Za-z0-9_]*'*")  # not inside "3x4"


_NESTED = re.compile(r"\[(\[[^\[\]]*\](?:, \[[^\[\]]*\])+)\]")
#: (3.59)'s braced terms, labelled "pdot_perp brace" (or "underbrace", LaTeX's command
#: name): "braced ṗ⊥" in words, never a LaTeX command as text
_BRACE = re.compile(r"(?<![\w(])([A-Za-z][\w']*) (?:under)?brace\b")
_DIAG = re.compile(r"\bdiag\(")


def _book_forms(text: str) -> str:
    """The ASCII text's own shorthands in the book's forms, before either printer reads
    it: ``diag(I_C, O)`` as the block matrix ``[I_C, O; O, O]`` (the book prints a
    block-diagonal matrix as its blocks, (3.138), as the labels beside it print theirs),
    a braced term's label in words."""
    text = _BRACE.sub(r"braced \1", text)
    text = re.sub(r"\((?:under)?brace\)", "(braced)", text)
    while m := _DIAG.search(text):
        depth, args, start = 0, [], m.end()
        for k in range(m.end(), len(text)):
            depth += (text[k] in "([") - (text[k] in ")]")
            if depth < 0:
                break
            if depth == 0 and text[k] == ",":
                args.append(text[start:k].strip())
                start = k + 1
        else:
            return text  # unbalanced: left as written
        args.append(text[start:k].strip())
        body = "; ".join(", ".join(a if i == j else "O" for j in range(len(args)))
                         for i, a in enumerate(args))
        text = f"{text[:m.start()]}[{body}]{text[k + 1:]}"
    return text


def _mathy(tok: str) -> bool:
    return len(tok) == 1 or bool(_MATH_TOKEN.match(tok))


def math_token(tok: str) -> bool:
    """Whether the ASCII word ``tok`` is a symbol however it is read (one letter, a Greek
    name, a name with a subscript or an accent: ``p0``, ``n_O``, ``omega_dot``), never an
    English word."""
    return _mathy(tok)


def _token(tok: str) -> str:
    if tok.endswith("_prime"):
        return _token(tok[:-6]) + "'"
    if tok.startswith("norm_") and _mathy(tok[5:]):
        return book_text(tok)
    if not _MATH_TOKEN.match(tok):
        return tok
    return book_text(tok)


#: a label's tokens for :func:`label_latex`
_LATEX_TOKEN = re.compile(r"\|\||\^T\b|\^-?\d+|[A-Za-z][A-Za-z0-9_]*'*~?|\d+|\s+|.")


def label_latex(text: str) -> str:
    """A member's ASCII label as LaTeX for the MathML printer (the errata table
    labels members in MathML, never in ASCII): its mathematics in book notation
    (``"adot . omega/||omega||^2"`` -> ``\\dot{a} \\cdot \\omega/\\|\\omega\\|^{2}``), its English
    words as ``\\text{...}`` (``"pdot_perp brace"`` -> ``\\text{braced } \\dot{p}_{\\perp}``).
    """
    # a size, 6x6, is 6 × 6 (not the product of 6 and x₆)
    toks = _LATEX_TOKEN.findall(re.sub(r"\b(\d+)x(\d+)\b", r"\1×\2", _book_forms(text or "")))
    out: list[tuple[bool, str]] = []  # (is_math, piece)

    def mathy(t: str) -> bool:
        t = t.rstrip("~")
        return bool(t) and (t[0].isalpha() and (_mathy(t) or (t.startswith("norm_")
                                                              and _mathy(t[5:]))))

    for i, t in enumerate(toks):
        near = [x for x in toks[i + 1:] if not x.isspace()][:1] + \
            [x for x in reversed(toks[:i]) if not x.isspace()][:1]
        if t == "||":
            out.append((True, r"\|"))
        elif t == "×":
            out.append((True, r"\times"))
        elif t == "^T":
            out.append((True, "^{T}"))
        elif t.startswith("^"):
            out.append((True, "^{" + t[1:] + "}"))
        elif t[0].isalpha() and t not in ("x",) and mathy(t):
            core = book_latex(t.rstrip("~"))
            out.append((True, rf"\tilde{{{core}}}" if t.endswith("~") else core))
        elif t == "x" and len(near) == 2 and all(mathy(n) or n in "()|" for n in near):
            out.append((True, r"\times"))
        elif t == "x":
            out.append((True, "x"))
        elif t == "." and len(near) == 2 and all(mathy(n) or n in "()|" for n in near):
            out.append((True, r"\cdot"))
        elif t[0].isalpha():
            out.append((False, t))
        elif t.isdigit() or t in "+/=()[],":
            out.append((True, t))
        elif t == "-" and not (out and not out[-1][0]):
            out.append((True, "-"))
        else:  # spaces and punctuation: prose between words, a space between symbols
            out.append((False, t) if t.strip() or (out and not out[-1][0]) else (True, " "))
    pieces, k = [], 0
    while k < len(out):
        if out[k][0]:
            pieces.append(out[k][1])
            k += 1
            continue
        run = ""
        while k < len(out) and (not out[k][0] or (out[k][1] == " " and k + 1 < len(out)
                                                  and not out[k + 1][0])):
            run += out[k][1]
            k += 1
        lead = " " if pieces else ""
        tail = " " if k < len(out) else ""
        pieces.append(r"\text{" + lead + run.strip() + tail + "}")
    return " ".join(p for p in pieces if p != " ").strip()


def label_text(text: str) -> str:
    """An ASCII label or evidence sentence with its mathematics in book notation.

    ``"adot . omega/||omega||^2"`` -> ``"ȧ·ω/‖ω‖²"``; ``"Ntilde vdot"`` -> ``"Ñ v̇"``;
    ``"normal to omega"`` -> ``"normal to ω"`` (words stay as they are). LaTeX commands in
    the text are rendered as Unicode (:func:`latex_text`).
    """
    if not text:
        return text
    if "\\" in text:
        text = "".join(latex_text(p) if is_tex else p for is_tex, p in latex_spans(text))
    out = re.sub(r"\|\|([^|]+?)\|\|", lambda m: f"‖{m.group(1)}‖", _book_forms(text))
    out = re.sub(r"([A-Za-z])~", lambda m: m.group(1) + _COMBINING["tilde"], out)
    out = re.sub(r"\^T\b", "ᵀ", out)
    out = re.sub(r"\^(-?\d+)\b", lambda m: m.group(1).translate(_SUP), out)
    out = out.replace("!=", "≠").replace("<=", "≤").replace(">=", "≥")
    # a block matrix written as Python's nested lists, m[[X, Y], [Z, W]]: block notation
    out = _NESTED.sub(lambda m: "[" + "; ".join(re.findall(r"\[([^\[\]]*)\]", m.group(1)))
                      + "]", out)
    # a dot product: "a . b", or "w.w" between two mathematical tokens (not "e.g.")
    out = re.sub(r"(?<=[\w)‖'\u0307\u0308\u0303]) \. (?=[\w(‖])", "·", out)
    out = re.sub(r"\b([A-Za-z][\w']*)\.([A-Za-z][\w']*)\b(?!\.)",
                 lambda m: f"{m.group(1)}·{m.group(2)}" if _mathy(m.group(1))
                 and _mathy(m.group(2)) else m.group(0), out)
    # a cross product: " x " between two operands (the x of "x = ..." is an operand)
    out = re.sub(r"(?<=[\w)\]‖'\u0307\u0308\u0303]) x (?=[A-Za-z(\[‖])", " × ", out)
    return unicodedata.normalize("NFC", _TOKEN.sub(lambda m: _token(m.group(0)), out))


# --------------------------------------------------------------------------- LaTeX
_TEX_GROUP = r"\{(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*\}"
#: a LaTeX span in running text: commands with their brace groups, sub/superscripts
_TEX_SPAN = re.compile(rf"(?:\\[A-Za-z]+(?:{_TEX_GROUP})*(?:[_^](?:{_TEX_GROUP}|\w))*)+")


def latex_spans(text: str) -> list[tuple[bool, str]]:
    """``text`` cut into ``(is_latex, piece)``: the LaTeX pieces are runs of commands with
    their brace groups (``\\dot{\\boldsymbol{\\nu}}``), the rest is prose."""
    out, pos = [], 0
    for m in _TEX_SPAN.finditer(text):
        if m.start() > pos:
            out.append((False, text[pos:m.start()]))
        out.append((True, m.group(0)))
        pos = m.end()
    if pos < len(text):
        out.append((False, text[pos:]))
    return out


_TEX_STYLE = re.compile(r"\\(?:mathbf|boldsymbol|mathrm|mathit|bm|operatorname)\{([^{}]*)\}")
_TEX_SYMBOLS = {r"\|": "‖", r"\cdot": "·", r"\times": "×", r"\parallel": "∥",
                r"\perp": "⊥", r"\le": "≤", r"\ge": "≥", r"\neq": "≠", r"\quad": " "}


def latex_text(tex: str) -> str:
    """A short LaTeX piece as Unicode text: ``\\dot{\\boldsymbol{\\nu}}`` -> ``ν̇``,
    ``\\tilde{\\mathbf{N}}`` -> ``Ñ``; unknown commands lose their backslash."""
    s = _TEX_STYLE.sub(lambda m: m.group(1), tex)
    for cmd, ch in _TEX_SYMBOLS.items():
        s = s.replace(cmd, ch)
    s = re.sub(r"\\([A-Za-z]+)", lambda m: GREEK.get(m.group(1), m.group(1)), s)
    while True:  # \dot{x} -> x + combining dot, innermost first
        m = re.search(r"(dot|ddot|tilde|hat|bar|mathring|breve|check)\{([^{}]*)\}", s)
        if not m:
            break
        s = s[:m.start()] + m.group(2) + _COMBINING[m.group(1)] + s[m.end():]
    s = re.sub(r"_\{([^{}]*)\}", r"_\1", s)
    s = re.sub(r"\^\{([^{}]*)\}", r"^\1", s)
    return s.replace("{", "").replace("}", "")
