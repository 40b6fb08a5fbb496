"""Shared fixtures: the registry, loaded once; the chapter text when it is present."""

from __future__ import annotations

from pathlib import Path

import pytest

from rigidsym.registry import load_all

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
