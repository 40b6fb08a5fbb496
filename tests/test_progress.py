"""Commands that never go quiet: ``report`` and ``exercise --all`` speak before they do any
work, on a terminal (a live display, redrawn several times a second by itself) and in a pipe
(one line at the start and at the end of each phase); labels say what is being done and the
verdict once known; the estimate of the time left is stable.

How soon the first words come is a benchmark's figure, never a test's: a test checks what
makes them come soon, that the command has built, decided and solved nothing and has not
loaded the book when it first speaks (``FIRST``, a wrapper that runs the command and notes
its state at its first words)."""

from __future__ import annotations

import io
import json
import os
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from rigidsym.checking import runner
from rigidsym.core import progress as _progress
from rigidsym.core.progress import PER_ITEM, Reporter, format_seconds
from rigidsym.course.worked import EXERCISE_IDS

ROOT = Path(__file__).resolve().parents[1]
#: the program's start lines (rigidsym.core.progress.starting), before a command's own
START = re.compile(r"rigidsym [a-z-]+: (starting \.\.\.|still (starting|working) \(.+\), .+ s)")
_ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]")
#: runs ``python -m rigidsym ARGS`` and, at the first words it writes on stderr from its main
#: thread (past the program's start line, rigidsym.core.progress.starting), writes to the
#: file ``FIRST_WORDS`` names those words, the work counted so far (:mod:`rigidsym.core.work`)
#: and the book's modules imported, then exits
FIRST = r"""
import json, os, re, runpy, sys, threading

ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]")


class FirstWords:
    def __init__(self, stream):
        self._stream = stream

    def __getattr__(self, name):
        return getattr(self._stream, name)

    def write(self, text):
        n = self._stream.write(text)
        if threading.current_thread() is threading.main_thread() and \
                re.search("[a-z]{5,}", ANSI.sub("", text)) and \
                not re.fullmatch(r"rigidsym [a-z-]+: starting \.\.\.\s*", ANSI.sub("", text)):
            from rigidsym.core import work
            state = {"text": ANSI.sub("", text), "work": sorted(set(work.COUNTS)),
                     "book": sorted(m for m in sys.modules
                                    if m.startswith("rigidsym.derivations."))}
            with open(os.environ["FIRST_WORDS"], "w", encoding="utf-8") as fh:
                json.dump(state, fh)
            self._stream.flush()
            os._exit(0)
        return n


sys.stderr = FirstWords(sys.stderr)
sys.argv = ["rigidsym", *sys.argv[1:]]
runpy.run_module("rigidsym", run_name="__main__", alter_sys=True)
"""


def _command(*args: str) -> list[str]:
    return [sys.executable, "-m", "rigidsym", *args]


def _env(tmp_path) -> dict:
    env = dict(os.environ, RIGIDSYM_CACHE=str(tmp_path / "cache"), COLUMNS="120",
               TERM="xterm", FIRST_WORDS=str(tmp_path / "first.json"))
    env.pop("RIGIDSYM_ASCII", None)
    return env


def _kill_group(p: subprocess.Popen) -> None:
    """Kill the command and every process it started (its checker's pool workers): they
    share its process group (``start_new_session=True``); killing the command alone
    would orphan them."""
    try:
        os.killpg(p.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    p.wait()


def _first_words(args: list[str], env: dict, terminal: bool, hang: float = 300) -> dict:
    """Run ``args`` through :data:`FIRST`, its stderr a pseudo-terminal or a pipe; the state
    it noted at its first words (``hang`` only guards against a command that never
    speaks)."""
    Path(env["FIRST_WORDS"]).unlink(missing_ok=True)
    argv = [sys.executable, "-c", FIRST, *args]
    if terminal:
        import pty

        master, slave = pty.openpty()
        p = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, close_fds=True,
                             cwd=ROOT, env=env, start_new_session=True)
        os.close(slave)
    else:
        master = None
        p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             cwd=ROOT, env=env, start_new_session=True)
    try:
        while master is not None and p.poll() is None:  # drain the terminal
            if select.select([master], [], [], 0.1)[0]:
                try:
                    os.read(master, 65536)
                except OSError:  # the other side closed
                    break
        _, err = p.communicate(timeout=hang)
    finally:
        _kill_group(p)
        if master is not None:
            os.close(master)
    assert p.returncode == 0, err
    return json.loads(Path(env["FIRST_WORDS"]).read_text(encoding="utf-8"))


@pytest.mark.parametrize("args, line, shown", [
    (("report", "--out", "{tmp}"), "rigidsym report: loading the chapter's declarations ...",
     "loading the chapter"),
    (("exercise", "--all"), "rigidsym exercise --all: solving 21 exercises ...",
     "solving 21 exercises")])
