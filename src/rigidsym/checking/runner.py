"""The parallel runner: check ids over worker processes, with progress that says what it
is doing (``checking 3.77a, 3.94``), what each finished id turned out to be, and a stable
estimate of the time left from each id's duration in earlier runs."""

from __future__ import annotations

import time
from collections.abc import Callable
from contextlib import nullcontext
from dataclasses import dataclass
from functools import partial

from rigidsym.checking import verdict_cache
from rigidsym.checking.repairing.correction import RepairSettings
from rigidsym.core import interrupts
from rigidsym.core import work as _work
from rigidsym.core.progress import Reporter, load_durations, save_durations

__all__ = ["run_checks", "check_cached", "verdict_words", "Extra"]


@dataclass(frozen=True)
class Extra:
    """Work per id done beside its verdict, in the worker that built the id (the
    transcription record), so that the parent never builds a declaration again.

    Attributes:
        missing: reads the stored results of the ids it is given into the parent and
            returns those it has none for (called in the parent, before the checks).
        compute: the result of one id (called in a worker, after the id's check, or alone
            for an id whose verdict is cached); stored by it where it keeps results.
        keep: gives the parent a result a worker computed.
        words: what it computes, for the progress line (``"transcriptions"``).
    """

    missing: Callable[[list[str]], list[str]]
    compute: Callable[[str], object]
    keep: Callable[[str, object], None]
    words: str = "transcriptions"

#: where earlier runs' seconds per id are kept (the user cache's ``timings/checks.json``)
DURATIONS = "checks"
#: the seconds assumed for an id never timed before, until some id of the run finishes
_PRIOR = 0.5
#: how many ids' worth of weight the prior keeps in the mean of a run's first ids
_SHRINK = 5
_STARTED = None  # the start queue, in a worker (set by the pool's initializer)


def _init_worker(queue) -> None:
    global _STARTED
    _STARTED = queue
    interrupts.for_worker()


def _check_one(eq_id: str, settings: RepairSettings | None = None, expanded: bool = True):
    from rigidsym.checking.checker import check
    if _STARTED is not None:
        _STARTED.put((eq_id, time.time()))
    settings = settings or RepairSettings()
    return check(eq_id, repairs=settings.enabled, repair_budget=settings.budget,
                 expanded=expanded)


def _decide(eq_id: str, settings: RepairSettings, expanded: bool, key: str | None,
            wait: bool = True):
    """The result of ``eq_id``: checked and stored under ``key`` while its lock is held
    (:func:`rigidsym.checking.verdict_cache.claimed`), or read from the cache where another
    process stored it meanwhile; ``None`` when another process is deciding it and not
    ``wait``. Without a key (no cache, or never cached): checked."""
    if key is None:
        return _check_one(eq_id, settings, expanded)
    with verdict_cache.claimed(key, wait) as held:
        if not held:
            return None
        hit = verdict_cache.read(eq_id, key, expanded)
        if hit is not None:
            return hit
        r = _check_one(eq_id, settings, expanded)
        verdict_cache.store([r], {eq_id: key})  # per id: an interrupt keeps it
        return r


def check_cached(eq_id: str, repairs: bool = True, repair_budget: int | None = None,
                 expanded: bool = True, cache: bool = True):
    """One id through the verdict cache (``rigidsym show``, :func:`rigidsym.api.check`):
    read where ``verdict``, ``report`` or an earlier call stored it under the same key,
    else checked and stored (one store of decided work).

    Args:
        eq_id: a registered id.
        repairs, repair_budget: those of :func:`rigidsym.checking.checker.check` (they
            join the key).
        expanded: the expanded strings are wanted (a result stored without them is then
            checked again).
        cache: ``False`` checks and stores nothing.

    Returns:
        The :class:`~rigidsym.checking.checker.Outcome` (``cached`` true when read).

    Raises:
        KeyError: for an id that is not registered.
    """
    settings = RepairSettings(repairs, repair_budget)
    key = verdict_cache.key_of(eq_id, {}, settings) if cache else None
    return _decide(eq_id, settings, expanded, key)


