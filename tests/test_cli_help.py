"""Help that shows the way: every option has help and its default, the
top-level help lists the commands one line each with examples, ``rigidsym exercise`` lists
the exercises without solving any, errors name the next step, piped output is never cut."""

from __future__ import annotations

import argparse
import json
import subprocess
import sys

import pytest

from rigidsym.cli import build_parser, main
from rigidsym.cli.common import HelpFormatter
from rigidsym.course.worked import EXERCISE_IDS, exercise_module


def _subparsers(p: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    out = {}
    for action in p._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                out[name] = sub
                out.update({f"{name} {k}": v for k, v in _subparsers(sub).items()})
    return out


def _options():
    parser = build_parser()
    for name, sub in _subparsers(parser).items():
        for action in sub._actions:
            if isinstance(action, argparse._HelpAction | argparse._SubParsersAction):
                continue
            yield name, sub, action


@pytest.mark.parametrize("name, sub, action", list(_options()),
                         ids=lambda x: x if isinstance(x, str) else "")
def test_every_option_has_help_with_its_default(name, sub, action):
    text = HelpFormatter(name)._get_help_string(action)
    what = "/".join(action.option_strings) or action.dest
    assert text and len(text) > 10, f"rigidsym {name} {what}: no help text"
    flag = action.nargs == 0  # store_true: the default (off) goes without saying
    required = not action.option_strings and action.nargs not in ("?", "*")
    if not flag and not required:
        assert "default" in text, f"rigidsym {name} {what}: the help does not give the default"


def test_top_level_help_lists_commands_one_line_each_and_examples(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert "``" not in out and "as they land" not in out  # no docstring fragments
    commands = [n for n in _subparsers(build_parser()) if " " not in n]
    listed = [line.split()[0] for line in out.split("commands:")[1].split("examples")[0]
              .splitlines()[2:] if line.strip()]
    assert listed == commands                     # each command on exactly one line
    examples = out.split("examples, one per job:")[1].splitlines()
    assert sum(line.lstrip().startswith("rigidsym ") for line in examples) >= 3
    assert "rigidsym glossary" in out


def test_command_helps_read_alike():
    """One style for the one-line helps: lower case, no final full stop, fits a line."""
    parser = build_parser()
    for action in parser._subparsers._group_actions[0]._choices_actions:
        h = action.help
        assert h[0].islower() and not h.endswith("."), (action.dest, h)
        assert len(h) <= 64, (action.dest, h)


def test_exercise_without_an_id_lists_all_without_solving(monkeypatch, capsys):
    import rigidsym.course.worked as worked

    def no_solving(*a, **k):
        raise AssertionError("listing must not solve")

    monkeypatch.setattr(worked, "solve", no_solving)  # the command imports it when it runs
    assert main(["exercise"]) == 0
    out = capsys.readouterr().out.splitlines()
    rows = [line for line in out if line.startswith("  ")]
    assert len(rows) == len(EXERCISE_IDS) == 21
    for i, row in zip(EXERCISE_IDS, rows, strict=True):
        assert row.split()[0] == i[2:] and exercise_module(i).TITLE in row


@pytest.mark.parametrize("argv, hint", [
    (["exercise", "3.99"], "rigidsym exercise"),
    (["verify", "3.999"], "rigidsym verify --section"),
    (["show", "frob"], "rigidsym show --help"),
    (["verify", "--frobnicate"], "rigidsym verify --help"),
    (["frobnicate"], "rigidsym --help"),
    (["glossary", "frobnication"], "rigidsym glossary"),
])
def test_errors_name_the_next_step(argv, hint, capsys):
    with pytest.raises(SystemExit) as exc:
        raise SystemExit(main(argv))
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("rigidsym: error:") and "\n" not in err
    assert hint in err, err


@pytest.mark.parametrize("argv, meant", [
    (["verfy"], "'verify'"),                       # a command
    (["shwo", "3.1"], "'show'"),
    (["show", "thm3.2.9"], "'thm3.2."),            # an id: a theorem of the same section
    (["check", "--latex", "x = x", "--let", "x: rotaton"], "'rotation'"),   # a kind
])
def test_a_mistyped_word_gets_a_did_you_mean(argv, meant, capsys):
    """the close matches (difflib) come first, on the one error line."""
    with pytest.raises(SystemExit) as exc:
        raise SystemExit(main(argv))
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()[-1]    # after a progress line
    assert err.startswith("rigidsym: error:") and f"did you mean {meant}" in err, err


def test_a_word_close_to_nothing_gets_no_suggestion(capsys):
    with pytest.raises(SystemExit):
        main(["frobnicate"])
    assert "did you mean" not in capsys.readouterr().err


def test_verify_plain_and_json_on_stdout_are_whole(capsys, monkeypatch):
    """In a pipe nothing is cut: titles in full in the plain format; --format json is the
    schema-2 document alone on stdout."""
    monkeypatch.setattr("sys.stdout.isatty", lambda: False, raising=False)
    assert main(["verify", "3.1", "thm3.2.1", "--jobs", "1", "--format", "plain"]) == 0
    out = capsys.readouterr().out
    from rigidsym.registry.declarations import REGISTRY
    for i in ("3.1", "thm3.2.1"):
        assert REGISTRY[i].title.split()[-1] in out
    assert "…" not in out
    assert main(["verify", "3.1", "--jobs", "1", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["schema"] == 2 and doc["equations"][0]["id"] == "3.1"


@pytest.mark.parametrize("argv", [["--help"], ["verify", "--help"], ["exercise", "--help"],
                                  ["report", "--help"], ["show", "--help"]])
def test_help_imports_no_computer_algebra(argv):
    # help is read at the first contact: it must not wait for sympy (about 2 s to import)
    code = ("import contextlib, io, sys\nfrom rigidsym.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()) as out:\n"
            f"    try:\n        main({argv!r})\n    except SystemExit:\n        pass\n"
            "assert 'usage: rigidsym' in out.getvalue()\n"
            "print(sorted(m for m in ('sympy', 'numpy', 'flint') if m in sys.modules))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "[]"



def test_a_reader_who_closes_the_pipe_sees_no_traceback():
    # `rigidsym glossary | head -0`: the reader has left before the command writes; exit 0
    # and nothing on stderr (no "Exception ignored ... BrokenPipeError" at exit)
    import os

    r, w = os.pipe()
    os.close(r)
    try:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}  # buffered
        run = subprocess.run([sys.executable, "-m", "rigidsym", "glossary"], stdout=w,
                             stderr=subprocess.PIPE, text=True, timeout=120, env=env)
    finally:
        os.close(w)
    assert run.returncode == 0 and run.stderr == "", run.stderr


def test_cache_info_lists_the_object_cache(tmp_path, monkeypatch, capsys):
    """``cache info`` lists the C build's object cache, its objects and
    folder, beside the verdicts; and says when it is off."""
    pytest.importorskip("filelock")
    objects = tmp_path / "objs"
    (objects / "ab").mkdir(parents=True)
    for name in ("ab/ab12.o", "ab/ab34.o"):
        (objects / name).write_bytes(b"\0" * 1000)
    (objects / "ab/ab12.o.sha256").write_text("x")
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("RIGIDSYM_OBJECT_CACHE", str(objects))
    assert main(["cache", "info"]) == 0
    line = [s for s in capsys.readouterr().out.splitlines() if "objects:" in s]
    assert len(line) == 1 and "2 compiled objects" in line[0] and str(objects) in line[0]
    monkeypatch.setenv("RIGIDSYM_OBJECT_CACHE", "0")
    assert main(["cache", "info"]) == 0
    assert "objects: off" in capsys.readouterr().out


def test_build_c_info_says_how_to_watch_pips_compile(capsys):
    """pip is silent for the minutes it compiles; ``build-c --info`` (stdout
    still one JSON document) says on stderr that ``pip install -v`` shows the progress."""
    assert main(["build-c", "--info"]) == 0
    cap = capsys.readouterr()
    info = json.loads(cap.out)
    if not isinstance(info, dict) or not isinstance(info.get("build"), dict):
        pytest.skip("no C build of the package here (NumPy kernels)")
    assert "pip install -v" in cap.err and f"{info['build']['compiled']} objects" in cap.err
