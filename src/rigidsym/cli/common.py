"""What the sub-commands share: consoles, the help formatter, the ``--module`` help, the
default job count, and the ``--ascii`` output switch."""

from __future__ import annotations

import argparse
import os
import sys
from contextlib import contextmanager

from rigidsym.registry.usermodules import MODULE_HELP

__all__ = ["console", "MODULE_HELP", "JOBS", "HelpFormatter", "ascii_output",
           "add_ascii", "FORMATS", "output_format", "add_repair_arguments", "repair_options"]

#: default worker processes of ``verify`` and ``report``
JOBS = min(2, os.cpu_count() or 1)
#: ``--format`` of verify and ``exercise --all``: what goes to stdout
FORMATS = ("table", "plain", "json")


class HelpFormatter(argparse.RawDescriptionHelpFormatter):
    """Descriptions and examples as written; every option's help ends with its default
    (``(default: 2)``, ``(default: none)`` when absent means nothing is given) unless it
    says it already, or the option is a flag."""

    def _get_help_string(self, action):
        text = action.help or ""
        d = action.default
        if "default" in text or not action.option_strings or action.nargs == 0 or \
                d is argparse.SUPPRESS:
            return text
        return text + (" (default: none)" if d in (None, []) else f" (default: {d})")


def console(stderr: bool = False):
    """A rich console; when stdout is not a terminal it is as wide as the longest line
    needs (tables are never cut in a pipe or a log)."""
    from rich.console import Console
    if sys.stdout.isatty():
        return Console(stderr=stderr)
    return Console(stderr=stderr, width=10_000, soft_wrap=True)


def _budget(text: str) -> int:
    import argparse

    try:
        n = int(text)
    except ValueError:
        n = -1
    if n < 0:
        raise argparse.ArgumentTypeError(f"expected a non-negative integer, got {text!r}")
    return n


def add_repair_arguments(p) -> None:
    """``--repair-budget N`` and ``--no-repairs`` (verify, show, report)."""
    p.add_argument("--repair-budget", type=_budget, metavar="N", default=None,
                   help="candidates the repair search tries per failing member (default: "
                        "the declaration's, else 5000)")
    p.add_argument("--no-repairs", action="store_true",
                   help="do not search repairs of members that do not hold")


def repair_options(args) -> dict:
    """The ``repairs``/``repair_budget`` keywords of the parsed repair arguments."""
    return {"repairs": not getattr(args, "no_repairs", False),
            "repair_budget": getattr(args, "repair_budget", None)}


def output_format(args) -> str:
    """The ``--format`` asked for, else ``table`` on a terminal and ``plain`` in a pipe."""
    fmt = getattr(args, "format", None)
    if fmt:
        return fmt
    return "table" if sys.stdout.isatty() else "plain"


def add_ascii(p) -> None:
    """``--ascii`` on a sub-command."""
    p.add_argument("--ascii", action="store_true",
                   help="plain ASCII output (omega, adot, ||omega||^2) for terminals without "
                        "Unicode (default: the book's notation, ω, ȧ, ‖ω‖², when the "
                        "terminal can show it; also RIGIDSYM_ASCII=1)")


@contextmanager
def ascii_output(wanted: bool):
    """Within the block, stdout and stderr write plain ASCII when ``wanted``, when
    ``RIGIDSYM_ASCII`` is set, or when their encoding cannot show the book's notation."""
    from rigidsym.printing.ascii import AsciiStream, needs_ascii

    env = os.environ.get("RIGIDSYM_ASCII", "") not in ("", "0")
    saved = sys.stdout, sys.stderr
    try:
        if wanted or env or needs_ascii(sys.stdout):
            sys.stdout = AsciiStream(sys.stdout)
        if wanted or env or needs_ascii(sys.stderr):
            sys.stderr = AsciiStream(sys.stderr)
        yield
    finally:
        sys.stdout, sys.stderr = saved
