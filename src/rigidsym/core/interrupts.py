"""Interrupts of a long command: SIGINT (Ctrl-C) and SIGTERM end it with one
line and exit status 130, keeping the work it finished.

- :func:`install` makes SIGINT and SIGTERM raise ``KeyboardInterrupt`` in the main thread
  and records that one came (:func:`received`), so that ``rigidsym.cli.main`` handles both
  and also an exception the interrupt caused in another form (a cut-short import).
- :func:`quiet`: once the line is said (or the command is done), both are ignored;
  :func:`end_workers`: an interrupted command leaves no worker process behind.
- :func:`for_worker` is the initializer of a worker process: it ignores SIGINT (a terminal
  sends Ctrl-C to the whole process group; the parent decides) and dies on SIGTERM (how
  the parent's pool stops it), so that no worker prints a traceback.
- :func:`deferred` holds both signals back while a cache entry is written, so that an
  entry is written whole or not at all and no temporary file is left.
- :func:`note_kept` and :func:`line`: how much finished work was kept, and the line said.
- :func:`checkpoint` marks a named point of a command: ``start`` (the command begins),
  ``write`` (a file is written, before its rename: :mod:`rigidsym.core.files`), ``phase``
  and ``advance`` (a progress phase begins, an item of it is done:
  :mod:`rigidsym.core.progress`), ``build``, ``decide``, ``transcribe`` and ``solve`` (a
  unit of work begins: :func:`rigidsym.core.work.count`). With ``RIGIDSYM_INTERRUPT_AT``
  set, the command sends itself SIGINT or SIGTERM at one of them, so that a test
  interrupts it at a chosen point rather than at a moment in time:

  - ``RIGIDSYM_INTERRUPT_AT=N``: at the Nth checkpoint passed (counted from 1);
  - ``RIGIDSYM_INTERRUPT_AT=NAME:N``: at the Nth passing of the checkpoint ``NAME``;
  - either followed by ``@SIGTERM`` (or ``@SIGINT``, the default): the signal sent.

  The signal is raised by :func:`signal.raise_signal`, so that the installed handler
  runs at once, as for a signal from outside; inside :func:`deferred` it waits for the
  block's end. With ``RIGIDSYM_INTERRUPT_TRACE=FILE`` each checkpoint passed appends its
  name as a line to ``FILE``: a run without an interrupt lists the points there are.
  Only the process that called :func:`install` counts, in its main thread (a worker
  process passes its checkpoints uncounted), and only until :func:`quiet`.

Imports nothing of rigidsym.
"""

from __future__ import annotations

import os
import signal
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager

__all__ = ["EXIT", "AT", "TRACE", "install", "for_worker", "deferred", "quiet", "received",
           "end_workers", "note_kept", "line", "reset", "checkpoint"]

#: the exit status of an interrupted command (128 + SIGINT, as a shell reports it)
EXIT = 130
_SIGNALS = (signal.SIGINT, signal.SIGTERM)
#: what the running command kept so far: ``(kept, total, what)``, or ``None``
_KEPT: list = [None]
#: whether SIGINT or SIGTERM arrived since :func:`reset`
_RECEIVED: list = [False]
#: the environment variable naming the checkpoint to interrupt at (:func:`checkpoint`)
AT = "RIGIDSYM_INTERRUPT_AT"
#: the environment variable naming a file that lists the checkpoints passed
TRACE = "RIGIDSYM_INTERRUPT_TRACE"
#: the checkpoints' state: the counting process's id (``None``: none counts), the point to
#: interrupt at ``(name or None, n, signal)`` or ``None``, the trace file or ``None``, the
#: count of all checkpoints passed and the counts per name
_POINTS: dict = {"pid": None, "at": None, "trace": None, "passed": 0, "by_name": {}}


def _raise(signum, frame) -> None:  # noqa: ARG001 - a signal handler's signature
    _RECEIVED[0] = True
    raise KeyboardInterrupt


def received() -> bool:
    """Whether SIGINT or SIGTERM arrived since :func:`reset`: an exception raised then may
    be the interrupt in another form (an import that the interrupt cut short fails as
    ``ImportError``, as numpy's C extension reports it), and is reported as the interrupt."""
    return _RECEIVED[0]


def _point(text: str) -> tuple[str | None, int, signal.Signals]:
    """``[NAME:]N[@SIGNAL]`` read: ``(NAME or None, N, the signal)``.

    Raises:
        ValueError: for text of another form, N below 1 or a signal other than SIGINT
            and SIGTERM.
    """
    where, _, sig = text.strip().partition("@")
    name, _, n = where.rpartition(":")
    signum = {"": signal.SIGINT, "SIGINT": signal.SIGINT, "SIGTERM": signal.SIGTERM}.get(
        sig.strip().upper())
    if signum is None or not n.strip().isdigit() or int(n) < 1:
        raise ValueError(f"{AT}: expected [NAME:]N[@SIGINT|@SIGTERM] with N >= 1, got "
                         f"{text!r}")
    return name.strip() or None, int(n), signum


