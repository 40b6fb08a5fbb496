"""The precision plan of the float32 kernels (issue 20): float32 arithmetic wherever the
result stays within the error budget, float64 for the subexpressions that need it.

Found by measuring, per kernel and per subexpression, at generate time. The nodes of a
kernel's straight-line program are its CSE temporaries, its sin/cos values and its output
expressions; a plan gives each one a C type (``"f"``: float, ``"d"``: double). The program
runs under a plan in NumPy, which rounds exactly as C does without FMA contraction (the
x86-64-v2 path; contraction on x86-64-v3 only removes roundings): float32 arrays for float
nodes, float64 for double nodes, C's promotion rules (an operation with a double operand is
double), sin/cos/atan2 in double (C's ``sin`` on a promoted float), sqrt in the type of its
argument (``sqrtf``). Its error is measured against the same program in float64 at the same
float32 inputs (float64's own error there is below 1e-8 ulp of float32), normwise as in
tests/test_float32.py: the max-norm of the difference over the max-norm of the reference,
per sample, in units of float32's epsilon, at :data:`N_RANDOM` random points and the
adversarial ones of the argument kinds (phi near 0 and pi, omega near 0, gimbal lock).

The search: all float if that meets :data:`BUDGET`; else, from all double, each node is made
float in the order of its own error (the node alone in float), kept float when the whole
plan still meets the budget. The double nodes are named in the generated header.

The budget is the rule of issue 37 (:mod:`rigidsym.codegen.rule`), per output and point: the
error (normwise relative) within ``max(2 e_ref, 4 u)``, ``e_ref`` the error of the textbook
formula (the declaration evaluated naively, in float32 arithmetic, at the same inputs),
``u = 2**-24``; its condition half (``8 u (kappa + 1)``) is the harness's, which has the
condition number. So a node stays in double only where float would make the kernel worse
than the formula a user would write, or than 4 u where that formula is better;
tests/test_float32.py asserts the same against the 50-digit reference.
"""

from __future__ import annotations

import math

import numpy as np

from rigidsym.codegen import rule
from rigidsym.codegen.compensated import diffprod, sumprod
from rigidsym.codegen.printers import KernelNumPyPrinter

__all__ = ["BUDGET", "U32", "N_RANDOM", "sample_inputs", "choose", "ProgramSpec", "trig_spec",
           "plan_kernel"]

#: the unit roundoff of float32
U32 = 2.0**-24


def BUDGET(e_ref):
    """The largest error the plan allows at a point and output (normwise relative against
    the float64 program): issue 37's rule, :func:`rigidsym.codegen.rule.allowed`, with
    ``e_ref`` the textbook formula's error in float32 there: ``max(2 e_ref, 4 u)``. The
    planner has no condition number: the rule's condition half, ``8 u (kappa + 1)``, is
    judged by the harness (``benchmarks/accuracy.py``, float32 on C and NumPy)."""
    return np.maximum(rule.REF_FACTOR * np.asarray(e_ref), rule.FLOOR * U32)
#: random points per kernel (then the adversarial ones)
N_RANDOM = 1000
_ADV_PHI = [1e-12, 1e-8, 1e-4, 1e-2, np.pi - 1e-4, np.pi - 1e-2, -1e-6, 3.0]
_F32, _F64 = np.float32, np.float64


def _unit(rng, n: int, k: int = 3) -> np.ndarray:
    x = rng.standard_normal((n, k))
    return x / np.linalg.norm(x, axis=1, keepdims=True)


def _rotations(e: np.ndarray, phi: np.ndarray) -> np.ndarray:
    c, s = np.cos(phi)[:, None, None], np.sin(phi)[:, None, None]
    x = np.zeros((len(e), 3, 3))
    x[:, 0, 1], x[:, 0, 2], x[:, 1, 2] = -e[:, 2], e[:, 1], -e[:, 0]
    x -= np.transpose(x, (0, 2, 1))
    ee = np.einsum("ni,nj->nij", e, e)
    return ee + c * (np.eye(3) - ee) + s * x


