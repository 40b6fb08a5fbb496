"""Hand-written code is cut by meaning, not by length: a module is one concept however long,
so the gate is only a backstop against a module or function that has grown past reading: no
module in ``src/`` or ``derivations/`` over 800 lines and no function over 80 lines (its
docstring aside), unless its docstring gives the reason in a paragraph that starts with
``Long:``. Splitting a module to meet the gate is not the fix: split it where its concepts
part (docs/layout.md).

``generated/`` is written by the generator and is not checked.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODULE_LINES = 800
FUNCTION_LINES = 80
REASON = "Long:"


def _sources() -> list[Path]:
    return sorted([*(ROOT / "src" / "rigidsym").rglob("*.py"),
                   *(ROOT / "derivations").rglob("*.py")])


def _docstring_lines(node) -> int:
    first = node.body[0] if node.body else None
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) \
            and isinstance(first.value.value, str):
        return first.end_lineno - first.lineno + 1
    return 0


def _has_reason(node) -> bool:
    doc = ast.get_docstring(node) or ""
    return any(line.strip().startswith(REASON) for line in doc.splitlines())


def test_modules_are_at_most_800_lines():
    long = []
    for p in _sources():
        text = p.read_text(encoding="utf-8")
        n = len(text.splitlines())
        if n > MODULE_LINES and not _has_reason(ast.parse(text)):
            long.append(f"{p.relative_to(ROOT)}: {n} lines")
    assert not long, (f"modules over {MODULE_LINES} lines (split them where their concepts "
                      f"part, or say why in a '{REASON}' paragraph of the module docstring):\n"
                      + "\n".join(long))


def test_functions_are_at_most_80_lines():
    long = []
    for p in _sources():
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                n = node.end_lineno - node.lineno + 1 - _docstring_lines(node)
                if n > FUNCTION_LINES and not _has_reason(node):
                    long.append(f"{p.relative_to(ROOT)}:{node.lineno} {node.name}: {n} lines")
    assert not long, (f"functions over {FUNCTION_LINES} lines, docstring aside (split them, or "
                      f"say why in a '{REASON}' paragraph of the docstring):\n" + "\n".join(long))


def test_the_rule_sees_a_long_function(tmp_path):
    """The measure counts a function's lines without its docstring, and a reason exempts."""
    body = "\n".join(f"    x{i} = {i}" for i in range(FUNCTION_LINES))
    for doc, exempt in (('"""Short."""', False), ('"""Short.\n\n    Long: a reason.\n    """',
                                                     True)):
        tree = ast.parse(f"def f():\n    {doc}\n{body}\n    return x0\n")
        node = tree.body[0]
        n = node.end_lineno - node.lineno + 1 - _docstring_lines(node)
        assert n == FUNCTION_LINES + 2 and _has_reason(node) is exempt
