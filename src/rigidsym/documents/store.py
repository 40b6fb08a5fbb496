"""The verdict store of documents: a relation's record, kept while nothing it depends on
changes, so that a re-run after an edit re-checks only the edited displays.

An entry lives in the user cache's ``verdicts/documents/`` folder (:mod:`rigidsym.core.cache`:
``RIGIDSYM_CACHE``, written atomically under its lock with a checksum; a corrupt entry is
recomputed, never trusted). Its key is a SHA-256 over what the verdict depends on, as the
verdict cache's (:mod:`rigidsym.checking.verdict_cache`): the package's machinery, the
versions of Python and the libraries, the engine's settings, and the relation itself: its
LaTeX, the declarations it is checked with (in order), the notation and the check's options.
Its place in the file is not part of the key (moving a display re-uses its verdicts).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from rigidsym.core import cache

__all__ = ["FORMAT", "get", "key", "put"]

#: the entry format (another format's entry is foreign: recomputed)
FORMAT = 1


def key(latex: str, lets: list[str], options: dict) -> str:
    """The store's key of a relation checked with ``lets`` and ``options`` (hex SHA-256)."""
    from rigidsym.checking.verdict_cache import engine_settings
    from rigidsym.core.sources import environment, machinery_digest

    h = hashlib.sha256()
    for part in (f"documents format {FORMAT}", machinery_digest(), environment(),
                 engine_settings(), json.dumps([latex, list(lets),
                                                sorted(options.items())], default=str)):
        h.update(part.encode() + b"\0")
    return h.hexdigest()


def _path(k: str) -> Path:
    return cache.folder("verdicts") / "documents" / k[:2] / f"{k}.json"


def get(k: str) -> dict | None:
    """The record stored under ``k``, or ``None`` (missing, corrupt or foreign)."""
    data = cache.get(_path(k))
    if data is None:
        return None
    try:
        entry = json.loads(data)
    except ValueError:
        return None
    if not isinstance(entry, dict) or entry.get("format") != FORMAT or entry.get("key") != k:
        return None
    rec = entry.get("record")
    return rec if isinstance(rec, dict) else None


def put(k: str, record: dict) -> None:
    """Store ``record`` under ``k`` (atomically, under the cache's lock)."""
    data = json.dumps({"format": FORMAT, "key": k, "record": record}, ensure_ascii=False)
    with cache.lock("verdicts", "documents"):
        _path(k).parent.mkdir(parents=True, exist_ok=True)
        cache.put(_path(k), data.encode())
