"""rigidsym.zero.cancel: the expressions sympy.cancel returns, reduced by FLINT first."""

import pytest
import sympy as sp

from rigidsym.algebra.primitives import rotation_from_quaternion
from rigidsym.zero.cancel import cancel, cancel_matrix

x, y, z, s = sp.symbols("x y z s", real=True)


def _same(a, b) -> bool:
    return sp.srepr(a) == sp.srepr(b)


def test_equals_sympy_cancel_as_a_tree():
    exprs = [
        (x**2 - y**2) / (x - y),  # a common factor
        (2 * x + 4) / (6 * x * y + 12 * y),  # integer content on both sides
        sp.Rational(3, 7) * x / (sp.Rational(5, 2) * y - x),  # rational coefficients
        -x / (-y - 1),  # the denominator's leading coefficient made positive
        (x * s + y * s) / (s * (x + y) * z),  # a symbol that cancels out entirely
        1 / x + 1 / y - (x + y) / (x * y),  # zero
        x**3 / 5,  # a constant denominator
        (x + 1) ** 4 / (x**2 - 1) ** 2,
    ]
    for e, c in zip(exprs, cancel(exprs), strict=True):
        assert _same(c, sp.cancel(e)), e


def test_rotation_products_equal_sympy_cancel():
    q = sp.symbols("q1:5", real=True)
    u = sp.symbols("u1:5", real=True)
    t = sp.Symbol("t", real=True)
    R = rotation_from_quaternion([a + t * b for a, b in zip(q, u, strict=True)])
    Rd = R.diff(t).subs(t, 0)
    R0 = R.subs(t, 0)
    prod = Rd * R0.T
    fast = cancel_matrix(prod)
    assert all(_same(a, sp.cancel(b)) for a, b in zip(fast, prod, strict=True))


def test_not_a_rational_function_goes_to_sympy():
    exprs = [sp.sqrt(x) * (x**2 - 1) / (x - 1), sp.cos(x) / sp.cos(x) + y, sp.Integer(3)]
    for e, c in zip(exprs, cancel(exprs), strict=True):
        assert _same(c, sp.cancel(e)), e


def test_the_declaration_vocabulary_cancels_as_sympy_does():
    # rigidsym.declare.cancel_matrix: what the book's models and a reader's module use
    import sympy as sp

    from rigidsym.declare import cancel_matrix as public

    x, y = sp.symbols("x y", real=True)
    m = sp.Matrix([[(x**2 - y**2) / (x - y), 1 / x + 1 / y], [sp.sin(x) / sp.sin(x), 3]])
    assert public(m) == m.applyfunc(sp.cancel) == sp.Matrix([[x + y, (x + y) / (x * y)],
                                                             [1, 3]])


@pytest.mark.parametrize("bad", ["x", None, 3])
def test_cancel_matrix_names_its_argument(bad):
    from rigidsym.declare import cancel_matrix

    with pytest.raises(TypeError, match="^m: expected a sympy matrix"):
        cancel_matrix(bad)
