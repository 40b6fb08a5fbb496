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

__all__ = ["export", "certificate_field", "certify_line", "all_checked"]


def _make(job: tuple) -> tuple[str, dict | str]:
    eq_id, verdict, members, reading = job
    return eq_id, certificate_or_reason(eq_id, verdict, members, reading)


def _keyed(key: str | None, reading: str | None) -> str | None:
    """A certificate's store key, the reader's reading file's bytes joined to it (a user
    id's table is the reading's lines: another reading, another certificate)."""
    if key is None or reading is None:
        return key
    import hashlib
    from pathlib import Path

    return hashlib.sha256(key.encode() + b"\0" + Path(reading).read_bytes()).hexdigest()


def export(results, directory, book: str | None = None, jobs: int = 1, cache: bool = True,
           progress: bool = True, reading: str | None = None) -> dict:
    """Write and re-check the certificates of ``results`` into ``directory``.

    Args:
        results: outcomes of :func:`rigidsym.checking.runner.run_checks`.
        directory: the folder (created).
        book: the book's text file, bound into the manifest and passed to certcheck.
        jobs: worker processes for the certificates not stored (1: in this process).
        cache: read and store certificates in the verdict store (``False``:
            ``--no-cache``, every certificate made anew and nothing stored).
        progress: a progress line per tenth of the certificates made (stderr).
        reading: the reading file of a reader's own text: the user ids' symbol tables are
            its lines, its SHA-256 goes into the manifest and certcheck is given it as
            ``--reading`` (``None``: the book's reading for a run of the book's ids).

    Returns:
        :func:`~rigidsym.checking.certifying.certificates.write_certificates`' summary.
    """
    decided = [r for r in results if r.verdict != "undecided"]
    deps: dict = {}
    keys = {r.id: _keyed(verdict_cache.certificate_key(r.id, r.verdict, r.members, deps),
                         reading)
            for r in decided} if cache else {}
    made = {i: c for i, k in keys.items() if k and (c := verdict_cache.read_certificate(i, k))}
    todo = [(r.id, r.verdict, r.members, reading) for r in decided if r.id not in made]
    with Reporter("rigidsym verify", enabled=progress) as rep:
        with rep.phase(f"certificates of {len(todo)} ids", total=len(todo)) as ph:
            for eq_id, cert in _made(todo, jobs):
                made[eq_id] = cert
                if keys.get(eq_id):
                    verdict_cache.store_certificate(eq_id, keys[eq_id], cert)
                ph.advance(1, eq_id)
            ph.finish(f"{len(todo)} made, {len(decided) - len(todo)} from the verdict store")
        summary = write_certificates(results, directory, book=book, made=made,
                                     reading=reading)
        if summary["written"]:
            with rep.phase(f"certcheck on {len(summary['written'])} certificates") as ph:
                summary.update(recheck_folder(directory, {certificate_file(i): i for i in
                                                          summary["written"]}, book, jobs,
                                              reading=summary.get("reading")))
                ph.finish("certcheck not found: not re-checked" if summary["rechecked"] is None
                          else f"certcheck FAILED on {len(summary['failures'])}"
                          if summary["failures"] else
                          f"proved; {len(summary['not_read'])} not read from the page on "
                          "every side" if summary.get("not_read") else "re-checked")
    return summary


def all_checked(summary: dict) -> bool:
    """Whether certcheck printed ``CHECKED (id)`` for every certificate written (each
    proved, bound to the page and the reading, every printed side read) and exited 0."""
    return summary.get("exit") == 0 and bool(summary["written"]) and \
        set(summary.get("checked") or ()) == set(summary["written"])


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


def certify_line(summary: dict, directory, bound: bool = False) -> str:
    """One line on what was written and re-checked (``rigidsym verify --certificates``).

    Args:
        summary: :func:`export`'s summary.
        directory: the folder, as the user named it.
        bound: the run is bound to a reader's own text and reading (``--book`` and
            ``--reading`` with ``--module``): the line says whether every certificate is
            ``CHECKED`` (:func:`all_checked`), and names those that are not.
    """
    s = f"certificates: {len(summary['written'])} written to {directory}"
    if summary["skipped"]:
        s += f", {len(summary['skipped'])} ids without one (SKIPPED.txt)"
    if summary["rechecked"] is None:
        return s + "; certcheck not found, not re-checked (pip install ./certcheck)"
    if bound:
        n, k = len(summary["written"]), len(set(summary.get("checked") or ()))
        s += (f"; certcheck CHECKED {k} of {n} (each bound to the text and the reading, every "
              "printed side read from the text)" if all_checked(summary) else
              f"; NOT CHECKED: certcheck CHECKED {k} of {n} (exit {summary.get('exit')}), "
              f"{len(summary['failures'])} failed, {len(summary.get('not_read') or {})} not "
              "read from the text on every side")
        for i, why in (summary.get("not_read") or {}).items():
            s += f"\n  certcheck NOT READ ({i}): {why}"
        for i, why in summary["failures"].items():
            s += f"\n  certcheck FAILED ({i}): {why}"
        return s
    ok = sum(summary["rechecked"].values())
    s += f"; certcheck re-checked {ok} of {len(summary['rechecked'])}"
    if summary.get("not_read"):
        s += (f", {len(summary['not_read'])} of them not read from the page on every side "
              "(the certificate's word there)")
    for i, why in summary["failures"].items():
        s += f"\n  certcheck FAILED ({i}): {why}"
    return s
