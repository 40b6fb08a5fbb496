"""Each module compiled once per test run, not once per process.

Where the environment forbids writing bytecode beside the sources (``PYTHONDONTWRITEBYTECODE``,
as in many containers) and the README's install byte-compiles nothing (``--no-compile``),
every process the suite starts (pytest itself, each xdist worker, each ``rigidsym`` command a
test runs) would compile sympy's and the package's modules again: about 2 s of CPU a process.
Imported first by tests/conftest.py, before sympy, this module keeps that bytecode under
``.pytest_cache/pycache`` in the checkout (``PYTHONPYCACHEPREFIX``, inherited by the workers
and the commands), so that the sources and the virtual environment stay as they were. A
``PYTHONPYCACHEPREFIX`` the caller set is kept.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

#: where the suite's bytecode goes when the environment forbids writing it beside the sources
PREFIX = Path(__file__).resolve().parents[1] / ".pytest_cache" / "pycache"

if os.environ.get("PYTHONDONTWRITEBYTECODE") or sys.dont_write_bytecode:
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    os.environ.setdefault("PYTHONPYCACHEPREFIX", str(PREFIX))
    sys.pycache_prefix = os.environ["PYTHONPYCACHEPREFIX"]
    sys.dont_write_bytecode = False
