"""Map a function over ``range(n)`` in forked worker processes (a class's handouts, its
grades): the work is set up in this process and the workers inherit it by ``fork``; where
the platform is not Linux, or one core is all there is, the map runs here."""

from __future__ import annotations

import multiprocessing as mp
import os
import sys
from collections.abc import Callable

__all__ = ["forked_map", "jobs"]

_FN: list = []


def jobs(n: int) -> int:
    """Worker processes for ``n`` items: the cores this process may use, at most 8."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:              # not Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, 8, n))


def _call(i: int):
    return _FN[0](i)


def forked_map(fn: Callable[[int], object], n: int) -> list:
    """``[fn(0), ..., fn(n - 1)]``, in order; ``fn`` may read anything this process holds
    (the workers are forks of it). Every worker has ended when it returns."""
    k = jobs(n)
    # fork only on Linux: macOS's system libraries are not fork-safe (Python's own warning)
    if k == 1 or not sys.platform.startswith("linux"):
        return [fn(i) for i in range(n)]
    from concurrent.futures import ProcessPoolExecutor

    from rigidsym.core.interrupts import for_worker

    _FN[:] = [fn]
    pool = ProcessPoolExecutor(k, mp_context=mp.get_context("fork"), initializer=for_worker)
    try:
        return list(pool.map(_call, range(n)))
    except KeyboardInterrupt:
        # the items not begun are cancelled; those under way end (a worker killed while it
        # writes its result would leave the pool's reader waiting for the rest forever)
        _quiet_pool_thread()
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    finally:
        pool.shutdown(wait=True)
        _FN.clear()


def _quiet_pool_thread() -> None:
    """An interrupted map's pool breaks as its workers are stopped, and the executor's
    management thread then sets an exception on futures the map already cancelled:
    CPython 3.11 raises ``InvalidStateError`` there and prints it as a thread's traceback
    (the interrupt's one line must stay the only one). From now on this process's thread
    hook drops a ``BrokenProcessPool`` or ``InvalidStateError`` of a thread; any other
    exception of a thread is printed as before."""
    import threading
    from concurrent.futures import InvalidStateError
    from concurrent.futures.process import BrokenProcessPool

    previous = threading.excepthook

    def hook(args) -> None:
        if args.exc_type is not None and issubclass(args.exc_type, (InvalidStateError,
                                                                    BrokenProcessPool)):
            return
        previous(args)

    threading.excepthook = hook
