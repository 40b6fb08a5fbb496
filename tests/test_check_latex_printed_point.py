"""A counterexample is the point it claims: the printed point, substituted into both sides by
an evaluator of this test's own (exact fractions, no rigidsym), gives the printed sides and
satisfies every constraint the reading states; a unit vector's rate is printed tangent to
the sphere (e · ė = 0), the value the check used."""

from __future__ import annotations

from fractions import Fraction

import pytest

import rigidsym
from rigidsym.registry import declarations as registry

E = [r"\mathbf{e}(t): unit vector"]


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _vec(point: dict, name: str) -> list[Fraction]:
    return [Fraction(point[f"{name}_{i}"]) for i in (1, 2, 3)]


def _rows(text: str) -> list[Fraction]:
    # sympy's str of a column, Matrix([[a], [b], [c]]) printed row by row
    inner = text.replace("Matrix(", "").replace("[", " ").replace("]", " ").replace(")", " ")
    return [Fraction(x) for x in inner.replace(",", " ").split()]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


@pytest.mark.parametrize("latex, lets, sides", [
    (r"\dot{\mathbf{e}} = \mathbf{e}", E, lambda p: (_vec(p, "edot"), _vec(p, "e"))),
    (r"\dot{\mathbf{e}} = \boldsymbol\omega\times\mathbf{e}", E + [r"\boldsymbol\omega: vector"],
     lambda p: (_vec(p, "edot"), _cross(_vec(p, "omega"), _vec(p, "e")))),
])
def test_the_printed_point_gives_the_printed_sides_and_a_tangent_rate(latex, lets, sides):
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == "does-not-hold"
    p = r.counterexample["point"]
    e, edot = _vec(p, "e"), _vec(p, "edot")
    assert sum(x * x for x in e) == 1  # the unit vector, exactly
    assert sum(x * y for x, y in zip(e, edot, strict=True)) == 0  # its rate tangent
    lhs, rhs = sides(p)
    assert lhs == _rows(r.counterexample["lhs"]) and rhs == _rows(r.counterexample["rhs"])
    assert lhs != rhs
    printed = next(s for s in r.counterexample["symbols"] if s["latex"] == r"\dot{\mathbf{e}}")
    assert _rows(printed["exact"]) == edot
