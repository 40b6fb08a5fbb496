"""Benchmark the book's built statements kept in the user cache
(:mod:`rigidsym.registry.statement_cache`): this tree against a baseline install, runs
interleaved (the machine may be shared: each run records the load average before it).

Measured, each in a fresh process (imports count, as for a reader):

- ``verify``: ``rigidsym verify`` of the chapter (its default ``--jobs``), wall and CPU
  (user + sys of the command and its workers, ``/usr/bin/time``), in three states: the
  baseline on an empty ``RIGIDSYM_CACHE``; this tree on an empty cache (its first run ever:
  it builds the statements and stores them); this tree on a cache that holds the stored
  statements and nothing else (cold verdicts: every id decided, no declaration built);
- ``statements``: a process that imports rigidsym and gets every book statement (the
  baseline builds them; this tree on the filled cache reads them), wall and CPU seconds of
  the getting, and of the whole process;
- ``pytest``: ``python -m pytest -n 0 -q FILE`` of each tree's own test file, wall and CPU:
  the baseline; this tree on an empty cache (the suite's default: a fresh cache per run);
  this tree with ``RIGIDSYM_CACHE`` set to a cache holding the statements;
- ``same``: ``rigidsym verify --json`` once more in each state, the records compared
  without their run fields (seconds, cached): statements read give the document that
  statements built give;
- ``layouts``: the entries' layout chosen: the chapter's statements pickled one file per
  id, one per book module (the cache's) and one for the whole book, then read back in fresh
  processes (each file with sympy's evaluation off, as the cache reads), wall and CPU
  seconds of reading all 181.

Usage (from the repository root)::

    python benchmarks/statement_cache.py --baseline-python /path/venv/bin/python \\
        --baseline-tree /path/checkout [--rounds 3] [--pytest tests/test_labels.py] \\
        [--out benchmarks/results/statement_cache.json]

Writes the figures, the machine (CPU model, cores, Python, sympy) and the load averages
as JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]

#: run in the child: every book statement, timed, and the work counted where it is
_STATEMENTS = """
import json, time
t0, c0 = time.perf_counter(), time.process_time()
from rigidsym.registry.declarations import REGISTRY, book_ids
ids = book_ids()
t1, c1 = time.perf_counter(), time.process_time()
for i in ids:
    REGISTRY[i].build()
t2, c2 = time.perf_counter(), time.process_time()
try:
    from rigidsym.core import work
    counts = {k: sum(n for (kk, _), n in work.COUNTS.items() if kk == k)
              for k in ("build", "load")}
except ImportError:
    counts = None
print("@@", json.dumps({"ids": len(ids), "get wall": t2 - t1, "get cpu": c2 - c1,
                        "process wall": t2 - t0, "process cpu": c2 - c0, "work": counts}))
"""


#: run in the child: the chapter's statements pickled in each layout under DIR
_LAYOUT_WRITE = """
import collections, pickle, sys
from pathlib import Path
from rigidsym.registry.declarations import REGISTRY, book_ids
where = Path(sys.argv[1])
sts = {i: REGISTRY[i].build() for i in book_ids()}
mods = collections.defaultdict(dict)
for i, st in sts.items():
    mods[REGISTRY[i].module][i] = st
for layout, parts in (("id", {i: {i: st} for i, st in sts.items()}), ("module", mods),
                      ("book", {"all": sts})):
    (where / layout).mkdir(parents=True)
    for n, (name, part) in enumerate(parts.items()):
        (where / layout / f"{n}.pickle").write_bytes(pickle.dumps(part, protocol=5))
"""

#: run in the child: every file of one layout read, each with evaluation off
_LAYOUT_READ = """
import json, pickle, sys, time
from pathlib import Path
from sympy.core.parameters import evaluate
from rigidsym.registry.declarations import book_ids
book_ids()
files = sorted(Path(sys.argv[1]).glob("*.pickle"))
t, c = time.perf_counter(), time.process_time()
n = 0
for f in files:
    with evaluate(False):
        n += len(pickle.loads(f.read_bytes()))
