"""PyTorch and JAX kernels on a GPU (the GPU table).

``python benchmarks/arrays_gpu.py [--sizes 1e4 1e6 1e7]`` on a machine with a CUDA GPU:
median wall time of one call of the generated kernels (``check=False``, and ``check=True``
for the value) and of the hand-written formula of the same mathematics
(``benchmarks/arrays.py``'s "hand"), value and value + gradient of the sum of the outputs,
float64 and float32. Inputs live on the GPU; every timing ends with a device
synchronisation (``torch.cuda.synchronize``, ``jax.block_until_ready``). PyTorch eager and
under ``torch.compile`` (inductor); JAX under ``jax.jit``. Prints the Markdown table of the
``arrays-gpu`` section of benchmarks/RESULTS.md.
"""

# ruff: noqa: B023 - each closure is timed at once, inside its own loop iteration
from __future__ import annotations

import argparse
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from arrays import KERNELS, _hand, _inputs, _tup, table  # noqa: E402 - after the path

COLS = ["torch", "torch check", "torch compiled", "torch hand", "torch+grad",
        "torch hand+grad", "jax", "jax hand", "jax+grad", "jax hand+grad"]


def _time(fn, sync, reps: int = 10) -> float:
    fn()
    sync()
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        fn()
        sync()
        ts.append(time.perf_counter() - t)
    return float(np.median(ts))


def _loss(out) -> object:
    return sum(o.sum() for o in _tup(out))


def run(sizes) -> list[dict]:
    import jax
    import torch

    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as rj
    from rigidsym.kernels import torch as rk

    dev = torch.device("cuda")
    tsync = torch.cuda.synchronize
    rows = []
    for name in KERNELS:
        for dtype in (np.float64, np.float32):
            for n in sizes:
                xs = _inputs(name, n, dtype)
                row = {"kernel": name, "dtype": np.dtype(dtype).name, "n": n}
                ts = [torch.from_numpy(x).to(dev) for x in xs]
                f = getattr(rk, name)
                row["torch"] = _time(lambda: f(*ts, check=False), tsync)
                row["torch check"] = _time(lambda: f(*ts, check=True), tsync)
                fc = torch.compile(lambda *a: f(*a, check=False))
                row["torch compiled"] = _time(lambda: fc(*ts), tsync)

                def tgrad():
                    g = [t.clone().requires_grad_(True) for t in ts]
                    _loss(f(*g, check=False)).backward()
                row["torch+grad"] = _time(tgrad, tsync)
                h = _hand(torch, name)
                for got, want in zip(_tup(h(*ts)), _tup(f(*ts, check=False)), strict=True):
                    torch.testing.assert_close(got, want, rtol=1e-4, atol=1e-4)
                row["torch hand"] = _time(lambda: h(*ts), tsync)

                def hgrad():
                    g = [t.clone().requires_grad_(True) for t in ts]
                    _loss(h(*g)).backward()
                row["torch hand+grad"] = _time(hgrad, tsync)
                gpu = jax.devices("gpu")[0]
                js = [jax.device_put(x, gpu) for x in xs]
                fj = getattr(rj, name)
                jsync = lambda: None  # noqa: E731 - the timed calls block themselves
                jv = jax.jit(fj)
                row["jax"] = _time(lambda: jax.block_until_ready(jv(*js)), jsync)
                argn = tuple(range(len(js)))
                jg = jax.jit(jax.value_and_grad(lambda *a: _loss(fj(*a)), argnums=argn))
                row["jax+grad"] = _time(lambda: jax.block_until_ready(jg(*js)), jsync)
                hj = jax.jit(_hand(jax.numpy, name))
                row["jax hand"] = _time(lambda: jax.block_until_ready(hj(*js)), jsync)
                hg = jax.jit(jax.value_and_grad(
                    lambda *a: _loss(_hand(jax.numpy, name)(*a)), argnums=argn))
                row["jax hand+grad"] = _time(lambda: jax.block_until_ready(hg(*js)), jsync)
                rows.append(row)
                print(row, flush=True)
    return rows


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", nargs="+", type=float, default=[1e4, 1e6, 1e7])
    args = ap.parse_args()
    import jax
    import torch
    rows = run([int(s) for s in args.sizes])
    print(table(rows, COLS, digits=3))
    print(f"\nGPU: {torch.cuda.get_device_name()}; host {platform.machine()}; "
          f"torch {torch.__version__}, jax {jax.__version__}")