def test_first_words_come_before_any_work_in_a_pipe_and_on_a_terminal(tmp_path, args, line,
                                                                      shown):
    """In a pipe the first line, on a terminal the live display: each said before anything
    is built, decided or solved and before the book is imported."""
    args = [a.format(tmp=tmp_path / "out") for a in args]
    piped = _first_words(args, _env(tmp_path), terminal=False)
    assert piped["text"].strip() == line
    assert piped["work"] == [] and piped["book"] == [], piped
    shown_live = _first_words(args, _env(tmp_path), terminal=True)
    assert shown in shown_live["text"], shown_live
    assert shown_live["work"] == [] and shown_live["book"] == [], shown_live


class _Terminal(io.StringIO):
    """A stream that says it is a terminal and counts its writes."""

    def __init__(self):
        super().__init__()
        self.writes = 0

    def isatty(self) -> bool:
        return True

    def write(self, text: str) -> int:
        self.writes += 1
        return super().write(text)


def test_the_live_display_redraws_itself_while_a_phase_reports_nothing(monkeypatch):
    """On a terminal the display is redrawn by its own thread (``REFRESH`` times a second),
    not only when the command reports progress: a long step still shows time passing.
    Counted as writes; the loop's time limit only guards against a display that never
    redraws."""
    monkeypatch.setenv("TERM", "xterm")
    out = _Terminal()
    with Reporter("rigidsym test", stream=out) as rep, rep.phase("waiting"):
        assert rep.live and _progress.REFRESH >= 1
        before, hang = out.writes, time.monotonic() + 120
        while out.writes < before + 3 and time.monotonic() < hang:
            time.sleep(0.05)
        redrawn = out.writes - before
    assert redrawn >= 3, "the live display did not redraw by itself"
    assert "waiting" in _ANSI.sub("", out.getvalue())


# the whole report in a pipe, each phase's lines: the chapter's chain of commands in
# test_work_counts.test_the_chapter_counts_verify_json_and_report_warm_do_no_work (its first
# report, piped), which runs the chapter once for both


@pytest.mark.slow
def test_exercise_all_in_a_pipe(tmp_path):
    p = subprocess.run(_command("exercise", "--all"), cwd=ROOT, env=_env(tmp_path),
                       capture_output=True, text=True)
    # the program's start lines (before sympy is imported) come first: then the command's
    err = [ln for ln in p.stderr.splitlines() if not START.fullmatch(ln)]
    # a slow exercise says it is still being solved, never a line that says nothing
    still = [ln for ln in err if ": still " in ln]
    assert all(re.fullmatch(r"rigidsym exercise --all: solving 21 exercises: still solving "
                            r"exercise 3\.\d+, .+ s", ln) for ln in still), still
    err = [ln for ln in err if ln not in still]
    assert err[0] == "rigidsym exercise --all: solving 21 exercises ..."
    # a line at each of the 21 exercises but the last, then the phase's end
    assert [int(re.match(r"rigidsym exercise --all: solving 21 exercises: (\d+)/21, ",
                         ln).group(1)) for ln in err[1:-1]] == list(range(1, 21)), err
    assert "21 / 21 solved and checked" in err[-1]
    # a line per exercise (its answers indented under it) and the summary
    out = p.stdout.splitlines()
    assert [ln.split()[0] for ln in out if not ln.startswith(" ")][:-1] == \
        EXERCISE_IDS
    assert out[-1] == "21 / 21 solved and checked"


# --------------------------------------------------------------------------- units
def test_piped_reporter_writes_one_line_per_phase_start_and_end():
    out = io.StringIO()
    with Reporter("rigidsym test", stream=out) as rep:
        with rep.phase("doing a", total=3) as ph:
            for k in range(3):
                ph.label(f"item {k}")
                ph.advance(1, label=f"item {k} done")
            ph.finish("3 items")
        with rep.phase("doing b"):
            pass
    lines = out.getvalue().splitlines()
    assert lines[0] == "rigidsym test: doing a ..."
    # each of the first two items passes a tenth of three: a count line each, not the last
    assert re.fullmatch(r"rigidsym test: doing a: 1/3, \d+\.\d s", lines[1])
    assert re.fullmatch(r"rigidsym test: doing a: 2/3, \d+\.\d s", lines[2])
    assert re.fullmatch(r"rigidsym test: doing a: done in \d+\.\d s: 3 items", lines[3])
    assert lines[4] == "rigidsym test: doing b ..."
    assert len(lines) == 6


