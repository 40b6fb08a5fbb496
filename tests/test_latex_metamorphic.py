"""Properties of any correct reader, over the corpus (issue 52, item 5): the verdict of an
entry read with its book's table is unchanged when

(a) its ``--let``s come in another order (with two models declared top-down, ``Y = Z``
    before ``Z = (x)``, so the order is one a book could give),
(b) a symbol is renamed consistently (``\\mathbf{u}`` -> ``\\mathbf{h}`` or
    ``\\boldsymbol{\\chi}``, ``\\theta`` -> ``\\kappa``, ``R`` -> ``K``; its table line too),
(c) it is spelt another equivalent way (``^T``/``^\\top``/``^\\mathsf{T}``, ``\\mathbf``/
    ``\\boldsymbol``, ``\\left(``/``(``, ``\\frac{a}{b}``/``((a)/(b))``, spacing),
(d) a declared symbol is replaced by a model of it (``\\mathbf{u}`` -> ``Y`` with
    ``--let 'Y = Z'``, ``--let 'Z = (\\mathbf{u})'``) instead of being written inline,
(e) a ``--let`` line moves into a ``--notation`` table.

Measured on the entries that are decided (verified or does-not-hold); a variant that does
not apply to an entry (nothing to rename, no ``^T``) is skipped and counted. Hypothesis
draws the variants; a quick share runs in the README's command, every entry under ``slow``.
On main before issue 52, (a) and (d) failed: ``Y`` met in its model before ``Z`` was
declared became a free scalar (recorded in docs/check-latex.md).
"""

from __future__ import annotations

import re
import sys
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

HERE = Path(__file__).resolve().parent / "data" / "latex_corpus"
sys.path.insert(0, str(HERE))

import corpus  # noqa: E402

import rigidsym  # noqa: E402
from rigidsym.checking.deciding import registry  # noqa: E402
from rigidsym.latex.notations import NOTATIONS  # noqa: E402

ENTRIES = {e["id"]: e for e in corpus.entries()}
QUICK = ["lynch-park-06", "spong-07", "barfoot-03", "sola-03", "craig-01", "corke-11"]


def verdict(latex: str, lets: list[str], notation: str | None) -> str:
    """``verified``, ``does-not-hold``, ``undecided`` or ``bad-input``."""
    try:
        return rigidsym.check_latex(latex, let=lets, repairs=False, notation=notation).verdict
    except ValueError:
        return "bad-input"
    finally:
        registry.forget_module("rigidsym.latex.letting")


def _case(i: str):
    e = ENTRIES[i]
    book = e["book"]["key"]
    return e["latex"], corpus.lets_of(e), (
        book if book in NOTATIONS else None)


_BASE: dict[str, str] = {}


def base(i: str) -> str:
    if i not in _BASE:
        _BASE[i] = verdict(*_case(i))
    return _BASE[i]


# ------------------------------------------------------------------------------ variants
_BOLD = re.compile(r"\\(?:mathbf|boldsymbol)\{([A-Za-z])\}")
_SPARE = "hkmnqswz"


def _bold_symbols(latex: str, lets: list[str]) -> list[str]:
    """Bold Latin letters declared by a table line (a renaming keeps their kind)."""
    declared = {m.group(1) for x in lets for m in [_BOLD.match(x.split(":")[0].strip())] if m
                and x.split(":")[0].strip() == m.group(0)}
    return sorted(c for c in declared if c.islower() and c not in "eit")


_GREEK = ("alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta",
          "vartheta", "iota", "kappa", "lambda", "mu", "nu", "xi", "rho", "varrho", "sigma", "tau",
          "phi", "varphi", "chi", "psi", "omega")


def _greek_in(text: str) -> set[str]:
    return {g for g in _GREEK if re.search(r"\\" + g + r"(?![A-Za-z])", text)}


