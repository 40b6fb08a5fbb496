"""The evidence behind a verdict (:mod:`rigidsym.checking.checker`): the ball-arithmetic
backing of the unparametrised relations at seeded points (:mod:`rigidsym.checking.deciding.balls`),
and a readable exact counterexample with its ball.
"""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp

from rigidsym.algebra.symbols import constraint_of
from rigidsym.checking.deciding.balls import (
    Backing,
    backing,
    ball_at,
)
from rigidsym.checking.deciding.explicit import entries_of, explicit, shape_of
from rigidsym.registry.declarations import Rel
from rigidsym.zero.decide import Unsupported, evaluate, make_plan
from rigidsym.zero.polar import norm_vectors

__all__ = ["numeric_backing", "counterexample_ball", "rational_norm_witness",
           "RATIONAL_DIRECTIONS"]

#: unit directions with rational entries, from the Pythagorean quadruples
#: 1 + 4 + 4 = 9, 4 + 9 + 36 = 49, 1 + 16 + 64 = 81: a free 3-vector ``s d`` (``s`` a
#: positive rational) has the rational norm ``s``
RATIONAL_DIRECTIONS = ((1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9))
#: the values a counterexample's parameters are drawn from (small rationals: readable)
SMALL_RATIONALS = tuple(Fraction(n, d) for n in range(-3, 4) for d in (1, 2, 3))
#: the norms tried (positive rationals, small: a readable counterexample)
RATIONAL_NORMS = (Fraction(1), Fraction(1, 2), Fraction(2), Fraction(3, 2), Fraction(1, 3),
                  Fraction(3))


# --------------------------------------------------------------------------- numeric
def numeric_backing(rels: list[Rel], model: dict, seed: int,
                    points: int | None = None) -> Backing:
    """Ball-arithmetic backing of ``lhs - rhs`` for every relation (same shapes), at
    ``points`` seeded constraint-satisfying points (default ``ENGINE.numeric_points``,
    :mod:`rigidsym.core.settings`; :func:`rigidsym.checking.deciding.balls.backing`).

    Raises:
        Unsupported: for a node with no numeric meaning.
    """
    lhs = [e for r in rels for e in entries_of(explicit(r.lhs, model))]
    rhs = [e for r in rels for e in entries_of(explicit(r.rhs, model))]
    return backing(lhs, rhs, make_plan(lhs + rhs), seed, points)


# --------------------------------------------------------------------------- counterexample
def small_witness(entries, plan, seed):
    """Look for a counterexample point with small rationals (readable), exactly checked;
    ``None`` at once where the norm of a free vector is under sin/cos (its sine at such a
    point has no exact rational value: :func:`rational_norm_witness` finds those points)."""
    if norm_vectors(entries):  # sin of an irrational norm: no exact value, never readable
        return None
    rng = random.Random(seed)
    # a fixed number of tries, never a clock: under load a deadline picked another point and
    # made the committed report depend on the machine (each try takes about a millisecond)
    for _ in range(300):
        pt = in_range(plan, {p: rng.choice(SMALL_RATIONALS) for p in plan.params})
        try:
            if any(evaluate(e, plan, pt) != 0 for e in entries) and _consistent(entries,
                                                                                plan, pt):
                return pt
        except (ZeroDivisionError, Unsupported):
            continue
    return None


def _consistent(entries, plan, pt) -> bool:
    """Whether the point is still a counterexample once each bare angle takes its own
    value ``2M atan(tau)`` (the zero test treats a bare angle as a variable of its own, so
    ``theta = acos(cos theta)`` is non-zero at ``theta = 1/2, tau = 0``, where the angle is
    0 and both sides vanish): the point shown must be one where the sides differ."""
    # computed in every case: a point where a side is undefined once the bare angles take
    # their values (tan theta at theta = pi/2) raises here and the search goes on
    vals = [_exact_value(e, plan, pt) for e in entries]
    if not any(a in plan.angles for a in plan.bare):
        return True
    return any(abs(float(sp.N(v, 30))) > 1e-12 for v in vals)


def in_range(plan, pt: dict) -> dict:
    """``pt`` with the half-angle tangent ``tau = tan(a / 2M)`` of every angle ``a`` on
    ``[0, pi]`` brought into range: ``|tau|`` for ``M = 1``, ``|tau| / (M (1 + |tau|)) <
    1 / M < tan(pi / 2M)`` above (a counterexample is a point of the declared domain)."""
    out = dict(pt)
    for a, (tau, m) in plan.angles.items():
        c = constraint_of(a)
        if c is not None and c.kind == "angle_pi" and tau in out:
            t = abs(out[tau])
            out[tau] = t if m == 1 else t / (m * (1 + t))
    return out


def _exact_value(x, plan, pt):
    """Exact value at a witness point; bare angles take their consistent value 2M atan(tau)."""
    bare = {a: 2 * plan.angles[a][1] * sp.atan(sp.Rational(pt[plan.angles[a][0]]))
            for a in plan.bare if a in plan.angles}
    bare.update({a: sp.Rational(pt[s]) for a, s in plan.bare.items() if a not in bare})
    # a bare angle is its own variable in the zero test (independent of its tangent);
    # the values shown are the consistent ones, 2M atan(tau), as the balls use
    own = {plan.bare[a] for a in bare if a in plan.angles}
    spt = {k: sp.Rational(v.numerator, v.denominator) for k, v in pt.items() if k not in own}

    def one(e):
        return evaluate(e, plan, spt, lift=lambda v: v, bare_value=bare)

    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x.rows, x.cols, [one(e) for e in x])
    return one(x)


