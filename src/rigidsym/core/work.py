"""Counts of the real work a command does: declarations built, ids decided, transcriptions
checked, exercises solved, kernels derived.

A cache hit counts nothing; only the work behind a miss does, so a test can say "a warm
``verify --json`` builds no declaration" without timing anything. Worker processes count in
their own copy; the runner (:mod:`rigidsym.checking.runner`) adds each worker's counts to
the parent's, so :data:`COUNTS` is the whole command's work. Each count is a checkpoint
of :mod:`rigidsym.core.interrupts`, named by its kind: the point where a unit of work
begins. Imports nothing of rigidsym but :mod:`rigidsym.core.interrupts`.
"""

from __future__ import annotations

from collections import Counter

from rigidsym.core.interrupts import checkpoint

__all__ = ["COUNTS", "KINDS", "ENV", "count", "snapshot", "since", "merge", "dump"]

#: what is counted: ``build`` (a declaration's function run: a miss of the registry's
#: built statements), ``load`` (a built statement read from the user cache instead,
#: :mod:`rigidsym.registry.statement_cache`: not a build), ``decide`` (one id decided by
#: the checker), ``transcribe`` (one printed form checked against its LaTeX), ``solve``
#: (one exercise solved), ``derive`` (one kernel derived by the generator: a miss of its
#: store, rigidsym.codegen.inputs)
KINDS = ("build", "load", "decide", "transcribe", "solve", "derive")
#: the environment variable naming a file the command writes its counts to, at its end
#: (``{"build": {id: n}, ...}``: how the tests and ``benchmarks/verify.py`` count the work
#: of a real, fresh command)
ENV = "RIGIDSYM_WORK_FILE"
#: the counts of this process (and of the workers the runner merged), by kind and id
COUNTS: Counter = Counter()


def count(kind: str, what: str) -> None:
    """Count one piece of work of ``kind`` (one of :data:`KINDS`) on ``what`` (an id), as it
    begins (the checkpoint ``kind``)."""
    COUNTS[(kind, what)] += 1
    checkpoint(kind)


def snapshot() -> Counter:
    """A copy of the counts now (for :func:`since`)."""
    return Counter(COUNTS)


def since(before: Counter, kind: str | None = None) -> Counter:
    """The work counted since ``before``: ``{(kind, id): n}``, or ``{id: n}`` of one
    ``kind``."""
    delta = COUNTS - before
    if kind is None:
        return delta
    return Counter({w: n for (k, w), n in delta.items() if k == kind})


def merge(delta: Counter) -> None:
    """Add a worker's counts (:func:`since` of its start) to this process's."""
    COUNTS.update(delta)


def dump() -> None:
    """Write the counts to the file named by :data:`ENV`, if it is set (atomically)."""
    import json
    import os

    where = os.environ.get(ENV)
    if not where:
        return
    out: dict = {k: {} for k in KINDS}
    for (kind, what), n in sorted(COUNTS.items()):
        out.setdefault(kind, {})[what] = n
    tmp = f"{where}.{os.getpid()}.tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(out, f, indent=1)
    os.replace(tmp, where)
