"""Accuracy rewrites of a kernel's outputs, chosen by measured error (issue 30).

Before the half-angle rewrite and CSE (:mod:`.optimise`), each build of a kernel (the main
one and each branch) is offered to a few candidate rewrites, in the manner of Herbie
(Panchekha et al., PLDI 2015, "Automatically improving accuracy for floating point
expressions"; Herbie itself is a Racket tool, so the selection here is ours):

1. each rule proposes a candidate (the outputs with a sub-expression replaced);
2. the candidate and the current outputs are evaluated in float64 at *measurement points*:
   exact points (constrained inputs on their manifold: a rotation from rational-looking
   Euler-Rodrigues parameters, a unit vector normalised, all in 40-digit mpmath), rounded to
   float64, over random points and the approaches to every cancellation the inputs' kinds
   have (angles to 0 and pi, rotations to 1 and to a half turn, vectors scaled 1e-6..1e6);
   the reference is the declared outputs at the exact point in mpmath;
3. the candidate is kept when its worst error is at least 4 times smaller, and only after
   the zero test (:func:`rigidsym.zero.decide.decide_zero`, the constraints of the inputs'
   kinds imposed exactly) decides the replaced parts equal to the declared ones.

The rewrite is of the *program* the printers share (C, NumPy, and any later printer), never
of the declaration; each kept rewrite is named, with its reason and measured gain, in the
headers of the generated files (:class:`Chosen`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from rigidsym.algebra.symbols import constrained_group
from rigidsym.codegen.compensated import DiffProd, diffprod, expand_diffprod

__all__ = ["Chosen", "Rewrite", "RULES", "improve"]

#: the candidate must be this many times more accurate (worst case) to be kept
GAIN = 4.0
#: expressions larger than this (operations) are not expanded
EXPAND_LIMIT = 60


@dataclass(frozen=True)
class Rewrite:
    """A candidate rewrite: ``propose(flat, ctx) -> (new flat, [(old, new) parts]) | None``;
    the parts are what the zero test decides equal."""

    name: str
    reason: str
    propose: Callable


@dataclass(frozen=True)
class Chosen:
    """A rewrite kept for one build of a kernel, for the generated source's header."""

    variant: str
    name: str
    reason: str
    before: float        # worst relative error of the outputs before, at the points
    after: float         # and after
    points: int
    decided: str         # the zero test's method

    def line(self) -> str:
        def err(x: float) -> str:
            return "a singular flag" if x == float("inf") else f"{x:.1e}"
        return (f"accuracy rewrite ({self.variant}): {self.name}: {self.reason}; worst "
                f"relative error at {self.points} measurement points (exact, rounded to "
                f"float64; some past a condition number of 1/u) {err(self.before)} -> "
                f"{err(self.after)}; equal to the declared formula by the zero test "
                f"({self.decided})")


# --------------------------------------------------------------------------- rules
def _skew_one_minus_cos(flat, ctx):
    """``(1 - Q00) + (1 - Q11) + (1 - Q22)`` (= 3 - tr Q = 2 (1 - cos phi)) ->
    ``||Q - Q^T||_F^2 / (2 (1 + tr Q))`` (= 2 sin^2 phi / (1 + cos phi))."""
    reps = {}
    for Q in ctx["rotations"]:
        d = [Q[i, i] for i in range(3)]
        old_forms = {sp.Add(*[sp.UnevaluatedExpr(1 - x) for x in d]), 3 - sum(d)}
        skew = sum((Q[i, j] - Q[j, i]) ** 2 for i, j in ((2, 1), (0, 2), (1, 0)))
        new = skew / (1 + sum(d))
        for e in flat:
            for sub in sp.preorder_traversal(e):
                if sub in old_forms:
                    reps[sub] = new
    if not reps:
        return None
    return [e.xreplace(reps) for e in flat], list(reps.items())


