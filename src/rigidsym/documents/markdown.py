"""The displays of a Markdown document, read with markdown-it-py and mdit-py-plugins.

markdown-it-py is CommonMark's reference port (already the reports' and docs' parser);
its plugins read every display flavour the notes of the field use: ``dollarmath``
(``$$...$$``, also inside a paragraph as GitHub and MkDocs allow, with Pandoc's
``$$...$$ (label)``), ``texmath`` with bracket delimiters (``\\[...\\]``), ``amsmath``
(a bare ``\\begin{align}...\\end{align}``) and a fence ```` ```math ```` (GitHub, GitLab).
Front matter (``---`` YAML) is skipped. Prose may be in any language: only the math is read.
"""

from __future__ import annotations

from markdown_it import MarkdownIt
from mdit_py_plugins.amsmath import amsmath_plugin
from mdit_py_plugins.dollarmath import dollarmath_plugin
from mdit_py_plugins.front_matter import front_matter_plugin
from mdit_py_plugins.texmath import texmath_plugin

from rigidsym.documents.displays import Display, Source

__all__ = ["markdown_displays"]

_BLOCKS = {"math_block": "$$", "math_block_label": "$$", "amsmath": "amsmath",
           "math_block_eqno": "\\["}
_INLINE = {"math_inline_double": "$$", "math_block": "\\[", "math_block_eqno": "\\["}


def _parser() -> MarkdownIt:
    return (MarkdownIt("commonmark")
            .use(front_matter_plugin)
            .use(dollarmath_plugin, allow_labels=True, double_inline=True)
            .use(texmath_plugin, delimiters="brackets")
            .use(amsmath_plugin))


def markdown_displays(source: Source, first: int = 1, macros: dict | None = None
                      ) -> list[Display]:
    """The displayed equations of a Markdown ``source``, numbered from ``first``.

    Args:
        source: the document.
        first: the number of its first display.
        macros: the macros in force (updated by the displays' own ``\\newcommand``s).

    Returns:
        One :class:`Display` per display, in document order.
    """
    macros = {} if macros is None else macros
    text = source.text
    out: list[Display] = []
    cursor = 0  # the displays are in document order: each is found after the one before

    def add(content: str, env: str, line_hint: int | None, label: str | None) -> None:
        nonlocal cursor
        start_from = source.offset(line_hint + 1) if line_hint is not None else cursor
        at = text.find(content, max(start_from, cursor if line_hint is None else 0))
        if at < 0 and line_hint is not None:
            at = text.find(content, cursor)
        if at >= 0:
            cursor = at + len(content)
            line, _ = source.line_col(at)
            out.append(Display(source, first + len(out), content, at, line, env, label,
                               macros))
        else:  # not verbatim (a block quote's >): counted from the block's line
            line = (line_hint or 0) + 1
            out.append(Display(source, first + len(out), content, None, line, env, label,
                               macros))

    for tok in _parser().parse(text):
        if tok.type in _BLOCKS or (tok.type == "fence" and tok.info.strip() == "math"):
            env = "math" if tok.type == "fence" else _BLOCKS[tok.type]
            label = tok.info.strip() or None if tok.type == "math_block_label" else None
            add(tok.content, env, tok.map[0] if tok.map else None, label)
        elif tok.type == "inline" and tok.children:
            for child in tok.children:
                if child.type in _INLINE:
                    add(child.content, _INLINE[child.type], tok.map[0] if tok.map else None,
                        None)
    return out
