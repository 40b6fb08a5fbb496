"""The default test run under an artificial load: the same outcomes as on a quiet machine.

Starts ``--busy`` processes that spin (8 by default, on a 2-core machine four times its
cores), runs the README's pytest selection in this checkout (``python -m pytest -q -n auto
--dist loadgroup``, its JUnit XML kept), stops the spinners, and records each test's
outcome; ``--runs`` repeats it, and ``--quiet`` adds a run with no load first. The record
keeps the host, the load average, each run's wall time and counts, and the node ids whose
outcome differs between any two runs (none expected: no test depends on the clock or the
load, docs/testing.md).

    python benchmarks/under_load.py --runs 2 --quiet --json benchmarks/results/under_load.json
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
SPIN = "while True:\n    pass\n"


def outcomes(junit: Path) -> dict[str, str]:
    """node id -> passed / failed / error / skipped / xfailed from pytest's JUnit XML."""
    out = {}
    for case in ET.parse(junit).getroot().iter("testcase"):
        nodeid = f"{case.get('classname', '').replace('.', '/')}.py::{case.get('name')}"
        kinds = [c.tag for c in case]
        if "failure" in kinds:
            out[nodeid] = "failed"
        elif "error" in kinds:
            out[nodeid] = "error"
        elif "skipped" in kinds:
            msg = next(c for c in case if c.tag == "skipped").get("type", "")
            out[nodeid] = "xfailed" if "xfail" in msg else "skipped"
        else:
            out[nodeid] = "passed"
    return out


def one_run(busy: int, tmp: Path, k: int) -> dict:
    spinners = [subprocess.Popen([sys.executable, "-c", SPIN]) for _ in range(busy)]
    try:
        time.sleep(2 if busy else 0)
        load_before, t0 = os.getloadavg(), time.perf_counter()
        junit = tmp / f"run{k}.xml"
        p = subprocess.run([sys.executable, "-m", "pytest", "-q", "-n", "auto", "--dist",
                            "loadgroup", "-p", "no:cacheprovider", f"--junitxml={junit}"],
                           cwd=ROOT, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        load_after = os.getloadavg()
    finally:
        for s in spinners:
            s.kill()
            s.wait()
    res = outcomes(junit) if junit.exists() else {}
    counts: dict[str, int] = {}
    for v in res.values():
        counts[v] = counts.get(v, 0) + 1
    return {"busy": busy, "rc": p.returncode, "wall_s": round(wall, 1),
            "load_before": load_before, "load_after": load_after, "counts": counts,
            "summary": p.stdout.strip().splitlines()[-1] if p.stdout.strip() else "",
            "outcomes": res}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--busy", type=int, default=8, help="spinning processes (default 8)")
    ap.add_argument("--runs", type=int, default=2, help="runs under load (default 2)")
    ap.add_argument("--quiet", action="store_true", help="a run with no load first")
    ap.add_argument("--json", type=Path, required=True)
    args = ap.parse_args(argv)
    runs = []
    with tempfile.TemporaryDirectory(prefix="rigidsym-load-") as t:
        plan = ([0] if args.quiet else []) + [args.busy] * args.runs
        for k, busy in enumerate(plan):
            r = one_run(busy, Path(t), k)
            print(f"run {k}: {busy} busy, {r['wall_s']} s, rc {r['rc']}, {r['summary']}",
                  flush=True)
            runs.append(r)
    ids = set().union(*(r["outcomes"] for r in runs))
    differ = sorted(i for i in ids if len({r["outcomes"].get(i) for r in runs}) > 1)
    doc = {"host": host(), "commit": subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT,
                                                   capture_output=True, text=True).stdout.strip(),
           "runs": [{k: v for k, v in r.items() if k != "outcomes"} for r in runs],
           "tests": len(ids), "differ": differ}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    part = args.json.with_suffix(".part")
    part.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
    part.replace(args.json)
    print(f"{len(ids)} tests, {len(differ)} with another outcome under load: {differ[:10]}")
    return 1 if differ or any(r["rc"] != 0 for r in runs) else 0


if __name__ == "__main__":
    sys.exit(main())