def _compensated(n):
    """``n`` (expanded) as a :class:`DiffProd` when it is ``+-a b +- c d`` (every sign: a
    sum of products of opposite signs cancels as a difference does); else None."""
    if not n.is_Add or len(n.args) != 2:
        return None
    pairs = []
    for t in n.args:
        c, fs = t.as_coeff_mul()
        if c not in (1, -1):
            return None
        fs = [f for x in fs for f in ([x.base] * int(x.exp) if x.is_Pow and x.exp.is_Integer
                                      and 1 <= x.exp <= 2 else [x])]
        if len(fs) != 2:
            return None
        pairs.append((c * fs[0], fs[1]))
    (a, b), (c, d) = sorted(pairs, key=lambda ab: sp.default_sort_key(ab[0] * ab[1]))
    return DiffProd(a, b, -c, d)


def _expand_numerators(flat, ctx):
    """Each small output ``n / d`` with its numerator expanded: cancelling terms of the
    declared grouping (``p1 x (p2 - p1)``) cancel symbolically, not in floating point; a
    numerator then of two products (a cross product ``p1 x p2``) is a compensated
    difference of products (:mod:`rigidsym.codegen.compensated`): ``p1 x p2`` of nearly
    parallel points cancels in floating point as ``p1 x (p2 - p1)`` did not."""
    out, parts = [], []
    for e in flat:
        if e.has(sp.Piecewise) or sp.count_ops(e) > EXPAND_LIMIT or ctx["angles"] and \
                e.has(*ctx["angles"]):
            out.append(e)
            continue
        n, d = sp.fraction(sp.together(e))
        ne = sp.expand(n)
        if sp.count_ops(ne) >= sp.count_ops(n) + 4 or ne == n:
            out.append(e)
            continue
        ne = _compensated(ne) or ne
        out.append(ne / d)
        parts.append((n, ne))
    return (out, parts) if parts else None


def _rewritten_then_differentiated(flat, ctx):
    """A ``<name>_with_jacobians`` kernel: its values through the other rules, and its
    derivatives those of the rewritten values (a rewrite of unconstrained inputs only: two
    functions equal on an open set have equal derivatives)."""
    k = ctx["kernel"]
    if not k.name.endswith("_with_jacobians"):
        return None
    m = len(k.outputs) // (1 + len(k.args))
    sizes = [o.size for o in k.outputs[:m]]
    nv = sum(sizes)
    values, parts = flat[:nv], []
    for rule in (r for r in RULES if r.propose is not _rewritten_then_differentiated):
        got = rule.propose(values, ctx)
        if got is not None:
            values, p = got
            parts += p
    constrained = {x for a in k.args if a.kind != "any" for x in ctx["flat"][a.name]}
    if not parts or any(sp.sympify(o).free_symbols & constrained for o, _ in parts):
        return None
    out, start = list(values), 0
    for size in sizes:
        f = values[start:start + size]
        for a in k.args:
            out += [sp.diff(fi, x) for fi in f for x in ctx["flat"][a.name]]
        start += size
    return out, parts


RULES = (
    Rewrite("derivatives of the rewritten values",
            "the Jacobian of the declared grouping inherits its cancellation; the "
            "derivatives of the rewritten values do not",
            _rewritten_then_differentiated),
    Rewrite("1 - cos(phi) from the skew part of Q",
            "3 - tr Q cancels as phi -> 0 and the rounding of the diagonal of Q is "
            "relative 1/phi^2 there; the skew part keeps relative accuracy 1/phi, the "
            "condition of the problem (valid where 1 + tr Q does not cancel: cos phi > -1/2)",
            _skew_one_minus_cos),
    Rewrite("expanded numerator",
            "the declared grouping subtracts nearly equal products (p1 x (p2 - p1) with "
            "|p1| >> |p2 - p1|); expanded, the cancelling terms cancel symbolically, and "
            "the difference of two products left is compensated (Kahan's algorithm, "
            "rigidsym.codegen.compensated: p1 x p2 of nearly coincident points cancels too)",
            _expand_numerators),
)


# --------------------------------------------------------------------------- measurement
def _kind(arg):
    from rigidsym import _kinds

    return _kinds.for_spec(arg.kind, arg.shape)


