"""Counted, not timed: the work a command does, from the counts it writes
(:mod:`rigidsym.core.work`): a warm ``verify --json`` builds no declaration, a cold one builds
each once, a change to one module rebuilds that module's ids only.

Each command runs in a fresh process (as a user runs it twice), on a cache of its own. It
guards against the parent building every declaration with LaTeX again for its
transcription record (1 build per such id on a warm ``--json`` run, 2 on a cold one).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "rotation_identities.py"
#: the example with one equation written in LaTeX (docs/own-equations.md's): its printed
#: form is read from the LaTeX
TEX = r'''

@equation("rot:trace-tex", "Trace of a rotation", latex=r"\mathrm{tr}(\mathbf{Q}) = 1 + 2\cos\phi")
def trace_of_rotation_tex():
    return MODEL
'''
#: a second module whose printed form is written by hand beside its LaTeX: its
#: transcription is checked
OTHER = r'''
"""Counting tests: a hand-written printed form beside its LaTeX."""
import sympy as sp
from rigidsym import Rel, Statement, angle, equation

phi = angle("phi")


@equation("oth:pyth", "cos^2 + sin^2 = 1", section="counting tests",
          latex=r"\cos^2\phi + \sin^2\phi = 1")
def pyth() -> Statement:
    return Statement([Rel(sp.cos(phi) ** 2 + sp.sin(phi) ** 2, sp.Integer(1))], {})


@equation("oth:double", "cos 2 phi", section="counting tests",
          latex=r"\cos 2\phi = 2\cos^2\phi - 1")
def double() -> Statement:
    return Statement([Rel(sp.cos(2 * phi), 2 * sp.cos(phi) ** 2 - 1)], {})
'''
ROT_IDS = 12  # the example's 11 and rot:trace-tex
OTH_IDS = {"oth:pyth", "oth:double"}


@pytest.fixture
def modules(tmp_path):
    (tmp_path / "rot_tex.py").write_text(EXAMPLE.read_text(encoding="utf-8") + TEX,
                                         encoding="utf-8")
    (tmp_path / "oth_tex.py").write_text(OTHER, encoding="utf-8")
    return tmp_path


def run(where: Path, *args: str, said: list | None = None) -> dict:
    """``rigidsym ARGS`` in a fresh process on ``where``'s cache, its output piped; its work
    counts (``said``, when given, gets its stdout and stderr)."""
    counts = where / "work.json"
    counts.unlink(missing_ok=True)
    env = dict(os.environ, RIGIDSYM_CACHE=str(where / "cache"),
               RIGIDSYM_WORK_FILE=str(counts))
    env.pop("RIGIDSYM_ASCII", None)
    p = subprocess.run([sys.executable, "-m", "rigidsym", *args], cwd=where, env=env,
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    if said is not None:
        said[:] = [p.stdout, p.stderr]
    return json.loads(counts.read_text(encoding="utf-8"))


def verify(where: Path, *more: str) -> dict:
    return run(where, "verify", "--module", "rot_tex.py", "--module", "oth_tex.py",
               "--jobs", "2", "--no-repairs", "--quiet", *more)


def lean(path: Path) -> list:
    """The JSON document's records without the run fields (seconds, cached)."""
    rows = json.loads(path.read_text(encoding="utf-8"))["equations"]
    return [{k: v for k, v in r.items() if k not in ("seconds", "cached")} for r in rows]


# three verify processes; quick: test_statement_cache.py::
# test_a_damaged_entry_is_built_again_and_replaced (each declaration built once cold, loaded
# warm) and test_a_change_of_what_the_key_covers_misses (an edit builds again)
@pytest.mark.slow
def test_verify_json_builds_each_declaration_once_cold_none_warm_and_a_module_s_own(modules):
    cold = verify(modules, "--json", "cold.json")
    assert len(cold["build"]) == ROT_IDS + len(OTH_IDS)
    assert max(cold["build"].values()) == 1, cold["build"]  # main: 2 for the LaTeX ids
    assert set(cold["transcribe"]) == OTH_IDS  # checked once, in the worker
    warm = verify(modules, "--json", "warm.json")
    assert warm["build"] == {}, warm["build"]  # main: the LaTeX ids, built for the record
    assert warm["decide"] == {} and warm["transcribe"] == {}
    assert lean(modules / "warm.json") == lean(modules / "cold.json")
    assert all(r["transcription"] for r in lean(modules / "warm.json")
               if r["id"] in OTH_IDS | {"rot:trace-tex"})
    # a change to one module: its ids only are built, decided and transcribed again
    path = modules / "oth_tex.py"
    path.write_text(path.read_text(encoding="utf-8") + "\n# edited\n", encoding="utf-8")
    again = verify(modules, "--json", "again.json")
    assert again["build"] == {i: 1 for i in OTH_IDS}, again["build"]  # main: the rot ids too
    assert set(again["decide"]) == OTH_IDS and set(again["transcribe"]) == OTH_IDS
    assert lean(modules / "again.json") == lean(modules / "cold.json")


