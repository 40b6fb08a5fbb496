"""Every benchmark module imports (nothing runs the benchmarks in CI, so they cannot rot
silently when an internal path they use moves)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks"


@pytest.mark.parametrize("path", sorted(BENCH.glob("*.py")), ids=lambda p: p.name)
def test_benchmark_module_imports(path, monkeypatch):
    monkeypatch.syspath_prepend(str(BENCH))  # they import each other as top-level modules
    name = f"_bench_{path.stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod      # a dataclass looks its module up there, as when run
    try:
        spec.loader.exec_module(mod)  # module level only: each guards its main()
    finally:
        sys.modules.pop(name, None)
    assert mod.__doc__, f"{path.name} has no module docstring saying what it measures"
