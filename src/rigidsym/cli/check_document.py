"""``rigidsym check FILE``: every displayed relation of a document decided, its errata
printed (``docs/check-documents.md``)."""

from __future__ import annotations

import sys

from rigidsym.cli.common import repair_options

__all__ = ["run_document"]


def run_document(args) -> int:
    """Check the document ``args.file``; exit 0 all decided and none false, 1 a false
    relation, 3 some not decided (bad input: the command's ``BadInput``, exit 2)."""
    from rigidsym.documents import check_document, exit_code
    from rigidsym.documents.report import as_json, as_markdown, as_text

    if args.book or args.module or args.certificate:
        print("rigidsym: error: --book, --module and --certificate go with --latex, not "
              "with a document FILE", file=sys.stderr)
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
    return exit_code(res)
