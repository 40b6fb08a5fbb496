"""Progress of the long commands, on stderr: never quiet for more than a second.

On a terminal, one ``rich`` live display refreshed four times a second: a spinner, what is
being done (``checking 3.77a``), a bar with a count when the amount of work is known, the
elapsed time and an estimate of the time left; when a phase ends, one line stays
(``✓ checked 181 ids in 40.1 s: ...``). When stderr is not a terminal (a pipe, a log, CI),
one line at the start and one at the end of each phase, and between them, in a phase whose
items are counted, one at each tenth of its items (``rigidsym verify: checking 181 ids:
37/181, 2.1 s``): a log reads as the list of phases with their durations (lines by count,
so that the same run writes the same lines). A phase quiet for :data:`SILENCE` seconds
all the same (one slow item: an exercise whose solution takes seconds) says what it is
still doing (``rigidsym exercise --all: solving 21 exercises: still solving exercise 3.3,
5.0 s``), as the build's progress does: no pipe waits more than that for a line.

The estimate is the caller's (:meth:`Phase.estimate`): the parallel checker predicts each
id's time from its previous runs (:func:`load_durations`), which moves far less than a
rate measured over the last few ids. A phase's start and each item done are checkpoints of
:mod:`rigidsym.core.interrupts`. Imports nothing of rigidsym but :mod:`rigidsym.core.cache`
and :mod:`rigidsym.core.interrupts`.
"""

from __future__ import annotations

import json
import os
import sys
import threading
import time
from contextlib import contextmanager

from rigidsym.core.interrupts import checkpoint

__all__ = ["Reporter", "Phase", "PER_ITEM", "SILENCE", "load_durations", "save_durations",
           "format_seconds", "starting", "begun", "doing"]

#: refreshes per second of the live display (at least one)
REFRESH = 4
#: the share of a new estimate taken at once (the rest follows over the next updates)
SMOOTHING = 1 / 3
#: in a pipe, a counted phase of at most this many items says each item (a tenth of a few
#: items, each taking seconds, would leave the reader seconds without a line)
PER_ITEM = 30
#: in a pipe, the most seconds a phase stays without a line before it says what it is still
#: doing (under the 3 s a reader waits; setup.py's build lines keep the same interval)
SILENCE = 2.5
#: how often the watch of a piped phase looks at the time since the last line, seconds
TICK = 0.25


def format_seconds(s: float) -> str:
    """``"0.4 s"``, ``"12 s"``, ``"2 min 05 s"``."""
    if s < 10:
        return f"{s:.1f} s"
    if s < 60:
        return f"{s:.0f} s"
    m, r = divmod(int(round(s)), 60)
    return f"{m} min {r:02d} s"


#: the start of the running command (:func:`starting`): its watch's stop, and the lock its
#: lines and the first progress of the command take in turn
_START = {"stop": None}
_START_LOCK = threading.Lock()


def doing(ident: int) -> str:
    """What the thread ``ident`` is doing, in words, from its stack: ``"importing sympy"``
    (the outermost library being imported, else the innermost module of rigidsym), else
    ``"in rigidsym.x.f"`` (its innermost function of rigidsym), else ``"working"``."""
    frame = sys._current_frames().get(ident)
    stack = []
    while frame is not None:
        stack.append(frame)
        frame = frame.f_back
    # a module's body run by the import system (not a script or exec'd code: pytest-xdist's
    # worker runs in a module body of its own), outermost first
    modules = [f.f_globals.get("__name__", "") for f in reversed(stack)
               if f.f_code.co_name == "<module>" and f.f_back is not None
               and f.f_back.f_globals.get("__name__", "").startswith("importlib")]
    modules = [m for m in modules if m not in ("__main__", "")]
    if modules:
        other = [m for m in modules if m.split(".")[0] != "rigidsym"]
        return f"importing {other[0] if other else modules[-1]}"
    for f in stack:                              # innermost first
        name = f.f_globals.get("__name__", "")
        if name.startswith("rigidsym") and not name.startswith("rigidsym.core.progress"):
            return f"in {name}.{f.f_code.co_name}"
    return "working"


