"""A display split into relations as a reader reads them.

The body is walked with pylatexenc's LaTeX walker (groups, environments and macro arguments
are TeX's, so a ``=`` inside braces or a matrix never splits). At the top level of the
display (outside parentheses, brackets, ``\\left...\\right`` pairs and groups):

- a chain ``A = B = C`` is ``A = B`` and ``B = C``;
- a line break ``\\\\`` of an ``align``/``eqnarray``/``split``/``aligned``/``gather``/
  ``multline`` ends a line; a line that begins with a relation (``&= D``) relates to the
  previous line's right side; a line with no relation continues the previous right side
  (``multline``, ``&\\quad + x``);
- ``,``, ``;``, ``\\quad``, ``\\qquad`` and prose (``\\text{and}``) separate relations;
- ``\\\\`` inside a matrix (``bmatrix``, ``cases``, ``array``...) stays inside it;
- ``\\label{x}`` and ``\\tag{x}`` name the relations of their line (of the display, where it
  has one label), and so does a printed number closing a line after ``\\quad``
  (``x = y \\quad (3.9a)``, as converted books print it); ``\\nonumber``, ``\\notag`` and
  ``&`` are dropped.

Each :class:`Relation` carries its file, line, column, display number and label.
"""

from __future__ import annotations

from dataclasses import dataclass

from pylatexenc.latexwalker import (
    LatexCharsNode,
    LatexCommentNode,
    LatexEnvironmentNode,
    LatexGroupNode,
    LatexMacroNode,
    LatexMathNode,
    LatexSpecialsNode,
    LatexWalkerError,
)

from rigidsym.core.errors import BadInput
from rigidsym.documents.displays import Display
from rigidsym.documents.macros import definitions, expand, walker
from rigidsym.latex.lexing import OPERATOR_FONTS, OPERATOR_NAMES

__all__ = ["DEFINING", "FLAT", "NOT_CHECKED", "Relation", "relation_ops", "split_display"]

#: environments whose lines are the display's lines (their ``\\`` ends a line)
FLAT = ("align", "align*", "aligned", "alignat", "alignat*", "alignedat", "split", "gather",
        "gather*", "gathered", "multline", "multline*", "eqnarray", "eqnarray*", "equation",
        "equation*", "displaymath", "flalign", "flalign*", "math")
#: relation symbols that define the symbol on their left (a model for what follows)
DEFINING = {":=": ":=", "\\coloneqq": ":=", "\\triangleq": ":=", "\\equiv": "\\equiv",
            "\\defeq": ":=", "\\doteq": ":=", "\\stackrel{\\text{def}}{=}": ":=",
            "\\overset{\\text{def}}{=}": ":=", "\\stackrel{\\mathrm{def}}{=}": ":=",
            "\\overset{\\mathrm{def}}{=}": ":="}
#: relation symbols no verdict is given for, with the reason said
NOT_CHECKED = {
    "\\approx": "an approximation (\\approx)", "\\simeq": "an approximation (\\simeq)",
    "\\sim": "a similarity (\\sim)", "\\propto": "a proportionality (\\propto)",
    "\\cong": "a congruence (\\cong)",
    "<": "an inequality (<)", ">": "an inequality (>)", "\\le": "an inequality (\\le)",
    "\\leq": "an inequality (\\leq)", "\\ge": "an inequality (\\ge)",
    "\\geq": "an inequality (\\geq)", "\\ll": "an inequality (\\ll)",
    "\\gg": "an inequality (\\gg)", "\\neq": "an inequation (\\neq)",
    "\\ne": "an inequation (\\ne)", "\\in": "a membership (\\in: a kind belongs in the "
    "reading file)", "\\subset": "an inclusion (\\subset)",
    "\\subseteq": "an inclusion (\\subseteq)", ":": "a signature (f : A \\to B)",
    "\\colon": "a signature (f \\colon A \\to B)", "\\to": "a map (\\to)",
    "\\rightarrow": "a map or limit (\\rightarrow)", "\\mapsto": "a map (\\mapsto)",
    "\\Rightarrow": "an implication (\\Rightarrow)", "\\implies": "an implication",
    "\\iff": "an equivalence of statements (\\iff)",
    "\\Leftrightarrow": "an equivalence of statements (\\Leftrightarrow)",
    "\\eqqcolon": "a definition written right to left (=:)",
}
_SEPARATORS = ("quad", "qquad", "text", "textrm", "mbox", "mathrm{and}", "hbox", "textnormal",
               "intertext", "shortintertext")