def _decided(ids: list[str], settings: RepairSettings, expanded: bool, keys: dict):
    """``(id, result)`` of each of ``ids``: those another process is deciding last, once it
    has (two runs at once share the work rather than both doing all of it)."""
    later = []
    for i in ids:
        r = _decide(i, settings, expanded, keys.get(i), wait=False)
        if r is None:
            later.append(i)
        else:
            yield i, r
    for i in later:
        yield i, _decide(i, settings, expanded, keys.get(i), wait=True)


def _check_group(ids: list[str], settings: RepairSettings | None = None,
                 expanded: bool = True, extra: Extra | None = None,
                 extra_ids: frozenset = frozenset(), keys: dict | None = None):
    """Check a group of ids in one worker, each result sent on the queue as it is known
    (so that progress stays per id), the ``extra`` result of each of ``extra_ids`` after
    it; returns the work the worker counted (:mod:`rigidsym.core.work`)."""
    before = _work.snapshot()
    for i, r in _decided(ids, settings or RepairSettings(), expanded, keys or {}):
        if i in extra_ids:
            _STARTED.put(("extra", i, extra.compute(i)))
        _STARTED.put(("done", r))
    return _work.since(before)


def _extra_group(ids: list[str], extra: Extra):
    """The ``extra`` results of ids whose verdict is cached, in one worker; returns
    ``([(id, result)...], the work counted)``."""
    before = _work.snapshot()
    out = [(i, extra.compute(i)) for i in ids]
    return out, _work.since(before)


def _group_of(eq_id: str) -> str:
    """The ids that share the declarations' cached models (a book section, or a user
    module): checked in one worker, so that each model is derived once, not per worker."""
    from rigidsym.registry.declarations import REGISTRY, is_user_id, section_of
    if is_user_id(eq_id):
        return REGISTRY[eq_id].module
    return section_of(eq_id)


def verdict_words(r) -> str:
    """``"3.57 does-not-hold, as expected"``; ``"3.16 undecided, EXPECTED verified"``."""
    if r.verdict == r.expected:
        return f"{r.id} {r.verdict}" + (", as expected" if r.verdict == "does-not-hold" else "")
    return f"{r.id} {r.verdict}, EXPECTED {r.expected}"


class _Estimate:
    """Time left from predicted seconds per id: earlier runs' durations, scaled by how this
    run compares with them (a loaded machine), else the mean of this run's ids so far."""

    def __init__(self, ids: list[str], jobs: int):
        self.before = load_durations(DURATIONS)
        self.jobs = max(1, jobs)
        self.actual: dict[str, float] = {}
        self.ids = ids
        self._memo: tuple = (-1, (1.0, _PRIOR))

    def _pred(self, i: str) -> float:
        scale, mean = self._rates()
        return self.before[i] * scale if i in self.before else mean

    def _rates(self) -> tuple[float, float]:
        """``(scale, mean)`` as of the ids finished so far, computed once per finished id
        (once per id and per progress tick, 20 times a second, it took a second of
        the parent's CPU in a cold chapter run, beside the workers, and 33 s on a loaded
        machine)."""
        n = len(self.actual)
        if self._memo[0] != n:
            known = [i for i in self.actual if i in self.before and self.before[i] > 0.05]
            scale = 1.0
            if len(known) >= 3:
                s = sum(self.actual[i] for i in known) / sum(self.before[i] for i in known)
                scale = min(max(s, 0.25), 4.0)
            # never timed: this run's mean so far, shrunk towards the prior while it rests
            # on few ids (one slow id first must not multiply the estimate by ten)
            mean = (sum(self.actual.values()) + _SHRINK * _PRIOR) / (n + _SHRINK)
            self._memo = (n, (scale, mean))
        return self._memo[1]

    def order(self) -> list[str]:
        """The ids longest first (known durations), so the workers finish together."""
        return sorted(self.ids, key=lambda i: -self.before.get(i, _PRIOR))

    def groups(self) -> list[list[str]]:
        """The ids by :func:`_group_of`, the heaviest group first (known durations, else
        the prior per id), each group in the order given; one id per group (longest first)
        when there are fewer groups than workers (a single user module), so that every
        worker has work."""
        out: dict[str, list[str]] = {}
        for i in self.ids:
            out.setdefault(_group_of(i), []).append(i)
        if len(out) < self.jobs:
            return [[i] for i in self.order()]
        return sorted(out.values(), key=lambda g: -sum(self.before.get(i, _PRIOR) for i in g))

    def left(self, running: dict[str, float]) -> float:
        now = time.time()
        rest = sum(self._pred(i) for i in self.ids if i not in self.actual and i not in running)
        rest += sum(max(self._pred(i) - (now - t), 0.0) for i, t in running.items())
        return rest / min(self.jobs, max(1, len(self.ids) - len(self.actual)))


