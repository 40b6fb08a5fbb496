"""Respellings of a reader's LaTeX that its ``--let`` declarations settle.

The grammar reads a plain ``e`` directly before ``^`` as the exponential (``e^{[\\omega]
\\theta}``), as the books mean it when nothing names a symbol ``e``. A reader who declares
one (``--let 'e = |\\mathbf{e}|'``, Hughes' and Markley's norm of the Euler-axis vector, or
``--let 'e: scalar'``) means ``e^2`` as its square: with such a declaration every ``e^`` of
the LaTeX and of the models is respelt ``{e}^`` (a braced group, the same glyph), before
either semantics parses it, and the reading says so.

A tilde over a vector expression, Wittenburg's ``\\widetilde{\\mathbf{a}\\times\\mathbf{b}}``
(the cross-product matrix of ``a \\times b``; a glyph's tilde is a choice of the reader,
:mod:`rigidsym.latex.transformer.tilde`), is respelt ``[\\mathbf{a}\\times\\mathbf{b}]_\\times``:
over a sum or a cross product no other meaning is written (before: a syntax error ending in
"expected one of: }").

A name with a lower-case superscript label, Groves' frames ``C_b^n``, ``\\Omega_{ib}^b``,
``\\boldsymbol\\omega_{ib}^b``, is a power to the grammar (``x_1^n``); where a ``--let``
declares that NAME it is the name: each occurrence (any bracing, ``\\dot{C}_b^n`` too) is
respelt with the label parenthesised, ``C_{b}^{(n)}``, the grammar's label (before: "the
name 'C_b^n' cannot be read").

Eade's cross-product matrix as a subscript, ``\\boldsymbol\\omega_\\times`` and
``(\\mathbf{R}\\boldsymbol\\omega)_\\times``, is respelt ``[\\boldsymbol\\omega]_\\times``
(before: "unexpected \\times"). A hat over more than one glyph, Chirikjian's
``\\widehat{R\\boldsymbol\\omega}``, is the hat of that vector, respelt
``[R\\boldsymbol\\omega]_\\times`` (a hat over one glyph stays a name of its own: a unit
vector in Modern Robotics).

Forster et al.'s preintegrated quantities ``\\Delta\\mathbf{R}_{ij}``, ``\\Delta t_{ij}``
are one name each where a ``--let`` declares that NAME: respelt ``\\mathbf{R}_{\\Delta ij}``
(the grammar's glyph with the Δ in its subscript; without the declaration ``\\Delta x`` stays
Δ times x). Kok, Hol & Schön's conjugate ``\\mathbf{q}^c`` is ``\\mathbf{q}^*`` where the
statement or a declaration uses the quaternion product (``\\odot``, ``\\otimes``).

Trawny and Roumeliotis' floor brackets around a cross, ``\\lfloor\\boldsymbol\\omega\\times
\\rfloor`` (``\\left\\lfloor ... \\right\\rfloor`` too), are the cross-product matrix of
the vector inside: respelt ``[\\boldsymbol\\omega]_\\times``. Floor brackets without the
cross stay unknown (the floor of a number is not read).

The rates of a vector's entries, Greenwood's ``\\dot\\epsilon_1 ... \\dot\\epsilon_4`` beside
a ``--let`` of the vector's rate ``\\dot{\\boldsymbol\\epsilon}``, are that rate's entries: each
is respelt ``\\dot{\\boldsymbol{\\epsilon}}_{k:k}`` (counted from 1; from 0 where the LaTeX
writes an ``\\epsilon_0``), so both semantics take the entry of the declared rate (before:
a free glyph of its own that the numeric cross-check does not evaluate). A ``--let`` of the
entry's rate itself (``\\dot\\epsilon_1: scalar``) keeps it a symbol of its own.
"""

from __future__ import annotations

import re

from rigidsym.latex.lets import read_lets, split_lets

__all__ = ["accent_primes", "angular_velocities", "conjugate_c", "cross_subscripts",
           "declared_columns", "declared_deltas", "declared_e", "declared_labels",
           "each_declaration", "floor_cross", "grouping_braces", "hat_expressions",
           "labels_as_typed", "rate_entries", "tilde_expressions"]

_E_POWER = re.compile(r"(?<![\\A-Za-z{])e(?=\^)")


