"""The judge of the accuracy harness: a kernel's (or any program's) outputs at exact points,
rounded to the float type, against the declared formula's truth (:mod:`.reference`), under
the accuracy rule (:mod:`rigidsym.codegen.accuracy.rule`).

Per output ``o`` of a sample: ``err = ||computed - ref|| / ||ref||`` and the condition
number ``kappa = sum_i ||J_oi|| ||x_i|| / ||ref||``. Verdict **accurate**: ``err <= 8 u
(kappa + 1)`` **and** ``err <= max(2 e_ref, 4 u)``, ``e_ref`` the smallest error of the
textbook formula and of each peer (:mod:`.yardsticks`), the second half decided over a
cloud of neighbours where it fails at the point (:mod:`.cloud`). A flagged sample (NaN) is
**expected** where the exact result is undefined, kappa >= 1e12, kappa u >= 1/8 or the
result overflows the type, else **spurious**. ``benchmarks/accuracy.py`` (the sweep of every
kernel), the project's accuracy tests and ``rigidsym audit`` all judge through :func:`judge`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rigidsym.codegen.accuracy import regimes as P
from rigidsym.codegen.accuracy import rule
from rigidsym.codegen.accuracy.harness import cloud as C
from rigidsym.codegen.accuracy.harness import reference as R
from rigidsym.codegen.accuracy.harness import yardsticks as O
from rigidsym.codegen.accuracy.harness.compare import (
    AtInput,
    Rounded,
    diff,
    judged_by,
    kappa_of,
    point_text,
)

#: a condition number past which a flagged sample is expected
KAPPA_SINGULAR = 1e12


@dataclass
class Row:
    """The worst of one (kernel, dtype, backend, regime)."""

    kernel: str
    dtype: str
    backend: str
    regime: str
    samples: int = 0
    worst_ratio: float = 0.0       # err / (8 u kappa + 8 u): the condition half
    rule_ratio: float = 0.0        # err / rule.allowed (both halves): <= 1 is accurate
    ref_ratio: float = 0.0         # worst err / e_ref where e_ref > 2 u
    err_u: float = 0.0             # worst normwise relative error, in u
    ref_source: str = ""           # the yardstick (textbook or peer) at the worst ref_ratio
    err: float = 0.0               # normwise relative error at the worst ratio
    kappa: float = 0.0             # condition number there
    ulps: float = 0.0              # worst componentwise ulps (components >= 1e-3 ||ref||)
    flagged_expected: int = 0      # singular/NaN where the mathematics is
    beyond: int = 0                # kappa u >= 1/8: the rounding of the input decides all
    spurious: list = field(default_factory=list)   # singular where the result is fine
    worst_point: str = ""
    seed: int = 0                  # the seed of the regimes' points

    @property
    def accurate(self) -> bool:
        return self.rule_ratio <= 1.0 and not self.spurious


def round_points(points, dtype, kernel) -> list[np.ndarray]:
    """Exact ``points`` (per point, per argument, exact components) rounded to ``dtype``:
    one ``(n,) + shape`` array per argument of ``kernel``."""
    n = len(points)
    arrays = []
    for j, a in enumerate(kernel.args):
        v = np.array([[float(x) for x in p[j]] for p in points], dtype=np.float64)
        arrays.append(np.ascontiguousarray(v.astype(dtype).reshape((n,) + a.shape)))
    return arrays


def run_kernel(name: str, arrays, dtype, backend: str) -> np.ndarray:
    """The package's kernel ``name`` on ``backend`` at the rows of ``arrays``: ``(n,
    outputs)`` float64, NaN where it flags a row."""
    from rigidsym import kernels as K

    k = R.kernel_of(name)
    n = arrays[0].shape[0]
    outs = [np.empty((n,) + o.shape, dtype=dtype) for o in k.outputs]
    with np.errstate(all="ignore"):
        K.batch_function(name, backend, dtype=dtype)(*arrays, *outs)
    return np.concatenate([o.reshape(n, -1).astype(np.float64) for o in outs], axis=1)


def judge(name: str, regime: str, points, dtype, backends, refs=None,
          runner=None, reference_half: bool = True) -> list[Row]:
    """Rows (one per backend) of one regime; ``refs`` caches the references per point;
    ``runner(name, arrays, dtype, backend) -> (n, outputs)`` replaces the package's kernels
    (a test hands it a program that loses, to see the harness fail; ``rigidsym audit`` a
    user's function); ``reference_half=False`` judges the condition half alone (no
    yardsticks evaluated: the audit compares with the kernel itself)."""
    k = R.kernel_of(name)
    u = float(np.finfo(dtype).eps) / 2
    sizes = [o.size for o in k.outputs]
    offs = np.cumsum([0] + sizes)
    arrays = round_points(points, dtype, k)
    rows = {b: Row(name, np.dtype(dtype).name, b, regime, len(points)) for b in backends}
    got = {b: (runner or run_kernel)(name, arrays, dtype, b) for b in backends}
    big = float(np.finfo(dtype).max)
    # the yardsticks: the textbook formula in the same type, and each peer
    # (float64 only)
    yard = {"textbook": O.textbook(name, arrays, dtype)} if reference_half else {}
    if reference_half and np.dtype(dtype) == np.float64:
        yard.update(O.evaluate(name, arrays, int(offs[-1])))
    for s, p in enumerate(points):
        flat_rounded = [float(x) for a in arrays for x in a[s].ravel()]
        f = R.pick(name, flat_rounded)
        exact = [x for a in p for x in a]
        key = (name, regime, s, np.dtype(dtype).name)
        if refs is not None and key in refs:
            ref, scale, norms = refs[key]
        else:
            ref, prec = R.reference(f, exact)
            scale, norms = (None, None) if ref is None else R.condition(name, f, p, sizes,
                                                                        ref, prec)
            if refs is not None:
                refs[key] = (ref, scale, norms)
        at_input = AtInput(f, arrays, s) if k.branches else None
        rounded = Rounded(k, f, p, arrays, s, ref)
        cloud = C.Cloud(name, k, p, arrays, s, dtype, runner or run_kernel,
                        kappa_of(scale, norms) if ref is not None else np.inf)
        for b in backends:
            row, c = rows[b], got[b][s]
            flagged = not np.isfinite(c).all()
            kappa = kappa_of(scale, norms) if ref is not None else np.inf
            # the mathematics is singular, or the rounding of the input can reach its
            # singular set (kappa u >= 1/8), or the result overflows the type; a derivative
            # past float64 is a condition number past any bound (beyond, never skipped)
            if ref is None or (flagged and (np.abs(ref).max() > big or kappa >= KAPPA_SINGULAR
                                            or kappa * u >= 0.125)):
                row.flagged_expected += flagged or ref is None
                continue
            if flagged:
                row.spurious.append(point_text(arrays, s))
                continue
            if kappa * u >= 0.125:      # no digit is determined by the input at this type
                row.beyond += 1
                continue
            _judge_outputs(row, b, c, s, arrays, dtype, ref, scale, norms, offs, at_input,
                           rounded, yard, cloud)
    return list(rows.values())


def _judge_outputs(row, b, c, s, arrays, dtype, ref, scale, norms, offs, at_input, rounded,
                   yard, cloud) -> None:
    """Judge each output of sample ``s`` (the kernel's ``c`` on back-end ``b``) into ``row``."""
    u = float(np.finfo(dtype).eps) / 2
    tiny = float(np.finfo(dtype).tiny) / u     # below it an output is (nearly) subnormal
    for o in range(len(offs) - 1):
        sl = slice(offs[o], offs[o + 1])
        # the type holds no relative accuracy there (or the truth overflows float64,
        # the reference's type: the float type cannot say how far off the kernel is)
        if 0 < norms[o] < tiny or not np.isfinite(norms[o]):
            row.beyond += 1
            continue
        norm = norms[o] if norms[o] > 0 else 1.0    # absolute where the truth is 0
        bound = 8 * u * (scale[o] + norms[o])
        err = diff(c[sl], ref[sl], at_input, sl, bound) / norm
        kap = scale[o] / norms[o] if norms[o] > 0 else np.inf
        ratio = err * norm / bound if bound > 0 else (0.0 if err == 0 else np.inf)
        # the reference half compares computations on the same input: against the
        # truth at the input the kernel and the yardsticks all got (unconstrained
        # arguments as rounded; constrained ones stay on their manifold), where the
        # rounding of the input, which the condition half judges, weighs on none
        r2 = rounded.get()[sl]
        n2 = float(np.linalg.norm(r2)) or 1.0
        err2 = diff(c[sl], r2, at_input, sl, bound) / n2
        refs_o = {lab: diff(v[s, sl], r2, at_input, sl, bound) / n2
                  for lab, v in yard.items()} or {"": np.inf}
        src = min(refs_o, key=refs_o.get)
        e_ref = refs_o[src]
        # the condition half as an absolute bound where the truth is 0
        kap_rule = bound / (8 * u * norm) - 1
        half = rule.ratio(err2, u, None, e_ref) if yard else 0.0
        if half > 1:
            # a screen: past it, the medians over a cloud of neighbouring inputs
            # decide (one input's error is luck where kappa u dominates it;
            # harness.cloud)
            half, err2, e_ref, src = cloud.ratio(b, sl, bound, u)
        rr = max(rule.ratio(err, u, kap_rule), half)
        # componentwise, over the components not tiny beside their output (below
        # 1e-3 of its norm a component's ulps say nothing of the result), against
        # the truth at the input the kernel got: the kernel's own error, which the
        # rounding of the input (the condition half's) does not swell to 1e14 ulps
        # of a component that cancels (plucker_from_points at scale 1e6)
        ref_c = judged_by(c[sl], r2, at_input, sl, bound)
        big_ = np.abs(ref_c) >= 1e-3 * n2
        ulp = np.spacing(np.abs(ref_c[big_]).astype(dtype)).astype(np.float64)
        ulps = float(np.max(np.abs(c[sl][big_] - ref_c[big_]) /
                            np.maximum(ulp, 1e-300), initial=0.0))
        row.ulps = max(row.ulps, ulps)
        row.err_u = max(row.err_u, err / u)
        if e_ref > 2 * u and err2 / e_ref > row.ref_ratio:
            row.ref_ratio, row.ref_source = err2 / e_ref, src
        row.rule_ratio = max(row.rule_ratio, rr)
        if ratio > row.worst_ratio:
            row.worst_ratio = ratio
            row.err = err
            row.kappa = kap
            row.worst_point = point_text(arrays, s)


def kernel_names(include_jacobians: bool = True) -> list[str]:
    """Every kernel the package ships (its ``_with_jacobians`` too unless asked not)."""
    from rigidsym.kernels.runtime.state import meta as kernel_meta

    meta = kernel_meta()
    names = sorted(meta)
    return [n for n in names if include_jacobians or not n.endswith("_with_jacobians")]


def sweep(names, dtypes, backends, n_random=8, small=None, progress=None, refs=None,
          runner=None, seeds=(0,)) -> list[Row]:
    """Every row of ``names`` x ``dtypes`` x regimes (``small``: the approach steps), the
    regimes drawn with each of ``seeds`` (more seeds: more points behind each bound)."""
    rows = []
    for name in names:
        k = R.kernel_of(name)
        for dt in dtypes:
            for seed in seeds:
                for regime, pts in P.regimes(k, dt, n_random=n_random, small=small,
                                             seed=seed, derived=True).items():
                    # the refs cache is keyed by regime and index: one seed only
                    for r in judge(name, regime, pts, dt, backends,
                                   refs if len(seeds) == 1 else None, runner):
                        r.seed = seed
                        rows.append(r)
        if progress:
            progress(name, rows)
    return rows


def summary(rows: list[Row], thresholds: dict | None = None) -> dict:
    """Per kernel, the row ``kernels.accuracy(name)`` returns: per float type the worst
    ``err / (u (kappa + 1))`` (``bound``: the error is at most ``bound`` u (kappa + 1)), its
    regime, kappa and error there, the worst componentwise ulps, the flagged and unjudged
    counts; the regimes swept; whether every row is accurate."""
    out: dict = {}
    for r in rows:
        k = out.setdefault(r.kernel, {"regimes": [], "accurate": True, "seeds": []})
        if r.regime not in k["regimes"]:
            k["regimes"].append(r.regime)
        if r.seed not in k["seeds"]:
            k["seeds"].append(r.seed)
        k["accurate"] = bool(k["accurate"] and r.accurate)
        d = k.setdefault(r.dtype, {"bound": 0.0, "regime": "", "kappa": 0.0, "err": 0.0,
                                   "ulps": 0.0, "flagged": 0, "beyond": 0, "spurious": 0,
                                   "rule": 0.0, "backends": {}})
        d["ulps"] = max(d["ulps"], _sig(r.ulps))
        d["rule"] = max(d["rule"], _sig(r.rule_ratio))
        be = d["backends"].setdefault(r.backend, {"err_u": 0.0, "vs_ref": 0.0,
                                                  "vs_ref_where": "", "rule": 0.0})
        be["err_u"] = max(be["err_u"], _sig(r.err_u))
        be["rule"] = max(be["rule"], _sig(r.rule_ratio))
        if _sig(r.ref_ratio) > be["vs_ref"]:
            be["vs_ref"] = _sig(r.ref_ratio)
            be["vs_ref_where"] = f"{r.regime}, against {r.ref_source}"
        d["flagged"] += r.flagged_expected
        d["beyond"] += r.beyond
        d["spurious"] += len(r.spurious)
        if 8 * r.worst_ratio > d["bound"]:
            d.update(bound=_sig(8 * r.worst_ratio), regime=r.regime, kappa=_sig(r.kappa),
                     err=_sig(r.err))
    from rigidsym.kernels.runtime.state import meta as kernel_meta

    for name, k in out.items():
        k["regimes"].sort()
        k["seeds"].sort()
        k["singular"] = kernel_meta()[name]["singular"]
        k["threshold"] = (thresholds or {}).get(name, "")
    return dict(sorted(out.items()))


def _sig(x: float) -> float:
    return float(f"{x:.3g}")
