"""The verdict cache: a checked result is stored once and read back while nothing it depends
on has changed (``<cache>/verdicts/``, see :mod:`rigidsym.core.cache` for where and how).

**The key** of an id is a SHA-256 over everything its verdict depends on:

- the source of the ``rigidsym`` package (every file, by content) but the book's ``.py``
  modules, which count per id: for a book id its declaring module and the book modules it
  imports, transitively (:mod:`rigidsym.core.sources`);
- for a user id, the declaring module's file and every *local* module it imports,
  transitively (an ``import`` in its source, resolved through ``sys.modules``; local means
  outside the standard library and site-packages), by content;
- the declaration itself: its metadata (title, kind, LaTeX, expected verdict, ...) and the
  compiled code of its function;
- the versions of Python, sympy, mpmath and python-flint;
- the engine's settings as they are at run time (point counts, precision, limits);
- the repair search's settings: on or off, the budget in effect for the id (the run's, the
  declaration's or the default) and the version of the edit vocabulary
  (:data:`rigidsym.checking.repairing.mutate.VOCABULARY_VERSION`).

**Not tracked** (say ``--no-cache`` or ``rigidsym cache clear --verdicts`` after changing
them): data files a declaration reads at run time; modules imported dynamically
(``importlib``) or by a helper's C code; environment variables a declaration reads; a
helper module imported before rigidsym first looked at it and edited in between. A helper
module edited on disk *after* this process imported it is detected: its dependents are
checked and not stored (the code in memory is not the code on disk).

A declaration that is not the function its module defines (replaced in a notebook or a
test) or whose module has no file is never cached. Entries are written atomically under
the cache lock; an entry that is corrupt or foreign (checksum, format, key or id do not
match) is ignored with a :class:`VerdictCacheWarning` and recomputed, never trusted.
"""

from __future__ import annotations

import hashlib
import json
import os
import site
import sys
import sysconfig
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import fields
from functools import cache
from pathlib import Path

from rigidsym.core import cache as _cache
from rigidsym.core import config as _config
from rigidsym.core import sources as _sources
from rigidsym.core.files import write_atomic_bytes
from rigidsym.core.settings import ENGINE
from rigidsym.registry import usermodules
from rigidsym.registry.declarations import REGISTRY, Equation, is_user_id

__all__ = ["lookup", "store", "key_of", "transcription_key", "VerdictCacheWarning", "FORMAT",
           "read", "claimed", "present", "certificate_key", "read_certificate",
           "store_certificate", "engine_settings"]

#: version of the entry format (an entry of another format is foreign)
FORMAT = 1


class VerdictCacheWarning(UserWarning):
    """A cache entry was ignored (corrupt or foreign) or a module changed under us."""


# --------------------------------------------------------------------------- digests
_file_digest = _sources.file_digest
_package_roots = _sources.package_roots
package_digest = _sources.package_digest  # the package's files
_environment = _sources.environment


def _settings() -> str:
    """The engine's settings as they are now (a test or a user may have changed them): every
    field of :data:`rigidsym.core.settings.ENGINE`, and the constants of the algorithms that
    stay in their modules (the Schwartz-Zippel sample set, the fast filter's modulus)."""
    from rigidsym.checking.repairing import fasteval
    from rigidsym.zero import decide

    values = {f.name: str(getattr(ENGINE, f.name)) for f in fields(ENGINE)}
    values |= {"zero.decide.SAMPLE_SET_SIZE": str(decide.SAMPLE_SET_SIZE),
               "repairing.fasteval.PRIME": str(fasteval.PRIME)}
    return json.dumps(values, sort_keys=True)


def engine_settings() -> str:
    """The engine's settings as they are now (JSON), a part of every key: a verdict store of
    another kind (``rigidsym.documents.store``) keys on them as this cache does."""
    return _settings()


@cache
def _nonlocal_dirs() -> tuple[Path, ...]:
    paths = {sysconfig.get_paths().get(k) for k in ("stdlib", "platstdlib", "purelib",
                                                    "platlib")}
    paths |= set(site.getsitepackages()) | {site.getusersitepackages()}
    return tuple(Path(p).resolve() for p in paths if p) + tuple(_package_roots())


