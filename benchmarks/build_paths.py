"""The default (portable, dispatched) build against a ``-march=native`` build, K1-K6.

    python benchmarks/build_paths.py [--n 1000000] [--rounds 7] [--md]

Both extension modules are loaded in one process: the package's own (x86-64-v2 and
x86-64-v3 objects, the dispatcher's choice; ``RIGIDSYM_DISPATCH=baseline`` times the
baseline) and the native build in the cache (``rigidsym build-c --native``, compiled here if
missing). Each kernel is timed alternately on the two, one thread, caller-provided outputs,
the same inputs; a cell is the minimum over rounds of one call at N samples (ns/sample).
K1 rotation_from_euler_rodrigues, K2 rotation_from_natural_invariants, K3 screw_axis_point,
K4 instant_screw_point_pitch, K5 N_matrix, K6 newton_euler_wrench.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT / "src") not in sys.path:
    sys.path.insert(0, str(ROOT / "src"))

from rigidsym.kernels import _build, _ext  # noqa: E402

BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_wrench"}
#: the target of issue 19: the default build within this factor of native on every kernel
TARGET = 1.10


def _unit(rng, n: int, k: int) -> np.ndarray:
    v = rng.standard_normal((n, k))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _rotation(rng, n: int) -> np.ndarray:
    """Rotation matrices by Rodrigues' formula (row-major)."""
    e, phi = _unit(rng, n, 3), rng.uniform(0.2, 3.0, n)
    E = np.zeros((n, 3, 3))
    E[:, 0, 1], E[:, 0, 2], E[:, 1, 2] = -e[:, 2], e[:, 1], -e[:, 0]
    E -= E.transpose(0, 2, 1)
    s, c = np.sin(phi)[:, None, None], np.cos(phi)[:, None, None]
    return np.eye(3) + s * E + (1 - c) * (E @ E)


def inputs(meta: dict, n: int, rng) -> list[np.ndarray]:
    """Valid inputs of every argument kind (unit vectors, angles away from 0 and pi,
    rotations, positive masses)."""
    out = []
    for a in meta["args"]:
        shape = tuple(a["shape"])
        size = int(np.prod(shape))
        if a["kind"] == "unit":
            v = _unit(rng, n, size)
        elif a["kind"] == "angle":
            v = rng.uniform(0.2, np.pi - 0.05, n)
        elif a["kind"] == "rotation":
            v = _rotation(rng, n)
        elif a["name"] == "m":
            v = rng.uniform(0.5, 5.0, n)
        else:
            v = rng.standard_normal((n,) + shape)
        out.append(np.ascontiguousarray(v, dtype=np.float64))
    return out


def modules():
    """The default module (the package's, else the cache's) and the native one."""
    gdir = _ext.generated_dir()
    sources = _build.sources_hash(gdir / "c")
    default = _ext._load_default(gdir, True, sources, "rigidsym._bench_default._ckernels")
    path = _ext.ensure(gdir, native=True, why="benchmark: native build")
    native = _ext._import(path, "cache (native)", sources, "rigidsym._bench_native._ckernels")
    return default, native


def measure(n: int, rounds: int) -> dict:
    default, native = modules()
    metas = {k["name"]: k for k in
             json.loads((_ext.generated_dir() / "kernels.json").read_text())["kernels"]}
    rng = np.random.default_rng(0)
    rows = {}
    for kid, name in BENCH.items():
        meta = metas[name]
        xs = inputs(meta, n, rng)
        outs = {w: [np.empty((n,) + tuple(o["shape"])) for o in meta["outputs"]]
                for w in ("default", "native")}
        calls = {w: (m.module.batch, m.module.kernels.index(name))
                 for w, m in (("default", default), ("native", native))}
        best = {"default": float("inf"), "native": float("inf")}
        for _ in range(rounds):                    # alternately: fair on a loaded machine
            for w, (batch, k) in calls.items():
                t0 = time.perf_counter()
                flagged = batch(k, False, n, 1, *xs, *outs[w])
                best[w] = min(best[w], time.perf_counter() - t0)
                assert flagged == 0, (name, w, flagged)
        for a, b in zip(outs["default"], outs["native"], strict=True):
            scale = np.abs(b).max()
            assert np.abs(a - b).max() <= 1e-13 * scale, name     # same results, normwise
        rows[kid] = {"kernel": name, "default": best["default"] / n * 1e9,
                     "native": best["native"] / n * 1e9}
    return {"rows": rows, "default_path": default.module.path, "default_file": default.origin,
            "native_flags": native.module.build, "n": n, "rounds": rounds,
            "load": os.getloadavg()[0]}


def table(res: dict) -> str:
    lines = [f"| K | kernel | default ({res['default_path']}) | native | default / native |",
             "|---|---|---:|---:|---:|"]
    for kid, r in res["rows"].items():
        ratio = r["default"] / r["native"]
        mark = "" if ratio <= TARGET else " (over 1.10)"
        lines.append(f"| {kid} | `{r['kernel']}` | {r['default']:.2f} | {r['native']:.2f} | "
                     f"{ratio:.3f}{mark} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=1_000_000)
    p.add_argument("--rounds", type=int, default=7)
    p.add_argument("--json", default=None, help="also write the numbers here")
    a = p.parse_args(argv)
    res = measure(a.n, a.rounds)
    print(f"N = {a.n:.0e}, one thread, ns/sample, minimum of {a.rounds} alternating rounds; "
          f"load average {res['load']:.1f} at the start")
    print(table(res))
    if a.json:
        Path(a.json).write_text(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
