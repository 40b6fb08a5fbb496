"""Interrupted, repeated and concurrent commands: an interrupt keeps what was decided, exits
130 with one line and no traceback; the next run reuses the kept work and ends with the
results of an uninterrupted run; ``show``, ``report`` and the API read what ``verify``
stored; two processes at once decide each id once.

An interrupt lands at a named checkpoint, never at a moment in time: the command sends
itself SIGINT or SIGTERM at the checkpoint ``RIGIDSYM_INTERRUPT_AT`` names (a file written,
a unit of work begun, a progress phase begun or advanced: :mod:`rigidsym.core.interrupts`),
and an uninterrupted run with ``RIGIDSYM_INTERRUPT_TRACE`` lists the checkpoints there are,
so that the slow set walks through each of them (a seeded sample of ``generate``'s), on a
fast machine or a loaded one alike. The reuse is counted (the ``decide`` counts a command
writes to ``RIGIDSYM_WORK_FILE``, :mod:`rigidsym.core.work`), never timed. The declarations
of the concurrency test sleep while they build, so that the two processes' checks overlap
(without the lock per id each would decide every id). Every process is waited for (killed if
still running) and every file lies under ``tmp_path``.
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import tomllib
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import _profile
import pytest

import rigidsym
from rigidsym.checking import verdict_cache
from rigidsym.cli import main
from rigidsym.core import interrupts, sources
from rigidsym.core import work as _work
from rigidsym.registry.declarations import REGISTRY

ROOT = Path(__file__).resolve().parents[1]
HEAD = '''
"""Declarations for the interrupt tests (a sleep while they build, where asked)."""
import time
import sympy as sp
from rigidsym import Rel, Statement, angle, equation

phi = angle("phi")
'''
DECL = '''

@equation("{tag}:e{k}", "cos^2 + sin^2 of {k} phi", section="interrupt tests")
def e{k}() -> Statement:
    time.sleep({sleep})
    return Statement([Rel(sp.cos({k} * phi) ** 2 + sp.sin({k} * phi) ** 2, 1)], {{}})
'''
LINE = re.compile(r"rigidsym: interrupted(: (\d+) of (\d+) (?:ids|kernels) kept)?; run again to "
                  r"continue"
                  r"|rigidsym: interrupted while starting; nothing was done")


def _module(where: Path, tag: str, n: int, sleep: float = 0.0) -> Path:
    path = where / f"{tag}.py"
    path.write_text(HEAD + "".join(DECL.format(tag=tag, k=k, sleep=sleep)
                                   for k in range(1, n + 1)), encoding="utf-8")
    return path


def _env(cache: Path, work: Path, at: str | None = None, trace: Path | None = None) -> dict:
    """The command's environment: its cache and work file; ``at`` the checkpoint it
    interrupts itself at, ``trace`` where it lists the checkpoints it passes."""
    env = dict(os.environ, RIGIDSYM_CACHE=str(cache), RIGIDSYM_WORK_FILE=str(work))
    for name in ("RIGIDSYM_ASCII", interrupts.AT, interrupts.TRACE):
        env.pop(name, None)
    if at is not None:
        env[interrupts.AT] = at
    if trace is not None:
        env[interrupts.TRACE] = str(trace)
    return env


@contextmanager
def terminal_caller() -> Iterator[None]:
    """Python's own SIGINT handler in this process while a child starts: a child inherits
    an ignored SIGINT (pytest started as a background job, ``cmd &``) and keeps ignoring it,
    by design (:func:`interrupts.install`); a terminal's caller does not ignore it."""
    outer = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, outer)


