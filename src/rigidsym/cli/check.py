"""``rigidsym check --latex``: LaTeX in, verdict out, for anyone's equations."""

from __future__ import annotations

import sys

from rigidsym.cli.common import MODULE_HELP, add_repair_arguments, repair_options

__all__ = ["add_arguments", "run", "HELP", "EXAMPLES", "EXIT"]

HELP = "decide LaTeX: one relation (--latex) or a whole document"
EXAMPLES = r"""  rigidsym check notes.md          every displayed relation of a Markdown or LaTeX
                                   document; its symbols: notes.reading.toml beside it
  rigidsym check notes.md --html errata.html   and the errata as one offline page (MathML)
  rigidsym check notes.md --certificates certs  and a certificate per decided relation,
                                   re-checked by certcheck against notes.md and its reading
  rigidsym check --latex '\mathbf{Q}^T\mathbf{Q} = \mathbf{1}' \
      --let '\mathbf{Q}: rotation'
  rigidsym check --latex \
      '\mathbf{Q} = \mathbf{1} + \sin\phi\,\mathbf{E} + (1 - \cos\phi)\mathbf{E}^2' \
      --let '\mathbf{e}: unit vector; \phi: angle; \mathbf{E} = \mathrm{CPM}(\mathbf{e})' \
      --let '\mathbf{Q} = \mathbf{e}\mathbf{e}^T
             + \cos\phi(\mathbf{1} - \mathbf{e}\mathbf{e}^T) + \sin\phi\,\mathbf{E}'
  rigidsym check --latex '\mathbf{W}^T = -\mathbf{W}' --book 3.5   the glyph table's W of 3.5

--let NAME: KIND   KIND one of: unit vector, unit 4-vector, rotation, angle, angle in [0, pi],
                   scalar, vector, n-vector (6-vector), matrix, mxn matrix (4x4 matrix),
                   symmetric matrix, twist, wrench, transform, so(3), se(3)
--let NAME = LATEX a first-principles model in the same notation
--notation NAME    a book's symbols: lynch-park, murray-li-sastry, siciliano, spong, craig,
                   featherstone, barfoot, sola, corke, jpl
--timeout S        the CPU-time limit of the whole check (default 60 s): past it undecided, exit 3
exit codes: 0 holds (verified or definition), 1 does not hold, 3 undecided (also past
            --timeout), 2 bad input; with FILE --certificates DIR, 4 when certcheck did not
            CHECK every certificate written"""

#: exit code per verdict
EXIT = {"verified": 0, "definition": 0, "does-not-hold": 1, "undecided": 3}


def add_arguments(c) -> None:
    """Arguments of ``rigidsym check``."""
    c.add_argument("file", nargs="?", metavar="FILE",
                   help="a document (.md or .tex): decide every displayed relation "
                        "(docs/check-documents.md); its declarations: the reading file "
                        "FILE's stem + .reading.toml beside it, --reading, --let (default: "
                        "none: --latex instead)")
    c.add_argument("--latex", metavar="LATEX",
                   help="the relation(s) in LaTeX: = or \\equiv chains, several separated "
                        "by ',' or \\quad (this or FILE)")
    c.add_argument("--reading", metavar="FILE",
                   help="with FILE: the document's reading file (default: the sidecar "
                        "X.reading.toml beside X.md, if there is one)")
    c.add_argument("--markdown", action="store_true",
                   help="with FILE: print the errata as Markdown (default: text)")
    c.add_argument("--html", metavar="OUT",
                   help="with FILE: also write the errata as one offline HTML page to OUT "
                        "(the displays in order, MathML, each relation's verdict beside it; "
                        "default: none)")
    c.add_argument("--let", action="append", metavar="DECL", default=[],
                   help="what a symbol is: 'NAME: KIND' or 'NAME = LATEX' (repeatable; one "
                        "value may hold several separated by '; '; default: none, every "
                        "symbol free with the book's conventional shape)")
    c.add_argument("--book", metavar="SECTION",
                   help="read the LaTeX as the book's: the glyphs' meanings from the rows "
                        "of this section (3.2, 3.4.2, ...) of the glyph table the book's "
                        "reading names (default: none, the text is one's own)")
    c.add_argument("--notation", metavar="NAME",
                   help="a book's symbol table: lynch-park, murray-li-sastry, siciliano, "
                        "spong, craig, featherstone, barfoot, sola, corke, jpl (what its symbols "
                        "are; a --let wins over it; default: none)")
    c.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + "; it lends its symbols and models, matched by name "
                                      "(default: none)")
    c.add_argument("--certificate", metavar="FILE",
                   help="write the verdict's certificate to FILE (docs/certificates.md) and "
                        "re-check it with certcheck when it is found (default: none)")
    c.add_argument("--certificates", metavar="DIR",
                   help="with FILE: write a certificate per decided relation into DIR, "
                        "bound to FILE and its reading file, and re-check them with certcheck "
                        "(docs/check-documents.md, 'Certificates'); exit 4 unless certcheck "
                        "CHECKED every one (default: none)")
    c.add_argument("--json", action="store_true",
                   help="print the schema-2 record, with read_as and readings (default: "
                        "book notation as text)")
    add_repair_arguments(c)
    c.add_argument("--repair-seconds", type=float, metavar="S", default=10.0,
                   help="a time limit of the repair search, seconds; past it the verdict is "
                        "printed with what was tried (default: 10)")
    c.add_argument("--timeout", type=float, metavar="S", default=None,
                   help="a time limit of the whole check, seconds; past it the verdict is "
                        "undecided (exit 3), naming the step it was in and a hint "
                        "(default: 60, or the environment variable RIGIDSYM_LATEX_TIMEOUT)")


