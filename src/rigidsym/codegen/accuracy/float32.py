"""The precision plan of the float32 kernels: float32 arithmetic wherever the
result stays within the error budget, float64 for the subexpressions that need it.

Found by measuring, per kernel and per subexpression, at generate time. The nodes of a
kernel's straight-line program are its CSE temporaries, its sin/cos values and its output
expressions; a plan gives each one a C type (``"f"``: float, ``"d"``: double). The program
runs under a plan in NumPy, which rounds exactly as C does without FMA contraction (the
x86-64-v2 path; contraction on x86-64-v3 only removes roundings): float32 arrays for float
nodes, float64 for double nodes, C's promotion rules (an operation with a double operand is
double), sin/cos/atan2 in double (C's ``sin`` on a promoted float), sqrt in the type of its
argument (``sqrtf``). Its error is measured as the harness measures it
(``benchmarks/accuracy.py``, the rule's reference half): against the program in float64 at the
input the kernel got, the unconstrained arguments as rounded to float32 and the constrained
ones (unit vectors, angles, rotations, transforms) unrounded, on their manifold (float64's
own error there is below 1e-8 ulp of float32); normwise relative per output
(:func:`rigidsym.codegen.accuracy.error.normwise`), at :data:`N_RANDOM` random points, the
adversarial ones of the argument kinds (phi near 0 and pi, omega near 0, gimbal lock) and
the harness's regimes (:mod:`rigidsym.codegen.accuracy.regimes`, drawn with seeds of their
own, :data:`REGIME_SEEDS`): :func:`rigidsym.codegen.accuracy.points.plan_inputs`. A point with an
input the C kernels' range test flags (nonzero magnitude outside :data:`RANGE32`) is left
out: C re-runs it in a wider type (the kernels' rescue), so the plan never computes it.

The search (:func:`choose`): all float if that stays within :data:`TARGET` of
:data:`BUDGET` at every point (where the kernel in double, rounded once, already uses more
than that: within its own ratio plus ``1 - TARGET``, and never past the rule where double is
within it); else, from all double, each node is made float in the order of its own error
(the node alone in float), kept float when the whole plan still is. The double nodes are
named in the generated header.

The budget is the accuracy rule (:mod:`rigidsym.codegen.accuracy.rule`), per output and point:
the error (normwise relative) within ``max(2 e_ref, 4 u)``, ``e_ref`` the error of the textbook
formula (the declaration evaluated naively, in float32 arithmetic, at the same inputs),
``u = 2**-24``; its condition half (``8 u (kappa + 1)``) is the harness's, which has the
condition number. So a node stays in double only where float would make the kernel worse
than the formula a user would write, or than 4 u where that formula is better;
tests/test_float32.py asserts the same against the 50-digit reference.
"""

from __future__ import annotations

import numpy as np

from rigidsym.codegen.accuracy import elementary, rule
from rigidsym.codegen.accuracy.compensated import diffprod, sumprod
from rigidsym.codegen.accuracy.error import budget, normwise, round_up, worst
from rigidsym.codegen.accuracy.points import (  # noqa: F401  (the planner's points, re-exported)
    N_RANDOM,
    RANGE32,
    REGIME_SEEDS,
    plan_inputs,
    regime_inputs,
    sample_inputs,
)

__all__ = ["BUDGET", "U32", "N_RANDOM", "REGIME_SEEDS", "RANGE32", "sample_inputs",
           "regime_inputs", "plan_inputs", "choose", "ProgramSpec", "trig_spec", "plan_kernel"]

#: the unit roundoff of float32
U32 = 2.0**-24


def BUDGET(e_ref):
    """The largest error the plan allows at a point and output (normwise relative against
    the float64 program): the accuracy rule, :func:`rigidsym.codegen.accuracy.rule.allowed`, with
    ``e_ref`` the textbook formula's error in float32 there: ``max(2 e_ref, 4 u)``. The
    planner has no condition number: the rule's condition half, ``8 u (kappa + 1)``, is
    judged by the harness (``benchmarks/accuracy.py``, float32 on C and NumPy)."""
    return budget(e_ref, U32)
