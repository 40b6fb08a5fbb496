"""``python -m certcheck [--book BOOK] [--reading READING] [--jobs N] [--lenient]
[--no-flint] [--quiet] PATH...``: check certificates (files, or every ``*.json`` of a
folder; over N processes with ``--jobs``, the same output in the same order); with
``--book``, each against the text printed as its id (a document's relation: its label, or
its line, ``line:L``; certcheck.document) and against its folder's ``MANIFEST.json``; with
``--reading``, each id's symbol table and class as the reading file gives them (a
certificate supplies evidence only); print the hypotheses, the printed text, the symbols,
a cause and a verdict per id. Exit 0: every certificate proved and every printed side read
from the page under the reading; 1: a certificate fails; 2: bad arguments; 3: nothing
fails, but a printed side is not read from the page (or no ``--book``, or no
``--reading``): 0 with ``--lenient``."""

from __future__ import annotations

import argparse
import functools
import json
import os
import re
import sys
import time

from certcheck.book import (
    BookError,
    cause_lines,
    check_manifest,
    check_page,
    definitions_before,
    locate,
)
from certcheck.braces import displays_after
from certcheck.by_definition import page_class, unread_vacuous
from certcheck.check import CheckError, check_certificate, load
from certcheck.compare import compare
from certcheck.document import bind_document, document_id, printed
from certcheck.limits import cpu_limit
from certcheck.reading import ReadingError, bind, load_reading
from certcheck.words import said, stated, use

#: the largest certificate file read (bytes; the chapter's largest is 0.36 MB)
MAX_BYTES = 4_000_000


def _files(paths: list[str]) -> list[str]:
    out = []
    for p in paths:
        if os.path.isdir(p):
            out += sorted(os.path.join(p, f) for f in os.listdir(p)
                          if f.endswith(".json") and f != "MANIFEST.json")
        else:
            out.append(p)
    return out


def _manifests(paths, files, book_bytes, reading=None) -> tuple[int, list[str]]:
    """Check each folder's manifest (a file's folder too, for the files given): required
    with a book, else where present."""
    failed, lines = 0, []
    folders = {os.path.dirname(f) or "." for f in files if not os.path.isdir(f)} | \
        {p.rstrip(os.sep) for p in paths if os.path.isdir(p)}
    for p in sorted(folders):
        if book_bytes is None and not os.path.exists(os.path.join(p, "MANIFEST.json")):
            lines.append(f"NOTE {p}: no MANIFEST.json; the folder is not bound to one run")
            continue
        mine = [f for f in files if (os.path.dirname(f) or ".") == p]
        try:
            lines += check_manifest(p, mine, book_bytes, whole=p in paths
                                    or p + os.sep in paths,
                                    reading=None if reading is None else reading["sha256"])
        except BookError as exc:
            failed += 1
            lines.append(f"FAILED MANIFEST.json of {p}: {exc}")
    return failed, lines


def _one(path: str, book: str | None, fast: bool, quiet: bool,
         reading: dict | None = None) -> tuple[str, int, int]:
    """One certificate file checked: ``(its output lines, n printed sides, k of them read)``,
    ``n = -1`` where it failed."""
    t = time.perf_counter()
    try:
        if os.path.getsize(path) > MAX_BYTES:
            raise ValueError(f"larger than {MAX_BYTES} bytes (certcheck's limit on one "
                             "certificate)")
        with cpu_limit():
            return _bounded(path, book, fast, quiet, reading, t)
    except (CheckError, BookError, ReadingError, OSError, ValueError) as exc:
        return f"FAILED {os.path.basename(path)}: {exc}", -1, 0
    except RecursionError:
        return (f"FAILED {os.path.basename(path)}: nested beyond what certcheck follows "
                "(its limits: docs/certificates.md)", -1, 0)
    except Exception as exc:  # a malformed certificate is a failure, never a pass
        return f"FAILED {os.path.basename(path)}: {type(exc).__name__}: {exc}", -1, 0


