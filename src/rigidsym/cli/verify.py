"""``rigidsym verify``: decide equations, print a table, optionally write JSON."""

from __future__ import annotations

import time

from rigidsym._io import write_atomic
from rigidsym.checking.runner import run_checks
from rigidsym.checking.usermodules import select_with_modules
from rigidsym.cli._common import (
    JOBS,
    MODULE_HELP,
    add_repair_arguments,
    console,
    repair_options,
)

__all__ = ["add_arguments", "run"]

HELP = "decide equations of chapter 3"


def add_arguments(v) -> None:
    """Arguments of ``rigidsym verify``."""
    v.add_argument("ids", nargs="*", help="ids like 3.16, 3.96 (all parts), thm3.2.1")
    v.add_argument("--section", action="append", help="3.2 ... 3.8 (repeatable)")
    v.add_argument("--json", help="write the results as JSON to this path")
    v.add_argument("--jobs", type=int, default=JOBS, help=f"worker processes (default {JOBS})")
    v.add_argument("--quiet", action="store_true", help="no progress bar or table")
    v.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + "; only its ids unless ids or sections are given")
    v.add_argument("--no-cache", action="store_true",
                   help="check every id again; neither read nor write the verdict cache")
    add_repair_arguments(v)


def _table(results) -> None:
    from rich.table import Table

    t = Table(title="rigidsym verify")
    for col in ("id", "title", "verdict", "method", "seconds"):
        t.add_column(col)
    for r in results:
        style = "" if r.verdict == r.expected else "bold red"
        v = r.verdict if r.verdict == r.expected else f"{r.verdict} (expected {r.expected})"
        secs = "cached" if getattr(r, "cached", False) else f"{r.seconds:.2f}"
        t.add_row(r.id, r.title[:48], v, r.method, secs, style=style)
    console().print(t)


def _repairs(results) -> None:
    """One line per failing member: its first repair (``rigidsym show ID`` lists them all)."""
    for r in results:
        for s in getattr(r, "repair_search", None) or []:
            who = f"({r.id})" + (f" {s['member']!r}" if s["member"] else "")
            first = next((x for x in r.repairs if x["member"] == s["member"]), None)
            if first is None:
                print(f"{who}: {s['words']}")
                continue
            tag = ", the declared correction" if first["equals_declared"] else ""
            print(f"{who}: repair ({'; then '.join(first['edits'])}{tag}): {first['text']}")


def run(args) -> int:
    """``rigidsym verify``: decide equations, print a table, optionally write JSON."""
    from rigidsym.report.record import summary, to_json

    ids = select_with_modules(args.ids, args.section, args.module)
    t0 = time.perf_counter()
    results = run_checks(ids, jobs=args.jobs, progress=not args.quiet,
                         cache=not args.no_cache, **repair_options(args))
    wall = time.perf_counter() - t0
    if not args.quiet:
        _table(results)
        _repairs(results)
    if args.json:
        write_atomic(args.json, to_json(results))
    off = [r for r in results if r.verdict != r.expected]
    s = summary(results)
    hits = "" if args.no_cache else \
        f" ({sum(bool(getattr(r, 'cached', False)) for r in results)} from the cache)"
    print(f"{len(results)} checked in {wall:.1f} s{hits}: "
          + ", ".join(f"{k} {v}" for k, v in s.items()))
    for r in off:
        print(f"MISMATCH ({r.id}): computed {r.verdict}, expected {r.expected}: {r.detail}")
    return 1 if off else 0
