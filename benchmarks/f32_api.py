"""float32 against float64 through the public API, beside the C batch
function alone, at N = 1e6 on one thread.

For each kernel (K1 ``rotation_from_euler_rodrigues``, ``instant_screw_axis``, K6
``newton_euler_wrench`` by default) and each dtype, in interleaved rounds in one process:

* ``bare``: the C batch function (``kernels.batch_function(name, "c", threads=1,
  dtype=...)``) on contiguous inputs and caller outputs;
* ``api``: the public function, ``f(*inputs, check=False, out=outputs)``;
* ``alloc``: the public function with its outputs allocated in the call
  (``f(*inputs, check=False)``: ``np.empty`` and the first touch of its pages, item 2).

Inputs: ``rigidsym.core.draws`` samples rounded to float32; the float64 inputs are the same
values widened (so both dtypes compute the same points). Clock: thread CPU time around one
call, minimum over the rounds (the machine is shared: read the ratios).

Usage (from the repository root)::

    python benchmarks/f32_api.py [--kernels NAME,...] [--n 1000000] [--rounds 15]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from rigidsym import kernels as K
from rigidsym.core.draws import draw
from rigidsym.kernels.runtime import state as _state

DEFAULT = ["rotation_from_euler_rodrigues", "instant_screw_axis", "newton_euler_wrench"]


def _inputs(meta: dict, n: int, rng) -> list[np.ndarray]:
    return [np.ascontiguousarray(draw(a["kind"], (n,) + tuple(a["shape"]), rng,
                                      phi=(0.2, 3.0), angle=(0.2, np.pi - 0.05),
                                      free=lambda s: rng.uniform(0.5, 2.0, s)),
                                 dtype=np.float32) for a in meta["args"]]


def calls(name: str, n: int, rng) -> dict:
    """The six timed calls of ``name`` (bare/api/alloc x float64/float32)."""
    m = _state.meta()[name]
    f = getattr(K, name)
    i32 = _inputs(m, n, rng)
    i64 = [a.astype(np.float64) for a in i32]
    res = {}
    for tag, ins, dt in (("64", i64, np.float64), ("32", i32, np.float32)):
        outs = [np.zeros((n,) + tuple(o["shape"]), dt) for o in m["outputs"]]
        out = outs[0] if len(outs) == 1 else tuple(outs)
        bare = K.batch_function(name, "c", threads=1, dtype=dt)
        res["bare" + tag] = lambda b=bare, a=ins + outs: b(*a)
        res["api" + tag] = lambda a=ins, o=out: f(*a, check=False, out=o)
        res["alloc" + tag] = lambda a=ins: f(*a, check=False)
    return res


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kernels", default=",".join(DEFAULT))
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=15)
    a = ap.parse_args()
    assert K.use_backend("c") == "c", "C backend unavailable"
    rng = np.random.default_rng(9)
    print(f"N = {a.n:.0e}, one thread, {a.rounds} interleaved rounds, minimum thread CPU "
          "time, ns/sample")
    print("| kernel | bare f64 | bare f32 | bare f64/f32 | api f64 | api f32 | api f64/f32 | "
          "alloc f64 | alloc f32 | alloc f64/f32 |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name in a.kernels.split(","):
        cs = calls(name, a.n, rng)
        t: dict = {k: [] for k in cs}
        for _ in range(a.rounds):
            for k, c in cs.items():
                t0 = time.thread_time()
                c()
                t[k].append((time.thread_time() - t0) / a.n * 1e9)
        b = {k: min(v) for k, v in t.items()}
        cells = []
        for kind in ("bare", "api", "alloc"):
            cells += [f"{b[kind + '64']:.2f}", f"{b[kind + '32']:.2f}",
                      f"{b[kind + '64'] / b[kind + '32']:.2f}"]
        print(f"| `{name}` | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
