"""A handout answerable from itself: every symbol a true-or-false statement uses is defined
on the handout, and 3.5's printed formulas, read literally on the printed data, are the key.

The symbols are read here from the rendered handout's text: each identifier of each
statement (i), (ii), (iii) must be a defined name (a name before ``:`` or ``=`` in a clause
of the handout's "Symbols:" sentence), an English word of the statement's prose (the
test's own short list), or a number.
"""

from __future__ import annotations

import html
import random
import re

import numpy as np
import pytest
import sympy as sp

from rigidsym.course.exam import handout_text, variants_module
from rigidsym.course.grading import grade

#: the prose words a statement may use beside its symbols
_WORDS = {"equals", "it", "is", "symmetric", "two", "small", "rotations", "commute",
          "exactly", "for", "every", "value", "of", "the", "symbols", "x", "and"}
_PROOFS = [i for i in variants_module().drawn() if i != "ex3.6"]


def _text(page: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


def _defined(text: str) -> set[str]:
    m = re.search(r"Symbols: (.*?)\. Reasons:", text, re.S)
    assert m, "the handout defines no symbols"
    names = set()
    for clause in m.group(1).split(";"):
        head = re.split(r"[:=]", clause, maxsplit=1)[0]
        names |= set(re.findall(r"[A-Za-z][A-Za-z0-9_]*", head))
    return names


@pytest.mark.parametrize("ex_id", _PROOFS, ids=[i[2:] for i in _PROOFS])
def test_every_symbol_of_a_statement_is_defined_on_the_handout(ex_id):
    mod = variants_module()
    for k in range(len(mod.statements(ex_id))):
        text = mod.statements(ex_id)[k][0]
        page = _text(handout_text("Quiz", [_one(ex_id, k)]))
        assert text in page
        defined = _defined(page)
        used = set(re.findall(r"[A-Za-z][A-Za-z0-9_]*", text))
        missing = sorted(u for u in used if u not in defined and u not in _WORDS)
        assert not missing, (ex_id, text, missing)


def _one(ex_id, k):
    """A drawn variant whose statements include statement ``k``."""
    for n in range(200):
        s = variants_module().draw(ex_id, random.Random(f"symbols {ex_id} {n}"))
        if k in [int(x) for x in s.data["statements"]]:
            return s
    pytest.skip(f"statement {k} of {ex_id} is never drawn (undecided)")


def test_35_read_literally_is_the_key():
    """3.5 on drawn data: p* = e x n and d = ||n|| computed from the printed data alone, as
    the handout says, are graded right (the data's e is a unit vector)."""
    from rigidsym.course.exam import _variant

    for n in range(6):
        s = _variant("ex3.5", random.Random(f"literal 3.5 {n}"))
        page = _text(handout_text("Quiz", [s]))
        assert "normalised" in page and "e is the unit vector" in page
        data = np.array([float(x) for x in s.data["plucker"]])
        e, m = data[:3], data[3:]
        assert abs(np.linalg.norm(e) - 1) < 1e-12
        answers = {"p_star": np.cross(e, m).tolist(), "d": float(np.linalg.norm(m))}
        assert all(g.correct for g in grade(s, answers)), [g.detail for g in grade(s, answers)]
        assert s.answers["d"] == sp.sqrt(sum(x**2 for x in s.data["plucker"][3:]))
