"""Properties of the reader on the chapter's own transcriptions (the 157
of ``tests/data/latex_parses.json`` that parse): each parses to the same structure (its
chains in sympy's ``srepr`` and its relation symbols, so the same verdict, which is decided
from that structure) when it is spelt another equivalent way: spacing around ``=``, ``+``
and ``,``; ``^T`` as ``^{T}``, a one-character subscript braced (``_1`` as ``_{1}``);
``\\mathbf``/``\\boldsymbol``/``\\bm``; ``\\left( ... \\right)`` as ``( ... )``. The chapter
has no ``--let`` to permute, and its symbols are named by the book's glyph table, so a
renaming is no equivalence there (the corpus carries those properties,
``tests/test_latex_metamorphic.py``). A quick share draws a few ids and variants; every id
with every variant that applies runs under ``slow``. They guard the grammar's ``(`` of an
argument list too."""

from __future__ import annotations

import json
import re
from functools import cache
from pathlib import Path

import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st


def _chains(latex: str, section: str):
    import sympy as sp

    from rigidsym.latex import parse_latex

    p = parse_latex(latex, section)
    return json.dumps([[sp.srepr(e) for e in c] for c in p.chains] + [p.ops])


IDS = sorted(k for k, h in json.loads((Path(__file__).resolve().parent / "data" /
                                       "latex_parses.json").read_text()).items() if h)


@cache
def _entry(k: str) -> tuple:
    """(latex, section, structure) of the chapter id ``k``."""
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    eq = REGISTRY[k]
    return eq.latex, eq.section, _chains(eq.latex, eq.section)


def _unleft(s: str) -> str | None:
    if "\\left(" not in s or s.count("\\left(") != s.count("\\right)"):
        return None
    return s.replace("\\left(", "(").replace("\\right)", ")")


_OPS = r"(?<![\\{^_])(\\equiv|=|\+|-|,)"
VARIANTS = {
    "spacing": lambda s: re.sub(_OPS, r" \1 ", s) if re.search(_OPS, s) else None,
    "sup-braces": lambda s: re.sub(r"\^T(?![A-Za-z{])", "^{T}", s)
    if re.search(r"\^T(?![A-Za-z{])", s) else None,
    # (not in \overrightarrow{AP_1}: there AP_1 is the name of a point pair, as written)
    "sub-braces": lambda s: re.sub(r"_([0-9A-Za-z])(?![0-9A-Za-z])", r"_{\1}", s)
    if re.search(r"_([0-9A-Za-z])(?![0-9A-Za-z])", s) and "overrightarrow" not in s else None,
    "boldsymbol": lambda s: re.sub(r"\\mathbf\{(?=[A-Za-z]\})", r"\\boldsymbol{", s)
    if re.search(r"\\mathbf\{[A-Za-z]\}", s) else None,
    "bm": lambda s: re.sub(r"\\mathbf\{(?=[A-Za-z]\})", r"\\bm{", s)
    if re.search(r"\\mathbf\{[A-Za-z]\}", s) else None,
    "unleft": _unleft,
}


def _same(k: str, name: str) -> bool:
    """The property on id ``k``; False if the variant does not apply."""
    latex, section, want = _entry(k)
    v = VARIANTS[name](latex)
    if v is None:
        return False
    assert _chains(v, section) == want, f"{k} {name}: {v}"
    return True


@settings(max_examples=examples(8), deadline=None, derandomize=True, database=None)
@given(data=st.data())
def test_a_chapter_parse_is_unchanged_by_an_equivalent_spelling_quick(data):
    k = data.draw(st.sampled_from(IDS))
    _same(k, data.draw(st.sampled_from(sorted(VARIANTS))))


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(VARIANTS))
def test_every_chapter_parse_is_unchanged_by_each_equivalent_spelling(name):
    ran = [k for k in IDS if _same(k, name)]
    assert len(IDS) == 157
    # the share of ids a variant applies to (measured: 157, 43, 68, 153, 153, 3 of 157);
    # spacing applies to every id, so no id is skipped by every variant
    floor = {"spacing": 1.0, "sup-braces": 0.25, "sub-braces": 0.4, "boldsymbol": 0.95,
             "bm": 0.95, "unleft": 0.015}[name]
    assert len(ran) >= floor * len(IDS), (name, len(ran))