def run_checks(ids: list[str], jobs: int = 1, progress: bool = True, cache: bool = False,
               reporter: Reporter | None = None, repairs: bool = True,
               repair_budget: int | None = None, expanded: bool = True,
               extra: Extra | None = None):
    """Check ``ids`` (in parallel over ``jobs`` processes), results in the order given.

    Args:
        ids: the ids to check.
        jobs: worker processes (1: in this process).
        progress: show progress on stderr (:mod:`rigidsym.core.progress`).
        cache: read results from the verdict cache where their key matches
            (:mod:`rigidsym.checking.verdict_cache`; ``Outcome.cached`` is then true);
            compute and store the others.
        reporter: the command's :class:`~rigidsym.core.progress.Reporter` (its phases), else
            one of its own.
        repairs, repair_budget: those of :func:`rigidsym.checking.checker.check` (they
            join the cache key).
        expanded: print each result's expanded strings (``printed``, ``derived``,
            ``corrected``; :func:`rigidsym.checking.checker.check`); a cached result
            without them is then checked again.
        extra: work per id done beside the verdict in the worker that builds it
            (:class:`Extra`); the ids whose verdict is cached but whose extra result is not
            get it from the workers too, after the checks.

    Returns:
        The :class:`~rigidsym.checking.checker.Outcome` of each id, in the order of ``ids``.
    """
    settings = RepairSettings(repairs, repair_budget)
    hits, keys = ({}, {})
    if cache:
        hits, keys = verdict_cache.lookup(ids, settings)
        if expanded:  # stored by a run that did not print them (rigidsym verify)
            hits = {i: r for i, r in hits.items() if r.derived is not None}
    results = dict(hits)
    todo = [i for i in ids if i not in hits]
    # what the workers stored is kept, and the interrupted command says how much: counted
    # when it says so, so that an interrupt in the tail below (the durations written) or
    # after the return counts the same stored entries
    interrupts.note_kept(partial(verdict_cache.present, keys), len(ids))
    try:
        _run(ids, todo, results, jobs, progress, reporter, settings, expanded, extra, keys)
    finally:
        save_durations(DURATIONS, {i: results[i].seconds for i in todo
                                   if i in results and not results[i].cached})
    return [results[i] for i in ids]


def _run(ids, todo, results, jobs, progress, reporter, settings, expanded, extra, keys):
    """The checks of :func:`run_checks`: ``todo`` over the workers, results into
    ``results``, each stored as it is decided (under ``keys``)."""
    hits = len(ids) - len(todo)
    extra_ids = frozenset(extra.missing(ids)) if extra else frozenset()
    rep = reporter or Reporter("rigidsym verify", enabled=progress)
    est = _Estimate(todo, jobs)
    what = f"checking {len(ids)} ids" + (f" ({hits} from the cache)" if hits else "")
    with (nullcontext(rep) if reporter else rep), \
            rep.phase(what, total=len(ids), doing="starting") as ph:
        if hits:
            ph.advance(hits, label=f"{hits} from the verdict cache")
        if jobs > 1 and len(todo) > 1:
            _parallel(est, min(jobs, len(todo)), ph, results,
                      partial(_check_group, settings=settings, expanded=expanded,
                              extra=extra, extra_ids=extra_ids, keys=keys), extra)
        else:
            ph.label(f"checking {todo[0]}" if todo else "checking")
            ph.estimate(est.left({todo[0]: time.time()} if todo else {}))
            for i, r in _decided(todo, settings, expanded, keys):
                results[i] = r
                if i in extra_ids:
                    extra.keep(i, extra.compute(i))
                _finished(r, est, ph, {})
        ph.finish(_summary(results.values()))
    rest = [i for i in ids if i in extra_ids and i not in todo]
    if rest:
        _extras(rest, jobs, extra, rep)