# four verify runs (seconds); the quick
# test_verify_json_builds_each_declaration_once_cold_none_warm_and_a_module_s_own keeps the
# counts of builds, decisions and transcriptions
@pytest.mark.slow
def test_json_after_text_builds_only_for_the_transcriptions(modules):
    text = verify(modules)  # no JSON: no transcription asked for
    assert text["transcribe"] == {} and max(text["build"].values()) == 1
    first = verify(modules, "--json", "a.json")  # verdicts cached, records not yet
    assert first["decide"] == {}
    assert first["build"] == {i: 1 for i in OTH_IDS | {"rot:trace-tex"}}
    assert verify(modules, "--format", "json")["build"] == {}


def test_an_exercise_on_the_book_s_data_is_solved_once_then_read_back(tmp_path, monkeypatch):
    """The report's exercises are read back, not solved again (main: solved every time a
    process asks)."""
    from rigidsym.core import work as _work
    from rigidsym.course import worked

    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    monkeypatch.setattr(worked, "_CACHE", type(worked._CACHE)())  # as a fresh process
    before = _work.snapshot()
    first = worked.solve("ex3.4")
    assert _work.since(before, "solve") == {"ex3.4": 1}
    monkeypatch.setattr(worked, "_CACHE", type(worked._CACHE)())
    again = worked.solve("ex3.4")
    assert _work.since(before, "solve") == {"ex3.4": 1}
    assert worked.render_markdown(again) == worked.render_markdown(first)
    assert again.checked and again.answers.keys() == first.answers.keys()
    # a student's data: solved, never kept on disk (an exam's variants would pile up)
    worked.solve("ex3.4", f_1=[1, 2, 0])
    monkeypatch.setattr(worked, "_CACHE", type(worked._CACHE)())
    worked.solve("ex3.4", f_1=[1, 2, 0])
    assert _work.since(before, "solve") == {"ex3.4": 3}


@pytest.mark.slow
def test_the_chapter_counts_verify_json_and_report_warm_do_no_work(tmp_path):
    """The whole chapter: verify --json builds each declaration at most once cold and none
    warm; the report after them reads the statements the cold run stored (it builds none,
    and reads each at most once) and, piped, states every phase (:func:`report_phases`); a
    warm report builds, decides and solves nothing, and writes the same files."""
    common = ("verify", "--jobs", "2", "--no-repairs", "--quiet")
    cold = run(tmp_path, *common, "--json", "cold.json")
    assert max(cold["build"].values()) == 1, cold["build"]
    warm = run(tmp_path, *common, "--json", "warm.json")
    assert warm["build"] == {} and warm["decide"] == {} and warm["transcribe"] == {}
    assert lean(tmp_path / "warm.json") == lean(tmp_path / "cold.json")
    said: list[str] = []
    first = run(tmp_path, "report", "--jobs", "2", "--out", "r1", said=said)
    report_phases(*said)
    assert first["build"] == {} and first["transcribe"] == {}, first["build"]
    assert max(first["load"].values()) == 1
    second = run(tmp_path, "report", "--jobs", "2", "--out", "r2")
    assert all(second[k] == {} for k in ("build", "decide", "transcribe", "solve")), second
    names = sorted(p.name for p in (tmp_path / "r1").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "r2").iterdir())
    for name in names:
        assert (tmp_path / "r1" / name).read_bytes() == (tmp_path / "r2" / name).read_bytes()


def report_phases(stdout: str, stderr: str) -> None:
    """The chapter's report in a pipe: a start and an end line per phase and, between them,
    a line at each tenth of a counted phase's items (each item of a phase of at most 30),
    nothing else on stderr."""
    phases = ["loading the chapter's declarations", "checking 181 ids",
              "rendering and writing 3 files of the chapter report", "solving 21 exercises",
              "rendering and writing the exercises (Markdown, HTML, figures)"]
    counts: dict[str, list[tuple[int, int]]] = {}
    lines = []
    for ln in stderr.splitlines():
        if re.fullmatch(r"rigidsym report: .+: still .+, \d.*", ln):
            continue  # a quiet phase saying what it is still doing
        if re.fullmatch(r"rigidsym report: (starting \.\.\.|still (starting|working) \(.+\), "
                        r".+ s)", ln):
            continue  # the program's start, before its heavy imports
        m = re.fullmatch(r"rigidsym report: (.+): (\d+)/(\d+), \d+(\.\d)? s|"
                         r"rigidsym report: (.+): (\d+)/(\d+), \d+ min \d\d s", ln)
        if m and (m.group(1) or m.group(5)) in phases:
            what = m.group(1) or m.group(5)
            done, total = (int(m.group(2)), int(m.group(3))) if m.group(1) else \
                (int(m.group(6)), int(m.group(7)))
            counts.setdefault(what, []).append((done, total))
            assert lines and lines[-1] == f"rigidsym report: {what} ...", (ln, lines)
        else:
            lines.append(ln)
    for seen in counts.values():       # increasing, below the total
        assert [d for d, _ in seen] == sorted({d for d, _ in seen}), seen
        assert all(0 < d < t for d, t in seen), seen
    assert len(counts.get("checking 181 ids", [])) == 9, counts     # each tenth
    assert [d for d, _ in counts["solving 21 exercises"]] == list(range(1, 21))  # each item
    assert len(lines) == 2 * len(phases), lines
    for k, what in enumerate(phases):
        assert lines[2 * k] == f"rigidsym report: {what} ..."
        assert lines[2 * k + 1].startswith(f"rigidsym report: {what}: done in ")
    assert "11 does-not-hold" in lines[3]
    assert stdout.startswith("wrote ")
