"""A displayed equation of a document: its body as written and where it stands.

A :class:`Display` is one ``$$...$$``, ```` ```math ````, ``\\[...\\]`` or display
environment (``equation``, ``align``, ...) of a Markdown or LaTeX document, numbered in
document order from 1. Its :meth:`Display.place` turns an offset into its body into the
file's line and column (from 1), so every relation split from it is located.
"""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass, field

__all__ = ["Display", "Source"]


@dataclass(frozen=True)
class Source:
    """A document file's text, with its lines' start offsets.

    Attributes:
        file: the file's name as given (relative names stay relative).
        text: its text.
    """

    file: str
    text: str
    starts: tuple[int, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        starts, at = [0], self.text.find("\n")
        while at >= 0:
            starts.append(at + 1)
            at = self.text.find("\n", at + 1)
        object.__setattr__(self, "starts", tuple(starts))

    def line_col(self, offset: int) -> tuple[int, int]:
        """The line and column (both from 1) of a character offset of :attr:`text`."""
        i = bisect_right(self.starts, max(offset, 0)) - 1
        return i + 1, offset - self.starts[i] + 1

    def offset(self, line: int) -> int:
        """The offset of the start of ``line`` (from 1)."""
        return self.starts[min(max(line, 1), len(self.starts)) - 1]


@dataclass(frozen=True)
class Display:
    """One displayed equation.

    Attributes:
        source: the file it stands in.
        number: its number in the document (from 1, in reading order across files).
        body: the LaTeX between its delimiters (an environment's body, or the whole
            ``\\begin{align}...\\end{align}`` of a Markdown display).
        start: the offset of ``body`` in ``source.text``; ``None`` where the body is not
            the file's text verbatim (a Markdown block quote's stripped ``>``): then lines
            are counted from ``line``.
        line: the line (from 1) the body starts on.
        environment: ``equation``, ``align``, ``$$``, ``math`` (a fence), ``\\[``...
        label: a label the document gives the display outside its body (Markdown's
            ``$$...$$ (label)``), ``None`` if none.
        macros: the document's macros in force here, ``{name: (number of arguments,
            default of the first or None, body)}``.
    """

    source: Source
    number: int
    body: str
    start: int | None
    line: int
    environment: str
    label: str | None = None
    macros: dict = field(default_factory=dict)

    def place(self, k: int) -> tuple[int, int]:
        """The file's line and column (from 1) of offset ``k`` into :attr:`body`."""
        if self.start is not None:
            return self.source.line_col(self.start + k)
        before = self.body[:k]
        return self.line + before.count("\n"), k - (before.rfind("\n") + 1) + 1
