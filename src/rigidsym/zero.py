"""Constraint-aware zero test: decide exactly whether expressions vanish identically.

Method (never ``simplify()``, never floating point):

1. **Parametrise.** Every constrained atom is replaced by a rational function of free
   parameters (:mod:`rigidsym.symbols`): a unit vector (in R^3 or R^4) by stereographic
   projection, a rotation by a rational quaternion, ``cos``/``sin`` of multiples of an
   angle ``phi`` by rational functions of ``tau = tan(phi / (2M))``; derivatives of
   time-dependent atoms become jets of those parameters. The bare angle stays an independent
   variable (an angle and its cosine/sine are algebraically independent functions, so this
   is exact).
   After this step the expression is a rational function over Q of free variables, and the
   constraints hold identically.
2. **Random-exact probe.** Evaluate with Python ``Fraction`` at seeded random rational
   points. A non-zero value is a *proof* that the expression is not identically zero, and
   the point is an exact counterexample.
3. **Exact cancellation** (``exact-cancel``): for expressions of moderate size, bring the
   rational function to lowest terms in ``sympy.polys`` fields; zero iff the numerator is 0.
4. **Schwartz-Zippel** (``random-exact``): for expressions too large to expand, a bound
   ``d`` on the total degree of the numerator is computed from the expression tree, and the
   expression is evaluated exactly at ``n`` independent points drawn uniformly from a set
   ``S`` of ``2^32 + 1`` rationals: if it is not identically zero, all ``n`` values vanish
   with probability at most ``(d / |S|)^n``, which is recorded.

Anything else (a float, an unknown function, an irrational power) makes the result
``undecided``.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache
from math import gcd

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.polys.fields import field as frac_field

from .symbols import TIME, constrained_atom, constraint_of

__all__ = [
    "Unsupported",
    "Plan",
    "ZeroResult",
    "make_plan",
    "evaluate",
    "to_rational",
    "degree_bound",
    "decide_zero",
    "SAMPLE_SET_SIZE",
]

#: |S| of the Schwartz-Zippel sample set: k / 2^16 for integers |k| <= 2^31.
SAMPLE_SET_SIZE = 2**32 + 1
_DEN = 2**16
#: Node-count limit above which exact cancellation is not attempted.
CANCEL_NODE_LIMIT = 2500
#: Degree-bound limit above which exact cancellation is not attempted (multivariate gcds
#: of high degree can take minutes; Schwartz-Zippel then decides in seconds).
CANCEL_DEGREE_LIMIT = 160
#: Exact cancellation is attempted when the degree bound is at most this, whatever the
#: number of parameters...
CANCEL_SMALL_DEGREE = 48
#: ... or when there are at most this many parameters (and the degree is within
#: CANCEL_DEGREE_LIMIT). Measured on the chapter: every attempt under this rule takes
#: <= 1 s; with 14+ parameters and degree > 48, multivariate gcds took 2 s to minutes.
#: A rule on the data, not a timer, so the method recorded does not depend on the machine.
CANCEL_PARAM_LIMIT = 13
#: Safety net only (CPU seconds; not reached on the chapter): then Schwartz-Zippel decides.
CANCEL_SECONDS = 5.0
#: Points evaluated by the Schwartz-Zippel path.
SZ_POINTS = 12

_TRIG = (sp.cos, sp.sin, sp.tan, sp.cot, sp.sec, sp.csc)


class Unsupported(Exception):
    """The expression holds something the exact evaluator cannot treat."""


def _atom_name(a) -> str:
    if isinstance(a, sp.Symbol):
        return a.name
    if isinstance(a, AppliedUndef):
        return a.func.__name__
    raise TypeError(a)


def _constraint(a):
    return constraint_of(a)  # carried by the atom itself, never looked up by name


def _is_angle_atom(a) -> bool:
    if isinstance(a, sp.Symbol | AppliedUndef):
        c = _constraint(a)
        return c is not None and c.kind == "angle"
    return False


def _deriv_order(d: sp.Derivative) -> int:
    n = 0
    for v, k in d.variable_count:
        if v != TIME:
            raise Unsupported(f"derivative with respect to {v}, not time")
        n += int(k)
    return n


# --------------------------------------------------------------------------- jets
def _jet_symbol(name: str, k: int, timed: bool = True) -> sp.Symbol:
    """Symbol for the k-th time derivative of atom ``name`` (``name(t)``, ``name__d1`` …).

    Static atoms keep their own symbol; time-dependent ones get names that cannot clash
    with a static atom of the same book name.
    """
    if not timed:
        return sp.Symbol(name, real=True)
    return sp.Symbol(f"{name}(t)" if k == 0 else f"{name}__d{k}", real=True)


def _replace_jets(expr, funcs: dict[str, sp.Expr]):
    """Replace f(t) and its derivatives, for f named in ``funcs``, by jet symbols."""
    reps = {}
    for d in expr.atoms(sp.Derivative):
        reps[d] = _jet_symbol(_atom_name(d.expr), _deriv_order(d))
    expr = expr.xreplace(reps)
    return expr.xreplace({f: _jet_symbol(n, 0) for n, f in funcs.items()})


@cache
def _group_rules(kind: str, name: str, names: tuple[str, ...], timed: bool, order: int):
    """Rational rules ``(atom name, derivative order) -> expr`` for a constrained group."""
    t = TIME
    if kind == "unit":
        pn = [f"{name}__u", f"{name}__v"]
    elif kind == "unit4":
        pn = [f"{name}__u", f"{name}__v", f"{name}__w"]
    elif kind == "rotation":
        pn = [f"{name}__q1", f"{name}__q2", f"{name}__q3", f"{name}__q0"]
    else:
        raise ValueError(kind)
    P = [sp.Function(p, real=True)(t) for p in pn] if timed else \
        [_jet_symbol(p, 0, timed=False) for p in pn]
    if kind == "unit":
        u, v = P
        den = 1 + u**2 + v**2
        vals = [2 * u / den, 2 * v / den, (1 - u**2 - v**2) / den]
    elif kind == "unit4":
        u, v, w = P
        den = 1 + u**2 + v**2 + w**2
        vals = [2 * u / den, 2 * v / den, 2 * w / den, (1 - u**2 - v**2 - w**2) / den]
    else:
        from .primitives import rotation_from_quaternion
        vals = list(rotation_from_quaternion(P))
    rules = {}
    funcs = dict(zip(pn, P, strict=True)) if timed else {}
    for n, val in zip(names, vals, strict=True):
        for k in range(order + 1):
            ex = sp.diff(val, t, k) if (timed and k) else val
            rules[(n, k)] = _replace_jets(ex, funcs) if timed else ex
            if not timed:
                break
    return rules


# --------------------------------------------------------------------------- plan
@dataclass
class Plan:
    """How to evaluate a family of expressions exactly.

    Attributes:
        rules: atom (Symbol, f(t) or Derivative) -> rational expression in parameters.
        angles: angle atom -> (tau symbol, M) with ``tau = tan(angle / (2 M))``.
        bare: angle atom -> symbol standing for the bare angle (independent variable).
        params: the free parameters, sorted by name.
    """

    rules: dict = field(default_factory=dict)
    angles: dict = field(default_factory=dict)
    bare: dict = field(default_factory=dict)
    params: list = field(default_factory=list)


def _linear_angles(arg) -> tuple[dict, Fraction]:
    """Write a trig argument as sum c_j * angle_j + c * pi with rational c_j, c."""
    arg = sp.expand(arg)
    coeffs: dict = {}
    cpi = Fraction(0)
    for term in sp.Add.make_args(arg):
        c, rest = term.as_coeff_Mul()
        if not c.is_Rational:
            raise Unsupported(f"trig argument {arg}")
        if rest == sp.pi:
            cpi += Fraction(int(c.p), int(c.q))
        elif _is_angle_atom(rest):
            coeffs[rest] = coeffs.get(rest, Fraction(0)) + Fraction(int(c.p), int(c.q))
        else:
            raise Unsupported(f"trig of non-angle argument {arg}")
    if (2 * cpi).denominator != 1:
        raise Unsupported(f"trig argument with pi multiple {cpi}")
    return coeffs, cpi


def _walk(expr, visit):
    seen = set()
    stack = [expr]
    while stack:
        x = stack.pop()
        if x in seen:
            continue
        seen.add(x)
        if visit(x):
            stack.extend(x.args)


def make_plan(exprs) -> Plan:
    """Collect atoms of ``exprs`` and build the parametrisation that imposes constraints."""
    plan = Plan()
    params: set = set()
    denoms: dict = {}
    groups: dict = {}
    free: set = set()

    def visit(x):
        if isinstance(x, sp.Derivative):
            base = x.expr
            if not isinstance(base, AppliedUndef):
                raise Unsupported(f"derivative of a non-atom {x}")
            _note(base, _deriv_order(x))
            return False
        if isinstance(x, AppliedUndef):
            _note(x, 0)
            return False
        if isinstance(x, sp.Symbol):
            if x != TIME:
                _note(x, 0)
            return False
        if x == sp.pi:
            # pi outside a trig argument: transcendental, so an independent variable is exact
            plan.rules[sp.pi] = sp.Symbol("pi__var", real=True)
            params.add(plan.rules[sp.pi])
            return False
        if isinstance(x, _TRIG):
            coeffs, _ = _linear_angles(x.args[0])
            for a, c in coeffs.items():
                denoms[a] = denoms.get(a, 1) * c.denominator // gcd(denoms.get(a, 1),
                                                                    c.denominator)
            return False
        return True

    def _note(atom, k):
        c = _constraint(atom)
        if c is None or c.kind == "angle":
            free.add((atom, k))
            if c is not None and k == 0:
                denoms.setdefault(atom, 1)
        else:
            groups[c] = max(groups.get(c, 0), k)

    for e in exprs:
        _walk(sp.sympify(e), visit)
    # Constrained groups: rational rules for all atoms and derivative orders present.
    for c, order in groups.items():
        rules = _group_rules(c.kind, c.name, c.names, c.timed, order)
        for (n, k), ex in rules.items():
            atom = constrained_atom(n, c)
            key = atom if k == 0 else sp.Derivative(atom, (TIME, k))
            plan.rules[key] = ex
            params |= ex.free_symbols
    # Free atoms (and bare angles, kept independent): each its own variable.
    for atom, k in free:
        sym = _jet_symbol(_atom_name(atom), k)
        key = atom if k == 0 else sp.Derivative(atom, (TIME, k))
        if isinstance(atom, sp.Symbol) and k == 0:
            plan.rules.setdefault(key, atom)
        else:
            plan.rules[key] = sym
        params.add(plan.rules[key] if k == 0 and isinstance(atom, sp.Symbol) else sym)
        if _is_angle_atom(atom) and k == 0:
            plan.bare[atom] = plan.rules[key]
    for a, M in denoms.items():
        tag = "(t)" if isinstance(a, AppliedUndef) else ""
        tau = sp.Symbol(f"tan({_atom_name(a)}{tag}/{2 * M})", real=True)
        plan.angles[a] = (tau, M)
        params.add(tau)
    plan.params = sorted(params, key=lambda s: s.name)
    return plan


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


def evaluate(expr, plan: Plan, point: dict, lift=Fraction, bare_value=None):
    """Evaluate ``expr`` exactly at ``point`` (parameter symbol -> value).

    Args:
        expr: a sympy expression built from the plan's atoms.
        plan: from :func:`make_plan`.
        point: values of ``plan.params`` (``Fraction`` by default).
        lift: converts a sympy Rational to the number type (``Fraction``, ``sp.Rational``…).
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
                bv = ev(b)
                return _rational_root(bv, int(n.p), int(n.q))
            raise Unsupported(f"power {x}")
        if isinstance(x, sp.Abs):
            return abs(ev(x.args[0]))
        if isinstance(x, _TRIG):
            coeffs, cpi = _linear_angles(x.args[0])
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
        raise Unsupported(f"node {type(x).__name__}: {x}")

    return ev(sp.sympify(expr))


