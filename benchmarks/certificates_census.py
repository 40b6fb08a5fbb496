"""The chapter's certificates counted and re-checked: the figures of docs/certificates.md's
"Measured" table.

Exports every id's certificate with the referee command (``rigidsym verify --certificates
DIR``, with ``--book`` when the book's text is there) on an empty user cache (``export``:
every verdict and certificate computed), then again on the cache it filled (``export_warm``:
read from the verdict store), beside ``rigidsym verify`` alone on an empty cache
(``verify_cold``), then counts, from the files:

- the ids by verdict (and whether they agree with ``generated/report/chapter3.json``);
- of the verified ids, how many are certified entirely by cofactors (every relation's
  evidence ``cofactors``), partly (some ``cofactors``, some ``identity``) and by
  re-computation (every relation ``identity``), naming the ids of the last two, and their
  relations by evidence;
- certcheck on the folder, once with python-flint and once with the standard library only
  (``python -I -S``, ``--no-flint``): its verdict counts, wall and CPU seconds, peak memory
  and its slowest ids;
- the folder's size in bytes and certcheck's size in lines (``certcheck/src/certcheck/*.py``).

Usage (from the repository root)::

    python benchmarks/certificates_census.py [--book BOOK] [--jobs N] [--keep DIR]
                                             [--json OUT]

``BOOK`` defaults to ``../shared/book/angeles-chapter3.md`` beside the checkout when it is
there. Each step is a separate process; its CPU seconds are its own (user + system, from
``wait4``). The machine and the load average before and after go into the record.
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
from collections import Counter
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
CERTCHECK = ROOT / "certcheck" / "src"
REPORT = ROOT / "generated" / "report" / "chapter3.json"
READING = ROOT / "derivations" / "angeles-chapter3.reading.toml"
_CLI = "import sys; from rigidsym.cli import main; sys.exit(main(sys.argv[1:]))"
_ISOLATED = ("import sys; sys.path.insert(0, {src!r}); from certcheck.__main__ import main; "
             "sys.exit(main({argv!r}))")
CHECKED = re.compile(r"^CHECKED \((?P<id>[^)]+)\) (?P<verdict>\S+)\s+\[(?P<s>[\d.]+) s\]$")
NOT_READ = re.compile(r"^NOT READ \S+: \((?P<id>[^)]+)\) .*\[(?P<s>[\d.]+) s\]$")


def _book_order(eq_id: str) -> list:
    """A sort key: 3.85 before 3.105, thm3.4.2 among the theorems."""
    return [(0, int(x), "") if x.isdigit() else (1, 0, x) for x in re.split(r"(\d+)", eq_id)]


def _book_default() -> Path | None:
    for where in (ROOT.parent / "shared", ROOT / "shared"):
        book = where / "book" / "angeles-chapter3.md"
        if book.is_file():
            return book
    return None


def timed(argv: list[str], env: dict | None = None) -> dict:
    """Run ``argv``; its exit code, wall seconds, CPU seconds (user + system of it and its
    waited-for children), peak resident memory and output."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        t0 = time.perf_counter()
        p = subprocess.Popen(argv, stdout=out, stderr=err, env=env, cwd=ROOT)
        _, status, ru = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return {"exit": p.returncode, "wall_s": round(wall, 1),
                "cpu_s": round(ru.ru_utime + ru.ru_stime, 1),
                "max_rss_mb": round(ru.ru_maxrss / 1024),
                "stdout": out.read().decode("utf-8", "replace"),
                "stderr": err.read().decode("utf-8", "replace")}


def export(folder: Path | None, book: Path | None, jobs: int, cache: Path) -> dict:
    """The referee command, certificates written into ``folder`` and re-checked by ``rigidsym
    verify`` (``None``: ``rigidsym verify`` alone, no certificate), with ``cache`` as the
    user cache (an empty folder: everything computed; one an earlier run filled: the verdicts
    and certificates read from its store)."""
    argv = ["verify", "--quiet", "--jobs", str(jobs)]
    if folder is not None:
        argv[1:1] = ["--certificates", str(folder)] + (["--book", str(book)] if book else [])
    run = timed([sys.executable, "-c", _CLI, *argv],
                env={**os.environ, "RIGIDSYM_CACHE": str(cache)})
    lines = (run["stderr"] + run["stdout"]).splitlines()
    shown = " ".join("BOOK" if a == str(book) else a for a in argv)
    return {"command": "rigidsym " + shown.replace(str(folder), "DIR"),
            "exit": run["exit"], "wall_s": run["wall_s"], "cpu_s": run["cpu_s"],
            "line": next((x for x in lines if x.startswith("certificates:")), None),
            "summary": next((x for x in lines if " checked in " in x), None)}


