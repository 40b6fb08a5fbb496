"""The time limit of ``rigidsym check --latex``: past it the answer is ``undecided``, naming
the step it was in and a hint, never a run without end.

The limit is on the **CPU time** of the checking process (``time.process_time``: user and
system time of its threads), never the wall clock: a statement decided on an idle machine is
decided alike beside other busy processes, which slow the wall clock and not the CPU time the
check spends.

A check passes through named steps (:data:`STEPS`): reading the LaTeX and the ``--let``s,
the symbolic zero test (with the repair search), the other readings, the numeric cross-check.
:func:`limited` arms a profiling timer (``ITIMER_PROF``, ``SIGPROF``: it counts the
process's CPU time) for the whole check and :func:`step` marks each step as it begins; when
the time passes, :class:`TimeUp` is raised in the step running then. The repair search's own
wall-clock alarm (``SIGALRM``) is another signal and runs inside it (it stops the search,
never the verdict), and at each step boundary a passed CPU deadline ends the check too (also
where no timer can be armed: outside the main thread, on a platform without
``setitimer``).

A deterministic hook for tests: with ``RIGIDSYM_LATEX_LIMIT_AT=STEP`` (a name of
:data:`STEPS`) the limit counts as passed the moment ``STEP`` begins, and the clock is not
consulted at all (no alarm, no deadline), so that a test of the undecided answer never
depends on the machine's speed or load.
"""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["DEFAULT_SECONDS", "ENV", "STEPS", "HOOK", "TimeUp", "limited", "step", "reason",
           "seconds_argument", "default_seconds"]

#: the default limit of one ``check --latex``, seconds
DEFAULT_SECONDS = 60.0
#: the environment variable that sets the default limit instead: seconds, or ``none`` (the
#: test suite sets ``none``, so that no verdict of it depends on the machine's load)
ENV = "RIGIDSYM_LATEX_TIMEOUT"
#: the steps of a check, by name, each with the words that say it and a hint for a statement
#: that the step could not finish in time
STEPS = {
    "reading": ("reading the LaTeX and the --let declarations",
                "split a long --let model into smaller named ones"),
    "deciding": ("the symbolic zero test (and the repair search)",
                 "write trigonometric functions of one angle through its half-angle "
                 "(t = tan(θ/2)), cancel a sin or cos that divides by hand, or give a "
                 "longer --timeout"),
    "readings": ("deciding the other readings",
                 "settle the choice with the --let the reading names"),
    "cross-check": ("the numeric cross-check of the verdict",
                    "give a longer --timeout"),
}
#: the environment variable of the deterministic hook (see the module's docstring)
HOOK = "RIGIDSYM_LATEX_LIMIT_AT"
#: the running check's limit: its deadline (``time.process_time()``), its length in CPU
#: seconds, the
#: step running now; ``None`` deadline: no limit
_NOW: dict = {"deadline": None, "seconds": None, "step": None}


class TimeUp(BaseException):  # noqa: N818  (not an error: the time is up)
    """The limit of a check passed in ``step`` (a name of :data:`STEPS`). A
    ``BaseException``, so that no ``except Exception`` on the way (sympy's fallbacks, the
    checker's own undecided) takes it for a failure and goes on."""

    def __init__(self, step: str, seconds: float | None):
        super().__init__(step)
        self.step = step
        self.seconds = seconds


def reason(exc: TimeUp) -> str:
    """The one-line reason of an ``undecided`` past the limit: the limit, the step, a hint."""
    words, hint = STEPS[exc.step]
    limit = "the time limit" if exc.seconds is None else f"the time limit ({exc.seconds:g} s)"
    return (f"{limit} passed during {words} (step '{exc.step}'); hint: {hint}; "
            f"--timeout S sets the limit")


def seconds_argument(x, name: str = "timeout") -> float | None:
    """``x`` as a limit in seconds: a positive number, or ``None`` for none.

    Raises:
        ValueError: ``x`` is neither, naming ``name``.
    """
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, int | float) or not x > 0 or x != x:
        raise ValueError(f"{name}: expected a positive number of seconds or None, got {x!r}")
    return float(x)


def default_seconds() -> float | None:
    """The default limit: :data:`ENV` where it is set, else :data:`DEFAULT_SECONDS`.

    Raises:
        ValueError: :data:`ENV` is neither a positive number nor ``none``, naming it.
    """
    text = os.environ.get(ENV, "").strip()
    if not text:
        return DEFAULT_SECONDS
    if text.lower() == "none":
        return None
    try:
        return seconds_argument(float(text), ENV)
    except ValueError:
        raise ValueError(f"{ENV}: expected a positive number of seconds or 'none', got "
                         f"{text!r}") from None


def step(name: str) -> None:
    """Step ``name`` (a key of :data:`STEPS`) begins. Raises :class:`TimeUp` naming it where
    the limit has passed already, or where :data:`HOOK` names it.

    Raises:
        ValueError: ``name`` is no step.
    """
    if name not in STEPS:
        raise ValueError(f"step: expected one of {', '.join(STEPS)}, got {name!r}")
    _NOW["step"] = name
    if os.environ.get(HOOK, "").strip() == name:
        raise TimeUp(name, _NOW["seconds"])
    deadline = _NOW["deadline"]
    if deadline is not None and time.process_time() >= deadline:
        raise TimeUp(name, _NOW["seconds"])


def _alarm_usable() -> bool:
    return hasattr(signal, "setitimer") and hasattr(signal, "SIGPROF") and \
        threading.current_thread() is threading.main_thread() and \
        signal.getsignal(signal.SIGPROF) in (signal.SIG_DFL, signal.SIG_IGN)


@contextmanager
def limited(seconds: float | None) -> Iterator[None]:
    """Within the block, a check's limit of ``seconds`` of CPU time (``None``: none, the
    block unguarded but for :data:`HOOK`): :class:`TimeUp` in the step running when it
    passes (see the module's docstring). Not re-entrant."""
    hooked = bool(os.environ.get(HOOK, "").strip())  # the hook alone, never the clock
    _NOW.update(deadline=None if seconds is None or hooked else time.process_time() + seconds,
                seconds=seconds, step=None)
    if seconds is None or hooked or not _alarm_usable():
        try:
            yield
        finally:
            _NOW.update(deadline=None, seconds=None, step=None)
        return
    on = [True]

    def _late(signum, frame):  # noqa: ARG001 - a signal handler's signature
        if not on[0]:
            return
        on[0] = False
        raise TimeUp(_NOW["step"] or "reading", seconds)

    old = signal.signal(signal.SIGPROF, _late)
    try:
        signal.setitimer(signal.ITIMER_PROF, seconds)
        yield
    finally:
        on[0] = False
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)
        _NOW.update(deadline=None, seconds=None, step=None)
