"""The certified numeric backing: ball arithmetic on the unparametrised expressions.

A verdict is decided exactly (:mod:`rigidsym.zero`); this module backs it with a second,
independent computation that never decides: the *unparametrised* relations (book atoms,
``cos``/``sin`` of angles, no rational parametrisation) are evaluated in FLINT's ball
arithmetic (python-flint ``arb``) at seeded points that satisfy the constraints exactly.
Every operation returns a ball that is guaranteed to contain the true value, so

- a verified relation gets a certified enclosure: every entry's relative residual at every
  point lies in ``[-r, r]`` (``ENGINE.certified_bound`` is the bound a record calls certified);
- a does-not-hold gets "0 is not in the residual's ball at the counterexample", a proof of
  the failure independent of the exact one.

Where a ball is too wide to say either, the working precision doubles (from
``ENGINE.numeric_digits`` up to ``ENGINE.max_digits``) and the record gives the precision used.
The expressions are translated once into a program with shared subexpressions
(:func:`rigidsym.zero.program.unparametrised`); nothing prints or compiles source code.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction

import flint
import sympy as sp
from flint import arb, fmpq
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import constraint_of
from rigidsym.core.settings import ENGINE
from rigidsym.zero.decide import Unsupported, evaluate
from rigidsym.zero.program import (
    ABS,
    ADD,
    CONST,
    FUNC,
    LEAF,
    MUL,
    PI,
    POW,
    ROOT,
    Program,
    parametrised,
    run_exact,
    unparametrised,
)

__all__ = ["Backing", "run_balls", "backing", "ball_at", "bits_of", "flint_version"]

# the precision, points and certified bound of a backing: rigidsym.core.settings


def flint_version() -> str:
    """The python-flint version (the document header names it)."""
    return flint.__version__


def bits_of(digits: int) -> int:
    """Working precision in bits for ``digits`` decimal digits (plus 10 guard bits)."""
    return int(digits * 3.3219280948873626) + 10


def run_balls(prog: Program, leaves: list) -> list:
    """Balls of the outputs of an unparametrised program at the current ``flint.ctx``
    precision; ``leaves`` are ``fmpq`` or ``arb`` values in the order of ``prog.leaves``.

    Returns balls that contain the exact values (a non-finite ball where the value is
    undefined or a denominator's ball contains 0).
    """
    # the loop of rigidsym.zero.program.run_exact on balls, written out: a shared loop
    # would cost a Python call per operation in the checker's inner loop
    vals: list = [None] * len(prog.ops)
    for i, op in enumerate(prog.ops):
        code = op[0]
        if code == MUL:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = acc * vals[j]
        elif code == ADD:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = acc + vals[j]
        elif code == POW:
            acc = _ipow(vals[op[1]], op[2])
        elif code == CONST:
            acc = arb(fmpq(op[1].numerator, op[1].denominator))
        elif code == LEAF:
            acc = arb(leaves[op[1]])
        elif code == ROOT:
            acc = vals[op[1]] ** arb(fmpq(op[2], op[3]))
        elif code == ABS:
            acc = abs(vals[op[1]])
        elif code == PI:
            acc = arb.pi()
        elif code == FUNC:
            args = [vals[j] for j in op[2:]]
            acc = arb.atan2(*args) if op[1] == "atan2" else getattr(args[0], op[1])()
        else:  # pragma: no cover
            raise Unsupported(f"operation {code}")
        vals[i] = acc
    return [vals[k] for k in prog.outputs]


def _ipow(x, n: int):
    """``x ** n`` by squarings: python-flint's ``arb ** int`` (0.9) returns nan for a ball
    that contains 0, which made an ordinary point look singular at every precision."""
    if n < 0:
        return 1 / _ipow(x, -n)
    acc, base = arb(1), x
    while n:
        if n & 1:
            acc = acc * base
        n >>= 1
        if n:
            base = base * base
    return acc


# --------------------------------------------------------------------------- exact bounds
def _exact(x) -> Fraction:
    """The exact value ``m 2^e`` of an ``arf`` (a ball's midpoint or radius), by shifts:
    ``Fraction(2) ** e`` took a tenth of the backing's time."""
    m, e = x.man_exp()
    m, e = int(m), int(e)
    return Fraction(m << e) if e >= 0 else Fraction(m, 1 << -e)


def upper(x) -> Fraction:
    """An exact upper bound of ``|x|`` over the ball ``x``: ``|mid| + rad``."""
    return abs(_exact(x.mid())) + _exact(x.rad())


def lower(x) -> Fraction:
    """An exact lower bound of ``|x|`` over the ball ``x``: ``max(0, |mid| - rad)``."""
    return max(Fraction(0), abs(_exact(x.mid())) - _exact(x.rad()))


def round_up(x: Fraction) -> float:
    """``x`` rounded up to two significant decimal digits, as a float that is still >= x
    (a bound stays a bound)."""
    if x <= 0:
        return 0.0
    e = len(str(x.numerator)) - len(str(x.denominator))  # 10^(e-1) < x < 10^(e+1)
    while Fraction(10) ** e > x:
        e -= 1
    while Fraction(10) ** (e + 1) <= x:
        e += 1
    unit = Fraction(10) ** (e - 1)  # x / unit in [10, 100)
    q = -(-x // unit)  # ceil: 10 ... 100
    out = float(f"{q}e{e - 1}")
    return out if Fraction(out) >= x else math.nextafter(out, math.inf)


# --------------------------------------------------------------------------- points
def _draw_order(leaves: list) -> list:
    """Leaves in the order the former mpmath backing drew their fill-in values
    (derivatives, then applied functions, then symbols, each sorted), so that the points
    stay those of earlier reports."""
    def rank(a) -> int:
        return 0 if isinstance(a, sp.Derivative) else 1 if isinstance(a, AppliedUndef) else 2

    return sorted(leaves, key=lambda a: (rank(a), sp.default_sort_key(a)))


def point_maker(plan):
    """A function ``rng -> {atom: Fraction}``: exact values of every atom of ``plan`` at a
    seeded random point that satisfies the constraints. Constrained groups take rational
    points of their parametrisation (``e.e = 1`` and ``Q^T Q = 1`` hold exactly), free
    atoms, jets and angles random rationals (the draws of the former mpmath backing, in the
    same order). The parametrisation is translated once (:func:`parametrised`).

    The function raises ``ZeroDivisionError`` at a point where a parametrisation is
    singular (all four quaternion parameters 0).
    """
    # sorted: the draws must not follow set/dict order, which varies with PYTHONHASHSEED
    rules = sorted(((a, r) for a, r in plan.rules.items() if a != sp.pi),
                   key=lambda kv: sp.default_sort_key(kv[0]))
    free = [isinstance(r, sp.Symbol) for _, r in rules]  # a free atom, a jet, a bare angle
    # an angle on [0, pi] takes its value there (the draw's magnitude: the same draws)
    half = [getattr(constraint_of(a), "kind", None) == "angle_pi" for a, _ in rules]
    prog = parametrised([r for (_, r), f in zip(rules, free, strict=True) if not f], plan)
    angles = [a for a in sorted(plan.angles, key=sp.default_sort_key)
              if a not in plan.rules]

    def draw(rng: random.Random) -> dict:
        pt = [fmpq(rng.randint(-40, 40), rng.randint(1, 12)) for _ in plan.params]
        values = iter(run_exact(prog, pt))
        out = {}
        for (atom, _), f, h in zip(rules, free, half, strict=True):
            v = Fraction(rng.randint(-10**8, 10**8), 10**8) * 3 if f else next(values)
            out[atom] = (abs(v) if h else v) if f else Fraction(int(v.p), int(v.q))
        for a in angles:  # one value per angle
            out[a] = Fraction(rng.randint(1, 10**8), 10**8) * 3
        return out

    return draw


def exact_point(plan, rng: random.Random) -> dict:
    """One point of :func:`point_maker` (see there)."""
    return point_maker(plan)(rng)


# --------------------------------------------------------------------------- backing
@dataclass
class Backing:
    """The ball-arithmetic backing of a list of relations.

    Attributes:
        points: points evaluated (the singular ones skipped).
        digits: the highest working precision used, decimal digits (above
            ``ENGINE.numeric_digits`` where a ball was too wide at first).
        max_residual: the largest relative residual at the balls' midpoints (an estimate).
        enclosure: a certified bound: every entry's relative residual at every point lies
            in ``[-enclosure, enclosure]`` (exact rational; ``None`` with no point).
        excluded: the first residual ball that does not contain 0 (text), if any: the
            relations then do *not* hold at that point.
        raised: points at which the precision had to rise.
    """

    points: int = 0
    digits: int = field(default_factory=lambda: ENGINE.numeric_digits)
    max_residual: float = 0.0
    enclosure: Fraction | None = None
    excluded: str | None = None
    raised: int = 0
    residuals: list = field(default_factory=list)

    @property
    def certified(self) -> bool:
        """Enclosed within ``ENGINE.certified_bound`` at every one of the points."""
        return (self.excluded is None and self.enclosure is not None
                and self.enclosure <= ENGINE.certified_bound)


def _at_point(prog: Program, n_left: int, values: list) -> tuple:
    """Residual balls at one point, the precision raised until they decide.

    Returns ``(rel_upper, rel_mid, excluded_text, digits)``; ``rel_upper`` is ``None`` when
    the point is singular (a ball stays non-finite at ``ENGINE.max_digits``).
    """
    digits = ENGINE.numeric_digits
    while True:
        with flint.ctx.workprec(bits_of(digits)):
            balls = run_balls(prog, values)
            finite = all(b.is_finite() for b in balls)
            if finite:
                res = [a - b for a, b in zip(balls[:n_left], balls[n_left:], strict=True)]
                scale = max([Fraction(1)] + [lower(b) for b in balls])
                rel_upper = max((upper(r) for r in res), default=Fraction(0)) / scale
                out = next((r for r in res if lower(r) > 0), None)
                if out is not None or rel_upper <= ENGINE.certified_bound \
                        or digits >= ENGINE.max_digits:
                    mid = max([Fraction(1)] + [abs(_exact(b.mid())) for b in balls])
                    rel_mid = max((abs(_exact(r.mid())) for r in res), default=Fraction(0))
                    text = out.str(10, radius=True) if out is not None else None
                    return rel_upper, float(rel_mid / mid), text, digits
        if digits >= ENGINE.max_digits:
            return None, None, None, digits
        digits = min(2 * digits, ENGINE.max_digits)


def backing(lhs: list, rhs: list, plan, seed: int, points: int | None = None) -> Backing:
    """Evaluate ``lhs[i] - rhs[i]`` (explicit scalar expressions) in ball arithmetic at
    ``points`` seeded constraint-satisfying points of ``plan``.

    Args:
        lhs, rhs: the entries of both sides, unparametrised (book atoms).
        plan: the zero test's plan of those entries (:func:`rigidsym.zero.make_plan`):
            it gives the constrained groups' exact rational points.
        seed: the id's seed; the same seed gives the same points.
        points: how many points (up to ``20 * points`` draws; singular ones are skipped);
            default ``ENGINE.numeric_points``.

    Raises:
        Unsupported: for a node with no numeric meaning (an unknown function).
    """
    prog = unparametrised(list(lhs) + list(rhs))
    order = _draw_order(prog.leaves)
    slot = {a: k for k, a in enumerate(prog.leaves)}
    rng = random.Random(seed)
    draw = point_maker(plan)
    out = Backing()
    tries = 0
    points = ENGINE.numeric_points if points is None else points
    while out.points < points and tries < 20 * points:
        tries += 1
        try:
            pt = draw(rng)
        except ZeroDivisionError:  # a singular parametrisation: another point
            continue
        values: list = [None] * len(prog.leaves)
        for a in order:
            fill = rng.random()  # drawn for every atom, as before: the points stay put
            v = pt.get(a, Fraction(fill))
            values[slot[a]] = fmpq(v.numerator, v.denominator)
        rel_upper, rel_mid, text, digits = _at_point(prog, len(lhs), values)
        if rel_upper is None:
            continue
        out.points += 1
        out.digits = max(out.digits, digits)
        out.raised += digits > ENGINE.numeric_digits
        out.residuals.append(rel_mid)
        out.max_residual = max(out.max_residual, rel_mid)
        out.enclosure = rel_upper if out.enclosure is None else max(out.enclosure, rel_upper)
        if text is not None and out.excluded is None:
            out.excluded = text
    return out


def ball_at(lhs: list, rhs: list, plan, pt: dict) -> tuple[bool, str, int]:
    """The residual's ball at an exact point of the plan's parameters (a counterexample).

    Atoms take the point's exact values; a bare angle takes ``2M atan(tau)``, consistent
    with its cosine and sine. The precision rises until a ball excludes 0 or reaches
    ``ENGINE.max_digits``.

    Returns:
        ``(excludes_zero, ball, digits)``: whether some entry's residual ball excludes 0
        (then the relation fails at the point, proven by ball arithmetic alone), the ball of
        the entry farthest from 0 as text (``[-0.5 +/- 3.1e-48]``), and the digits used.

    Raises:
        Unsupported: for an atom the point gives no value.
    """
    prog = unparametrised([a - b for a, b in zip(lhs, rhs, strict=True)])
    exact = {}
    for atom, rule in plan.rules.items():
        if atom in plan.bare or atom == sp.pi:
            continue
        exact[atom] = evaluate(rule, plan, pt) if rule != atom else pt[atom]
    for a, s in plan.bare.items():
        if a not in plan.angles:
            exact[a] = pt[s]
    digits = ENGINE.numeric_digits
    while True:
        with flint.ctx.workprec(bits_of(digits)):
            values = []
            for a in prog.leaves:
                if a in plan.angles:
                    tau, m = plan.angles[a]
                    values.append(2 * m * arb(fmpq(pt[tau].numerator, pt[tau].denominator))
                                  .atan())
                elif a in exact:
                    v = exact[a]
                    values.append(fmpq(v.numerator, v.denominator))
                else:
                    raise Unsupported(f"no value for atom {a} at the counterexample")
            balls = [b for b in run_balls(prog, values) if b.is_finite()]
            best = max(balls, key=lower, default=None)
            if best is not None and (lower(best) > 0 or digits >= ENGINE.max_digits):
                return lower(best) > 0, best.str(10, radius=True), digits
            if best is None and digits >= ENGINE.max_digits:
                return False, "[non-finite]", digits
        digits = min(2 * digits, ENGINE.max_digits)
