"""Shared fixtures: the registry, loaded once; the chapter text when it is present; the
kernels' backend, switched for a test (NumPy, then C; fails if a compiler is present but the
C backend does not build)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from rigidsym import kernels as K
from rigidsym.checking.registry import load_all

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