#: the share of :data:`BUDGET` a plan may use at its own points: they are a sample and the
#: harness and the tests judge at others, where a plan that used its whole budget here
#: went past it (at 1: screw_axis_point 4.3 u against 4 u at one of the harness's random
#: points, L_tilde_dot_with_jacobians 1.4 of the rule at ||omega|| -> 0)
TARGET = 0.75
_F32, _F64 = np.float32, np.float64


class _Shim:
    """``numpy`` for the printed expressions: the transcendental functions in double (C's
    ``sin`` of a promoted float), with the values of
    :mod:`rigidsym.codegen.accuracy.elementary` (the same on every machine); everything
    else NumPy's (sqrt keeps its argument's type)."""

    def sin(self, x):
        return elementary.sin(np.asarray(x, dtype=_F64))

    def cos(self, x):
        return elementary.cos(np.asarray(x, dtype=_F64))

    def arctan2(self, y, x):
        return elementary.arctan2(np.asarray(y, dtype=_F64), np.asarray(x, dtype=_F64))

    def __getattr__(self, name):
        return getattr(elementary.NUMPY, name)


def _diffprod64(*args):
    # C's rigidsym_diffprod is a double function: float arguments are widened
    return diffprod(*(np.asarray(a, dtype=_F64) for a in args))


def _sumprod64(*args):
    # and rigidsym_sumprod<n>
    return sumprod(*(np.asarray(a, dtype=_F64) for a in args))


_GLOBALS = {"numpy": _Shim(), "_diffprod": _diffprod64, "_sumprod": _sumprod64}


class ProgramSpec:
    """One straight-line program to plan: temporaries, outputs, and the trig values it reads
    (``trig_<k>`` symbols, computed in double by the batch loop)."""

    def __init__(self, temps: list, outputs: list, trig: dict | None = None):
        npp = elementary.KERNEL_PRINTER()
        self.temps = [(str(s), compile(npp.doprint(e), str(s), "eval")) for s, e in temps]
        self.outputs = [compile(npp.doprint(e), f"out{j}", "eval")
                        for j, e in enumerate(outputs)]
        self.trig = trig or {}            # name -> compiled double expression of the inputs
        self.nodes = ([n for n in self.trig] + [n for n, _ in self.temps]
                      + [f"out:{j}" for j in range(len(outputs))])

    def run(self, cols: dict, plan: dict | None) -> np.ndarray:
        """Outputs ``(n, nout)`` as float64: under ``plan`` rounded to float32 at the end;
        ``plan=None``: the float64 reference (nothing rounded)."""
        return self.evaluate(cols, plan)[0]

    def evaluate(self, cols: dict, plan: dict | None, state=None, start: int = 0):
        """``(outputs, state)``: :meth:`run`'s outputs and the values of every node.
        ``state``: an earlier call's at the same points, whose plan agrees with ``plan`` on
        every node before ``nodes[start]``: those values are kept, the rest recomputed (a
        trial of the search changes one node: half the program on average)."""
        if state is None:
            env, env64 = dict(cols), {k: np.asarray(v, dtype=_F64) for k, v in cols.items()}
            outs, start = [None] * len(self.outputs), 0
        else:
            env, env64, outs = dict(state[0]), dict(state[1]), list(state[2])
        shape = next(iter(cols.values())).shape
        nt = len(self.trig)
        with np.errstate(all="ignore"):
            for i, (name, code) in enumerate(self.trig.items()):
                if i >= start:
                    self._store(name, eval(code, _GLOBALS, env64), plan, env, env64)
            for i, (name, code) in enumerate(self.temps, nt):
                if i >= start:
                    ctx = "d" if plan is None else plan[name]
                    v = eval(code, _GLOBALS, env64 if ctx == "d" else env)
                    self._store(name, v, plan, env, env64)
            for j, code in enumerate(self.outputs, nt + len(self.temps)):
                if j >= start:
                    k = j - nt - len(self.temps)
                    ctx = "d" if plan is None else plan[f"out:{k}"]
                    v = np.broadcast_to(np.asarray(eval(code, _GLOBALS, env64 if ctx == "d"
                                                        else env)), shape)
                    outs[k] = v.astype(_F64) if plan is None else v.astype(_F32).astype(_F64)
        return np.stack(outs, axis=1), (env, env64, outs)

    @staticmethod
    def _store(name, v, plan, env, env64) -> None:
        v = np.asarray(v)
        if plan is not None and plan[name] == "f":
            v = v.astype(_F32)
        else:
            v = v.astype(_F64)
        env[name] = v
        env64[name] = v.astype(_F64)


