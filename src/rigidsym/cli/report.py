"""``rigidsym report``: the chapter report (Markdown, JSON, HTML) and the exercises."""

from __future__ import annotations

import os
from pathlib import Path

from rigidsym._io import write_atomic
from rigidsym.checking.registry import select
from rigidsym.checking.runner import run_checks
from rigidsym.cli._common import JOBS, MODULE_HELP

__all__ = ["add_arguments", "run", "default_report_dir"]

HELP = "write the chapter report (Markdown, JSON, HTML)"


def add_arguments(r) -> None:
    """Arguments of ``rigidsym report``."""
    r.add_argument("--out", default=None,
                   help="output folder (default: generated/report/ at the root of a rigidsym "
                        "source tree, else ./rigidsym-report/)")
    r.add_argument("--full", action="store_true",
                   help="also write chapter3-full.{md,json} with the expanded values")
    r.add_argument("--jobs", type=int, default=JOBS)
    r.add_argument("--no-cache", action="store_true",
                   help="check every id again; neither read nor write the verdict cache")
    r.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + ": report its ids into --out as <module>.{md,json,html}")


def default_report_dir(cwd: Path | None = None) -> Path:
    """Where ``rigidsym report`` writes by default: ``generated/report/`` at the root of a
    rigidsym source tree (a ``pyproject.toml`` naming ``rigidsym``), else
    ``./rigidsym-report/``."""
    import tomllib
    here = Path.cwd() if cwd is None else Path(cwd)
    try:
        meta = tomllib.loads((here / "pyproject.toml").read_text(encoding="utf-8"))
        if meta.get("project", {}).get("name") == "rigidsym":
            return here / "generated" / "report"
    except (OSError, ValueError):
        pass
    return here / "rigidsym-report"


def run(args) -> int:
    """``rigidsym report``: write ``chapter3.{md,json,html}`` and the exercises to ``--out``."""
    if args.module:  # a user module's report: titled by it, files named after it
        from rigidsym.report.user import write_user_report
        return write_user_report(args.module, Path(args.out) if args.out else Path.cwd(),
                                 args.jobs, cache=not args.no_cache)
    from rigidsym.cli.exercise import write_report as write_exercises
    from rigidsym.report.html import to_html
    from rigidsym.report.markdown import to_markdown
    from rigidsym.report.record import to_json
    ids = select(None, None)
    results = run_checks(ids, jobs=args.jobs, progress=True, cache=not args.no_cache)
    out = Path(args.out) if args.out else default_report_dir()
    written = [write_atomic(out / "chapter3.md", to_markdown(results)),
               write_atomic(out / "chapter3.json", to_json(results, timings=False)),
               write_atomic(out / "chapter3.html", to_html(results))]
    if args.full:  # expanded values: never over the lean, committed files
        written += [write_atomic(out / "chapter3-full.md", to_markdown(results, full=True)),
                    write_atomic(out / "chapter3-full.json",
                                 to_json(results, timings=False, full=True))]
    written += write_exercises(out)
    where = os.path.relpath(out) if not os.path.relpath(out).startswith("..") else str(out)
    print(f"wrote {len(written)} files to {where}{os.sep}: "
          + ", ".join(sorted(Path(p).name for p in written)))
    return 1 if any(r.verdict != r.expected for r in results) else 0
