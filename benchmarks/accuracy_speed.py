"""Speed of the accuracy rewrites: the kernels before and after, interleaved.

Loads the generated kernels of a git revision (default: the commit before the rewrites)
with ``kernels.load`` beside the package's, and times the C batch function of each kernel
at N = 1e6, one thread, float64, in interleaved rounds (old, new, old, new, ...): the median
ratio new/old per kernel. Then float32 against float64 of the package's kernels (K1,
``instant_screw_axis``, K6). Clock: thread CPU time around one call; the machine is
shared, so the medians of interleaved rounds are what to read, not single figures.

Usage (from the repository root)::

    python benchmarks/accuracy_speed.py [--rev afc7196] [--mid REV] [--rounds 7] [--n 1000000]
"""

from __future__ import annotations

import argparse
import io
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

os.environ.setdefault("OMP_NUM_THREADS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.accuracy import regimes as P  # noqa: E402
from rigidsym.codegen.accuracy.harness import judge as A  # noqa: E402
from rigidsym.codegen.accuracy.harness import reference as R  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
KS = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
      "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
      "K6": "newton_euler_wrench"}
CHANGED = ["screw_of_displacement", "plucker_from_points"]


def old_generated(rev: str, into: Path) -> Path:
    """``generated/`` of ``rev`` extracted under ``into`` (git archive)."""
    tar = subprocess.run(["git", "archive", rev, "generated"], cwd=ROOT, check=True,
                         capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tar)) as t:
        t.extractall(into, filter="data")
    return into / "generated"