def install() -> None:
    """SIGINT and SIGTERM raise ``KeyboardInterrupt`` and are recorded (:func:`received`)
    (main thread only; elsewhere, where handlers cannot be set, nothing changes; a signal
    the process was started ignoring, as ``nohup`` or a shell's background job does,
    stays ignored). This process then counts its checkpoints (:func:`checkpoint`), as
    :data:`AT` and :data:`TRACE` ask.

    Raises:
        ValueError: :data:`AT` is set to text that names no checkpoint.
    """
    if threading.current_thread() is not threading.main_thread():
        return
    for sig in _SIGNALS:
        if signal.getsignal(sig) is not signal.SIG_IGN:
            signal.signal(sig, _raise)
    at, trace = os.environ.get(AT), os.environ.get(TRACE)
    _POINTS.update(pid=os.getpid(), at=_point(at) if at else None, trace=trace or None,
                   passed=0, by_name={})


def checkpoint(name: str) -> None:
    """A named point of a command (see the module's docstring): counted, listed in the
    trace file, and where :data:`AT` names it, the point where the command sends itself
    the signal (the handler :func:`install` set then raises ``KeyboardInterrupt`` here, or
    at the end of the enclosing :func:`deferred` block). Does nothing in a process or
    thread that does not count, and after :func:`quiet`.

    Args:
        name: the point's name (``write``, ``phase``, ...).
    """
    if _POINTS["pid"] != os.getpid() or \
            threading.current_thread() is not threading.main_thread():
        return
    _POINTS["passed"] += 1
    by_name = _POINTS["by_name"]
    by_name[name] = by_name.get(name, 0) + 1
    if _POINTS["trace"]:
        with open(_POINTS["trace"], "a", encoding="utf-8") as fh:
            fh.write(name + "\n")
    at = _POINTS["at"]
    if at is not None and (at[1] == by_name[name] if at[0] == name else
                           at[0] is None and at[1] == _POINTS["passed"]):
        signal.raise_signal(at[2])


def quiet() -> None:
    """From now on SIGINT and SIGTERM are ignored: the command has finished, or has said
    that it was interrupted, and only exits. A signal that arrived just before (its
    handler not yet run) is absorbed here rather than raised after the one line, where it
    would end the process by SIGINT instead of exit status 130. Main thread only."""
    if threading.current_thread() is not threading.main_thread():
        return
    _POINTS["pid"] = None  # no checkpoint counts from now on
    while True:
        try:  # signal.signal runs a pending handler before it changes the disposition
            for sig in _SIGNALS:
                signal.signal(sig, signal.SIG_IGN)
            break
        except KeyboardInterrupt:
            continue
    # CPython marks "unhandled KeyboardInterrupt" when one ends a string that exec or eval
    # ran (sympy's lambdify and monomial builders do), even one caught later, and ``python
    # -m`` then ends itself by SIGINT at exit instead of status 130; each evaluated string
    # resets that mark first, and this one completes
    eval("None")  # noqa: S307 - a constant string, only for that reset


def end_workers() -> None:
    """Kill and reap every worker process this process started (a pool that the interrupt
    cut short in its construction has no owner left to stop it, and its workers would keep
    the command's output pipes open after it exits). SIGKILL: a worker forked before its
    initializer ran may still ignore SIGTERM."""
    import sys

    mp = sys.modules.get("multiprocessing")
    if mp is None:  # no worker was ever started
        return
    for child in mp.active_children():
        child.kill()
    for child in mp.active_children():
        child.join(timeout=5)


def for_worker() -> None:
    """In a forked worker: SIGINT ignored, SIGTERM ends it (the default action)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


@contextmanager
def deferred() -> Iterator[None]:
    """Within the block SIGINT and SIGTERM wait (they are delivered when it ends): a
    write of the user cache is then whole or absent. A no-op where threads cannot block
    signals (not POSIX)."""
    block = getattr(signal, "pthread_sigmask", None)
    if block is None:
        yield
        return
    old = block(signal.SIG_BLOCK, _SIGNALS)
    try:
        yield
    finally:
        block(signal.SIG_SETMASK, old)


def note_kept(kept: int | Callable[[], int], total: int, what: str = "ids") -> None:
    """Record that ``kept`` of ``total`` ``what`` are finished and stored; :func:`line`
    reports the last call. ``kept`` may be a function that counts them, called when the
    line is said: the runner registers one before its work starts, so that an interrupt at
    any moment after (even while the count would be taken) reports what is stored then."""
    _KEPT[0] = (kept, total, what)


def reset() -> None:
    """Forget what :func:`note_kept` recorded (a new command in the same process)."""
    _KEPT[0] = None
    _RECEIVED[0] = False


def line() -> str:
    """The one line an interrupted command prints: ``interrupted: 37 of 181 ids kept; run
    again to continue`` (or, for a command that counts no ids, ``interrupted; run again to
    continue``: what it writes, it writes whole)."""
    if _KEPT[0] is None:
        return "interrupted; run again to continue"
    kept, total, what = _KEPT[0]
    if callable(kept):
        try:
            kept = kept()
        except OSError:  # the store unreadable now: what was written is still whole
            return "interrupted; run again to continue"
    return f"interrupted: {kept} of {total} {what} kept; run again to continue"
