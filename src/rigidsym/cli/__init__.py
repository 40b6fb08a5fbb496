"""The ``rigidsym`` command: verify, report, show, exercise, generate, build-c, cache.

Exit codes: 0 = all as expected, 1 = some computed verdict differs from its expectation,
2 = bad input (a one-line message naming what was expected).
"""

from __future__ import annotations

import argparse
import os
import sys

from rigidsym.checking.registry import BadInput
from rigidsym.cli import cache, exercise, generate, report, show, verify

__all__ = ["main", "build_parser"]

#: the sub-commands: name -> module with ``HELP``, ``add_arguments(parser)``, ``run(args)``
_COMMANDS = {"verify": verify, "report": report, "show": show, "exercise": exercise,
             "generate": generate.GENERATE, "build-c": generate.BUILD_C, "cache": cache}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``rigidsym`` command (one sub-parser per command)."""
    p = argparse.ArgumentParser(prog="rigidsym", description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)
    for name, cmd in _COMMANDS.items():
        c = sub.add_parser(name, help=cmd.HELP)
        cmd.add_arguments(c)
        c.set_defaults(func=cmd.run)
    return p


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``rigidsym`` command.

    Args:
        argv: the arguments after ``rigidsym`` (default ``sys.argv[1:]``).

    Returns:
        The exit code: 0 all as expected, 1 a verdict differs from its expectation (or a
        check failed), 2 bad input.
    """
    parser = build_parser()

    def _error(message):  # argparse errors are bad input: one line, exit 2
        print(f"rigidsym: error: {message}", file=sys.stderr)
        raise SystemExit(2)

    parser.error = _error
    for sp_ in parser._subparsers._group_actions[0].choices.values():
        sp_.error = _error
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except BadInput as exc:
        print(f"rigidsym: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # `rigidsym exercise 3.10 | head`: the reader left, not an error
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
