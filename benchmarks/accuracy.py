"""Accuracy of every generated kernel against the condition of the problem (issue 30).

For each kernel (the public ones, their ``<name>_with_jacobians``, the Euler-angle
variants), each float type (float64, float32) and backend (C, NumPy), and each regime of
``_accuracy_points`` (random points; angles to 0 and pi from both sides, exactly 0 and pi;
rotations to the identity and to a half turn; ||omega|| and ||f|| to 0; gimbal lock of each
Euler sequence; points scaled 1e-6 .. 1e6; nearly coincident points; unit vectors a few ulps
off their constraint): exact points, rounded to the float type, handed to the kernel; the
reference is the declared formula in ``arb`` ball arithmetic at the exact point
(``_accuracy_ref``).

Per output ``o`` of a sample: ``err = ||computed - ref|| / ||ref||`` and the condition
number ``kappa = sum_i ||J_oi|| ||x_i|| / ||ref||`` (``J_oi``: the derivative along the
tangent space of argument ``i``; a relative perturbation ``u`` of every argument moves the
output by at most ``u kappa``). Verdict **accurate** by issue 37's rule
(:mod:`rigidsym.codegen.accuracy.rule`): ``err <= 8 u (kappa + 1)`` (the absolute floor judges
outputs that are exactly zero) **and** ``err <= max(2 e_ref, 4 u)``, ``e_ref`` the smallest error of
the textbook formula (the declaration, naively, in the same type) and of each peer that has
the operation (``_accuracy_peers``; float64), the second half measured against the truth at
the input the kernel got (the unconstrained arguments as rounded); where it fails at the
point, it is decided by the medians of the kernel's and the yardsticks' errors over a cloud
of neighbouring inputs (``_accuracy_cloud``: one input's error is luck where ``u kappa``
dominates it). A flagged sample (NaN,
``SingularConfigurationError`` in the API) is
**expected** where the exact result is undefined, kappa >= 1e12, kappa u >= 1/8 (the
rounding of the input can reach the singular set) or the result overflows the type, else
**spurious**. A finite sample with kappa u >= 1/8, or an output below ``tiny / u`` or past
float64, is not judged (``beyond``).

Usage (from the repository root)::

    python benchmarks/accuracy.py [--kernels A,B] [--dtypes float64,float32]
        [--backends c,numpy] [--random N] [--seeds auto|0,1] [--json PATH] [--md PATH]

The full sweep of the 134 kernels takes tens of minutes on one core; ``tests/test_accuracy.py``
runs a float64 subsample.
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _accuracy_cloud as C  # noqa: E402
import _accuracy_peers as O  # noqa: E402
import _accuracy_points as P  # noqa: E402
import _accuracy_ref as R  # noqa: E402
from _accuracy_judge import _AtInput, _diff, _judged_by, _kappa, _point, _Rounded  # noqa: E402,F401
from _accuracy_seeds import DATA, DEFAULT_SEEDS, merged, seeds_for  # noqa: E402,F401
from _accuracy_tables import kernel_table, markdown, rule_table, synced  # noqa: E402,F401

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.accuracy import rule  # noqa: E402

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


def _round(points, dtype, kernel):
    n = len(points)
    arrays = []
    for j, a in enumerate(kernel.args):
        v = np.array([[float(x) for x in p[j]] for p in points], dtype=np.float64)
        arrays.append(np.ascontiguousarray(v.astype(dtype).reshape((n,) + a.shape)))
    return arrays


def run_kernel(name: str, arrays, dtype, backend: str) -> np.ndarray:
    k = R.kernel_of(name)
    n = arrays[0].shape[0]
    outs = [np.empty((n,) + o.shape, dtype=dtype) for o in k.outputs]
    with np.errstate(all="ignore"):
        K.batch_function(name, backend, dtype=dtype)(*arrays, *outs)
    return np.concatenate([o.reshape(n, -1).astype(np.float64) for o in outs], axis=1)


def judge(name: str, regime: str, points, dtype, backends, refs=None,
          runner=None) -> list[Row]:
    """Rows (one per backend) of one regime; ``refs`` caches the references per point;
    ``runner(name, arrays, dtype, backend) -> (n, outputs)`` replaces the package's kernels
    (a test hands it a program that loses, to see the harness fail)."""
    k = R.kernel_of(name)
    u = float(np.finfo(dtype).eps) / 2
    sizes = [o.size for o in k.outputs]
    offs = np.cumsum([0] + sizes)
    arrays = _round(points, dtype, k)
    rows = {b: Row(name, np.dtype(dtype).name, b, regime, len(points)) for b in backends}
    got = {b: (runner or run_kernel)(name, arrays, dtype, b) for b in backends}
    big = float(np.finfo(dtype).max)
    tiny = float(np.finfo(dtype).tiny) / u     # below it an output is (nearly) subnormal
    # the yardsticks (issue 37): the textbook formula in the same type, and each peer
    # (float64 only)
    yard = {"textbook": O.textbook(name, arrays, dtype)}
    if np.dtype(dtype) == np.float64:
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
        at_input = _AtInput(f, arrays, s) if k.branches else None
        rounded = _Rounded(k, f, p, arrays, s, ref)
        cloud = C.Cloud(name, k, p, arrays, s, dtype, runner or run_kernel,
                        _kappa(scale, norms) if ref is not None else np.inf)
        for b in backends:
            row, c = rows[b], got[b][s]
            flagged = not np.isfinite(c).all()
            kappa = _kappa(scale, norms) if ref is not None else np.inf
            # the mathematics is singular, or the rounding of the input can reach its
            # singular set (kappa u >= 1/8), or the result overflows the type; a derivative
            # past float64 is a condition number past any bound (beyond, never skipped)
            if ref is None or (flagged and (np.abs(ref).max() > big or kappa >= KAPPA_SINGULAR
                                            or kappa * u >= 0.125)):
                row.flagged_expected += flagged or ref is None
                continue
            if flagged:
                row.spurious.append(_point(arrays, s))
                continue
            if kappa * u >= 0.125:      # no digit is determined by the input at this type
                row.beyond += 1
                continue
            for o in range(len(sizes)):
                sl = slice(offs[o], offs[o + 1])
                # the type holds no relative accuracy there (or the truth overflows float64,
                # the reference's type: the float type cannot say how far off the kernel is)
                if 0 < norms[o] < tiny or not np.isfinite(norms[o]):
                    row.beyond += 1
                    continue
                norm = norms[o] if norms[o] > 0 else 1.0    # absolute where the truth is 0
                bound = 8 * u * (scale[o] + norms[o])
                err = _diff(c[sl], ref[sl], at_input, sl, bound) / norm
                kap = scale[o] / norms[o] if norms[o] > 0 else np.inf
                ratio = err * norm / bound if bound > 0 else (0.0 if err == 0 else np.inf)
                # the reference half compares computations on the same input: against the
                # truth at the input the kernel and the yardsticks all got (unconstrained
                # arguments as rounded; constrained ones stay on their manifold), where the
                # rounding of the input, which the condition half judges, weighs on none
                r2 = rounded.get()[sl]
                n2 = float(np.linalg.norm(r2)) or 1.0
                err2 = _diff(c[sl], r2, at_input, sl, bound) / n2
                refs_o = {lab: _diff(v[s, sl], r2, at_input, sl, bound) / n2
                          for lab, v in yard.items()}
                src = min(refs_o, key=refs_o.get)
                e_ref = refs_o[src]
                # the condition half as an absolute bound where the truth is 0
                kap_rule = bound / (8 * u * norm) - 1
                half = rule.ratio(err2, u, None, e_ref)
                if half > 1:
                    # a screen: past it, the medians over a cloud of neighbouring inputs
                    # decide (one input's error is luck where kappa u dominates it;
                    # _accuracy_cloud)
                    half, err2, e_ref, src = cloud.ratio(b, sl, bound, u)
                rr = max(rule.ratio(err, u, kap_rule), half)
                # componentwise, over the components not tiny beside their output (below
                # 1e-3 of its norm a component's ulps say nothing of the result), against
                # the truth at the input the kernel got: the kernel's own error, which the
                # rounding of the input (the condition half's) does not swell to 1e14 ulps
                # of a component that cancels (plucker_from_points at scale 1e6)
                ref_c = _judged_by(c[sl], r2, at_input, sl, bound)
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
                    row.worst_point = _point(arrays, s)
    return list(rows.values())


def kernel_names(include_jacobians: bool = True) -> list[str]:
    meta = K._state.meta()
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
    for name, k in out.items():
        k["regimes"].sort()
        k["seeds"].sort()
        k["singular"] = K._state.meta()[name]["singular"]
        k["threshold"] = (thresholds or {}).get(name, "")
    return dict(sorted(out.items()))


def _sig(x: float) -> float:
    return float(f"{x:.3g}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kernels", default="", help="comma-separated names (default: all)")
    ap.add_argument("--dtypes", default="float64,float32")
    ap.add_argument("--backends", default="c,numpy")
    ap.add_argument("--random", type=int, default=8, help="random points per kernel")
    ap.add_argument("--seeds", default="auto", help="comma-separated seeds of the regimes' "
                    "points (tests/test_bounds_fresh.py re-measures at another); 'auto': 0 "
                    "and each kernel's own seeds in the data file (its 'seeds')")
    ap.add_argument("--no-jacobians", action="store_true")
    ap.add_argument("--json", default="", help="write every row here")
    ap.add_argument("--md", default="", help="write the markdown table here")
    ap.add_argument("--losses", action="store_true", help="print only the failing rows")
    ap.add_argument("--table", default="", help="print the per-kernel table of this "
                    "data file (docs/accuracy.md) and exit")
    ap.add_argument("--rule-table", default="", help="print the table of the rule (per "
                    "kernel, type, back-end) of this data file and exit")
    ap.add_argument("--docs", default="", help="write the tables of this data file into "
                    "docs/accuracy.md and benchmarks/RESULTS.md (their marked regions) "
                    "and exit")
    ap.add_argument("--data", default="", help="write the per-kernel rows (the data "
                    "`rigidsym generate` ships for kernels.accuracy) here")
    a = ap.parse_args(argv)
    if a.rule_table:
        print(rule_table(json.loads(Path(a.rule_table).read_text(encoding="utf-8"))), end="")
        return 0
    if a.docs:
        from rigidsym.core.files import write_atomic

        tables = synced(DATA.parents[1], json.loads(Path(a.docs).read_text("utf-8")))
        for rel, text in tables.items():
            write_atomic(DATA.parents[1] / rel, text)
        return 0
    if a.table:
        print(kernel_table(json.loads(Path(a.table).read_text(encoding="utf-8"))), end="")
        return 0
    names = a.kernels.split(",") if a.kernels else kernel_names(not a.no_jacobians)
    dtypes = [np.dtype(d).type for d in a.dtypes.split(",")]
    backends = a.backends.split(",")
    if "c" in backends and K.use_backend("c") != "c":
        backends.remove("c")

    def progress(name, rows):
        bad = [r for r in rows if r.kernel == name and not r.accurate]
        print(f"{name}: {'accurate' if not bad else f'{len(bad)} losing rows'}", flush=True)
        for r in bad:
            print(f"   {r.dtype} {r.backend} {r.regime}: rule {r.rule_ratio:.3g} vs e_ref "
                  f"{r.ref_ratio:.3g} ({r.ref_source}) ratio {r.worst_ratio:.3g} err "
                  f"{r.err:.2g} kappa {r.kappa:.2g} spurious {len(r.spurious)} at "
                  f"{(r.spurious or [r.worst_point])[0]}", flush=True)

    data_path = Path(a.data) if a.data else DATA
    old = json.loads(data_path.read_text(encoding="utf-8")) if data_path.is_file() else {}
    rows = []
    for name in names:
        rows += sweep([name], dtypes, backends, a.random, progress=progress,
                      seeds=seeds_for(name, old, a.seeds))
    if a.json:
        Path(a.json).write_text(json.dumps([asdict(r) for r in rows], indent=1))
    if a.data:
        from _accuracy_thresholds import thresholds

        from rigidsym.core.files import write_atomic

        write_atomic(Path(a.data), json.dumps(merged(old, summary(rows, thresholds())),
                                              indent=1, sort_keys=True) + "\n")
    if a.md:
        Path(a.md).write_text(markdown([r for r in rows if not a.losses or not r.accurate]))
    return 0 if all(r.accurate for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