def _finished(r, est: _Estimate, ph, running: dict) -> None:
    est.actual[r.id] = r.seconds
    running.pop(r.id, None)
    ph.advance(1, label=_doing(running, r))
    ph.estimate(est.left(running))


def _doing(running: dict, last=None) -> str:
    now = ", ".join(sorted(running)) if running else ""
    parts = ([f"checking {now}"] if now else []) + ([verdict_words(last)] if last else [])
    return " · ".join(parts) or "checking"


def _extras(ids: list[str], jobs: int, extra: Extra, rep: Reporter) -> None:
    """The ``extra`` results of ids whose verdict was cached, over ``jobs`` fork workers
    by :func:`_group_of` (so that a section's models are built once)."""
    groups: dict[str, list[str]] = {}
    for i in ids:
        groups.setdefault(_group_of(i), []).append(i)
    with rep.phase(f"{extra.words} of {len(ids)} ids", total=len(ids)) as ph:
        if jobs > 1 and len(groups) > 1:
            import multiprocessing as mp

            with mp.get_context("fork").Pool(min(jobs, len(groups)),
                                             initializer=interrupts.for_worker) as pool:
                for out, work in pool.imap_unordered(partial(_extra_group, extra=extra),
                                                     list(groups.values())):
                    _work.merge(work)
                    for i, value in out:
                        extra.keep(i, value)
                    ph.advance(len(out))
        else:
            for i in ids:
                extra.keep(i, extra.compute(i))
                ph.advance(1)
        ph.finish(f"{len(ids)} {extra.words}")


def _parallel(est: _Estimate, jobs: int, ph, results: dict, group,
              extra: Extra | None = None) -> None:
    """Groups of ids (:meth:`_Estimate.groups`) over ``jobs`` fork workers, heaviest group
    first; each worker reports every id it starts and every result on one queue."""
    import multiprocessing as mp

    # the checker and what it imports lazily, once before the fork rather than per worker
    import rigidsym.checking.checker  # noqa: F401

    ctx = mp.get_context("fork")
    queue = ctx.SimpleQueue()
    running: dict[str, float] = {}
    with ctx.Pool(jobs, initializer=_init_worker, initargs=(queue,)) as pool:
        pending = pool.map_async(group, est.groups(), chunksize=1)
        last = None
        while len(est.actual) < len(est.ids):
            if not queue.empty():
                msg = queue.get()
                if msg[0] == "done":
                    results[msg[1].id] = last = msg[1]
                    _finished(msg[1], est, ph, running)
                elif msg[0] == "extra":
                    extra.keep(msg[1], msg[2])
                else:
                    running[msg[0]] = msg[1]
                continue
            if pending.ready() and queue.empty():
                break
            time.sleep(0.05)
            ph.label(_doing(running, last))
            ph.estimate(est.left(running))
        for work in pending.get():  # a worker's exception is raised here
            _work.merge(work)  # what each worker built and decided


def _summary(results) -> str:
    from collections import Counter

    from rigidsym.registry.declarations import VERDICTS

    c = Counter(r.verdict for r in results)
    off = sum(r.verdict != r.expected for r in results)
    words = ", ".join(f"{c[v]} {v}" for v in VERDICTS if c[v])
    return words + (f"; {off} differ from the recorded expectation" if off else "")
