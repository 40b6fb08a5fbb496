"""A does-not-hold never contradicts its counterexample.

A verdict does-not-hold rests on an exact non-zero residual backed by a ball, or on a shape
mismatch that the shape rules establish from nodes whose shapes they know; a node the
engine does not know is refused when the relation is made.
"""

from __future__ import annotations

import pytest
import sympy as sp
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym import (
    Blocks,
    Cross,
    Det,
    Rel,
    Statement,
    angle,
    cpm,
    equation,
    mat,
    rotation_from_natural_invariants,
    trace,
    unit_vector,
    vec,
    vect,
    vector,
)
from rigidsym.algebra.operators import Diff
from rigidsym.checking.checker import check
from rigidsym.checking.deciding.explicit import UnknownShape, shape_of
from rigidsym.registry.declarations import REGISTRY, BadInput

w, theta = unit_vector("nc_w"), angle("nc_theta")
a_ = vector("nc_a")
R, Omega, a = mat("R"), mat("Omega"), vec("a")
MODEL = {R: rotation_from_natural_invariants(w, theta), Omega: cpm(w), a: a_}


@pytest.fixture(autouse=True)
def _forget():
    yield
    for k in [k for k in REGISTRY if k.startswith("nc:")]:
        del REGISTRY[k]


def _verdict(eq_id: str, printed: list[Rel], model: dict = MODEL) -> str:
    equation(eq_id, eq_id)(lambda: Statement(printed, model))
    return check(eq_id, repairs=False, expanded=False).verdict


def test_the_derivative_probe_is_verified():
    # dR/dθ = [ω] R for Rodrigues' R (MR (3.51)-(3.52)); it was does-not-hold, with a
    # counterexample whose two sides were equal ("shape mismatch: 1x1 vs 3x3")
    assert _verdict("nc:probe", [Rel(sp.Derivative(R, theta), Omega * R)]) == "verified"


def test_a_false_derivative_is_does_not_hold_on_values():
    # the transposed product is false: the verdict rests on a residual, not on a shape
    equation("nc:false", "nc:false")(
        lambda: Statement([Rel(sp.Derivative(R, theta), R * Omega.T)], MODEL))
    out = check("nc:false", repairs=False)
    assert out.verdict == "does-not-hold"
    assert out.counterexample["residual"] not in ("0", "Matrix([\n[0, 0, 0],\n[0, 0, 0],\n"
                                                         "[0, 0, 0]])")
    assert "shape" not in out.detail


def test_a_matrix_derivative_inside_an_expression_is_refused():
    # sympy's Derivative of a matrix symbol is a shapeless scalar to sympy: 2 dR/dθ is a
    # Mul, and sin(θ) dR/dθ is not even matrix-kinded; the shape rules read both as 1 x 1
    for node in (2 * sp.Derivative(R, theta), sp.sin(theta) * sp.Derivative(R, theta)):
        with pytest.raises(BadInput, match=r"Derivative.*rigidsym\.diff"):
            Rel(node, Omega)
    with pytest.raises(UnknownShape):
        shape_of(2 * sp.Derivative(R, theta))


@pytest.mark.parametrize("node, word", [
    (sp.exp(theta * Omega), "rigidsym.expm"),
    (sp.Function("f", real=True)(theta), "rigidsym.scalar"),
    (sp.acot(theta), "rigidsym.atan2"),   # (asin: decided on its principal branch)
])
def test_unknown_nodes_are_refused_naming_the_word(node, word):
    with pytest.raises(BadInput) as err:
        Rel(node, 1)
    assert type(node).__name__ in str(err.value) and word in str(err.value)


def test_an_undefined_function_of_time_stays_a_free_atom():
    f = sp.Function("nc_f", real=True)(sp.Symbol("t", real=True))
    Rel(f, f)  # scalar(name, t=TIME): accepted


# ------------------------------------------------------------------ property over the nodes
def _leaf_matrix(i: int):
    return [R, Omega, R.T, sp.Identity(3), Diff(R, theta), cpm(a)][i]


def _build(ops: list[int], leaves: list[int]):
    """A 3 x 3 printed form through the supported nodes, from drawn choices."""
    ops_ = [lambda x, y: x * y, lambda x, y: x + y, lambda x, y: x.T,
            lambda x, y: x - 2 * y, lambda x, y: sp.sin(theta) * x, lambda x, y: x ** 2,
            lambda x, y: x * y.T, lambda x, y: cpm(Cross(a, vect(x + R))),
            lambda x, y: cpm(x * a), lambda x, y: trace(x) * y,
            lambda x, y: sp.cos(theta) ** 2 * x, lambda x, y: Diff(x, theta)]
    x = _leaf_matrix(leaves[0])
    for op, leaf in zip(ops, leaves[1:], strict=False):
        x = ops_[op](x, _leaf_matrix(leaf))
    return x


@settings(max_examples=examples(12), deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.integers(0, 11), min_size=1, max_size=3),
       st.lists(st.integers(0, 5), min_size=4, max_size=4))
def test_true_identities_through_every_node_never_do_not_hold(ops, leaves):
    printed = _build(ops, leaves)
    # the other side computed by sympy's generic path, independently of the checker's
    truth = sp.Matrix(printed.xreplace(MODEL).doit())
    truth = truth.applyfunc(lambda z: sp.expand(z.doit()))  # not the checker's trees
    blocks = Blocks([[printed, sp.ZeroMatrix(3, 1)], [sp.ZeroMatrix(1, 3), sp.Identity(1)]])
    rels = [Rel(printed, truth), Rel(blocks[0, 0], truth[0, 0]),
            Rel(sp.Derivative(R, theta), MODEL[R].diff(theta)), Rel(Det(R), 1)]
    for k in [k for k in REGISTRY if k.startswith("nc:")]:
        del REGISTRY[k]
    assert _verdict("nc:prop", rels) != "does-not-hold"


def test_repairs_are_ranked_as_a_reader_fixes():
    # Ω = (R − Rᵀ)/sin θ drops a ½ (MR (3.53)): "insert −Ω" (the same equation, moved) and
    # "a 2 on Ω" are true edits, but the ½ on the formula's side comes first (docs/repairs.md)
    tp = angle("nc_tp", range="[0, pi]")
    model = {R: rotation_from_natural_invariants(w, tp), Omega: cpm(w)}
    equation("nc:half", "nc:half", expected="does-not-hold")(
        lambda: Statement([Rel(Omega, (R - R.T) / sp.sin(tp))], model))
    out = check("nc:half")
    assert out.verdict == "does-not-hold" and out.correction == "found by search"
    kinds = [r["kinds"] for r in out.repairs]
    assert kinds[0] == ["scale-term"] and "1/2" in out.repairs[0]["edits"][0], out.repairs[0]
    # the 2 on Ω (the defined symbol's side) and the moved equation come after
    assert out.repairs[1]["text"].startswith("⟦2⟧ Ω")
    assert kinds.index(["insert-term"]) > 1