def census(folder: Path) -> dict:
    """The ids by verdict, and the verified ids by evidence, from the certificate files."""
    certs = {}
    for path in sorted(folder.glob("*.json")):
        if path.name != "MANIFEST.json":
            cert = json.loads(path.read_text(encoding="utf-8"))
            certs[cert["id"]] = cert
    verdicts = Counter(c["verdict"] for c in certs.values())
    report = {e["id"]: e["verdict"] for e in
              json.loads(REPORT.read_text(encoding="utf-8"))["equations"]}
    mine = {i: c["verdict"] for i, c in certs.items()}
    entirely, partly, recomputed = [], [], []
    relations = Counter()
    for i, c in certs.items():
        if c["verdict"] != "verified":
            continue
        kinds = [r["evidence"]["type"] for r in c["relations"]]
        relations.update(kinds)
        n = kinds.count("cofactors")
        (entirely if n == len(kinds) else recomputed if n == 0 else partly).append(i)
    verified = verdicts["verified"]
    return {
        "ids": len(certs),
        "by_verdict": dict(sorted(verdicts.items())),
        "report_verdicts": dict(sorted(Counter(report.values()).items())),
        "agrees_with_report": mine == report,
        "differ_from_report": sorted(i for i in set(mine) | set(report)
                                     if mine.get(i) != report.get(i)),
        "verified": {
            "ids": verified,
            "entirely_by_cofactors": len(entirely),
            "entirely_by_cofactors_percent": round(100 * len(entirely) / verified, 1)
            if verified else None,
            "partly_by_cofactors": len(partly), "partly_ids": sorted(partly, key=_book_order),
            "by_recomputation": len(recomputed),
            "recomputation_ids": sorted(recomputed, key=_book_order),
            "relations": sum(relations.values()),
            "relations_by_evidence": dict(sorted(relations.items())),
        },
    }


def certcheck(folder: Path, book: Path | None, flint: bool) -> dict:
    """certcheck on the folder (``--quiet``, bound to the book and to the chapter's reading,
    as docs/certificates.md's referee command), with python-flint or the standard library
    only (``python -I -S``, ``--no-flint``)."""
    args = ["--quiet", *(["--book", str(book)] if book else []), "--reading", str(READING),
            str(folder)]
    if flint:
        env = dict(os.environ, PYTHONPATH=str(CERTCHECK))
        argv = [sys.executable, "-m", "certcheck", *args]
        shown = "python -m certcheck"
    else:
        env = None
        argv = [sys.executable, "-I", "-S", "-c",
                _ISOLATED.format(src=str(CERTCHECK), argv=[*args, "--no-flint"])]
        shown = "python -I -S -c '...certcheck.__main__.main(...)'"
    run = timed(argv, env)
    out = run["stdout"].splitlines()
    times = {}
    for line in out:
        m = CHECKED.match(line) or NOT_READ.match(line)
        if m:
            times[m["id"]] = float(m["s"])
    checked = sum(bool(CHECKED.match(x)) for x in out)
    not_read = sum(bool(NOT_READ.match(x)) for x in out)
    failed = sum(x.startswith("FAILED ") for x in out)
    slowest = sorted(times.items(), key=lambda kv: -kv[1])[:5]
    shown += " --quiet" + (" --book BOOK" if book else "") + " --reading READING DIR"
    return {"command": shown + ("" if flint else " --no-flint"),
            "exit": run["exit"], "wall_s": run["wall_s"], "cpu_s": run["cpu_s"],
            "max_rss_mb": run["max_rss_mb"], "certificates": len(times) + failed,
            "checked": checked, "not_read": not_read, "failed": failed,
            "passed": checked + not_read,
            "not_read_ids": sorted((m["id"] for m in map(NOT_READ.match, out) if m),
                                   key=_book_order),
            "summary": next((x for x in out if x.startswith("certcheck:")), None),
            "slowest": [{"id": i, "s": s} for i, s in slowest],
            "failures": [x for x in out if x.startswith("FAILED ")][:10]}


def sizes(folder: Path) -> dict:
    files = [p for p in folder.iterdir() if p.is_file()]
    total = sum(p.stat().st_size for p in files)
    lines = {p.name: len(p.read_text(encoding="utf-8").splitlines())
             for p in sorted((CERTCHECK / "certcheck").glob("*.py"))}
    return {"folder": {"files": len(files), "bytes": total, "megabytes": round(total / 1e6, 1)},
            "certcheck_lines": sum(lines.values()), "certcheck_lines_by_file": lines}


def _flint_version() -> str | None:
    try:
        import flint
    except ImportError:
        return None
    return getattr(flint, "__version__", "?")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--book", type=Path, default=_book_default(),
                    help="the book's text (default: ../shared/book/angeles-chapter3.md)")
    ap.add_argument("--jobs", type=int, default=2,
                    help="rigidsym verify's worker processes (default 2)")
    ap.add_argument("--keep", type=Path, help="write the certificates here (kept)")
    ap.add_argument("--json", metavar="OUT", help="write the record here")
    args = ap.parse_args()
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True, check=False).stdout.strip()
    record = {"host": {**host(), "load_before": round(os.getloadavg()[0], 1)},
              "commit": commit, "python_flint": _flint_version(),
              "book": args.book is not None}
    with tempfile.TemporaryDirectory() as tmp:
        folder = args.keep or Path(tmp) / "certs"
        caches = Path(tmp) / "verify-cache", Path(tmp) / "export-cache"
        for name, where, cache in (("verify_cold", None, caches[0]),
                                   ("export", folder, caches[1]),
                                   ("export_warm", Path(tmp) / "again", caches[1])):
            print(f"{name} ...", file=sys.stderr, flush=True)
            record[name] = export(where, args.book, args.jobs, cache)
            print(json.dumps(record[name]), file=sys.stderr, flush=True)
        record.update(census(folder))
        record.update(sizes(folder))
        record["certcheck"] = {}
        for name, flint in (("flint", True), ("stdlib", False)):
            print(f"certcheck ({name}) ...", file=sys.stderr, flush=True)
            record["certcheck"][name] = certcheck(folder, args.book, flint)
            print(record["certcheck"][name]["summary"], file=sys.stderr, flush=True)
    record["host"]["load_after"] = round(os.getloadavg()[0], 1)
    text = json.dumps(record, indent=1, ensure_ascii=False) + "\n"
    if args.json:
        Path(args.json).write_text(text, encoding="utf-8")
    print(text)


if __name__ == "__main__":
    main()
