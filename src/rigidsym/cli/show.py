"""``rigidsym show ID``: one equation explained in book notation."""

from __future__ import annotations

import inspect
import os
import sys

from rigidsym.cli.common import MODULE_HELP, add_repair_arguments, repair_options
from rigidsym.registry.declarations import REGISTRY
from rigidsym.registry.usermodules import select_with_modules

__all__ = ["add_arguments", "run"]

HELP = "explain one equation: verdict, counterexample, correction"
EXAMPLES = """\
  rigidsym show 3.57                  why (3.57) does not hold, in the book's symbols
  rigidsym show 3.83 --full           everything, the expression trees included
  rigidsym show 3.96                  every part of (3.96), one after the other
  rigidsym show rot:trace --module examples/rotation_identities.py   one of your ids
  rigidsym show 3.148 --json          the schema-2 record"""


def add_arguments(s) -> None:
    """Arguments of ``rigidsym show``."""
    s.add_argument("id", help="an id: 3.57, 3.96 (all its parts), thm3.2.1, or one of your "
                              "module's (namespace:name, with --module)")
    s.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help=MODULE_HELP + " (default: none)")
    fmt = s.add_mutually_exclusive_group()
    fmt.add_argument("--latex", action="store_true",
                     help="print the members as LaTeX (default: book notation as text)")
    fmt.add_argument("--json", action="store_true",
                     help="print the schema-2 record (default: book notation as text)")
    s.add_argument("--full", action="store_true",
                   help="everything: the expression trees, where the equation is declared, "
                        "the repairs, the model and the numeric backing (default: at most "
                        "40 lines: the members, the verdict, the counterexample, the cause "
                        "and the corrected form)")
    s.add_argument("--certificates", metavar="DIR",
                   help="also write each shown verdict's certificate into DIR and say whether "
                        "certcheck re-checks it (docs/certificates.md; default: none)")
    add_repair_arguments(s)


def reader_path(path: str, cwd: str | None = None) -> str:
    """A path a reader can use: relative to ``cwd`` when the file lies under
    it (``examples/rot.py``); a file of the installed package as ``rigidsym/...``
    (``rigidsym/derivations/sec3_2.py``); else the absolute path, never a relative one
    that climbs out (``../../work/...``)."""
    path = os.path.abspath(path)
    cwd = os.path.abspath(cwd or os.getcwd())
    if os.path.commonpath([path, cwd]) == cwd:
        return os.path.relpath(path, cwd)
    import rigidsym
    pkg = os.path.dirname(os.path.abspath(rigidsym.__file__))
    if os.path.commonpath([path, pkg]) == pkg:
        return os.path.join("rigidsym", os.path.relpath(path, pkg))
    return path


def declared_where(eq) -> str:
    """Where a declaration lives, function and file first: ``trace_wrong in
    notes/rot.py``; a user module imported by its dotted name says it last (the package's
    own module names and the import name of a module given by path are internal ones and
    are left out)."""
    mod = sys.modules[eq.module]
    try:
        src = reader_path(inspect.getsourcefile(getattr(mod, eq.function.split(".")[0])))
    except (TypeError, ValueError, AttributeError):  # no source file (a notebook cell)
        src = eq.where
    internal = eq.module.startswith(("_rigidsym_user_", "rigidsym.")) or \
        eq.module in ("__main__", "rigidsym")
    tail = "" if internal else f" (module {eq.module})"
    return f"{eq.function} in {src}{tail}"


def run(args) -> int:
    """``rigidsym show ID``: one equation explained (verdict, members, counterexample, cause,
    corrected form, singular set) in book notation; ``--latex`` or ``--json`` instead."""
    import json

    from rigidsym.checking.runner import check_cached, verdict_words
    from rigidsym.core.progress import Reporter
    from rigidsym.printing import notation
    from rigidsym.report.record import result_record
    from rigidsym.report.show import explain, output_width
    width = output_width()
    shown = []
    for k, eq_id in enumerate(select_with_modules([args.id], None, args.module)):
        eq = REGISTRY[eq_id]
        with Reporter("rigidsym show", keep=False) as rep, \
                rep.phase(f"checking {eq_id}") as ph:
            st = eq.build()
            # the verdict cache that verify and report fill: a warm show decides nothing
            r = check_cached(eq_id, expanded=False, **repair_options(args))
            ph.finish(verdict_words(r) + (" (from the verdict cache)" if r.cached else ""))
        shown.append(r)
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
        where = declared_where(eq)
        if k:
            print("\n" + "-" * min(width, 40) + "\n")
        print(explain(r, {"printed": st.printed, "claim": st.claims,
                          "corrected": st.corrected or []}, where, width, full=args.full,
                      ascii=getattr(sys.stdout, "encoding", "") == "ascii"))
    if args.certificates:
        _certificates(shown, args.certificates, args.json)
    return 0


def _certificates(results, directory, to_stderr: bool = False) -> None:
    """Write the shown verdicts' certificates and say, per id, whether each is certified and
    re-checked by certcheck (on stderr with ``--json``, so stdout stays the records)."""
    from rigidsym.checking.export import certificate_field, export

    done = export(results, directory, progress=False)
    for r in results:
        f = certificate_field(done, r.id)
        if f["file"] is None:
            line = f"Certificate ({r.id}): none ({f['why']})"
        else:
            state = {True: "re-checked by certcheck", False: "certcheck FAILED: "
                     + done["failures"].get(r.id, "?"), None: "certcheck not found"}
            line = (f"Certificate ({r.id}): {directory}/{f['file']} "
                    f"({', '.join(f['evidence'])}); {state[f['rechecked']]}")
        print(line, file=sys.stderr if to_stderr else sys.stdout)