def _book_text(notation: str | None) -> str:
    """The lines of the book's --notation table: a letter they name keeps its name."""
    if notation is None:
        return ""
    from rigidsym.latex import notations

    return " ".join(x.text for x in notations.notation(notation).lets)


# a plain capital letter (group 2), not a macro's name nor a letter of a font's argument
_MACRO = (r"(\\(?:mathrm|operatorname|mathcal|mathbf|boldsymbol|bm|text|mathsf)\s*\{[^{}]*\}"
          r"|\\[A-Za-z]+)")


def _capital(c: str) -> re.Pattern:
    return re.compile(_MACRO + "|(" + c + ")")


def _has_capital(text: str, c: str) -> bool:
    return any(m.group(2) for m in _capital(c).finditer(text))


def _occurs(key: str, latex: str) -> bool:
    """``key`` written in ``latex`` as a glyph of its own (not the start of a longer one)."""
    before = r"(?<![\\A-Za-z{^_])" if key[:1].isalpha() else ""
    return re.search(before + re.escape(key) + r"(?![A-Za-z_'])", latex) is not None


def _renamable(latex, lets, notation):
    """What (b) may rename: Greek letters, letters of bold glyphs and plain capitals the
    entry declares; a letter the book's --notation table names for a glyph of the LaTeX
    that no --let of the entry declares keeps its name (so does a Greek letter of any
    glyph the table names: MLS's ``\\hat\\omega``, the skew matrix of ``\\omega``)."""
    text = " ".join([latex, *lets])
    keys = [x.split(":")[0].split("=")[0].strip().removesuffix("(t)") for x in lets]
    book = []
    if notation is not None:
        from rigidsym.latex import notations

        book = [x for x in notations.notation(notation).lets
                if _occurs(x.key, latex) and x.key not in keys
                or x.key not in keys and _greek_in(x.key) & _greek_in(latex)]
    kept = _greek_in(" ".join(x.text for x in book))
    kept_latin = set(re.sub(r"\\[A-Za-z]+", "", " ".join(x.text for x in book)))
    greek = sorted(_greek_in(text) - kept)
    bold = sorted({m.group(1) for k in keys for m in _BOLD.finditer(k)} - set("IOeit")
                  - kept_latin)
    capital = sorted({c for k in keys for c in "ABCDFGHJKLMNPQRSUVWXYZ"
                      if _has_capital(k, c)} - kept_latin)
    return greek, bold, capital


def rename(latex, lets, notation, draw):
    """(b) a symbol renamed everywhere (the LaTeX and its --let lines) into a letter the entry
    does not use: a Greek letter into another (``\\theta`` -> ``\\kappa``, its subscripted,
    dotted and bold forms with it), a bold letter into another or into a bold Greek one
    (``\\mathbf{u}`` -> ``\\mathbf{h}``, ``\\boldsymbol{\\chi}``: Latin <-> Greek), a
    plain capital into another (``{}^A_B R`` -> ``{}^A_B W``)."""
    greek, bold, capital = _renamable(latex, lets, notation)
    text = " ".join([latex, *lets])
    letters = set(re.sub(r"\\[A-Za-z]+", "", text))
    used = _greek_in(text) | _greek_in(_book_text(notation))
    spare_greek = [g for g in ("kappa", "chi", "zeta", "iota", "varrho", "nu") if g not in used]
    spare = [c for c in _SPARE if c not in letters]
    spare_cap = [c for c in "GHKLMNUVW" if not _has_capital(text, c)
                 and c not in _book_text(notation)]
    options = ([("greek", g) for g in greek] * bool(spare_greek)
               + [("bold", c) for c in bold] * bool(spare or spare_greek)
               + [("capital", c) for c in capital] * bool(spare_cap))
    if not options:
        return None
    how, old = draw(st.sampled_from(options))
    if how == "greek":
        new = draw(st.sampled_from(spare_greek))
        rx, sub = re.compile(r"\\" + old + r"(?![A-Za-z])"), (lambda m: "\\" + new)
    elif how == "capital":
        new = draw(st.sampled_from(spare_cap))
        rx, sub = _capital(old), (lambda m: m.group(1) or new)
    else:
        into = draw(st.sampled_from([("mathbf", c) for c in (spare if old.islower() else
                                                             spare_cap)]
                                    + [("boldsymbol", "\\" + g) for g in spare_greek
                                       if old.islower()]))
        rx = re.compile(r"\\(mathbf|boldsymbol)\{" + old + r"\}")
        sub = (lambda m: rf"\{m.group(1)}{{{into[1]}}}") if into[0] == "mathbf" else \
            (lambda m: rf"\boldsymbol{{{into[1]}}}")
    return rx.sub(sub, latex), [rx.sub(sub, x) for x in lets], notation


