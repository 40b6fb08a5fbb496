"""A guard that fails a test whose child processes outlive it: imported by
conftest.py as an autouse fixture; tests/test_procguard.py runs it on a test that leaks."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest

#: children that belong to the run, not to a test: multiprocessing's helpers, and the browser
#: driver (Playwright's node process, module-scoped in tests/test_browser.py)
_RUN_HELPERS = ("multiprocessing.resource_tracker", "multiprocessing.forkserver", "playwright")


#: how long children may take to exit after their test (a pool's terminate, a killed
#: command's workers); tests/test_procguard.py shortens it
GRACE_S = float(os.environ.get("RIGIDSYM_TESTS_PROCESS_GRACE", "5"))


def become_subreaper() -> None:
    """Orphans of this process's descendants (a pool worker whose parent was killed) are
    re-parented to it, not to init, so that the guard below sees them (Linux only)."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)    # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        pass


def _children() -> dict[int, str]:
    """This process's live children (orphans included, see above): pid -> command line."""
    out = {}
    for f in Path("/proc/self/task").glob("*/children"):
        try:
            pids = f.read_text().split()
        except OSError:
            continue
        for pid in map(int, pids):
            try:
                stat = Path(f"/proc/{pid}/stat").read_text()
                if stat.rsplit(")", 1)[1].split()[0] == "Z":   # exited, not yet reaped
                    os.waitpid(pid, os.WNOHANG)
                    continue
                cmd = Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ")
            except (OSError, ChildProcessError):
                continue
            out[pid] = cmd.decode(errors="replace").strip()
    return out


@pytest.fixture(autouse=True)
def _no_process_outlives_its_test():
    """Fail a test whose child processes are still alive a few seconds after it ends (they
    are killed first, so that one leak does not fail every later test)."""
    if not Path("/proc/self/task").is_dir():
        yield
        return
    before = set(_children())
    yield
    deadline, left = time.monotonic() + GRACE_S, {}
    while True:
        left = {p: c for p, c in _children().items()
                if p not in before and not any(h in c for h in _RUN_HELPERS)}
        if not left or time.monotonic() > deadline:
            break
        time.sleep(0.05)
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
        except (OSError, ChildProcessError):
            pass
    if left:
        pytest.fail("child processes outlived the test: "
                    + "; ".join(f"{p} {c[:120]}" for p, c in left.items()), pytrace=False)
