"""Shared fixtures: the registry, loaded once; the chapter text when it is present; the
kernels' backend, switched for a test (NumPy, then C; fails if a compiler is present but the
C backend does not build)."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import pytest

from rigidsym import kernels as K
from rigidsym.checking.deciding.registry import load_all


def pytest_configure(config):
    # the suite never reads or fills the reader's own cache (verdicts, user kernels, timings):
    # a verdict cached by an older checkout would hide a regression
    if "RIGIDSYM_CACHE" not in os.environ:
        os.environ["RIGIDSYM_CACHE"] = tempfile.mkdtemp(prefix="rigidsym-tests-")


def pytest_unconfigure(config):
    path = os.environ.get("RIGIDSYM_CACHE", "")
    if Path(path).name.startswith("rigidsym-tests-"):
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
