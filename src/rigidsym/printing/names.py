"""Book names of atoms: the ASCII names declarations use (``omega``, ``e_dot``,
``pdot_perp``, ``norm_omega``) in the book's notation, as Unicode text (``ω``, ``ė``, ``ṗ⊥``,
``‖ω‖``) and as LaTeX. The printers of :mod:`rigidsym.printing.notation` print every atom
through these.
"""

from __future__ import annotations

import re

__all__ = ["book_text", "book_group", "book_latex"]

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "lam": "λ",
    "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "upsilon": "υ", "phi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π",
    "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
    # TeX's variants, each a glyph of its own ("read as" printed varphi): \phi is
    # printed φ throughout, so \varphi takes the other form, ϕ; likewise ϵ for \varepsilon
    "varphi": "ϕ", "vartheta": "ϑ", "varepsilon": "ϵ", "varrho": "ϱ", "varpi": "ϖ",
    "varsigma": "ς", "varkappa": "ϰ", "Upsilon": "Υ",
}
_ACCENTS = ("ddot", "dot", "tilde", "hat", "bar", "mathring", "breve", "check", "vec",
            "underline")
_COMBINING = {"dot": "\u0307", "ddot": "\u0308", "tilde": "\u0303", "hat": "\u0302",
              "bar": "\u0304", "mathring": "\u030a", "breve": "\u0306", "check": "\u030c",
              "vec": "\u20d7", "underline": "\u0332"}
_SUB_TEXT = {"par": "∥", "perp": "⊥", "inf": "∞"}
_SUB_LATEX = {"par": r"\parallel", "perp": r"\perp", "inf": r"\infty"}
#: name parts that are primes in the book (``e_2prime`` is e'', ``V_alt`` is the
#: other V, V'): the count of primes each adds
_PRIME_TAGS = {"prime": 1, "alt": 1, **{f"{k}prime": k for k in range(2, 4)}}
SUBSCRIPT_DIGITS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
#: names the chapter's declarations give to tell apart two uses of one book letter, or
#: a model's free atoms, printed as the book prints them: the wrench's
#: pitch is p'' (3.109) in both its forms, the A and b of (3.11) and of (3.66) are both A
#: and b; the name is code, what a reader sees is the book's glyph. The pitch of (3.7)
#: stays "pitch" in both forms: its p would read as the point p beside it in (3.71)'s
#: screw array s = [e; p e + P e]
_BOOK_NAMES = {"pitch_turn": "pitch", "p_wrench": "p''", "p_wrench_turn": "p''",
               "A_isa": "A", "b_isa": "b", "r_isa": "r", "A_screw": "A", "b_screw": "b",
               "A_amp": "A", "alpha_AtA": "alpha", "beta_AtA": "beta",
               "lambda_mc": "lambda", "w_axis": "w", "d0_axial": "d_0", "d0_vec": "d_0"}
#: names printed as a compound of the book's glyphs: (Unicode text, LaTeX, LaTeX in bold)
_BOOK_COMPOUNDS = {"p_star": ("p*", "p^{*}", r"\mathbf{p}^{*}"),
                   "AtA_inv": ("(AᵀA)⁻¹", r"(\mathbf{A}^T\mathbf{A})^{-1}",
                               r"(\mathbf{A}^T\mathbf{A})^{-1}")}
#: a declaration module's private prefix on atom names (``s34_adot``, ``sec342_vdot``)
_PRIVATE = re.compile(r"^(?:s|sec|ex)\d{2,}_")


def strip_private(name: str) -> str:
    """An atom name without its declaration module's private prefix (``s34_adot`` ->
    ``adot``)."""
    return _PRIVATE.sub("", name)
#: an entry of a reader's vector renamed beside a scalar of the same glyph (``a__1`` beside
#: ``a_1``, :func:`rigidsym.latex.values._fresh`): printed ``(a)₁``, never the scalar's ``a₁``
_RENAMED_ENTRY = re.compile(r"(.*[^_])__+(\d{1,2})")