def _rational_root(v: Fraction, p: int, q: int) -> Fraction:
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
        elif isinstance(x, _TRIG):
            r = evaluate(x, plan, {tau: tau for tau, _ in plan.angles.values()},
                         lift=lambda v: v)
        elif x.args:
            r = x.func(*[tr(a) for a in x.args])
        else:
            raise Unsupported(f"node {x}")
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
        elif isinstance(x, _TRIG):
            coeffs, _ = _linear_angles(x.args[0])
            deg = sum(2 * abs(int(c * plan.angles[a][1])) for a, c in coeffs.items())
            r = (deg, deg)
        elif isinstance(x, sp.Abs):
            r = db(x.args[0])
        else:
            raise Unsupported(f"degree of {x}")
        memo[x] = r
        return r

    return db(sp.sympify(expr))[0]


def _size(expr) -> int:
    n = 0

    def visit(x):
        nonlocal n
        n += 1
        return n <= CANCEL_NODE_LIMIT

    _walk(expr, visit)
    return n


# --------------------------------------------------------------------------- decision
@dataclass
class ZeroResult:
    """Outcome of :func:`decide_zero`.

    Attributes:
        zero: True (identically zero), False (a non-zero witness exists), None (undecided).
        method: ``exact-cancel``, ``random-exact``, ``counterexample`` or ``undecided``.
        detail: one line (degree bound and failure probability, or why undecided).
        witness: parameter point where an entry is non-zero (exact), when ``zero`` is False.
        entry: index of that entry.
    """

    zero: bool | None
    method: str
    detail: str = ""
    witness: dict | None = None
    entry: int | None = None
    plan: Plan | None = None


