"""The ``rigidsym`` command: verify, report, show, check, exercise, exam, grade, generate,
build-c, audit, cache, glossary.

Exit codes: 0 = all as expected, 1 = some computed verdict differs from its expectation,
2 = bad input (a one-line message naming what was expected and, where there is one, the
next step), 130 = interrupted (SIGINT or SIGTERM: one line saying what was kept).
"""

from __future__ import annotations

import os
import signal
import sys


def _loading(signum, frame) -> None:  # noqa: ARG001 - a signal handler's signature
    """SIGINT or SIGTERM while the command loads, before :func:`main` runs: nothing was
    done yet; one line, exit 130, no traceback."""
    os.write(2, b"rigidsym: interrupted while starting; nothing was done\n")
    os._exit(130)


def _is_the_program() -> bool:
    """Whether this process is the ``rigidsym`` command (its script, ``python -m
    rigidsym``), not a program that imports the package (a notebook, a test runner)."""
    spec = getattr(sys.modules.get("__main__"), "__spec__", None)
    return getattr(spec, "name", None) == "rigidsym.__main__" or \
        os.path.basename(sys.argv[0] if sys.argv else "") in ("rigidsym", "rigidsym.exe")


if _is_the_program():
    for _sig in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(_sig) is not signal.SIG_IGN:  # ignored: nohup, a background job
            signal.signal(_sig, _loading)

# ruff: noqa: E402 - the imports below come after the handlers above
import argparse
import re

from rigidsym.cli import (
    audit,
    cache,
    check,
    exam,
    exercise,
    generate,
    glossary,
    grade,
    report,
    show,
    verify,
)
from rigidsym.cli.common import HelpFormatter, add_ascii, ascii_output
from rigidsym.core import interrupts, progress
from rigidsym.core import work as _work
from rigidsym.core.errors import did_you_mean

__all__ = ["main", "build_parser"]

#: the sub-commands: name -> module with ``HELP``, ``add_arguments(parser)``, ``run(args)``
#: (and optionally ``EXAMPLES``, shown under the command's own ``--help``)
_COMMANDS = {"verify": verify, "report": report, "show": show, "check": check,
             "exercise": exercise,
             "exam": exam, "grade": grade,
             "generate": generate.GENERATE, "build-c": generate.BUILD_C, "audit": audit,
             "cache": cache,
             "glossary": glossary}

#: the commands that answer at once (no sympy, no checking): no start line
_QUICK = frozenset({"cache", "glossary"})

DESCRIPTION = """\
Checked computer algebra for chapter 3 of J. Angeles, Fundamentals of Robotic Mechanical
Systems: decide its equations (and yours), explain one, solve its exercises, generate
NumPy and C kernels. Each command has its own help: rigidsym COMMAND --help."""