def declared_e(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: with a ``--let`` naming a plain ``e``, each ``e^`` respelt
    ``{e}^`` in the LaTeX and in every declaration (``note`` says so); else all unchanged
    and ``note`` is ``""``.

    Args:
        latex: the LaTeX.
        let: the declarations as :func:`rigidsym.latex.lets.read_lets` takes them (``None``,
            a string, a list of strings or a dict).

    Raises:
        BadInput: as :func:`rigidsym.latex.lets.read_lets`.
    """
    if let is None or not any(x.key == "e" for x in read_lets(let)):
        return latex, let, ""
    new = _E_POWER.sub("{e}", latex)
    if isinstance(let, dict):
        out = {k: _E_POWER.sub("{e}", v) if isinstance(v, str) else v for k, v in let.items()}
    else:
        out = [_E_POWER.sub("{e}", d) for d in split_lets([let] if isinstance(let, str)
                                                             else let)]
    changed = new != latex or out != let
    note = ("e^: a power of the declared symbol e (a --let names e), not the exponential; "
            "write \\exp for it") if changed else ""
    return new, out, note


#: Ginsberg's column-matrix braces around one glyph, \{\omega\}, \{\omega'\}
_COLUMN = re.compile(r"\\\{\s*((?:\\[A-Za-z]+\s*(?:\{[^{}]*\})?|[A-Za-z])'*)\s*\\\}")


def declared_columns(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: where a ``--let`` names ``\\{x\\}`` (Ginsberg's column matrix
    of x's components, ``--let '\\{\\omega\\}: vector'``), each ``\\{x\\}`` of the LaTeX and the
    declarations is the glyph x, respelt ``{x}`` (a TeX group: the braces draw the column and
    group nothing; ``note`` says so); undeclared, ``\\{`` stays unread (a set's braces in
    other books). Else all unchanged and ``note`` is ``""``.

    Args:
        latex: the LaTeX.
        let: the declarations, as :func:`declared_e`'s.
    """
    decls = each_declaration(let)
    named = {re.sub(r"\s+", "", m.group(1)) for d in decls or []
             if (m := _COLUMN.fullmatch(re.split(r"[:=]", d, maxsplit=1)[0].strip()))}
    if not named:
        return latex, let, ""

    def group(m):
        return "{" + m.group(1) + "}" if re.sub(r"\s+", "", m.group(1)) in named else m.group(0)

    said = ", ".join(f"\\{{{g}\\}}" for g in sorted(named))
    return (_COLUMN.sub(group, latex), [_COLUMN.sub(group, d) for d in decls],
            f"{said}: the column matrix of the glyph inside the braces (Ginsberg's), "
            f"that glyph")


def _braced(text: str, start: int) -> int:
    """The index just past the ``\\}`` that closes the ``\\{`` at ``start`` (nested pairs
    counted), or -1."""
    depth, i = 0, start
    while i < len(text) - 1:
        pair = text[i:i + 2]
        if pair == "\\{":
            depth += 1
        elif pair == "\\}":
            depth -= 1
            if depth == 0:
                return i + 2
        i += 2 if pair[0] == "\\" else 1
    return -1


#: what makes braces a set's in the books, never a group: a list, a condition, a bar
_SET_MARK = re.compile(r",|\\mid|\\vert|\\colon|:|\\in(?![A-Za-z])|\\lvert|\|")


#: a sizing command closing a delimiter, at the end of the delimited text (``\right``)
_SIZED_CLOSE = re.compile(r"\\(?:right|bigr|Bigr|biggr|Biggr)\s*$")


def grouping_braces(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\{ ... \\}`` around an expression that is no single
    glyph (Lee–Leok–McClamroch's ``(\\{\\operatorname{tr}[A]I - A\\}x)^\\wedge``) respelt as
    parentheses in the LaTeX and the declarations (``note`` says so); a single glyph's
    braces (Ginsberg's column ``\\{\\omega\\}``, :func:`declared_columns`) and braces
    holding a list, a bar or a condition (a set's) are left as written, unread. Else all
    unchanged and ``note`` is ``""``.

    Where the braces hold an expression, grouping it and Ginsberg's column of its
    components are the same value here (a column of components is the vector the reader
    reads), so no reading is picked where the books' readings could differ: a set's braces
    are never read.

    Args:
        latex: the LaTeX.
        let: the declarations, as :func:`declared_e`'s.
    """
    decls = each_declaration(let)
    if decls is None:
        return latex, let, ""
    said: list[str] = []
    # one glyph, subscripted or primed (Ginsberg's column, declared_columns), or one number
    # (a set's {1}): never a group
    one = re.compile(r"\s*(?:(?:" + _GLYPH + r")\s*(?:_\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]+))?'*"
                     r"|-?\d+(?:\.\d+)?)\s*")

    def respell(text: str) -> str:
        out, i = [], 0
        while (j := text.find("\\{", i)) >= 0:
            end = _braced(text, j)
            if end < 0:
                break
            inner = text[j + 2:end - 2]
            core = _SIZED_CLOSE.sub("", inner)  # \left\{ x \right\}: x's braces
            if one.fullmatch(core) or not core.strip() or _SET_MARK.search(core):
                out.append(text[i:j + 2])
                i = j + 2
                continue
            inner = respell(inner)
            out.append(text[i:j] + "(" + inner + ")")
            said.append(f"\\{{{inner.strip()}\\}}")
            i = end
        out.append(text[i:])
        return "".join(out)

    latex2, decls2 = respell(latex), [respell(d) for d in decls]
    if not said:
        return latex, let, ""
    return latex2, decls2, (f"{', '.join(dict.fromkeys(said))}: braces around an expression, "
                            f"read as parentheses (Lee–Leok–McClamroch's grouping; Ginsberg's "
                            f"column of its components is the same value)")


_TILDE = re.compile(r"\\(?:wide)?tilde\s*\{")


def tilde_expressions(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\tilde{X}`` (``\\widetilde``) whose braces hold a cross
    product, a sum, a difference or a juxtaposed product of glyphs (Haug's
    ``\\widetilde{\\tilde{\\mathbf{a}}\\mathbf{b}}``, the cross-product matrix of the vector
    ã b) respelt ``[X]_\\times`` in the LaTeX and the declarations (``note`` says so); else
    all unchanged and ``note`` is ``""``. A tilde over one glyph is left to the glyph's
    reading.

    Args and Raises: as :func:`declared_e`.
    """
    hits: list[str] = []

    def respell(text: str) -> str:
        return _braced_as_cross_matrix(text, _TILDE, lambda inner: bool(re.search(
            r"\\times|[+-]", re.sub(r"\{[^{}]*\}", "", inner))) or _juxtaposed(inner), hits)

    new, out = _respelt(respell, latex, let)
    if not hits:
        return latex, let, ""
    return new, out, (f"\\tilde{{{hits[0]}}}: the cross-product matrix of the vector "
                      f"{hits[0]}, read as [{hits[0]}]_\\times")


_ACCENT = re.compile(r"\\(?:(?:wide)?(?:tilde|hat)|d?dot)\s*\{")


def accent_primes(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\tilde{X}'`` (``\\hat``, the wide ones, ``\\dot``,
    ``\\ddot``) whose glyph no ``--let`` declares while one declares ``X'`` (Nikravesh's
    ``\\tilde{\\boldsymbol\\omega}'``, the tilde of the declared ``\\boldsymbol\\omega'``;
    Fowles & Cassiday's ``\\ddot{\\mathbf{r}}'``, the acceleration of the declared
    ``\\mathbf{r}'(t)`` seen in the moving frame) respelt ``\\tilde{X'}`` in the LaTeX and
    the declarations (``note`` says so); else all unchanged and ``note`` is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    from rigidsym.latex.declgraph import glyph_keys
    from rigidsym.latex.shapes import LatexError

    decls = each_declaration(let)
    if not decls or "'" not in latex:
        return latex, let, ""
    declared = {x.key for x in read_lets(decls)}
    hits: list[str] = []

    def key(text: str) -> str | None:
        try:
            keys = glyph_keys(text)
        except LatexError:
            return None
        return next(iter(keys)) if len(keys) == 1 else None

    def respell(text: str) -> str:
        out, k = [], 0
        for m in _ACCENT.finditer(text):
            if m.start() < k:
                continue
            j = _group_end(text, m.end())
            primes = None if j < 0 else re.match(r"\s*('+)", text[j:])
            if primes is None:
                continue
            inner, end = text[m.end():j - 1], j + primes.end()
            inside = f"{text[m.start():m.end()]}{inner}{primes.group(1)}}}"
            if key(text[m.start():end]) in declared or key(inner + primes.group(1)) \
                    not in declared:
                continue
            out += [text[k:m.start()], inside]
            hits.append(f"{text[m.start():end]}: read as {inside}")
            k = end
        return "".join(out) + text[k:]

    new, out = _respelt(respell, latex, let)
    if not hits:
        return latex, let, ""
    return new, out, (f"{hits[0]}, the accent of the declared primed glyph (a --let "
                      f"declares it, none the accented glyph)")


_INDEX = re.compile(r"[_^]\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]+)")


def _juxtaposed(inner: str) -> bool:
    """Whether ``inner`` is a product of two glyphs or more written side by side
    (``\\tilde{\\mathbf{a}}\\mathbf{b}``; ``\\mathbf{r}_{C}`` or ``\\boldsymbol\\omega'`` is
    one)."""
    return len(re.findall(_GLYPH, _INDEX.sub("", inner))) >= 2


def _group_end(text: str, start: int) -> int:
    """The index just past the ``}`` that closes a group opened just before ``start``
    (nested groups counted), or -1 where it is not closed."""
    depth, j = 1, start
    while j < len(text) and depth:
        depth += {"{": 1, "}": -1}.get(text[j], 0)
        j += 1
    return -1 if depth else j


def _braced_as_cross_matrix(text: str, opening: re.Pattern, takes, hits: list,
                            form: str = "[{}]_\\times") -> str:
    """``text`` with each accent ``opening`` matches (up to its opening brace) whose braced
    argument ``takes`` (a predicate of the argument's text) respelt ``form`` of ARG
    (``[ARG]_\\times``); each argument respelt is appended to ``hits``. An unbalanced brace
    leaves the rest as is."""
    out, k = [], 0
    for m in opening.finditer(text):
        if m.start() < k:
            continue
        j = _group_end(text, m.end())
        inner = text[m.end():j - 1]
        if j < 0 or not takes(inner):
            continue
        out += [text[k:m.start()], form.format(inner)]
        hits.append(inner)
        k = j
    return "".join(out) + text[k:]


def _respelt(respell, latex: str, let: object) -> tuple[str, object]:
    """``respell`` applied to the LaTeX and to every declaration of ``let`` (a dict's string
    values, or the list :func:`each_declaration` reads; ``let`` unchanged where it reads none), the
    LaTeX first."""
    new = respell(latex)
    if isinstance(let, dict):
        out = {k: respell(v) if isinstance(v, str) else v for k, v in let.items()}
    else:
        decls = each_declaration(let)
        out = let if decls is None else [respell(d) for d in decls]
    return new, out


_FLOOR = re.compile(r"(?:\\left\s*)?\\lfloor(?![A-Za-z])")
_FLOOR_END = re.compile(r"\\times\s*(?:\\right\s*)?\\rfloor(?![A-Za-z])")


def floor_cross(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\lfloor X\\times\\rfloor`` respelt ``[X]_\\times``
    in the LaTeX and the declarations (``note`` says so); else all unchanged and ``note``
    is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    hits: list[str] = []

    def respell(text: str) -> str:
        out, k = [], 0
        for m in _FLOOR.finditer(text):
            if m.start() < k:
                continue
            end = _FLOOR_END.search(text, m.end())
            inner = text[m.end():end.start()].strip() if end else ""
            if not inner or _FLOOR.search(inner) or "\\rfloor" in inner:
                continue
            out += [text[k:m.start()], f"[{inner}]_\\times"]
            hits.append(inner)
            k = end.end()
        return "".join(out) + text[k:]

    new, out = _respelt(respell, latex, let)
    if not hits:
        return latex, let, ""
    return new, out, (f"\\lfloor {hits[0]}\\times\\rfloor: the cross-product matrix of the "
                      f"vector {hits[0]} (Trawny & Roumeliotis (2005)), read as "
                      f"[{hits[0]}]_\\times")


_RATE_DECL = re.compile(
    r"\\dot\s*\{?\s*\\(?P<font>mathbf|boldsymbol|bm)\s*\{?\s*(?P<letter>\\[A-Za-z]+|[A-Za-z])"
    r"\s*\}?\s*\}?\s*(?:\(t\))?\s*[:=]")


def _entry_rate(letter: str) -> re.Pattern:
    """``\\dot\\epsilon_k`` (any bracing) of the plain ``letter``, the subscript a digit."""
    tail = r"(?![A-Za-z])" if letter.startswith("\\") else ""
    return re.compile(r"\\dot\s*(?:\{\s*" + re.escape(letter) + r"\s*\}|" + re.escape(letter)
                      + tail + r")\s*_\s*(?:\{\s*(?P<k>\d)\s*\}|(?P<k1>\d))")


#: a vector of time, ``\\mathbf{e}(t): unit 4-vector``: the rate of its entries is its rate's
_TIMED_VECTOR = re.compile(
    r"(?:\\(?P<font>mathbf|boldsymbol|bm)\s*\{?\s*)?(?P<letter>\\[A-Za-z]+|[A-Za-z])\s*\}?\s*"
    r"\(t\)\s*:[^=]*vector")


def rate_entries(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\dot\\epsilon_k`` beside a ``--let`` of the rate
    ``\\dot{\\boldsymbol\\epsilon}`` (a model or a kind), or of the vector as a function of
    time (``\\mathbf{e}(t): unit 4-vector``, Baruh's ``\\dot e_0``), respelt as that rate's
    entry ``\\dot{\\boldsymbol{\\epsilon}}_{k:k}`` in the LaTeX and the other declarations
    (``note`` says so); else all unchanged and ``note`` is ``""``.

    Counted from 1, as Greenwood's ``\\epsilon_1 ... \\epsilon_4``; from 0 where the LaTeX or a
    declaration writes the letter's subscript 0 (Kuipers' ``q_0``).

    Args and Raises: as :func:`declared_e`.
    """
    decls = each_declaration(let)
    if not decls:
        return latex, let, ""
    rates = {}
    for i, d in enumerate(decls):
        m = _RATE_DECL.match(d.strip()) or _TIMED_VECTOR.match(d.strip())
        if m:
            rates.setdefault(m["letter"], (m["font"], i))
    hits: list[str] = []
    for letter, (font, i) in rates.items():
        pat = _entry_rate(letter)
        own = [d for d in decls if pat.match(d.strip())]  # --let '\dot\epsilon_1: ...'
        if own:
            continue
        zero = re.compile(re.escape(letter) + (r"(?![A-Za-z])" if letter.startswith("\\")
                                                else "") + r"\s*_\s*\{?\s*0(?!\d)")
        base = 1 if any(zero.search(t) for t in [latex, *decls]) else 0
        vec = f"\\dot{{\\{font}{{{letter}}}}}" if font else f"\\dot{{{letter}}}"  # Kane's \epsilon

        def one(m, vec=vec, base=base):
            k = int(m["k"] or m["k1"]) + base
            hits.append(f"{m.group(0)}: entry {k} of {vec}")
            return f"{vec}_{{{k}:{k}}}"

        latex = pat.sub(one, latex)
        decls = [d if j == i else pat.sub(one, d) for j, d in enumerate(decls)]
    if not hits:
        return latex, let, ""
    return latex, decls, (f"{'; '.join(dict.fromkeys(hits))} (the rates of a vector's "
                          f"entries are the entries of its rate, which a --let declares)")


_LABELLED = re.compile(
    r"(?P<acc>\\d?dot\s*\{\s*)?"
    r"(?P<base>\\(?:mathbf|boldsymbol|bm)\s*(?:\{\s*\\?[A-Za-z]+\s*\}|\\[A-Za-z]+|[A-Za-z])"
    r"|\\[A-Za-z]+|(?:(?<![\\A-Za-z])|(?<=\^[a-z]))[A-Za-z])"
    r"(?(acc)\s*\})"
    r"(?P<sub>_\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]))?"
    r"\s*\^\s*(?P<lbl>\{\s*[a-z][a-z0-9]*\s*\}|[a-z]|\{\s*[A-Z]{2,}\s*\})")
#: Zipfel's bracketed names, ``[T]^{BL}``, ``[\Omega^{BI}]^B``: a glyph (with a frame pair
#: of capitals or none) in brackets, then a frame label (capitals, never ``T`` alone)
_BRACKETED = re.compile(
    r"\[\s*(?P<glyph>(?:\\(?:mathbf|boldsymbol|bm)\s*)?(?:\{\s*\\?[A-Za-z]+\s*\}|\\[A-Za-z]+"
    r"|[A-Za-z]))\s*(?:\^\s*(?P<inner>\{\s*[A-Z]{2,}\s*\}))?\s*\]"
    r"\s*\^\s*(?P<lbl>\{\s*(?!T\s*\})[A-Z]+\s*\}|[A-SU-Z](?![A-Za-z]))")
#: a label written before the subscript, Beard's ``R^b_{v2}``: read as ``R_{v2}^b``
_LABEL_FIRST = re.compile(r"\^\s*(?P<lbl>\{\s*[a-z][a-z0-9]*\s*\}|[a-z])"
                          r"\s*(?P<sub>_\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]))")


def _parts(m) -> tuple[str, str, str]:
    base = re.sub(r"\s+", "", m["base"])
    base = re.sub(r"^(\\(?:mathbf|boldsymbol|bm))(\\?[A-Za-z]+)$", r"\1{\2}", base)
    sub = re.sub(r"[\s{}_]", "", m["sub"] or "")
    return base, sub, re.sub(r"[\s{}]", "", m["lbl"])


def _label_names(let: object) -> set[tuple[str, str, str]]:
    """``(base, subscript, label)`` of each NAME with a lower-case superscript label that a
    declaration of ``let`` names (a function's parameters aside: Beard's
    ``R_{v2}^b(\\phi) = ...``, ``R^b_{v2}`` read as ``R_{v2}^b``)."""
    names = set()
    for d in each_declaration(let) or ():
        name = re.split(r"\s*(?:\([^()]*\))?\s*[:=]", d, maxsplit=1)[0].strip()
        m = _LABELLED.fullmatch(_LABEL_FIRST.sub(r"\g<sub>^\g<lbl>", name))
        if m and not m["acc"]:
            names.add(_parts(m))
    return names


def _bracketed_names(let: object) -> dict[str, str]:
    """Each bracketed NAME with a frame label that a declaration of ``let`` names (Zipfel's
    ``[T]^{BL}``, ``[\\Omega^{BI}]^B``), as typed (spaces dropped) -> its respelling, a
    parenthesised label the grammar reads as part of the name (``[T]^{(BL)}``,
    ``[\\Omega^{(BI)}]^{(B)}``)."""
    names = {}
    for d in each_declaration(let) or ():
        name = re.split(r"\s*(?:\([^()]*\))?\s*[:=]", d, maxsplit=1)[0].strip()
        m = _BRACKETED.fullmatch(name)
        if m:
            names["".join(name.split())] = _bracket_respelt(m)
    return names


def _bracket_respelt(m) -> str:
    glyph = "".join(m["glyph"].split())
    inner = f"^{{({_letters(m['inner'])})}}" if m["inner"] else ""
    return f"[{glyph}{inner}]^{{({_letters(m['lbl'])})}}"


def _letters(label: str) -> str:
    return re.sub(r"[{}\s]", "", label)


def labels_as_typed(let: object):
    """The function that writes back, in a message, each labelled NAME of ``let`` that
    :func:`declared_labels` respells (``R_{v2}^{(b)}`` and its printed ``R_v2^(b)``: the
    ``R_{v2}^b`` the reader typed): a message names only what the user wrote."""
    pairs = []
    for base, sub, lbl in _label_names(let) if let is not None else ():
        typed = f"{base}{_index('_', sub)}{_index('^', lbl)}"
        pairs.append((f"{base}{'_{' + sub + '}' if sub else ''}^{{({lbl})}}", typed))
        plain = re.sub(r"\\(?:mathbf|boldsymbol|bm)|[{}\s]", "", base)
        if re.fullmatch(r"[A-Za-z]", plain):
            pairs.append((f"{plain}{'_' + sub if sub else ''}^({lbl})", typed))
    for typed, respelt in _bracketed_names(let).items():
        pairs.append((respelt, typed))
        pairs.append((re.sub(r"\\(?:mathbf|boldsymbol|bm)|[{}]", "", respelt), typed))

    def back(text):
        if isinstance(text, (list, tuple)):  # a note of several lines
            return type(text)(back(t) for t in text)
        if not isinstance(text, str):
            return text
        for respelt, typed in pairs:
            text = text.replace(respelt, typed)
        return text
    return back


def declared_labels(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each glyph with a lower-case superscript label or a frame pair
    of capitals whose NAME a ``--let`` declares (Groves' ``C_b^n``, Zipfel's ``T^{BL}``)
    respelt ``C_{b}^{(n)}`` (``T^{(BL)}``), and each bracketed NAME with a frame label
    (Zipfel's ``[T]^{BL}``, ``[\\Omega^{BI}]^B``) respelt ``[T]^{(BL)}``
    (``[\\Omega^{(BI)}]^{(B)}``), in the LaTeX and the declarations (``note`` says so); else
    all unchanged and ``note`` is ``""``. A power is never written with two capitals, and a
    bracketed name's label is never ``T`` (the transpose).

    Args and Raises: as :func:`declared_e`.
    """
    if let is None:
        return latex, let, ""
    decls = each_declaration(let)
    if decls is None:
        return latex, let, ""
    names, bracketed = _label_names(decls), _bracketed_names(decls)
    if not names and not bracketed:
        return latex, let, ""

    def in_brackets(m):
        respelt = bracketed.get("".join(m.group(0).split()))
        return respelt if respelt is not None else m.group(0)

    def respell(text: str) -> str:
        def one(m):
            base, sub, lbl = _parts(m)
            if (base, sub, lbl) not in names:
                return m.group(0)
            glyph = f"{base}{'_{' + sub + '}' if sub else ''}^{{({lbl})}}"
            return f"{m['acc'].strip()}{glyph}}}" if m["acc"] else glyph
        if bracketed:
            text = _BRACKETED.sub(in_brackets, text)
        if not names:
            return text
        return _LABELLED.sub(one, _LABEL_FIRST.sub(r"\g<sub>^\g<lbl>", text))

    out = [respell(d) for d in decls]
    shown = ", ".join(sorted([f"{b}{_index('_', s)}{_index('^', lbl)}" for b, s, lbl in names]
                             + list(bracketed)))
    return respell(latex), out, (f"{shown}: a superscript frame label (a --let names it), "
                                 f"read as a label, not a power")


def _index(mark: str, text: str) -> str:
    """``_v``, ``_{v2}`` (``mark`` and ``text``) as a reader types it; ``""`` for no text."""
    return "" if not text else f"{mark}{text}" if len(text) == 1 else f"{mark}{{{text}}}"


def each_declaration(let: object) -> list[str] | None:
    """The declarations of ``let`` one by one, or ``None`` for a dict or a value that
    :func:`rigidsym.latex.lets.read_lets` refuses (it says why, later)."""
    if let is None or isinstance(let, dict):
        return None if isinstance(let, dict) else []
    try:
        return split_lets([let] if isinstance(let, str) else let)
    except (TypeError, ValueError):
        return None


_GREEK = (r"\\(?:var)?(?:alpha|beta|gamma|delta|epsilon|zeta|eta|theta|iota|kappa|lambda|mu|"
          r"nu|xi|pi|rho|sigma|tau|upsilon|phi|chi|psi|omega|Gamma|Delta|Theta|Lambda|Xi|Pi|"
          r"Sigma|Upsilon|Phi|Psi|Omega)(?![A-Za-z])")
#: one glyph as a reader types it: a bold letter, an accented glyph, a Greek or Latin letter
_GLYPH = (r"\\(?:mathbf|boldsymbol|bm)\s*(?:\{\s*\\?[A-Za-z]+\s*\}|" + _GREEK
          + r"|[A-Za-z])|\\(?:hat|bar|tilde|check|breve|mathring|vec)\s*\{[^{}]*\}|" + _GREEK
          + r"|(?<![\\A-Za-z])[A-Za-z]")
_GLYPH_END = re.compile(r"(?:" + _GLYPH + r")\s*$")
_SUB_TIMES = re.compile(r"_\s*\\times(?![A-Za-z])")


def _named_cross_subscripts(let: object) -> set[str]:
    """The glyphs ``X`` whose ``X_\\times`` a declaration names on its left (Szeliski's
    ``\\mathbf{v}_\\times = \\hat{\\mathbf{n}}\\times\\mathbf{v}``, a vector): names of
    their own, never respelt, in the LaTeX or the declarations."""
    out = set()
    for d in each_declaration(let) or []:
        name = re.split(r"[:=]", d, maxsplit=1)[0]
        m = _SUB_TIMES.search(name)
        g = _GLYPH_END.search(name[:m.start()]) if m else None
        if g:
            out.add(re.sub(r"\s+", "", g.group(0)))
    return out


def cross_subscripts(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``X_\\times`` of one glyph or of a parenthesised
    expression (Eade's ``\\boldsymbol\\omega_\\times``,
    ``(\\mathbf{R}\\boldsymbol\\omega)_\\times``) respelt ``[X]_\\times`` in the LaTeX
    and the declarations (``note`` says so); else all unchanged and ``note`` is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    hits: list[str] = []
    named = _named_cross_subscripts(let)

    def respell(text: str) -> str:
        k = 0
        while True:
            m = _SUB_TIMES.search(text, k)
            if not m:
                return text
            head = text[:m.start()].rstrip()
            inner = start = None
            if head.endswith(")"):
                close = len(head) - 1 - (6 if head.endswith("\\right)") else 0)
                depth, j = 0, len(head) - 1
                while j >= 0:
                    depth += {")": 1, "(": -1}.get(head[j], 0)
                    if depth == 0:
                        break
                    j -= 1
                if j >= 0:
                    start = j - 5 if head[:j].endswith("\\left") else j
                    inner = head[j + 1:close]
            else:
                g = _GLYPH_END.search(head)
                if g:
                    start, inner = g.start(), g.group(0).strip()
            if inner is None or re.sub(r"\s+", "", inner) in named:
                k = m.end()
                continue
            hits.append(inner)
            new = f"[{inner}]_\\times"
            text = text[:start] + new + text[m.end():]
            k = start + len(new)

    new, out = _respelt(respell, latex, let)
    if not hits:
        return latex, let, ""
    return new, out, (f"{hits[0]}_\\times: the cross-product matrix of {hits[0]} (Eade's "
                      f"subscript), read as [{hits[0]}]_\\times")


_WIDEHAT = re.compile(r"\\widehat\s*\{")
_ONE_GLYPH = re.compile(r"\s*(?:" + _GLYPH + r")\s*(?:_\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]+))?\s*")


def hat_expressions(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\widehat{X}`` whose braces hold more than one glyph
    (Chirikjian's ``\\widehat{R\\boldsymbol\\omega}``, Bullo-Lewis'
    ``\\widehat{\\mathrm{Ad}_g\\xi}``: the hat of a vector expression) respelt
    ``(X)^\\wedge`` in the LaTeX and the declarations (``note`` says so): so(3) of a
    3-vector, se(3) of a 6-vector; else all unchanged and ``note`` is ``""``. A hat over
    one glyph is left to the glyph's reading.

    Args and Raises: as :func:`declared_e`.
    """
    hits: list[str] = []

    def respell(text: str) -> str:
        return _braced_as_cross_matrix(text, _WIDEHAT,
                                       lambda inner: not _ONE_GLYPH.fullmatch(inner), hits,
                                       "({})^\\wedge")

    new, out = _respelt(respell, latex, let)
    if not hits:
        return latex, let, ""
    return new, out, (f"\\widehat{{{hits[0]}}}: the hat of the vector {hits[0]} (so(3) of a "
                      f"3-vector, se(3) of a 6-vector), read as ({hits[0]})^\\wedge")


_DELTA_NAME = re.compile(r"\\Delta\s*(?P<glyph>" + _GLYPH + r")\s*"
                         r"(?P<sub>_\s*(?:\{[^{}]*\}|\\?[A-Za-z0-9]))?")


def _delta_parts(m) -> tuple[str, str]:
    return re.sub(r"\s+", "", m["glyph"]), re.sub(r"[\s{}_]", "", m["sub"] or "")


def declared_deltas(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``\\Delta X_{ij}`` whose NAME a ``--let`` declares
    (Forster et al.'s ``\\Delta\\mathbf{R}_{ij}``, ``\\Delta t_{ij}``) respelt ``X_{\\Delta ij}``,
    one glyph, in the LaTeX and the declarations (``note`` says so); else all unchanged and
    ``note`` is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    decls = each_declaration(let)
    if not decls:
        return latex, let, ""
    names = set()
    for d in decls:
        m = _DELTA_NAME.fullmatch(re.split(r"\s*(?:\(t\))?\s*[:=]", d, maxsplit=1)[0].strip())
        if m:
            names.add(_delta_parts(m))
    if not names:
        return latex, let, ""

    def respell(text: str) -> str:
        def one(m):
            glyph, sub = _delta_parts(m)
            if (glyph, sub) not in names:
                return m.group(0)
            return f"{{{glyph}_{{\\Delta {sub}}}}}"
        return _DELTA_NAME.sub(one, text)

    shown = ", ".join(sorted(f"\\Delta {g}_{{{s}}}" for g, s in names))
    return respell(latex), [respell(d) for d in decls], (
        f"{shown}: one name each (a --let declares it), read as the glyph with Δ in its "
        f"subscript, not Δ times the glyph")


_CONJ_C = re.compile(r"\^\s*(?:\{\s*c\s*\}|c(?![A-Za-z]))")
_QPRODUCT = re.compile(r"\\(?:odot|otimes|star)(?![A-Za-z])")


def conjugate_c(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: where the LaTeX or a declaration uses the quaternion product,
    each ``^c`` (Kok, Hol & Schön's conjugate ``\\mathbf{q}^c``) respelt ``^*`` in the LaTeX
    and the declarations (``note`` says so); else all unchanged and ``note`` is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    decls = each_declaration(let) or []
    if not any(_QPRODUCT.search(t) for t in [latex, *decls]) or \
            not any(_CONJ_C.search(t) for t in [latex, *decls]):
        return latex, let, ""
    new, out = _respelt(lambda t: _CONJ_C.sub("^{*}", t), latex, let)
    return new, out, ("q^c: the conjugate of a quaternion (Kok, Hol & Schön), read as q^*")


#: ``NAME: angular velocity of X`` (the space frame's, unless ``in the body frame`` or
#: ``body angular velocity of X``)
_SPIN = re.compile(r"^\s*(?P<name>.+?)\s*:\s*(?:the\s+)?(?P<body>body\s+)?angular\s+velocity"
                   r"\s+of\s+(?P<of>.+?)(?:\s+in\s+the\s+(?P<frame>body|space)\s+frame)?"
                   r"\s*$")


def angular_velocities(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: each ``--let 'NAME: angular velocity of X'`` (X a rotation of
    time; the books' "ω is the angular velocity of Q") respelt as its model, in the space
    frame ``NAME = (\\dot{X}X^T)^\\vee`` (``\\dot X = [ω]_× X``), in the body frame
    (``... in the body frame``, ``body angular velocity of X``) ``NAME = (X^T\\dot{X})^\\vee``
    (``\\dot X = X [ω]_×``); ``note`` says so. Else all unchanged and ``note`` is ``""``.

    Args and Raises: as :func:`declared_e`.
    """
    decls = each_declaration(let)
    if not decls:
        return latex, let, ""
    out, said = [], []
    for d in decls:
        m = _SPIN.match(d)
        if not m:
            out.append(d)
            continue
        x = m["of"].strip()
        dot = f"\\dot{{{x}}}"
        body = bool(m["body"]) or m["frame"] == "body"
        model = f"({x}^T{dot})^\\vee" if body else f"({dot}{x}^T)^\\vee"
        out.append(f"{m['name'].strip()} = {model}")
        said.append(f"{m['name'].strip()}: the {'body' if body else 'space'} angular velocity "
                    f"of {x}, read as {m['name'].strip()} = {model} ({dot} = "
                    + (f"{x}[{m['name'].strip()}]_\\times)" if body else
                       f"[{m['name'].strip()}]_\\times {x})"))
    if not said:
        return latex, let, ""
    return latex, out, "; ".join(said)
