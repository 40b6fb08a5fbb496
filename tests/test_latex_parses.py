"""Every chapter id of the recorded parses parses to the same structure (its
chains in sympy's srepr, its relation symbols and its readings), whatever the grammar and
the tokenizer learnt since: ``tests/data/latex_parses.json`` (recorded by
``tests/data/make_latex_parses.py`` before the change)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

DATA = Path(__file__).resolve().parent / "data"


def test_every_chapter_parse_is_unchanged():
    sys.path.insert(0, str(DATA))
    from make_latex_parses import structures

    before = json.loads((DATA / "latex_parses.json").read_text())
    now = structures()
    assert set(now) == set(before)
    lost = [k for k, h in before.items() if h is not None and now[k] is None]
    changed = [k for k, h in before.items() if h is not None and now[k] not in (None, h)]
    assert not lost and not changed, (lost, changed)
    assert sum(h is not None for h in before.values()) == 157
