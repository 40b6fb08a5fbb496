"""Load the corpus: the books' modules, each entry with an id, the
``--let`` lines of its book's symbol table for the symbols it uses, and its numerical
confirmation at random points (:func:`confirm`), independent of rigidsym."""

from __future__ import annotations

import importlib
import re
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
BOOKS = ("lynch_park", "murray_li_sastry", "siciliano", "spong", "corke", "featherstone",
         "craig", "barfoot", "sola",
         # books the corpus did not cover, read with --let functions and models
         "shuster", "diebel", "markley", "tsai", "mccarthy", "goldstein", "selig")
POINTS = 6  # random points per entry
SEED = 40


def _modules():
    if str(HERE) not in sys.path:
        sys.path.insert(0, str(HERE))
    return [importlib.import_module(b) for b in BOOKS]


def entries() -> list[dict]:
    """Every entry, with ``id`` (``book-NN``), ``book`` and ``table`` added."""
    out = []
    for m in _modules():
        for i, e in enumerate(m.ENTRIES, 1):
            out.append({**e, "id": f"{m.BOOK['key']}-{i:02d}", "book": m.BOOK,
                        "table": m.TABLE})
    return out


def _rows(table: str) -> list[tuple[str, str]]:
    from _num import parse_table

    return parse_table(table)


_FONT = re.compile(r"\\(mathbf|boldsymbol|bm|mathsf|mathrm|mathcal|operatorname|text|"
                   r"begin|end|vec|underline|hat|dot)\s*$")


def lets_for(latex: str, table: str) -> list[str]:
    """The table's ``NAME: KIND`` lines whose NAME occurs in ``latex``: longest names first,
    each occurrence blanked out (so ``\\theta`` inside ``R_{z,\\theta}`` is not ``\\theta``);
    a one-letter NAME only as a letter of its own (not a transpose's T, not a font's
    argument, not part of a macro). ``X(t)`` occurs where ``X`` does."""
    text = re.sub(r"\\frac\s*\{\s*d\s*\}\s*\{\s*d", lambda m: " " * len(m.group()), latex)
    used = []
    for name, kind in sorted(_rows(table), key=lambda r: -len(r[0])):
        base = name[:-3] if name.endswith("(t)") else name
        found = False
        start = 0
        while True:
            i = text.find(base, start)
            if i < 0:
                break
            start = i + 1
            before, after = text[:i], text[i + len(base):]
            if base[-1].isalpha() and "_" not in base and re.match(r"[A-Za-z_]", after):
                continue  # \theta in \theta_1, R in Rb is fine (a letter after a macro is not)
            if len(base) == 1 or re.fullmatch(r"[A-Za-z](_\S+)?", base):
                if re.search(r"(\\[A-Za-z]*|\^|\^\{)$", before) or _FONT.search(before[:-1]) \
                        and before.endswith("{"):
                    continue
            found = True
            text = before + " " * len(base) + after
        if found:
            used.append(f"{name}: {kind}")
    return used


def lets_of(entry: dict) -> list[str]:
    """Every ``--let`` of an entry: its table's kinds of the symbols its LaTeX and its
    models use, then its models and functions."""
    models = list(entry.get("lets", []))
    return lets_for(" ".join([entry["latex"], *models]), entry["table"]) + models


def confirm(entry: dict) -> tuple[bool, str]:
    """The entry's verdict by NumPy at ``POINTS`` random points: ``(holds, how)``. A member
    pair NumPy cannot even form (a shape slip) does not hold."""
    from _num import Point, residual

    rng = np.random.default_rng([SEED, sum(map(ord, entry["id"]))])
    worst = 0.0
    for _ in range(POINTS):
        p = Point(entry["table"], rng)
        try:
            r = residual(entry["num"](p))
        except ValueError as exc:
            return False, f"shapes: {exc}"
        worst = max(worst, r)
    return worst < 1e-6, f"largest relative residual {worst:.2e}"
