"""The error of bad user input, in a module that imports nothing: the command line's help and
its argument checks raise and catch it without importing sympy (tests/test_cli_help.py)."""

from __future__ import annotations

__all__ = ["BadInput"]


class BadInput(ValueError):
    """Bad user input: an unknown or malformed id or section, a user module that cannot be
    loaded (the CLI exits with code 2). A ``ValueError``.

    Args:
        message: one line naming the input and what was expected.
    """