EPILOG = """\
examples, one per job:
  rigidsym show 3.57                  the chapter: why (3.57) does not hold as printed
                                      (rigidsym verify checks all 181 ids)
  rigidsym verify --module my_eqs.py  your own equations (see examples/ in the source)
  rigidsym check --latex '\\mathbf{Q}^T\\mathbf{Q} = \\mathbf{1}' --let '\\mathbf{Q}: rotation'
                                      an equation in LaTeX, its symbols declared
  rigidsym exercise 3.10              a worked exercise (no id: the list of all 21)
  rigidsym audit mymod:log --as rotation_vector_from_rotation
                                      any implementation judged against the book

words (verdict, member, claim, model, parametrisation, ...): rigidsym glossary
exit codes: 0 as expected, 1 a verdict differs from its expectation, 2 bad input"""


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``rigidsym`` command.

    Returns:
        An ``argparse.ArgumentParser`` with one sub-parser per command (``verify``,
        ``report``, ``show``, ``exercise``, ``generate``, ``build-c``, ...).
    """
    p = argparse.ArgumentParser(prog="rigidsym", description=DESCRIPTION, epilog=EPILOG,
                                formatter_class=HelpFormatter)
    p.add_argument("--ascii", action="store_true", dest="ascii_all",
                   help="plain ASCII output for every command (as the commands' own "
                        "--ascii; default: off)")
    sub = p.add_subparsers(dest="command", required=True, title="commands",
                           metavar="COMMAND")
    for name, cmd in _COMMANDS.items():
        examples = getattr(cmd, "EXAMPLES", "")
        c = sub.add_parser(name, help=cmd.HELP, description=cmd.HELP[0].upper() + cmd.HELP[1:]
                           + ".", epilog=("examples:\n" + examples) if examples else None,
                           formatter_class=HelpFormatter)
        cmd.add_arguments(c)
        add_ascii(c)
        c.set_defaults(func=cmd.run)
    return p


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``rigidsym`` command.

    Args:
        argv: the arguments after ``rigidsym`` (default ``sys.argv[1:]``).

    Returns:
        int: the exit code, 0 when all is as expected, 1 when a verdict differs from its
        expectation (or a check failed), 2 on bad input, 130 when interrupted (SIGINT or
        SIGTERM; the finished work is kept in the user cache and one line says how much).
    """
    saved = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    interrupts.install()
    interrupts.reset()
    try:
        interrupts.checkpoint("start")
        code = _main(argv)
        if argv is None:  # the program: done and written; an interrupt now changes nothing
            interrupts.quiet()
        return code
    except (KeyboardInterrupt, Exception) as exc:  # SIGINT or SIGTERM: work kept, one line
        if not (isinstance(exc, KeyboardInterrupt) or interrupts.received()):
            raise  # a failure of its own, not the interrupt in another form
        interrupts.quiet()  # a second Ctrl-C, or one already pending: no second exit
        if argv is None:  # the program: its workers only (a caller's children are its own)
            interrupts.end_workers()
        print(f"rigidsym: {interrupts.line()}", file=sys.stderr, flush=True)
        _work.dump()
        return interrupts.EXIT
    finally:
        if argv is not None:  # called in a process of the caller's (a test): as it was
            for sig, handler in saved.items():
                if handler is not None:
                    signal.signal(sig, handler)


def _main(argv: list[str] | None) -> int:
    parser = build_parser()

    def _error(where: str):
        def error(message):  # argparse errors are bad input: one line, exit 2
            m = re.match(r"argument COMMAND: invalid choice: '([^']*)'", message)
            if m:  # a mistyped command: the close ones first, then the list
                message = message.replace(" (choose", did_you_mean(m.group(1), _COMMANDS)
                                          + " (choose", 1)
            print(f"rigidsym: error: {message} ({where})", file=sys.stderr)
            raise SystemExit(2)
        return error

    given = sys.argv[1:] if argv is None else argv
    cmd = next((a for a in given if a in _COMMANDS), None)  # "unrecognized arguments" of it
    parser.error = _error(f"rigidsym {cmd} --help lists its options" if cmd else
                          "rigidsym --help lists the commands")
    for name, sp_ in parser._subparsers._group_actions[0].choices.items():
        sp_.error = _error(f"rigidsym {name} --help lists its options")
    args = parser.parse_args(argv)
    from rigidsym.registry.declarations import BadInput
    if getattr(args, "ascii_all", False):   # rigidsym --ascii COMMAND: as COMMAND --ascii
        args.ascii = True
    # the program's first line before its heavy imports, and one every 2.5 s until the
    # command's own progress (tests calling main() in-process see none)
    announce = argv is None and args.command not in _QUICK and not getattr(args, "quiet", False)
    with ascii_output(getattr(args, "ascii", False)):
        try:
            with progress.starting(f"rigidsym {args.command}", enabled=announce):
                code = args.func(args)
            sys.stdout.flush()  # a closed pipe shows here, not at the interpreter's exit
            _work.dump()  # the work done, where a test or a benchmark asked for it
            return code
        except BadInput as exc:
            hint = "" if "rigidsym " in str(exc) else \
                f" (rigidsym {args.command} --help shows what it takes)"
            print(f"rigidsym: error: {exc}{hint}", file=sys.stderr)
            return 2
        except BrokenPipeError:  # `rigidsym exercise 3.10 | head`: the reader left
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
