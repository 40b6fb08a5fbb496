"""What the sub-commands share: consoles, the ``--module`` help, the default job count."""

from __future__ import annotations

import os
import sys

from rigidsym.checking.usermodules import MODULE_HELP

__all__ = ["console", "MODULE_HELP", "JOBS"]

#: default worker processes of ``verify`` and ``report``
JOBS = min(2, os.cpu_count() or 1)


def console(stderr: bool = False):
    """A rich console (120 columns when stdout is not a terminal)."""
    from rich.console import Console
    return Console(stderr=stderr, width=120 if not sys.stdout.isatty() else None)
