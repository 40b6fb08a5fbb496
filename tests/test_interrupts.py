"""Interrupted, repeated and concurrent commands (issue 69): an interrupt keeps what was
decided, exits 130 with one line and no traceback; the next run reuses the kept work and
ends with the results of an uninterrupted run; ``show``, ``report`` and the API read what
``verify`` stored; two processes at once decide each id once.

The reuse is counted (the ``decide`` counts a command writes to ``RIGIDSYM_WORK_FILE``,
:mod:`rigidsym.core.work`), never timed. The user module's declarations sleep while they
build, so that an interrupt or a second process meets a run in its middle at little CPU
cost; a first run without repairs (:func:`_warm`) leaves them known to build, so that a
run with repairs, cold for its verdicts, builds them while it checks them rather than
while it loads the module. Every process is waited for (killed if still running) and
every file lies under ``tmp_path``.
"""

from __future__ import annotations

import json
import os
import random
import re
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import pytest

import rigidsym
from rigidsym.checking import verdict_cache
from rigidsym.cli import main
from rigidsym.core import interrupts, sources
from rigidsym.core import work as _work
from rigidsym.registry.declarations import REGISTRY

ROOT = Path(__file__).resolve().parents[1]
HEAD = '''
"""Declarations that take a while to build (a sleep): interrupt tests."""
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


def _module(where: Path, tag: str, n: int, sleep: float) -> Path:
    path = where / f"{tag}.py"
    path.write_text(HEAD + "".join(DECL.format(tag=tag, k=k, sleep=sleep)
                                   for k in range(1, n + 1)), encoding="utf-8")
    return path


def _env(cache: Path, work: Path) -> dict:
    env = dict(os.environ, RIGIDSYM_CACHE=str(cache), RIGIDSYM_WORK_FILE=str(work))
    env.pop("RIGIDSYM_ASCII", None)
    return env


def _start(args: list[str], env: dict, cwd: Path) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "rigidsym", *args], env=env, cwd=cwd,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _finish(p: subprocess.Popen, timeout: float = 300) -> tuple[int, str, str]:
    try:
        out, err = p.communicate(timeout=timeout)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    return p.returncode, out, err


def _interrupt(p: subprocess.Popen, delay: float, sig=signal.SIGINT,
               after: str | None = "checking") -> tuple[int, str, str]:
    """Signal ``p`` ``delay`` s after its stderr shows ``after`` (else after its start)."""
    head = ""
    try:
        while after is not None and after not in head and p.poll() is None:
            head += p.stderr.readline()
        time.sleep(delay)
        if p.poll() is None:
            p.send_signal(sig)
    except BaseException:
        p.kill()
        p.wait()
        raise
    rc, out, err = _finish(p)
    return rc, out, head + err


def _warm(mod: Path, cache: Path, tmp_path: Path) -> None:
    """Verify ``mod`` without repairs into ``cache``: its declarations are then known to
    build (the verdict cache's marks), and verdicts with repairs (another key) still cold."""
    rc, _, err = _finish(_start(["verify", "--module", str(mod), "--no-repairs", "--quiet",
                                 "--jobs", "1"], _env(cache, tmp_path / "warm.json"),
                                tmp_path))
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


def _interrupt_and_resume(tmp_path: Path, delay: float, sig=signal.SIGINT,
                          reference: bool = True) -> None:
    """Interrupt a cold ``verify`` ``delay`` s into its checks, run it again; with
    ``reference``, beside an uninterrupted run whose results the second run's must equal."""
    n = 6
    mod = _module(tmp_path, "intr", n, 0.3)
    args = ["verify", "--module", str(mod), "--jobs", "2", "--format", "json"]
    work = tmp_path / "work.json"
    _warm(mod, tmp_path / "c", tmp_path)
    ref = _start(args + ["--no-cache"], _env(tmp_path / "ref", tmp_path / "ref.json"),
                 tmp_path) if reference else None
    try:
        rc, _, err = _interrupt(_start(args, _env(tmp_path / "c", work), tmp_path), delay,
                                sig)
    finally:
        ref_rc, ref_doc, _ = _finish(ref) if ref else (0, "", "")
    assert ref_rc == 0
    if rc == 0:  # the delay outlasted the run: nothing to resume
        return
    kept = _assert_one_line(rc, err, n)
    rc, doc, err = _finish(_start(args, _env(tmp_path / "c", work), tmp_path))
    assert rc == 0, err
    assert _decided(work) == n - kept  # the kept work is reused, the rest decided once
    assert sum(r["cached"] for r in json.loads(doc)["equations"]) == kept
    assert [r["verdict"] for r in _rows(doc)] == ["verified"] * n
    if ref:
        assert _rows(doc) == _rows(ref_doc)


def test_sigint_during_verify_keeps_the_decided_ids_and_the_next_run_reuses_them(tmp_path):
    """One random moment, without the uninterrupted run beside it (the slow set's 20
    moments compare with one)."""
    _interrupt_and_resume(tmp_path, random.Random().uniform(0.4, 1.2), reference=False)


@pytest.mark.slow
@pytest.mark.parametrize("moment", range(20))
def test_sigint_or_sigterm_at_random_moments_of_verify(tmp_path, moment):
    rng = random.Random(moment)
    _interrupt_and_resume(tmp_path, rng.uniform(0.0, 1.5),
                          signal.SIGTERM if moment % 4 == 3 else signal.SIGINT)


@pytest.mark.slow
@pytest.mark.parametrize("moment", range(20))
def test_sigint_at_random_moments_of_report(tmp_path, moment):
    """``report --module``: interrupted, then run again: the same files as an uninterrupted
    run's, the kept ids not decided again."""
    n = 6
    mod = _module(tmp_path, "rep", n, 0.4)
    work = tmp_path / "work.json"

    def report(out: str, cache: str, work: Path) -> subprocess.Popen:
        return _start(["report", "--module", str(mod), "--out", str(tmp_path / out),
                       "--jobs", "2"], _env(tmp_path / cache, work), tmp_path)

    ref = report("ref", "refc", tmp_path / "ref.json")
    try:
        rc, _, err = _interrupt(report("out", "c", work), random.Random(moment).uniform(0, 2))
    finally:
        assert _finish(ref)[0] == 0
    if rc == 0:
        return
    kept = _assert_one_line(rc, err, n)
    rc, _, err = _finish(report("out", "c", work))
    assert rc == 0, err
    assert _decided(work) == n - kept
    for name in ("rep.md", "rep.json"):
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "ref" / name).read_bytes()


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
@pytest.mark.parametrize("moment", range(20))
def test_sigint_at_random_moments_of_exam_and_generate(tmp_path, command, moment):
    """Interrupted at a random moment from its start, then run again: exit 130 and one
    line, then the files of an uninterrupted run, byte for byte."""
    (tmp_path / "quiz.toml").write_text(SPEC, encoding="utf-8")
    example = ROOT / "examples" / "rotation_identities.py"

    def run(out: str, cache: str) -> subprocess.Popen:
        args = (["exam", str(tmp_path / "quiz.toml"), "--out", str(tmp_path / out)]
                if command == "exam" else
                ["generate", "--module", str(example), "--out", str(tmp_path / out),
                 "--no-build"])
        return _start(args, _env(tmp_path / cache, tmp_path / f"{out}.json"), tmp_path)

    ref = run("ref", "refc")
    try:
        rc, _, err = _interrupt(run("out", "c"), random.Random(moment).uniform(0.5, 20),
                                after=None)
    finally:
        assert _finish(ref)[0] == 0
    if rc != 0:
        _assert_one_line(rc, err, 0)
        rc, _, err = _finish(run("out", "c"))
        assert rc == 0, err
    assert _files(tmp_path / "out") == _files(tmp_path / "ref")



def test_an_error_caused_by_the_interrupt_is_reported_as_the_interrupt(monkeypatch, capsys):
    """An import cut short by Ctrl-C fails as ``ImportError`` (numpy's C extension says
    "PyCapsule_Import could not import module"): after a signal it is the interrupt (one
    line, 130); without one, the same error is the command's own and propagates."""
    import rigidsym.cli as cli

    def failing(signalled: bool):
        def run(argv):
            if signalled:
                try:
                    os.kill(os.getpid(), signal.SIGINT)  # main's handler: KeyboardInterrupt
                    time.sleep(1)
                except KeyboardInterrupt:
                    pass  # as an import's C code does: the interrupt becomes its error
            raise ImportError('PyCapsule_Import could not import module "datetime"')
        return run

    # a run started ignoring SIGINT (a background job, nohup) keeps ignoring it, by design
    # (interrupts.install); here the caller is a terminal's: Python's own handler
    outer = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _interrupt_or_error(monkeypatch, capsys, cli, failing)
    finally:
        signal.signal(signal.SIGINT, outer)


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
    exec("import os, signal, time\\nos.kill(os.getpid(), signal.SIGINT)\\ntime.sleep(5)")
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
    # a child inherits an ignored SIGINT (pytest started as a background job, `cmd &`) and
    # then keeps ignoring it, by design (interrupts.install): here a terminal's caller, whose
    # handler exec resets to the default
    outer = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        p = subprocess.run([sys.executable, "-m", "cut_short"], cwd=tmp_path, env=env,
                           capture_output=True, text=True, timeout=60)
    finally:
        signal.signal(signal.SIGINT, outer)
    assert p.returncode == interrupts.EXIT, (p.returncode, p.stderr)
    assert p.stderr.strip() == "rigidsym: interrupted; run again to continue", p.stderr