def _bounded(path: str, book: str | None, fast: bool, quiet: bool, reading: dict | None,
             t: float) -> tuple[str, int, int]:
    """:func:`_one` under certcheck's CPU limit."""
    cert = load(path)
    rel = None  # a document's relation: located, classed and read by certcheck.document
    if document_id(cert, book, reading):
        rel, bound = bind_document(cert, book, reading)
    else:
        bound = [] if reading is None else bind(cert, reading)
    if book is not None and os.path.basename(path) != \
            re.sub(r"[^A-Za-z0-9._-]", "_", str(cert.get("id"))) + ".json":
        raise BookError(f"({cert.get('id')}): the certificate of ({cert.get('id')}) "
                        f"in the file of another id")
    page = bound + (check_page(cert, book, None if rel is None else printed(rel))
                    if book is not None else cause_lines(cert))
    verdict, lines = check_certificate(cert, fast=fast)
    k = n = 0
    if book is not None:  # the second reader: what is proved is what is printed
        eq_id = str(cert.get("id"))
        defs = definitions_before(book, eq_id) if eq_id[0].isdigit() else {}
        # a theorem in words: the relation they state; a document's relation: its sides
        text = locate(book, eq_id) if rel is None else f"{rel['lhs']} = {rel['rhs']}"
        page += said(eq_id, text) + compare(
            cert, stated(eq_id, text), fast=fast, defs=defs, counts=(counts := []),
            later=displays_after(book, eq_id), read_sides=(sides := []))
        (k, n, firm), = counts
        page += page_class(cert, verdict, sides)  # a restatement: the page's word
        vac, lines_read = unread_vacuous(cert, firm)  # vacuous: read, or not
        k, page = max(0, k - 2 * vac), page + lines_read
    else:
        n = 2 * sum(r.get("role") == "printed" for r in cert.get("relations", []))
    words = book is not None and not any(  # a theorem in words: no relation on the page
        r.get("role") == "printed" or isinstance(r.get("page"), int)
        for r in cert.get("relations", []))
    out = [(f"CHECKED ({cert.get('id')}) {verdict}" if k == n else
            f"NOT READ {os.path.basename(path)}: ({cert.get('id')}) {verdict} proved, "
            + (f"stated in words only: its claims' {n - k} sides are the certificate's "
               "reading of the words, not read from the page" if words else
               f"{n - k} of {n} printed sides not read from the page (the certificate's "
               "word)")) + f"  [{time.perf_counter() - t:.2f} s]"]
    if not quiet:
        out += [f"    {line}" for line in page + lines]
    return "\n".join(out), n, k


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["explain"]:
        from certcheck.explain import run
        return run(argv[1:])
    ap = argparse.ArgumentParser(prog="certcheck", description=__doc__.split("\n\n")[0])
    ap.add_argument("paths", nargs="+", help="certificate files or folders of them")
    ap.add_argument("--book", metavar="FILE",
                    help="the book's text (Markdown with LaTeX): bind each certificate to the "
                         "text printed as its id, and each folder to its manifest")
    ap.add_argument("--reading", metavar="FILE",
                    help="the reading of the book (TOML): each id's symbol table and class "
                         "are the reading's, the certificate supplies evidence only")
    ap.add_argument("--no-flint", action="store_true",
                    help="standard-library arithmetic only, even when python-flint is there")
    ap.add_argument("--quiet", action="store_true", help="one line per certificate")
    ap.add_argument("--jobs", type=int, default=1, metavar="N",
                    help="check the certificates over N processes (the same output, in order)")
    ap.add_argument("--lenient", action="store_true",
                    help="exit 0 when nothing fails, though a printed side is not read "
                         "(NOT READ: the certificate's word) or no --book is given")
    args = ap.parse_args(argv)
    if args.jobs < 1:
        ap.error(f"--jobs: expected a positive integer, got {args.jobs}")
    files = _files(args.paths)
    if not files:
        print("certcheck: no certificate found", file=sys.stderr)
        return 2
    book_bytes = None
    if args.book:
        try:
            with open(args.book, "rb") as f:
                book_bytes = f.read()
        except OSError as exc:
            print(f"certcheck: --book: cannot read {args.book}: {exc}", file=sys.stderr)
            return 2
    book = None if book_bytes is None else book_bytes.decode("utf-8")
    reading = None
    if args.reading:
        try:
            with open(args.reading, "rb") as f:
                reading = load_reading(f.read(), args.reading)
        except OSError as exc:
            print(f"certcheck: --reading: cannot read {args.reading}: {exc}", file=sys.stderr)
            return 2
        except ReadingError as exc:
            print(f"certcheck: --reading: {exc}", file=sys.stderr)
            return 2
    use(reading)   # the theorems in words: the reading's
    t0 = time.perf_counter()
    bad_manifests, head = _manifests(args.paths, files, book_bytes, reading)
    ids: dict = {}
    for f in files:  # one id once per run: two certificates of one id are one too many
        try:
            with open(f, "rb") as fh:
                head_id = json.loads(fh.read(MAX_BYTES + 1)).get("id") \
                    if os.path.getsize(f) <= MAX_BYTES else None
        except (OSError, ValueError, AttributeError):
            continue  # reported by its own check
        if head_id is not None and str(head_id) in ids:
            bad_manifests += 1
            head.append(f"FAILED ({head_id}): two certificates of one id in one run "
                        f"({ids[str(head_id)]} and {f})")
        ids.setdefault(str(head_id), f)
    for line in head:
        print(line)
    failed = not_read = sides = unread = 0
    one = functools.partial(_one, book=book, fast=not args.no_flint, quiet=args.quiet,
                            reading=reading)
    if args.jobs > 1 and len(files) > 1:
        import multiprocessing

        with multiprocessing.Pool(min(args.jobs, len(files))) as pool:
            results = list(pool.imap(one, files))  # in order: the output is the same
    else:
        results = map(one, files)
    for out, n, k in results:
        print(out)
        if n < 0:
            failed += 1
        else:
            sides, unread, not_read = sides + n, unread + n - k, not_read + (k < n)
    print(f"certcheck: {len(files) - failed - not_read} of {len(files)} certificates "
          f"checked (every printed side read from the page), {not_read} not read on every "
          f"side ({unread} of {sides} printed sides not read), {failed} failed, "
          f"{time.perf_counter() - t0:.1f} s"
          + (f", {bad_manifests} manifest(s) failed" if bad_manifests else "")
          + ("" if book is not None else "; not bound to the page (no --book)")
          + ("" if reading is not None else "; not bound to a reading (no --reading): each "
             "symbol table and class is the certificate's word"))
    if failed or bad_manifests:
        return 1
    return 3 if (not_read or reading is None) and not args.lenient else 0

if __name__ == "__main__":
    sys.exit(main())
