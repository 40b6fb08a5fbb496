"""Digests of the sources a cached result depends on (the verdict cache, the transcription
records, the worked exercises' solutions): the package, the book's modules one by one, the
versions of the libraries behind the results.

The book's ``.py`` files are digested per module, with the book modules each imports
(transitively), so that a change to one module invalidates the results of what uses it
only; every other file of the package (the machinery, the book's data files)
is in :func:`machinery_digest`. Imports nothing of rigidsym but :mod:`rigidsym.core.config` and
:mod:`rigidsym.core.cache`.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import json
import sys
from functools import cache
from pathlib import Path

from rigidsym.core import config as _config

__all__ = ["file_digest", "package_roots", "package_digest", "machinery_digest",
           "imported_names", "book_module_files", "environment", "is_built", "code_bytes"]


def file_digest(path: Path) -> str:
    """SHA-256 of a file's bytes."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


@cache
def package_roots() -> tuple[Path, ...]:
    """The folder of the ``rigidsym`` package, and the book's where it lies elsewhere."""
    import rigidsym

    roots = [Path(rigidsym.__file__).resolve().parent]
    spec = importlib.util.find_spec(_config.BOOK)
    for loc in (spec.submodule_search_locations or []) if spec else []:
        p = Path(loc).resolve()
        if not any(p == r or r in p.parents for r in roots):
            roots.append(p)
    return tuple(roots)


@cache
def _book_root() -> Path | None:
    spec = importlib.util.find_spec(_config.BOOK)
    locs = list(spec.submodule_search_locations or []) if spec else []
    return Path(locs[0]).resolve() if locs else None


def is_built(path: Path) -> bool:
    """Whether ``path`` is an output of the package's build rather than a source: the C
    kernels' extension module and its build record (``_ckernels.build.json``), which
    differ between a regular and an editable install of the same sources, and
    compiled ``__pycache__`` files."""
    import importlib.machinery

    return ("__pycache__" in path.parts or path.suffix == ".pyc"
            or path.name.endswith(tuple(importlib.machinery.EXTENSION_SUFFIXES))
            or path.name.endswith(".build.json"))


@cache
def _generated_root() -> Path | None:
    spec = importlib.util.find_spec("rigidsym.generated")
    locs = list(spec.submodule_search_locations or []) if spec else []
    return Path(locs[0]).resolve() if locs else None


def _files(book_py: bool) -> list[tuple[str, Path]]:
    """``(name, path)`` of the package's source files, named as they are in an installed
    wheel (``derivations/sec3_2.py``) whether the book lies inside the package's folder (a
    regular install) or beside it (an editable one), sorted by name: the digest is the
    same for the same sources however installed. ``rigidsym.generated`` is left
    out: the generator's output, made from sources the digest covers."""
    book, generated = _book_root(), _generated_root()
    prefix = _config.BOOK.split(".", 1)[1].replace(".", "/") + "/"
    out = []
    for k, root in enumerate(package_roots()):
        for p in root.rglob("*"):
            if not p.is_file() or is_built(p) or (generated is not None and
                                                   generated in p.parents):
                continue
            in_book = book is not None and (p.parent == book or book in p.parents)
            if not book_py and p.suffix == ".py" and in_book:
                continue
            rel = p.relative_to(root).as_posix()
            out.append((prefix + rel if k else rel, p))
    return sorted(out)


def code_bytes(code) -> bytes:
    """A code object's marshal bytes without where its file lies (``co_filename``, in it
    and in the code objects it holds): the same source compiled in ``site-packages`` and
    in a source tree gives the same bytes (a regular then an editable install keep the
    verdict cache's keys)."""
    import marshal

    def bare(c):
        consts = tuple(bare(x) if hasattr(x, "co_code") else x for x in c.co_consts)
        return c.replace(co_filename="", co_consts=consts)

    return marshal.dumps(bare(code), 2)


@cache
def package_digest() -> str:
    """SHA-256 of every source file of the ``rigidsym`` package and of the book's folder
    (relative path and content; build outputs left out, :func:`is_built`). Computed once
    per process."""
    return _digest(_files(book_py=True))


@cache
def machinery_digest() -> str:
    """:func:`package_digest` without the book's ``.py`` files (digested per module by
    :func:`book_module_files`)."""
    return _digest(_files(book_py=False))


def _digest(files) -> str:
    h = hashlib.sha256()
    for name, p in files:
        h.update(f"{name}\0{file_digest(p)}\n".encode())
    return h.hexdigest()


def imported_names(path: Path, package: str) -> set[str]:
    """Module names an ``import`` of the file may bind (submodules of ``from`` imports too).

    Kept in the user cache by the file's content (``<key>.imports``): parsing the book's
    modules was most of a warm command's cache keys."""
    from rigidsym.core import cache as _cache

    data = path.read_bytes()
    key = hashlib.sha256(data + b"\0" + package.encode()).hexdigest()
    where = _cache.folder("verdicts") / key[:2] / f"{key}.imports"
    hit = _cache.get(where)
    if hit is not None:
        return set(json.loads(hit))
    out = _parsed_imports(data, path, package)
    _cache.put(where, json.dumps(sorted(out)).encode())
    return out


def _parsed_imports(data: bytes, path: Path, package: str) -> set[str]:
    out: set[str] = set()
    for node in ast.walk(ast.parse(data, str(path))):
        if isinstance(node, ast.Import):
            for a in node.names:
                parts = a.name.split(".")
                out.update(".".join(parts[:k]) for k in range(1, len(parts) + 1))
        elif isinstance(node, ast.ImportFrom):
            try:
                base = importlib.util.resolve_name("." * node.level + (node.module or ""),
                                                   package) if node.level else node.module
            except (ImportError, ValueError):
                continue
            if base:
                out.add(base)
                out.update(f"{base}.{a.name}" for a in node.names)
    return out


@cache
def book_module_files(name: str) -> tuple[tuple[str, str], ...]:
    """``(path relative to the book, digest)`` of the book module ``name`` and of the book
    modules it imports, transitively (as they are in ``sys.modules``)."""
    book = _book_root()
    out: dict[str, str] = {}
    stack = [name]
    while stack and book is not None:
        mod = sys.modules.get(stack.pop())
        file = getattr(mod, "__file__", None)
        if not file:
            continue
        path = Path(file).resolve()
        if not (path.parent == book or book in path.parents):
            continue
        rel = path.relative_to(book).as_posix()
        if rel in out:
            continue
        out[rel] = file_digest(path)
        stack.extend(n for n in imported_names(path, mod.__package__ or "")
                     if n in sys.modules)
    return tuple(sorted(out.items()))


@cache
def environment() -> str:
    """The versions of Python, sympy, mpmath and python-flint, as JSON."""
    import flint
    import mpmath
    import sympy

    return json.dumps({"python": sys.version, "sympy": sympy.__version__,
                       "mpmath": mpmath.__version__, "python-flint": flint.__version__})