_SPELLINGS = [
    (re.compile(r"\^T(?![A-Za-z])|\^\{T\}"), [r"^\top", r"^{\top}", r"^\mathsf{T}"]),
    (re.compile(r"\\mathbf\{(?=\\?[A-Za-z]\})"), [r"\boldsymbol{"]),  # a letter, not Ad
    (re.compile(r" "), ["  "]),
    (re.compile(r"="), [" = "]),
]


def _unleft(latex: str) -> str | None:
    if "\\left(" not in latex or latex.count("\\left(") != latex.count("\\right)"):
        return None
    return latex.replace("\\left(", "(").replace("\\right)", ")")


_FRAC = re.compile(r"\\frac\{([^{}]*)\}\{([^{}]*)\}")


def respell(latex, lets, notation, draw):
    """(c) an equivalent spelling of the LaTeX (the --let lines as they were)."""
    options = [(rx, alts) for rx, alts in _SPELLINGS if rx.search(latex)]
    which = draw(st.sampled_from(["sub"] * bool(options) + ["left"] * bool(_unleft(latex))
                                 + ["frac"] * bool(_FRAC.search(latex)) or ["none"]))
    if which == "none":
        return None
    if which == "left":
        return _unleft(latex), lets, notation
    if which == "frac":
        return _FRAC.sub(r"((\1)/(\2))", latex), lets, notation
    rx, alts = draw(st.sampled_from(options))
    alt = draw(st.sampled_from(alts))
    return rx.sub(lambda m: alt, latex), lets, notation


_ACCENTS = r"\\(hat|dot|ddot|tilde|bar|vec|underline)\s*\{?\s*"


def _standalone(latex: str, glyph: str) -> re.Pattern | None:
    """A pattern of ``glyph``'s occurrences in ``latex`` if each is the symbol alone (no
    subscript, prime, accent, argument or index of another glyph), else ``None``."""
    g = re.escape(glyph) + (r"(?![A-Za-z])" if glyph[-1].isalpha() else "")
    rx = re.compile(r"(?<![A-Za-z\\{_^])" + g if not glyph.startswith("\\") else g)
    spots = list(rx.finditer(latex))
    if not spots:
        return None
    for m in spots:
        after, before = latex[m.end():m.end() + 2], latex[:m.start()]
        dual = re.match(r"\^\s*(\*|\{\s*(\*|-\s*T)\s*\})", latex[m.end():])
        if after[:1] in ("_", "'", "(") or dual or re.search(_ACCENTS + r"$", before) \
                or re.search(r"_\s*\{?[^{}]*$", before[-12:]) or before.endswith("\\"):
            return None
    return rx