def _points(kernel, rng, n_random: int = 6):
    """Exact points (mpmath, 40 digits) per argument, flat, over the regimes of the kinds."""
    def base():
        return [_random(a, rng) for a in kernel.args]

    pts = [base() for _ in range(n_random)]
    small = [10.0**-k for k in (1, 3, 5, 7, 9, 11, 13, 15, 20, 100)]
    for i, a in enumerate(kernel.args):
        for s in small:
            if a.kind == "angle":
                for phi in (s, -s, math.pi * (1 - s)):
                    p = base()
                    p[i] = [mpmath.mpf(phi)]
                    pts.append(p)
                continue
            if a.kind == "rotation":
                for t, t0 in ((s, 1), (1, s)):
                    p = base()
                    p[i] = _rotation(_unit(rng, 3), t, t0)
                    pts.append(p)
                continue
            if a.kind == "any" and a.shape == (3,):
                for scale in (s, 1 / s) if s >= 1e-6 else ():
                    p = base()
                    p[i] = [x * scale for x in p[i]]
                    pts.append(p)
                # nearly coincident points (|p2 - p1| / |p| = s), near the origin and at a
                # large offset (issue 37: the regimes where p1 x p2 cancels)
                for j, b in enumerate(kernel.args):
                    if j <= i or b.kind != "any" or b.shape != (3,) or s < 1e-13:
                        continue
                    for offset in (1, 1e6):
                        p = base()
                        # floats: the reference judges the formula, not the rounding
                        p[i] = [mpmath.mpf(float(x * offset)) for x in p[i]]
                        p[j] = [mpmath.mpf(float(x + s * offset * r)) for x, r in
                                zip(p[i], rng.standard_normal(3), strict=True)]
                        pts.append(p)
    return pts


def _unit(rng, n):
    v = [mpmath.mpf(float(x)) for x in rng.standard_normal(n)]
    nn = mpmath.sqrt(sum(x * x for x in v))
    return [x / nn for x in v]


def _rotation(e, r, r0):
    x, y, z = (mpmath.mpf(r) * v for v in e)
    r0 = mpmath.mpf(r0)
    n = x * x + y * y + z * z + r0 * r0
    Q = [[r0 * r0 + x * x - y * y - z * z, 2 * (x * y - r0 * z), 2 * (x * z + r0 * y)],
         [2 * (x * y + r0 * z), r0 * r0 - x * x + y * y - z * z, 2 * (y * z - r0 * x)],
         [2 * (x * z - r0 * y), 2 * (y * z + r0 * x), r0 * r0 - x * x - y * y + z * z]]
    return [v / n for row in Q for v in row]


def _random(arg, rng):
    if arg.kind == "unit":
        return _unit(rng, arg.size)
    if arg.kind == "rotation":
        return _rotation(_unit(rng, 3), rng.uniform(0.1, 2), 1)
    return [mpmath.mpf(float(x)) for x in rng.standard_normal(arg.size)]