def _parse(name: str) -> tuple[str, list[str], list[str], str]:
    """Split an ASCII atom name into (base, accents, subscripts, primes)."""
    name = _PRIVATE.sub("", name)
    primes = ""
    while name.endswith("'"):
        primes, name = primes + "'", name[:-1]
    tokens = [t for t in name.split("_") if t]
    if len(tokens) > 1:  # primes anywhere after the base: e_2prime, p_0_2prime, L_alt_dot
        primes += "'" * sum(_PRIME_TAGS.get(t, 0) for t in tokens[1:])
        tokens = tokens[:1] + [t for t in tokens[1:] if t not in _PRIME_TAGS]
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
            if base.endswith(acc) and (stem in GREEK or len(stem) == 1
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
    if name in _BOOK_COMPOUNDS:
        return _BOOK_COMPOUNDS[name][0]
    if m := _RENAMED_ENTRY.fullmatch(name):
        return f"({book_text(m.group(1))}){m.group(2).translate(SUBSCRIPT_DIGITS)}"
    base, accents, subs, primes = _parse(_BOOK_NAMES.get(name, name))
    out = GREEK.get(base, base)
    if len(out) == 1:
        out += "".join(_COMBINING[a] for a in accents)
    else:
        out += "".join("_" + a for a in accents)
    out += primes
    if _entry_of_subscripted(subs):  # I_C_21: the entry (2, 1) of I_C, (I_C)₂₁, not I_C₂₁
        return f"({book_text(name.rsplit('_', 1)[0])})" + subs[-1].translate(SUBSCRIPT_DIGITS)
    for s in subs:
        if s in _SUB_TEXT:
            out += _SUB_TEXT[s]
        elif s.isdigit():
            out += s.translate(SUBSCRIPT_DIGITS)
        else:   # a Greek subscript in its letter (Craig's c_θ, Spong's R_z,θ+φ), as the base is
            out += "_" + re.sub(r"[A-Za-z]+", lambda m: GREEK.get(m.group(0), m.group(0)), s)
    return out


def _entry_of_subscripted(subs: list[str]) -> bool:
    """Whether the subscripts are a letter subscript and then an entry's digits (``C``,
    ``21`` of ``I_C_21``): two subscripts on one letter would read as one."""
    return len(subs) > 1 and subs[-1].isdigit() and not subs[-2].isdigit() \
        and subs[-2] not in _SUB_TEXT


def has_subscript(name: str) -> bool:
    """Whether an atom's book name carries a subscript (``M_A``, ``pdot_perp``, ``x_1``): an
    entry of it is printed ``(M_A)₁₂``, never with a second subscript."""
    return bool(_RENAMED_ENTRY.fullmatch(name) or _parse(_BOOK_NAMES.get(name, name))[2])


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
    if name in _BOOK_COMPOUNDS:
        return _BOOK_COMPOUNDS[name][2 if bold else 1]
    if m := _RENAMED_ENTRY.fullmatch(name):  # an entry of a vector: the vector in bold
        return rf"\left({book_latex(m.group(1), bold=True)}\right)_{{{m.group(2)}}}"
    base, accents, subs, primes = _parse(_BOOK_NAMES.get(name, name))
    if base in GREEK:
        core = "\\" + ("lambda" if base == "lam" else base)
        core = rf"\boldsymbol{{{core}}}" if bold else core
    elif len(base) == 1:
        core = rf"\mathbf{{{base}}}" if bold else base
    else:
        core = rf"\mathrm{{{base}}}"
    for a in accents:
        core = rf"\{a}{{{core}}}"
    core += primes
    if _entry_of_subscripted(subs):  # (\mathbf{I}_{C})_{21}: as the text's (I_C)₂₁
        return rf"\left({book_latex(name.rsplit('_', 1)[0], True)}\right)_{{{subs[-1]}}}"
    if subs:  # a word (isa, wrench) upright, as one symbol, not a product of letters
        core += "_{" + ",".join(_SUB_LATEX.get(s) or (rf"\mathrm{{{s}}}" if len(s) > 1
                                                      and s.isalpha() else s)
                                for s in subs) + "}"
    return core
