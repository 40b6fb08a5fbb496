"""benchmarks/generated_diff.py, the comparison of generated code with comments stripped that
says a move of the generator changed no kernel: it ignores what a comment or a docstring
says and sees every change of the code, on real generated files."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import generated_diff as gd  # noqa: E402

GEN = ROOT / "generated"


def _pair(rel: str) -> tuple[str, str]:
    return rel, (GEN / rel).read_text(encoding="utf-8")


def test_comments_and_docstrings_are_ignored_on_real_files():
    for rel in ("numpy/kinetic_energy.py", "c/kinetic_energy.c", "torch/kinetic_energy.py"):
        path, text = _pair(rel)
        if path.endswith(".py"):
            edited = text.replace('"""', '"""A reworded docstring. ', 1) \
                .replace("\n", "  # a new comment\n", 3)
        else:
            edited = "/* a moved module's name */\n" + text.replace("\n", " // note\n", 3)
        assert edited != text
        assert gd.code_of(path, edited) == gd.code_of(path, text), rel


def _edit_a_number(text: str) -> str:
    """``text`` with its first numeric literal of code (not of a docstring) changed."""
    import ast

    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Constant) and type(node.value) in (int, float):
            lines = text.splitlines(keepends=True)
            line = lines[node.lineno - 1]
            lines[node.lineno - 1] = (line[:node.col_offset] + repr(node.value + 1)
                                      + line[node.end_col_offset:])
            return "".join(lines)
    raise AssertionError("no number in the code")


def test_a_change_of_code_is_seen_on_real_files():
    for rel in ("numpy/kinetic_energy.py", "jax/kinetic_energy.py", "torch/wrench_axis.py"):
        path, text = _pair(rel)
        edited = _edit_a_number(text)
        assert edited != text
        assert gd.code_of(path, edited) != gd.code_of(path, text), rel
    path, text = _pair("c/kinetic_energy.c")
    # a type of an argument, and an index stride, each alone
    for old, new in (("const double *RIGIDSYM_RESTRICT in_m",
                      "const float *RIGIDSYM_RESTRICT in_m"),
                     ("in_omega + 3 * j", "in_omega + 2 * j")):
        assert old in text
        assert gd.code_of(path, text.replace(old, new)) != gd.code_of(path, text), old


def test_compare_sorts_code_changes_from_the_record_and_one_sided_files():
    a = {"numpy/k.py": "x = 1  # old\n", "inputs.json": "{}", "c/k.c": "int k; /* a */",
         "gone.py": "y = 2\n"}
    b = {"numpy/k.py": "x = 1  # new\n", "inputs.json": '{"a": 1}', "c/k.c": "int k2;",
         "new.py": "y = 2\n"}
    assert gd.compare(a, b) == {"code differs": ["c/k.c"], "only in the first": ["gone.py"],
                                "only in the second": ["new.py"]}