print("@@", json.dumps({"files": len(files), "statements": n,
                        "bytes": sum(f.stat().st_size for f in files),
                        "read wall": time.perf_counter() - t,
                        "read cpu": time.process_time() - c}))
"""


def load() -> list[float]:
    """The 1, 5 and 15 minute load averages now."""
    return [round(x, 2) for x in os.getloadavg()]


def timed(argv: list[str], env: dict, cwd: Path) -> dict:
    """Wall and CPU seconds of ``argv`` (``/usr/bin/time``: the command and its children),
    its exit status and the load average before it."""
    before = load()
    with tempfile.NamedTemporaryFile("r", suffix=".time") as tf:
        p = subprocess.run(["/usr/bin/time", "-o", tf.name, "-f", "%e %U %S", *argv],
                           env=env, cwd=cwd, capture_output=True, text=True)
        wall, user, sys_ = (float(x) for x in Path(tf.name).read_text().split()[-3:])
    if p.returncode != 0:
        raise RuntimeError(f"{argv} exited {p.returncode}:\n{p.stdout[-2000:]}"
                           f"\n{p.stderr[-2000:]}")
    return {"load before": before, "wall s": wall, "cpu s": round(user + sys_, 2)}


def statements(python: str, env: dict, cwd: Path) -> dict:
    """Seconds of a fresh ``python`` process getting every book statement (built or read),
    its work counted where the tree counts, and the load average before it.

    Raises:
        subprocess.CalledProcessError: the process failed.
    """
    before = load()
    p = subprocess.run([python, "-c", _STATEMENTS], env=env, cwd=cwd, capture_output=True,
                       text=True, check=True)
    line = next(x for x in p.stdout.splitlines() if x.startswith("@@"))
    out = json.loads(line[3:])
    return {"load before": before, **{k: round(v, 3) if isinstance(v, float) else v
                                      for k, v in out.items()}}


def with_statements(filled: Path, dst: Path) -> Path:
    """A fresh cache folder holding a copy of ``filled``'s statements only."""
    dst.mkdir(parents=True)
    shutil.copytree(filled / "statements", dst / "statements")
    return dst


def lean(path: Path) -> list:
    """The JSON document's records without the run fields (seconds, cached)."""
    rows = json.loads(path.read_text(encoding="utf-8"))["equations"]
    return [{k: v for k, v in r.items() if k not in ("seconds", "cached")} for r in rows]


def machine() -> dict:
    """The CPU model, the cores, the versions of Python and sympy, the platform."""
    model = host()["cpu"]
    import sympy

    return {"cpu model": model or platform.processor(), "cores": os.cpu_count(),
            "python": platform.python_version(), "sympy": sympy.__version__,
            "platform": platform.platform()}


