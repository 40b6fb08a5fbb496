"""``rigidsym check FILE``: every displayed relation of a document decided, its errata
printed (``docs/check-documents.md``)."""

from __future__ import annotations

import sys

from rigidsym.cli.common import repair_options

__all__ = ["run_document"]


def run_document(args) -> int:
    """Check the document ``args.file``; exit 0 all decided and none false, 1 a false
    relation, 3 some not decided (bad input: the command's ``BadInput``, exit 2); with
    ``--certificates DIR``, 4 unless certcheck CHECKED every certificate written."""
    from rigidsym.documents import check_document, exit_code
    from rigidsym.documents.report import as_json, as_markdown, as_text

    if args.book or args.module or args.certificate:
        print("rigidsym: error: --book, --module and --certificate go with --latex, not "
              "with a document FILE", file=sys.stderr)
        return 2
    if args.certificates and (args.let or args.notation):
        print("rigidsym: error: --certificates: declare each symbol in the reading file, not "
              "with --let or --notation (certcheck holds each certificate's symbol table to "
              "the reading file's lines)", file=sys.stderr)
        return 2
    if args.json and args.markdown:
        print("rigidsym: error: --json or --markdown, not both", file=sys.stderr)
        return 2
    opts = repair_options(args)

    def progress(line: str) -> None:
        print(line, file=sys.stderr, flush=True)

    res = check_document(args.file, reading=args.reading, lets=list(args.let),
                         notation=args.notation, repairs=opts["repairs"],
                         repair_seconds=args.repair_seconds,
                         timeout="default" if args.timeout is None else args.timeout,
                         progress=progress)
    print(as_json(res) if args.json else as_markdown(res) if args.markdown else as_text(res))
    if args.html:
        from rigidsym.core.files import write_atomic
        from rigidsym.documents.html import as_html

        write_atomic(args.html, as_html(res))
        print(f"errata page: {args.html}", file=sys.stderr)
    if args.certificates:
        return _certificates(res, args.certificates, exit_code(res))
    return exit_code(res)


def _certificates(res, folder: str, code: int) -> int:
    """Write and re-check the document's certificates (:func:`rigidsym.documents.
    certifying.certify_document`), say how many certcheck CHECKED and which relations are
    not certified and why (stderr); ``code``, or 4 unless every certificate is CHECKED."""
    from rigidsym.documents.certifying import certify_document

    out = certify_document(res, folder)
    written, checked = out["written"], set(out["checked"])
    for where, why in out["skipped"].items():
        print(f"not certified: {where}: {why}", file=sys.stderr)
    for eq_id, why in {**out["failures"], **out["not_read"]}.items():
        print(f"NOT CHECKED ({eq_id}) {written.get(eq_id, '')}: {why}", file=sys.stderr)
    reading = res.reading.path if res.reading is not None else None
    bound = f"{res.document.path} and {reading}" if reading else \
        f"{res.document.path} (no reading file: each table is the certificate's word)"
    line = (f"certificates: {len(written)} written to {folder}, one per decided relation; "
            f"{len(out['skipped'])} relation{'s' * (len(out['skipped']) != 1)} not certified "
            f"(listed in {folder}/SKIPPED.txt)")
    if out["rechecked"] is None and written:
        print(f"{line}; certcheck not found: NOT CHECKED", file=sys.stderr)
        return 4
    ok = bool(written) and checked >= set(written) and out["exit"] == 0
    print(f"{line}; certcheck CHECKED {len(checked & set(written))} of {len(written)} "
          f"against {bound}" + ("" if ok or not written else f" (certcheck exit {out['exit']})"),
          file=sys.stderr)
    return code if ok or not written else 4
