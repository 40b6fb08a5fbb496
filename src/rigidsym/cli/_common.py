"""What the sub-commands share: consoles, the ``--module`` help, the default job count."""

from __future__ import annotations

import os
import sys

from rigidsym.checking.usermodules import MODULE_HELP

__all__ = ["console", "MODULE_HELP", "JOBS", "add_repair_arguments", "repair_options"]

#: default worker processes of ``verify`` and ``report``
JOBS = min(2, os.cpu_count() or 1)


def console(stderr: bool = False):
    """A rich console (120 columns when stdout is not a terminal)."""
    from rich.console import Console
    return Console(stderr=stderr, width=120 if not sys.stdout.isatty() else None)


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
