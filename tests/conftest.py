"""Shared fixtures: the registry, loaded once; the chapter text when it is present; the
kernels' backend, switched for a test (NumPy, then C; fails if a compiler is present but the
C backend does not build), and restored after every test; a guard that fails a test whose
child processes outlive it; and the two profiles of ``tests/_profile.py`` (Hypothesis's
settings profiles, the seeded sample of a family marked ``sample``)."""

from __future__ import annotations

import os
import shutil
import sys
import tempfile

import _book
import _bytecode  # noqa: F401  (first: before sympy is imported; tests/_bytecode.py)
import _profile
import _shared_run
import pytest
from _procguard import _no_process_outlives_its_test, become_subreaper  # noqa: F401
from hypothesis import HealthCheck, settings

from rigidsym import kernels as K
from rigidsym.kernels.runtime.state import STATE as KSTATE
from rigidsym.registry.declarations import load_all

_CREATED: list[str] = []

# no property depends on the machine's speed: no deadline, no health check on slow data;
# both profiles draw the same examples every run (CI's verdict is not a coin it flips; a
# failure reproduces), the thorough one at _profile.THOROUGH_FACTOR times the budget
# (_profile.examples). A new search is a person's: `--hypothesis-profile=search` (new
# examples each run, at the budget RIGIDSYM_TEST_PROFILE sets)
settings.register_profile("quick", deadline=None, derandomize=True, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("thorough", deadline=None, derandomize=True, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("search", deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("quick" if _profile.PROFILE == "quick" else "thorough")


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
    # the tests' objects: in their own cache (RIGIDSYM_CACHE does not move the object cache)
    os.environ["RIGIDSYM_OBJECT_CACHE"] = os.path.join(os.environ["RIGIDSYM_CACHE"], "objects")
    os.environ.setdefault("RIGIDSYM_LATEX_TIMEOUT", "none")  # no verdict rests on the load
    become_subreaper()


def pytest_unconfigure(config):
    for path in _CREATED:
        shutil.rmtree(path, ignore_errors=True)



def _say(config, line: str) -> None:
    """One line on the terminal, whatever ``-q`` says (the controller's reporter)."""
    reporter = config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None:
        reporter.write_line(line, flush=True)


def pytest_sessionstart(session):
    # the first line within seconds of the command: what runs and what the first seconds do
    if os.environ.get("PYTEST_XDIST_WORKER"):
        return
    workers = getattr(session.config.option, "numprocesses", None)
    where = f"on {workers} workers" if workers else "in this process"
    seeds = f"seed {_profile.SEED}"
    if _profile.PROFILE == "thorough":
        seeds += f", thorough share's seed {_profile.THOROUGH_SEED} (RIGIDSYM_THOROUGH_SEED)"
    _say(session.config, f"rigidsym tests: profile {_profile.PROFILE}, {seeds}; "
                         f"collecting {where} (importing sympy and the kernels) ...")


_COLLECTED: list[int] = []


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_node_collection_finished(node, ids):
    if not _COLLECTED:                  # the first worker to finish says it, once
        _COLLECTED.append(len(ids))
        _say(node.config, f"rigidsym tests: {len(ids)} collected; running (a mark per test; "
                          "the chapter's verdicts are decided once, on one worker)")

sys.addaudithook(_book._audit)   # the guard: opens under ../shared (tests/_book.py)


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_setup(item):
    _book.begin(item.nodeid)          # before any fixture of the test is set up


@pytest.hookimpl(trylast=True)
def pytest_runtest_teardown(item, nextitem):
    # no test reads outside the checkout but through tests/_book.py, which skips where the
    # chapter is absent: a test that opened ../shared another way passes only beside the
    # project's own checkout, and fails in every other clone
    opened = _book.ungranted(item.nodeid)
    if opened:
        pytest.fail(f"{item.nodeid} opened {', '.join(opened)} outside the checkout without "
                    "tests/_book.py (book_path, book_text or the book fixture): a clone with "
                    "no ../shared would fail it", pytrace=False)


@pytest.fixture(scope="session")
def registry():
    return load_all()


@pytest.fixture
def chapter_text():
    """The chapter's text (skips the test where it is absent: it is never shipped)."""
    return _book.book_text()


@pytest.fixture
def book():
    """The chapter's text, as certcheck's page-reading tests name it (skips without it)."""
    return _book.book_text()


@pytest.fixture(scope="session")
def chapter_certificates(tmp_path_factory, worker_id):
    """Every chapter id's certificate of its recorded verdict, built once per run (about
    90 s of CPU) and shared by the workers (``tests/_shared_run.py``)."""
    return _shared_run.shared_json(_shared_run.run_folder(tmp_path_factory, worker_id),
                                   "chapter_certificates", _shared_run.chapter_certificates)


@pytest.fixture(autouse=True)
def _backend_kept():
    """Every test ends on the backend it started on: a test that switches the global backend
    and does not switch back would otherwise decide which backend later tests on the same
    worker call (which kernels, which bits), so a result would depend on the test order."""
    # read, not selected: K.backend() would load (or build) the C backend for every test
    before = KSTATE["backend"]
    yield
    if KSTATE["backend"] != before:
        K.use_backend(before or "c")    # none selected yet: the default, C


@pytest.fixture(params=["numpy", "c"])
def backend(request):
    if K.use_backend(request.param) != request.param:
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    yield request.param


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session, config, items):
    """Before the marker expression deselects: every Hypothesis property gets the ``budget``
    mark (the thorough run runs it again at its larger budget), the parameters of a
    family marked ``sample`` outside the seeded sample get ``slow``, and the tests of the
    chapter's certificates one ``xdist_group``."""
    families: dict[tuple, list] = {}
    for item in items:
        if getattr(getattr(item, "obj", None), "is_hypothesis_test", False):
            item.add_marker("budget")
        mark = item.get_closest_marker("sample")
        if mark is not None and item.get_closest_marker("slow") is None:
            key = (item.path, item.cls, getattr(item, "originalname", item.name))
            families.setdefault(key, []).append(item)
    for members in families.values():
        mark = members[0].get_closest_marker("sample")
        fraction = mark.kwargs.get("fraction", mark.args[0] if mark.args else
                                   _profile.DEFAULT_FRACTION)
        # the draw is of plain ids: the same with and without --dist loadgroup's @group suffix
        keep = _profile.kept([_profile.plain(i.nodeid) for i in members], fraction)
        for item in members:
            if _profile.plain(item.nodeid) not in keep:
                item.add_marker("slow")
    _thorough_shares(config, items)
    # unpriced: slow tests new to the suite whose cost in .ci/run is not measured yet (its
    # 90 minutes are shared by every part): the exhaustive profile only, until priced
    if _profile.PROFILE != "exhaustive":
        unpriced = [i for i in items if i.get_closest_marker("unpriced") is not None]
        if unpriced:
            gone = {id(i) for i in unpriced}
            config.hook.pytest_deselected(items=unpriced)
            items[:] = [i for i in items if id(i) not in gone]
    # the tests that read the chapter (its fixtures, or a module that reads it through
    # tests/_book.py): marked ``book``, so that .ci/run's thorough part, beside the chapter,
    # runs them after the README's command ran them (skipping) in a clone with no ../shared
    readers = {id(getattr(_book, n)) for n in ("book_path", "book_text", "BOOK")}
    for item in items:
        module = getattr(item, "module", None)
        if ({"book", "chapter_text"} & set(getattr(item, "fixturenames", ()))
                or any(id(v) in readers for v in vars(module).values() if module)):
            item.add_marker("book")
    # the tests of the chapter's certificates on one worker (--dist loadgroup): the other
    # worker runs other tests while the first builds them, instead of waiting on the lock
    for item in items:
        if ("chapter_certificates" in getattr(item, "fixturenames", ())
                and item.get_closest_marker("xdist_group") is None):
            item.add_marker(pytest.mark.xdist_group("chapter_certificates"))


def _thorough_shares(config, items) -> None:
    """Deselect the slow members of each family marked ``thorough(fraction)`` outside the
    family's seeded share (the same in every xdist worker: the draw is of plain node ids)."""
    families: dict[tuple, list] = {}
    for item in items:
        if item.get_closest_marker("thorough") is not None and item.get_closest_marker("slow"):
            key = (item.path, item.cls, getattr(item, "originalname", item.name))
            families.setdefault(key, []).append(item)
    dropped = []
    for members in families.values():
        mark = members[0].get_closest_marker("thorough")
        fraction = mark.kwargs.get("fraction", mark.args[0] if mark.args else None)
        if fraction is None:
            raise ValueError(f"{members[0].nodeid}: the thorough mark needs a fraction")
        keep = set(_profile.share([_profile.plain(i.nodeid) for i in members], fraction))
        dropped += [i for i in members if _profile.plain(i.nodeid) not in keep]
    if dropped:
        gone = {id(i) for i in dropped}
        config.hook.pytest_deselected(items=dropped)
        items[:] = [i for i in items if id(i) not in gone]