def test_a_piped_phase_says_each_tenth_of_its_items_once():
    """A line when the count passes a tenth (by count, never by clock): 100 items one by one
    give 9 lines (10, 20, ..., 90), 100 items ten at a time the same 9, an uncounted phase
    none; a phase of at most PER_ITEM items a line per item but the last."""
    for step in (1, 10):
        out = io.StringIO()
        with Reporter("rigidsym test", stream=out) as rep, \
                rep.phase("doing", total=100) as ph:
            for _ in range(100 // step):
                ph.advance(step)
        got = [int(m.group(1)) for m in
               re.finditer(r"rigidsym test: doing: (\d+)/100, ", out.getvalue())]
        assert got == list(range(10, 100, 10)), (step, got)
    out = io.StringIO()
    with Reporter("rigidsym test", stream=out) as rep, \
            rep.phase("doing", total=PER_ITEM) as ph:
        for _ in range(PER_ITEM):
            ph.advance()
    got = [int(m.group(1)) for m in re.finditer(rf"doing: (\d+)/{PER_ITEM}, ", out.getvalue())]
    assert got == list(range(1, PER_ITEM))
    out = io.StringIO()
    with Reporter("rigidsym test", stream=out) as rep, rep.phase("spinning") as ph:
        for _ in range(50):
            ph.advance()
    assert len(out.getvalue().splitlines()) == 2


def test_a_piped_phase_quiet_for_a_while_says_what_it_is_still_doing(monkeypatch):
    """One slow item (a solution taking seconds) between two count lines: the phase says
    what it is on after SILENCE seconds without a line, and again after as many more; a
    phase that ends before then says nothing more. Lines are waited for, not timed: the
    loop's limit only guards against a watch that never speaks."""
    monkeypatch.setattr(_progress, "SILENCE", 0.05)
    monkeypatch.setattr(_progress, "TICK", 0.01)
    out = io.StringIO()
    with Reporter("rigidsym test", stream=out) as rep, \
            rep.phase("solving 3 items", total=3) as ph:
        ph.label("solving item 1")
        hang = time.monotonic() + 60
        while out.getvalue().count("still") < 2 and time.monotonic() < hang:
            time.sleep(0.01)
        ph.advance()
        ph.label("solving item 2")
    lines = out.getvalue().splitlines()
    still = [ln for ln in lines if ": still " in ln]
    assert len(still) >= 2 and all(
        re.fullmatch(r"rigidsym test: solving 3 items: still solving item 1, \d+\.\d s", ln)
        for ln in still[:2]), lines
    assert lines[0] == "rigidsym test: solving 3 items ..." and \
        lines[-1].startswith("rigidsym test: solving 3 items: done in ")
    # no watch outlives its phase: nothing more once the command has ended
    time.sleep(0.2)
    assert out.getvalue().splitlines() == lines
    # unlabelled, it is still working; disabled, silent
    out = io.StringIO()
    with Reporter("rigidsym test", stream=out) as rep, rep.phase("loading"):
        hang = time.monotonic() + 60
        while "still" not in out.getvalue() and time.monotonic() < hang:
            time.sleep(0.01)
    assert "rigidsym test: loading: still working, " in out.getvalue()
    out = io.StringIO()
    with Reporter("x", enabled=False, stream=out) as rep, rep.phase("y"):
        time.sleep(0.2)
    assert out.getvalue() == ""


def test_disabled_reporter_is_silent():
    out = io.StringIO()
    with Reporter("x", enabled=False, stream=out) as rep, rep.phase("y", total=1) as ph:
        ph.advance()
    assert out.getvalue() == ""


def test_seconds_read_as_a_person_would():
    assert format_seconds(0.42) == "0.4 s"
    assert format_seconds(12.4) == "12 s"
    assert format_seconds(125) == "2 min 05 s"


class _R:
    def __init__(self, i, verdict, expected, seconds=1.0):
        self.id, self.verdict, self.expected, self.seconds = i, verdict, expected, seconds


def test_labels_give_the_verdict_and_flag_a_surprise():
    assert runner.verdict_words(_R("3.57", "does-not-hold", "does-not-hold")) == \
        "3.57 does-not-hold, as expected"
    assert runner.verdict_words(_R("3.16", "verified", "verified")) == "3.16 verified"
    assert runner.verdict_words(_R("3.16", "undecided", "verified")) == \
        "3.16 undecided, EXPECTED verified"
    assert runner._doing({"3.77a": 0.0, "3.94": 0.0}, _R("3.57", "verified", "verified")) \
        == "checking 3.77a, 3.94 · 3.57 verified"


def test_estimate_from_earlier_durations_is_stable(monkeypatch, tmp_path):
    """Ten ids of known durations on a machine twice as slow as last time: after the first
    three, every estimate is within 10 % of the true time left (a rate over the last ids
    would swing with each id's own size)."""
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    sizes = {f"id{k}": float(s) for k, s in enumerate([9, 1, 5, 1, 1, 8, 2, 1, 3, 1])}
    _progress.save_durations(runner.DURATIONS, sizes)
    clock = [1000.0]
    monkeypatch.setattr(runner.time, "time", lambda: clock[0])
    est = runner._Estimate(list(sizes), jobs=1)
    order = est.order()
    assert order[0] == "id0" and order[1] == "id5"  # longest first
    total = 2 * sum(sizes.values())
    done_time = 0.0
    for k, i in enumerate(order):
        left = est.left({i: clock[0]})
        true_left = total - done_time
        if k >= 3:
            assert abs(left - true_left) <= 0.1 * true_left, (k, left, true_left)
        clock[0] += 2 * sizes[i]
        done_time += 2 * sizes[i]
        est.actual[i] = 2 * sizes[i]
    assert est.left({}) == 0.0


def test_durations_survive_a_corrupt_file(monkeypatch, tmp_path):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    (tmp_path / "timings").mkdir()
    (tmp_path / "timings" / "checks.json").write_text("{not json")
    assert _progress.load_durations("checks") == {}
    _progress.save_durations("checks", {"3.16": 1.25})
    assert _progress.load_durations("checks") == {"3.16": 1.25}


def test_shown_estimate_moves_smoothly(monkeypatch):
    """One surprising id does not make the shown estimate jump: it moves a third of the way
    towards a new estimate, and otherwise counts down."""
    clock = [0.0]
    monkeypatch.setattr(_progress.time, "perf_counter", lambda: clock[0])
    ph = _progress.Phase(Reporter("x", enabled=False), "y", 10)
    ph.estimate(60.0)
    assert ph._eta == 60.0
    clock[0] = 10.0
    ph.estimate(50.0)                     # as counted down: unchanged
    assert ph._eta == pytest.approx(50.0)
    clock[0] = 11.0
    ph.estimate(200.0)                    # a slow id: a third of the way, not 200
    assert ph._eta == pytest.approx(49.0 + (200.0 - 49.0) / 3)


def test_first_run_estimate_does_not_explode(monkeypatch, tmp_path):
    """No earlier durations: one slow first id does not multiply the estimate by the count."""
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    est = runner._Estimate([f"i{k}" for k in range(50)], jobs=2)
    est.actual["i0"] = 12.0               # the first id is slow
    prior_only = runner._Estimate([f"i{k}" for k in range(50)], jobs=2).left({})
    naive = 49 * 12.0 / 2                 # every id as slow as the first
    assert prior_only < est.left({}) < naive / 4


def test_a_command_says_it_starts_and_what_it_imports_until_its_progress(monkeypatch,
                                                                         tmp_path):
    """The start of a command: a first line at once, then, while it imports (sympy takes
    seconds), a line after each SILENCE seconds naming the module being imported; its own
    progress (a Reporter) ends them. Lines are waited for, not timed."""
    monkeypatch.setattr(_progress, "SILENCE", 0.05)
    monkeypatch.setattr(_progress, "TICK", 0.01)
    said = tmp_path / "said.txt"
    (tmp_path / "slow_to_import.py").write_text(
        f"import time\nfrom pathlib import Path\nhang = time.monotonic() + 60\n"
        f"while 'still' not in Path({str(said)!r}).read_text() and time.monotonic() < hang:\n"
        f"    time.sleep(0.01)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    with open(said, "w") as out, _progress.starting("rigidsym test", stream=out):
        import slow_to_import  # noqa: F401
        with Reporter("rigidsym test", stream=out) as rep, rep.phase("checking"):
            time.sleep(0.2)
    lines = said.read_text().splitlines()
    assert lines[0] == "rigidsym test: starting ..."
    assert re.fullmatch(r"rigidsym test: still starting \(importing slow_to_import\), "
                        r"\d+\.\d s", lines[1]), lines
    first = lines.index("rigidsym test: checking ...")
    assert not any("starting" in ln for ln in lines[first:]), lines
    out = io.StringIO()
    with _progress.starting("x", enabled=False, stream=out):
        time.sleep(0.1)
    assert out.getvalue() == ""


def test_the_program_speaks_before_it_imports_sympy():
    """``rigidsym verify``'s first line on stderr is its start line, written before sympy
    (seconds to import) is loaded: read, then the command is stopped."""
    p = subprocess.Popen([sys.executable, "-c", "import sys; sys.argv[0] = 'rigidsym'; "
                          "from rigidsym.cli import main; import sys as s; "
                          "s.modules.get('sympy') and print('sympy early', file=s.stderr); "
                          "main()", "verify", "3.1"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        first = p.stderr.readline()
    finally:
        p.kill()
        p.wait()
    assert first == "rigidsym verify: starting ...\n", first
