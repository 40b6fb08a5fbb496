"""The parallel runner: check ids over worker processes, with a progress display."""

from __future__ import annotations

import sys

__all__ = ["run_checks"]


def _check_one(eq_id: str):
    from rigidsym.checking.checker import check
    return check(eq_id)


def run_checks(ids: list[str], jobs: int = 1, progress: bool = True, cache: bool = False):
    """Check ``ids`` (in parallel over ``jobs`` processes), results in the order given.

    With ``cache``, results are read from the verdict cache where their key matches
    (:mod:`rigidsym.checking.verdict_cache`; ``Result.cached`` is then true) and the others
    are computed and stored.
    """
    from rich.progress import Progress

    hits, keys = ({}, {})
    if cache:
        from rigidsym.checking import verdict_cache
        hits, keys = verdict_cache.lookup(ids)
    results = dict(hits)
    todo = [i for i in ids if i not in hits]
    with Progress(disable=not progress, transient=True,
                  console=_console(stderr=True)) as bar:
        task = bar.add_task("verifying", total=len(ids), completed=len(hits))
        if jobs > 1 and len(todo) > 1:
            import multiprocessing as mp

            ctx = mp.get_context("fork")
            with ctx.Pool(min(jobs, len(todo))) as pool:
                for r in pool.imap_unordered(_check_one, todo):
                    results[r.id] = r
                    bar.update(task, advance=1, description=f"verified ({r.id})")
        else:
            for i in todo:
                results[i] = _check_one(i)
                bar.update(task, advance=1, description=f"verified ({i})")
    if cache and todo:
        verdict_cache.store([results[i] for i in todo], keys)
    return [results[i] for i in ids]


def _console(stderr: bool = False):
    from rich.console import Console
    return Console(stderr=stderr, width=120 if not sys.stdout.isatty() else None)
