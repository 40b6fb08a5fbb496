"""Per-book notations (``--notation NAME``): what a book's symbols are,
as a table shipped with the package (``rigidsym/latex/notations/NAME.txt``).

A table is ``--let`` lines, one per symbol: ``NAME: KIND`` (a kind of
:data:`rigidsym.latex.lets.KIND_WORDS`) or ``NAME = LATEX`` (a model in the book's own
notation, e.g. Murray-Li-Sastry's ``\\hat\\omega = [\\omega]_\\times``); ``#`` starts a
comment. In a NAME and its LaTeX, ``{i}`` stands for a joint index (digits: ``c_{12}`` with
``c_{i} = \\cos(\\theta_{i})`` is ``\\cos(\\theta_{1} + \\theta_{2})``, the sum of the indexed
angles as Siciliano, Spong and Craig abbreviate) and ``{x}`` for a Greek letter
(``c_{\\theta}``, Spong's ``R_{z,\\theta}`` from ``R_{z,{x}}``). A line ``NAME(params) =
LATEX`` is a function (Craig's ``R_X(\\theta)``), lent where the LaTeX mentions NAME. A
``--let`` of the same symbol wins over the table; a line whose symbol the LaTeX does not use
is ignored (unlike a ``--let``). Every line used is printed under ``read as:``. A line
``\\otimes: JPL`` declares the quaternion product's convention (``jpl``), as the ``--let``
does (:mod:`rigidsym.latex.quaternions`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from importlib import resources

from rigidsym.core.errors import BadInput
from rigidsym.latex import quaternions
from rigidsym.latex.lets import Let, read_lets

__all__ = ["NOTATIONS", "Notation", "notation"]

#: the notations shipped (``rigidsym/latex/notations/NAME.txt``)
NOTATIONS = ("lynch-park", "murray-li-sastry", "siciliano", "spong", "craig", "featherstone",
             "barfoot", "sola", "corke", "jpl")

_INDEX, _GREEK = r"(\d+)", r"(\\[A-Za-z]+)"
_STAND_IN = r"\iota"  # the name's Greek letter of a pattern such as R_{z,{x}}
# the angle of R_{z,{x}}: a Greek letter or a sum of them, with signs, digits and a slash
# (R_{z,\theta+\phi}, R_{z,-\theta}, R_{z,\pi/2}), put in the model in parentheses
_ANGLE = r"((?:[-+]?(?:\\[A-Za-z]+ ?|\d+)(?:/\d+)?)+)"


@dataclass(frozen=True)
class Notation:
    """A book's symbol table.

    Attributes:
        name: its name (``"lynch-park"``).
        title: the book, edition and sections it follows (the file's first comment line).
        lets: the table's literal lines (no ``{i}`` or ``{x}``), as :class:`Let`.
        patterns: ``(regex of a glyph key, placeholder, Let)`` of the lines with one.
        functions: the ``NAME(params) = LATEX`` lines (Craig's ``R_X(\\theta)``), each a
            ``--let`` function wherever the LaTeX mentions NAME and no ``--let`` declares it.
        hat_is_skew: the table's line ``\\hat{*} = [*]_\\times``: every ``\\hat{X}`` (and
            ``\\widehat{X}``) the table does not list is the skew matrix of X, as
            Murray-Li-Sastry's (2.9) defines it for any vector (not only
            ``\\hat\\omega``, so that ``\\widehat{T}R`` reads under the notation a refusal
            names).
    """

    name: str
    title: str
    lets: tuple[Let, ...]
    patterns: tuple[tuple[re.Pattern, str, Let], ...]
    functions: tuple[Let, ...] = ()
    hat_is_skew: bool = False

    def let_for(self, key: str) -> Let | None:
        """The declaration of the glyph ``key`` under this notation, or ``None``."""
        for x in self.lets:
            if x.key == key:
                return x
        for rx, hole, x in self.patterns:
            m = rx.fullmatch(key)
            if m:
                return _instance(x, hole, m.group(1), key)
        m = re.fullmatch(r"\\hat\{(.+)\}", key) if self.hat_is_skew else None
        if m:
            (x,) = read_lets([f"{key} = [{m.group(1)}]_\\times"])
            return x
        return None


def _instance(x: Let, hole: str, value: str, key: str) -> Let:
    """A pattern line for one glyph: ``c_{12} = \\cos(\\theta_{1} + \\theta_{2})``."""
    latex = x.latex
    if latex and hole == "{i}":  # each digit an index: the sum of the indexed glyphs
        m = re.search(r"(\\[A-Za-z]+|[A-Za-z])_\{i\}", latex)
        if m:
            latex = latex.replace(m.group(0), " + ".join(
                f"{m.group(1)}_{{{d}}}" for d in value))
    elif latex:
        latex = latex.replace("{x}", value)
    text = f"{key} = {latex}" if latex else f"{key}: {x.kind}"
    return Let(text, key, key, x.kind, latex)


@cache
def notation(name: str) -> Notation:
    """The notation ``name`` (one of :data:`NOTATIONS`), read from its table once.

    Raises:
        BadInput: an unknown name (the notations listed), or a table line that is no
            declaration (a defect of the table, named with its line number).
    """
    key = (name or "").strip().lower()
    if key not in NOTATIONS:
        raise BadInput(f"--notation: unknown notation {name!r}; expected one of: "
                       f"{', '.join(NOTATIONS)}")
    text = resources.files("rigidsym.latex").joinpath("notations", f"{key}.txt") \
        .read_text("utf-8")
    lines = text.splitlines()
    title = lines[0].lstrip("# ").strip() if lines else key
    lets, patterns, functions, hat = [], [], [], False
    for n, line in enumerate(lines, 1):
        line = line.split(" #")[0].strip() if not line.startswith("#") else ""
        if "".join(line.split()) == "\\hat{*}=[*]_\\times":
            hat = True
            continue
        if not line:
            continue
        name, _, value = line.partition(":")
        if name.strip() in quaternions.NAMES:  # \otimes: JPL, read by quaternions.split_setting
            if quaternions.word(value) != quaternions.NOTATION_PRODUCTS.get(key,
                                                                           quaternions.HAMILTON):
                raise BadInput(f"notation {key}, line {n}: {line} disagrees with "
                               f"rigidsym.latex.quaternions.NOTATION_PRODUCTS")
            continue
        # a Greek letter after a comma of a subscript (Spong's R_{z,{x}}): the name is read
        # with a stand-in letter, which the pattern then matches as any Greek letter
        inner = ",{x}}" in line.split("=")[0]
        try:
            (x,) = read_lets([line.replace(",{x}}", "," + _STAND_IN + "}", 1) if inner
                              else line])
        except (BadInput, ValueError) as exc:
            raise BadInput(f"notation {key}, line {n}: {exc}") from None
        if x.params:  # R_X(\theta) = ...: a function, taken where the LaTeX applies it
            functions.append(x)
            continue
        hole = "{i}" if "_{i}" in x.key else "{x}" if "_{x}" in x.key or inner else ""
        if hole:
            rx = re.escape(x.key).replace(re.escape(_STAND_IN if inner else hole), (
                "{" + _INDEX + "}" if hole == "{i}" else _ANGLE if inner else
                "{" + _GREEK + "}"))
            patterns.append((re.compile(rx), hole, x))
        else:
            lets.append(x)
    return Notation(key, title, tuple(lets), tuple(patterns), tuple(functions), hat)
