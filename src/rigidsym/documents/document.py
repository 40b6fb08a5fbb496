"""A document read: its displays and their relations, Markdown or LaTeX by its suffix."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rigidsym.core.errors import BadInput
from rigidsym.documents.displays import Display, Source
from rigidsym.documents.markdown import markdown_displays
from rigidsym.documents.relations import Relation, split_display
from rigidsym.documents.tex import tex_displays

__all__ = ["MARKDOWN", "TEX", "Document", "read_document"]

#: suffixes read as Markdown, and as LaTeX
MARKDOWN = (".md", ".markdown", ".mdown", ".mkd", ".qmd", ".rmd")
TEX = (".tex", ".latex", ".ltx")


@dataclass(frozen=True)
class Document:
    """A document's displays and relations, in reading order.

    Attributes:
        path: the file named on the command line.
        displays: its displays (and those of the files it inputs).
        relations: every relation of every display.
    """

    path: Path
    displays: tuple[Display, ...]
    relations: tuple[Relation, ...]


def read_document(path: str | Path) -> Document:
    """Read the document at ``path``: ``.md`` (and Markdown's other suffixes) with
    :mod:`.markdown`, ``.tex`` with :mod:`.tex`.

    Raises:
        BadInput: a file that is missing or unreadable, a suffix of neither kind (the
            suffixes listed), a display that cannot be read (its line named).
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix in MARKDOWN:
        try:
            text = p.read_text(encoding="utf-8-sig")
        except (OSError, UnicodeDecodeError) as exc:
            raise BadInput(f"{p}: cannot read the file ({exc})") from None
        displays = markdown_displays(Source(str(p), text))
    elif suffix in TEX:
        displays = tex_displays(p)
    else:
        raise BadInput(f"{p}: expected a Markdown ({', '.join(MARKDOWN)}) or LaTeX "
                       f"({', '.join(TEX)}) document, got the suffix {suffix or '(none)'!r}")
    relations = [r for d in displays for r in split_display(d)]
    return Document(p, tuple(displays), tuple(relations))
