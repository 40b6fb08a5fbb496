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
    python benchmarks/kernel_api.py --ab /tmp/old/generated --ab-json ab.json   # C A/B
    python benchmarks/kernel_api.py --compare old.json new.json --ab-json ab.json   # RESULTS.md

Timing: thread CPU time, median over rounds of repeated calls for >= 20 ms, rounds
interleaved over kernels so that a load change on the shared machine hits all of them;
``--save`` to an existing file keeps the minimum per entry, so runs alternating between
the two commits can be pooled.
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


def measure(rounds: int, batch: bool = True) -> dict:
    from rigidsym import kernels as K
    from rigidsym.kernels import _state

    assert K.use_backend("c") == "c", "C backend unavailable"
    meta = {k: m for k, m in _state.meta().items() if m["public"]}
    rng = np.random.default_rng(7)
    calls, batches = {}, {}

    def bind(f, args):
        return lambda: f(*args)
    for name in OVERHEAD:
        calls[name] = bind(getattr(K, name), _inputs(meta[name], 1000, rng))
    for name, m in sorted(meta.items()) if batch else ():
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


def measure_ab(old_dir: Path, rounds: int) -> dict:
    """C batch at N = 1e6, old and new generated C loaded in this one process (both built
    by this checkout's driver, rigidsym.kernels._build, same flags; the old folder needs the
    extension's own C, c/rigidsym_module.c, of this version's generator) and timed
    alternately: fair on a loaded machine."""
    from rigidsym.kernels import _ext, _state

    mods = {"old": _ext.load(old_dir).module, "new": _state.builtin().c_lib().module}
    meta = {k: m for k, m in _state.meta().items() if m["public"]}
    rng = np.random.default_rng(7)
    n = 1_000_000
    res: dict = {"old": {}, "new": {}}
    for name, m in sorted(meta.items()):
        arrays = _inputs(m, n, rng) + [np.empty((n,) + tuple(o["shape"]))
                                       for o in m["outputs"]]
        calls = {}
        for tag, mod in mods.items():
            k = mod.kernels.index(name)
            calls[tag] = (lambda b=mod.batch, k=k, a=arrays: b(k, False, n, 1, *a))
        times: dict = {"old": [], "new": []}
        for _ in range(rounds):
            for tag in ("old", "new"):
                times[tag].append(_time(calls[tag], 0.05) * 1e9 / n)
        for tag in times:
            res[tag][name] = min(times[tag])
    return res


def section(old: dict, new: dict, old_label: str, note: str, ab: dict | None = None) -> str:
    lines = [MARK[0], "## Kernel API cost (issue 12)", "",
             f"C backend, one thread; {note}. `old` is commit {old_label} "
             "(wrappers taking `*args`, finiteness tested only after divisions and roots); "
             "`new` has true signatures, argument-naming validation, the per-block finiteness "
             "test of the outputs and the overflow classification. Regenerate: "
             "`python benchmarks/kernel_api.py --overhead-only --save new.json` here and "
             "(with PYTHONPATH at its src/) in a checkout of the old commit, alternately; "
             "`--ab OLD/generated --ab-json ab.json`; then "
             "`--compare old.json new.json --ab-json ab.json`.", "",
             "### Call overhead, N = 1e3 (us per public call, allocated outputs)", "",
             "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in old["overhead_us"]:
        o, n = old["overhead_us"][k], new["overhead_us"][k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.1f} | {n:.1f} | {n / o:.3f} |")
    batch_old, batch_new = (ab["old"], ab["new"]) if ab else (old["batch_ns"], new["batch_ns"])
    how = ("both C builds loaded in one process and timed alternately, minimum over rounds"
           if ab else "separate processes")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", "",
              f"### C batch alone, N = 1e6 (ns/sample, caller-provided outputs; {how})", "",
              "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in batch_old:
        if k not in batch_new:
            continue
        o, n = batch_old[k], batch_new[k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.2f} | {n:.2f} | {n / o:.3f} |")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", MARK[1]]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--save", help="measure this checkout and write JSON here")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--overhead-only", action="store_true", help="skip the N = 1e6 batches")
    p.add_argument("--compare", nargs=2, metavar=("OLD", "NEW"))
    p.add_argument("--ab", metavar="OLD_GENERATED_DIR",
                   help="time the old commit's generated C against this one in-process")
    p.add_argument("--ab-json", default="ab.json", help="where --ab writes / --compare reads")
    p.add_argument("--old-label", default="f6c9ea0")
    p.add_argument("--note", default="measured on the shared 2-core machine under load")
    p.add_argument("--results", default=str(Path(__file__).with_name("RESULTS.md")))
    args = p.parse_args(argv)
    if args.save:
        data = measure(args.rounds, batch=not args.overhead_only)
        path = Path(args.save)
        if path.exists():       # repeated runs (alternating commits): keep the minimum
            prev = json.loads(path.read_text())
            data = {sec: {k: min(v, d.get(k, v)) for k, v in prev.get(sec, {}).items()}
                    | {k: min(v, prev.get(sec, {}).get(k, v)) for k, v in d.items()}
                    for sec, d in (prev | data).items()}
        path.write_text(json.dumps(data, indent=1))
        json.dump(data, sys.stdout, indent=1)
        print()
    if args.ab:
        data = measure_ab(Path(args.ab), args.rounds)
        Path(args.ab_json).write_text(json.dumps(data, indent=1))
    if args.compare:
        old, new = (json.loads(Path(f).read_text()) for f in args.compare)
        abp = Path(args.ab_json)
        ab = json.loads(abp.read_text()) if abp.exists() else None
        text = section(old, new, args.old_label, args.note, ab)
        path = Path(args.results)
        body = path.read_text(encoding="utf-8")
        if MARK[0] in body:
            a, b = body.index(MARK[0]), body.index(MARK[1]) + len(MARK[1]) + 1
            body = body[:a] + text + body[b:]
        else:
            body = body.rstrip("\n") + "\n\n" + text
        from rigidsym._io import write_atomic
        write_atomic(path, body)
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