_SPACES = ("\\,", "\\;", "\\!", "\\:", "\\ ", "~")
_OPEN, _CLOSE = "([", ")]"


def relation_ops() -> tuple[str, ...]:
    """Every relation symbol the splitter knows: ``=``, :data:`DEFINING`, :data:`NOT_CHECKED`."""
    return ("=", *DEFINING, *NOT_CHECKED)


@dataclass(frozen=True)
class Relation:
    """One relation of a display.

    Attributes:
        file, line, column: where it stands (its left side's start; for a line that begins
            with ``&=``, the relation symbol's).
        display: the display's number in the document (from 1).
        index: its number in the display (from 1).
        label: the ``\\label``/``\\tag`` of its line or display, ``None`` if none.
        lhs, op, rhs: its two sides and relation symbol as written (macros of the document
            expanded, ``&`` dropped).
        environment: the display's environment.
    """

    file: str
    line: int
    column: int
    display: int
    index: int
    label: str | None
    lhs: str
    op: str
    rhs: str
    environment: str = ""

    @property
    def latex(self) -> str:
        """The relation as one LaTeX string (``lhs op rhs``)."""
        return f"{self.lhs} {self.op} {self.rhs}"

    @property
    def place(self) -> str:
        """``FILE:LINE:COLUMN``."""
        return f"{self.file}:{self.line}:{self.column}"


