"""The error of bad user input, in a module that imports nothing: the command line's help and
its argument checks raise and catch it without importing sympy (tests/test_cli_help.py)."""

from __future__ import annotations

import difflib
from collections.abc import Iterable

__all__ = ["BadInput", "did_you_mean"]


class BadInput(ValueError):
    """Bad user input: an unknown or malformed id or section, a user module that cannot be
    loaded (the CLI exits with code 2). A ``ValueError``.

    Args:
        message: one line naming the input and what was expected.
    """


# a user meets it as ``rigidsym.BadInput`` (the package exports it): a traceback says so
BadInput.__module__ = "rigidsym"


def did_you_mean(word: str, known: Iterable[str], n: int = 3) -> str:
    """The close matches of a mistyped ``word`` among ``known``, as a clause to append to an
    error message (``"; did you mean 'verify'?"``), or ``""`` when none is close.

    Args:
        word: what was typed (``"verfy"``).
        known: the valid words (commands, ids, kinds).
        n: at most this many suggestions.

    Returns:
        str: ``"; did you mean 'a' or 'b'?"``, or an empty string.

    Source: difflib's ratio (the standard library), cutoff 0.6, as ``git``'s and Python
    3.14 argparse's suggestions.
    """
    close = difflib.get_close_matches(str(word), list(known), n=n, cutoff=0.6)
    if not close:
        return ""
    return "; did you mean " + " or ".join(repr(c) for c in close) + "?"