def choose(prog: ProgramSpec, cols: dict, groups=None, textbook=None,
           exact: dict | None = None) -> tuple[dict, float]:
    """The plan of ``prog`` at the points ``cols`` (rows where the reference is finite),
    and its worst ratio to :data:`BUDGET` where the kernel in double is within it (at most
    1: :data:`TARGET`, or the ratio of the kernel in double plus ``1 - TARGET``).
    ``groups``: the slices of the outputs (default: one); ``textbook``: ``(n, outputs)``
    the textbook formula in float32 at the points (default: none, the 4 u floor);
    ``exact``: the inputs of the truth (default ``cols``; the program in float64 there is
    the reference)."""
    ref = prog.run(cols if exact is None else exact, None)
    keep = np.isfinite(ref).all(axis=1)
    cols = {k: v[keep] for k, v in cols.items()}
    ref = ref[keep]
    nodes = prog.nodes
    if not len(ref):
        return dict.fromkeys(nodes, "d"), 0.0
    groups = groups or [slice(0, ref.shape[1])]
    e_ref = (normwise(textbook[keep], ref, groups) if textbook is not None
             else np.zeros((len(ref), len(groups))))
    allowed = BUDGET(e_ref)
    # the kernel in double, rounded once: where it already uses much of the budget (the
    # rounding of a constrained input, which the truth does not see, outweighs the
    # arithmetic) a plan may add 1 - TARGET of it, but not past the rule where double is
    # within it
    with np.errstate(all="ignore"):
        r0 = normwise(prog.run(cols, dict.fromkeys(nodes, "d")), ref, groups) / allowed
    r0 = np.where(np.isfinite(r0), r0, np.inf)
    room = r0 + 1 - TARGET
    limit = allowed * np.where(r0 <= 1, np.clip(room, TARGET, 1), room)

    def ratios(plan, rows=None, state=None, start=0):
        c = cols if rows is None else {k: v[rows] for k, v in cols.items()}
        out, state = prog.evaluate(c, plan, state, start)
        with np.errstate(all="ignore"):
            e = normwise(out, ref if rows is None else ref[rows], groups)
            lim = limit if rows is None else limit[rows]
            return np.where(e == 0, 0.0, e / lim).max(axis=1), state

    def score(plan):
        # the worst ratio to the rule where the kernel in double is within it (elsewhere
        # the rounding of a constrained input decides, which no plan changes)
        ok = r0.max(axis=1) <= 1
        return worst(normwise(prog.run(cols, plan), ref, groups)[ok], e_ref[ok], U32,
                     every_point=True, rounded=True)

    plan = dict.fromkeys(nodes, "f")
    r = ratios(plan)[0]
    if round_up(r.max()) <= 1:
        return plan, score(plan)
    plan = _search(nodes, ratios, r)
    return plan, score(plan)