def inputs(name: str, n: int, dtype) -> list[np.ndarray]:
    k = R.kernel_of(name)
    pts = P.regimes(k, np.float64, n_random=64)["random"]
    arrays = A.round_points(pts, dtype, k)
    reps = -(-n // len(pts))
    return [np.ascontiguousarray(np.tile(a, (reps,) + (1,) * (a.ndim - 1))[:n])
            for a in arrays]


def timer(f, arrays, outs):
    def once() -> float:
        t = time.thread_time()
        f(*arrays, *outs)
        return time.thread_time() - t
    return once


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rev", default="afc7196")
    ap.add_argument("--mid", default=None, help="a second revision timed in the same rounds "
                    "(a column of its own, and after/mid)")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--n", type=int, default=10**6)
    ap.add_argument("--float32-only", action="store_true",
                    help="only the float64/float32 table (no build of --rev)")
    a = ap.parse_args(argv)
    K.use_backend("c")
    if not a.float32_only:
        before_after(a)
    float32_table(a)
    return 0


def before_after(a) -> None:
    """The kernels before and after the rewrites of --rev, interleaved."""
    with tempfile.TemporaryDirectory() as tmp, tempfile.TemporaryDirectory() as tmp2:
        old = K.load(old_generated(a.rev, Path(tmp)))
        mid = None if a.mid is None else K.load(old_generated(a.mid, Path(tmp2)))
        print(f"N = {a.n:.0e}, one thread, {a.rounds} interleaved rounds, median; "
              f"before = {a.rev}" + ("" if mid is None else f", mid = {a.mid}"), flush=True)
        cols = " mid ms | after/mid |" if mid else ""
        print(f"| kernel | before ms |{cols} after ms | after/before |\n"
              f"|---|---|{'---|---|' if mid else ''}---|---|")
        for label, name in [*KS.items(), *((n, n) for n in CHANGED)]:
            k = R.kernel_of(name)
            arrays = inputs(name, a.n, np.float64)
            outs = [np.empty((a.n,) + o.shape) for o in k.outputs]
            spaces = [old, K] if mid is None else [old, mid, K]
            fs = [timer(s.batch_function(name, "c", threads=1), arrays, outs) for s in spaces]
            for f in fs:                  # warm
                f()
            ts: list[list[float]] = [[] for _ in fs]
            for _ in range(a.rounds):     # interleaved: before, (mid,) after, before, ...
                for f, t in zip(fs, ts, strict=True):
                    t.append(f())
            to, tn = ts[0], ts[-1]
            ratio = statistics.median(n_ / o_ for n_, o_ in zip(tn, to, strict=True))
            extra = ""
            if mid is not None:
                rm = statistics.median(n_ / m_ for n_, m_ in zip(tn, ts[1], strict=True))
                extra = f" {1e3 * statistics.median(ts[1]):.2f} | {rm:.3f} |"
            print(f"| {label} `{name}` | {1e3 * statistics.median(to):.2f} |{extra} "
                  f"{1e3 * statistics.median(tn):.2f} | {ratio:.3f} |", flush=True)


def float32_table(a) -> None:
    """float64 time / float32 time of the package's kernels, side by side in one run (the
    target: >= 1.5 for instant_screw_axis), and the nodes each float32 plan keeps in
    double with the measured reason (the rule's ratio with that node alone in float)."""
    print("\n| kernel | float64 ms | float32 ms | float64/float32 |\n|---|---|---|---|")
    reasons = {}
    for label, name in (("K1", KS["K1"]), ("", "instant_screw_axis"), ("K6", KS["K6"])):
        k = R.kernel_of(name)
        t = {}
        fs = {}
        for dt in (np.float64, np.float32):
            arrays = inputs(name, a.n, dt)
            outs = [np.empty((a.n,) + o.shape, dtype=dt) for o in k.outputs]
            fs[dt] = timer(K.batch_function(name, "c", threads=1, dtype=dt), arrays, outs)
            fs[dt]()
            t[dt] = []
        for _ in range(a.rounds):
            for dt in fs:
                t[dt].append(fs[dt]())
        r = statistics.median(x / y for x, y in zip(t[np.float64], t[np.float32], strict=True))
        print(f"| {label} `{name}` | {1e3 * statistics.median(t[np.float64]):.2f} | "
              f"{1e3 * statistics.median(t[np.float32]):.2f} | {r:.2f} |", flush=True)
        reasons[name] = r
    for name in reasons:
        print(f"\n`{name}` float32 plan, the nodes kept in double and why:")
        for line in double_nodes(name):
            print(f"- {line}")


def double_nodes(name: str) -> list[str]:
    """Per node the plan keeps in double: the rule's worst ratio (rigidsym.codegen.accuracy.float32)
    of the plan with that node made float too (> 1: float there breaks the rule)."""
    from rigidsym.codegen.accuracy import float32 as F
    from rigidsym.codegen.accuracy.error import normwise
    from rigidsym.codegen.generator import compile_kernel
    from rigidsym.codegen.optimise import trig_split as _trig_split
    from rigidsym.codegen.spec import flat_symbols

    k = R.kernel_of(name)
    kc = compile_kernel(k)
    cols = F.sample_inputs(k.args)
    offs = np.cumsum([0] + [o.size for o in k.outputs])
    groups = [slice(int(x), int(y)) for x, y in zip(offs[:-1], offs[1:], strict=True)]
    names = [str(s) for _, ss in flat_symbols(k) for s in ss]
    tb = F.rule.textbook(k, [cols[n] for n in names], np.float32)
    split = _trig_split(kc)
    if split is not None:
        progs = [(F.ProgramSpec(split["program"].temps, split["program"].outputs,
                                F.trig_spec(split["calls"], split["pre"])),
                  kc.plan32["trig"]["plan"], np.ones(len(tb), dtype=bool))]
    else:
        masks = F._variant_points(kc.variants, cols)
        progs = [(F.ProgramSpec(v.program.temps, v.program.outputs), p["plan"], m)
                 for v, p, m in zip(kc.variants, kc.plan32["variants"], masks, strict=True)]
    out = []
    for spec, plan, m in progs:
        sub = {c: v[m] for c, v in cols.items()}
        ref = spec.run(sub, None)
        ok = np.isfinite(ref).all(axis=1)
        sub, ref = {c: v[ok] for c, v in sub.items()}, ref[ok]
        allowed = F.BUDGET(normwise(tb[m][ok], ref, groups))
        for node in [n for n, t in plan.items() if t == "d"]:
            err = normwise(spec.run(sub, plan | {node: "f"}), ref, groups)
            with np.errstate(all="ignore"):
                r = np.where(err == 0, 0.0, err / allowed)
            i = int(np.argmax(np.where(np.isfinite(r), r, np.inf).max(axis=1)))
            where = ", ".join(f"{c}={sub[c][i]:.3g}" for c in list(sub)[:9])
            out.append(f"{node}: in float the error reaches {r[i].max():.3g} of the rule "
                       f"(at {where})")
    return out or ["none"]


if __name__ == "__main__":
    raise SystemExit(main())