def _start(args: list[str], env: dict, cwd: Path) -> subprocess.Popen:
    with terminal_caller():
        return subprocess.Popen([sys.executable, "-m", "rigidsym", *args], env=env, cwd=cwd,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _finish(p: subprocess.Popen, timeout: float = 300) -> tuple[int, str, str]:
    """Wait for ``p`` (``timeout`` only guards against a hang); its status and output."""
    try:
        out, err = p.communicate(timeout=timeout)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    return p.returncode, out, err


def _run(args: list[str], env: dict, cwd: Path) -> tuple[int, str, str]:
    return _finish(_start(args, env, cwd))


def _points(args: list[str], cache: Path, work: Path, cwd: Path) -> tuple[list[str], str]:
    """An uninterrupted run of ``args`` into ``cache``: the checkpoints it passed, in order,
    and its stdout."""
    trace = cwd / f"{cache.name}.trace"
    rc, out, err = _run(args, _env(cache, work, trace=trace), cwd)
    assert rc == 0, err
    points = trace.read_text(encoding="utf-8").split()
    assert points[0] == "start" and "write" in points, points
    return points, out


def _signal_at(k: int) -> str:
    """The signal of the ``k``-th checkpoint's interrupt: SIGTERM for every fourth."""
    return "SIGTERM" if k % 4 == 3 else "SIGINT"


def each_kind_of_checkpoint(points: list[str]) -> list[int]:
    """The checkpoints (counted from 1) a slow test interrupts: the first and the last
    passing of every kind of checkpoint of ``points`` (a cache entry written, an id decided,
    a phase begun, ...), and the third (a SIGTERM, :func:`_signal_at`): each kind of point
    where the command can be cut short, at the start and the end of its work, rather than
    every passing of each (a cold ``verify`` of three ids passes some twenty). The thorough
    run interrupts the third and a seeded third of the others (another third each commit;
    every one in the exhaustive profile)."""
    first: dict[str, int] = {}
    last: dict[str, int] = {}
    for k, name in enumerate(points, 1):
        first.setdefault(name, k)
        last[name] = k
    every = sorted({*first.values(), *last.values()} - {3})
    third = [3] if len(points) >= 3 else []
    return sorted(third + _profile.share(every, 1 / 3, key=lambda k: f"{k}:{points[k - 1]}"))


def _warm(mod: Path, cache: Path, tmp_path: Path) -> None:
    """Verify ``mod`` without repairs into ``cache``: its declarations are then known to
    build (the verdict cache's marks), and verdicts with repairs (another key) still cold."""
    rc, _, err = _run(["verify", "--module", str(mod), "--no-repairs", "--quiet", "--jobs",
                       "1"], _env(cache, tmp_path / "warm.json"), tmp_path)
    assert rc == 0, err


def _decided(work: Path) -> int:
    return sum(json.loads(work.read_text())["decide"].values())


def _rows(doc: str) -> list[dict]:
    """The records of a ``verify --format json`` document without run facts (seconds,
    cached): what must be identical between runs."""
    rows = json.loads(doc)["equations"]
    return [{k: v for k, v in r.items() if k not in ("seconds", "cached")} for r in rows]


def _assert_one_line(rc: int, err: str, total: int) -> int:
    """The interrupted run's promises; returns how many ids it said it kept."""
    assert rc == interrupts.EXIT, err
    assert "Traceback" not in err and "✓" not in err, err
    said = [x for x in err.splitlines() if "interrupted" in x]
    assert len(said) == 1 and err.rstrip().endswith(said[0]), err
    m = LINE.fullmatch(said[0])
    assert m, said[0]
    if total == 0 or m.group(1) is None:
        return 0
    assert int(m.group(3)) == total
    return int(m.group(2))


def _verify_args(mod: Path, jobs: int) -> list[str]:
    return ["verify", "--module", str(mod), "--jobs", str(jobs), "--format", "json"]


def _interrupt_and_resume(tmp_path: Path, args: list[str], n: int, at: str, name: str,
                          ) -> tuple[int, str]:
    """Run ``args`` (a verify of ``n`` ids) into a fresh cache, interrupted at the
    checkpoint ``at``; check its one line; run it again: it decides only what was not kept
    and reads the rest. Returns ``(ids kept, the second run's document)``."""
    cache, work = tmp_path / f"c-{name}", tmp_path / f"w-{name}.json"
    rc, _, err = _run(args, _env(cache, work, at=at), tmp_path)
    kept = _assert_one_line(rc, err, n)
    rc, doc, err = _run(args, _env(cache, work), tmp_path)
    assert rc == 0, err
    assert _decided(work) == n - kept  # the kept work is reused, the rest decided once
    assert sum(r["cached"] for r in json.loads(doc)["equations"]) == kept
    assert [r["verdict"] for r in _rows(doc)] == ["verified"] * n
    return kept, doc


def test_sigint_during_verify_keeps_the_decided_ids_and_the_next_run_reuses_them(tmp_path):
    """Interrupted as the second of four ids is done: two ids kept, and the next run decides
    only the other two (the slow set walks through every checkpoint, over one worker and
    two)."""
    n = 4
    mod = _module(tmp_path, "intr", n)
    kept, _ = _interrupt_and_resume(tmp_path, _verify_args(mod, 1), n, "advance:2", "mid")
    assert kept == 2


@pytest.mark.slow
@pytest.mark.parametrize("jobs", [1, 2])
def test_sigint_or_sigterm_at_each_checkpoint_of_verify(tmp_path, jobs):
    """Each kind of checkpoint of a cold ``verify`` (a cache entry written, an id decided,
    ...) at its first and last passing: interrupted there, then run again, its results
    equal an uninterrupted run's."""
    n = 3
    mod = _module(tmp_path, "intr", n)
    args = _verify_args(mod, jobs)
    points, ref = _points(args, tmp_path / "ref", tmp_path / "ref.json", tmp_path)
    assert points.count("decide") == (n if jobs == 1 else 0), points  # workers' uncounted
    for k in each_kind_of_checkpoint(points):
        _, doc = _interrupt_and_resume(tmp_path, args, n, f"{k}@{_signal_at(k)}", str(k))
        assert _rows(doc) == _rows(ref), (k, points[k - 1])


@pytest.mark.slow
def test_sigint_at_each_checkpoint_of_report(tmp_path):
    """``report --module``: interrupted at each kind of checkpoint (its first and last
    passing), then run again: the same files as an uninterrupted run's, the kept ids not
    decided again."""
    n = 3
    mod = _module(tmp_path, "rep", n)

    def args(out: str) -> list[str]:
        return ["report", "--module", str(mod), "--out", str(tmp_path / out), "--jobs", "2"]

    points, _ = _points(args("ref"), tmp_path / "refc", tmp_path / "ref.json", tmp_path)
    for k in each_kind_of_checkpoint(points):
        cache, work, out = tmp_path / f"c{k}", tmp_path / f"w{k}.json", f"out{k}"
        rc, _, err = _run(args(out), _env(cache, work, at=f"{k}@{_signal_at(k)}"), tmp_path)
        kept = _assert_one_line(rc, err, n)
        rc, _, err = _run(args(out), _env(cache, work), tmp_path)
        assert rc == 0, err
        assert _decided(work) == n - kept, (k, points[k - 1])
        for name in ("rep.md", "rep.json"):
            assert (tmp_path / out / name).read_bytes() == \
                (tmp_path / "ref" / name).read_bytes(), (k, points[k - 1], name)


def test_two_verify_at_once_decide_each_id_once(tmp_path):
    n = 4
    mod = _module(tmp_path, "conc", n, 0.4)
    _warm(mod, tmp_path / "c", tmp_path)
    args = ["verify", "--module", str(mod), "--jobs", "1", "--format", "json"]
    works = [tmp_path / "w1.json", tmp_path / "w2.json"]
    procs = []
    try:
        for w in works:
            procs.append(_start(args, _env(tmp_path / "c", w), tmp_path))
    finally:
        done = [_finish(p) for p in procs]
    assert [d[0] for d in done] == [0, 0], [d[2] for d in done]
    # without the lock per id both decide all n ids (2 n): each builds (sleeps) while it
    # checks, so their checks overlap
    assert sum(_decided(w) for w in works) == n
    assert _rows(done[0][1]) == _rows(done[1][1])


@pytest.fixture
def quick(tmp_path, monkeypatch):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    monkeypatch.chdir(tmp_path)
    tag = "quick" + tmp_path.name.replace("-", "_").lower()
    yield _module(tmp_path, tag, 2, 0.0), tag
    sys.modules.pop(tag, None)
    for k in [k for k in REGISTRY if k.startswith(tag + ":")]:
        del REGISTRY[k]


def test_show_and_report_after_verify_decide_nothing_and_the_api_shares_the_store(
        quick, tmp_path, capsys):
    mod, tag = quick
    assert main(["verify", "--module", str(mod), "--jobs", "1", "--quiet"]) == 0
    before = _work.snapshot()
    assert main(["show", f"{tag}:e1", "--module", str(mod)]) == 0
    assert main(["report", "--module", str(mod), "--out", str(tmp_path / "r"),
                 "--jobs", "1"]) == 0
    assert _work.since(before, "decide") == {}
    assert "from the verdict cache" in capsys.readouterr().err
    # the API's results carry the expanded strings verify does not store: decided once,
    # then read, by the API and by show
    first, second = rigidsym.check(f"{tag}:e2"), rigidsym.check(f"{tag}:e2")
    assert not first.cached and second.cached and second.verdict == "verified"
    assert main(["show", f"{tag}:e2", "--module", str(mod)]) == 0
    assert _work.since(before, "decide") == {f"{tag}:e2": 1}
    assert not rigidsym.check(f"{tag}:e2", cache=False).cached
    assert _work.since(before, "decide") == {f"{tag}:e2": 2}


def test_an_interrupt_after_the_checks_counts_what_they_stored(quick, monkeypatch, capsys):
    """An interrupt in the runner's tail (the durations written, after every id is stored)
    says the ids it stored, not "nothing kept": the next run then decides none (CI once
    met that window under load, and the second run found every id stored)."""
    from rigidsym.checking import runner

    mod, tag = quick

    def interrupted(*_a, **_k):
        raise KeyboardInterrupt

    saved = runner.save_durations
    monkeypatch.setattr(runner, "save_durations", interrupted)
    assert main(["verify", "--module", str(mod), "--jobs", "1", "--quiet"]) == interrupts.EXIT
    assert capsys.readouterr().err.rstrip().endswith(
        "rigidsym: interrupted: 2 of 2 ids kept; run again to continue")
    monkeypatch.setattr(runner, "save_durations", saved)
    before = _work.snapshot()
    assert main(["verify", "--module", str(mod), "--jobs", "1", "--quiet"]) == 0
    assert _work.since(before, "decide") == {}


def test_the_line_counts_when_said_and_survives_an_unreadable_store():
    """The count registered as a function is taken when the line is said (not when it was
    registered); one that cannot read the store gives the plain line, not a traceback."""
    stored = [0]
    interrupts.reset()
    interrupts.note_kept(lambda: stored[0], 5)
    stored[0] = 3
    assert interrupts.line() == "interrupted: 3 of 5 ids kept; run again to continue"

    def unreadable() -> int:
        raise PermissionError("verdicts/ab")

    interrupts.note_kept(unreadable, 5)
    assert interrupts.line() == "interrupted; run again to continue"
    interrupts.reset()


@pytest.fixture
def handlers() -> Iterator[None]:
    """This process's SIGINT and SIGTERM handlers restored after the test (which installs
    the command's), Python's own SIGINT handler during it (as a terminal's caller has)."""
    saved = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    with terminal_caller():
        yield
    for sig, handler in saved.items():
        signal.signal(sig, handler)
    interrupts.reset()


def test_a_checkpoint_sends_the_signal_at_the_point_named_and_nowhere_else(
        handlers, monkeypatch, tmp_path):
    """``NAME:N@SIGNAL``: the Nth passing of that checkpoint raises the interrupt, at once
    (recorded as received); inside ``deferred`` at the block's end, after its work; the
    trace lists every point passed; after ``quiet`` nothing counts. ``N``: the Nth
    checkpoint of any name, where a forked worker passes its checkpoints uncounted (its
    interrupt is the parent's to decide). Text that names no point is refused."""
    trace = tmp_path / "trace"
    monkeypatch.setenv(interrupts.AT, "write:2@SIGTERM")
    monkeypatch.setenv(interrupts.TRACE, str(trace))
    interrupts.install()
    interrupts.reset()
    interrupts.checkpoint("write")
    interrupts.checkpoint("phase")
    assert not interrupts.received()
    done = []
    with pytest.raises(KeyboardInterrupt):
        with interrupts.deferred():
            interrupts.checkpoint("write")
            done.append("the entry's second half")
    assert done and interrupts.received()
    assert trace.read_text().split() == ["write", "phase", "write"]
    interrupts.checkpoint("write")  # past the point: nothing more
    interrupts.quiet()
    interrupts.checkpoint("start")
    assert trace.read_text().split() == ["write", "phase", "write", "write"]

    monkeypatch.setenv(interrupts.AT, "3")
    monkeypatch.delenv(interrupts.TRACE)
    signal.signal(signal.SIGINT, signal.default_int_handler)  # quiet ignored it
    interrupts.install()
    pid = os.fork()
    if pid == 0:  # a worker: three checkpoints, no signal
        code = 1
        try:
            for name in ("decide", "write", "advance"):
                interrupts.checkpoint(name)
            code = 0
        finally:
            os._exit(code)
    assert os.waitpid(pid, 0)[1] == 0
    interrupts.checkpoint("decide")
    interrupts.checkpoint("write")
    with pytest.raises(KeyboardInterrupt):
        interrupts.checkpoint("advance")

    for bad in ("0", "write:", "x", "write:2@SIGHUP", "-1"):
        monkeypatch.setenv(interrupts.AT, bad)
        with pytest.raises(ValueError, match=interrupts.AT):
            interrupts.install()


def test_the_lock_of_a_key_is_held_by_one_holder_at_a_time(tmp_path, monkeypatch):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    key = "ab" + "0" * 62
    with verdict_cache.claimed(key) as first:
        with verdict_cache.claimed(key, wait=False) as second:
            assert first and not second
    with verdict_cache.claimed(key, wait=False) as again:  # released on leaving
        assert again


def test_the_code_digest_does_not_depend_on_where_the_file_lies():
    src = "def f(x):\n    return [y * 2 for y in x]\n"
    here, there = (compile(src, name, "exec") for name in ("/a/f.py", "/site/b/f.py"))
    assert sources.code_bytes(here) == sources.code_bytes(there)
    other = compile(src.replace("2", "3"), "/a/f.py", "exec")
    assert sources.code_bytes(other) != sources.code_bytes(here)


@pytest.mark.parametrize(("name", "built"), [
    ("_ckernels.cpython-311-x86_64-linux-gnu.so", True), ("_ckernels.build.json", True),
    ("x.cpython-311.pyc", True), ("sec3_2.py", False), ("notes.json", False),
    ("grammar.lark", False)])
def test_build_outputs_are_not_sources(name, built):
    assert sources.is_built(Path("rigidsym") / "kernels" / name) is built


def test_the_wheel_lists_every_package_of_the_source_tree():
    """A package missing from pyproject's list is missing from a regular install (as
    rigidsym.numeval was), and the two installs' digests then differ."""
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
                 ["packages"])
    found = {".".join(p.parent.relative_to(ROOT / "src").parts)
             for p in (ROOT / "src" / "rigidsym").rglob("__init__.py")}
    assert found <= listed, sorted(found - listed)


