"""The text of ``--let`` values: one value may hold several declarations, separated by
``"; "`` outside braces (``--let '\\mathbf{e}: unit vector; \\phi: angle'``)."""

from __future__ import annotations

__all__ = ["split_lets"]


def split_lets(items) -> list[str]:
    """The declarations of ``--let`` values: each value split at ``"; "`` outside braces.

    Args:
        items: the ``--let`` values (strings).

    Returns:
        The declarations, stripped, empty ones dropped.
    """
    out = []
    for item in items or ():
        depth, start = 0, 0
        for i, ch in enumerate(item):
            depth += {"{": 1, "}": -1}.get(ch, 0)
            if ch == ";" and depth == 0 and item[i + 1:i + 2] in (" ", ""):
                out.append(item[start:i])
                start = i + 1
        out.append(item[start:])
    return [d.strip() for d in out if d.strip()]
