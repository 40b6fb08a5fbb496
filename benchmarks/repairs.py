"""Benchmark the repair search: ``rigidsym verify`` with and without it, one run.

Measured, each in a fresh process with an empty verdict cache (``--no-cache``), side by
side and interleaved (with, without, with, without, ...) so that a shared machine's load
falls on both columns alike:

- ``chapter``: the whole chapter, ``--jobs 2`` (wall and CPU seconds, both workers);
- ``example``: ``--module examples/rotation_identities.py``, one job.

Also printed: the search's own CPU seconds per does-not-hold id (one process, one job),
from ``Result.seconds`` with and without the search; and (``corpus``) the wall
time of ``rigidsym.check_latex`` with repairs on (the default ``--repair-seconds`` 10) on
every entry of the book corpus (``tests/data/latex_corpus``), one process, an empty verdict
cache, each entry with its book's table and ``--notation`` as the corpus test reads it: the
slowest entries and the maximum (the target: none over 15 s).

Usage (from the repository root)::

    python benchmarks/repairs.py [--repeat N] [--skip chapter,example,per-id,corpus]

Target: the cold chapter with repairs takes at most 1.5 times as long as with
``--no-repairs``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "rotation_identities.py"

_VERIFY = """
import resource, sys, time
t0 = time.perf_counter()
from rigidsym.cli import main
code = main({argv!r})
wall = time.perf_counter() - t0
ru = [resource.getrusage(w) for w in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
print("@@", wall, sum(r.ru_utime + r.ru_stime for r in ru), code)
"""

_PER_ID = """
import json
from rigidsym.checking.checker import check
from rigidsym.registry.declarations import load_all, select
load_all()
out = {}
for i in select(None, None):
    r0 = check(i, repairs=False)
    if r0.verdict != "does-not-hold":
        continue
    r1 = check(i)
    out[i] = [r0.seconds, r1.seconds, sum(s["candidates"] for s in r1.repair_search)]
print("@@", json.dumps(out))
"""

_CORPUS = """
import json, sys, time
sys.path.insert(0, "tests/data/latex_corpus")
import corpus, rigidsym
from rigidsym.checking.deciding import registry
from rigidsym.latex.notations import NOTATIONS
out = {}
for e in corpus.entries():
    book = e["book"]["key"]
    t0 = time.perf_counter()
    try:
        r = rigidsym.check_latex(e["latex"], let=corpus.lets_of(e),
                                 notation=book if book in NOTATIONS else None)
        v = r.verdict
        words = [s["words"] for s in r.repair_search]
    except ValueError:
        v, words = "bad-input", []
    finally:
        registry.forget_module("rigidsym.latex.statement")
    out[e["id"]] = [round(time.perf_counter() - t0, 2), v, words]
print("@@", json.dumps(out))
"""


def _run(code: str) -> list[str]:
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, RIGIDSYM_CACHE=cache, COLUMNS="120")
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           env=env, cwd=ROOT, check=False)
    line = next((x for x in p.stdout.splitlines() if x.startswith("@@ ")), None)
    if line is None:
        raise RuntimeError(f"benchmark child failed:\n{p.stderr[-2000:]}")
    return line[3:]


def _verify(argv: list[str]) -> tuple[float, float]:
    wall, cpu, _ = _run(_VERIFY.format(argv=["verify", "--quiet", "--no-cache", *argv])).split()
    return float(wall), float(cpu)


def _side_by_side(name: str, argv: list[str], repeat: int) -> dict:
    rows = {"with": [], "without": []}
    for _ in range(repeat):
        rows["with"].append(_verify(argv))
        rows["without"].append(_verify([*argv, "--no-repairs"]))
    med = {k: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v))
           for k, v in rows.items()}
    ratio = med["with"][0] / med["without"][0]
    print(f"{name:8s} with repairs {med['with'][0]:6.1f} s wall {med['with'][1]:6.1f} s CPU | "
          f"--no-repairs {med['without'][0]:6.1f} s wall {med['without'][1]:6.1f} s CPU | "
          f"ratio (wall) {ratio:.2f} | runs {json.dumps(rows)}")
    return {"with": med["with"], "without": med["without"], "ratio": ratio}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--skip", default="", help="comma-separated: chapter, example, per-id")
    args = ap.parse_args(argv)
    skip = set(filter(None, args.skip.split(",")))
    print(f"load average before: {os.getloadavg()}, cpus: {os.cpu_count()}")
    if "example" not in skip:
        _side_by_side("example", ["--module", str(EXAMPLE), "--jobs", "1"], args.repeat)
    if "chapter" not in skip:
        _side_by_side("chapter", ["--jobs", "2"], args.repeat)
    if "per-id" not in skip:
        per = json.loads(_run(_PER_ID))
        print("per does-not-hold id (one job): seconds without, with the search, candidates")
        for i, (a, b, n) in per.items():
            print(f"  {i:7s} {a:6.2f} {b:6.2f}  +{b - a:5.2f} s  {n} candidates")
        print(f"  total  {sum(a for a, _, _ in per.values()):6.2f} "
              f"{sum(b for _, b, _ in per.values()):6.2f}")
    if "corpus" not in skip:
        per = json.loads(_run(_CORPUS))
        slow = sorted(per.items(), key=lambda kv: -kv[1][0])
        print(f"corpus with repairs ({len(per)} entries, one process, cold verdict cache): "
              f"max {slow[0][1][0]:.2f} s ({slow[0][0]}), total "
              f"{sum(v[0] for v in per.values()):.1f} s; the slowest:")
        for i, (sec, v, words) in slow[:8]:
            print(f"  {i:22s} {sec:6.2f} s  {v:14s} {'; '.join(words)[:90]}")
    print(f"load average after: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