def sample_inputs(args, n: int = N_RANDOM, seed: int = 20) -> dict[str, np.ndarray]:
    """float32 values per flat input symbol (``e_0``, ``phi``, ``Q_01``): ``n`` random rows
    then adversarial ones, by argument kind and name (as tests/test_kernels.py)."""
    rng = np.random.default_rng(seed)
    adv = len(_ADV_PHI)
    names = [a.name for a in args]
    cols: dict[str, np.ndarray] = {}
    for a in args:
        m = n + adv
        if a.kind == "unit":
            v = _unit(rng, m, a.size)
        elif a.kind == "angle":
            v = np.concatenate([rng.uniform(-np.pi, np.pi, n), _ADV_PHI])
        elif a.kind == "rotation":
            v = _rotations(_unit(rng, m), np.concatenate([rng.uniform(0, np.pi, n),
                                                          _ADV_PHI]))
        elif a.kind == "transform":
            v = np.zeros((m, 4, 4))
            v[:, :3, :3] = _rotations(_unit(rng, m), np.concatenate([
                rng.uniform(0, np.pi, n), _ADV_PHI]))
            v[:, :3, 3], v[:, 3, 3] = rng.standard_normal((m, 3)), 1.0
        elif a.name == "m":
            v = rng.uniform(0.5, 2.0, m)
        elif a.name == "I_C":
            g = rng.standard_normal((m, 3, 3))
            v = np.einsum("nij,nkj->nik", g, g) + 0.1 * np.eye(3)
        else:
            v = rng.standard_normal((m,) + tuple(a.shape))
            if a.name == "omega" and "omega_dot" not in names and "phi" not in names:
                # down to 1e-18 (issue 30): a Jacobian's ||omega||^-3 overflows float32
                # below 7e-13, so the plan must see such omegas to keep that node in double
                v[n:n + 5] *= np.array([1e-12, 1e-6, 1e-3, 1e-15, 1e-18])[:, None] / \
                    np.linalg.norm(v[n:n + 5], axis=1, keepdims=True)
            if a.name == "angles":   # gimbal lock of either family, as close as float32 gets
                v[n:n + 8, 1] = [1e-9, np.pi / 2 - 1e-9, -1e-9, np.pi / 2 + 1e-9, 1e-6,
                                 np.pi / 2 - 1e-3, 1e-2, 1.5]
        flat = np.asarray(v, dtype=_F32).reshape(m, -1)
        if a.shape == ():
            cols[a.name] = flat[:, 0]
        elif len(a.shape) == 1:
            for i in range(a.shape[0]):
                cols[f"{a.name}_{i}"] = flat[:, i]
        else:
            r, c = a.shape
            for i in range(r):
                for j in range(c):
                    cols[f"{a.name}_{i}{j}"] = flat[:, i * c + j]
    return cols


class _Shim:
    """``numpy`` for the printed expressions: the transcendental functions in double (C's
    ``sin`` of a promoted float), everything else NumPy's (sqrt keeps its argument's type)."""

    def sin(self, x):
        return np.sin(np.asarray(x, dtype=_F64))

    def cos(self, x):
        return np.cos(np.asarray(x, dtype=_F64))

    def arctan2(self, y, x):
        return np.arctan2(np.asarray(y, dtype=_F64), np.asarray(x, dtype=_F64))

    def __getattr__(self, name):
        return getattr(np, name)


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
        npp = KernelNumPyPrinter()
        self.temps = [(str(s), compile(npp.doprint(e), str(s), "eval")) for s, e in temps]
        self.outputs = [compile(npp.doprint(e), f"out{j}", "eval")
                        for j, e in enumerate(outputs)]
        self.trig = trig or {}            # name -> compiled double expression of the inputs
        self.nodes = ([n for n in self.trig] + [n for n, _ in self.temps]
                      + [f"out:{j}" for j in range(len(outputs))])

    def run(self, cols: dict, plan: dict | None) -> np.ndarray:
        """Outputs ``(n, nout)`` as float64: under ``plan`` rounded to float32 at the end;
        ``plan=None``: the float64 reference (nothing rounded)."""
        env = dict(cols)
        env64 = {k: np.asarray(v, dtype=_F64) for k, v in cols.items()}
        with np.errstate(all="ignore"):
            for name, code in self.trig.items():
                v = eval(code, _GLOBALS, env64)
                self._store(name, v, plan, env, env64)
            for name, code in self.temps:
                ctx = "d" if plan is None else plan[name]
                v = eval(code, _GLOBALS, env64 if ctx == "d" else env)
                self._store(name, v, plan, env, env64)
            outs = []
            for j, code in enumerate(self.outputs):
                ctx = "d" if plan is None else plan[f"out:{j}"]
                v = np.asarray(eval(code, _GLOBALS, env64 if ctx == "d" else env))
                v = np.broadcast_to(v, next(iter(cols.values())).shape)
                outs.append(v.astype(_F64) if plan is None else v.astype(_F32).astype(_F64))
        return np.stack(outs, axis=1)

    @staticmethod
    def _store(name, v, plan, env, env64) -> None:
        v = np.asarray(v)
        if plan is not None and plan[name] == "f":
            v = v.astype(_F32)
        else:
            v = v.astype(_F64)
        env[name] = v
        env64[name] = v.astype(_F64)


