"""Constraint-aware zero test: decide exactly whether expressions vanish identically.

Method (never ``simplify()``, never floating point):

1. **Parametrise.** Every constrained atom is replaced by a rational function of free
   parameters (:mod:`rigidsym.algebra.symbols`): a unit vector (in R^3 or R^4) by stereographic
   projection, a rotation by a rational quaternion, ``cos``/``sin`` of multiples of an
   angle ``phi`` by rational functions of ``tau = tan(phi / (2M))``; derivatives of
   time-dependent atoms become jets of those parameters. The bare angle stays an independent
   variable (an angle and its cosine/sine are algebraically independent functions, so this
   is exact).
   After this step the expression is a rational function over Q of free variables, and the
   constraints hold identically.
2. **Random-exact probe.** Evaluate with FLINT rationals (``fmpq``) at seeded random rational
   points. A non-zero value is a *proof* that the expression is not identically zero, and
   the point is an exact counterexample.
3. **Exact cancellation** (``exact-cancel``): compute the rational function as a fraction
   of FLINT polynomials (python-flint ``fmpq_mpoly``, common factors removed by FLINT's
   multivariate gcd); zero iff the numerator is 0. Attempted within a work budget on the
   sizes of the polynomials (``ENGINE.cancel_terms_limit``), not on time.
4. **Schwartz-Zippel** (``random-exact``): for expressions past that budget, a bound
   ``d`` on the total degree of the numerator is computed from the expression tree, and the
   expression is evaluated exactly at ``n`` independent points drawn uniformly from a set
   ``S`` of ``2^32 + 1`` rationals: if it is not identically zero, all ``n`` values vanish
   with probability at most ``(d / |S|)^n``, which is recorded.

Anything else (a float, an unknown function, an irrational power) makes the result
``undecided``. Each family of expressions is translated once into a straight-line program
(:mod:`rigidsym.zero.program`) that steps 2-4 share.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp

from rigidsym.core.settings import ENGINE
from rigidsym.zero.exact import degree_bound, evaluate, to_rational, tree_size
from rigidsym.zero.plan import Plan, Unsupported, make_plan
from rigidsym.zero.polar import polar_norms
from rigidsym.zero.program import Program, TooLarge, parametrised, run_exact, run_rational
from rigidsym.zero.roots import decide_roots, has_roots

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
# the budgets of exact cancellation and the Schwartz-Zippel points: rigidsym.core.settings



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
        polar_differs: with ``zero`` None, the note of the substitution (``|(phi_1,
            phi_2, phi_3)| = θ > 0, ...``) when the entries written with a free vector as
            ``θ u`` (:mod:`rigidsym.zero.polar`) are not identically zero, a proof that
            they differ for some vector, but no exact rational point is given (the vector's
            norm is irrational at the zero test's points); the checker looks for a point of
            rational norm where ball arithmetic proves it
            (:func:`rigidsym.checking.deciding.evidence.rational_norm_witness`). Else "".
    """

    zero: bool | None
    method: str
    detail: str = ""
    witness: dict | None = None
    entry: int | None = None
    plan: Plan | None = None
    polar_differs: str = ""


class _OutOfTime(Exception):
    pass


def _cancel_within_budget(prog: Program, plan: Plan) -> list[int] | None:
    """Indices of entries whose numerator is non-zero; ``None`` if the budget ran out.

    The budget is process CPU time (ITIMER_VIRTUAL/SIGVTALRM, main thread on POSIX), so the
    method chosen does not depend on how loaded the machine is: multivariate gcds
    occasionally take minutes where Schwartz-Zippel needs a second. (A FLINT call is not
    interrupted: the alarm is seen when it returns.)
    """
    import signal
    import threading

    timed = hasattr(signal, "setitimer") and threading.current_thread() is \
        threading.main_thread()

    def on_alarm(signum, frame):
        raise _OutOfTime

    old = signal.signal(signal.SIGVTALRM, on_alarm) if timed else None
    try:
        if timed:
            signal.setitimer(signal.ITIMER_VIRTUAL, ENGINE.cancel_seconds)
        if not plan.params:  # constants: their exact values decide
            return [i for i, v in enumerate(run_exact(prog, [])) if v != 0]
        # positional names: two parameters may print alike
        ctx = flint.fmpq_mpoly_ctx.get([f"x{i}" for i in range(len(plan.params))],
                                       "degrevlex")
        out = run_rational(prog, ctx, ENGINE.cancel_terms_limit, ENGINE.cancel_product_limit)
        return [i for i, (num, _) in enumerate(out) if not num.is_zero()]
    except (_OutOfTime, TooLarge):
        return None
    finally:
        if timed:
            signal.setitimer(signal.ITIMER_VIRTUAL, 0)
            signal.signal(signal.SIGVTALRM, old)


def random_point(plan: Plan, rng: random.Random) -> dict:
    """A point drawn uniformly from S^n, S = {k / 2^16 : |k| <= 2^31}."""
    return {p: Fraction(rng.randint(-(2**31), 2**31), _DEN) for p in plan.params}


def _eval_entries(prog: Program, plan: Plan, point: dict) -> list:
    """Exact values (``fmpq``) of the program's outputs at ``point`` (``Fraction`` values)."""
    return run_exact(prog, [flint.fmpq(point[p].numerator, point[p].denominator)
                            for p in plan.params])


