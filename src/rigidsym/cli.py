"""Command-line interface: ``rigidsym verify | report | show`` (and more as they land).

Exit codes: 0 = all as expected, 1 = some computed verdict differs from its expectation,
2 = bad input (a one-line message naming what was expected).
"""

from __future__ import annotations

import argparse
import inspect
import os
import sys
import time
from collections.abc import Callable
from pathlib import Path

from .registry import REGISTRY, BadInput, select
from .usermodules import MODULE_HELP as _MODULE_HELP
from .usermodules import select_with_modules, write_user_report

__all__ = ["main", "run_checks", "COMMANDS"]

#: extra sub-commands: name -> (add_arguments, run) registered by other modules.
COMMANDS: dict[str, tuple[Callable, Callable]] = {}


def _check_one(eq_id: str):
    from .checker import check
    return check(eq_id)


def run_checks(ids: list[str], jobs: int = 1, progress: bool = True):
    """Check ``ids`` (in parallel over ``jobs`` processes), results in the order given."""
    from rich.progress import Progress

    results = {}
    with Progress(disable=not progress, transient=True,
                  console=_console(stderr=True)) as bar:
        task = bar.add_task("verifying", total=len(ids))
        if jobs > 1 and len(ids) > 1:
            import multiprocessing as mp

            ctx = mp.get_context("fork")
            # big derivations first, so the two workers finish together
            with ctx.Pool(jobs) as pool:
                for r in pool.imap_unordered(_check_one, ids):
                    results[r.id] = r
                    bar.update(task, advance=1, description=f"verified ({r.id})")
        else:
            for i in ids:
                results[i] = _check_one(i)
                bar.update(task, advance=1, description=f"verified ({i})")
    return [results[i] for i in ids]


def _console(stderr: bool = False):
    from rich.console import Console
    return Console(stderr=stderr, width=120 if not sys.stdout.isatty() else None)


def _table(results) -> None:
    from rich.table import Table

    t = Table(title="rigidsym verify")
    for col in ("id", "title", "verdict", "method", "seconds"):
        t.add_column(col)
    for r in results:
        style = "" if r.verdict == r.expected else "bold red"
        v = r.verdict if r.verdict == r.expected else f"{r.verdict} (expected {r.expected})"
        t.add_row(r.id, r.title[:48], v, r.method, f"{r.seconds:.2f}", style=style)
    _console().print(t)


def cmd_verify(args) -> int:
    """``rigidsym verify``: decide equations, print a table, optionally write JSON."""
    ids = select_with_modules(args.ids, args.section, args.module)
    t0 = time.perf_counter()
    results = run_checks(ids, jobs=args.jobs, progress=not args.quiet)
    wall = time.perf_counter() - t0
    if not args.quiet:
        _table(results)
    from .report import summary, to_json
    if args.json:
        from .io import write_atomic
        write_atomic(args.json, to_json(results))
    off = [r for r in results if r.verdict != r.expected]
    s = summary(results)
    print(f"{len(results)} checked in {wall:.1f} s: "
          + ", ".join(f"{k} {v}" for k, v in s.items()))
    for r in off:
        print(f"MISMATCH ({r.id}): computed {r.verdict}, expected {r.expected}: {r.detail}")
    return 1 if off else 0


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


def cmd_report(args) -> int:
    """``rigidsym report``: write ``chapter3.{md,json,html}`` and the exercises to ``--out``."""
    if args.module:  # a user module's report: titled by it, files named after it
        return write_user_report(args.module, Path(args.out) if args.out else Path.cwd(),
                                 args.jobs)
    from .io import write_atomic
    from .report import to_json, to_markdown
    from .report_html import to_html
    ids = select(None, None)
    results = run_checks(ids, jobs=args.jobs, progress=True)
    out = Path(args.out) if args.out else default_report_dir()
    written = [write_atomic(out / "chapter3.md", to_markdown(results)),
               write_atomic(out / "chapter3.json", to_json(results, timings=False)),
               write_atomic(out / "chapter3.html", to_html(results))]
    if args.full:  # expanded values: never over the lean, committed files
        written += [write_atomic(out / "chapter3-full.md", to_markdown(results, full=True)),
                    write_atomic(out / "chapter3-full.json",
                                 to_json(results, timings=False, full=True))]
    for hook in REPORT_HOOKS:
        written += hook(out) or []
    where = os.path.relpath(out) if not os.path.relpath(out).startswith("..") else str(out)
    print(f"wrote {len(written)} files to {where}{os.sep}: "
          + ", ".join(sorted(Path(p).name for p in written)))
    return 1 if any(r.verdict != r.expected for r in results) else 0


