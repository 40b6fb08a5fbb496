"""The guard of tests/_procguard.py: a test that leaves a process behind (also one orphaned
by its killed parent) fails, the process is killed, and a test that cleans up passes."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]

LEAKY = '''
import subprocess, sys, time

def test_cleans_up():
    p = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    p.kill()
    p.wait()

def test_leaks_a_child():
    p = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(61)"])
    open("pid1", "w").write(str(p.pid))

def test_leaks_an_orphan():
    # a parent that starts a grandchild and exits at once: the grandchild is an orphan
    code = ("import subprocess, sys; p = subprocess.Popen([sys.executable, '-c', "
            "'import time; time.sleep(62)'], stdout=subprocess.DEVNULL, "
            "stderr=subprocess.DEVNULL); print(p.pid)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    open("pid2", "w").write(out.stdout.strip())
    time.sleep(0.2)
'''


def _alive(pid: int) -> bool:
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
def test_a_test_that_leaves_a_process_behind_fails(pytester):
    pytester.makeconftest("from _procguard import _no_process_outlives_its_test, "
                          "become_subreaper\n\n\ndef pytest_configure(config):\n"
                          "    become_subreaper()\n")
    pytester.makepyfile(test_leaky=LEAKY)
    env = dict(os.environ, RIGIDSYM_TESTS_PROCESS_GRACE="0.5", PYTHONPATH=os.pathsep.join(
        [str(Path(__file__).parent), os.environ.get("PYTHONPATH", "")]))
    p = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                        "-p", "no:xdist", "-o", "addopts="], cwd=pytester.path, env=env,
                       capture_output=True, text=True, timeout=120)
    assert "2 errors" in p.stdout and "3 passed" in p.stdout, p.stdout
    assert "child processes outlived the test" in p.stdout
    for name in ("pid1", "pid2"):
        pid = int((pytester.path / name).read_text())
        assert not _alive(pid), f"{name}: {pid} still running"