def model(latex, lets, notation, draw):
    """(d) a symbol a ``NAME: KIND`` line declares, written only alone, replaced by ``Y`` with
    ``Y = Z``, ``Z = (NAME)`` declared top-down (a model that uses a model declared after
    it). Not: a function of time (``\\theta(t)``), a Greek letter the book's --notation
    names, a symbol under Featherstone's dual (``X^*``, ``X^{-T}``: the dual needs the
    kind ``spatial transform``, which a model has not; measured: 5 entries)."""
    if re.search(r"(?<!\\)[YZ]", latex):
        return None
    keys = [x.split(":")[0].strip() for x in lets if ":" in x and "=" not in x.split(":")[0]]
    book = _greek_in(_book_text(notation))
    options = []
    for k in keys:
        if k.endswith(")") or (re.fullmatch(r"\\[a-z]+", k) and k[1:] in book):
            continue
        rx = _standalone(latex, k)
        if rx is not None:
            options.append((k, rx))
    if not options:
        return None
    k, rx = draw(st.sampled_from(options))
    return (rx.sub(lambda m: "{Y}", latex), ["Y = Z", f"Z = ({k})"] + lets, notation)


def permute(latex, lets, notation, draw):
    """(a) the --lets in any order: those of (d)'s variant (a model declared before the one
    it uses) where it applies, else the entry's own --lets."""
    v = model(latex, lets, notation, draw)
    if v is None:
        if len(lets) < 2:
            return None
        v = (latex, lets, notation)
    return v[0], draw(st.permutations(v[1])), v[2]


def into_notation(latex, lets, notation, draw, monkeypatch):
    """(e) one --let line moved into the --notation table (a table of its own, the book's
    lines and that one)."""
    if not lets:
        return None
    from rigidsym.latex import notations
    from rigidsym.latex.lets import read_lets

    moved = draw(st.sampled_from(lets))
    table = notations.notation(notation) if notation else notations.Notation("none", "", (), ())
    (x,) = read_lets([moved])
    mine = replace(table, name="moved", lets=(x, *[y for y in table.lets if y.key != x.key]))
    original = notations.notation
    monkeypatch.setattr(notations, "notation",
                        lambda name: mine if name == "moved" else original(name))
    return latex, [y for y in lets if y != moved], "moved"


PROPERTIES = {"a-permutation": permute, "b-renaming": rename, "c-spelling": respell,
              "d-model": model, "e-notation": into_notation}


def _holds(i: str, prop: str, data, monkeypatch) -> bool:
    """The property on entry ``i``; False if the variant did not apply (skipped)."""
    want = base(i)
    if want not in ("verified", "does-not-hold"):
        return False  # measured on decided inputs
    make = PROPERTIES[prop]
    args = (*_case(i), data.draw)
    v = make(*args, monkeypatch) if prop == "e-notation" else make(*args)
    if v is None:
        return False
    got = verdict(*v)
    assert got == want, f"{i} {prop}: {want} became {got} for {v}"
    return True


@pytest.mark.parametrize("prop", sorted(PROPERTIES))
@settings(max_examples=4, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_the_verdict_is_unchanged_quick(prop, data, monkeypatch):
    i = data.draw(st.sampled_from(QUICK))
    _holds(i, prop, data, monkeypatch)


@pytest.mark.slow
@pytest.mark.parametrize("prop", sorted(PROPERTIES))
@settings(max_examples=1, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=st.data())
def test_the_verdict_is_unchanged_on_every_entry(prop, data, monkeypatch):
    """Every entry once per property (one Hypothesis example draws every entry's variant);
    the variants that apply are counted: a property measured on few entries is no
    property."""
    ran = []
    for i in sorted(ENTRIES):
        if _holds(i, prop, data, monkeypatch):
            ran.append(i)
        monkeypatch.undo()
    decided = [i for i in ENTRIES if base(i) in ("verified", "does-not-hold")]
    # the share of decided entries a variant applies to (measured on 255: a 216, b 223,
    # c 255, d 172, e 255; what is skipped and why: docs/check-latex.md)
    floor = {"a-permutation": 0.8, "b-renaming": 0.85, "c-spelling": 0.95, "d-model": 0.65,
             "e-notation": 0.95}[prop]
    assert len(ran) >= floor * len(decided), (prop, len(ran), len(decided))