class _Tokens:
    """The display flattened into tokens ``(kind, text, offset)``, kind one of ``text``,
    ``op``, ``sep``, ``br`` (a line break), ``label``."""

    def __init__(self, origin: list[int]):
        self.out: list[tuple[str, str, int]] = []
        self.depth = 0
        self.delim = 0  # after \left (+1) or \right (-1): the next token is the delimiter
        self.origin = origin

    def at(self, pos: int) -> int:
        return self.origin[min(pos, len(self.origin) - 1)] if self.origin else 0

    def add(self, kind: str, text: str, pos: int) -> None:
        self.out.append((kind, text, self.at(pos)))

    def op(self, text: str, pos: int) -> None:
        self.add("op" if self.depth == 0 else "text", text, pos)

    def chars(self, s: str, pos: int) -> None:
        i = 0
        while i < len(s):
            c = s[i]
            if self.delim:
                self.depth += self.delim
                self.delim = 0
                self.add("text", c, pos + i)
            elif c in _OPEN:
                self.depth += 1
                self.add("text", c, pos + i)
            elif c in _CLOSE:
                self.depth -= 1
                self.add("text", c, pos + i)
            elif self.depth == 0 and c == ":" and s[i + 1:i + 2] == "=":
                self.op(":=", pos + i)
                i += 1
            elif self.depth == 0 and c in "=<>:":
                if c == "=" and self.out and self.out[-1][0] == "op" and \
                        self.out[-1][1] in ("<", ">"):  # <= and >= written so
                    self.out[-1] = ("op", "\\le" if self.out[-1][1] == "<" else "\\ge",
                                    self.out[-1][2])
                else:
                    self.op(c, pos + i)
            elif self.depth == 0 and c in ",;":
                self.add("sep", c, pos + i)
            else:
                self.add("text", c, pos + i)
            i += 1

    def walk(self, nodes, text: str) -> None:
        skip_group = False
        for n in nodes:
            if n is None or isinstance(n, LatexCommentNode):
                continue
            if skip_group and isinstance(n, LatexGroupNode):
                text = n.latex_verbatim()
                if skip_group == "label":
                    self.add("label", text[1:-1].strip(), n.pos)
                elif skip_group is True:
                    self.add("sep", text, n.pos)
                else:  # a font read with no argument (\mbox {...}): an operator or prose
                    kind = "text" if _operator_name(text) else "sep"
                    self.add(kind, skip_group, n.pos)
                    self.add(kind, text, n.pos)
                skip_group = False
                continue
            if isinstance(skip_group, str) and skip_group != "label":  # no argument: prose
                self.add("sep", skip_group, n.pos)
            skip_group = False
            if isinstance(n, LatexCharsNode):
                self.chars(n.chars, n.pos)
            elif isinstance(n, LatexSpecialsNode):
                if n.specials_chars == "&":
                    continue
                self.add("text", " " if n.specials_chars == "~" else n.specials_chars, n.pos)
            elif isinstance(n, LatexGroupNode):
                self.add("text", n.latex_verbatim(), n.pos)
            elif isinstance(n, LatexEnvironmentNode) and n.environmentname in FLAT:
                self.walk(n.nodelist, text)
            elif isinstance(n, LatexEnvironmentNode | LatexMathNode):
                self.add("text", n.latex_verbatim(), n.pos)
            elif isinstance(n, LatexMacroNode):
                skip_group = self.macro(n)

    def macro(self, n) -> bool | str:
        """Add a macro node; ``True`` when the next group is its argument to drop,
        ``"label"`` when it is a label's."""
        name, whole = n.macroname, n.latex_verbatim()
        has_args = bool(n.nodeargd and any(a is not None for a in n.nodeargd.argnlist))
        if name == "\\" and self.depth == 0:
            self.add("br", "\\\\", n.pos)
        elif name in ("label", "tag", "tag*"):
            if not has_args:
                return "label"
            self.add("label", whole[whole.find("{") + 1:whole.rfind("}")].strip(), n.pos)
        elif name in ("nonumber", "notag"):
            pass
        elif name in ("left", "bigl", "Bigl", "biggl", "Biggl"):
            self.delim = 1 if name == "left" else 0
            self.add("text", whole, n.pos)
        elif name in ("right", "bigr", "Bigr", "biggr", "Biggr"):
            self.delim = -1 if name == "right" else 0
            self.add("text", whole, n.pos)
        elif self.delim and not has_args:  # \left\{ ... \right\}: the delimiter
            self.depth += self.delim
            self.delim = 0
            self.add("text", whole, n.pos)
        elif name in ("{", "langle", "lVert", "lvert", "lbrace"):
            self.depth += 1
            self.add("text", whole, n.pos)
        elif name in ("}", "rangle", "rVert", "rvert", "rbrace"):
            self.depth -= 1
            self.add("text", whole, n.pos)
        elif name in OPERATOR_FONTS and has_args and _operator_name(whole[len(name) + 1:]):
            self.add("text", whole, n.pos)  # \text{vect}, \mathrm{tr}: an operator, not prose
        elif self.depth == 0 and name in _SEPARATORS:
            if not has_args and name in OPERATOR_FONTS:
                return whole  # its argument may be an operator's name (walk decides)
            self.add("sep", whole, n.pos)
            return not has_args and name not in ("quad", "qquad")
        elif "\\" + name in NOT_CHECKED or "\\" + name in DEFINING:
            self.op("\\" + name, n.pos)
            if has_args:
                self.add("text", whole[len(name) + 1:], n.pos)
        elif name in ("stackrel", "overset") and has_args and whole.rstrip().endswith("{=}") \
                and self.depth == 0:
            self.op(":=" if "def" in whole else "=", n.pos)
        else:
            self.add("text", whole, n.pos)
        return False


def _operator_name(argument: str) -> bool:
    """Whether a font macro's argument (``{vect}``, ``{ tr }``) is an operator name the
    LaTeX reader knows (:data:`rigidsym.latex.lexing.OPERATOR_NAMES`): then ``\\text{vect}``
    is the operator vect, an operand, not prose that separates relations."""
    a = argument.strip()
    return a.startswith("{") and a.endswith("}") and a[1:-1].strip() in OPERATOR_NAMES


def _clean(text: str) -> str:
    """A side without surrounding space, spacing macros and a closing period or comma."""
    t = " ".join(text.split())
    changed = True
    while changed and t:
        changed = False
        for s in _SPACES + (".", ","):
            if t.endswith(s) and not t.endswith("\\" + s):
                t, changed = t[:-len(s)].rstrip(), True
            if t.startswith(s) and s not in (".", ","):
                t, changed = t[len(s):].lstrip(), True
    return t


def _printed_number(line: list) -> str | None:
    """The equation number a converted book prints at the end of a line, after ``\\quad``
    (``x = y \\quad (3.9a)``, as ``\\tag{3.9a}``): the last segment of the line when it is
    a parenthesised number alone (digits, dots, one letter) and a segment with a relation
    comes before it; else None."""
    if len(line) < 2 or any(k == "op" for k, _, _ in line[-1]) or \
            not any(k == "op" for seg in line[:-1] for k, _, _ in seg):
        return None
    text = "".join(t for _, t, _ in line[-1]).strip().rstrip(".").strip()
    if len(text) < 3 or text[0] != "(" or text[-1] != ")":
        return None
    inner = text[1:-1].strip()
    core = inner[:-1] if inner[-1:].isalpha() and inner[-1:].islower() else inner
    parts = core.split(".")
    return inner if core and all(p.isdigit() for p in parts) else None


