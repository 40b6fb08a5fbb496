"""The theorems the page states in words, with no display: a table the reading gives
(``--reading``: part of what a referee reviews), each entry an id, the theorem's statement as
:func:`certcheck.book.locate` gives it (spaces collapsed, the italic text after its bold
head), the relation(s) that statement states, in the page's own glyphs, as LaTeX the
second reader parses (:mod:`certcheck.reader`), and why the relation is what the words
say, no stronger, no weaker. An entry is used only where the page's statement of its id is
the entry's, character for character; otherwise the words are not read (NOT READ: fail
closed). The relation is then read under the certificate's symbol table and held to its
printed relation as a display's is (:func:`certcheck.compare.compare`): a sign, a
coefficient, a transpose, a relation dropped or added is a rejection naming the id.
"""

from __future__ import annotations

import re

__all__ = ["WORDS", "stated", "said", "use"]

#: id -> (the statement, the relation(s) it states, why they are what it says): the
#: reading's (``[id."thm3.2.1"] words``, ``states``, ``why``), filled by :func:`use`; empty
#: without a reading, when no theorem in words is read
WORDS: dict[str, tuple[str, str, str]] = {}


def use(reading: dict | None) -> None:
    """Take the theorems in words from ``reading`` (:func:`certcheck.reading.load_reading`)."""
    WORDS.clear()
    if reading is not None:
        WORDS.update(reading.get("words") or {})


def _statement(page: str) -> str | None:
    """The italic statement after the bold head of a theorem's paragraph (None: none)."""
    m = re.fullmatch(r"\*\*[^*]+\*\* \*(.+)\*", page)
    return m[1] if m else None


def stated(eq_id: str, page: str) -> str:
    """The relation(s) the words of ``eq_id`` state, where ``page`` (its text, from
    :func:`certcheck.book.locate`) states exactly the table's statement; else ``page`` (a
    paragraph in words, read as nothing)."""
    entry = WORDS.get(eq_id)
    return entry[1] if entry and _statement(page) == entry[0] else page


def said(eq_id: str, page: str) -> list[str]:
    """The referee's line for the table's entry used (none where none is)."""
    if stated(eq_id, page) == page:
        return []
    return [f"the page's words state: {WORDS[eq_id][1]} (the reading: {WORDS[eq_id][2]})"]