def _is_local(path: Path) -> bool:
    return path.suffix == ".py" and not any(d == path or d in path.parents
                                            for d in _nonlocal_dirs())


_imported_names = _sources.imported_names


#: path -> (id of the module object, digest of the file when first seen with it)
_SEEN: dict[str, tuple[int, str]] = {}


def _module_files(name: str) -> dict[str, str] | None:
    """``{path: digest}`` of module ``name`` and of the local modules it imports,
    transitively; ``None`` when one of them changed on disk since it was imported."""
    out: dict[str, str] = {}
    stack = [name]
    while stack:
        mod = sys.modules.get(stack.pop())
        file = getattr(mod, "__file__", None)
        if not file:
            continue
        path = Path(file).resolve()
        if str(path) in out or not _is_local(path) or not path.is_file():
            continue
        now = _file_digest(path)
        seen = _SEEN.get(str(path))
        if seen is not None and seen[0] == id(mod) and seen[1] != now:
            warnings.warn(f"verdict cache: {path} changed on disk since it was imported; the "
                          f"ids that depend on it are checked and not stored (restart or "
                          f"reload it)", VerdictCacheWarning, stacklevel=3)
            return None
        _SEEN[str(path)] = (id(mod), now)
        out[str(path)] = now
        stack.extend(n for n in _imported_names(path, mod.__package__ or "")
                     if n in sys.modules)
    return out


def _declared_function(eq: Equation):
    obj = sys.modules.get(eq.module)
    for part in eq.function.split("."):
        obj = getattr(obj, part, None)
    return obj


def _repair_key(eq: Equation, settings) -> str:
    from rigidsym.checking.repairing.correction import RepairSettings, budget_of
    from rigidsym.checking.repairing.mutate import VOCABULARY_VERSION

    settings = settings or RepairSettings()
    return json.dumps({"repairs": settings.enabled, "vocabulary": VOCABULARY_VERSION,
                       "budget": budget_of(eq, settings) if settings.enabled else None})


def _declaration_parts(eq_id: str, deps: dict | None) -> list[str] | None:
    """What any result of ``eq_id`` depends on besides the run's settings: the package,
    the environment, the declaration's metadata and module files (``None``: never
    cached)."""
    eq = REGISTRY[eq_id]
    mod = sys.modules.get(eq.module)
    if mod is None or not getattr(mod, "__file__", None) or "<locals>" in eq.function \
            or _declared_function(eq) is not eq.build_fn:
        return None
    if eq.module == _config.BOOK or eq.module.startswith(_config.BOOK + "."):
        # the declaring module and the book modules it imports: an edit elsewhere in the
        # book leaves its verdicts cached
        files: dict | None = dict(_sources.book_module_files(eq.module))
    else:
        deps = {} if deps is None else deps
        if eq.module not in deps:
            deps[eq.module] = _module_files(eq.module)
        files = deps[eq.module]
    if files is None:
        return None
    meta = [eq.id, eq.title, eq.section, eq.kind, eq.latex, eq.expected, eq.cause,
            eq.evidence, eq.singular, eq.module, eq.function,
            getattr(eq, "repair_budget", None)]
    return [f"format {FORMAT}", _sources.machinery_digest(), _environment(), json.dumps(meta),
            json.dumps(sorted(files.items()))]


def _digest(parts: list[str], eq_id: str) -> str:
    h = hashlib.sha256()
    for part in parts:
        h.update(part.encode() + b"\0")
    # version 2: no back-references, whose use depends on reference counts at the time
    # (a key computed after a check differed from one computed before it)
    # version 3: without the file's path, which an install moves
    h.update(_sources.code_bytes(REGISTRY[eq_id].build_fn.__code__))
    return h.hexdigest()


