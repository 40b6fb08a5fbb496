"""A document's own macros: ``\\newcommand``, ``\\renewcommand``, ``\\def`` and
``\\DeclareMathOperator``, found and expanded with pylatexenc's LaTeX walker (TeX's own
reading of where a macro and its arguments end; no regular expressions of our own).

An expansion keeps, for every character of its result, the offset in the original text it
comes from (a macro's expansion: the macro's own offset), so a relation read from expanded
LaTeX is still located in the file.
"""

from __future__ import annotations

from pylatexenc import macrospec
from pylatexenc.latexwalker import (
    LatexCharsNode,
    LatexCommentNode,
    LatexEnvironmentNode,
    LatexGroupNode,
    LatexMacroNode,
    LatexMathNode,
    LatexWalker,
    LatexWalkerError,
    get_default_latex_context_db,
)

from rigidsym.core.errors import BadInput

__all__ = ["DEFINERS", "definitions", "expand", "walker"]

#: the macros that define macros
DEFINERS = ("newcommand", "renewcommand", "providecommand", "DeclareMathOperator", "def")
#: how deep an expansion may nest before it is refused (a macro that expands to itself)
DEPTH = 20


def walker(text: str, macros: dict | None = None) -> LatexWalker:
    """A LaTeX walker over ``text`` that knows the arguments of ``macros``
    (``{name: (n, default, body)}``) and of the definers."""
    db = get_default_latex_context_db()
    specs = [macrospec.MacroSpec("DeclareMathOperator", "*{{")]
    for name, (n, default, _) in (macros or {}).items():
        specs.append(macrospec.MacroSpec(name, ("[" if default is not None else "")
                                         + "{" * (n - (default is not None))))
    db.add_context_category("document-macros", macros=specs, prepend=True)
    return LatexWalker(text, latex_context=db, tolerant_parsing=True)


def _inner(node) -> str:
    """The text inside a group node's braces (or the node's text)."""
    if isinstance(node, LatexGroupNode):
        return "".join(n.latex_verbatim() for n in node.nodelist)
    return node.latex_verbatim() if node is not None else ""


def definitions(nodes, where: str) -> tuple[dict, list[tuple[int, int]]]:
    """The macros ``nodes`` define (at their top level), and the spans ``(pos, end)`` of the
    definitions (to leave out of a display).

    Args:
        nodes: pylatexenc nodes.
        where: the file (named in messages).

    Raises:
        BadInput: a definition whose name or body cannot be read (named with its text).
    """
    out: dict = {}
    spans = []
    i = 0
    nodes = [n for n in nodes if n is not None]
    while i < len(nodes):
        n = nodes[i]
        if isinstance(n, LatexMacroNode) and n.macroname in DEFINERS[:3]:
            args = n.nodeargd.argnlist if n.nodeargd else []
            # newcommand's arguments: *, {name}, [n], [default], {body}
            name = _inner(args[1]).strip().lstrip("\\") if len(args) > 4 else ""
            if not name or args[4] is None:
                raise BadInput(f"{where}: cannot read the macro definition "
                               f"{n.latex_verbatim()!r}")
            count = int(_inner(args[2]).strip("[] ") or 0) if args[2] is not None else 0
            default = _inner(args[3]).strip("[]") if args[3] is not None else None
            out[name] = (count, default, _inner(args[4]))
            spans.append((n.pos, n.pos + n.len))
        elif isinstance(n, LatexMacroNode) and n.macroname == "DeclareMathOperator":
            args = n.nodeargd.argnlist if n.nodeargd else []
            name = _inner(args[1]).strip().lstrip("\\") if len(args) > 2 else ""
            out[name] = (0, None, f"\\operatorname{{{_inner(args[2])}}}")
            spans.append((n.pos, n.pos + n.len))
        elif isinstance(n, LatexMacroNode) and n.macroname == "def":
            # \def\name#1#2{body}: the name, its parameter text, then a group
            j, params = i + 1, 0
            if j < len(nodes) and isinstance(nodes[j], LatexMacroNode):
                name = nodes[j].macroname
                j += 1
                while j < len(nodes) and isinstance(nodes[j], LatexCharsNode) \
                        and not isinstance(nodes[j], LatexGroupNode):
                    params += nodes[j].chars.count("#")
                    j += 1
                if j < len(nodes) and isinstance(nodes[j], LatexGroupNode):
                    out[name] = (params, None, _inner(nodes[j]))
                    spans.append((n.pos, nodes[j].pos + nodes[j].len))
                    i = j + 1
                    continue
            raise BadInput(f"{where}: cannot read the macro definition starting "
                           f"{n.latex_verbatim()!r} (expected \\def\\name{{body}})")
        i += 1
    return out, spans


def _uses(nodes, macros: dict, out: list) -> None:
    """Every node of ``nodes`` (recursively) that is one of ``macros``."""
    for n in nodes:
        if n is None:
            continue
        if isinstance(n, LatexMacroNode):
            if n.macroname in macros:
                out.append(n)
                continue
            for a in (n.nodeargd.argnlist if n.nodeargd else []):
                _uses([a], macros, out)
        elif isinstance(n, LatexGroupNode | LatexEnvironmentNode | LatexMathNode):
            _uses(n.nodelist, macros, out)
            if isinstance(n, LatexEnvironmentNode) and n.nodeargd:
                _uses(n.nodeargd.argnlist, macros, out)
        elif isinstance(n, LatexCommentNode):
            continue


def _body(node, spec: tuple) -> str:
    """A macro use's expansion: its body with ``#k`` replaced by the arguments."""
    n, default, body = spec
    args = [] if not node.nodeargd else list(node.nodeargd.argnlist)
    values = []
    for k, a in enumerate(args[:n]):
        values.append(default if (a is None and k == 0 and default is not None)
                      else _inner(a).removeprefix("[").removesuffix("]")
                      if a is not None and not isinstance(a, LatexGroupNode) else _inner(a))
    out = body
    for k in range(n, 0, -1):
        out = out.replace(f"#{k}", values[k - 1] if k - 1 < len(values) else "")
    # a macro that ends in a letter glued to what follows: keep TeX's token boundary
    return out + " " if out and out[-1].isalpha() else out


def expand(text: str, macros: dict, origin: list[int] | None = None) -> tuple[str, list[int]]:
    """``text`` with every use of ``macros`` expanded, and for each character of the result
    the offset in ``text`` it comes from.

    Raises:
        BadInput: an expansion nested deeper than :data:`DEPTH` (a macro defined by itself).
    """
    origin = list(range(len(text))) if origin is None else origin
    for _ in range(DEPTH):
        if not macros:
            return text, origin
        try:
            nodes = walker(text, macros).get_latex_nodes()[0]
        except LatexWalkerError as exc:
            raise BadInput(f"cannot read the LaTeX {text[:60]!r}: {exc}") from None
        uses: list = []
        _uses(nodes, macros, uses)
        if not uses:
            return text, origin
        out, where, at = [], [], 0
        for u in sorted(uses, key=lambda u: u.pos):
            if u.pos < at:
                continue
            out.append(text[at:u.pos])
            where.extend(origin[at:u.pos])
            rep = _body(u, macros[u.macroname])
            out.append(rep)
            where.extend([origin[u.pos]] * len(rep))
            at = u.pos + u.len
        out.append(text[at:])
        where.extend(origin[at:])
        text, origin = "".join(out), where
    raise BadInput(f"a macro of the document expands more than {DEPTH} times deep "
                   f"(defined through itself?): {text[:80]!r}")