def _errors(got: np.ndarray, ref: np.ndarray, groups) -> np.ndarray:
    """``(samples, outputs)``: the normwise relative error of each output (absolute where it
    is exactly 0; inf where not finite)."""
    out = np.zeros((len(ref), len(groups)))
    for j, sl in enumerate(groups):
        norm = np.linalg.norm(ref[:, sl], axis=1)
        with np.errstate(all="ignore"):
            d = np.linalg.norm(got[:, sl] - ref[:, sl], axis=1)
            e = np.where(norm > 0, d / np.where(norm > 0, norm, 1.0), d)
        out[:, j] = np.where(np.isfinite(e), e, np.inf)
    return out


def _worst(err: np.ndarray, allowed: np.ndarray) -> float:
    """The worst ratio to the budget, rounded up to 1e-3 (so that float64 noise never flips
    a decision between machines)."""
    if not err.size:
        return 0.0
    with np.errstate(all="ignore"):
        r = np.where(err == 0, 0.0, err / allowed)
    worst = float(np.max(np.where(np.isfinite(r), r, np.inf)))
    return math.ceil(worst * 1000) / 1000 if math.isfinite(worst) else math.inf


def choose(prog: ProgramSpec, cols: dict, groups=None, textbook=None) -> tuple[dict, float]:
    """The plan of ``prog`` at the points ``cols`` (rows where the reference is finite),
    and its worst ratio to :data:`BUDGET` (<= 1). ``groups``: the slices of the outputs
    (default: one); ``textbook``: ``(n, outputs)`` the textbook formula in float32 at the
    points (default: none, the 4 u floor)."""
    ref = prog.run(cols, None)
    keep = np.isfinite(ref).all(axis=1)
    cols = {k: v[keep] for k, v in cols.items()}
    ref = ref[keep]
    nodes = prog.nodes
    if not len(ref):
        return dict.fromkeys(nodes, "d"), 0.0
    groups = groups or [slice(0, ref.shape[1])]
    e_ref = (_errors(textbook[keep], ref, groups) if textbook is not None
             else np.zeros((len(ref), len(groups))))
    allowed = BUDGET(e_ref)

    def err(plan):
        return _worst(_errors(prog.run(cols, plan), ref, groups), allowed)
    plan = dict.fromkeys(nodes, "f")
    e = err(plan)
    if e <= 1:
        return plan, e
    base = dict.fromkeys(nodes, "d")
    alone = {n: err(base | {n: "f"}) for n in nodes}
    plan, e = base, err(base)
    for n in sorted(nodes, key=lambda n: (alone[n], nodes.index(n))):
        trial = plan | {n: "f"}
        et = err(trial)
        if et <= 1:
            plan, e = trial, et
    return plan, e


def trig_spec(calls: dict, pre: list) -> dict:
    """The trig values of a split program: ``{trig_k: compiled double expression}`` (the
    prelude's temporaries substituted)."""
    npp = KernelNumPyPrinter()
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
    npp = KernelNumPyPrinter()
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
    :data:`BUDGET` (issue 37's rule against the textbook formula in float32)."""
    from rigidsym.codegen.spec import flat_symbols

    cols = sample_inputs(kernel.args)
    offs = np.cumsum([0] + [o.size for o in kernel.outputs])
    groups = [slice(int(a), int(b)) for a, b in zip(offs[:-1], offs[1:], strict=True)]
    names = [str(s) for _, ss in flat_symbols(kernel) for s in ss]
    tb = rule.textbook(kernel, [cols[n] for n in names], _F32)
    if split is not None:
        prog = split["program"]
        spec = ProgramSpec(prog.temps, prog.outputs, trig_spec(split["calls"], split["pre"]))
        plan, err = choose(spec, cols, groups, tb)
        return {"trig": {"plan": plan, "error": err}, "variants": None}
    plans = []
    for v, mask in zip(variants, _variant_points(variants, cols), strict=True):
        spec = ProgramSpec(v.program.temps, v.program.outputs)
        plan, err = choose(spec, {k: c[mask] for k, c in cols.items()}, groups, tb[mask])
        plans.append({"plan": plan, "error": err})
    return {"trig": None, "variants": plans}
