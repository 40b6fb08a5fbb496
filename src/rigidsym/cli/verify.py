"""``rigidsym verify``: decide equations, print a table, optionally write JSON."""

from __future__ import annotations

import sys
import time

from rigidsym.cli.common import (
    FORMATS,
    JOBS,
    MODULE_HELP,
    add_repair_arguments,
    console,
    output_format,
    repair_options,
)
from rigidsym.core.files import write_atomic
from rigidsym.printing.labels import label_text
from rigidsym.registry.usermodules import select_with_modules

__all__ = ["add_arguments", "run"]

HELP = "decide the chapter's equations (or yours, with --module)"
EXAMPLES = """\
  rigidsym verify                         all 181 ids of the chapter (timed by benchmarks/verify.py)
  rigidsym verify 3.96 --section 3.8      every part of (3.96), and section 3.8
  rigidsym verify --module my_eqs.py      your own equations
  rigidsym verify --format json > v.json  the schema-2 document on stdout
  rigidsym verify --certificates certs    a certificate per id, re-checked by certcheck
                                          (docs/certificates.md)
  rigidsym verify --certificates certs --book ../shared/book/angeles-chapter3.md
                                          ... each bound to its printed text, one run
  rigidsym verify --module examples/rotation_notes.py --certificates certs \\
      --book examples/rotation_notes.md --reading examples/rotation_notes.reading.toml
                                          your module's, bound to your text and reading:
                                          exit 1 unless certcheck CHECKED every one"""


def add_arguments(v) -> None:
    """Arguments of ``rigidsym verify``."""
    v.add_argument("ids", nargs="*",
                   help="ids like 3.16, 3.96 (all its parts), thm3.2.1 (default: the whole "
                        "chapter, or the --module's ids)")
    v.add_argument("--section", action="append", metavar="S",
                   help="a section of the book (repeatable; one it does not have is "
                        "refused, naming those it has; default: none)")
    v.add_argument("--json", metavar="PATH",
                   help="also write the results (JSON schema 2) to this file (default: none)")
    v.add_argument("--format", choices=FORMATS,
                   help="what goes to stdout: a table, plain text lines (never cut) or the "
                        "JSON document (default: table on a terminal, plain in a pipe)")
    v.add_argument("--jobs", type=int, default=JOBS, metavar="N", help="worker processes")
    v.add_argument("--quiet", action="store_true",
                   help="no progress and no table, only the summary line (default: off)")
    v.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + "; only its ids unless ids or sections are given "
                                      "(default: none)")
    v.add_argument("--no-cache", action="store_true",
                   help="check every id again; neither read nor write the verdict cache "
                        "(default: off, the cache is used)")
    v.add_argument("--certificates", metavar="DIR",
                   help="write a certificate per decided id into DIR (docs/certificates.md) "
                        "and re-check them with the independent checker certcheck when it "
                        "is found (default: none)")
    v.add_argument("--coq", metavar="DIR",
                   help="write a Coq file per certificate Coq can be given into DIR "
                        "(eq3_16.v: the identities' lemmas, a does-not-hold's counterexample "
                        "lemmas) and NO-PROOF.txt with the others and why; check them with "
                        "coqc (docs/certificates.md) (default: none)")
    v.add_argument("--book", metavar="FILE",
                   help="with --certificates: the book's text (Markdown with LaTeX; the "
                        "referee's copy, never shipped): its SHA-256 goes into the folder's "
                        "MANIFEST.json and certcheck binds each certificate to the text "
                        "printed as its id (default: none)")
    v.add_argument("--reading", metavar="FILE",
                   help="with --certificates and --module: the reading of your text (TOML, "
                        "docs/own-equations.md): your ids' symbol tables and classes are its "
                        "lines, certcheck holds them to it, and the run exits 1 unless "
                        "certcheck CHECKED every certificate (default: with --book, the "
                        "reading beside the text, TEXT.reading.toml, when there is one)")
    add_repair_arguments(v)


def _table(results) -> None:
    from rich.table import Table

    t = Table(title="rigidsym verify")
    for col in ("id", "title", "verdict", "method", "seconds"):
        t.add_column(col, overflow="fold")
    for r in results:
        style = "" if r.verdict == r.expected else "bold red"
        v = r.verdict if r.verdict == r.expected else f"{r.verdict} (expected {r.expected})"
        secs = "cached" if getattr(r, "cached", False) else f"{r.seconds:.2f}"
        t.add_row(r.id, label_text(r.title), v, r.method, secs, style=style)
    console().print(t)


