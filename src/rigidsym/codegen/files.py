"""The generator's files on disk: write a generation atomically (removing orphans) or
compare it with the disk (``rigidsym generate --check``).

A generation is anything with a ``files`` mapping ``{relative path: text}``
(:class:`rigidsym.codegen.generator.GenerationResult`).
"""

from __future__ import annotations

import difflib
import os
import sys
import time
from pathlib import Path
from typing import Protocol

from rigidsym.core.config import generated_dir
from rigidsym.core.files import write_atomic

__all__ = ["write", "check", "check_or_write", "Generation"]


class Generation(Protocol):
    """What these functions read of a generation: its files."""

    #: relative path under the output folder -> text
    files: dict[str, str]

#: file names under generated/ owned by the generator (anything else there is an orphan,
#: except the report folder, which belongs to ``rigidsym report``, and the notebooks, which
#: ``rigidsym generate`` writes through :mod:`rigidsym.course.notebooks`).
_FOREIGN = ("report/", "notebooks/")
#: the file that marks a folder as a generation's (``rigidsym generate --out`` writes into a
#: folder that is not empty only when it holds it): written first, so that a write cut short
#: (an interrupt) leaves a folder that the next run takes up and completes
_MARK = "kernels.json"


def files_on_disk(out: Path) -> dict[str, Path]:
    """``{relative path: file}`` of the generator's files under ``out`` (none if it does not
    exist): caches, hidden files and the folders other commands own (``_FOREIGN``) aside."""
    found = {}
    if out.exists():
        for p in sorted(out.rglob("*")):
            rel = p.relative_to(out).as_posix()
            if p.is_file() and "__pycache__" not in rel and not rel.startswith(_FOREIGN) \
                    and not p.name.startswith("."):
                found[rel] = p
    return found


def write(result: Generation, out: Path | None = None) -> list[str]:
    """Write changed files atomically (the folder's mark, ``kernels.json``, first), delete
    orphans; returns the paths touched."""
    out = Path(out) if out is not None else generated_dir()
    touched = []
    disk = files_on_disk(out)
    for rel, text in sorted(result.files.items(), key=lambda item: item[0] != _MARK):
        p = out / rel
        if rel in disk and p.read_text(encoding="utf-8") == text:
            continue
        write_atomic(p, text)
        touched.append(rel)
    for rel, p in disk.items():
        if rel not in result.files:
            os.unlink(p)
            touched.append(f"{rel} (removed orphan)")
    return touched


def check(result: Generation, out: Path | None = None) -> str:
    """Unified diff between ``result`` and the disk ("" when byte-identical, no orphans)."""
    out = Path(out) if out is not None else generated_dir()
    disk = files_on_disk(out)
    chunks = []
    for rel in sorted(set(disk) | set(result.files)):
        old = disk[rel].read_text(encoding="utf-8") if rel in disk else None
        new = result.files.get(rel)
        if old == new:
            continue
        a = [] if old is None else old.splitlines(keepends=True)
        b = [] if new is None else new.splitlines(keepends=True)
        label_a = f"a/generated/{rel}" if old is not None else "/dev/null"
        label_b = f"b/generated/{rel}" if new is not None else "/dev/null"
        diff = "".join(difflib.unified_diff(a, b, label_a, label_b))
        if old is None:
            diff = f"missing file: generated/{rel}\n" + diff
        elif new is None:
            diff = f"orphan file: generated/{rel}\n" + diff
        chunks.append(diff if diff.endswith("\n") else diff + "\n")
    return "".join(chunks)


def check_or_write(result: Generation, out: Path, *, check_only: bool, kernels: int,
                   rerun: str, t0: float) -> int | None:
    """What ``rigidsym generate --out DIR [--check]`` does with a generation (the user's
    kernels, the C target): with ``check_only``, print the diff and return 1 when ``out`` is
    stale (``rerun`` is the command that rewrites it), else 0; otherwise write the changed
    files, say how many, and return None (the caller may go on, e.g. to build)."""
    if check_only:
        diff = check(result, out)
        if diff:
            sys.stdout.write(diff)
            print(f"{out} is stale: run `{rerun}`", file=sys.stderr)
            return 1
        print(f"{out} is up to date: {kernels} kernels, {len(result.files)} files "
              f"({time.perf_counter() - t0:.1f} s)")
        return 0
    touched = write(result, out)
    print(f"{kernels} kernels, {len(result.files)} files, {len(touched)} changed in {out} "
          f"({time.perf_counter() - t0:.1f} s)")
    return None
