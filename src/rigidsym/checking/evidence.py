"""The evidence behind a verdict (:mod:`rigidsym.checking.checker`): the 50-digit mpmath backing of
the unparametrised relations at seeded points, and a readable exact counterexample.
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.checking.explicit import _entries, explicit, shape_of
from rigidsym.checking.registry import Rel
from rigidsym.zero.decide import Unsupported, evaluate, make_plan

NUMERIC_DIGITS = 50
NUMERIC_POINTS = 10


# --------------------------------------------------------------------------- numeric
def _dummify(exprs) -> tuple[list, list, list]:
    """Replace derivatives, then applied functions, then symbols by dummies (outside-in,
    so ``e_1(t)`` inside ``Derivative(e_1(t), t)`` is not mistaken for a lone atom)."""
    exprs = [sp.sympify(e) for e in exprs]
    atoms, dummies = [], []
    for kind in (sp.Derivative, AppliedUndef, sp.Symbol):
        found = set().union(*(e.atoms(kind) for e in exprs)) if exprs else set()
        found = sorted((a for a in found if not isinstance(a, sp.Dummy)),
                       key=sp.default_sort_key)
        sub = {a: sp.Dummy() for a in found}
        exprs = [e.xreplace(sub) for e in exprs]
        atoms += found
        dummies += [sub[a] for a in found]
    return atoms, dummies, exprs


def numeric_point(plan, rng: random.Random) -> dict:
    """Values (mpf) of every atom of ``plan`` at a random point satisfying the constraints.

    Constrained groups get exact rational points of their parametrisation (so ``e.e = 1``
    and ``Q^T Q = 1`` hold exactly); angles and free atoms get random reals.
    """
    pt = {p: Fraction(rng.randint(-40, 40), rng.randint(1, 12)) for p in plan.params}
    out = {}
    # sorted: the draws must not follow set/dict order, which varies with PYTHONHASHSEED
    for atom, rule in sorted(plan.rules.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if atom == sp.pi:
            continue
        if isinstance(rule, sp.Symbol):  # a free atom, a jet, or a bare angle
            out[atom] = mpmath.mpf(rng.randint(-10**8, 10**8)) / 10**8 * 3
        else:  # a constrained group: an exact rational point of its parametrisation
            f = evaluate(rule, plan, pt)
            out[atom] = mpmath.mpf(f.numerator) / f.denominator
    for a in sorted(plan.angles, key=sp.default_sort_key):  # one value per angle
        if a not in out:
            out[a] = mpmath.mpf(rng.randint(1, 10**8)) / 10**8 * 3
    return out


def numeric_residual(rels: list[Rel], model: dict, seed: int, points: int = NUMERIC_POINTS):
    """Max relative residual of ``lhs - rhs`` over seeded constraint-satisfying points."""
    lhs = [explicit(r.lhs, model) for r in rels]
    rhs = [explicit(r.rhs, model) for r in rels]
    flat_l = [e for x in lhs for e in _entries(x)]
    flat_r = [e for x in rhs for e in _entries(x)]
    plan = make_plan(flat_l + flat_r)
    atoms, dummies, flat = _dummify(flat_l + flat_r)
    fl = sp.lambdify(dummies, flat[:len(flat_l)], modules="mpmath", cse=True)
    fr = sp.lambdify(dummies, flat[len(flat_l):], modules="mpmath", cse=True)
    rng = random.Random(seed)
    worst = mpmath.mpf(0)
    residuals = []
    done = tries = 0
    with mpmath.workdps(NUMERIC_DIGITS):
        while done < points and tries < 20 * points:
            tries += 1
            pt = numeric_point(plan, rng)
            args = [pt.get(a, mpmath.mpf(rng.random())) for a in atoms]
            try:
                lv, rv = fl(*args), fr(*args)
            except (ZeroDivisionError, ValueError):
                continue
            scale = max([mpmath.mpf(1)] + [abs(mpmath.mpf(x)) for x in list(lv) + list(rv)])
            res = max((abs(mpmath.mpf(a) - mpmath.mpf(b)) for a, b in zip(lv, rv,
                                                                          strict=True)),
                      default=mpmath.mpf(0)) / scale
            if not mpmath.isfinite(res):
                continue
            residuals.append(res)
            worst = max(worst, res)
            done += 1
    return worst, done, residuals


# --------------------------------------------------------------------------- counterexample
def _small_witness(entries, plan, seed):
    """Look for a counterexample point with small rationals (readable), exactly checked."""
    rng = random.Random(seed)
    small = [Fraction(n, d) for n in range(-3, 4) for d in (1, 2, 3)]
    # a fixed number of tries, never a clock: under load a deadline picked another point and
    # made the committed report depend on the machine (each try takes about a millisecond)
    for _ in range(300):
        pt = {p: rng.choice(small) for p in plan.params}
        try:
            if any(evaluate(e, plan, pt) != 0 for e in entries):
                return pt
        except (ZeroDivisionError, Unsupported):
            continue
    return None


def _exact_value(x, plan, pt):
    """Exact value at a witness point; bare angles take their consistent value 2M atan(tau)."""
    bare = {a: 2 * plan.angles[a][1] * sp.atan(sp.Rational(pt[plan.angles[a][0]]))
            for a in plan.bare if a in plan.angles}
    bare.update({a: sp.Rational(pt[s]) for a, s in plan.bare.items() if a not in bare})
    spt = {k: sp.Rational(v.numerator, v.denominator) for k, v in pt.items()}

    def one(e):
        return evaluate(e, plan, spt, lift=lambda v: v, bare_value=bare)

    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x.rows, x.cols, [one(e) for e in x])
    return one(x)


def _counterexample(lhs, rhs, witness, seed, describe=None) -> dict:
    """The readable exact counterexample; ``describe(plan, point)``, when given, adds the
    book symbols there (:func:`rigidsym.checking.bookpoint.describe_point`)."""
    plan = make_plan(_entries(lhs) + _entries(rhs))
    diff = [a - b for a, b in zip(_entries(lhs), _entries(rhs), strict=True)] \
        if shape_of(lhs) == shape_of(rhs) else []
    pt = _small_witness(diff, plan, seed) if diff else None
    if pt is None:  # keep the proven witness; parameters it does not mention get 1/2
        pt = {p: witness.get(p, Fraction(1, 2)) for p in plan.params}
    point = {}
    for atom, rule in sorted(plan.rules.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if atom in plan.bare:
            continue
        v = evaluate(rule, plan, pt) if rule != atom else pt[atom]
        point[sp.sstr(atom)] = str(v)
    for a, (tau, M) in plan.angles.items():
        point[sp.sstr(a)] = f"{2 * M}*atan({pt[tau]})"
    lv, rv = _exact_value(lhs, plan, pt), _exact_value(rhs, plan, pt)
    ce = {"point": point, "lhs": sp.sstr(lv), "rhs": sp.sstr(rv)}
    if shape_of(lhs) == shape_of(rhs):
        ce["residual"] = sp.sstr(lv - rv)
    if describe is not None:
        ce.update(describe(plan, pt))
    return ce