def _plain(results) -> None:
    """One line per id, columns aligned, nothing cut (for pipes, logs and grep)."""
    rows = [(r.id, r.verdict if r.verdict == r.expected else
             f"{r.verdict} (EXPECTED {r.expected})", r.method,
             "cached" if getattr(r, "cached", False) else f"{r.seconds:.2f}",
             label_text(r.title)) for r in results]
    head = ("id", "verdict", "method", "seconds", "title")
    w = [max(len(x[k]) for x in [head, *rows]) for k in range(4)]
    for row in [head, *rows]:
        print("  ".join(x.ljust(w[k]) for k, x in enumerate(row[:4])) + "  " + row[4])


def _repairs(results) -> None:
    """One line per failing member: its first repair (``rigidsym show ID`` lists them all)."""
    for r in results:
        for s in getattr(r, "repair_search", None) or []:
            who = f"({r.id})" + (f" {label_text(s['member'])}" if s["member"] else "")
            first = next((x for x in r.repairs if x["member"] == s["member"]), None)
            if first is None:
                print(f"{who}: {s['words']}")
                continue
            tag = ", the declared correction" if first["equals_declared"] else ""
            print(f"{who}: repair ({'; then '.join(first['edits'])}{tag}): {first['text']}")


def _undecided(results, off) -> None:
    """Why each undecided result is undecided (a mismatch says it in its own line)."""
    from rigidsym.report.markdown import undecided_reasons

    for r in results:
        if r.verdict == "undecided" and r.id not in {o.id for o in off}:
            for why in undecided_reasons({"members": r.members, "verdict": r.verdict,
                                          "decision": r.detail}):
                print(f"({r.id}) undecided: {label_text(why)}")


def _document(results, certified) -> str:
    """The JSON document; with ``--certificates``, each record says whether its verdict is
    certified and re-checked (``"certificate"``, docs/certificates.md)."""
    from rigidsym.report.record import dumps, to_json

    text = to_json(results)
    if certified is None:
        return text
    import json

    from rigidsym.checking.export import certificate_field

    doc = json.loads(text)
    for row in doc["equations"]:
        row["certificate"] = certificate_field(certified, row["id"])
    return dumps(doc) + "\n"


def _coq(results, cert_dir, certified, coq_dir) -> str:
    """Write the Coq files of the decided results (from the certificates just written, or
    made here); one line on what was written."""
    import json
    from pathlib import Path

    from rigidsym.checking.certifying.certificates import (
        Unprintable,
        certificate,
        certificate_file,
    )
    from rigidsym.checking.certifying.coq_export import write_coq_folder

    certs, none = {}, {}
    for r in results:
        if r.verdict == "undecided":
            none[r.id] = "undecided: no certificate"
        elif certified is not None:
            if r.id in certified["written"]:
                certs[r.id] = json.loads((Path(cert_dir) / certificate_file(r.id)).read_text())
            else:
                none[r.id] = f"no certificate: {certified['skipped'].get(r.id, '')}"
        else:
            try:
                certs[r.id] = certificate(r.id, r.verdict, r.members)
            except (Unprintable, ValueError) as exc:
                none[r.id] = f"no certificate: {exc}"
    done = write_coq_folder(certs, coq_dir, extra_none=none)
    return (f"coq: {len(done['written'])} files written to {coq_dir} (check each with "
            f"coqc -q FILE), {len(done['none'])} ids without one (NO-PROOF.txt)")


def _check_book(args) -> None:
    """``--book`` only with ``--certificates``, and a file.

    Raises:
        rigidsym.core.errors.BadInput: either is not so (names ``--book``).
    """
    if args.book is None:
        return
    from pathlib import Path

    from rigidsym.core.errors import BadInput

    if not args.certificates:
        raise BadInput("--book: only with --certificates DIR (it binds the certificates "
                       "to the page)")
    if not Path(args.book).is_file():
        raise BadInput(f"--book: expected the book's text file, got {args.book!r}")