def _files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


SPEC = """title = "Quiz"
seed = 7

[[problem]]
exercise = "3.4"
variants = 2
"""


@pytest.mark.slow
@pytest.mark.parametrize("command", ["exam", "generate"])
def test_sigint_or_sigterm_at_checkpoints_of_exam_and_generate(tmp_path, command):
    """Interrupted at each kind of checkpoint of ``exam`` (an exercise solved, a file
    written) and of ``generate`` (a file written, a kernel derived), at its first and last
    passing, then run again: exit 130 and one line, then the files of an uninterrupted run,
    byte for byte."""
    (tmp_path / "quiz.toml").write_text(SPEC, encoding="utf-8")
    example = ROOT / "examples" / "rotation_identities.py"

    def args(out: str) -> list[str]:
        return (["exam", str(tmp_path / "quiz.toml"), "--out", str(tmp_path / out)]
                if command == "exam" else
                ["generate", "--module", str(example), "--out", str(tmp_path / out),
                 "--no-build"])

    points, _ = _points(args("ref"), tmp_path / "refc", tmp_path / "ref.json", tmp_path)
    for k in each_kind_of_checkpoint(points):
        env = _env(tmp_path / f"c{k}", tmp_path / f"w{k}.json", at=f"{k}@{_signal_at(k)}")
        rc, _, err = _run(args(f"out{k}"), env, tmp_path)
        _assert_one_line(rc, err, 0)
        rc, _, err = _run(args(f"out{k}"), _env(tmp_path / f"c{k}", tmp_path / f"w{k}.json"),
                          tmp_path)
        assert rc == 0, err
        assert _files(tmp_path / f"out{k}") == _files(tmp_path / "ref"), (k, points[k - 1])


