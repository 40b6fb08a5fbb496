"""Every test's time in one profile of the suite: the table a re-pricing starts from.

Runs pytest (in this checkout, the current environment) with a plugin that appends each
test's setup, call and teardown times to a JSON-lines file as the test ends, so that an
interrupted run keeps what it measured; then writes the table: the host (CPU model, cores,
Python, load average before and after), the run's wall time and exit code, and the time by
file, by parametrised family (the node id less its parameters) and by test, costliest first.

    python benchmarks/durations.py --profile quick --json benchmarks/results/durations-quick.json
    python benchmarks/durations.py --profile thorough --json ... -- -x tests/test_zero.py

``--profile quick`` runs the README's selection (``-m 'not slow'``), ``thorough`` the second
part of ``.ci/run`` (``-m "slow or extra or budget"`` with ``RIGIDSYM_TEST_PROFILE=thorough``).
Arguments after ``--`` go to pytest. Times are wall seconds of each phase in its worker; with
``-n auto`` their sum is about the workers' busy time, not the run's wall time.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
SELECTION = {"quick": [], "thorough": ["-m", "slow or extra or budget"]}

PLUGIN = '''
import json, os
_OUT = os.environ["RIGIDSYM_DURATIONS_LOG"]

def pytest_runtest_logreport(report):
    if os.environ.get("PYTEST_XDIST_WORKER"):   # the controller writes each report once
        return
    with open(_OUT, "a", encoding="utf-8") as f:
        f.write(json.dumps({"id": report.nodeid, "phase": report.when,
                            "s": round(report.duration, 4),
                            "outcome": report.outcome}) + "\\n")
'''


def family(nodeid: str) -> str:
    """The node id without its parameters and xdist group: ``f.py::test_x[a-b]@g`` ->
    ``f.py::test_x``."""
    return re.sub(r"\[.*$", "", nodeid.split("@")[0])


def table(rows: list[dict]) -> dict:
    """Times by test, family and file (seconds, costliest first) from the log's rows."""
    by_test: dict[str, float] = defaultdict(float)
    for r in rows:
        by_test[r["id"].split("@")[0]] += r["s"]
    by_family: dict[str, list] = defaultdict(lambda: [0.0, 0])
    by_file: dict[str, float] = defaultdict(float)
    for nodeid, s in by_test.items():
        by_family[family(nodeid)][0] += s
        by_family[family(nodeid)][1] += 1
        by_file[nodeid.split("::")[0]] += s

    def ranked(d: dict) -> dict:
        return dict(sorted(((k, round(v, 2)) for k, v in d.items()), key=lambda kv: -kv[1]))

    return {"tests": len(by_test), "seconds": round(sum(by_test.values()), 1),
            "by_file": ranked(by_file),
            "by_family": {k: {"s": round(v[0], 2), "tests": v[1]} for k, v in
                          sorted(by_family.items(), key=lambda kv: -kv[1][0])},
            "by_test": ranked(by_test)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--profile", choices=sorted(SELECTION), default="quick")
    ap.add_argument("--json", type=Path, required=True, help="write the table here")
    ap.add_argument("--workers", default="auto", help="pytest-xdist's -n (default auto)")
    ap.add_argument("pytest_args", nargs="*", help="more arguments for pytest (after --)")
    args = ap.parse_args(argv)

    with tempfile.TemporaryDirectory(prefix="rigidsym-durations-") as tmp:
        (Path(tmp) / "rigidsym_durations_log.py").write_text(PLUGIN, encoding="utf-8")
        log = Path(tmp) / "log.jsonl"
        env = dict(os.environ, RIGIDSYM_DURATIONS_LOG=str(log), RIGIDSYM_TEST_PROFILE=args.profile,
                   PYTHONPATH=os.pathsep.join(filter(None, [tmp, os.environ.get("PYTHONPATH")])))
        cmd = [sys.executable, "-m", "pytest", "-q", "-n", args.workers, "--dist", "loadgroup",
               "-p", "rigidsym_durations_log", *SELECTION[args.profile], *args.pytest_args]
        load_before, t0 = os.getloadavg(), time.perf_counter()
        rc = subprocess.run(cmd, cwd=ROOT, env=env).returncode
        wall = time.perf_counter() - t0
        rows = [json.loads(line) for line in log.read_text(encoding="utf-8").splitlines()] \
            if log.exists() else []
    outcomes: dict[str, int] = defaultdict(int)
    for r in rows:
        if r["phase"] == "call" or r["outcome"] != "passed":
            outcomes[r["outcome"]] += 1
    doc = {"host": host(), "profile": args.profile, "command": cmd[2:],
           "load_before": load_before, "load_after": os.getloadavg(),
           "wall_s": round(wall, 1), "rc": rc, "outcomes": dict(outcomes), **table(rows)}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    tmp_out = args.json.with_suffix(".tmp")
    tmp_out.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
    tmp_out.replace(args.json)
    print(f"{args.profile}: {doc['tests']} tests, {doc['seconds']} s of test time, "
          f"{doc['wall_s']} s wall, rc {rc}; {args.json}")
    for name, s in list(doc["by_family"].items())[:15]:
        print(f"{s['s']:8.1f} s {s['tests']:5d}  {name}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