def run(args) -> int:
    """``rigidsym verify``: decide equations, print a table, optionally write JSON."""
    from rigidsym.checking.export import all_checked
    from rigidsym.checking.runner import run_checks  # sympy: after the parser
    from rigidsym.registry.declarations import is_user_id
    from rigidsym.report.record import cause_line, summary, transcription_extra

    _check_book(args)
    ids = select_with_modules(args.ids, args.section, args.module)
    reading = _user_reading(args, ids, is_user_id)
    fmt = output_format(args)
    # a JSON document carries the transcription records: computed beside the verdicts in
    # the workers that build the declarations, never built again here
    extra = transcription_extra() if args.json or fmt == "json" else None
    t0 = time.perf_counter()
    results = run_checks(ids, jobs=args.jobs, progress=not args.quiet,
                         cache=not args.no_cache, expanded=False, extra=extra,
                         **repair_options(args))
    wall = time.perf_counter() - t0
    certified = None
    # a reader's module bound to their text: only CHECKED certificates pass (fail closed)
    bound = bool(args.certificates) and (reading is not None or (
        args.book is not None and any(is_user_id(i) for i in ids)))
    if args.certificates:
        from rigidsym.checking.export import certify_line, export

        certified = export(results, args.certificates, book=args.book, jobs=args.jobs,
                           cache=not args.no_cache, progress=not args.quiet, reading=reading)
        print(certify_line(certified, args.certificates, bound=bound), file=sys.stderr)
    if args.coq:
        print(_coq(results, args.certificates, certified, args.coq), file=sys.stderr)
    if args.json:
        write_atomic(args.json, _document(results, certified))
    off = [r for r in results if r.verdict != r.expected]
    s = summary(results)
    hits = "" if args.no_cache else \
        f" ({sum(bool(getattr(r, 'cached', False)) for r in results)} from the cache)"
    line = (f"{len(results)} checked in {wall:.1f} s{hits}: "
            + ", ".join(f"{k} {v}" for k, v in s.items()))
    book = [r for r in results if not is_user_id(r.id)]   # origins are the book's words
    if book and summary(book)["does-not-hold"]:
        line += (f"; of the book's equations, {summary(book)['does-not-hold']} do not hold "
                 f"as printed: {cause_line(book)}")
    unchecked = bound and certified is not None and bool(certified["written"]) and \
        not all_checked(certified)
    if unchecked:
        line += ("; certificates NOT CHECKED by certcheck (" + (
            "certcheck not found" if certified["rechecked"] is None else
            f"{len(set(certified.get('checked') or ()))} of {len(certified['written'])} "
            f"CHECKED, certcheck exit {certified.get('exit')}") + ")")
    elif bound and certified is not None and certified["written"]:
        line += (f"; certificates: certcheck CHECKED {len(certified['written'])} of "
                 f"{len(certified['written'])} against the text and the reading")
    if fmt == "json":  # stdout is the document; the words go to stderr
        sys.stdout.write(_document(results, certified))
        print(line, file=sys.stderr)
        return 1 if off or unchecked else 0
    if not args.quiet:
        (_table if fmt == "table" else _plain)(results)
        _repairs(results)
        _undecided(results, off)
    print(line)
    for r in off:
        print(f"MISMATCH ({r.id}): computed {r.verdict}, expected {r.expected}: {r.detail} "
              f"(rigidsym show {r.id} explains it)")
    if any(r.verdict == "does-not-hold" for r in results) and not args.quiet:
        whose = "the book's" if any(not is_user_id(r.id) for r in results
                                    if r.verdict == "does-not-hold") else "its own"
        print(f"Why an equation does not hold, in {whose} symbols: rigidsym show ID")
    if certified is not None and certified["written"] and (
            certified["rechecked"] is None or certified["failures"] or unchecked):
        return 1   # a certificate certcheck rejected, or none re-checked: never a pass
    return 1 if off else 0


def _user_reading(args, ids: list[str], is_user_id) -> str | None:
    """The reading file of the reader's text the run's user ids are bound to: ``--reading``,
    or with ``--book`` and a module's ids, the reading beside the text
    (``TEXT.reading.toml``, :func:`rigidsym.reading.sidecar`) when there is one; ``None``
    for a run of the book's ids.

    Raises:
        BadInput: ``--reading`` without ``--certificates``, not a readable reading file, or
            given for a run that holds the book's ids (their reading is the book's).
    """
    from pathlib import Path

    from rigidsym.core.errors import BadInput
    from rigidsym.reading import load_reading, sidecar

    path = args.reading
    if path is None:
        beside = sidecar(args.book) if args.book is not None else None
        if beside is None or not beside.is_file() or not any(is_user_id(i) for i in ids):
            return None
        path = str(beside)
    elif not args.certificates:
        raise BadInput("--reading: only with --certificates DIR (the certificates' symbol "
                       "tables are its lines)")
    book_ids = [i for i in ids if not is_user_id(i)]
    if book_ids:
        raise BadInput(f"--reading: the reading of your own text, for a --module's ids; the "
                       f"run holds the book's ids too ({', '.join(book_ids[:3])}"
                       f"{', ...' if len(book_ids) > 3 else ''}), whose reading is the book's: "
                       "certify them in a run of their own")
    if not Path(path).is_file():
        raise BadInput(f"--reading: expected a reading file (TOML), got {path!r}")
    try:
        load_reading(path)
    except BadInput as exc:
        raise BadInput(f"--reading: {exc}") from None
    return path
