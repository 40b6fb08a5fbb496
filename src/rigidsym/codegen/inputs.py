"""What ``generated/`` is made from: the source files of ``rigidsym generate`` and their digests.

A full generation takes 70 to 360 s of CPU (issue 54), too much for the default test run. The
generator therefore records, in ``generated/inputs.json``, the SHA-256 of every file that can
decide its output and of every file it wrote. The default run compares those digests with
the tree (seconds); a ``slow`` test still regenerates everything and compares byte for byte.

Which files can decide the output is found statically, so the answer does not depend on what
a process happened to import before: the import closure of the generator's entry modules
(every ``import``/``from … import`` of a ``rigidsym`` module anywhere in a file, lazy ones
inside functions included, a module named in a string constant ``"rigidsym.…"`` as
``importlib`` takes it, and the ``__init__`` of every package on the way), every module of
the book's sections (``rigidsym/derivations/*.py``, which the registry imports by names it
builds), and every data file
(templates, JSON, grammar) in the folders of those modules. ``rigidsym.generated``, the
output itself, is never an input. Over-inclusion only asks for a regeneration that changes
nothing; a file missed would let a stale ``generated/`` pass, so the rule errs on the side of
inclusion, and a ``slow`` test generates in a fresh process and requires every ``rigidsym``
module it imported to be among the inputs.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import json
from functools import cache
from pathlib import Path

import sympy as sp

from rigidsym.core.config import KERNEL_SPEC

__all__ = ["MANIFEST", "ENTRY_MODULES", "input_files", "manifest", "compare"]

#: the manifest's name under generated/
MANIFEST = "inputs.json"
#: where the generation starts: the generator, the Jacobian kernels, the book's kernel list
ENTRY_MODULES = ("rigidsym.codegen.generator", "rigidsym.codegen.derivatives.jacobians",
                 KERNEL_SPEC)
#: the output and the manifest's own module's outputs: never inputs
_NOT_INPUTS = ("rigidsym.generated",)
_DATA_SUFFIXES = (".j2", ".json", ".lark", ".csv", ".txt", ".c", ".h")
#: what a build writes beside the sources (the extension's build record, with its time): not
#: an input, and different on every machine
_BUILD_OUTPUTS = ("_ckernels",)

_PKG = Path(__file__).resolve().parents[1]          # src/rigidsym


def _roots() -> dict[str, Path]:
    """Package name -> folder, as the source tree or an installed wheel lays them out."""
    # found, not imported: the generator reads the book's declarations only by name
    spec = importlib.util.find_spec("rigidsym.derivations")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError("rigidsym.derivations cannot be found (a broken installation)")
    return {"rigidsym": _PKG,
            "rigidsym.derivations": Path(list(spec.submodule_search_locations)[0]).resolve()}


def _module_file(name: str, roots: dict[str, Path]) -> Path | None:
    """The file of module ``name`` (a package's ``__init__.py``), or None when it is none of
    ours or does not exist (a name imported from a module, not a submodule)."""
    if not name.startswith("rigidsym") or name.startswith(_NOT_INPUTS):
        return None
    for pkg in sorted(roots, key=len, reverse=True):
        if name == pkg or name.startswith(pkg + "."):
            rest = name[len(pkg):].lstrip(".").split(".") if name != pkg else []
            base = roots[pkg].joinpath(*rest)
            for cand in (base / "__init__.py", base.with_suffix(".py")):
                if cand.is_file():
                    return cand
            return None
    return None


def _imports(path: Path, name: str) -> set[str]:
    """Every module name an ``import`` in the file may load (both ``pkg.x`` and ``pkg`` for
    ``from pkg import x``: whichever is a module)."""
    is_pkg = path.name == "__init__.py"
    package = name if is_pkg else name.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[:len(base) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            found.add(mod)
            found.update(f"{mod}.{a.name}" for a in node.names)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and node.value.startswith("rigidsym.") and " " not in node.value:
            found.add(node.value)       # importlib.import_module("rigidsym.…") by name
    return found


@cache
def input_files() -> tuple[Path, ...]:
    """Every file whose bytes can change what ``generate()`` returns (absolute paths, sorted).

    Raises:
        RuntimeError: when an entry module's file cannot be found (a broken installation).
    """
    roots = _roots()
    todo = list(ENTRY_MODULES)
    # the book's sections: the registry imports them by names it builds (a slow test found
    # ten that no import statement names)
    todo += [f"rigidsym.derivations.{p.stem}" for p in sorted(roots["rigidsym.derivations"]
                                                              .glob("*.py"))]
    seen: dict[str, Path] = {}
    while todo:
        name = todo.pop().removesuffix(".")
        if name in seen:
            continue
        path = _module_file(name, roots)
        if path is None:
            if name in ENTRY_MODULES:
                raise RuntimeError(f"the generator's entry module {name} has no file")
            continue
        seen[name] = path
        parts = name.split(".")
        todo += [".".join(parts[:i]) for i in range(1, len(parts))]   # parents run first
        todo += sorted(_imports(path, name))
    files = set(seen.values())
    for folder in {p.parent for p in seen.values()}:
        for p in folder.rglob("*"):
            if p.is_file() and p.suffix in _DATA_SUFFIXES and "__pycache__" not in p.parts \
                    and not p.name.startswith(_BUILD_OUTPUTS):
                files.add(p)
    return tuple(sorted(files))


def _label(path: Path, roots: dict[str, Path]) -> str:
    for pkg, folder in sorted(roots.items(), key=lambda kv: len(str(kv[1])), reverse=True):
        if path.is_relative_to(folder):
            return pkg.replace(".", "/") + "/" + path.relative_to(folder).as_posix()
    raise ValueError(f"{path}: outside rigidsym")


def _sha(text: bytes) -> str:
    return hashlib.sha256(text).hexdigest()


def manifest(outputs: dict[str, str] | None = None) -> dict:
    """The record ``generated/inputs.json`` holds: ``inputs`` (label -> SHA-256 of every file of
    :func:`input_files`), ``sympy`` (its version, which the printed code depends on),
    and, when ``outputs`` (relative path -> text, the generation's files) is given,
    ``outputs`` (path -> SHA-256 of its UTF-8 text)."""
    roots = _roots()
    rec: dict = {"format": 1, "sympy": sp.__version__,
                 "inputs": {_label(p, roots): _sha(p.read_bytes()) for p in input_files()}}
    if outputs is not None:
        rec["outputs"] = {rel: _sha(text.encode("utf-8")) for rel, text in sorted(outputs.items())
                          if rel != MANIFEST}
    return rec


def render(outputs: dict[str, str]) -> str:
    """``generated/inputs.json``'s text for a generation's files."""
    return json.dumps(manifest(outputs), indent=1, sort_keys=True) + "\n"


def compare(out: Path) -> list[str]:
    """What keeps ``out`` (a generated/ folder) from being what a generation from this tree
    writes, read from its manifest without generating: one line per changed input, per output
    changed, missing or orphaned on disk; empty when it is fresh.

    Raises:
        FileNotFoundError: ``out`` has no ``inputs.json``.
    """
    from rigidsym.codegen.files import files_on_disk

    rec = json.loads((out / MANIFEST).read_text(encoding="utf-8"))
    now = manifest()
    lines = []
    if rec.get("sympy") != now["sympy"]:
        lines.append(f"sympy {now['sympy']} (generated with {rec.get('sympy')})")
    old, new = rec.get("inputs", {}), now["inputs"]
    lines += [f"input changed: {k}" for k in sorted(old.keys() & new.keys()) if old[k] != new[k]]
    lines += [f"input added: {k}" for k in sorted(new.keys() - old.keys())]
    lines += [f"input removed: {k}" for k in sorted(old.keys() - new.keys())]
    recorded = rec.get("outputs", {})
    disk = {rel: p for rel, p in files_on_disk(out).items() if rel != MANIFEST}
    for rel in sorted(recorded.keys() | disk.keys()):
        if rel not in disk:
            lines.append(f"missing file: generated/{rel}")
        elif rel not in recorded:
            lines.append(f"orphan file: generated/{rel}")
        elif _sha(disk[rel].read_bytes()) != recorded[rel]:
            lines.append(f"changed by hand: generated/{rel}")
    return lines
