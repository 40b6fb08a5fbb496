"""The user cache: one folder, one lock helper, atomic and checksummed entries.

Layout (``RIGIDSYM_CACHE``, else ``$XDG_CACHE_HOME/rigidsym``, else ``~/.cache/rigidsym``)::

    <root>/kernels/    compiled C kernels (rigidsym.kernels.cbuild.driver)
    <root>/verdicts/   checked results and their certificates (the verdict cache)
    <root>/latex/      the LaTeX grammar's LALR analysis (lark's own cache=)
    <root>/statements/ the book declarations' built statements
                       (rigidsym.registry.statement_cache)
    <root>/codegen/    derived kernels, by the digest of their inputs (rigidsym.codegen.inputs)

The writers of kernels, verdicts and statements take :func:`lock` (a cross-process file
lock from the well-kept ``filelock`` package, not a lock of our own: parallel first-use
writers into one cache otherwise race) and write through :func:`put` (a temporary file and
a rename, so a reader never sees half an entry). :func:`get` returns ``None`` for a missing
entry and for one whose SHA-256 does not match what :func:`put` recorded (truncated,
overwritten, foreign), so a corrupt entry is recomputed, never trusted. An interrupt
(SIGINT, SIGTERM) waits while :func:`put` writes (:func:`rigidsym.core.interrupts.deferred`):
an entry is whole or absent. Imports nothing else of rigidsym but
:mod:`rigidsym.core.files` and :mod:`rigidsym.core.interrupts`.
"""

from __future__ import annotations

import hashlib
import os
import shutil
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from rigidsym.core.files import write_atomic_bytes
from rigidsym.core.interrupts import deferred

__all__ = ["root", "folder", "lock", "put", "get", "digest", "info", "clear", "KINDS"]

#: the cache's sub-folders
KINDS = ("kernels", "verdicts", "latex", "statements", "codegen")
#: seconds a writer waits for another process's lock before giving up with an error
LOCK_TIMEOUT = 600.0


def root() -> Path:
    """The cache folder: ``RIGIDSYM_CACHE``, else the platform's user cache + ``rigidsym``."""
    env = os.environ.get("RIGIDSYM_CACHE")
    if env:
        return Path(env).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or (Path.home() / ".cache")
    return Path(base) / "rigidsym"


def folder(kind: str) -> Path:
    """The sub-folder of ``kind`` (one of :data:`KINDS`), not created.

    Raises:
        ValueError: ``kind`` is not one of :data:`KINDS`.
    """
    if kind not in KINDS:
        raise ValueError(f"kind: expected one of {KINDS}, got {kind!r}")
    return root() / kind


@contextmanager
def lock(kind: str, name: str = "cache", timeout: float = LOCK_TIMEOUT) -> Iterator[Path]:
    """Hold the cross-process lock ``<folder(kind)>/<name>.lock``; yields the folder.

    Raises:
        filelock.Timeout: another process held the lock for longer than ``timeout`` s.
    """
    from filelock import FileLock

    where = folder(kind)
    where.mkdir(parents=True, exist_ok=True)
    with FileLock(str(where / f"{name}.lock"), timeout=timeout):
        yield where


def digest(data: bytes) -> str:
    """The SHA-256 hex digest recorded beside each entry."""
    return hashlib.sha256(data).hexdigest()


def put(path: Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` and its checksum to ``path.sha256``, each atomically
    (the checksum last: an entry without a matching checksum is never read); an interrupt
    waits until both are written."""
    with deferred():
        write_atomic_bytes(path, data)
        write_atomic_bytes(path.with_name(path.name + ".sha256"), digest(data).encode())
    return path


def get(path: Path) -> bytes | None:
    """The bytes of an entry written by :func:`put`, or ``None`` if it is missing or its
    checksum does not match (a corrupt entry: the caller recomputes and warns)."""
    try:
        data = path.read_bytes()
        want = path.with_name(path.name + ".sha256").read_text().strip()
    except OSError:
        return None
    return data if digest(data) == want else None


def info() -> dict:
    """Where the cache is and, per kind, how many entries and bytes it holds."""
    out: dict = {"root": str(root())}
    for kind in KINDS:
        where = folder(kind)
        files = [p for p in where.rglob("*") if p.is_file()] if where.is_dir() else []
        # a .built file marks a user declaration known to build (verdict_cache), an .imports
        # file what a module imports (rigidsym.core.sources): no entries
        entries = [p for p in files
                   if not p.name.endswith((".sha256", ".lock", ".built", ".imports"))]
        out[kind] = {"path": str(where), "entries": len(entries),
                     "bytes": sum(p.stat().st_size for p in files)}
    return out


def clear(kinds: tuple[str, ...] = KINDS) -> list[Path]:
    """Remove the folders of ``kinds`` (default all); returns those removed."""
    gone = []
    for kind in kinds:
        where = folder(kind)
        if where.is_dir():
            shutil.rmtree(where)
            gone.append(where)
    return gone