def _take_printed_numbers(lines: list, labels: list[list[str]]) -> None:
    """Each line's closing printed number (:func:`_printed_number`) moved to its labels."""
    for li, line in enumerate(lines):
        number = _printed_number(line)
        if number is not None:
            line.pop()
            labels[li].append(number)


def split_display(display: Display) -> list[Relation]:
    """The relations of ``display``, in reading order (:mod:`this module <.relations>`).

    Raises:
        BadInput: a body pylatexenc cannot read (naming the file and line), a line that
            begins with a relation symbol with no line before it to relate to.
    """
    try:  # the display's own definitions (MathJax's \newcommand in a $$ block) first
        raw = walker(display.body, display.macros).get_latex_nodes()[0]
        defined, spans = definitions(raw, display.source.file)
        display.macros.update(defined)
        body = list(display.body)  # the definitions blanked, offsets kept
        for a, b in spans:
            body[a:b] = " " * (b - a)
        text, origin = expand("".join(body), display.macros)
        nodes = walker(text).get_latex_nodes()[0]
    except LatexWalkerError as exc:
        line, _ = display.place(0)
        raise BadInput(f"{display.source.file}:{line}: cannot read the display: {exc}") from None
    toks = _Tokens(origin)
    toks.walk(nodes, text)
    # lines, each a list of segments, each a list of tokens
    lines: list[list[list[tuple[str, str, int]]]] = [[[]]]
    labels: list[list[str]] = [[]]
    for tok in toks.out:
        if tok[0] == "br":
            lines.append([[]])
            labels.append([])
        elif tok[0] == "sep":
            lines[-1].append([])
        elif tok[0] == "label":
            labels[-1].append(tok[1])
        else:
            lines[-1][-1].append(tok)
    _take_printed_numbers(lines, labels)
    all_labels = [x for ls in labels for x in ls]
    pending: list[dict] = []  # relations being built: lhs, op, rhs, pos, line
    carry = ""
    for li, line in enumerate(lines):
        first = True  # no segment of this line read yet
        for seg in line:
            parts: list[list] = [["", None]]  # operand text, offset of its first token
            ops: list[tuple[str, int]] = []
            for kind, t, pos in seg:
                if kind == "op":
                    ops.append((t, pos))
                    parts.append(["", None])
                else:
                    if parts[-1][1] is None and t.strip():
                        parts[-1][1] = pos + (len(t) - len(t.lstrip()))
                    parts[-1][0] += t
            if not ops:
                if not parts[0][0].strip():
                    continue
                if first and li > 0 and pending and pending[-1]["line"] < li:
                    pending[-1]["rhs"] += " " + parts[0][0]  # continues the right side
                elif first and li + 1 < len(lines) and not pending:
                    carry += parts[0][0]  # a left side split over lines
                first = False
                continue  # prose or a list between relations: no relation
            first = False
            lhs, lhs_at = carry + parts[0][0], parts[0][1]
            carry = ""
            if not _clean(lhs):
                if not pending:
                    line_no, _ = display.place(ops[0][1])
                    raise BadInput(f"{display.source.file}:{line_no}: display {display.number} "
                                   f"begins with the relation symbol {ops[0][0]!r} and has "
                                   f"no left side")
                lhs, lhs_at = pending[-1]["rhs"], None
            for (op, op_at), (rhs, _) in zip(ops, parts[1:], strict=True):
                pending.append({"lhs": lhs, "op": op, "rhs": rhs,
                                "at": lhs_at if lhs_at is not None else op_at, "line": li})
                lhs, lhs_at = rhs, None
    out = []
    for i, p in enumerate(pending, start=1):
        line_labels = labels[p["line"]]
        label = line_labels[0] if line_labels else (
            all_labels[0] if len(all_labels) == 1 else display.label)
        line_no, col = display.place(p["at"])
        out.append(Relation(display.source.file, line_no, col, display.number, i, label,
                            _clean(p["lhs"]), p["op"], _clean(p["rhs"]), display.environment))
    return out