class _Meter:
    """The declared outputs at the measurement points (mpmath) and a candidate's error."""

    def __init__(self, kernel, flat, syms_flat, conds, cond):
        rng = np.random.default_rng(30)
        with mpmath.workdps(40):
            pts = _points(kernel, rng)
        self.syms = syms_flat
        offs = np.cumsum([0] + [o.size for o in kernel.outputs])
        self.groups = [slice(a, b) for a, b in zip(offs[:-1], offs[1:], strict=True)]
        keep = []
        for p in pts:
            row = [float(x) for a in p for x in a]
            ok = cond is None or bool(cond(*row))
            ok = ok and not any(bool(c(*row)) for c in conds)
            if ok:
                keep.append(p)
        self.exact = keep
        self.rounded = np.array([[float(x) for a in p for x in a] for p in keep], dtype=float)
        f = sp.lambdify(syms_flat, flat, modules="mpmath", cse=True)
        refs = []
        with mpmath.workdps(40):
            for p in keep:
                try:
                    refs.append([float(v) for v in f(*[x for a in p for x in a])])
                except (ZeroDivisionError, ValueError):
                    refs.append([math.nan] * len(flat))
        self.ref = np.array(refs, dtype=float).reshape(len(keep), len(flat))

    def worst(self, flat) -> float:
        if not len(self.exact):
            return 0.0
        f = sp.lambdify(self.syms, flat, modules=[{"DiffProd": diffprod}, "numpy"], cse=True)
        with np.errstate(all="ignore"):
            got = np.array([np.broadcast_to(np.asarray(v, dtype=float), (len(self.exact),))
                            for v in f(*self.rounded.T)]).T
        ok = np.isfinite(self.ref).all(axis=1)
        if not ok.any():
            return 0.0
        r, g = self.ref[ok], got[ok]
        floor = 1e-12 * np.abs(r).max(axis=1)     # an output group that is exactly zero
        err = np.zeros(len(r))
        for sl in self.groups:                     # per output, normwise (as the harness)
            scale = np.maximum(np.maximum(np.abs(r[:, sl]).max(axis=1), floor), 1e-300)
            err = np.maximum(err, np.abs(g[:, sl] - r[:, sl]).max(axis=1) / scale)
        err = np.where(np.isfinite(err), err, np.inf)
        return float(err.max())


def _constrained(kernel, syms_by_arg) -> dict:
    """Kernel input symbols -> the zero test's constrained atoms of the same kinds."""
    sub = {}
    for a in kernel.args:
        kind = {"unit": "unit" if a.size == 3 else "unit4", "rotation": "rotation",
                "angle": "angle"}.get(a.kind)
        if kind is None:
            continue
        g = constrained_group(kind, f"zt_{a.name}")
        old = syms_by_arg[a.name]
        if a.shape == ():
            sub[old] = g
        else:
            sub.update(dict(zip(list(old), list(g), strict=True)))
    return sub


def _decide(parts, sub) -> str:
    from rigidsym.zero.decide import decide_zero

    def bare(x):      # the zero test reads no UnevaluatedExpr (a grouping, not a value)
        x = expand_diffprod(x).xreplace(sub)
        return x.replace(lambda y: isinstance(y, sp.UnevaluatedExpr), lambda y: y.args[0])

    diff = [bare(o) - bare(n) for o, n in parts]
    res = decide_zero([sp.expand(d) if not d.has(sp.Piecewise) else d for d in diff])
    if res.zero is not True:
        raise AssertionError(f"an accuracy rewrite is not equal to the declaration: "
                             f"{res.method} {res.detail}")
    return res.method


def improve(kernel, variant: str, flat, syms_by_arg, syms_flat, conds, cond=None):
    """``(flat, [Chosen])``: the outputs with the kept rewrites, and what was kept.

    ``conds`` are the float predicates of the branches tried before this build (a point
    they take is not this build's), ``cond`` this build's own (None for the main build).
    """
    ctx = {"rotations": [syms_by_arg[a.name] for a in kernel.args if a.kind == "rotation"],
           "angles": [syms_by_arg[a.name] for a in kernel.args if a.kind == "angle"],
           "kernel": kernel,
           "flat": {a.name: [syms_by_arg[a.name]] if a.shape == () else
                    list(syms_by_arg[a.name]) for a in kernel.args}}
    proposals = []
    for rule in RULES:
        got = rule.propose(flat, ctx)
        if got is not None:
            proposals.append((rule, got))
    if not proposals:
        return flat, []
    meter = _Meter(kernel, flat, syms_flat, conds, cond)
    best = meter.worst(flat)
    chosen = []
    sub = _constrained(kernel, syms_by_arg)
    for rule, _ in proposals:
        got = rule.propose(flat, ctx)     # again: on the outputs kept so far
        if got is None:
            continue
        cand, parts = got
        w = meter.worst(cand)
        if w * GAIN <= best:
            method = _decide(parts, sub)
            chosen.append(Chosen(variant, rule.name, rule.reason, best, w,
                                 len(meter.exact), method))
            flat, best = cand, w
    return flat, chosen