def _probe(prog: Program, plan: Plan, rng: random.Random, n: int):
    """Evaluate the entries of ``prog`` at ``n`` random points off the singular set;
    ``(point, entry)`` of the first non-zero value (a proof that an entry is not zero), or
    ``None``.

    Raises:
        Unsupported: no ``n`` points off the singular set in ``20 n + 20`` tries.
    """
    tries = 0
    done = 0
    while done < n:
        tries += 1
        if tries > 20 * n + 20:
            raise Unsupported("could not find sample points off the singular set")
        pt = random_point(plan, rng)
        try:
            vals = _eval_entries(prog, plan, pt)
        except ZeroDivisionError:
            continue
        done += 1
        for i, v in enumerate(vals):
            if v != 0:
                return pt, i
    return None


def _traced(e):
    """``e`` with the trace of each explicit matrix written out (``tr A`` of a model ``A``
    in a fraction, so that no undecided's reason prints sympy's ``Trace(Matrix(
    [...]))``)."""
    return e.replace(lambda y: isinstance(y, sp.Trace) and isinstance(y.arg, sp.MatrixBase),
                     lambda y: y.arg.trace()) if e.has(sp.Trace) else e


def _in_polar_form(entries, seed: int, probes: int, why: str, plan: Plan) -> ZeroResult:
    """Entries with the norm of a free 3-vector under sin/cos, decided with the vector
    written θu (:mod:`rigidsym.zero.polar`): zero, or undecided with the reason (a
    non-zero result has no exact rational witness in the vector's own entries, which the
    counterexample and its second-semantics check need: it is marked ``polar_differs``, and
    the checker looks for a point of rational norm proven by ball arithmetic)."""
    polar = polar_norms(entries, lambda a, b: decide_zero([a - b], seed, probes, plan).zero
                        is True)
    if polar is None:
        return ZeroResult(None, "undecided", why, plan=plan)
    r = decide_zero(polar[0], seed, probes)
    if r.zero is True:
        return ZeroResult(True, r.method, f"{r.detail}; with {polar[1]}", plan=r.plan)
    if r.zero is False:
        return ZeroResult(None, "undecided",
                          f"the norm of a free vector under sin/cos: written so ({polar[1]}), "
                          f"the sides differ, but no exact counterexample in the vector's "
                          f"own entries is found: for one, declare the vector an angle times a "
                          f"unit vector, --let 'VECTOR = a u' in place of 'VECTOR: vector', "
                          f"with --let 'a: angle' and --let 'u: unit vector' (names the "
                          f"statement does not use; a --let function of the vector, as "
                          f"Forster's Exp, keeps its body as typed)",
                          plan=plan, polar_differs=polar[1])
    return ZeroResult(None, "undecided", f"{why}; with {polar[1]}: {r.detail}", plan=plan)


def decide_zero(entries, seed: int = 0, probes: int = 2, plan: Plan | None = None,
                polar: bool = False) -> ZeroResult:
    """Decide whether every expression in ``entries`` is identically zero on the
    constraint set (see the module docstring for the method and its guarantees).

    ``plan``: the parametrisation to use (that of larger expressions whose parts these are,
    so a witness values every parameter of theirs); by default made from ``entries``. An
    entry with a square root (a norm) irrational at the sample points is decided through
    its square (:mod:`rigidsym.zero.roots`). ``polar``: a norm of a free 3-vector under
    sin/cos is decided with the vector written θu (:mod:`rigidsym.zero.polar`; the checker's
    verdicts), else undecided (the code generator's rewrites keep their choices).
    """
    entries = [_traced(sp.sympify(e)) for e in entries]
    entries = [e for e in entries if e != 0]
    if not entries:
        return ZeroResult(True, "exact-cancel", "all entries cancel structurally", plan=plan)
    top = plan is None
    try:
        plan = make_plan(entries) if top else plan
    except Unsupported as exc:
        return ZeroResult(None, "undecided", str(exc))
    rng = random.Random(seed)
    try:
        prog = parametrised(entries, plan)  # once: shared by the probes and cancellation
    except Unsupported as exc:
        if top and "irrational root" in str(exc) and any(has_roots(e) for e in entries):
            return decide_roots(entries, lambda xs: decide_zero(xs, seed, probes, plan),
                                ZeroResult)
        if top and polar and "trig of non-angle" in str(exc):
            return _in_polar_form(entries, seed, probes, str(exc), plan)
        return ZeroResult(None, "undecided", str(exc), plan=plan)

    def probe(n):
        return _probe(prog, plan, rng, n)

    try:
        hit = probe(probes)
        if hit is not None:
            return ZeroResult(False, "counterexample", "non-zero at an exact rational point",
                              hit[0], hit[1], plan)
        if all(tree_size(e, ENGINE.cancel_node_limit) <= ENGINE.cancel_node_limit for e in entries):
            nonzero = _cancel_within_budget(prog, plan)
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
        d = max(degree_bound(e, plan) for e in entries)  # raises for |x| and roots
        hit = probe(ENGINE.sz_points)
        if hit is not None:
            return ZeroResult(False, "counterexample", "non-zero at an exact rational point",
                              hit[0], hit[1], plan)
        n = ENGINE.sz_points + probes
        prob = sp.Rational(d, SAMPLE_SET_SIZE) ** n
        return ZeroResult(True, "random-exact",
                          f"Schwartz-Zippel: degree <= {d}, |S| = 2^32+1, {n} points, "
                          f"P(false zero) <= {sp.N(prob, 3)}", plan=plan)
    except Unsupported as exc:
        if top and "irrational root" in str(exc) and any(has_roots(e) for e in entries):
            return decide_roots(entries, lambda xs: decide_zero(xs, seed, probes, plan),
                                ZeroResult)
        return ZeroResult(None, "undecided", str(exc), plan=plan)