#: functions ``(out_dir: Path) -> list[Path]`` that add files to the report (exercises,
#: figures) and return the paths they wrote.
REPORT_HOOKS: list[Callable] = []


def cmd_show(args) -> int:
    """``rigidsym show ID``: one equation explained (verdict, members, counterexample, cause,
    corrected form, singular set) in book notation; ``--latex`` or ``--json`` instead."""
    import json

    from . import notation
    from .checker import check
    from .report import result_record
    from .show import explain, output_width
    width = output_width()
    for k, eq_id in enumerate(select_with_modules([args.id], None, args.module)):
        eq = REGISTRY[eq_id]
        st = eq.build()
        r = check(eq_id)
        if args.json:
            print(json.dumps(result_record(r), indent=1, ensure_ascii=False))
            continue
        if args.latex:
            print(f"% ({eq.id}) {eq.title}; printed:\n{eq.latex}")
            for role, rels in (("printed", st.printed), ("claim", st.claims),
                               ("corrected", st.corrected or [])):
                for rel in rels:
                    print(f"% {role}{': ' + rel.label if rel.label else ''}\n"
                          f"{notation.latex(rel.lhs)} = {notation.latex(rel.rhs)}")
            continue
        mod = sys.modules[eq.module]
        src = inspect.getsourcefile(getattr(mod, eq.function.split(".")[0]))
        where = f"{eq.function} of {eq.module} ({os.path.relpath(src)})"
        if k:
            print("\n" + "-" * min(width, 40) + "\n")
        print(explain(r, {"printed": st.printed, "claim": st.claims,
                          "corrected": st.corrected or []}, where, width))
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser (sub-commands verify, report, show and registered extras)."""
    p = argparse.ArgumentParser(prog="rigidsym", description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)
    jobs = min(2, os.cpu_count() or 1)
    v = sub.add_parser("verify", help="decide equations of chapter 3")
    v.add_argument("ids", nargs="*", help="ids like 3.16, 3.96 (all parts), thm3.2.1")
    v.add_argument("--section", action="append", help="3.2 ... 3.8 (repeatable)")
    v.add_argument("--json", help="write the results as JSON to this path")
    v.add_argument("--jobs", type=int, default=jobs, help=f"worker processes (default {jobs})")
    v.add_argument("--quiet", action="store_true", help="no progress bar or table")
    v.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=_MODULE_HELP + "; only its ids unless ids or sections are given")
    v.set_defaults(func=cmd_verify)
    r = sub.add_parser("report", help="write the chapter report (Markdown, JSON, HTML)")
    r.add_argument("--out", default=None,
                   help="output folder (default: generated/report/ at the root of a rigidsym "
                        "source tree, else ./rigidsym-report/)")
    r.add_argument("--full", action="store_true",
                   help="also write chapter3-full.{md,json} with the expanded values")
    r.add_argument("--jobs", type=int, default=jobs)
    r.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=_MODULE_HELP + ": report its ids into --out as <module>.{md,json,html}")
    r.set_defaults(func=cmd_report)
    s = sub.add_parser("show", help="explain one equation (verdict, why, counterexample)")
    s.add_argument("id")
    s.add_argument("--module", action="append", metavar="PATH_OR_DOTTED", help=_MODULE_HELP)
    fmt = s.add_mutually_exclusive_group()
    fmt.add_argument("--latex", action="store_true", help="print the members as LaTeX")
    fmt.add_argument("--json", action="store_true", help="print the schema-2 record")
    s.set_defaults(func=cmd_show)
    for name, (add_args, run) in sorted(COMMANDS.items()):
        c = sub.add_parser(name, help=(run.__doc__ or "").splitlines()[0])
        add_args(c)
        c.set_defaults(func=run)
    return p


def _load_extensions() -> None:
    """Import optional command modules (code generation, exercises) if present."""
    import importlib
    for mod in ("rigidsym.codegen.cli", "rigidsym.derivations.exercises.cli"):
        try:
            importlib.import_module(mod)
        except ModuleNotFoundError as exc:
            if exc.name is None or not mod.startswith(exc.name):
                raise


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``rigidsym`` command; returns the exit code."""
    _load_extensions()
    parser = build_parser()

    def _error(message):  # argparse errors are bad input: one line, exit 2
        print(f"rigidsym: error: {message}", file=sys.stderr)
        raise SystemExit(2)

    parser.error = _error
    for sp_ in parser._subparsers._group_actions[0].choices.values():
        sp_.error = _error
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except BadInput as exc:
        print(f"rigidsym: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # `rigidsym exercise 3.10 | head`: the reader left, not an error
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
