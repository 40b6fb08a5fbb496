"""The displays of a LaTeX document, read with pylatexenc's LaTeX walker.

Displays are the environments ``equation``, ``equation*``, ``align``, ``align*``,
``gather``, ``gather*``, ``multline``, ``multline*``, ``eqnarray``, ``eqnarray*``,
``displaymath``, ``flalign`` and ``\\[...\\]``/``$$...$$``; ``split``, ``aligned`` and
``cases`` are read inside them (:mod:`.relations`). ``\\newcommand``, ``\\renewcommand``,
``\\def`` and ``\\DeclareMathOperator`` define macros for what follows (expanded where a
display uses them); ``\\input{file}`` and ``\\include{file}`` are followed (``.tex`` added
when the name has no suffix), relative to the including file's folder.
"""

from __future__ import annotations

from pathlib import Path

from pylatexenc.latexwalker import (
    LatexEnvironmentNode,
    LatexGroupNode,
    LatexMacroNode,
    LatexMathNode,
    LatexWalkerError,
)

from rigidsym.core.errors import BadInput
from rigidsym.documents.displays import Display, Source
from rigidsym.documents.macros import definitions, walker

__all__ = ["DISPLAYS", "tex_displays"]

#: the environments that are displays
DISPLAYS = ("equation", "equation*", "align", "align*", "gather", "gather*", "multline",
            "multline*", "eqnarray", "eqnarray*", "displaymath", "flalign", "flalign*",
            "alignat", "alignat*", "math")
#: how deep \input may nest (a file that inputs itself)
DEPTH = 16


def _read(path: Path, shown: str) -> Source:
    try:
        return Source(shown, path.read_text(encoding="utf-8-sig"))
    except (OSError, UnicodeDecodeError) as exc:
        raise BadInput(f"{shown}: cannot read the file ({exc})") from None


def tex_displays(path: str | Path, first: int = 1, macros: dict | None = None,
                 _depth: int = 0, _shown: str | None = None) -> list[Display]:
    """The displayed equations of the LaTeX file ``path`` and the files it inputs, in
    reading order, numbered from ``first``.

    Raises:
        BadInput: a file that cannot be read (named), an ``\\input`` nested deeper than
            :data:`DEPTH`, a macro definition that cannot be read.
    """
    path = Path(path)
    if _depth > DEPTH:
        raise BadInput(f"{path}: \\input nested more than {DEPTH} deep (a file that inputs "
                       f"itself?)")
    source = _read(path, _shown or str(path))
    macros = {} if macros is None else macros
    try:
        nodes = walker(source.text, macros).get_latex_nodes()[0]
    except LatexWalkerError as exc:
        raise BadInput(f"{source.file}: cannot read the LaTeX: {exc}") from None
    out: list[Display] = []
    _walk(nodes, source, path, macros, out, first, _depth)
    return out


def _walk(nodes, source: Source, path: Path, macros: dict, out: list, first: int,
          depth: int) -> None:
    defined, _ = definitions(nodes, source.file)
    macros.update(defined)  # a definition holds from where it stands: document order
    for n in nodes:
        if n is None:
            continue
        if isinstance(n, LatexMacroNode) and n.macroname in ("input", "include"):
            arg = n.nodeargd.argnlist[-1] if n.nodeargd and n.nodeargd.argnlist else None
            name = "".join(c.latex_verbatim() for c in arg.nodelist).strip() \
                if isinstance(arg, LatexGroupNode) else ""
            if not name:
                raise BadInput(f"{source.file}:{source.line_col(n.pos)[0]}: cannot read "
                               f"{n.latex_verbatim()!r}")
            target = path.parent / name
            if not target.suffix:
                target = target.with_suffix(".tex")
            shown = str(Path(source.file).parent / target.relative_to(path.parent))
            out.extend(tex_displays(target, first + len(out), macros, depth + 1, shown))
        elif isinstance(n, LatexEnvironmentNode) and n.environmentname in DISPLAYS or \
                isinstance(n, LatexMathNode) and n.displaytype == "display":
            body = [c for c in n.nodelist if c is not None]
            env = n.environmentname if isinstance(n, LatexEnvironmentNode) else \
                n.delimiters[0]
            if not body:
                continue
            start = body[0].pos
            end = body[-1].pos + body[-1].len
            line, _ = source.line_col(start)
            out.append(Display(source, first + len(out), source.text[start:end], start, line,
                               env, None, macros))
        elif isinstance(n, LatexEnvironmentNode | LatexGroupNode):
            _walk(n.nodelist, source, path, macros, out, first, depth)