@contextmanager
def starting(command: str, enabled: bool = True, stream=None):
    """The first line of a command, before its heavy imports (sympy takes seconds, tens of
    seconds on a loaded machine), and until the command's own progress begins (its first
    :class:`Reporter`), a line whenever :data:`SILENCE` seconds pass without one, saying
    what runs (:func:`doing`): ``rigidsym verify: still starting (importing sympy), 5.0 s``,
    or, past its imports, ``rigidsym generate: still working (in rigidsym.x.f), 9.0 s``.

    Args:
        command: the head of each line (``rigidsym verify``).
        enabled: ``False`` prints nothing (``--quiet``).
        stream: where to write (default ``sys.stderr``).
    """
    if not enabled:
        yield
        return
    out = stream if stream is not None else sys.stderr
    t0, main = time.perf_counter(), threading.get_ident()
    print(f"{command}: starting ...", file=out, flush=True)
    stop = threading.Event()
    said = [t0]

    def watch() -> None:
        while not stop.wait(TICK):
            with _START_LOCK:
                now = time.perf_counter()
                if now - said[0] >= SILENCE and not stop.is_set():
                    what = doing(main)
                    phase = "starting" if what.startswith("importing") else "working"
                    print(f"{command}: still {phase} ({what}), {format_seconds(now - t0)}",
                          file=out, flush=True)
                    said[0] = now

    th = threading.Thread(target=watch, daemon=True, name="rigidsym-starting")
    _START["stop"] = stop
    th.start()
    try:
        yield
    finally:
        begun()
        th.join()


def begun() -> None:
    """The command's own progress begins (a :class:`Reporter`, the C build's lines): the
    start's lines (:func:`starting`) end, none after this returns."""
    with _START_LOCK:
        stop, _START["stop"] = _START["stop"], None
        if stop is not None:
            stop.set()