class _OutOfTime(Exception):
    pass


def _cancel_within_budget(entries, plan: Plan) -> list[int] | None:
    """Indices of entries whose reduced numerator is non-zero; ``None`` if the budget ran out.

    The budget is process CPU time (ITIMER_VIRTUAL/SIGVTALRM, main thread on POSIX), so the
    method chosen does not depend on how loaded the machine is: multivariate gcds
    occasionally take minutes where Schwartz-Zippel needs a second.
    """
    import signal
    import threading

    gens = plan.params
    if gens:
        K, *_ = frac_field(gens, sp.QQ)
        conv = K.from_expr
    else:
        def conv(x):
            return sp.Rational(x)
    timed = hasattr(signal, "setitimer") and threading.current_thread() is \
        threading.main_thread()

    def on_alarm(signum, frame):
        raise _OutOfTime

    old = signal.signal(signal.SIGVTALRM, on_alarm) if timed else None
    try:
        if timed:
            signal.setitimer(signal.ITIMER_VIRTUAL, CANCEL_SECONDS)
        return [i for i, e in enumerate(entries) if conv(to_rational(e, plan)) != 0]
    except _OutOfTime:
        return None
    finally:
        if timed:
            signal.setitimer(signal.ITIMER_VIRTUAL, 0)
            signal.signal(signal.SIGVTALRM, old)


