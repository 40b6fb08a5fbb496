"""``rigidsym report``: the chapter report (Markdown, JSON, HTML) and the exercises."""

from __future__ import annotations

import os
from pathlib import Path

from rigidsym.cli.common import JOBS, MODULE_HELP
from rigidsym.core.files import write_atomic
from rigidsym.registry.declarations import select

__all__ = ["add_arguments", "run", "default_report_dir"]

HELP = "write the report: HTML, Markdown, JSON, the exercises"
EXAMPLES = """\
  rigidsym report                          into generated/report/ (a source tree) or
                                           ./rigidsym-report/ (timed by benchmarks/verify.py)
  rigidsym report --module my_eqs.py --out notes/   your own equations' report
  rigidsym report --certificates certs     each entry says how its verdict is certified
                                           and whether certcheck re-checked it"""


def add_arguments(r) -> None:
    """Arguments of ``rigidsym report``."""
    r.add_argument("--out", default=None, metavar="DIR",
                   help="output folder (default: generated/report/ at the root of a rigidsym "
                        "source tree, else ./rigidsym-report/)")
    r.add_argument("--full", action="store_true",
                   help="also write chapter3-full.{md,json} with the expanded values "
                        "(default: off)")
    r.add_argument("--jobs", type=int, default=JOBS, metavar="N", help="worker processes")
    r.add_argument("--no-cache", action="store_true",
                   help="check every id again; neither read nor write the verdict cache "
                        "(default: off, the cache is used)")
    r.add_argument("--certificates", metavar="DIR", default=None,
                   help="write each verdict's certificate into DIR, re-check them with "
                        "certcheck, and say in the Markdown and HTML how each verdict is "
                        "certified (docs/certificates.md; default: none)")
    r.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + ": report its ids into --out as <module>.{md,json,html} "
                                      "(default: none, the chapter)")


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


def _chapter_files(results, full: bool, certified: dict | None = None
                   ) -> list[tuple[str, object]]:
    """``(file name, function making its text)`` of the chapter report, in writing order."""
    from rigidsym.report.html import to_html
    from rigidsym.report.markdown import to_markdown
    from rigidsym.report.record import to_json

    files = [("chapter3.md", lambda: to_markdown(results, certified=certified)),
             ("chapter3.json", lambda: to_json(results, timings=False)),
             ("chapter3.html", lambda: to_html(results, certified=certified))]
    if full:  # expanded values: never over the lean, committed files
        files += [("chapter3-full.md", lambda: to_markdown(results, full=True)),
                  ("chapter3-full.json", lambda: to_json(results, timings=False, full=True))]
    return files


def _solve_exercises(rep) -> None:
    """Solve every exercise (the report hook then reads the solutions from the cache)."""
    from rigidsym.course import EXERCISE_IDS
    from rigidsym.course import solve_exercise as solve

    with rep.phase(f"solving {len(EXERCISE_IDS)} exercises", total=len(EXERCISE_IDS)) as ph:
        ok = 0
        for i in EXERCISE_IDS:
            ph.label(f"solving exercise {i[2:]}")
            s = solve(i)
            ok += s.status == "solved" and s.checked
            ph.advance(1, label=f"exercise {i[2:]} {s.status}")
        ph.finish(f"{ok} / {len(EXERCISE_IDS)} solved and checked")


def run(args) -> int:
    """``rigidsym report``: write ``chapter3.{md,json,html}`` and the exercises to ``--out``,
    with progress on stderr (loading, checking, rendering and writing, exercises)."""
    from rigidsym.checking.runner import run_checks  # sympy: after the parser

    if args.module:  # a user module's report: titled by it, files named after it
        from rigidsym.report.user import write_user_report
        return write_user_report(args.module, Path(args.out) if args.out else Path.cwd(),
                                 args.jobs, cache=not args.no_cache,
                                 certificates=args.certificates)
    from rigidsym.cli.exercise import write_report as write_exercises
    from rigidsym.core.progress import Reporter
    from rigidsym.report.record import transcription_extra

    out = Path(args.out) if args.out else default_report_dir()
    with Reporter("rigidsym report") as rep:
        with rep.phase("loading the chapter's declarations") as ph:
            ids = select(None, None)
            ph.finish(f"{len(ids)} ids")
        results = run_checks(ids, jobs=args.jobs, progress=True, cache=not args.no_cache,
                             reporter=rep, expanded=args.full, extra=transcription_extra())
        cert = None
        if args.certificates:
            from rigidsym.report.user import certified

            with rep.phase("writing and re-checking the certificates") as ph:
                cert = certified(results, args.certificates)
                ph.finish(f"{len(cert)} ids")
        files = _chapter_files(results, args.full, cert)
        written = []
        with rep.phase(f"rendering and writing {len(files)} files of the chapter report",
                       total=len(files)) as ph:
            for name, make in files:
                ph.label(f"rendering {name}")
                written.append(write_atomic(out / name, make()))
                ph.advance(1, label=f"wrote {name}")
        from rigidsym.course import rendered

        if rendered() is None:  # else nothing they depend on changed
            _solve_exercises(rep)
        with rep.phase("rendering and writing the exercises (Markdown, HTML, figures)") as ph:
            more = write_exercises(out)
            ph.finish(f"{len(more)} files")
        written += more
    where = os.path.relpath(out) if not os.path.relpath(out).startswith("..") else str(out)
    print(f"wrote {len(written)} files to {where}{os.sep}: "
          + ", ".join(sorted(Path(p).name for p in written)))
    return 1 if any(r.verdict != r.expected for r in results) else 0