def key_of(eq_id: str, _deps: dict | None = None, settings=None) -> str | None:
    """The cache key of ``eq_id`` (hex SHA-256), or ``None`` when it must not be cached (a
    declaration replaced in memory, a module without a file, a helper changed on disk).
    ``settings`` are the run's :class:`rigidsym.checking.repairing.correction.RepairSettings`.

    Raises:
        KeyError: for an id that is not registered.
    """
    parts = _declaration_parts(eq_id, _deps)
    if parts is None:
        return None
    return _digest(parts + [_settings(), _repair_key(REGISTRY[eq_id], settings)], eq_id)


def _built_path(eq_id: str, deps: dict) -> Path | None:
    parts = _declaration_parts(eq_id, deps)
    if parts is None:
        return None
    key = _digest(parts + ["built"], eq_id)
    return _cache.folder("verdicts") / key[:2] / f"{key}.built"  # a mark, not an entry


def known_to_build(ids: tuple[str, ...]) -> set[str]:
    """The ids of ``ids`` whose declaration, as it is now, built before: a result of it is
    stored (a declaration that does not build is ``undecided``, never stored)."""
    deps: dict = {}
    out = set()
    for i in ids:
        path = _built_path(i, deps)
        if path is not None and path.exists():
            out.add(i)
    return out


def transcription_key(eq_id: str, _deps: dict | None = None) -> str | None:
    """The cache key of ``eq_id``'s transcription record: what
    :func:`key_of` covers but the engine's and the repair search's settings, which a
    transcription does not depend on; found without building the declaration. ``None``
    when it must not be cached.

    Raises:
        KeyError: for an id that is not registered.
    """
    parts = _declaration_parts(eq_id, _deps)
    return None if parts is None else _digest(parts + ["transcription"], eq_id)


# --------------------------------------------------------------------------- entries
def _path(key: str) -> Path:
    return _cache.folder("verdicts") / key[:2] / f"{key}.json"


def present(keys: dict) -> int:
    """How many of ``keys`` (``id -> key``, ``None``: never cached) have an entry stored
    (what an interrupted run kept)."""
    return sum(1 for k in keys.values() if k and _path(k).exists())


