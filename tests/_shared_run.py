"""Artefacts built once per test run and shared by every pytest-xdist worker through a file
(the pattern of pytest-xdist's docs, "Making session-scoped fixtures execute only once"): the
first worker that needs one builds it under an exclusive lock and writes it atomically; the
others wait on the lock and read it. A file that cannot be read back is built again, never
taken as empty.
"""

from __future__ import annotations

import fcntl
import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest


def run_folder(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """The folder every worker of this run shares (the parent of the workers' base
    temporary folders under xdist; the base temporary folder without it)."""
    base = tmp_path_factory.getbasetemp()
    return base if worker_id == "master" else base.parent


def shared_json(folder: Path, name: str, build: Callable[[], object]) -> object:
    """``build()``'s value, built by one worker of the run and read by the others (a JSON
    file ``name`` in ``folder``)."""
    path = folder / f"{name}.json"
    with open(folder / f"{name}.lock", "w", encoding="utf-8") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if path.exists():
            try:
                return json.loads(path.read_text(encoding="utf-8"))
            except ValueError:
                pass    # unreadable: built again below
        value = build()
        part = path.with_suffix(".part")
        part.write_text(json.dumps(value), encoding="utf-8")
        os.replace(part, path)
        return json.loads(path.read_text(encoding="utf-8"))


def chapter_certificates() -> dict[str, dict]:
    """Every chapter id's certificate of its recorded verdict (``certificate(i,
    REGISTRY[i].expected)``, read back from JSON), the ids of other books left out."""
    from rigidsym.checking.certifying.certificates import certificate
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    return {i: json.loads(json.dumps(certificate(i, REGISTRY[i].expected)))
            for i in REGISTRY if ":" not in i}
