"""What ``generated/`` is made from: the source files of ``rigidsym generate`` and their digests.

A full generation takes 70 to 360 s of CPU, too much for the default test run. The
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

**The store of derived kernels.** ``rigidsym generate`` keeps what it derived for each kernel
under the digest of that kernel's own inputs (:func:`kernel_key`), so that a generation
re-derives only the kernels whose inputs changed (the rule of make, ninja and Bazel: rebuild
what an input changed, keep what finished). The unit is a group of the generator's pool: a
kernel and its ``_with_jacobians`` twin, derived together in one process. Its key is the
SHA-256 of its declaration (every field of each kernel of the group that is data, and the
digest of the mathematics its formula functions build, :func:`declared_hash`: a change
anywhere in a formula's call chain is seen, an unrelated edit of the same file is not), of
the machinery (:func:`machinery_hash`: every input file above but the book's own modules,
whose part is the declaration) and of the settings (:func:`settings`, and the origin written
in the headers). An entry holds each kernel's compiled programs (pickled), hash, operation
count, inputs, rewrites and its files of every package target, in the user cache
(:mod:`rigidsym.core.cache`, ``<root>/codegen/``), written atomically and checksummed: a
missing or corrupt entry is derived again, never trusted.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import json
import pickle
import sys
from collections.abc import Iterator
from dataclasses import fields
from functools import cache
from pathlib import Path

import sympy as sp

import rigidsym
from rigidsym.codegen.optimise import math_hash
from rigidsym.codegen.spec import Kernel, input_symbols
from rigidsym.codegen.spec import flatten_outputs as _flatten
from rigidsym.core import cache as _cache
from rigidsym.core.config import KERNEL_SPEC

__all__ = ["MANIFEST", "ENTRY_MODULES", "input_files", "manifest", "compare", "STORE",
           "settings", "machinery_hash", "declared_hash", "declaration", "kernel_key",
           "entry_path", "load_entry", "save_entry", "kept"]

#: the manifest's name under generated/
MANIFEST = "inputs.json"
#: where the generation starts: the generator, the Jacobian kernels, the book's kernel list,
#: and the ``generate`` command, which writes the exercises' notebooks beside the kernels,
#: with the CLI's helpers it runs through (its output stream)
ENTRY_MODULES = ("rigidsym.codegen.generator", "rigidsym.codegen.derivatives.jacobians",
                 KERNEL_SPEC, "rigidsym.cli.generate", "rigidsym.cli.common")
#: entry modules whose package is no input: the CLI package imports every command's module,
#: and only ``generate``'s runs
_NO_PARENTS = ("rigidsym.cli.generate", "rigidsym.cli.common")
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


#: the quotes a string constant ``"rigidsym.…"`` starts after in the source text
_QUOTED = ('"rigidsym.', "'rigidsym.")


def _statements(tree: ast.Module) -> Iterator[ast.AST]:
    """Every statement of ``tree``, nested ones (in functions, classes, ``try``, ``match``)
    included; expressions are not entered (an import is always a statement)."""
    todo: list[ast.AST] = list(tree.body)
    while todo:
        node = todo.pop()
        yield node
        todo.extend(c for c in ast.iter_child_nodes(node)
                    if isinstance(c, ast.stmt | ast.excepthandler | ast.match_case))


def _imports(path: Path, name: str) -> set[str]:
    """Every module name an ``import`` in the file may load (both ``pkg.x`` and ``pkg`` for
    ``from pkg import x``: whichever is a module), and every string constant ``"rigidsym.…"``
    without a space (``importlib.import_module`` by name). Expressions are walked only in a
    file whose text has a quote before ``rigidsym.`` (27 of the generator's 324 modules): the
    statements alone are a tenth of the nodes."""
    is_pkg = path.name == "__init__.py"
    package = name if is_pkg else name.rpartition(".")[0]
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text)
    found: set[str] = set()
    for node in _statements(tree):
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
    if any(q in text for q in _QUOTED):
        found.update(node.value for node in ast.walk(tree)
                     if isinstance(node, ast.Constant) and isinstance(node.value, str)
                     and node.value.startswith("rigidsym.") and " " not in node.value)
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
    # the exercises, which the notebooks solve: their registry imports them by file name
    todo += [f"rigidsym.derivations.exercises.{p.stem}" for p in
             sorted((roots["rigidsym.derivations"] / "exercises").glob("*.py"))]
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
        if name not in _NO_PARENTS:
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


#: the user cache's folder of the store
STORE = "codegen"
#: the labels of the book's modules among the generator's inputs (their part of a kernel is
#: its declaration)
_BOOK = "rigidsym/derivations/"
#: the entry format (a change of what an entry holds changes every key)
_FORMAT = 1


def settings() -> dict[str, str]:
    """The versions a derivation depends on besides the sources: Python (the pickles),
    rigidsym, sympy (the printed code), numpy (the points the float32 plans are measured on)
    and mpmath (the reference)."""
    import mpmath
    import numpy as np

    return {"python": f"{sys.version_info[0]}.{sys.version_info[1]}",
            "rigidsym": rigidsym.__version__, "sympy": sp.__version__,
            "numpy": np.__version__, "mpmath": mpmath.__version__,
            "format": str(_FORMAT)}


@cache
def machinery_hash() -> str:
    """The digest of the generator's input files but the book's modules, and of
    :func:`settings` (once per process: the files do not change while it runs)."""
    h = hashlib.sha256()
    for label, digest in sorted(manifest()["inputs"].items()):
        if not label.startswith(_BOOK):
            h.update(f"{label}\0{digest}\n".encode())
    for name, version in sorted(settings().items()):
        h.update(f"{name}\0{version}\n".encode())
    return h.hexdigest()


def declared_hash(kernel: Kernel) -> str:
    """The digest of the mathematics ``kernel`` declares: the conditions and outputs of its
    branches and of its main build, as sympy builds them from its formula functions (for a
    Jacobian kernel differentiated over the program: those of the kernel it differentiates)."""
    spec = kernel.jacobian_of if kernel.jacobian_from == "program" and kernel.jacobian_of \
        else kernel
    syms = input_symbols(spec)
    parts: list = []
    for br in spec.branches:
        parts += [br.when(**syms), *_flatten(spec, br.build(**syms))]
    parts += _flatten(spec, spec.build(**syms))
    return math_hash(parts)


def declaration(kernel: Kernel) -> str:
    """The data fields of ``kernel``'s declaration, as text (its callables aside: their part
    is :func:`declared_hash`; a branch by its name, doc and default)."""
    out = []
    for f in fields(kernel):
        value = getattr(kernel, f.name)
        if f.name == "branches":
            value = [(b.name, b.doc, b.default) for b in value]
        elif f.name == "jacobian_of":
            value = None if value is None else value.name
        elif callable(value):
            continue
        out.append(f"{f.name}={value!r}")
    return "\n".join(out)


def kernel_key(group: list[Kernel], origin: str) -> str:
    """The key of a group of kernels (a kernel, then its ``_with_jacobians`` twin, if any):
    the digest of their declarations, the machinery and the settings (module docstring). A
    twin of a kernel in the group adds its fields only: its mathematics is the kernel's,
    differentiated by the machinery."""
    h = hashlib.sha256()
    h.update(f"{machinery_hash()}\0{origin}\n".encode())
    names = {k.name for k in group}
    for k in group:
        h.update(declaration(k).encode() + b"\0")
        twin_of = k.name.removesuffix("_with_jacobians")
        if twin_of == k.name or twin_of not in names:
            h.update(declared_hash(k).encode() + b"\0")
    return h.hexdigest()


def entry_path(digest: str) -> Path:
    """The file of the entry of key ``digest`` (not created)."""
    return _cache.folder(STORE) / digest[:2] / f"{digest}.pkl"


def load_entry(digest: str) -> list | None:
    """The store's entry of key ``digest``: ``[(kernel name, packed programs, hash, ops, inputs,
    rewrites, {(target, kernel name): {path: text}})]`` per kernel of the group, or None
    when it is missing or corrupt."""
    data = _cache.get(entry_path(digest))
    if data is None:
        return None
    try:
        return pickle.loads(data)
    except Exception:  # noqa: BLE001 - an entry of another version: derived again
        return None


def save_entry(digest: str, entry: list) -> Path:
    """Store ``entry`` (as :func:`load_entry` returns it) under ``digest``, atomically (an
    interrupt waits until it is written whole)."""
    return _cache.put(entry_path(digest), pickle.dumps(entry, pickle.HIGHEST_PROTOCOL))


def kept(digests: dict[str, int]) -> int:
    """How many kernels the stored entries among ``digests`` (key -> kernels in its group)
    hold: what an interrupted generation keeps."""
    return sum(n for d, n in digests.items() if _cache.get(entry_path(d)) is not None)
