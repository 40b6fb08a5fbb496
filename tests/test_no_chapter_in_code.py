"""What the chapter says is data, not code: no string of rigidsym or of certcheck names a
chapter id. The symbol tables, the classes, the page readings and the theorems in words are
the chapter's reading (``derivations/angeles-chapter3.reading.toml``), its glyph table the
CSV that reading names, the registry's sections those its declarations name, the course's
handout words ``derivations/exercises/handout.toml``; docstrings and comments may cite the
book. What may still name an id is :data:`ALLOWED`, entry by entry, each with why."""

from __future__ import annotations

import ast
import re
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: a chapter id: 3.13, 3.96e, thm3.2.1, cor3.4.1, caveat3.4
ID = re.compile(r"(?<![\d.])(3\.\d{1,3}[a-e]?|thm3\.\d\.\d|cor3\.\d\.\d|caveat3\.\d)(?!\d)")
SRC = ROOT / "src" / "rigidsym"
#: the code that holds no chapter: every module and package of rigidsym, and certcheck
CLEAN = [*sorted(p for p in SRC.iterdir() if p.suffix == ".py" or (
    p.is_dir() and (p / "__init__.py").exists())), ROOT / "certcheck" / "src"]

_HELP = ("an example of the command line in its help, the id a person types (the command "
         "takes every id, section and exercise from the loaded book)")
_AUDIT = ("a target's description cites the chapter's equation a peer's function is audited "
          "against, shown in the audit report as a docstring would cite it")
_MR = "Modern Robotics' (Lynch & Park 2017) equation number: another book's, not the chapter's"
#: (file under src/rigidsym, the id its string names) -> why it may
ALLOWED: dict[tuple[str, str], str] = {
    **dict.fromkeys([("cli/__init__.py", "3.10"), ("cli/__init__.py", "3.57"),
                     ("cli/check.py", "3.5"), ("cli/check.py", "3.2"), ("cli/check.py", "3.4"),
                     ("cli/exam.py", "3.4"), ("cli/exercise.py", "3.10"),
                     ("cli/exercise.py", "3.4"), ("cli/show.py", "3.148"),
                     ("cli/show.py", "3.57"), ("cli/show.py", "3.83"), ("cli/show.py", "3.96"),
                     ("cli/show.py", "thm3.2.1"), ("cli/verify.py", "3.8"),
                     ("cli/verify.py", "3.96"), ("cli/verify.py", "3.16"),
                     ("cli/verify.py", "thm3.2.1")], _HELP),
    **dict.fromkeys([("auditing/targets.py", "3.83"), ("auditing/targets.py", "3.119"),
                     ("auditing/targets.py", "3.10"), ("auditing/targets.py", "3.95")], _AUDIT),
    ("kernels/arrays/namespace.py", "3.10"): (
        "the Euler-angle kernels' docstring templates (formatted per back end) cite "
        "Exercise 3.10, as a docstring may"),
    ("codegen/accuracy/peers.py", "3.17"): "pytransform3d's version 3.17, not an id",
    ("latex/contested.py", "3.51"): _MR,
    **dict.fromkeys([("latex/transformer/rigid_motions.py", i)
                     for i in ("3.51", "3.88", "3.53", "3.54", "3.30", "3.85")], _MR),
}


def ids_in_strings(path: Path, whole: bool = False) -> list[tuple[int, str]]:
    """(line, text) of each string literal of ``path`` that names a chapter id, docstrings
    left out; the text cut to 60 characters unless ``whole``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docs = {id(n.body[0].value) for n in ast.walk(tree)
            if isinstance(n, ast.Module | ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef)
            and n.body and isinstance(n.body[0], ast.Expr)
            and isinstance(n.body[0].value, ast.Constant)}
    return [(n.lineno, n.value if whole else n.value[:60]) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str)
            and id(n) not in docs and ID.search(n.value)]


@cache
def named_ids(path: Path) -> frozenset[tuple[str, str]]:
    """(file under src/rigidsym, id) of each id the strings of ``path`` name (docstrings
    left out)."""
    rel = path.relative_to(SRC).as_posix() if path.is_relative_to(SRC) else str(path)
    return frozenset((rel, i) for _, text in ids_in_strings(path, whole=True)
                     for i in ID.findall(text))


@pytest.mark.parametrize("root", CLEAN, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_string_of_the_code_names_a_chapter_id(root):
    files = [root] if root.is_file() else sorted(root.rglob("*.py"))
    found = {x for p in files for x in named_ids(p)} - set(ALLOWED)
    assert found == set(), sorted(found)


def test_every_allowed_id_is_still_named_where_it_is_allowed():
    """The allow-list holds no entry the code no longer needs (it only shrinks)."""
    found = {x for p in sorted(SRC.rglob("*.py")) for x in named_ids(p)}
    assert set(ALLOWED) - found == set()


def test_the_check_sees_an_id_in_a_string_and_not_in_a_docstring(tmp_path):
    p = tmp_path / "m.py"
    p.write_text('"""Cites (3.13)."""\n\nTABLE = {"3.96e": 1}\n\n\ndef f():\n    """3.1"""\n'
                 '    return "thm3.2.1 and 13.5"\n')
    assert [line for line, _ in ids_in_strings(p)] == [3, 8]
