"""Shared fixtures: the registry, loaded once; the chapter text when it is present; the
kernels' backend, switched for a test (NumPy, then C; fails if a compiler is present but the
C backend does not build); and a guard that fails a test whose child processes outlive it."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import pytest
from _procguard import _no_process_outlives_its_test, become_subreaper  # noqa: F401

from rigidsym import kernels as K
from rigidsym.registry.declarations import load_all

_CREATED: list[str] = []


def pytest_configure(config):
    # the suite never reads or fills the reader's own cache (verdicts, user kernels, timings):
    # a verdict cached by an older checkout would hide a regression. The one exception is
    # read through RIGIDSYM_TESTS_OBJECTS: the reader's compiled-object cache, which the
    # wheel test's build reuses (objects keyed by their sources' bytes, flags and compiler,
    # and checksummed: a reused object is the object a compile would give)
    if "RIGIDSYM_TESTS_OBJECTS" not in os.environ:
        from rigidsym.kernels.cbuild import objects as _objects

        os.environ["RIGIDSYM_TESTS_OBJECTS"] = str(_objects.root() or "0")
    if "RIGIDSYM_CACHE" not in os.environ:
        os.environ["RIGIDSYM_CACHE"] = tempfile.mkdtemp(prefix="rigidsym-tests-")
        _CREATED.append(os.environ["RIGIDSYM_CACHE"])   # xdist workers inherit it
    os.environ.pop("RIGIDSYM_OBJECT_CACHE", None)       # the tests' objects: in their cache
    become_subreaper()


def pytest_unconfigure(config):
    for path in _CREATED:
        shutil.rmtree(path, ignore_errors=True)


CHAPTER = Path(__file__).resolve().parents[2] / "shared" / "book" / "angeles-chapter3.md"


@pytest.fixture(scope="session")
def registry():
    return load_all()


@pytest.fixture(scope="session")
def chapter_text():
    if not CHAPTER.exists():
        pytest.skip(f"the chapter is not beside the checkout ({CHAPTER}); the project never "
                    "ships it")
    return CHAPTER.read_text(encoding="utf-8")


@pytest.fixture(params=["numpy", "c"])
def backend(request):
    if K.use_backend(request.param) != request.param:
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    yield request.param
    K.use_backend("numpy")


#: what this process collected (tests/test_budget.py): every node id before the marker
#: expression deselects, then the ids selected, and whether the whole of tests/ was collected
COLLECTED: dict = {}


def _plain_id(item) -> str:
    """The node id without the ``@group`` suffix that ``--dist loadgroup`` appends."""
    nodeid = item.nodeid
    for mark in item.iter_markers("xdist_group"):
        name = mark.args[0] if mark.args else mark.kwargs.get("name", "")
        nodeid = nodeid.removesuffix(f"@{name}")
    return nodeid


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session, config, items):
    COLLECTED["all"] = [_plain_id(i) for i in items]
    tests = Path(__file__).resolve().parent
    args = [Path(str(a).split("::")[0]).resolve() for a in config.args] or [tests]
    COLLECTED["whole"] = all(tests.is_relative_to(a) for a in args) and \
        not config.getoption("keyword") and not config.getoption("deselect")


def pytest_collection_finish(session):
    COLLECTED["selected"] = [_plain_id(i) for i in session.items]
    # the tests that need no extra: the same set whichever extras are installed
    COLLECTED["core"] = [_plain_id(i) for i in session.items
                         if i.get_closest_marker("extra") is None]
    COLLECTED["markexpr"] = session.config.getoption("markexpr")
