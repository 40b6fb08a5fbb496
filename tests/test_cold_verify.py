"""The cold path of ``rigidsym verify`` made cheaper without changing what it
computes: each shortcut gives the very expressions sympy's own route gives."""

from __future__ import annotations

import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.checking.deciding.explicit import matmul

_X, _Y, _Z = sp.symbols("x y z", real=True)
_ENTRIES = st.sampled_from([
    sp.S.Zero, sp.S.One, sp.Integer(-2), sp.Rational(1, 3), _X, _Y, _X * _Y - 1,
    sp.cos(_Z), 1 / (_X**2 + 1), sp.sqrt(_Y**2 + 1), sp.Float(0.0),
])


def _matrix(rows: int, cols: int, entries=_ENTRIES):
    return st.lists(entries, min_size=rows * cols, max_size=rows * cols).map(
        lambda v: sp.ImmutableMatrix(rows, cols, v))


@st.composite
def _pair(draw, entries=_ENTRIES):
    n, k, m = (draw(st.integers(1, 4)) for _ in range(3))
    return draw(_matrix(n, k, entries)), draw(_matrix(k, m, entries))


@settings(max_examples=examples(30), deadline=None)
@given(_pair())
def test_matmul_gives_sympys_product_entry_for_entry(ab):
    a, b = ab
    got, want = matmul(a, b), a * b
    assert got.shape == want.shape
    for g, w in zip(got, want, strict=True):
        assert g == w  # the same expression, not only an equal value


@settings(max_examples=examples(20), deadline=None)
@given(_pair(st.sampled_from([sp.S.Zero, sp.S.One, _X, sp.oo, sp.zoo, -sp.oo, sp.nan])))
def test_matmul_with_infinities_is_sympys_product(ab):
    a, b = ab  # 0 * oo is nan: sympy's product, taken as such
    got, want = matmul(a, b), a * b
    assert [str(g) for g in got] == [str(w) for w in want]


def test_matmul_refuses_shapes_that_do_not_fit():
    import pytest

    with pytest.raises(sp.ShapeError):
        matmul(sp.ImmutableMatrix([[1, 2]]), sp.ImmutableMatrix([[1, 2]]))


_TREES = st.recursive(
    st.sampled_from([_X, _Y, _Z, sp.Integer(2), sp.Rational(1, 2)]),
    lambda c: st.one_of(
        st.tuples(c, c).map(lambda t: t[0] + t[1]), st.tuples(c, c).map(lambda t: t[0] * t[1]),
        c.map(sp.acos), c.map(sp.sqrt), st.tuples(c, c).map(lambda t: sp.atan2(*t)),
        c.map(sp.asin), c.map(lambda e: e ** -1)),
    max_leaves=12)


@settings(max_examples=examples(40), deadline=None)
@given(st.lists(_TREES, min_size=1, max_size=4))
def test_nodes_are_sympys_atoms(exprs):
    from rigidsym.checking.deciding.branches import _nodes

    types = (sp.acos, sp.asin, sp.atan2, sp.Pow)
    want = set().union(*(e.atoms(*types) for e in exprs))
    assert _nodes(exprs, types) == want