def test_an_error_caused_by_the_interrupt_is_reported_as_the_interrupt(monkeypatch, capsys):
    """An import cut short by Ctrl-C fails as ``ImportError`` (numpy's C extension says
    "PyCapsule_Import could not import module"): after a signal it is the interrupt (one
    line, 130); without one, the same error is the command's own and propagates."""
    import rigidsym.cli as cli

    def failing(signalled: bool):
        def run(argv):
            if signalled:
                try:
                    signal.raise_signal(signal.SIGINT)  # main's handler, run at once
                except KeyboardInterrupt:
                    pass  # as an import's C code does: the interrupt becomes its error
            raise ImportError('PyCapsule_Import could not import module "datetime"')
        return run

    # a run started ignoring SIGINT (a background job, nohup) keeps ignoring it, by design
    # (interrupts.install); here the caller is a terminal's: Python's own handler
    with terminal_caller():
        _interrupt_or_error(monkeypatch, capsys, cli, failing)


def _interrupt_or_error(monkeypatch, capsys, cli, failing) -> None:
    before = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(cli, "_main", failing(True))
    assert main(["verify"]) == interrupts.EXIT
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and LINE.fullmatch(err), err
    monkeypatch.setattr(cli, "_main", failing(False))
    with pytest.raises(ImportError):
        main(["verify"])
    assert signal.getsignal(signal.SIGINT) is before  # the caller's handler, restored


