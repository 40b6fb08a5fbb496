"""Exact evaluation of a planned expression (:mod:`rigidsym.zero.decide`, steps 2-4): at rational
points with ``Fraction``, to a rational function over Q, and a bound on its degree.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.zero.plan import TRIG, Plan, Unsupported, linear_angles, walk_tree


# --------------------------------------------------------------------------- evaluation
def _cis(tau, k: int, one):
    """(cos(2k atan tau), sin(2k atan tau)) as exact values: ((1 + i tau)^2/(1+tau^2))^k."""
    d = one + tau * tau
    c, s = (one - tau * tau) / d, 2 * tau / d
    re, im = one, 0 * one
    base_re, base_im = (c, s) if k >= 0 else (c, -s)
    for _ in range(abs(k)):
        re, im = re * base_re - im * base_im, re * base_im + im * base_re
    return re, im


def _power(x, ev, one, lift):
    """``b**n`` at the point: integer ``n`` in the number type, a rational ``n`` only with
    ``Fraction`` (an exact root, or :class:`Unsupported`)."""
    b, n = x.args
    if n.is_Integer:
        bv = ev(b)
        n = int(n)
        if n < 0:
            if bv == 0:
                raise ZeroDivisionError(str(x))
            return (one / bv) ** (-n)
        return bv**n
    if n.is_Rational and lift is Fraction:
        return rational_root(ev(b), int(n.p), int(n.q))
    bv = ev(b) if n.is_Rational else None
    if isinstance(bv, sp.Rational):  # a counterexample's values (sympy numbers): ‖ω̂‖ = 2
        try:
            r = rational_root(Fraction(int(bv.p), int(bv.q)), int(n.p), int(n.q))
        except Unsupported:  # an irrational norm shown in closed form (√21/4), exact
            return bv**n if bv >= 0 or n.q % 2 else _unsupported(x)
        return sp.Rational(r.numerator, r.denominator)
    raise Unsupported(f"power {x}")


def _unsupported(x):
    raise Unsupported(f"even root of a negative number: {x}")


def _trig(x, plan: Plan, point: dict, one):
    """A trigonometric function of a rational combination of angles (plus a multiple of
    pi/2) at the point: exact, through the half-angle tangents of the plan."""
    coeffs, cpi = linear_angles(x.args[0])
    re, im = one, 0 * one
    for a, c in coeffs.items():
        tau, M = plan.angles[a]
        k = int(c * M)
        cr, ci = _cis(point[tau], k, one)
        re, im = re * cr - im * ci, re * ci + im * cr
    # rotation by cpi * pi, cpi a multiple of 1/2
    q = int(2 * cpi) % 4
    for _ in range(q):
        re, im = -im, re
    f = x.func
    if f is sp.cos:
        return re
    if f is sp.sin:
        return im
    num, den = {sp.tan: (im, re), sp.cot: (re, im), sp.sec: (one, re),
                sp.csc: (one, im)}[f]
    if den == 0:
        raise ZeroDivisionError(str(x))
    return num / den


def _numeric_argument(arg, plan: Plan) -> bool:
    """Whether a trigonometric argument has no angle of the plan in it (its value at a point
    is a number, such as a norm, not a combination of half-angle tangents)."""
    return not any(a in plan.angles for a in sp.sympify(arg).atoms(sp.Symbol, AppliedUndef))


def evaluate(expr, plan: Plan, point: dict, lift=Fraction, bare_value=None):
    """Evaluate ``expr`` exactly at ``point`` (parameter symbol -> value).

    Args:
        expr: a sympy expression built from the plan's atoms.
        plan: from :func:`make_plan`.
        point: values of ``plan.params`` (``Fraction`` by default).
        lift: converts a sympy Rational to the number type (``Fraction``, ``sp.Rational``…);
            with sympy numbers, a trigonometric function of an argument free of angles
            (a norm) is kept in closed form at its exact argument (``sin(2)``).
        bare_value: optional ``angle atom -> value`` overriding the bare-angle variable
            (used to make a counterexample consistent: ``phi = 2M atan(tau)``).

    Raises:
        Unsupported: for a node the exact evaluator cannot treat.
        ZeroDivisionError: where a denominator vanishes at the point.
    """
    memo: dict = {}
    one = lift(sp.Integer(1))

    def ev(x):
        r = memo.get(x)
        if r is not None:
            return r
        r = _ev(x)
        memo[x] = r
        return r

    def _ev(x):
        if x.is_Rational:
            return lift(x)
        if x in point:
            return point[x]
        if bare_value is not None and x in bare_value:
            return bare_value[x]
        if x == sp.pi or isinstance(x, sp.Symbol | AppliedUndef | sp.Derivative):
            rule = plan.rules.get(x)
            if rule is None or rule == x:
                raise Unsupported(f"no value for atom {x}")
            return ev(rule)
        if isinstance(x, sp.Add):
            acc = 0 * one
            for a in x.args:
                acc = acc + ev(a)
            return acc
        if isinstance(x, sp.Mul):
            acc = one
            for a in x.args:
                acc = acc * ev(a)
            return acc
        if isinstance(x, sp.Pow):
            return _power(x, ev, one, lift)
        if isinstance(x, sp.Abs):
            return abs(ev(x.args[0]))
        if isinstance(x, TRIG):
            if lift is not Fraction and _numeric_argument(x.args[0], plan):
                # sin of a rational norm (a counterexample of rational norm,
                # rigidsym.zero.polar): a closed form, sin(2), exact and not rational
                v = ev(x.args[0])
                if isinstance(v, sp.Expr) and v.is_number:
                    return x.func(v)
            return _trig(x, plan, point, one)
        raise Unsupported(f"an operator the exact evaluator does not take "
                          f"({type(x).__name__.lower()})")

    return ev(sp.sympify(expr))


def rational_root(v: Fraction, p: int, q: int) -> Fraction:
    """``v ** (p/q)`` exactly, for a rational ``v`` whose ``q``-th root is rational.

    Raises:
        Unsupported: an even root of a negative number, or an irrational root."""
    if v < 0 and q % 2 == 0:
        raise Unsupported("even root of a negative number")
    sgn = -1 if v < 0 else 1
    num, den = abs(v.numerator), v.denominator
    rn, rd = _iroot(num, q), _iroot(den, q)
    if rn is None or rd is None:
        raise Unsupported("irrational root at the sample point")
    return (Fraction(sgn * rn, rd)) ** p


def _iroot(n: int, q: int):
    r = round(n ** (1.0 / q)) if n < 2**1000 else None
    if r is None:
        return None
    for c in (r - 1, r, r + 1):
        if c >= 0 and c**q == n:
            return c
    return None


def to_rational(expr, plan: Plan):
    """The parametrised expression: a rational function over Q of ``plan.params``."""
    memo: dict = {}

    def tr(x):
        if x in memo:
            return memo[x]
        if x.is_Rational or (x.is_Atom or isinstance(x, AppliedUndef | sp.Derivative)) and \
                x not in plan.rules:
            r = x
        elif x in plan.rules:
            r = plan.rules[x]
            r = r if r == x else tr(r)
        elif isinstance(x, TRIG):
            r = evaluate(x, plan, {tau: tau for tau, _ in plan.angles.values()},
                         lift=lambda v: v)
        elif x.args:
            r = x.func(*[tr(a) for a in x.args])
        else:
            raise Unsupported(f"an operator the exact evaluator does not take "
                          f"({type(x).__name__.lower()})")
        memo[x] = r
        return r

    return tr(sp.sympify(expr))


def degree_bound(expr, plan: Plan) -> int:
    """Upper bound on the total degree of the numerator of the parametrised expression."""
    memo: dict = {}

    def db(x) -> tuple[int, int]:
        if x in memo:
            return memo[x]
        if x.is_Rational:
            r = (0, 0)
        elif isinstance(x, sp.Symbol | AppliedUndef | sp.Derivative):
            rule = plan.rules.get(x, x)
            r = (1, 0) if rule == x or isinstance(rule, sp.Symbol) else db(rule)
        elif x == sp.pi:
            r = (1, 0)
        elif isinstance(x, sp.Add):
            ds = [db(a) for a in x.args]
            tot = sum(d for _, d in ds)
            r = (max(n + tot - d for n, d in ds), tot)
        elif isinstance(x, sp.Mul):
            ds = [db(a) for a in x.args]
            r = (sum(n for n, _ in ds), sum(d for _, d in ds))
        elif isinstance(x, sp.Pow) and x.args[1].is_Integer:
            n, d = db(x.args[0])
            k = int(x.args[1])
            r = (k * n, k * d) if k >= 0 else (-k * d, -k * n)
        elif isinstance(x, TRIG):
            coeffs, _ = linear_angles(x.args[0])
            deg = sum(2 * abs(int(c * plan.angles[a][1])) for a, c in coeffs.items())
            r = (deg, deg)
        else:  # |f| too: not a rational function, so Schwartz-Zippel says nothing of it
            raise Unsupported(f"degree of {x}")
        memo[x] = r
        return r

    return db(sp.sympify(expr))[0]


def tree_size(expr, limit: int) -> int:
    """Node count of ``expr``, counting stops past ``limit``."""
    n = 0

    def visit(x):
        nonlocal n
        n += 1
        return n <= limit

    walk_tree(expr, visit)
    return n
