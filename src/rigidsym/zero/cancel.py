"""``sympy.cancel`` through FLINT: the same canonical fractions, computed faster.

Derivations bring models to lowest terms with ``sympy.cancel`` (exact, and it keeps the
expressions small). On a large rational function most of that time goes into sympy's
expansion and gcd; here the fraction is reduced first with python-flint's multivariate
polynomials (:func:`rigidsym.zero.program.run_rational`), and ``sympy.cancel``'s own last
step (sympy's polynomial ring over the integers, its gcd and its sign rule) brings the
small, already reduced fraction to its canonical form: coprime numerator and denominator
over Z in the sorted generators, the denominator's leading coefficient positive. That form
is unique, so the result is the expression ``sympy.cancel`` itself returns (a test compares
them on the models that use this). Anything that is not a rational function of its
atoms (a square root, a trigonometric function) goes to ``sympy.cancel`` unchanged.
"""

from __future__ import annotations

import math

import flint
import sympy as sp

from rigidsym.zero.plan import Unsupported
from rigidsym.zero.program import TooLarge, run_rational, unparametrised

__all__ = ["cancel", "cancel_matrix"]


def _to_expr(poly, leaves: list, scale: int) -> sp.Expr:
    """``scale`` times a ``fmpq_mpoly`` as a sympy polynomial in ``leaves``."""
    terms = []
    for exps, c in poly.to_dict().items():
        mono = [x**e for x, e in zip(leaves, exps, strict=True) if e]
        terms.append(sp.Mul(sp.Integer(int(c.p) * scale // int(c.q)), *mono))
    return sp.Add(*terms)


def _canonical(num, den, leaves: list) -> sp.Expr:
    """``sympy.cancel``'s own last step on a fraction of ``fmpq_mpoly``: both scaled to
    integer coefficients, turned into sympy's ring (the sorted generators ``sympy.cancel``
    takes), reduced there (a small gcd: FLINT has removed the common factors already) and
    made canonical (the denominator's leading coefficient positive)."""
    from sympy.polys.rings import sring

    dens = [int(c.q) for p in (num, den) for c in p.coeffs()]
    scale = 1
    for q in dens:
        scale = scale * q // math.gcd(scale, q)
    _, (f, g) = sring((_to_expr(num, leaves, scale), _to_expr(den, leaves, scale)))
    p, q = f.cancel(g)
    return p.as_expr() / q.as_expr()


def cancel(exprs) -> list:
    """``[sympy.cancel(e) for e in exprs]``, the fractions reduced by FLINT first.

    Args:
        exprs: sympy scalar expressions (rational functions of their atoms, else they go
            to ``sympy.cancel`` as they are).

    Returns:
        The list of cancelled expressions, each equal (as an expression tree) to
        ``sympy.cancel`` of the input.
    """
    exprs = [sp.sympify(e) for e in exprs]
    try:
        prog = unparametrised(exprs)
        if not prog.leaves:
            raise Unsupported("constants")
        ctx = flint.fmpq_mpoly_ctx.get([f"x{i}" for i in range(len(prog.leaves))],
                                       "degrevlex")
        fractions = run_rational(prog, ctx)
    except (Unsupported, TooLarge, ZeroDivisionError):
        return [sp.cancel(e) for e in exprs]
    return [_canonical(n, d, prog.leaves) for n, d in fractions]


def cancel_matrix(m) -> sp.Matrix:
    """:func:`cancel` of every entry of a matrix.

    Args:
        m: a sympy matrix (any shape) of rational functions.

    Returns:
        A new mutable matrix of the same shape, equal entry by entry (as expression trees)
        to ``m.applyfunc(sympy.cancel)``.
    """
    m = sp.Matrix(m)
    return sp.Matrix(m.rows, m.cols, cancel(list(m)))
