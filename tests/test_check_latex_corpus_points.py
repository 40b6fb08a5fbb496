"""A counterexample is the point it claims, over the typed-books corpora: every
does-not-hold's printed point satisfies the constraints its declarations state, read back
by this test alone (exact fractions): a unit vector's norm is 1, a rotation is orthogonal
with determinant 1, and a unit vector's printed rate is tangent (e · ė = 0)."""

from __future__ import annotations

import importlib.util
import re
from fractions import Fraction
from pathlib import Path

import pytest

import rigidsym
from rigidsym.registry import declarations as registry

DATA = Path(__file__).resolve().parent / "data"
SETS = ("latex_books_typed_a", "latex_books_typed_b", "estimation_books_typed",
        "lie_books_typed")
#: the kinds whose constraints a printed point must satisfy
KINDS = ("unit vector", "unit 4-vector", "rotation")


def _cases() -> dict:
    out = {}
    for name in SETS:
        spec = importlib.util.spec_from_file_location(name, DATA / f"{name}.py")
        m = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(m)
        for c in m.CASES:
            if c.get("slip") and any(re.search(r":\s*(" + "|".join(KINDS) + r")\s*$", x)
                                     for x in c["let"]):
                out[f"{name}:{c['id']}"] = c
    return out


CASES = _cases()
#: one case per kind in the quick run
FAST = {"lie_books_typed:k-rot-orth-slip"}


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _flat(key: str) -> str:
    """A glyph's LaTeX without fonts, braces, spaces and label parentheses: the printer's
    ``\\mathbf{C}_i^{(b)}`` and the typed ``C_i^b`` alike."""
    return re.sub(r"\\(?:mathbf|boldsymbol|bm)|[\s{}()]", "", key)


def _matrix(text: str) -> list[list[Fraction]]:
    rows = re.findall(r"\[([^\[\]]*)\]", text.replace("Matrix(", ""))
    return [[Fraction(x.strip()) for x in r.split(",")] for r in rows if r.strip()]


def _declared(lets) -> dict:
    """glyph (flattened LaTeX) -> its kind, of the constrained kinds."""
    out = {}
    for x in lets:
        m = re.match(r"^(.*?)(\(t\))?\s*:\s*(" + "|".join(KINDS) + r")\s*$", x.strip())
        if m:
            out[_flat(m[1])] = (m[3], bool(m[2]))
    return out


def _params():
    rest = (pytest.mark.slow,)
    return [pytest.param(k, marks=() if k in FAST else rest) for k in sorted(CASES)]


def test_the_corpora_hold_slips_of_constrained_kinds():
    assert len(CASES) >= 5, sorted(CASES)


@pytest.mark.parametrize("cid", _params())
def test_a_printed_counterexample_satisfies_its_declarations(cid):
    case = CASES[cid]
    try:
        r = rigidsym.check_latex(case["latex"], let=list(case["let"]), repairs=False)
    except ValueError:
        pytest.skip("refused: no point printed")
    if r.verdict != "does-not-hold" or not r.counterexample:
        pytest.skip(f"{r.verdict}: no point printed")
    declared = _declared(case["let"])
    values = {}
    for s in r.counterexample.get("symbols") or []:
        try:  # a rational value; one in sqrt, atan ... is no point of this check's
            values[_flat(s["latex"])] = _matrix(s["exact"]) \
                if s["exact"].startswith("Matrix") else [[Fraction(s["exact"])]]
        except (ValueError, KeyError, ZeroDivisionError):
            continue
    checked = [g for g in declared if g in values]
    assert checked, (cid, sorted(declared), sorted(values))  # the point gives them
    for glyph, (kind, timed) in declared.items():
        v = values.get(glyph)
        if v is None:
            continue
        if kind.startswith("unit"):
            e = [row[0] for row in v]
            assert sum(x * x for x in e) == 1, (cid, glyph, e)
            rate = values.get(_flat(rf"\dot{{{glyph}}}"))
            if timed and rate is not None:
                assert sum(a * row[0] for a, row in zip(e, rate, strict=True)) == 0, \
                    (cid, glyph, rate)
        else:
            n = len(v)
            for i in range(n):
                for j in range(n):
                    dot = sum(v[k][i] * v[k][j] for k in range(n))
                    assert dot == (1 if i == j else 0), (cid, glyph, v)