def _search(nodes: list, ratios, r: np.ndarray) -> dict:
    """The greedy search of :func:`choose` from all double; ``ratios(plan, rows, state,
    start) -> (per-row ratio to the limit, state)``, ``r`` the all-float plan's ratios."""
    base = dict.fromkeys(nodes, "d")
    # the search runs on the points where float arithmetic comes nearest the limit (past
    # half of it, the 1000 worst), then the plan is checked at every point and the points
    # it fails join (the search runs the program nodes^2 times: over every point it was
    # most of the generation's time)
    rows = np.zeros(len(r), dtype=bool)
    rows[np.argsort(-r, kind="stable")[:1000]] = True
    rows &= r > 0.5
    index = {n: i for i, n in enumerate(nodes)}
    while True:
        _, s0 = ratios(base, rows)
        alone = {n: round_up(ratios(base | {n: "f"}, rows, s0, index[n])[0].max())
                 for n in nodes}
        plan, state = base, s0
        for n in sorted(nodes, key=lambda n: (alone[n], index[n])):
            trial = plan | {n: "f"}
            rt, st = ratios(trial, rows, state, index[n])
            if round_up(rt.max()) <= 1:
                plan, state = trial, st
        r = ratios(plan)[0]
        if round_up(r.max()) <= 1:
            break
        rows |= r > 1
    return plan


def trig_spec(calls: dict, pre: list) -> dict:
    """The trig values of a split program: ``{trig_k: compiled double expression}`` (the
    prelude's temporaries substituted)."""
    npp = elementary.KERNEL_PRINTER()
    defs = dict(pre)
    out = {}
    for name, call in calls.items():
        e = call
        for _ in range(len(defs) + 1):
            e2 = e.xreplace(defs)
            if e2 == e:
                break
            e = e2
        out[name] = compile(npp.doprint(e), name, "eval")
    return out


def _variant_points(variants, cols: dict) -> list[np.ndarray]:
    """Per variant, the points whose branch it is (conditions in double, first true wins)."""
    npp = elementary.KERNEL_PRINTER()
    env64 = {k: np.asarray(v, dtype=_F64) for k, v in cols.items()}
    n = len(next(iter(cols.values())))
    left = np.ones(n, dtype=bool)
    masks = []
    for v in variants:
        if v.cond is None:
            m = left.copy()
        else:
            with np.errstate(all="ignore"):
                c = np.broadcast_to(np.asarray(eval(compile(npp.doprint(v.cond), "cond", "eval"),
                                                    _GLOBALS, env64), dtype=bool), (n,))
            m = left & c
        masks.append(m)
        left &= ~m
    return masks


def plan_kernel(kernel, variants, split: dict | None) -> dict:
    """The precision plans of a kernel: of its trig split's per-sample program when it has
    one (``"trig"``), else of each variant (``"variants"``), with their worst ratios to
    :data:`BUDGET` (the accuracy rule against the textbook formula in float32)."""
    from rigidsym.codegen.spec import flat_symbols

    cols, exact = plan_inputs(kernel)
    offs = np.cumsum([0] + [o.size for o in kernel.outputs])
    groups = [slice(int(a), int(b)) for a, b in zip(offs[:-1], offs[1:], strict=True)]
    names = [str(s) for _, ss in flat_symbols(kernel) for s in ss]
    tb = rule.textbook(kernel, [cols[n] for n in names], _F32)
    if split is not None:
        prog = split["program"]
        spec = ProgramSpec(prog.temps, prog.outputs, trig_spec(split["calls"], split["pre"]))
        plan, err = choose(spec, cols, groups, tb, exact)
        return {"trig": {"plan": plan, "error": err}, "variants": None}
    plans = []
    for v, mask in zip(variants, _variant_points(variants, cols), strict=True):
        spec = ProgramSpec(v.program.temps, v.program.outputs)
        plan, err = choose(spec, {k: c[mask] for k, c in cols.items()}, groups, tb[mask],
                           {k: c[mask] for k, c in exact.items()})
        plans.append({"plan": plan, "error": err})
    return {"trig": None, "variants": plans}
