"""The compiled-object cache of the C driver: a second build of the same sources (an editable
install after a regular one, a CI re-run, the wheel test, a user's kernels rebuilt) reuses
each object instead of compiling it again.

An object's key is the SHA-256 of everything that decides its bytes: the compile command
with the folders it names made neutral (the generated folder by the bytes of its sources
and headers, NumPy's headers by NumPy's version, the object's own path dropped), the
source's bytes, the bytes of every header of its folder that it includes (directly or
through another: a kernel's object keeps its key when another kernel is added), and the
compiler's identity (``cc --version`` and ``cc -dumpmachine``). Entries live in
``<root>/<key[:2]>/<key>.o`` with a ``.sha256`` beside them, written as the kernel cache
writes its entries (a temporary file and a rename, the checksum last, under a ``filelock``
lock): an entry that fails its checksum is compiled again, never linked.

The root is ``RIGIDSYM_OBJECT_CACHE``, else ``$XDG_CACHE_HOME/rigidsym/objects``
(``~/.cache/rigidsym/objects``); ``RIGIDSYM_OBJECT_CACHE=0`` turns the cache off.
``RIGIDSYM_CACHE`` does not move it: that variable keeps one run's verdicts apart, and the
objects, which depend only on the sources and the compiler, stay shared by every build.
Standard library and ``filelock`` only: ``setup.py`` loads the driver by path before
rigidsym is importable (``filelock`` is in ``build-system.requires``); without ``filelock``
every object is compiled.
"""

from __future__ import annotations

import hashlib
import os
import re
import subprocess
from collections.abc import Callable
from functools import cache
from pathlib import Path

__all__ = ["root", "key", "fetch", "store", "compiler_id", "cc_words", "headers_digest",
           "compile_cached"]

#: bumped when the key's recipe changes (old entries are then never hit)
FORMAT = "1"


def root() -> Path | None:
    """The object cache folder: ``RIGIDSYM_OBJECT_CACHE``, else
    ``$XDG_CACHE_HOME/rigidsym/objects`` (``~/.cache/rigidsym/objects``), whatever
    ``RIGIDSYM_CACHE`` says; ``None`` when ``RIGIDSYM_OBJECT_CACHE=0`` or ``filelock`` is
    missing."""
    env = os.environ.get("RIGIDSYM_OBJECT_CACHE")
    if env == "0":
        return None
    try:
        import filelock  # noqa: F401
    except ImportError:
        return None
    if env:
        return Path(env).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME") or (Path.home() / ".cache")
    return Path(xdg) / "rigidsym" / "objects"


@cache
@cache
def compiler_id(cc: tuple[str, ...]) -> str:
    """What the compiler says of itself (version and target); part of every key (asked once
    per process and command)."""
    out = []
    for flag in ("--version", "-dumpmachine"):
        r = subprocess.run([*cc, flag], capture_output=True, text=True)
        out.append(r.stdout.strip() or r.stderr.strip())
    return "\n".join(out)


def key(argv: list[str], src: Path, headers: str, neutral: dict[str, str]) -> str:
    """The key of one compile: ``argv`` (its ``-o`` target dropped, the folders in
    ``neutral`` replaced by their labels, the source by its name), the source's bytes, the
    digest ``headers`` of its folder's headers, and the compiler's identity."""
    words, skip = [], False
    for a in argv:
        if skip:
            skip = False
            continue
        if a == "-o":
            skip = True
            continue
        if a == str(src):
            a = src.name
        for path, label in neutral.items():
            a = a.replace(path, label)
        words.append(a)
    h = hashlib.sha256()
    for part in (FORMAT, "\0".join(words), headers, compiler_id(cc_words(argv))):
        h.update(part.encode() + b"\0")
    h.update(src.read_bytes())
    return h.hexdigest()


def cc_words(argv: list[str]) -> tuple[str, ...]:
    """The compiler command of ``argv``: the words before its first flag."""
    n = next((i for i, a in enumerate(argv) if a.startswith("-")), len(argv))
    return tuple(argv[:n])


def _entry(where: Path, k: str) -> Path:
    return where / k[:2] / f"{k}.o"


def fetch(where: Path, k: str, dest: Path) -> bool:
    """Copy the cached object ``k`` to ``dest`` when it is present and whole."""
    path = _entry(where, k)
    try:
        data = path.read_bytes()
        want = path.with_name(path.name + ".sha256").read_text().strip()
    except OSError:
        return False
    if hashlib.sha256(data).hexdigest() != want:
        return False
    dest.write_bytes(data)
    return True


def store(where: Path, k: str, obj: Path) -> None:
    """Publish the compiled ``obj`` as entry ``k``: the object, then its checksum, each by a
    temporary file and a rename, under the cache's lock. A cache that cannot be written
    (read-only, full) is skipped: the build itself has succeeded."""
    from filelock import FileLock

    path = _entry(where, k)
    tmps: list[Path] = []
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        data = obj.read_bytes()
        with FileLock(str(where / "objects.lock"), timeout=600):
            for target, payload in ((path, data),
                                    (path.with_name(path.name + ".sha256"),
                                     hashlib.sha256(data).hexdigest().encode())):
                tmp = target.with_name(f".{target.name}.{os.getpid()}.tmp")
                tmps.append(tmp)
                tmp.write_bytes(payload)
                os.replace(tmp, target)
    except OSError:
        for tmp in tmps:                # nothing half-written is left behind
            tmp.unlink(missing_ok=True)


def headers_digest(cdir: Path, src: Path | None = None) -> str:
    """SHA-256 over the names and bytes of the headers of ``cdir`` that ``src`` includes,
    directly or through another (part of its key; ``src`` None: every header). A kernel's
    object then keeps its key when another kernel is added or changed (its own header and
    ``rigidsym_common.h`` are all it reads), and only the objects that read the changed
    headers compile again. Every ``#include`` written counts, whatever conditional it sits
    in (more headers than the compiler reads: never fewer); an ``#include`` of a macro
    counts every header."""
    cdir = Path(cdir)
    every = sorted(p.name for p in cdir.glob("*.h"))
    if src is None:
        names = every
    else:
        names, todo = set(), [Path(src)]
        while todo:
            text = todo.pop().read_bytes()
            if _MACRO_INCLUDE.search(text):
                names = set(every)
                break
            for m in _INCLUDE.finditer(text):
                name = m.group(1).decode()
                if name not in names and (cdir / name).is_file():
                    names.add(name)
                    todo.append(cdir / name)
        names = sorted(names)
    h = hashlib.sha256()
    for name in names:
        h.update(name.encode() + b"\0" + (cdir / name).read_bytes() + b"\0")
    return h.hexdigest()


#: an ``#include "x.h"`` or ``#include <x.h>`` (the name)
_INCLUDE = re.compile(rb'^[ \t]*#[ \t]*include[ \t]*[<"]([^>"]+)[>"]', re.M)
#: an ``#include`` of a macro's expansion
_MACRO_INCLUDE = re.compile(rb"^[ \t]*#[ \t]*include[ \t]+[A-Za-z_]", re.M)


def compile_cached(run: Callable[[list[str]], None], argv: list[str], where: Path | None,
                   headers: str, neutral: dict[str, str]) -> bool:
    """Run the compile ``argv`` (through ``run``), or copy its object from the cache at
    ``where`` (None: no cache); True when it was compiled."""
    obj = Path(argv[argv.index("-o") + 1])
    if where is None:
        run(argv)
        return True
    k = key(argv, Path(argv[argv.index("-c") + 1]), headers, neutral)
    if fetch(where, k, obj):
        return False
    run(argv)
    store(where, k, obj)
    return True
