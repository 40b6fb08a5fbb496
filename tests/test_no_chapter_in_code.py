"""What the chapter says is data, not code: no string of rigidsym's checking layer (the
verifier, its certificates) or of certcheck names a chapter id. The symbol tables, the
classes, the page readings and the theorems in words are the chapter's reading
(``derivations/angeles-chapter3.reading.toml``), which both read; docstrings and comments
may cite the book."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: a chapter id: 3.13, 3.96e, thm3.2.1, cor3.4.1, caveat3.4
ID = re.compile(r"(?<![\d.])(3\.\d{1,3}[a-e]?|thm3\.\d\.\d|cor3\.\d\.\d|caveat3\.\d)(?!\d)")
#: the code that holds no chapter (a ratchet: other layers still name ids, docs/layout.md)
CLEAN = [*(ROOT / "src" / "rigidsym" / layer for layer in (
    "checking", "documents", "numeval", "printing", "report", "zero", "algebra")),
    ROOT / "certcheck" / "src"]


def ids_in_strings(path: Path) -> list[tuple[int, str]]:
    """(line, text) of each string literal of ``path`` that names a chapter id, docstrings
    left out."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docs = {id(n.body[0].value) for n in ast.walk(tree)
            if isinstance(n, ast.Module | ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
            and n.body and isinstance(n.body[0], ast.Expr)
            and isinstance(n.body[0].value, ast.Constant)}
    return [(n.lineno, n.value[:60]) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str)
            and id(n) not in docs and ID.search(n.value)]


@pytest.mark.parametrize("root", CLEAN, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_string_of_the_code_names_a_chapter_id(root):
    found = {str(p.relative_to(ROOT)): hits for p in sorted(root.rglob("*.py"))
             if (hits := ids_in_strings(p))}
    assert found == {}, found


def test_the_check_sees_an_id_in_a_string_and_not_in_a_docstring(tmp_path):
    p = tmp_path / "m.py"
    p.write_text('"""Cites (3.13)."""\n\nTABLE = {"3.96e": 1}\n\n\ndef f():\n    """3.1"""\n'
                 '    return "thm3.2.1 and 13.5"\n')
    assert [line for line, _ in ids_in_strings(p)] == [3, 8]
