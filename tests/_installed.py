"""An installed peer library, never a file of its name elsewhere on the path: a user
module's folder stays last on ``sys.path`` once loaded (``rigidsym.registry.usermodules``),
and examples/ holds a ``modern_robotics.py`` of its own, whose import would run the example
and declare its ids a second time (a later ``verify --module`` of it then exits 2)."""

from __future__ import annotations

from importlib import metadata

import pytest


def peer(module: str, distribution: str, reason: str | None = None):
    """``module``, imported only where ``distribution`` is installed; else the test skips
    with ``reason`` (``"DISTRIBUTION is not installed"``)."""
    try:
        metadata.distribution(distribution)
    except metadata.PackageNotFoundError:
        pytest.skip(reason or f"{distribution} is not installed")
    return pytest.importorskip(module, reason=reason or f"{distribution} is not installed")
