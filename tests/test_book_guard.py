"""No test reads outside the checkout: the chapter (never shipped) is optional test data,
read only through ``tests/_book.py``, and the guard of ``tests/conftest.py`` fails a test that
opens anything under ``../shared`` another way, so that a clone with no ``../shared`` beside it
cannot meet a ``FileNotFoundError`` the project's own checkout never sees."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import _book
import pytest

ROOT = Path(__file__).resolve().parents[1]


def test_an_open_under_shared_is_caught_and_a_grant_lets_it_pass():
    """The audit hook records an open under ../shared (even of a file that is not there)
    for the test that made it; ``book_path`` grants the test the chapter."""
    me = "tests/test_book_guard.py::probe"
    _book.begin(me)
    with pytest.raises(OSError):
        open(_book.SHARED / "no-such-file-here.md", encoding="utf-8")   # noqa: SIM115
    with pytest.raises(OSError):
        open(os.path.relpath(_book.SHARED / "elsewhere" / "x.json", Path.cwd()), "rb")  # noqa: SIM115
    assert _book.ungranted(me) == sorted({str(_book.SHARED / "no-such-file-here.md"),
                                          str(_book.SHARED / "elsewhere" / "x.json")})
    open(ROOT / "README.md", encoding="utf-8").close()     # inside the checkout: not recorded
    assert len(_book.ungranted(me)) == 2
    _book.GRANTED.add(me)
    assert _book.ungranted(me) == []
    _book.GRANTED.discard(me)
    _book.OPENED.clear()       # this test's own probe: not a read of the chapter


# a pytest process; quick: the README's command itself, which .ci/run runs in a clone with
# no ../shared, where every test marked book skips this way
@pytest.mark.slow
def test_without_the_book_each_reader_skips_with_one_line(tmp_path):
    """``RIGIDSYM_TESTS_BOOK=none`` is a clone with no ../shared: every test that needs the
    chapter skips naming why, none errors (a test module of the page, run so)."""
    env = {**os.environ, "RIGIDSYM_TESTS_BOOK": "none"}
    env.pop("PYTEST_XDIST_WORKER", None)
    p = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                        "-p", "no:xdist", "-rs", "tests/test_cert_page_displacement.py",
                        "-k", "determinant or displacement_ids or displaced"],
                       cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-2000:]
    assert "3 skipped" in p.stdout and "failed" not in p.stdout, p.stdout[-2000:]
    assert "the chapter is not at" in p.stdout, p.stdout[-2000:]
