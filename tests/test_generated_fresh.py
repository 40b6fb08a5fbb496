"""generated/ is what `rigidsym generate` would write: byte for byte, no missing or orphan file.

Runs the `--check` logic in-process, and regenerates under another PYTHONHASHSEED to prove
the output does not depend on set iteration order.
"""

from __future__ import annotations

import os
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest

from rigidsym.codegen.generator import check, default_out_dir, generate, write

ROOT = Path(__file__).resolve().parents[1]

# one worker generates once for the whole module (--dist loadgroup): a generation is 70 to
# 100 s of CPU since the VJP/JVP programs and the removable-singularity pass joined it, and
# each worker that ran one of these tests paid for its own
pytestmark = pytest.mark.xdist_group("generated_fresh")


@cache
def _generated():
    # one in-process generation shared by the tests below (it is deterministic; the
    # subprocess test regenerates independently)
    return generate()


def test_loadgroup_keeps_this_module_on_one_worker(request):
    """--dist loadgroup marks a grouped test's node id with its group; when it does not
    (pytest 9.2 with pytest-xdist 3.8, pytest-xdist#1386) every worker that runs a test of
    this module pays for its own generation."""
    if not getattr(request.config.option, "loadgroup", False):
        pytest.skip("not under pytest-xdist's --dist loadgroup")
    assert request.node.nodeid.endswith("@generated_fresh"), request.node.nodeid


def test_generated_is_fresh():
    res = _generated()
    diff = check(res)
    assert diff == "", "generated/ is stale; run `rigidsym generate`:\n" + diff[:4000]


def test_check_reports_missing_orphan_and_changed(tmp_path):
    res = _generated()
    write(res, tmp_path)
    assert check(res, tmp_path) == ""
    first = next(iter(res.files))
    (tmp_path / first).write_text("changed\n")
    (tmp_path / "numpy" / "orphan.py").write_text("x = 1\n")
    (tmp_path / "kernels.json").unlink()
    diff = check(res, tmp_path)
    assert f"a/generated/{first}" in diff
    assert "orphan file: generated/numpy/orphan.py" in diff
    assert "missing file: generated/kernels.json" in diff
    write(res, tmp_path)
    assert check(res, tmp_path) == ""
    assert not (tmp_path / "numpy" / "orphan.py").exists()


def test_no_timestamps_or_absolute_paths():
    res = _generated()
    for rel, text in res.files.items():
        assert str(ROOT) not in text, rel
        assert "/home/" not in text and "/root/" not in text, rel


@pytest.mark.slow  # a second, independent generation in a subprocess
def test_independent_of_hash_seed(tmp_path):
    env = dict(os.environ, PYTHONHASHSEED="4242")
    code = ("import sys; from rigidsym.codegen.generator import generate, write; "
            "write(generate(), sys.argv[1])")
    subprocess.run([sys.executable, "-c", code, str(tmp_path)], check=True, env=env,
                   cwd=ROOT)
    assert check(_generated(), tmp_path) == ""
    assert default_out_dir() == ROOT / "generated"


@pytest.mark.slow  # the CLI generates again; test_generated_is_fresh checks the same tree
def test_cli_check_exit_code(capsys):
    from rigidsym.cli import main
    assert main(["generate", "--check"]) == 0


def test_cli_check_without_generated_folder(tmp_path, capsys):
    """Outside a checkout (no generated/ folder): a one-line error and exit code 2."""
    from rigidsym.cli import main
    assert main(["generate", "--check", "--out", str(tmp_path / "generated")]) == 2
    err = capsys.readouterr().err
    assert "no generated/ folder here" in err and "stale" not in err
