"""Write ``latex_parses.json``: for each chapter id whose LaTeX parses, a hash of what
``parse_latex(latex, section)`` builds (its chains in sympy's ``srepr`` and its readings),
so a change to the grammar or the tokenizer is tested to leave every parse as it was
("every chapter id that parses today parses to the same structure").
Run: ``python tests/data/make_latex_parses.py`` (only to record a deliberate change)."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

OUT = Path(__file__).resolve().parent / "latex_parses.json"


def structures() -> dict[str, str | None]:
    """id -> hash of the parse (``None``: it does not parse)."""
    import sympy as sp

    from rigidsym.latex import LatexError, parse_latex
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    out = {}
    for k, eq in sorted(REGISTRY.items()):
        if k.count(":"):
            continue
        try:
            p = parse_latex(eq.latex, eq.section)
        except LatexError:
            out[k] = None
            continue
        text = json.dumps([[sp.srepr(e) for e in c] for c in p.chains] + [p.ops, p.readings])
        out[k] = hashlib.sha256(text.encode()).hexdigest()[:16]
    return out


if __name__ == "__main__":
    OUT.write_text(json.dumps(structures(), indent=1) + "\n")
