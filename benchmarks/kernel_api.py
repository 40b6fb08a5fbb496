"""Cost of the checked kernel API: call overhead at N = 1e3 and batch cost at N = 1e6.

Two measurements of the C backend, comparable across commits (it uses only
``kernels.use_backend``, ``kernels.batch_function``, the public kernels and ``kernels.json``):

* ``overhead``: one public call (validation, broadcasting, output allocation, the C batch,
  the singular/non-finite bookkeeping) at N = 1e3, in microseconds per call;
* ``batch``: the C batch function alone with caller-provided outputs at N = 1e6, in ns per
  sample (what the per-block finiteness test of the outputs costs).

Usage::

    python benchmarks/kernel_api.py --save new.json           # this checkout
    PYTHONPATH=/tmp/old/src python benchmarks/kernel_api.py --save old.json
    python benchmarks/kernel_api.py --compare old.json new.json   # RESULTS.md section

Timing: thread CPU time, median over rounds of repeated calls for >= 20 ms, rounds
interleaved over kernels so that a load change on the shared machine hits all of them.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

OVERHEAD = ["rotation_from_natural_invariants", "twist_transfer", "screw_of_displacement",
            "kinetic_energy", "N_matrix", "plucker_from_points"]
MARK = ("<!-- kernel-api -->", "<!-- /kernel-api -->")


def _inputs(meta: dict, n: int, rng) -> list[np.ndarray]:
    from rigidsym import kernels as K

    out = []
    for a in meta["args"]:
        shape = (n,) + tuple(a["shape"])
        if a["kind"] == "unit":
            v = rng.standard_normal(shape)
            v /= np.linalg.norm(v, axis=-1, keepdims=True)
        elif a["kind"] == "angle":
            v = rng.uniform(0.2, np.pi - 0.05, shape)
        elif a["kind"] == "rotation":
            e = rng.standard_normal((n, 3))
            e /= np.linalg.norm(e, axis=1, keepdims=True)
            v = K.rotation_from_natural_invariants(e, rng.uniform(0.2, 3.0, n))
        else:
            v = rng.uniform(0.5, 2.0, shape)
        out.append(np.ascontiguousarray(v))
    return out


def _time(f, budget: float = 0.02) -> float:
    """Seconds per call of ``f``: repeated for >= ``budget`` of thread CPU time."""
    reps, t = 1, 0.0
    while True:
        t0 = time.thread_time()
        for _ in range(reps):
            f()
        t = time.thread_time() - t0
        if t >= budget:
            return t / reps
        reps *= 2


def measure(rounds: int) -> dict:
    from rigidsym import kernels as K

    assert K.use_backend("c") == "c", "C backend unavailable"
    meta = {k: m for k, m in K._meta().items() if m["public"]}
    rng = np.random.default_rng(7)
    calls, batches = {}, {}

    def bind(f, args):
        return lambda: f(*args)
    for name in OVERHEAD:
        calls[name] = bind(getattr(K, name), _inputs(meta[name], 1000, rng))
    for name, m in sorted(meta.items()):
        n = 1_000_000
        outs = [np.empty((n,) + tuple(o["shape"])) for o in m["outputs"]]
        batches[name] = bind(K.batch_function(name, "c"), _inputs(m, n, rng) + outs)
    res = {"overhead_us": {k: [] for k in calls}, "batch_ns": {k: [] for k in batches}}
    for _ in range(rounds):
        for k, f in calls.items():
            res["overhead_us"][k].append(_time(f) * 1e6)
        for k, f in batches.items():
            res["batch_ns"][k].append(_time(f, 0.05) * 1e9 / 1_000_000)
    return {sec: {k: statistics.median(v) for k, v in d.items()} for sec, d in res.items()}


def section(old: dict, new: dict, old_label: str, note: str) -> str:
    lines = [MARK[0], "## Kernel API cost (issue 12)", "",
             f"C backend, one thread; {note}. `old` is commit {old_label} "
             "(wrappers taking `*args`, finiteness tested only after divisions and roots); "
             "`new` has true signatures, argument-naming validation, the per-block finiteness "
             "test of the outputs and the overflow classification. Regenerate: "
             "`python benchmarks/kernel_api.py --save new.json` here and in a checkout of the "
             "old commit, then `--compare old.json new.json`.", "",
             "### Call overhead, N = 1e3 (us per public call, allocated outputs)", "",
             "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in old["overhead_us"]:
        o, n = old["overhead_us"][k], new["overhead_us"][k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.1f} | {n:.1f} | {n / o:.3f} |")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", "",
              "### C batch alone, N = 1e6 (ns/sample, caller-provided outputs)", "",
              "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in old["batch_ns"]:
        if k not in new["batch_ns"]:
            continue
        o, n = old["batch_ns"][k], new["batch_ns"][k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.2f} | {n:.2f} | {n / o:.3f} |")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", MARK[1]]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--save", help="measure this checkout and write JSON here")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--compare", nargs=2, metavar=("OLD", "NEW"))
    p.add_argument("--old-label", default="f6c9ea0")
    p.add_argument("--note", default="measured on the shared 2-core machine under load")
    p.add_argument("--results", default=str(Path(__file__).with_name("RESULTS.md")))
    args = p.parse_args(argv)
    if args.save:
        data = measure(args.rounds)
        Path(args.save).write_text(json.dumps(data, indent=1))
        json.dump(data, sys.stdout, indent=1)
        print()
    if args.compare:
        old, new = (json.loads(Path(f).read_text()) for f in args.compare)
        text = section(old, new, args.old_label, args.note)
        path = Path(args.results)
        body = path.read_text(encoding="utf-8")
        if MARK[0] in body:
            a, b = body.index(MARK[0]), body.index(MARK[1]) + len(MARK[1]) + 1
            body = body[:a] + text + body[b:]
        else:
            body = body.rstrip("\n") + "\n\n" + text
        from rigidsym.io import write_atomic
        write_atomic(path, body)
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
