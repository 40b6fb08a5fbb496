"""Which generated files differ in their code between two revisions, comments aside.

    python benchmarks/generated_diff.py REV [REV2]

A change that should not change behaviour (a move of the generator's modules, a renamed
template, a reworded docstring) still rewrites the provenance lines of every generated file
and ``inputs.json``; this says whether anything else moved. Each file of ``generated/`` at
REV is compared with the same file at REV2 (default: the working tree) after
:func:`code_of`: Python by its syntax tree with every docstring blanked, C by its tokens with
comments and ``#error`` messages dropped; ``inputs.json`` (the digests of the generator's
inputs, which any edit of them changes) not at all; any other file byte for byte. Prints the
files whose code differs, the files only one side has, and exits 1 if there is any.
"""

from __future__ import annotations

import argparse
import ast
import io
import re
import subprocess
import sys
import tarfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WORKTREE = "WORKTREE"

_C_COMMENT = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)
_C_ERROR = re.compile(r"#[ \t]*error[^\n]*")
_C_SUFFIXES = (".c", ".h", ".cpp", ".hpp", ".cc")
#: the record of the generator's inputs: it changes with any edit of them, code or not
RECORD = "inputs.json"


def _blank_docstrings(tree: ast.AST) -> ast.AST:
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef) \
                and body and isinstance(body[0], ast.Expr) \
                and isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value,
                                                                           str):
            body[0].value.value = ""
    return tree


def code_of(path: str, text: str) -> str:
    """The code of generated file ``path`` (its relative path, which says its language) with
    comments and docstrings removed; the text itself for a file of no known language.

    Raises:
        SyntaxError: a ``.py`` file that does not parse.
    """
    if path.endswith(".py"):
        return ast.dump(_blank_docstrings(ast.parse(text)))
    if path.endswith(_C_SUFFIXES):
        # string literals of the C are kernel names and messages with no comment markers in them
        return " ".join(_C_ERROR.sub("#error", _C_COMMENT.sub(" ", text)).split())
    return text


def files_at(rev: str) -> dict[str, str]:
    """``{path under generated/: text}`` at git revision ``rev`` (or the working tree)."""
    if rev == WORKTREE:
        base = ROOT / "generated"
        return {p.relative_to(base).as_posix(): p.read_text(encoding="utf-8", errors="replace")
                for p in base.rglob("*") if p.is_file() and "__pycache__" not in p.parts}
    data = subprocess.run(["git", "-C", str(ROOT), "archive", rev, "generated"],
                          check=True, capture_output=True).stdout
    out = {}
    with tarfile.open(fileobj=io.BytesIO(data)) as tar:
        for m in tar.getmembers():
            if m.isfile():
                out[m.name.removeprefix("generated/")] = tar.extractfile(m).read().decode(
                    "utf-8", errors="replace")
    return out


def compare(a: dict[str, str], b: dict[str, str]) -> dict[str, list[str]]:
    """The files whose code differs between the trees ``a`` and ``b`` (as :func:`files_at`
    gives them), and those only one of them has."""
    both = sorted((a.keys() & b.keys()) - {RECORD})
    return {"code differs": [p for p in both if a[p] != b[p]
                             and code_of(p, a[p]) != code_of(p, b[p])],
            "only in the first": sorted(a.keys() - b.keys()),
            "only in the second": sorted(b.keys() - a.keys())}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rev")
    ap.add_argument("rev2", nargs="?", default=WORKTREE)
    args = ap.parse_args(argv)
    a, b = files_at(args.rev), files_at(args.rev2)
    found = compare(a, b)
    print(f"{len(a.keys() & b.keys())} files in both, "
          f"{sum(a[p] != b.get(p, a[p]) for p in a)} with any change")
    for what, paths in found.items():
        print(f"{what}: {len(paths)}" + "".join(f"\n  {p}" for p in paths))
    return 1 if any(found.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
