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
    already (pytest-timeout's, a caller's); elsewhere the block runs unguarded."""
    if deadline is None or not hasattr(signal, "setitimer") \
            or threading.current_thread() is not threading.main_thread() \
            or signal.getsignal(signal.SIGALRM) is not signal.SIG_DFL:
        yield
        return
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
