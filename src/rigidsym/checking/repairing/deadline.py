"""The repair search's time limit: an alarm that stops the search inside a
step (one symbolic inverse of a final check can take a minute), which the search catches and
reports as "search stopped after N s, K candidates tried"."""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["Late", "time_limit"]


class Late(BaseException):  # noqa: N818  (not an error: the time is up)
    """The repair search's time limit passed inside one of its steps (a symbolic inverse
    of a final check): raised by :func:`time_limit`'s alarm, caught by the search,
    which stops and says so. A ``BaseException``, so that no ``except Exception`` on the
    way (sympy's fallbacks) takes it for a failure and goes on."""


@contextmanager
def time_limit(deadline: float | None) -> Iterator[None]:
    """Within the block, :class:`Late` is raised when ``time.monotonic()`` passes
    ``deadline`` (``SIGALRM``, once), wherever the search is: between candidates the search
    checks the time itself, but one step (sympy's Gauss-Jordan inverse of a 6x6) can take a
    minute. Only in the main thread of a POSIX process whose ``SIGALRM`` has no handler
    already (pytest-timeout's, a caller's), or whose handler is marked ``nestable``: then
    the nearer of the two times stops the search, and the outer alarm is re-armed for its
    own time at the end; elsewhere the block runs unguarded. (The whole check's CPU-time
    limit, :func:`rigidsym.latex.limit.limited`, is another signal, ``SIGPROF``.)"""
    outer = signal.getsignal(signal.SIGALRM) if hasattr(signal, "setitimer") else None
    nested = getattr(outer, "nestable", False)
    if deadline is None or not hasattr(signal, "setitimer") \
            or threading.current_thread() is not threading.main_thread() \
            or (outer is not signal.SIG_DFL and not nested):
        yield
        return
    outer_end = None
    if nested:
        left = signal.getitimer(signal.ITIMER_REAL)[0]
        if left > 0:
            outer_end = time.monotonic() + left
            deadline = min(deadline, outer_end)
    on = [True]

    def _late(signum, frame):
        if on[0]:
            on[0] = False
            raise Late

    old = signal.signal(signal.SIGALRM, _late)
    try:
        signal.setitimer(signal.ITIMER_REAL, max(deadline - time.monotonic(), 1e-3))
        yield
    finally:
        on[0] = False
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
        if outer_end is not None and outer_end > time.monotonic():  # else the check's
            # next step ends it (rigidsym.latex.limit.step), the verdict found kept so far
            signal.setitimer(signal.ITIMER_REAL, outer_end - time.monotonic())
