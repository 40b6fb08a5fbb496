"""``rigidsym audit MODULE:FUNCTION --as OPERATION``: judge any implementation against the
book (its convention, its worst input, its silent wrongs)."""

from __future__ import annotations

import sys

__all__ = ["add_arguments", "run", "HELP", "EXAMPLES"]

HELP = "judge any implementation against the book (yours, a peer's, C)"
EXAMPLES = """\
  rigidsym audit mypkg.mymod:adjoint --as twist_transfer
                                      convention found, worst input, silent wrongs
  rigidsym audit pytransform3d.rotations:compact_axis_angle_from_matrix \\
      --as rotation_vector_from_rotation --markdown
                                      a summary to paste into the library's issue
  rigidsym audit --c ./libfoo.so:wrench --signature "T[4,4],w[6]->out[6]" \\
      --as wrench_transfer            a C function through ctypes
  rigidsym audit mymod:log --as rotation_vector_from_rotation --pytest test_log.py
                                      a regression test of the worst input
  rigidsym audit 'pyquaternion:Quaternion(matrix=...).axis' \
      --as natural_invariants_from_rotation
                                      a bound method or chain, each argument as ...
  rigidsym audit 'liegroups.numpy:lambda Q: SO3.from_matrix(Q).log()' \
      --as rotation_vector_from_rotation
                                      the lambda form
exit codes: 0 no finding, 1 findings, 2 bad input"""


def add_arguments(p) -> None:
    """Arguments of ``rigidsym audit``."""
    p.add_argument("function", nargs="?", default="",
                   help="the function, MODULE:FUNCTION, importable from here, or a method "
                        "or chain over the module's names, MODULE:'Class(matrix=...).method' "
                        "(each argument as ...) or MODULE:'lambda Q: Class(Q).method()' "
                        "(default: none; then --c)")
    p.add_argument("--as", dest="as_", required=True, metavar="OPERATION",
                   help="what it claims to compute, a kernel's name (no default: required; "
                        "a wrong name lists those there are): twist_transfer, "
                        "wrench_transfer, rotation_vector_from_rotation, ...")
    p.add_argument("--c", default="", metavar="LIB:SYMBOL",
                   help="a C function of a shared library instead, with --signature "
                        "(default: none)")
    p.add_argument("--signature", default="",
                   help="the C function's arrays of doubles, inputs then outputs: "
                        "'t_A[6],a[3],p[3]->t_P[6]' (default: none)")
    p.add_argument("--args", default="", metavar="NAMES",
                   help="the function's parameter names, comma-separated (default: read "
                        "from the function), which choose its argument layout first")
    p.add_argument("--seed", type=int, default=0, help="the seed of inputs and search (default: 0)")
    p.add_argument("--float32", action="store_true", help="sweep float32 too")
    p.add_argument("--no-search", action="store_true",
                   help="the singular sets only, no hill climbing")
    out = p.add_mutually_exclusive_group()
    out.add_argument("--json", action="store_true", help="the report as JSON")
    out.add_argument("--markdown", action="store_true",
                     help="a Markdown summary to paste into an issue")
    p.add_argument("--pytest", default="", metavar="FILE",
                   help="write a regression test of the worst input to FILE (default: "
                        "none, nothing is written)")


def run(args) -> int:
    """Audit the function; print the report; 1 where there is a finding."""
    from rigidsym.auditing import callables, report
    from rigidsym.auditing.audit import audit
    from rigidsym.core.errors import BadInput

    names = tuple(n.strip() for n in args.args.split(",") if n.strip()) or None
    if args.c:
        if args.function:
            raise BadInput("give either MODULE:FUNCTION or --c LIB:SYMBOL, not both")
        if not args.signature:
            raise BadInput("--c needs --signature (the arrays: 't_A[6],a[3],p[3]->t_P[6]')")
        func, c_names = callables.c_function(args.c, args.signature)
        names, spec = names or c_names, ""
    elif args.function:
        if "" not in sys.path:
            sys.path.insert(0, "")      # a module beside the user, as python -m finds it
        func, spec = callables.load(args.function), args.function
    else:
        raise BadInput("function: expected MODULE:FUNCTION or --c LIB:SYMBOL")
    rep = audit(func, args.as_, names=names, seed=args.seed,
                dtypes=("float64", "float32") if args.float32 else ("float64",),
                search=not args.no_search, spec=spec)
    if args.pytest:
        path = report.write_pytest(rep, args.pytest)
        print(f"wrote {path}", file=sys.stderr)
    print(report.to_json(rep) if args.json else report.markdown(rep) if args.markdown
          else report.text(rep), end="")
    return 0 if rep.ok else 1