@contextmanager
def claimed(key: str, wait: bool = True) -> Iterator[bool]:
    """Hold the lock of one key while its id is decided and stored, so that two processes
    share the work rather than both doing it: ``<verdicts>/ab/<key>.lock``,
    locked with ``flock``, which the system releases when the holder exits or is killed.

    Args:
        key: the id's cache key (:func:`key_of`).
        wait: wait for another holder; ``False`` yields ``False`` at once when it is held.

    Yields:
        Whether this process holds the lock (always ``True`` with ``wait``, and where
        ``fcntl`` is missing, not POSIX: no sharing there).
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX
        yield True
        return
    where = _cache.folder("verdicts") / key[:2]
    where.mkdir(parents=True, exist_ok=True)
    fd = os.open(where / f"{key}.lock", os.O_RDWR | os.O_CREAT, 0o666)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
        except BlockingIOError:
            yield False
            return
        yield True
    finally:
        os.close(fd)  # releases the lock


def read(eq_id: str, key: str, expanded: bool = False):
    """The stored result of ``eq_id`` under ``key`` (``Outcome.cached`` true), or ``None``;
    with ``expanded``, ``None`` also for a result stored without its expanded strings."""
    r = _read(eq_id, key)
    return None if r is None or (expanded and r.derived is None) else r


def _entry(path: Path, eq_id: str, key: str) -> dict:
    """The entry at ``path``, its checksum, format, key and id checked.

    Raises:
        ValueError: a checksum that does not match, or an entry written for another key.
    """
    data = _cache.get(path)
    if data is None:
        raise ValueError("checksum does not match")
    entry = json.loads(data)
    if entry.get("format") != FORMAT or entry.get("key") != key or entry.get("id") != eq_id:
        raise ValueError("written for another key")
    return entry


def _read(eq_id: str, key: str):
    """The cached result of ``eq_id`` under ``key``, or ``None`` (missing, or ignored)."""
    from rigidsym.checking.checker import Outcome

    path = _path(key)
    if not path.exists():
        return None
    try:
        row = _entry(path, eq_id, key)["result"]
        if set(row) != {f.name for f in fields(Outcome)} or row["id"] != eq_id:
            raise ValueError("not a result of this version")
        return Outcome(**dict(row, cached=True))
    except (ValueError, TypeError, KeyError, AttributeError) as exc:
        warnings.warn(f"verdict cache: ignored the entry of {eq_id} ({path}): {exc}; "
                      f"recomputed", VerdictCacheWarning, stacklevel=3)
        return None


def lookup(ids: list[str], settings=None) -> tuple[dict, dict]:
    """Cached results and keys of ``ids`` (under the run's repair ``settings``).

    Returns:
        ``(hits, keys)``: ``id -> Outcome`` (with ``cached=True``) for the ids found, and
        ``id -> key`` for every id that may be stored (``None``: never cached).
    """
    deps: dict = {}
    keys = {i: key_of(i, deps, settings) for i in ids}
    hits = {}
    with _cache.lock("verdicts"):
        for i, k in keys.items():
            r = _read(i, k) if k else None
            if r is not None:
                hits[i] = r
    return hits, keys


def store(results: list, keys: dict) -> int:
    """Write each result whose id has a key (atomically, under the cache lock); returns how
    many were written. An ``undecided`` result is never written: it may come from a defect
    of the run (memory, an interrupt) rather than of the code, and is worth a new look."""
    todo = [(r, keys[r.id]) for r in results if keys.get(r.id) and r.verdict != "undecided"]
    if not todo:
        return 0
    deps: dict = {}
    with _cache.lock("verdicts"):
        for r, k in todo:
            row = dict(r.as_json(), cached=False)
            entry = {"format": FORMAT, "key": k, "id": r.id, "result": row}
            _cache.put(_path(k), json.dumps(entry).encode())  # key order is record order
            built = _built_path(r.id, deps) if is_user_id(r.id) else None
            if built is not None:  # a user module's load need not build it again
                write_atomic_bytes(built, b"")
    return len(todo)


# --------------------------------------------------------------------------- certificates
def certificate_key(eq_id: str, verdict: str, members: list[dict] | None,
                    _deps: dict | None = None) -> str | None:
    """The key of an id's certificate (hex SHA-256): its verdict's key (the package's
    source, the certificate's code included, the declaration, the engine's settings), the
    verdict and the members' statuses the certificate reads; ``None`` where the id is never
    cached (:func:`key_of`)."""
    k = key_of(eq_id, _deps)
    status = json.dumps([m.get("status") for m in members or []])
    return None if k is None else _digest([k, "certificate", verdict, status], eq_id)


def _certificate_path(key: str) -> Path:
    return _cache.folder("verdicts") / key[:2] / f"{key}.certificate.json"


def read_certificate(eq_id: str, key: str) -> dict | str | None:
    """The stored certificate of ``eq_id`` under ``key`` (a dict), the stored reason it has
    none (a str), or ``None``: nothing stored, or an entry ignored with a
    :class:`VerdictCacheWarning` (corrupt or foreign: recomputed, never trusted)."""
    path = _certificate_path(key)
    if not path.exists():
        return None
    try:
        made = _entry(path, eq_id, key).get("certificate")
        if not isinstance(made, dict | str):
            raise ValueError("no certificate in it")
        return made
    except (ValueError, TypeError, AttributeError) as exc:
        warnings.warn(f"verdict cache: ignored the certificate of {eq_id} ({path}): {exc}; "
                      f"recomputed", VerdictCacheWarning, stacklevel=2)
        return None


def store_certificate(eq_id: str, key: str, made: dict | str) -> None:
    """Store ``made``, the certificate of ``eq_id`` (a dict) or the reason it has none (a
    str), under ``key`` (:func:`certificate_key`), atomically under the cache lock."""
    entry = {"format": FORMAT, "key": key, "id": eq_id, "certificate": made}
    with _cache.lock("verdicts"):
        _cache.put(_certificate_path(key), json.dumps(entry).encode())


usermodules.KNOWN_TO_BUILD = known_to_build
