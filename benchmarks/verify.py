"""Benchmark ``rigidsym verify`` and ``rigidsym report``: this tree side by side with a
baseline commit, in one run.

Measured, each in a fresh process (so imports count, as for a reader), ``--jobs 2
--no-repairs`` for verify:

- ``text`` cold and warm: the chapter with an empty verdict cache, then the same again with
  nothing changed ("n/a" warm for a baseline without a cache);
- ``--json`` cold and warm: the same writing the schema-2 document (the transcription
  records in it), on a cache of its own;
- ``report`` cold and warm: ``rigidsym report --out DIR`` (the chapter's three files and the
  exercises), on a cache of its own;
  each with its ratio to the text path (cold to cold, warm to warm), and for this tree the
  work counted (:mod:`rigidsym.core.work`: declarations built, ids decided, transcriptions
  checked, exercises solved);
- ``example``: ``rigidsym verify --module examples/rotation_identities.py``, cold;
- ``build``: CPU seconds of building the declarations (``registry._build``) per section,
  one process, no checking;
- ``where``: CPU seconds per stage of a single-job chapter run as ``rigidsym verify`` does
  it (this tree only, no expanded strings): building, the zero test, the numeric backing,
  member records, the model in words, the rest.

Usage (from the repository root)::

    python benchmarks/verify.py [--baseline REV] [--skip text,json,report,example,...]

``REV`` defaults to ``HEAD~1`` (a commit with the ``src/rigidsym`` layout). Both trees are laid
out as one byte-compiled ``rigidsym`` package in a temporary folder (``src/rigidsym`` with
``derivations/`` and ``generated/`` inside, as in a wheel) and imported from there; each
run gets its own empty ``RIGIDSYM_CACHE``. The machine's load average is printed: on a
shared machine, compare the columns of one run, not runs.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "rotation_identities.py"

#: run in the child: the chapter (or a module) through the command line, timed
_VERIFY = """
import resource, sys, time
t0 = time.perf_counter()
sys.path.insert(0, {tree!r})
from rigidsym.cli import main
code = main({argv!r})
wall = time.perf_counter() - t0
ru = [resource.getrusage(w) for w in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
print("@@", wall, sum(r.ru_utime + r.ru_stime for r in ru), code)
"""

#: run in the child: CPU seconds of building every declaration, per section
_BUILD = """
import collections, json, sys, time
sys.path.insert(0, {tree!r})
from rigidsym.registry.declarations import REGISTRY, load_all, select, section_of
load_all()
per = collections.Counter()
for i in select(None, None):
    t = time.process_time()
    REGISTRY[i].build()
    per[section_of(i)] += time.process_time() - t
print("@@", json.dumps(per))
"""

#: run in the child: CPU seconds per stage of a single-job chapter run
_WHERE = """
import collections, json, sys, time
sys.path.insert(0, {tree!r})
from rigidsym.checking import checker
from rigidsym.checking.deciding import evidence, registry
spent = collections.Counter()
def timed(mod, name, label):
    f = getattr(mod, name)
    def g(*a, **k):
        t = time.process_time()
        try:
            return f(*a, **k)
        finally:
            spent[label] += time.process_time() - t
    setattr(mod, name, g)
timed(registry, "_build", "build declarations")
timed(checker, "decide_rel", "zero test (with explicit values, counterexamples)")
timed(checker, "_numeric", "numeric backing (balls)")
timed(checker, "member_record", "member records (book notation)")
timed(checker, "model_words", "model in words")
registry.load_all()
t0 = time.process_time()
for i in registry.select(None, None):
    checker.check(i, expanded=False)  # as `rigidsym verify`: no expanded strings
spent["total"] = time.process_time() - t0
print("@@", json.dumps(spent))
"""


def layout(rev: str | None, dst: Path) -> Path:
    """The tree of ``rev`` (``None``: the working tree) as one importable ``rigidsym``."""
    src = dst / "src"
    if rev is None:
        src = ROOT
    else:
        src.mkdir(parents=True)
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True,
                                 capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", str(src)], input=archive, check=True)
    pkg = dst / "tree" / "rigidsym"
    shutil.copytree(src / "src" / "rigidsym", pkg,
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for sub in ("derivations", "generated"):
        shutil.copytree(src / sub, pkg / sub, dirs_exist_ok=True,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc", "report"))
    # byte-compiled as pip does on install: the cold run is not a first import
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(pkg)], check=True)
    return dst / "tree"


def child(code: str, cache: Path, cwd: Path) -> list[str]:
    """Run ``code`` in a fresh interpreter; the fields of its ``@@`` line."""
    env = dict(os.environ, RIGIDSYM_CACHE=str(cache))
    out = subprocess.run([sys.executable, "-c", code], env=env, cwd=cwd, check=False,
                         capture_output=True, text=True)
    line = next((x for x in out.stdout.splitlines() if x.startswith("@@")), None)
    if line is None:
        raise RuntimeError(f"child failed:\n{out.stdout[-2000:]}\n{out.stderr[-3000:]}")
    return line.split(maxsplit=1)[1].split() if not line[3:].startswith("{") else [line[3:]]


def verify_run(tree: Path, argv: list[str], cache: Path, cwd: Path) -> tuple:
    """``(wall s, CPU s, work counted or None)`` of ``rigidsym ARGV`` in a fresh process."""
    counts = cwd / f"work-{time.monotonic_ns()}.json"
    env_code = _VERIFY.format(tree=str(tree), argv=argv)
    os.environ["RIGIDSYM_WORK_FILE"] = str(counts)  # read by a tree that counts
    try:
        wall, cpu, code = child(env_code, cache, cwd)
    finally:
        del os.environ["RIGIDSYM_WORK_FILE"]
    if int(code) != 0:
        raise RuntimeError(f"rigidsym {' '.join(argv)} exited {code}")
    work = json.loads(counts.read_text()) if counts.exists() else None
    return float(wall), float(cpu), work


#: the side-by-side runs: name -> (cache of its own, arguments); cold then warm on one cache
_VERIFY_ARGS = ["verify", "--quiet", "--jobs", "2", "--no-repairs"]
RUNS = {"text": _VERIFY_ARGS, "json": [*_VERIFY_ARGS, "--json", "out.json"],
        "report": ["report", "--jobs", "2", "--out", "report-out"]}


def measure(name: str, tree: Path, has_cache: bool, skip: set, work: Path) -> dict:
    out: dict = {}
    for run, argv in RUNS.items():
        if run in skip:
            continue
        cache = work / f"cache-{name}-{run}-{time.monotonic_ns()}"
        out[f"{run} cold"] = verify_run(tree, argv, cache, work)
        if has_cache:
            out[f"{run} warm"] = verify_run(tree, argv, cache, work)
    if "example" not in skip:
        out["example"] = verify_run(tree, ["verify", "--quiet", "--module", str(EXAMPLE)],
                                    work / f"cache-{name}-ex-{time.monotonic_ns()}", work)
    if "build" not in skip:
        cache = work / f"cache-{name}-build"
        out["build"] = json.loads(child(_BUILD.format(tree=str(tree)), cache, work)[0])
    return out


def _cell(x, text=None) -> str:
    if x is None:
        return "n/a"
    ratio = f" ({x[0] / text[0]:.2f} ×)" if text else ""
    return f"{x[0]:.1f} s wall{ratio}, {x[1]:.1f} s CPU"


def _work(x) -> str:
    if not x or not x[2]:
        return ""
    return ", ".join(f"{sum(x[2].get(k, {}).values())} {w}" for k, w in
                     (("build", "built"), ("decide", "decided"),
                      ("transcribe", "transcribed"), ("solve", "solved")))


def report(rows: dict, where: dict | None) -> str:
    names = list(rows)
    lines = ["| measure | " + " | ".join(names) + " | work (this tree) |",
             "|---|" + "---|" * (len(names) + 1)]
    for run in RUNS:
        for state in ("cold", "warm"):
            key = f"{run} {state}"
            if not any(key in rows[n] for n in names):
                continue
            cells = [_cell(rows[n].get(key), None if run == "text" else
                           rows[n].get(f"text {state}")) for n in names]
            lines.append(f"| {run}, {state} | " + " | ".join(cells) + " | "
                         + _work(rows[names[-1]].get(key)) + " |")
    if any("example" in rows[n] for n in names):
        lines.append("| example module, cold | " + " | ".join(
            _cell(rows[n].get("example")) for n in names) + " | |")
    sections = sorted({s for n in names for s in rows[n].get("build", {})})
    for s in sections:
        lines.append(f"| build {s} (CPU s) | " + " | ".join(
            f"{rows[n]['build'][s]:.2f}" if s in rows[n].get("build", {}) else "n/a"
            for n in names) + " | |")
    if sections:
        lines.append("| build, all (CPU s) | " + " | ".join(
            f"{sum(rows[n]['build'].values()):.2f}" if rows[n].get("build") else "n/a"
            for n in names) + " | |")
    if where:
        total = where.pop("total")
        lines += ["", "| stage (single job, this tree) | CPU s | share |", "|---|---|---|"]
        for k, v in sorted(where.items(), key=lambda kv: -kv[1]):
            lines.append(f"| {k} | {v:.1f} | {100 * v / total:.0f} % |")
        rest = total - sum(where.values())
        lines.append(f"| the rest (explicit values of the backing, records, ...) | "
                     f"{rest:.1f} | {100 * rest / total:.0f} % |")
        lines.append(f"| **total** | {total:.1f} | 100 % |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--baseline", default="HEAD~1", help="git revision to compare with")
    p.add_argument("--skip", default="",
                   help="comma-separated: text,json,report,example,build,where")
    args = p.parse_args(argv)
    skip = set(filter(None, args.skip.split(",")))
    with tempfile.TemporaryDirectory(prefix="rigidsym-bench-") as tmp:
        work = Path(tmp)
        base = layout(args.baseline, work / "base")
        this = layout(None, work / "this")
        # a baseline without a verdict cache: no warm runs
        cached = (base / "rigidsym" / "checking" / "verdict_cache.py").exists()
        rows = {f"baseline ({args.baseline})": measure("base", base, cached, skip, work),
                "this tree": measure("this", this, True, skip, work)}
        where = None
        if "where" not in skip:
            where = json.loads(child(_WHERE.format(tree=str(this)), work / "cache-w",
                                     work)[0])
    print(f"# rigidsym verify, {time.strftime('%Y-%m-%d')}, {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.1f}\n")
    print(report(rows, where))
    return 0


if __name__ == "__main__":
    sys.exit(main())
