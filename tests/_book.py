"""The chapter's text as optional test data, in one place.

The project never ships the chapter: it lies at ``../shared/book/angeles-chapter3.md`` beside
the project's own checkout (and CI's) and nowhere else. Every test that reads it goes through
this module, so that in a clone anywhere else each such test skips with one line saying why
(``book_text``, ``book_path``, the ``book`` fixture of ``tests/conftest.py``), and the guard of
``tests/conftest.py`` fails a test that opens anything under ``SHARED`` by another way.

``RIGIDSYM_TESTS_BOOK`` names another copy of the chapter; ``RIGIDSYM_TESTS_BOOK=none``
runs the suite as a fresh clone does, the book absent.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: the folder beside the project's own checkout that users never have
SHARED = ROOT.parent / "shared"
_WHERE = os.environ.get("RIGIDSYM_TESTS_BOOK", "")
#: the chapter's path (a path that does not exist under ``RIGIDSYM_TESTS_BOOK=none``)
BOOK = (ROOT / "tests" / "no-book-here" if _WHERE.lower() == "none"
        else Path(_WHERE) if _WHERE else SHARED / "book" / "angeles-chapter3.md")
#: the chapter's reading (shipped: rigidsym.derivations), certcheck's ``--reading``
READING = ROOT / "derivations" / "angeles-chapter3.reading.toml"



#: the skip's one line
REASON = (f"the chapter is not at {BOOK} (the project never ships it; "
          "RIGIDSYM_TESTS_BOOK names a copy)")
#: the tests granted the chapter (``grant``): the guard of tests/conftest.py lets these read it
GRANTED: set[str] = set()
_CURRENT: list[str] = [""]


def present() -> bool:
    """Whether the chapter is there (a module's skipif, without opening it)."""
    return BOOK.is_file()


def book_path() -> Path:
    """The chapter's path for the test that calls it; skips the test when it is absent."""
    if not present():
        pytest.skip(REASON)
    GRANTED.add(_CURRENT[0])
    return BOOK


def book_text() -> str:
    """The chapter's text; skips the calling test when it is absent."""
    return book_path().read_text(encoding="utf-8")


#: a module's or test's mark: skip without the chapter
needs_book = pytest.mark.skipif(not present(), reason=REASON)


# -- the guard: a test that opens anything under SHARED without being granted the chapter --

#: (test, path) of each open under SHARED since the current test began
OPENED: list[tuple[str, str]] = []
#: ``SHARED`` as written and as resolved: where ``shared`` is a link (a clone beside a
#: linked ``shared/``), an open through either spelling is under it
_SHARED_TEXTS = tuple(dict.fromkeys((os.path.abspath(SHARED) + os.sep,
                                     str(SHARED.resolve()) + os.sep)))


def _audit(event: str, args: tuple) -> None:
    """``sys.addaudithook``'s hook: records an ``open`` of a path under ``SHARED``."""
    if event != "open" or not args or not isinstance(args[0], (str, bytes, os.PathLike)):
        return
    try:
        path = os.path.abspath(os.fsdecode(args[0]))
    except (TypeError, ValueError):
        return
    if path.startswith(_SHARED_TEXTS) or path + os.sep in _SHARED_TEXTS:
        OPENED.append((_CURRENT[0], path))


def begin(test: str) -> None:
    """A test starts: its opens are its own from here on."""
    _CURRENT[0] = test
    OPENED.clear()


def ungranted(test: str) -> list[str]:
    """The paths under ``SHARED`` that ``test`` opened without ``book_path``/``book_text``."""
    return [] if test in GRANTED else sorted({p for t, p in OPENED if t == test})