def main(argv: list[str] | None = None) -> int:
    """Run the measures, print each round, write the JSON (``--out``); returns 0.

    Raises:
        RuntimeError: a command exited non-zero.
    """
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--baseline-python", required=True, help="the baseline's interpreter")
    ap.add_argument("--baseline-tree", required=True, type=Path,
                    help="the baseline's checkout (its tests, for the pytest runs)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--pytest", default="tests/test_labels.py", help="test file to time")
    ap.add_argument("--skip", default="",
                    help="comma-separated: verify,statements,pytest,same,layouts")
    ap.add_argument("--out", type=Path,
                    default=ROOT / "benchmarks" / "results" / "statement_cache.json")
    args = ap.parse_args(argv)
    skip = set(filter(None, args.skip.split(",")))
    base_py, this_py = args.baseline_python, sys.executable
    base_bin, this_bin = Path(base_py).parent, Path(this_py).parent
    work = Path(tempfile.mkdtemp(prefix="statement-cache-bench-"))
    env0 = {k: v for k, v in os.environ.items() if k not in ("RIGIDSYM_CACHE",
                                                             "RIGIDSYM_WORK_FILE")}

    def cache(name: str) -> Path:
        return work / f"{name}-{time.monotonic_ns()}"

    res: dict = {"machine": machine(), "started": time.strftime("%Y-%m-%d %H:%M:%S"),
                 "baseline": str(args.baseline_tree), "tree": str(ROOT), "rounds": []}
    filled = None
    for _ in range(args.rounds):
        row: dict = {}
        if "verify" not in skip:
            empty = cache("base")
            row["verify baseline (empty cache)"] = timed(
                [str(base_bin / "rigidsym"), "verify"], dict(env0, RIGIDSYM_CACHE=str(empty)),
                work)
            first = cache("first")
            row["verify this tree, first run (empty cache: fills the statements)"] = timed(
                [str(this_bin / "rigidsym"), "verify"], dict(env0, RIGIDSYM_CACHE=str(first)),
                work)
            filled = first
            again = with_statements(filled, cache("again"))
            row["verify this tree, cold verdicts (statements cached)"] = timed(
                [str(this_bin / "rigidsym"), "verify"], dict(env0, RIGIDSYM_CACHE=str(again)),
                work)
        if filled is None:  # the statements stored once, for the other measures
            filled = cache("fill")
            statements(this_py, dict(env0, RIGIDSYM_CACHE=str(filled)), work)
        if "statements" not in skip:
            row["statements baseline (built)"] = statements(
                base_py, dict(env0, RIGIDSYM_CACHE=str(cache("sb"))), work)
            row["statements this tree (read)"] = statements(
                this_py, dict(env0, RIGIDSYM_CACHE=str(with_statements(filled,
                                                                       cache("st")))), work)
        if "pytest" not in skip:
            test = ["-m", "pytest", "-n", "0", "-q", "-p", "no:cacheprovider", args.pytest]
            row["pytest baseline"] = timed([base_py, *test], env0, args.baseline_tree)
            row["pytest this tree (fresh cache, the suite's default)"] = timed(
                [this_py, *test], env0, ROOT)
            row["pytest this tree (RIGIDSYM_CACHE holding the statements)"] = timed(
                [this_py, *test],
                dict(env0, RIGIDSYM_CACHE=str(with_statements(filled, cache("pt")))), ROOT)
        if row:
            res["rounds"].append(row)
            print(json.dumps(row, indent=1), flush=True)
    if "same" not in skip:
        docs = {}
        for name, exe, where in (("baseline", base_bin, cache("jb")),
                                 ("built", this_bin, cache("jt")),
                                 ("read", this_bin, with_statements(filled, cache("jr")))):
            out = work / f"{name}.json"
            timed([str(exe / "rigidsym"), "verify", "--json", str(out)],
                  dict(env0, RIGIDSYM_CACHE=str(where)), work)
            docs[name] = lean(out)
        res["same"] = {"records": len(docs["read"]),
                       "read == built": docs["read"] == docs["built"],
                       "read == baseline": docs["read"] == docs["baseline"]}
        print(json.dumps(res["same"]), flush=True)
    if "layouts" not in skip:
        pickles = work / "layouts"
        subprocess.run([this_py, "-c", _LAYOUT_WRITE, str(pickles)], env=env0, cwd=work,
                       check=True, capture_output=True)
        res["layouts"] = []
        for _ in range(args.rounds):
            row = {}
            for layout in ("id", "module", "book"):
                before = load()
                p = subprocess.run([this_py, "-c", _LAYOUT_READ, str(pickles / layout)],
                                   env=env0, cwd=work, check=True, capture_output=True,
                                   text=True)
                got = json.loads(next(x for x in p.stdout.splitlines()
                                      if x.startswith("@@"))[3:])
                row[layout] = {"load before": before,
                               **{k: round(v, 3) for k, v in got.items()}}
            res["layouts"].append(row)
            print(json.dumps(row), flush=True)
    res["finished"] = time.strftime("%Y-%m-%d %H:%M:%S")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(res, indent=1) + "\n", encoding="utf-8")
    shutil.rmtree(work, ignore_errors=True)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
