"""The export of a run's certificates (``rigidsym verify --certificates DIR``): each decided
id's certificate read from the verdict store where its key matches
(:func:`rigidsym.checking.verdict_cache.certificate_key`), the others made over worker
processes and stored, then written, with the folder's manifest, and re-checked by certcheck
(:func:`rigidsym.checking.certifying.certificates.write_certificates`). A certificate is a
function of what its key covers (the package's source, the declaration, the verdict and the
members' statuses; its counterexample search is seeded by the id), so a stored one is the
one the run would make (``tests/test_certificate_store.py`` compares the two), but for the
cofactor search's CPU-time budget: a relation past it on a loaded machine gets the
re-computation evidence instead, which certcheck checks as well, and the store keeps the
certificate made first.
"""

from __future__ import annotations

from rigidsym.checking import verdict_cache
from rigidsym.checking.certifying.certificates import (
    certificate_file,
    certificate_or_reason,
    recheck_folder,
    write_certificates,
)
from rigidsym.core.progress import Reporter

__all__ = ["export", "certificate_field", "certify_line"]


def _make(job: tuple) -> tuple[str, dict | str]:
    eq_id, verdict, members = job
    return eq_id, certificate_or_reason(eq_id, verdict, members)


def export(results, directory, book: str | None = None, jobs: int = 1, cache: bool = True,
           progress: bool = True) -> dict:
    """Write and re-check the certificates of ``results`` into ``directory``.

    Args:
        results: outcomes of :func:`rigidsym.checking.runner.run_checks`.
        directory: the folder (created).
        book: the book's text file, bound into the manifest and passed to certcheck.
        jobs: worker processes for the certificates not stored (1: in this process).
        cache: read and store certificates in the verdict store (``False``:
            ``--no-cache``, every certificate made anew and nothing stored).
        progress: a progress line per tenth of the certificates made (stderr).

    Returns:
        :func:`~rigidsym.checking.certifying.certificates.write_certificates`' summary.
    """
    decided = [r for r in results if r.verdict != "undecided"]
    deps: dict = {}
    keys = {r.id: verdict_cache.certificate_key(r.id, r.verdict, r.members, deps)
            for r in decided} if cache else {}
    made = {i: c for i, k in keys.items() if k and (c := verdict_cache.read_certificate(i, k))}
    todo = [(r.id, r.verdict, r.members) for r in decided if r.id not in made]
    with Reporter("rigidsym verify", enabled=progress) as rep:
        with rep.phase(f"certificates of {len(todo)} ids", total=len(todo)) as ph:
            for eq_id, cert in _made(todo, jobs):
                made[eq_id] = cert
                if keys.get(eq_id):
                    verdict_cache.store_certificate(eq_id, keys[eq_id], cert)
                ph.advance(1, eq_id)
            ph.finish(f"{len(todo)} made, {len(decided) - len(todo)} from the verdict store")
        summary = write_certificates(results, directory, book=book, made=made)
        if summary["written"]:
            with rep.phase(f"certcheck on {len(summary['written'])} certificates") as ph:
                summary.update(recheck_folder(directory, {certificate_file(i): i for i in
                                                          summary["written"]}, book, jobs,
                                              reading=summary.get("reading")))
                ph.finish("certcheck not found: not re-checked" if summary["rechecked"] is None
                          else "re-checked" if not summary["failures"] else
                          f"certcheck FAILED on {len(summary['failures'])}")
    return summary


def _made(todo: list, jobs: int):
    """``(id, certificate or reason)`` of each job, over ``jobs`` fork workers (one id a
    task, as they finish) or in this process."""
    if jobs > 1 and len(todo) > 1:
        import multiprocessing as mp

        from rigidsym.core import interrupts

        with mp.get_context("fork").Pool(min(jobs, len(todo)),
                                         initializer=interrupts.for_worker) as pool:
            yield from pool.imap_unordered(_make, todo)
    else:
        yield from map(_make, todo)


def certificate_field(summary: dict, eq_id: str) -> dict:
    """The ``certificate`` member of an id's JSON record (``verify --certificates --json``):
    ``{"file", "evidence", "rechecked"}``, or ``{"file": None, "why"}``."""
    if eq_id in summary["skipped"]:
        return {"file": None, "why": summary["skipped"][eq_id]}
    rechecked = summary["rechecked"]
    return {"file": certificate_file(eq_id), "evidence": summary["evidence"].get(eq_id, []),
            "rechecked": None if rechecked is None else rechecked.get(eq_id)}


def certify_line(summary: dict, directory) -> str:
    """One line on what was written and re-checked (``rigidsym verify --certificates``)."""
    s = f"certificates: {len(summary['written'])} written to {directory}"
    if summary["skipped"]:
        s += f", {len(summary['skipped'])} ids without one (SKIPPED.txt)"
    if summary["rechecked"] is None:
        return s + "; certcheck not found, not re-checked (pip install ./certcheck)"
    ok = sum(summary["rechecked"].values())
    s += f"; certcheck re-checked {ok} of {len(summary['rechecked'])}"
    if summary.get("not_read"):
        s += (f", {len(summary['not_read'])} of them not read from the page on every side "
              "(the certificate's word there)")
    for i, why in summary["failures"].items():
        s += f"\n  certcheck FAILED ({i}): {why}"
    return s
