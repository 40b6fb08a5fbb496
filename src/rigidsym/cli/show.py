"""``rigidsym show ID``: one equation explained in book notation."""

from __future__ import annotations

import inspect
import os
import sys

from rigidsym.checking.registry import REGISTRY
from rigidsym.checking.usermodules import select_with_modules
from rigidsym.cli._common import MODULE_HELP, add_repair_arguments, repair_options

__all__ = ["add_arguments", "run"]

HELP = "explain one equation (verdict, why, counterexample)"


def add_arguments(s) -> None:
    """Arguments of ``rigidsym show``."""
    s.add_argument("id")
    s.add_argument("--module", action="append", metavar="PATH_OR_DOTTED", help=MODULE_HELP)
    fmt = s.add_mutually_exclusive_group()
    fmt.add_argument("--latex", action="store_true", help="print the members as LaTeX")
    fmt.add_argument("--json", action="store_true", help="print the schema-2 record")
    add_repair_arguments(s)


def run(args) -> int:
    """``rigidsym show ID``: one equation explained (verdict, members, counterexample, cause,
    corrected form, singular set) in book notation; ``--latex`` or ``--json`` instead."""
    import json

    from rigidsym.checking.checker import check
    from rigidsym.printing import notation
    from rigidsym.report.record import result_record
    from rigidsym.report.show import explain, output_width
    width = output_width()
    for k, eq_id in enumerate(select_with_modules([args.id], None, args.module)):
        eq = REGISTRY[eq_id]
        st = eq.build()
        r = check(eq_id, **repair_options(args))
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
        mod = sys.modules[eq.module]
        src = inspect.getsourcefile(getattr(mod, eq.function.split(".")[0]))
        where = f"{eq.function} of {eq.module} ({os.path.relpath(src)})"
        if k:
            print("\n" + "-" * min(width, 40) + "\n")
        print(explain(r, {"printed": st.printed, "claim": st.claims,
                          "corrected": st.corrected or []}, where, width))
    return 0
