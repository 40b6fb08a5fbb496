"""PyTorch and JAX kernels against the NumPy and C kernels, on the CPU.

``python benchmarks/arrays.py --grad [--sizes 1e3 1e4 1e5 1e6]``: value + gradient
against the hand-written formula and the peers, side by side: ``benchmarks/arrays_grad.py``.

``python benchmarks/arrays.py [--sizes 1e4 1e6]``: median wall time of one call of the
checked kernels (``check=False``) and of a hand-written formula of the same mathematics
(what a user would write instead; "hand"), float64 and float32, value and value + gradient
(of the sum of the outputs), for two kernels (one trig kernel, one rational), and prints the
Markdown table of the ``arrays`` section of benchmarks/RESULTS.md. JAX runs under
``jax.jit``; PyTorch eagerly on one thread (as the C kernels' default). No GPU in the
session that wrote the figures: CPU only.
"""

# ruff: noqa: B023 - each closure is timed at once, inside its own loop iteration
from __future__ import annotations

import argparse
import platform
import time

import numpy as np

from rigidsym import kernels as K

KERNELS = ("rotation_from_natural_invariants", "instant_screw_axis")


def _inputs(name: str, n: int, dtype) -> list[np.ndarray]:
    rng = np.random.default_rng(0)
    if name == "rotation_from_natural_invariants":
        e = rng.standard_normal((n, 3))
        e /= np.linalg.norm(e, axis=1, keepdims=True)
        return [e.astype(dtype), rng.uniform(0.3, 2.8, n).astype(dtype)]
    return [rng.standard_normal((n, 3)).astype(dtype) for _ in range(3)]


def _hand(xp, name: str):
    """What a user would write instead, in ``xp`` (torch or jax.numpy): the textbook
    formula, unrewritten (Rodrigues' formula; the instant screw axis (3.53)-(3.55), (3.70))."""
    def cross(u, v):
        return xp.stack([u[..., 1] * v[..., 2] - u[..., 2] * v[..., 1],
                         u[..., 2] * v[..., 0] - u[..., 0] * v[..., 2],
                         u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]], -1)

    if name == "rotation_from_natural_invariants":
        def rodrigues(e, phi):
            z = xp.zeros_like(phi)
            E = xp.stack([xp.stack([z, -e[..., 2], e[..., 1]], -1),
                          xp.stack([e[..., 2], z, -e[..., 0]], -1),
                          xp.stack([-e[..., 1], e[..., 0], z], -1)], -2)
            s, c = xp.sin(phi)[..., None, None], xp.cos(phi)[..., None, None]
            on = {"device": e.device} if xp.__name__ == "torch" else {}  # the GPU table
            return xp.eye(3, dtype=e.dtype, **on) + s * E + (1 - c) * (E @ E)
        return rodrigues

    def screw(omega, a, a_dot):
        w2 = (omega * omega).sum(-1, keepdims=True)
        p0 = cross(omega, a_dot - cross(omega, a)) / w2
        pitch = (a_dot * omega).sum(-1) / w2[..., 0]
        e = omega / xp.sqrt(w2)
        return p0, pitch, xp.concatenate([e, cross(p0, e)], -1)
    return screw


def _time(fn, reps: int = 5) -> float:
    fn()
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t)
    return float(np.median(ts))


def run(sizes) -> list[dict]:
    import jax
    import torch

    jax.config.update("jax_enable_x64", True)
    # one thread, as the C kernels' default: on a loaded machine torch's OpenMP pool spins
    # (torch.sin of 1e4 doubles: 15 ms with 2 threads under load, 0.01 ms with 1)
    torch.set_num_threads(1)
    from rigidsym.kernels import jax as rj
    from rigidsym.kernels import torch as rk

    rows = []
    for name in KERNELS:
        for dtype in (np.float64, np.float32):
            for n in sizes:
                xs = _inputs(name, n, dtype)
                row = {"kernel": name, "dtype": np.dtype(dtype).name, "n": n}
                for be in ("c", "numpy"):
                    K.use_backend(be)
                    row[be] = _time(lambda: getattr(K, name)(*xs, check=False))
                K.use_backend("c")
                ts = [torch.from_numpy(x) for x in xs]
                f = getattr(rk, name)
                row["torch"] = _time(lambda: f(*ts, check=False))

                def tgrad():
                    g = [t.clone().requires_grad_(True) for t in ts]
                    out = f(*g, check=False)
                    sum(o.sum() for o in (out if isinstance(out, tuple) else (out,))).backward()
                row["torch+grad"] = _time(tgrad)
                h = _hand(torch, name)
                for got, want in zip(_tup(h(*ts)), _tup(f(*ts, check=False)), strict=True):
                    torch.testing.assert_close(got, want, rtol=1e-4, atol=1e-4)
                row["torch hand"] = _time(lambda: h(*ts))

                def hgrad():
                    g = [t.clone().requires_grad_(True) for t in ts]
                    sum(o.sum() for o in _tup(h(*g))).backward()
                row["torch hand+grad"] = _time(hgrad)
                js = [jax.device_put(x) for x in xs]
                fj = getattr(rj, name)
                jv = jax.jit(fj)
                row["jax"] = _time(lambda: jax.block_until_ready(jv(*js)))

                def loss(*a):
                    out = fj(*a)
                    return sum(o.sum() for o in (out if isinstance(out, tuple) else (out,)))
                jg = jax.jit(jax.value_and_grad(loss, argnums=tuple(range(len(js)))))
                row["jax+grad"] = _time(lambda: jax.block_until_ready(jg(*js)))
                hj = jax.jit(_hand(jax.numpy, name))
                row["jax hand"] = _time(lambda: jax.block_until_ready(hj(*js)))
                hg = jax.jit(jax.value_and_grad(
                    lambda *a: sum(o.sum() for o in _tup(_hand(jax.numpy, name)(*a))),
                    argnums=tuple(range(len(js)))))
                row["jax hand+grad"] = _time(lambda: jax.block_until_ready(hg(*js)))
                rows.append(row)
                print(row, flush=True)
    return rows


def _tup(v):
    return v if isinstance(v, tuple) else (v,)


COLS = ["c", "numpy", "torch", "torch hand", "torch+grad", "torch hand+grad", "jax",
        "jax hand", "jax+grad", "jax hand+grad"]


def table(rows, cols=COLS, digits: int = 2) -> str:
    """The Markdown table of ``rows`` (median seconds, shown in ms)."""
    lines = ["| kernel | dtype | N | " + " | ".join(cols) + " |",
             "|---|---|---:|" + "---:|" * len(cols)]
    for r in rows:
        lines.append(f"| {r['kernel']} | {r['dtype']} | {r['n']:.0e} | "
                     + " | ".join(f"{r[c] * 1e3:.{digits}f}" for c in cols) + " |")
    return "\n".join(lines)


def _loss(out):
    return sum(o.sum() for o in _tup(out))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", nargs="+", type=float, default=None)
    ap.add_argument("--grad", action="store_true", help="the value + gradient ratio table")
    args = ap.parse_args()
    import jax
    import torch
    if args.grad:  # the gradients' table (benchmarks/arrays_grad.py)
        from arrays_grad import main
        main(args.sizes)
        raise SystemExit(0)
    else:
        rows = run([int(s) for s in args.sizes or [1e4, 1e6]])
        print(table(rows))
    print(f"\nCPU: {platform.processor() or platform.machine()}; torch {torch.__version__} "
          f"({torch.get_num_threads()} threads), jax {jax.__version__}")
