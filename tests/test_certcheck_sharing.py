"""certcheck's sharing of work is exact: a division it cuts short is one that does not go,
two parses of one expression are one element, and relations with square roots of two
different radicands are each decided in a K(s) of their own."""

from __future__ import annotations

import sys
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "certcheck" / "src"))

from certcheck.field import Field, evaluate  # noqa: E402
from certcheck.parse import parse  # noqa: E402
from certcheck.poly import Ring  # noqa: E402

from certcheck import CheckError, check_certificate  # noqa: E402

_TERMS = st.dictionaries(st.tuples(*[st.integers(0, 3)] * 3), st.integers(-5, 5).filter(bool),
                         min_size=1, max_size=5)


def _poly(ring: Ring, terms: dict):
    out = ring.const(0)
    for exps, c in terms.items():
        m = ring.const(c)
        for i, e in enumerate(exps):
            m = m * ring.var(i) ** e
        out = out + m
    return out


@settings(max_examples=60, deadline=None)
@given(_TERMS, _TERMS)
def test_exact_division_recovers_the_quotient_and_refuses_a_remainder(qt, ft):
    ring = Ring(["x", "y", "z"])
    q, f = _poly(ring, qt), _poly(ring, ft)
    if ring.is_zero(q) or ring.is_zero(f):
        return
    f = ring.scale_div(f, ring.content(f))  # primitive, as the field's factors are
    assert ring.divexact(q * f, f) == q
    if ring.constant(f) is None:  # a non-unit f never divides q f + 1
        assert ring.divexact(q * f + ring.const(1), f) is None


def test_one_expression_parsed_twice_is_one_element():
    ring = Ring(["x", "y"])
    F = Field(ring)
    memo: dict = {}

    def leaf(name):
        return F.var(["x", "y"].index(name))
    text = "(x + y)^3 / (x^2 + 1) - x*y"
    a = evaluate(parse(text), F, leaf, None, memo)
    b = evaluate(parse(text), F, leaf, None, memo)
    assert a is b
    c = evaluate(parse("x*y - x*y"), F, leaf, None, memo)
    assert F.is_zero(c)


def _two_roots(rhs2: str) -> dict:
    atoms = [{"group": n, "kind": "free", "names": [n], "timed": False} for n in "xy"]
    rel = [{"label": "a", "role": "printed", "lhs": [["sqrt(x^2 + 1)^2"]],
            "rhs": [["x^2 + 1"]], "evidence": {"type": "identity"}},
           {"label": "b", "role": "printed", "lhs": [["sqrt(y)*sqrt(y)*x"]],
            "rhs": [[rhs2]], "evidence": {"type": "identity"}}]
    return {"format": "rigidsym-certificate", "version": 1, "id": "t", "verdict": "verified",
            "atoms": atoms, "let": [], "relations": rel}


def test_square_roots_of_two_radicands_each_in_their_own_field():
    verdict, lines = check_certificate(_two_roots("x*y"), fast=False)
    assert verdict == "verified" and sum("identity" in x for x in lines) == 2
    try:
        check_certificate(_two_roots("x*y + 1"), fast=False)
    except CheckError as exc:
        assert "not zero" in str(exc)
    else:
        raise AssertionError("x y + 1 passed as sqrt(y)^2 x")
