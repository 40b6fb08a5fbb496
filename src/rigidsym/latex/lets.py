"""The declarations of ``rigidsym check --latex``: ``--let NAME: KIND``
and ``--let NAME = LATEX``, read and checked (:func:`read_lets`), and the other sources of
what a reader's symbols are: a trailing ``, R \\in SO(3)`` of the LaTeX
(:func:`declared_lets`) and the symbols and models a reader's modules lend (:func:`lent`,
also to a module's own ``equation(..., latex=...)``).

A ``--let`` (``let=`` in Python) says what a symbol is. A KIND is a constrained kind of
:mod:`rigidsym.core.kinds` (unit vector, unit 4-vector, rotation, angle; imposed exactly by
the zero test), a free shape, or a word of the vocabulary of rigid motions (twist, wrench,
transform, so(3), se(3)): :data:`KIND_WORDS`. ``NAME = LATEX`` is a first-principles model in
the same notation. A NAME is compared after parsing (``\\mathbf Q`` is ``\\mathbf{Q}``).
``rigidsym.latex.statement`` reads the LaTeX itself with these.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp

from rigidsym.algebra import symbols as _sym
from rigidsym.algebra.rigid_motions import Ad, hat, transform
from rigidsym.core.errors import BadInput, did_you_mean
from rigidsym.latex.kinematics import rate_target
from rigidsym.latex.let_text import split_lets
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.shapes import LatexError
from rigidsym.latex.transformer.book_notations import SETS

__all__ = ["KIND_WORDS", "Let", "kind_of", "let_items", "model_names", "model_spelling",
           "rated_lets", "read_lets", "respell_model_names", "split_lets", "without_lets"]

#: the kinds a ``--let NAME: KIND`` takes, in words (``n``, ``m``: sizes, e.g. ``6-vector``,
#: ``4x4 matrix``)
KIND_WORDS = ("unit vector", "unit 4-vector", "rotation", "angle", "angle in [0, pi]",
              "scalar", "vector", "n-vector", "matrix", "m×n matrix", "symmetric matrix",
              "twist", "wrench", "transform", "spatial transform", "so(3)", "se(3)")

_FIXED = {  # words -> (shape, model of the named symbol, words in the reading)
    "unit vector": ((3, 1), _sym.unit_vector, "unit vector"),
    "unit 3-vector": ((3, 1), _sym.unit_vector, "unit vector"),
    "unit 4-vector": ((4, 1), _sym.unit_vector4, "unit 4-vector"),
    "rotation": ((3, 3), _sym.rotation, "rotation"),
    "rotation matrix": ((3, 3), _sym.rotation, "rotation"),
    "angle": ((), _sym.angle, "angle"),
    "angle in [0, pi]": ((), lambda n: _sym.angle(n, range="[0, pi]"), "angle in [0, π]"),
    "scalar": ((), _sym.scalar, "scalar"),
    "vector": ((3, 1), _sym.vector, "3-vector"),
    "matrix": ((3, 3), _sym.matrix, "3×3 matrix"),
    "symmetric matrix": ((3, 3), _sym.symmetric_matrix, "symmetric 3×3 matrix"),
    "twist": ((6, 1), _sym.twist, "twist [ω; v]"),
    "wrench": ((6, 1), _sym.wrench, "wrench [n; f]"),
    "transform": ((4, 4), lambda n: transform(_sym.rotation(f"{n}_R"), _sym.vector(f"{n}_p")),
                  "homogeneous transform (rotation and translation)"),
    # Featherstone's Plücker transform of motion vectors [E 0; -E r×, E] (RBDA (2.24)): the
    # adjoint of the 4x4 transform (E, -E r), so every one is Ad of a rotation and a vector
    "spatial transform": ((6, 6), lambda n: Ad(transform(_sym.rotation(f"{n}_E"),
                                                         _sym.vector(f"{n}_r"))),
                          "spatial transform (Plücker, 6×6: [E 0; −E r×, E])"),
    "so(3)": ((3, 3), lambda n: hat(_sym.vector(n)), "so(3) matrix: the hat of a free 3-vector"),
    "se(3)": ((4, 4), lambda n: hat(_sym.vector(n, n=6)),
              "se(3) matrix: the hat of a free twist [ω; v]"),
}


def kind_of(text: str, decl: str):
    """What a KIND says.

    Args:
        text: the KIND as written (``"unit vector"``, ``"6-vector"``, ``"4×4 matrix"``).
        decl: the declaration it comes from (for the message).

    Returns:
        ``(shape, factory, words)``: the shape (``()`` or ``(rows, cols)``), the model of
        a symbol of that kind by name (``factory("Q")``) and the kind in words.

    Raises:
        BadInput: an unknown KIND (the message lists the kinds).
    """
    t = text.lower().replace("×", "x").replace("π", "pi").replace("\\pi", "pi")
    t = " ".join(t.split())
    t = re.sub(r"\[\s*0\s*,\s*pi\s*\]", "[0, pi]", t)
    t = t.replace("angle on [0, pi]", "angle in [0, pi]")
    if t in _FIXED:
        return _FIXED[t]
    m = re.fullmatch(r"(\d+)-vector", t)
    if m and int(m.group(1)) >= 1:
        n = int(m.group(1))
        return (n, 1), (lambda name: _sym.vector(name, n=n)), f"{n}-vector"
    m = re.fullmatch(r"(\d+) ?x ?(\d+) matrix", t)
    if m and int(m.group(1)) >= 1 and int(m.group(2)) >= 1:
        r, c = int(m.group(1)), int(m.group(2))
        return (r, c), (lambda name: _sym.matrix(name, r, c)), f"{r}×{c} matrix"
    raise BadInput(f"--let '{decl}': unknown kind {text.strip()!r}"
                   f"{did_you_mean(t, KIND_WORDS) or ';'} expected one of: "
                   f"{', '.join(KIND_WORDS)}")


@dataclass(frozen=True)
class Let:
    """One declaration of a ``--let``.

    Attributes:
        text: as written (``"\\mathbf{Q}: rotation"``).
        name: the NAME as written.
        key: the glyph's key after parsing (``\\mathbf{Q}``).
        kind: the KIND as written, or ``""`` for a model.
        latex: the model's LaTeX, or ``""`` for a kind.
        params: a function's parameters as written (``S(\\mathbf{a}) = ...``: ``("\\mathbf{a}",)``),
            ``()`` for a symbol.
        param_keys: their glyph keys.
    """

    text: str
    name: str
    key: str
    kind: str = ""
    latex: str = ""
    params: tuple[str, ...] = ()
    param_keys: tuple[str, ...] = ()


def _top_level(text: str, ch: str) -> int:
    depth = 0
    for i, c in enumerate(text):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == ch and depth == 0:
            return i
    return -1


def _split_commas(text: str) -> list[str]:
    """``text`` split at the commas outside braces (``\\phi,\\theta,\\psi``)."""
    out, depth, start = [], 0, 0
    for i, c in enumerate(text):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == "," and depth == 0:
            out.append(text[start:i])
            start = i + 1
    return out + [text[start:]]


def _key(name: str, decl: str) -> str:
    """The glyph key of a NAME (``\\mathbf Q`` -> ``\\mathbf{Q}``)."""
    if not name:
        raise BadInput(f"--let '{decl}': expected a NAME before ':' or '='")
    star = re.fullmatch(r"(.*?)\s*\^\s*(?:\*|\{\s*\*\s*\}|\\ast|\{\s*\\ast\s*\})", name)
    if star and star.group(1):  # {}^B X_A^{*}: a starred name of its own
        return _key(star.group(1), decl) + "^{*}"
    ranged = re.fullmatch(r"(.+?)_\{\s*(\d+)\s*:\s*(\d+)\s*\}", name.strip())
    if ranged:  # q_{1:3}: entries of q, read so in the LaTeX (said, not "one symbol")
        base, lo, hi = ranged.groups()
        raise BadInput(f"--let '{decl}': {name.strip()} is entries {lo} to {hi} of {base}, "
                       f"not a symbol of its own: declare {base} (e.g. --let '{base}: "
                       f"{max(int(hi), 4)}-vector', or its model) and {name.strip()} is read "
                       f"from it")
    if name.strip() == "t":  # time: what X(t) and \dot X are functions of
        raise BadInput(f"--let '{decl}': t is time, the variable of every X(t) and the "
                       f"derivative of every \\dot X, read without a declaration; a glyph of "
                       f"your own needs another name (t_0, \\tau)")
    try:
        p = parse_latex(f"{name} = 0", None)
    except LatexError as exc:
        raise BadInput(f"--let '{decl}': the name '{name}' cannot be read: "
                       f"{str(exc).splitlines()[0]}") from None
    lhs = p.chains[0][0] if p.chains else None
    if len(p.glyphs) != 1 or not isinstance(lhs, sp.Symbol | sp.MatrixSymbol):
        raise BadInput(f"--let '{decl}': expected one symbol as NAME (a glyph such as "
                       f"\\mathbf{{Q}} or \\phi), got '{name}'")
    return next(iter(p.glyphs))


def read_lets(let) -> list[Let]:
    """The declarations of ``let``.

    Args:
        let: ``None``, one string, a list of strings (``"NAME: KIND"`` or ``"NAME =
            LATEX"``, each possibly several separated by ``"; "``), or a dict ``{NAME:
            KIND or LATEX}`` (a value that is a KIND is a kind, anything else a model; a
            word or words that are no KIND, ``"rotaton"``, are an error: write ``"= abcd"``
            for a model that is a product of letters).

    Returns:
        One :class:`Let` per declaration, in order.

    Raises:
        BadInput: a declaration that is neither form, a NAME that is not one glyph, an
            unknown KIND (the kinds listed), a name declared twice.
    """
    items = let_items(let)
    names = model_names(items)
    out = [_one_let(respell_model_names(d, names)) for d in items]
    seen: dict[str, Let] = {}
    for x in out:
        if x.key in seen:
            raise BadInput(f"--let: {x.key} is declared twice ('{seen[x.key].text}' and "
                           f"'{x.text}')")
        seen[x.key] = x
    return out


_BOLD_NAME = re.compile(r"\\mathbf\s*\{\s*([A-Za-z][A-Za-z0-9_]*)\s*\}")
_BARE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)*")


def model_spelling(name: str) -> str:
    """The glyph a name of the model is read as: ``w_axis`` -> ``\\mathrm{w\\_axis}`` (as
    LaTeX prints the name, upright, one symbol).

    Args:
        name: the name of the model, without ``\\mathbf``.

    Returns:
        The LaTeX of its glyph.
    """
    return "\\mathrm{" + name.replace("_", "\\_") + "}"


def model_names(texts) -> dict[str, str]:
    """The names of the model that the declarations ``texts`` declare by a kind: a
    ``NAME: KIND`` whose NAME is a name of the model, not a LaTeX glyph, a bare identifier
    that is not one glyph (``ell``, ``d0_axial``, ``sec342_sigma``; ``m_1`` is the glyph
    m₁) or a bold one (``\\mathbf{w_axis}``, ``\\mathbf{rw}``).

    Args:
        texts: the declarations, one string each (:func:`let_items`).

    Returns:
        ``{NAME as written: the glyph it is read as}`` (:func:`model_spelling`); raises
        nothing.
    """
    out: dict[str, str] = {}
    for d in texts:
        colon, eq = _top_level(d, ":"), _top_level(d, "=")
        if colon < 0 or 0 <= eq < colon:
            continue
        name = d[:colon].strip().removesuffix("(t)").strip()
        bold = _BOLD_NAME.fullmatch(name)
        if bold and len(bold.group(1)) > 1 and bold.group(1) not in ("Ad", "ad"):
            out[name] = model_spelling(bold.group(1))
        elif _BARE_NAME.fullmatch(name) and len(name) > 1:
            try:
                _key(name, d)
            except (BadInput, LatexError, ValueError):
                out[name] = model_spelling(name)
    return out


def respell_model_names(text: str, names: dict[str, str]) -> str:
    """``text`` with each name of the model of ``names`` written as the glyph it is read
    as: a bold one wherever it stands, a bare one where it stands alone (not part of a
    macro, a word or another name).

    Args:
        text: a declaration or LaTeX.
        names: :func:`model_names`' answer.

    Returns:
        The text respelt (``text`` itself when ``names`` is empty).
    """
    if not names:
        return text
    alts = sorted(names, key=len, reverse=True)
    pat = "|".join(re.escape(n) if n.startswith("\\") else
                   r"(?<![\\A-Za-z_])(?<!\\mathrm\{)(?<!\\operatorname\{)"
                   + re.escape(n) + r"(?![A-Za-z0-9_])" for n in alts)
    return re.sub(pat, lambda m: names[m.group(0)], text)


def without_lets(let, keys) -> list[str]:
    """The declarations of ``let`` less those whose NAME's glyph key is one of ``keys``.

    Args:
        let: the declarations, as :func:`read_lets` takes them (a string, a list, a dict).
        keys: glyph keys (``\\mathbf{L}``) whose declarations are left out.

    Returns:
        The other declarations, one string each, in order.

    Raises:
        rigidsym.core.errors.BadInput: as :func:`read_lets`.
    """
    items, keys = let_items(let), set(keys)
    return [d for d, x in zip(items, read_lets(items), strict=True) if x.key not in keys]


def let_items(let) -> list[str]:
    """The declaration strings of ``let``, a dict's values written as ``NAME: KIND`` or
    ``NAME = LATEX``.

    Args:
        let: :func:`read_lets`' argument: ``None``, a string, a list of strings or a dict
            ``NAME -> KIND or LaTeX``.

    Returns:
        The declarations, one string each, in order.

    Raises:
        rigidsym.core.errors.BadInput: a dict whose keys or values are not strings.
    """
    if let is None:
        return []
    if isinstance(let, str):
        return split_lets([let])
    if isinstance(let, dict):
        items = []
        for name, value in let.items():
            if not isinstance(name, str) or not isinstance(value, str):
                raise BadInput(f"let: expected a dict of strings NAME -> KIND or LaTeX, got "
                               f"{name!r}: {value!r}")
            v = value.strip()
            try:
                kind_of(v, f"{name}: {v}")
                items.append(f"{name}: {v}")
            except BadInput as exc:
                if re.fullmatch(r"[A-Za-z]+(?:[ -][A-Za-z]+)*", v) and (" " in v or len(v) > 3):
                    # a word that is no kind ('rotaton'), not a product of letters
                    raise BadInput(f"{exc} (a model written in letters: '= {v}')") from None
                items.append(f"{name} = {v.removeprefix('=').strip()}")
        return items
    if isinstance(let, list | tuple):
        if not all(isinstance(x, str) for x in let):
            raise BadInput(f"let: expected strings 'NAME: KIND' or 'NAME = LATEX', got "
                           f"{let!r}")
        return split_lets(let)
    raise BadInput(f"let: expected a list of strings or a dict, got {type(let).__name__}")


def _one_let(d: str) -> Let:
    """One declaration: ``NAME: KIND``, ``NAME = LATEX`` or ``NAME(params) = LATEX``."""
    colon, eq = _top_level(d, ":"), _top_level(d, "=")
    if colon >= 0 and (eq < 0 or colon < eq):
        name, kind = d[:colon].strip(), d[colon + 1:].strip()
        kind_of(kind, d)
        return Let(d, name, _key(name, d), kind=kind)
    if eq >= 0:
        name, tex = d[:eq].strip(), d[eq + 1:].strip()
        params: tuple[str, ...] = ()
        applied = re.fullmatch(r"(.+?)\s*\(([^()]+)\)", name)
        if applied:  # S(\mathbf{a}) = ...: a function of its parameters
            name = applied.group(1)
            params = tuple(q.strip() for q in _split_commas(applied.group(2)))
            if not all(params):
                raise BadInput(f"--let '{d}': expected parameters NAME(a, b, ...), "
                               f"got an empty one")
        if not tex:
            raise BadInput(f"--let '{d}': expected LaTeX after '='")
        keys = tuple(_key(q, d) for q in params)
        if len(set(keys)) != len(keys):
            raise BadInput(f"--let '{d}': a parameter is named twice")
        return Let(d, name, _key(name, d), latex=tex, params=params, param_keys=keys)
    raise BadInput(f"--let '{d}': expected 'NAME: KIND' (e.g. '\\mathbf{{Q}}: "
                   f"rotation') or 'NAME = LATEX' (e.g. '\\mathbf{{E}} = "
                   f"\\mathrm{{CPM}}(\\mathbf{{e}})')")


def rated_lets(lets: list[Let]) -> list[Let]:
    """The symbols whose rate a ``--let '\\dot{X} = ...'`` declares and no ``--let``
    declares: each a function of time of the book's conventional shape (bold lower-case a
    3-vector, bold capital 3x3, else a scalar), as ``--let 'X(t): KIND'``.

    Args:
        lets: the ``--let`` declarations as read (:func:`read_lets`).

    Returns:
        One new :class:`Let` per such symbol, in the order of the rates; empty when every
        rated symbol is declared. Raises nothing.
    """
    own = {x.key for x in lets}
    out = []
    for x in lets:
        k = rate_target(x.key) if x.latex and not x.params else ""
        if not k or k in own:
            continue
        bold = re.match(r"\\(mathbf|boldsymbol)\{\\?([A-Za-z]+)\}", k)
        kind = "scalar" if not bold else ("matrix" if bold.group(2)[0].isupper() else "vector")
        out.append(Let(f"{k}(t): {kind}", f"{k}(t)", k, kind=kind))
        own.add(k)
    return out


# --------------------------------------------------------------------- from the LaTeX
_DECL = re.compile(r"(?:(?:,|\\q?quad)\s*)+(?:\\forall\s*)?([^=,]*?)\s*\\in\s*"
                   r"(SO\(3\)|SE\(3\)|so\(3\)|se\(3\))\s*[.,]?\s*$")


def declared_lets(latex: str, lets: list) -> list:
    """The ``--let`` a trailing ``, R \\in SO(3)`` (``SE(3)``, ``so(3)``, ``se(3)``) states,
    when no ``--let`` declares that symbol already (one that does is checked against it by
    the parse)."""
    m = _DECL.search(latex)
    if not m or not m.group(1).strip():
        return []
    new = read_lets([f"{m.group(1).strip()}: {SETS[m.group(2)][1]}"])
    return [x for x in new if x.key not in {y.key for y in lets}]


# --------------------------------------------------------------------- lent by modules
def lent(modules) -> dict:
    """The symbols and models user modules lend, by name.

    A module's models are its module-level dicts whose keys are all book symbols (``MODEL``
    first, then in module order; the first value of a name wins); its symbols are those
    keys and its module-level symbols (a constrained atom such as ``angle("theta")`` lends
    itself as its model).

    Args:
        modules: paths, dotted names or module objects
            (:func:`rigidsym.registry.usermodules.load`).

    Returns:
        ``{name: (symbol, model value or None)}``.

    Raises:
        BadInput: a module that cannot be loaded.
    """
    import sys
    from types import ModuleType

    from rigidsym.registry import usermodules

    out: dict = {}
    for m in modules or ():
        um = usermodules.adopt(m) if isinstance(m, ModuleType) else usermodules.load(m)
        for name, v in module_symbols(vars(sys.modules[um.name])).items():
            out.setdefault(name, v)
    return out


def module_symbols(names: dict) -> dict:
    """What one module's namespace lends (see :func:`lent`): ``{name: (symbol, value)}``."""
    out: dict = {}
    dicts = [v for v in names.values() if isinstance(v, dict) and v and all(
        isinstance(k, sp.Symbol | sp.MatrixSymbol) for k in v)]
    if isinstance(names.get("MODEL"), dict) and names["MODEL"] in dicts:
        dicts.remove(names["MODEL"])
        dicts.insert(0, names["MODEL"])
    for d in dicts:
        for sym, value in d.items():
            out.setdefault(sym.name, (sym, value))
    for v in names.values():
        if isinstance(v, sp.MatrixSymbol) or (isinstance(v, sp.Symbol)
                                              and not isinstance(v, sp.Dummy)):
            out.setdefault(v.name, (v, v if _sym.constraint_of(v) is not None else None))
    return out