class Phase:
    """One phase of a command: what it does, how far it is, what it found."""

    def __init__(self, reporter: Reporter, what: str, total: int | None):
        self.reporter, self.what, self.total = reporter, what, total
        self.done = 0
        self.summary = ""
        self.t0 = time.perf_counter()
        self._eta: float | None = None
        self._eta_at = self.t0
        self._task = None
        #: what is being done now, said in a pipe when the phase stays quiet
        self.doing: str | None = None

    def label(self, text: str) -> None:
        """What is being done now (``checking 3.77a``), shown on a terminal; in a pipe, said
        if the phase stays quiet for :data:`SILENCE` seconds."""
        self.doing = text
        if self._task is not None:
            self.reporter.bar.update(self._task, description=text)

    def advance(self, n: int = 1, label: str | None = None) -> None:
        """``n`` more items done; ``label`` what was found (``3.57 does-not-hold``). In a
        pipe, a line when the count passes a tenth of the phase's items, or at each item of
        a phase of at most :data:`PER_ITEM` items (their items take seconds each: 21
        exercises), never at the last."""
        before, self.done = self.done, self.done + n
        if self._task is not None:
            kw = {"description": label} if label else {}
            self.reporter.bar.update(self._task, advance=n, **kw)
        elif self.reporter.enabled and self.total and self.done < self.total and (
                self.total <= PER_ITEM
                or 10 * self.done // self.total > 10 * before // self.total):
            self.reporter._line(f"{self.reporter.command}: {self.what}: {self.done}/{self.total}, "
                                f"{format_seconds(time.perf_counter() - self.t0)}")
        checkpoint("advance")

    def counted(self, done: int, total: int) -> None:
        """The phase's count as its worker reports it: ``done`` of ``total`` items (a total
        known only once the work starts, e.g. the kernels a generation derives), then as
        :meth:`advance`."""
        if total != self.total:
            self.total = total
            if self._task is not None:
                self.reporter.bar.update(self._task, total=total)
        if done > self.done:
            self.advance(done - self.done)

    def estimate(self, seconds_left: float | None) -> None:
        """The caller's estimate of the time left (``None``: unknown), smoothed: the shown
        value moves a third of the way from where the last one has counted down to, so one
        surprising id does not make it jump."""
        now = time.perf_counter()
        if seconds_left is not None and self._eta is not None:
            counted = max(self._eta - (now - self._eta_at), 0.0)
            seconds_left = counted + SMOOTHING * (seconds_left - counted)
        self._eta, self._eta_at = seconds_left, now
        if self._task is not None:
            text = "" if seconds_left is None else f"≈ {format_seconds(seconds_left)} left"
            self.reporter.bar.update(self._task, eta=text)

    def finish(self, summary: str) -> None:
        """What the phase found, printed with its end line (``121 verified, ...``)."""
        self.summary = summary


class Reporter:
    """The progress of one command (``rigidsym report``): a sequence of phases.

    Args:
        command: the command's name, the head of each piped line (``rigidsym report``).
        enabled: ``False`` prints nothing (``--quiet``).
        stream: where to write (default ``sys.stderr``); a terminal gets the live display.
        keep: on a terminal, leave one line per finished phase (``False``: the display
            vanishes, for a command whose own output follows at once, ``show``).
    """

    def __init__(self, command: str, enabled: bool = True, stream=None, keep: bool = True):
        self.command, self.enabled, self.keep = command, enabled, keep
        self.stream = stream
        self.bar = None
        self.live = False
        self._lock = threading.Lock()
        self._said = time.perf_counter()

    def _stream(self):
        return self.stream if self.stream is not None else sys.stderr

    def _line(self, text: str) -> None:
        """One line in a pipe (from the command or from a phase's watch, never interleaved)."""
        with self._lock:
            print(text, file=self._stream(), flush=True)
            self._said = time.perf_counter()

    def _watch(self, ph: Phase, stop: threading.Event) -> None:
        """In a pipe, while ``ph`` runs: a line saying what it is still doing whenever
        :data:`SILENCE` seconds pass without one."""
        while not stop.wait(TICK):
            if time.perf_counter() - self._said >= SILENCE and not stop.is_set():
                self._line(f"{self.command}: {ph.what}: still {ph.doing or 'working'}, "
                           f"{format_seconds(time.perf_counter() - ph.t0)}")

    def __enter__(self) -> Reporter:
        if self.enabled:
            begun()
        s = self._stream()
        self.live = self.enabled and hasattr(s, "isatty") and s.isatty() and \
            os.environ.get("TERM") != "dumb"
        if self.live:
            from rich.console import Console
            from rich.progress import (
                BarColumn,
                Progress,
                SpinnerColumn,
                TextColumn,
                TimeElapsedColumn,
            )
            self.bar = Progress(SpinnerColumn(), TextColumn("{task.description}"), BarColumn(),
                                _count_column(), TimeElapsedColumn(),
                                TextColumn("{task.fields[eta]}"),
                                console=Console(file=s), transient=True,
                                refresh_per_second=REFRESH,
                                # stdout into the display only when it is the terminal too
                                # (piped stdout must reach the pipe untouched)
                                redirect_stdout=sys.stdout.isatty(), redirect_stderr=True)
            self.bar.__enter__()
        return self

    def __exit__(self, *exc) -> None:
        if self.bar is not None:
            self.bar.__exit__(*exc)
            self.bar = None

    def say(self, text: str) -> None:
        """One line that stays (above the live display on a terminal)."""
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.console.print(text, highlight=False, markup=False)
        else:
            self._line(text)

    @contextmanager
    def phase(self, what: str, total: int | None = None, doing: str | None = None):
        """A phase: ``what`` names it (``checking 181 ids``), ``total`` counts its items
        (``None``: unknown, a spinner), ``doing`` is the first label (default ``what``).

        Yields:
            The :class:`Phase`, to advance, label and estimate.
        """
        ph = Phase(self, what, total)
        ph.doing = doing
        stop = threading.Event()
        watch = None
        if self.bar is not None:
            ph._task = self.bar.add_task(doing or what, total=total, eta="")
        elif self.enabled:
            self._line(f"{self.command}: {what} ...")
            watch = threading.Thread(target=self._watch, args=(ph, stop), daemon=True,
                                     name="rigidsym-progress")
            watch.start()
        failed, stopped = True, False
        try:
            checkpoint("phase")
            yield ph
            failed = False
        except KeyboardInterrupt:  # the command's one line says it: no ✓
            stopped = True
            raise
        finally:
            stop.set()
            if watch is not None:
                watch.join()  # its last line, if any, before the phase's end line
            took = format_seconds(time.perf_counter() - ph.t0)
            if self.bar is not None:
                self.bar.remove_task(ph._task)
            tail = f": {ph.summary}" if ph.summary else ""
            if stopped:
                pass
            elif self.bar is not None:
                if self.keep:
                    self.say(f"{'✗' if failed else '✓'} {what}: "
                             f"{'stopped after ' if failed else ''}{took}{tail}")
            elif self.enabled:
                ended = "stopped after" if failed else "done in"
                self._line(f"{self.command}: {what}: {ended} {took}{tail}")


def _count_column():
    """``12/181`` when the phase has a count, nothing when it has not (no ``0/?``)."""
    from rich.progress import ProgressColumn
    from rich.text import Text

    class Count(ProgressColumn):
        def render(self, task):
            if task.total is None:
                return Text("")
            return Text(f"{int(task.completed)}/{int(task.total)}", style="progress.download")

    return Count()


# --------------------------------------------------------------------------- durations
def _durations_file(kind: str):
    from rigidsym.core import cache as _cache
    return _cache.root() / "timings" / f"{kind}.json"


def load_durations(kind: str) -> dict[str, float]:
    """Seconds per id of earlier runs (``{}`` when none, or unreadable: only an estimate
    depends on it)."""
    try:
        data = json.loads(_durations_file(kind).read_text(encoding="utf-8"))
        return {str(k): float(v) for k, v in data.items()}
    except (OSError, ValueError, TypeError, AttributeError):
        return {}


def save_durations(kind: str, seconds: dict[str, float]) -> None:
    """Merge ``seconds`` into the stored durations (atomic write; a failure to write is
    ignored: the next estimate is only less good)."""
    from rigidsym.core.files import write_atomic

    merged = load_durations(kind)
    merged.update({k: round(float(v), 3) for k, v in seconds.items()})
    try:
        write_atomic(_durations_file(kind), json.dumps(merged, indent=0, sort_keys=True))
    except OSError:
        pass
