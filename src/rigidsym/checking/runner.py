"""The parallel runner: check ids over worker processes, with a progress display."""

from __future__ import annotations

import sys

__all__ = ["run_checks"]


def _check_one(eq_id: str):
    from rigidsym.checking.checker import check
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