def exact_counterexample(lhs, rhs, witness, seed, extra=()) -> tuple[dict, object, dict]:
    """The readable counterexample record, with the plan and the exact parameter point
    (``extra``: expressions whose atoms the plan must also give values, the ball's)."""
    plan = make_plan(entries_of(lhs) + entries_of(rhs) + list(extra))
    diff = [a - b for a, b in zip(entries_of(lhs), entries_of(rhs), strict=True)] \
        if shape_of(lhs) == shape_of(rhs) else []
    pt = small_witness(diff, plan, seed) if diff else None
    if pt is None:  # keep the proven witness; parameters it does not mention get 1/2
        pt = in_range(plan, {p: witness.get(p, Fraction(1, 2)) for p in plan.params})
    point = {}
    for atom, rule in sorted(plan.rules.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if atom in plan.bare:
            continue
        v = evaluate(rule, plan, pt) if rule != atom else pt[atom]
        point[sp.sstr(atom)] = str(v)
    for a, (tau, M) in plan.angles.items():
        # evaluated where it is a number ("ψ = 0", "-pi/2", never "2*atan(0)")
        point[sp.sstr(a)] = sp.sstr(2 * M * sp.atan(sp.Rational(pt[tau].numerator,
                                                                pt[tau].denominator)))
    lv, rv = _exact_value(lhs, plan, pt), _exact_value(rhs, plan, pt)
    if isinstance(lv, sp.MatrixBase) != isinstance(rv, sp.MatrixBase):
        # a 1 x 1 matrix (a^T b) against a scalar: shape_of calls both 1 x 1
        lv, rv = (x[0, 0] if isinstance(x, sp.MatrixBase) else x for x in (lv, rv))
    ce = {"point": point, "lhs": sp.sstr(lv), "rhs": sp.sstr(rv)}
    if shape_of(lhs) == shape_of(rhs):
        ce["residual"] = sp.sstr(lv - rv)
    return ce, plan, pt


def counterexample_ball(lhs, rhs, plan, pt) -> tuple[bool, str, int]:
    """``lhs - rhs`` in ball arithmetic at the counterexample
    (:func:`rigidsym.checking.deciding.balls.ball_at`): ``(excludes_zero, ball text, digits)``."""
    return ball_at(entries_of(lhs), entries_of(rhs), plan, pt)


def rational_norm_witness(lhs, rhs, seed: int, extra=(), tries: int = 36) -> dict | None:
    """An exact point where ``lhs`` and ``rhs`` differ, proven by ball arithmetic, for sides
    that hold the norm of a free 3-vector under sin/cos (Rodrigues' ``\\sin\\|\\phi\\| /
    \\|\\phi\\|``): the zero test's points give the norm irrational, and the sine of an
    irrational norm is no exact value.

    Each such vector is put at ``s (a, b, c) / d`` for a Pythagorean quadruple ``a^2 + b^2 +
    c^2 = d^2`` (:data:`RATIONAL_DIRECTIONS`, entries permuted and signed) and a small norm
    ``s`` (:data:`RATIONAL_NORMS`), so every root of the norm is the rational ``s`` and the
    sides are rationals and sines and cosines of rationals; the other parameters take small
    rationals (constraints exact, as :func:`small_witness`). The residual is evaluated in
    ball arithmetic (:func:`rigidsym.checking.deciding.balls.ball_at`): a ball that excludes
    0 proves the sides differ there; one that holds 0 proves nothing, and the next point is
    tried. No floating point decides.

    Args:
        lhs, rhs: the explicit sides (book atoms), of the same shape.
        seed: the id's seed (the same seed, the same points).
        extra: expressions whose atoms the plan must also give values (as
            :func:`exact_counterexample`'s).
        tries: how many points, a fixed count (never a clock).

    Returns:
        The point (plan parameter -> ``Fraction``; the plan of
        ``entries_of(lhs) + entries_of(rhs) + extra``), or ``None`` when no vector's norm is
        under sin/cos or no ball at the points tried excludes 0.
    """
    le, re_ = entries_of(lhs), entries_of(rhs)
    if len(le) != len(re_):
        return None
    vectors = norm_vectors([a - b for a, b in zip(le, re_, strict=True)])
    if not vectors:
        return None
    plan = make_plan(le + re_ + list(extra))
    if not all(x in plan.params for xs in vectors for x in xs):
        return None
    rng = random.Random(seed)
    for _ in range(tries):
        pt = in_range(plan, {p: rng.choice(SMALL_RATIONALS) for p in plan.params})
        for xs in vectors:
            *abc, d = rng.choice(RATIONAL_DIRECTIONS)
            rng.shuffle(abc)
            s = rng.choice(RATIONAL_NORMS)
            for x, a in zip(xs, abc, strict=True):
                pt[x] = s * Fraction(rng.choice((-1, 1)) * a, d)
        try:
            excludes, _, _ = ball_at(le, re_, plan, pt)
        except (ZeroDivisionError, Unsupported):
            continue
        if excludes:
            return pt
    return None
