"""``rigidsym exam SPEC.toml --out DIR``: a student handout and an answer key."""

from __future__ import annotations

import sys

__all__ = ["add_arguments", "run", "HELP", "EXAMPLES"]

HELP = "write an exam: a student handout and an answer key"
EXAMPLES = """\
  rigidsym exam quiz.toml --out quiz/         handout.html, key.html, key.json
  rigidsym exam quiz.toml --out quiz/ --seed 8   other random variants
  rigidsym exam quiz.toml --students roster.csv --out class/   an exam per student
  rigidsym exam quiz.toml --students roster.csv --out class/ --weights 1,1,2
                                              problem 3 counts twice (key.json, exports)
  rigidsym grade class/ class/answers.csv      grade the class (rigidsym grade --help)"""


def add_arguments(p) -> None:
    """Arguments of ``rigidsym exam``."""
    p.add_argument("spec", help="the exam's TOML spec: [[problem]] tables with exercise = "
                                "\"3.4\" and data = {...} or variants = N (docs/exams.md)")
    p.add_argument("--out", required=True, metavar="DIR", help="the folder to write")
    p.add_argument("--seed", type=int, help="the seed of the random variants (default: the "
                                            "spec's seed, else 0)")
    p.add_argument("--students", metavar="ROSTER.csv",
                   help="a class: one exam per student of the roster (a 'name' column; 'id' "
                        "and 'email' optional), each with its own seed and a different "
                        "variant of every drawn problem; one key, an answers template and "
                        "a Moodle XML export (default: one exam)")
    p.add_argument("--weights", metavar="W1,W2,...",
                   help="a class's problems' weights (their points), comma separated, one "
                        "per problem of the exam, problem 1 first (e.g. 1,1,2), in place "
                        "of the spec's weight = ...; kept in DIR/key.json, the gradebook and "
                        "the Moodle and STACK exports (needs --students)")


def run(args) -> int:
    """Write the handout and the key; 0 written, 2 a bad spec or data, 3 a defect."""
    from rigidsym.cli.grade import parse_weights
    from rigidsym.core import interrupts
    from rigidsym.course import write_exam as exam

    try:
        weights = parse_weights(getattr(args, "weights", None))
        if getattr(args, "students", None):
            from rigidsym.course import class_exam
            paths = class_exam(args.spec, args.students, args.out, seed=args.seed,
                               weights=weights)
        elif weights is not None:
            raise ValueError("--weights: weights go with a class exam (--students "
                             "ROSTER.csv); a single exam has no gradebook")
        else:
            paths = exam(args.spec, args.out, seed=args.seed)
    except (ValueError, TypeError) as exc:
        if interrupts.received():
            raise           # the interrupt in another form: rigidsym.cli.main says it
        print(f"rigidsym: error: {exc} (docs/exams.md describes the spec)", file=sys.stderr)
        return 2
    except Exception as exc:  # noqa: BLE001 - a defect, never the code of a bad spec
        if interrupts.received():
            raise           # a worker pool cut short by Ctrl-C: rigidsym.cli.main says it
        print(f"rigidsym: internal error, please report: {type(exc).__name__}: {exc}",
              file=sys.stderr)
        return 3
    for p in paths.values():
        print(f"wrote {p}")
    return 0