PROGRAM = '''
import sys
from rigidsym.core import interrupts

interrupts.install()
try:
    # a string that exec runs (as sympy's lambdify does) cut short by the interrupt
    exec("import signal\\nsignal.raise_signal(signal.SIGINT)")
except KeyboardInterrupt:
    interrupts.quiet()
    print("rigidsym: interrupted; run again to continue", file=sys.stderr)
    sys.exit(interrupts.EXIT)
'''


def test_an_interrupt_inside_an_evaluated_string_still_exits_130_under_python_m(tmp_path):
    """CPython marks an interrupt that ends an exec'd string "unhandled", even when caught,
    and ``python -m`` then kills itself by SIGINT at exit (status -2, not 130: seen in
    ``generate`` interrupted inside sympy's lambdify); :func:`interrupts.quiet` clears it."""
    (tmp_path / "cut_short.py").write_text(PROGRAM, encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), *sys.path]))
    with terminal_caller():  # its handler, which exec resets to the default
        p = subprocess.run([sys.executable, "-m", "cut_short"], cwd=tmp_path, env=env,
                           capture_output=True, text=True, timeout=60)
    assert p.returncode == interrupts.EXIT, (p.returncode, p.stderr)
    assert p.stderr.strip() == "rigidsym: interrupted; run again to continue", p.stderr