def run(args) -> int:
    """``rigidsym check --latex``: read the LaTeX, decide it, explain it as ``show`` does."""
    import json

    from rigidsym.latex import LatexError
    from rigidsym.registry.declarations import BadInput

    if (args.file is None) == (args.latex is None):
        print("rigidsym: error: give a document FILE or --latex LATEX (one of them)",
              file=sys.stderr)
        return 2
    if args.file is not None:
        from rigidsym.cli.check_document import run_document

        return run_document(args)
    if args.reading or args.markdown or args.html or args.certificates:
        print("rigidsym: error: --reading, --markdown, --html and --certificates go with a "
              "document FILE", file=sys.stderr)
        return 2
    try:
        from rigidsym.api import check_latex_run
        from rigidsym.core.progress import Reporter

        opts = repair_options(args)
        with Reporter("rigidsym check", keep=False) as rep, \
                rep.phase("reading and checking the LaTeX") as ph:  # no silent second
            r, reading = check_latex_run(args.latex, args.let, args.book, args.module or (),
                                      opts["repairs"], opts["repair_budget"], args.notation,
                                      args.repair_seconds,
                                      "default" if args.timeout is None else args.timeout)
            ph.finish(f"{r.id} {r.verdict}")  # an ad-hoc check expects nothing
    except LatexError as exc:
        print(f"rigidsym: error: --latex: {exc}", file=sys.stderr)
        return 2
    except BadInput:
        raise  # the command's one-line error, exit 2
    except Exception:  # noqa: BLE001 -- a model sympy refuses (a shape, a power): the
        # check turns its own errors into undecided, so this is the reading's; its text is
        # internal and never reaches the message
        print(f"rigidsym: error: --latex: an internal error while reading and checking "
              f"{args.latex!r} (never a verdict); say it another way or report it",
              file=sys.stderr)
        return 2
    if args.certificate:
        _certify(r, args.certificate)
    if args.json:
        from rigidsym.report.record import result_record

        rec = {**result_record(r), "read_as": reading.text if reading else None,
               "readings": reading.notes if reading else []}
        print(json.dumps(rec, indent=1, ensure_ascii=False))
        return EXIT.get(r.verdict, 3)
    if r.method == "time-limit":  # the limit passed: what was read, the step, a hint
        if reading is not None:
            print(f"read as: {reading.text}")
        print(f"undecided: {r.cause}")
        return EXIT["undecided"]
    import dataclasses
    import textwrap

    from rigidsym.report.show import explain, output_width

    width = output_width()
    st = reading.statement
    print(f"read as: {reading.text}")
    for note in reading.notes:  # how it was read (free symbols too), apart from the atoms
        print(textwrap.fill(note, width, initial_indent="  ", subsequent_indent="    "))
    print()
    atoms = dataclasses.replace(r, model=[m for m in r.model if m not in reading.notes])
    # everything, as show --full: a relation read from LaTeX has no id to show again
    print(explain(atoms, {"printed": st.printed, "claim": st.claims,
                          "corrected": st.corrected or []}, "--latex (rigidsym check)", width,
                  full=True, ascii=getattr(sys.stdout, "encoding", "") == "ascii"))
    return EXIT.get(r.verdict, 3)


def _certify(r, path: str) -> None:
    """Write ``r``'s certificate to ``path`` and re-check it (a line on stderr)."""
    import json
    from pathlib import Path

    from rigidsym.checking.certifying.certificates import Unprintable, certificate, recheck_folder
    from rigidsym.core.files import write_atomic

    if r.verdict == "undecided":
        print("certificate: none (the verdict is undecided)", file=sys.stderr)
        return
    try:
        cert = certificate(r.id, r.verdict, r.members)
    except Unprintable as exc:
        print(f"certificate: none ({exc})", file=sys.stderr)
        return
    write_atomic(path, json.dumps(cert, indent=1) + "\n")
    out = recheck_folder(path, {Path(path).name: r.id})
    if out["rechecked"] is None:
        print(f"certificate: written to {path}; certcheck not found, not re-checked",
              file=sys.stderr)
    elif out["rechecked"].get(r.id):
        print(f"certificate: written to {path}, re-checked by certcheck", file=sys.stderr)
    else:
        print(f"certificate: written to {path}; certcheck FAILED: "
              f"{out['failures'].get(r.id, '?')}", file=sys.stderr)
