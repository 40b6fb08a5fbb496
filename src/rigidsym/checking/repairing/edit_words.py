"""An edit of :mod:`rigidsym.checking.repairing.mutate` in words, in book notation
(``flip the sign of the term -sin φ E``, ``replace v̇ by ν̇ (one occurrence)``): what the
reports say a repair did."""

from __future__ import annotations

from rigidsym.printing import notation

__all__ = ["describe"]


def _t(x) -> str:
    return notation.text(x)


def describe(e) -> str:
    """The edit in words, in book notation (``flip the sign of -sin φ E``)."""
    w = e.what
    kind = w[0]
    if kind == "flip":
        return f"flip the sign of the term {_t(w[1])}"
    if kind == "drop":
        return f"drop the term {_t(w[1])}"
    if kind == "insert":
        return f"insert the term {'+' if w[2] > 0 else '-'} {_t(w[1])}"
    if kind == "scale":
        return f"multiply the term {_t(w[1])} by {_t(w[2])}"
    if kind == "coef":
        return f"replace the coefficient {_t(w[1])} by {_t(w[2])}"
    if kind == "transpose":
        return f"transpose {_t(w[1])} (one occurrence)"
    if kind == "untranspose":
        return f"drop the transpose of {_t(w[1])}"
    if kind == "transpose-every":
        return f"transpose every {_t(w[1])}"
    if kind == "swap":
        return f"swap {_t(w[2])} and {_t(w[3])} in {_t(w[1])}"
    if kind == "reverse":
        return f"reverse the product {_t(w[1])}"
    if kind in ("sincos", "oneminus"):
        return f"{_t(w[1])} → {_t(w[2])}"
    if kind == "replace":
        return f"replace {_t(w[1])} by {_t(w[2])} (one occurrence)"
    if kind == "replace-every":
        return f"replace every {_t(w[1])} by {_t(w[2])}"
    if kind == "multiply":
        return f"multiply the term {_t(w[1])} by {_t(w[2])} on the {w[3]}"
    raise ValueError(f"edit kind {kind!r}")
