"""The package's layers, enforced: import-linter contracts (pyproject.toml) and the book's
imports.

``lint-imports`` reads the package from disk through grimp, which cannot follow the
``package-dir`` mapping of ``rigidsym.derivations`` (``derivations/``) and
``rigidsym.generated`` (``generated/``); the test therefore lays the three folders out as
one ``rigidsym`` tree of ``.py`` files in a temporary folder and runs the contracts there.
"""

from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: what the book's modules may import of rigidsym (what a user module can, plus the
#: worked-exercise framework); their own package aside
BOOK_MAY_IMPORT = ("rigidsym.declare", "rigidsym.codegen.spec", "rigidsym.course.worked")


def _tree(dst: Path) -> Path:
    pkg = dst / "rigidsym"
    for src, sub in ((ROOT / "src" / "rigidsym", ""), (ROOT / "derivations", "derivations"),
                     (ROOT / "generated", "generated")):
        for p in src.rglob("*.py"):
            q = pkg / sub / p.relative_to(src)
            q.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(p, q)
    return dst


def test_import_contracts_hold(tmp_path):
    exe = Path(sys.executable).with_name("lint-imports")
    if not exe.exists():
        pytest.skip("import-linter is not installed (pip install -e '.[test]')")
    where = _tree(tmp_path)
    env = dict(os.environ, PYTHONPATH=str(where))
    res = subprocess.run([str(exe), "--config", str(ROOT / "pyproject.toml")], cwd=where,
                         env=env, capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stdout[-4000:] + res.stderr[-2000:]
    assert "0 broken" in res.stdout


def test_kernels_import_no_symbolic_layer():
    code = ("import sys, rigidsym.kernels as K; K.N_matrix([0.0, 0.6, 0.8], 0.5); "
            "bad = sorted(m for m in sys.modules if m == 'sympy' or m.startswith(("
            "'sympy.', 'rigidsym.codegen', 'rigidsym.checking', 'rigidsym.zero', "
            "'rigidsym.derivations', 'rigidsym.report', 'rigidsym.algebra'))); print(bad)")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300, check=True)
    assert res.stdout.strip() == "[]"


def _rigidsym_imports(path: Path):
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            yield node.lineno, node.module
        elif isinstance(node, ast.Import):
            yield from ((node.lineno, a.name) for a in node.names)


def test_the_book_imports_only_what_a_user_module_can():
    bad = []
    for p in sorted((ROOT / "derivations").rglob("*.py")):
        for line, mod in _rigidsym_imports(p):
            if mod.startswith("rigidsym") and not mod.startswith("rigidsym.derivations") \
                    and mod not in BOOK_MAY_IMPORT:
                bad.append(f"{p.relative_to(ROOT)}:{line}: {mod}")
    assert not bad, "\n".join(bad)