def random_point(plan: Plan, rng: random.Random) -> dict:
    """A point drawn uniformly from S^n, S = {k / 2^16 : |k| <= 2^31}."""
    return {p: Fraction(rng.randint(-(2**31), 2**31), _DEN) for p in plan.params}


def _eval_entries(entries, plan, point):
    return [evaluate(e, plan, point) for e in entries]


def decide_zero(entries, seed: int = 0, probes: int = 2) -> ZeroResult:
    """Decide whether every expression in ``entries`` is identically zero on the
    constraint set (see the module docstring for the method and its guarantees)."""
    entries = [sp.sympify(e) for e in entries]
    entries = [e for e in entries if e != 0]
    if not entries:
        return ZeroResult(True, "exact-cancel", "all entries cancel structurally")
    try:
        plan = make_plan(entries)
    except Unsupported as exc:
        return ZeroResult(None, "undecided", str(exc))
    rng = random.Random(seed)

    def probe(n):
        tries = 0
        done = 0
        while done < n:
            tries += 1
            if tries > 20 * n + 20:
                raise Unsupported("could not find sample points off the singular set")
            pt = random_point(plan, rng)
            try:
                vals = _eval_entries(entries, plan, pt)
            except ZeroDivisionError:
                continue
            done += 1
            for i, v in enumerate(vals):
                if v != 0:
                    return pt, i
        return None

    try:
        hit = probe(probes)
        if hit is not None:
            return ZeroResult(False, "counterexample", "non-zero at an exact rational point",
                              hit[0], hit[1], plan)
        d = max(degree_bound(e, plan) for e in entries)
        small = d <= CANCEL_SMALL_DEGREE or (d <= CANCEL_DEGREE_LIMIT and
                                              len(plan.params) <= CANCEL_PARAM_LIMIT)
        if small and all(_size(e) <= CANCEL_NODE_LIMIT for e in entries):
            nonzero = _cancel_within_budget(entries, plan)
        else:
            nonzero = None
        if nonzero is not None:
            for i in nonzero:
                hit = probe(50)
                if hit is None:
                    return ZeroResult(None, "undecided",
                                      f"entry {i} non-zero but no witness found")
                return ZeroResult(False, "counterexample", "non-zero after cancellation",
                                  hit[0], hit[1], plan)
            return ZeroResult(True, "exact-cancel",
                              f"numerators cancel to 0 over Q({len(plan.params)} parameters)",
                              plan=plan)
        hit = probe(SZ_POINTS)
        if hit is not None:
            return ZeroResult(False, "counterexample", "non-zero at an exact rational point",
                              hit[0], hit[1], plan)
        n = SZ_POINTS + probes
        prob = sp.Rational(d, SAMPLE_SET_SIZE) ** n
        return ZeroResult(True, "random-exact",
                          f"Schwartz-Zippel: degree <= {d}, |S| = 2^32+1, {n} points, "
                          f"P(false zero) <= {sp.N(prob, 3)}", plan=plan)
    except Unsupported as exc:
        return ZeroResult(None, "undecided", str(exc), plan=plan)
