"""The worked exercises' solutions on the book's data, kept in the user cache:
``rigidsym report`` reads them back instead of solving again while nothing they depend on
changed. A solution is a pickled :class:`~rigidsym.course.worked.Solution` (exact sympy
values, steps and checks), in ``verdicts/`` beside the verdicts (``rigidsym cache clear
--verdicts`` removes both).
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["path", "stored", "store", "FORMAT"]

#: version of a stored solution; an entry of another is never read
FORMAT = 2


def path(ex_id: str, module: str, d) -> Path:
    """Where the solution of ``ex_id`` on ``d`` is kept in the user cache: keyed
    by the data (:meth:`~.data.Data.key`), the exercise's module and the book
    modules it imports, the rest of the package and the libraries' versions, so that a
    changed declaration re-solves the exercises that use it only."""
    import hashlib

    from rigidsym.core import cache as _cache
    from rigidsym.core import sources as _sources

    h = hashlib.sha256()
    for part in (f"solution {FORMAT}", _sources.machinery_digest(),
                 _sources.environment(), repr(_sources.book_module_files(module)),
                 ex_id, repr(d.key())):
        h.update(part.encode() + b"\0")
    key = h.hexdigest()
    return _cache.folder("verdicts") / key[:2] / f"solution-{key}.pickle"


def stored(where: Path, ex_id: str, kind: type):
    """The solution stored at ``where`` (a ``kind``, of ``ex_id``), or ``None`` (none, or
    not readable: solved again)."""
    import pickle

    import sympy as sp

    from rigidsym.core import cache as _cache

    data = _cache.get(where)  # checksummed: a torn or foreign entry is None
    try:
        # rebuilt unevaluated: sympy's pickles re-run each constructor, and an evaluated
        # Mul(1/12, a + b) distributes into a + b terms, so a read-back solution printed
        # differently from the one solved (the exercise page differed cold and warm)
        with sp.evaluate(False):
            s = pickle.loads(data) if data is not None else None
    except Exception:  # noqa: BLE001 -- an entry of another version of a class: solved again
        return None
    return s if isinstance(s, kind) and s.id == ex_id else None


def store(where: Path, s) -> None:
    """Keep the solution ``s`` at ``where`` (atomically, checksummed)."""
    import pickle

    from rigidsym.core import cache as _cache

    try:
        blob = pickle.dumps(s)
    except Exception:  # noqa: BLE001 -- a solution holding something unpicklable: not kept
        return
    _cache.put(where, blob)
