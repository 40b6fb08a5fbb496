"""How a trial of typed statements is judged: each case's own NumPy truth (``case["truth"]``,
a residual of random inputs) against the checker's verdict."""

from __future__ import annotations

import numpy as np

import rigidsym


def holds(case: dict, tolerance: float) -> bool:
    """Whether the case's statement holds by its NumPy truth: the largest residual of five
    seeded draws below ``tolerance``."""
    rng = np.random.default_rng(81)
    return max(case["truth"](rng) for _ in range(5)) < tolerance


def answer(case: dict, tolerance: float, latex: str | None = None,
           lets: list | None = None) -> str:
    """right / WRONG / refused / undecided, judged by the NumPy truth (the case as typed, or
    the ``latex`` and ``lets`` given)."""
    latex = case["latex"] if latex is None else latex
    lets = case["let"] if lets is None else lets
    try:
        r = rigidsym.check_latex(latex, let=lets, repairs=False)
    except ValueError:
        return "refused"
    if r.verdict == "undecided":
        return "undecided"
    said = r.verdict in ("verified", "definition")
    return "right" if said == holds(case, tolerance) else "WRONG"
