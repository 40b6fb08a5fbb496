"""Value + gradient of the kernels against a hand-written formula (issue 38, item 4).

``python benchmarks/arrays_grad.py [--sizes 1e3 1e4 1e5 1e6]`` (also ``arrays.py --grad``):
one training step, the values and the gradient of the sum of the outputs with respect to
every input, ``check=False``, of the kernel ("k") and of the same mathematics written by
hand ("h", ``arrays._hand``), torch eager (one thread), ``torch.compile`` (inductor,
``dynamic=True``: one compile for every N) and ``jax.jit(value_and_grad)``, float64 and
float32; where a peer has the operation (``rotation_from_natural_invariants``: jaxlie's
``SO3.exp`` and PyPose's ``so3(...).matrix()`` of the rotation vector phi e), the peer too.

Side by side: every timing sample runs the candidates of one (kernel, dtype, N, mode) one
after the other, in turn, so that a machine shared with other work loads them alike; each
sample times a loop of calls long enough for the timer (~N = 2e4 worth), and the table
gives the median per call of wall time and, in brackets, the ratio of process CPU time
(robust to the load: the time the step computed, not the time it waited for a core).
Also: the first call's time (trace + compile + run) of ``torch.compile`` and ``jax.jit``
for kernel and hand, the graph breaks (``torch._dynamo.explain``), the load average.
Prints the Markdown of the ``arrays-grad`` section of benchmarks/RESULTS.md.
"""

# ruff: noqa: B023 - each closure is timed at once, inside its own loop iteration
from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from arrays import KERNELS, _hand, _inputs, _loss  # noqa: E402 - after the path

TARGETS = {"eager": 1.2, "compiled": 1.1, "jit": 1.1}


def _interleaved(fns: dict, n: int, reps: int) -> dict:
    """``{name: (wall s, cpu s)}``: medians per call, the candidates timed in turn."""
    loops = max(1, int(2e4 // n))
    for f in fns.values():
        f()
    wall: dict = {k: [] for k in fns}
    cpu: dict = {k: [] for k in fns}
    for _ in range(reps):
        for k, f in fns.items():
            w, c = time.perf_counter(), time.process_time()
            for _ in range(loops):
                f()
            wall[k].append((time.perf_counter() - w) / loops)
            cpu[k].append((time.process_time() - c) / loops)
    return {k: (float(np.median(wall[k])), float(np.median(cpu[k]))) for k in fns}


def _peers(name: str) -> tuple[dict, dict]:
    """The peers' torch and JAX formulas of kernel ``name`` (absent ones skipped)."""
    tp, jp = {}, {}
    if name != "rotation_from_natural_invariants":
        return tp, jp
    try:
        import pypose as pp
        tp["pypose"] = lambda e, phi: pp.so3(e * phi[..., None]).matrix()
    except ImportError:
        pass
    try:
        import jaxlie
        jp["jaxlie"] = lambda e, phi: jaxlie.SO3.exp(e * phi[..., None]).as_matrix()
    except ImportError:
        pass
    return tp, jp


def _first(fn) -> float:
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def _warm_inductor(torch) -> None:
    """One small compile with gradient first, so that neither first-call time below pays
    inductor's once-per-process start (imports, compile workers, headers)."""
    with torch._inductor.config.patch(force_disable_caches=True):
        x = torch.ones(8, dtype=torch.float64, requires_grad=True)
        torch.compile(lambda v: (v.sin() * v).sum(), dynamic=True)(x).backward()
    torch._dynamo.reset()


def run_grad(sizes, reps: int = 9) -> tuple[list[dict], dict]:
    """Rows (one per kernel, dtype, N: seconds per mode and candidate) and the compile
    facts (first-call seconds, graph breaks)."""
    import jax
    import torch

    jax.config.update("jax_enable_x64", True)
    torch.set_num_threads(1)
    from rigidsym.kernels import jax as rj
    from rigidsym.kernels import torch as rk

    rows, facts = [], {}
    _warm_inductor(torch)
    jax.block_until_ready(jax.jit(jax.grad(lambda v: (jax.numpy.sin(v) * v).sum()))(
        jax.numpy.ones(8)))  # and JAX's start
    for name in KERNELS:
        f = getattr(rk, name)
        tpeer, jpeer = _peers(name)
        eager = {"k": lambda *a, f=f: f(*a, check=False), "h": _hand(torch, name), **tpeer}
        jfns = {"k": getattr(rj, name), "h": _hand(jax.numpy, name), **jpeer}
        nargs = len(_inputs(name, 1, float))
        jits = {k: jax.jit(jax.value_and_grad(lambda *a, fn=fn: _loss(fn(*a)),
                                              argnums=tuple(range(nargs))))
                for k, fn in jfns.items()}
        first = [torch.from_numpy(x) for x in _inputs(name, sizes[0], np.float64)]
        firstj = [jax.device_put(x) for x in _inputs(name, sizes[0], np.float64)]
        comp, fact = {}, {}
        for k in ("h", "k"):
            g = [t.clone().requires_grad_(True) for t in first]
            fact[f"breaks {k}"] = torch._dynamo.explain(eager[k])(*g).graph_break_count
            torch._dynamo.reset()
            with torch._inductor.config.patch(force_disable_caches=True):
                comp[k] = torch.compile(eager[k], dynamic=True)
                fact[f"compile {k}"] = _first(lambda c=comp[k]: _loss(c(*[
                    t.clone().requires_grad_(True) for t in first])).backward())
            fact[f"jit {k}"] = _first(lambda j=jits[k]: jax.block_until_ready(j(*firstj)))
        facts[name] = fact
        for dtype in (np.float64, np.float32):
            for n in sizes:
                xs = _inputs(name, n, dtype)
                ts = [torch.from_numpy(x) for x in xs]
                js = [jax.device_put(x) for x in xs]
                row = {"kernel": name, "dtype": np.dtype(dtype).name, "n": n}
                r = max(3, reps if n < 1e6 else 3)

                def steps(fns):
                    return {k: (lambda fn=fn: _loss(fn(*[t.clone().requires_grad_(True)
                                                         for t in ts])).backward())
                            for k, fn in fns.items()}
                for mode, got in (
                        ("eager", _interleaved(steps(eager), n, r)),
                        ("compiled", _interleaved(steps(comp), n, r)),
                        ("jit", _interleaved({k: (lambda j=j: jax.block_until_ready(j(*js)))
                                              for k, j in jits.items()}, n, r))):
                    for k, v in got.items():
                        row[f"{mode} {k}"] = v
                rows.append(row)
                print({k: (f"{v[0] * 1e3:.3g}" if isinstance(v, tuple) else v)
                       for k, v in row.items()}, flush=True)
    return rows, facts


def _cell(r, mode):
    (kw, kc), (hw, hc) = r[f"{mode} k"], r[f"{mode} h"]
    return [f"{kw * 1e3:.3g} / {hw * 1e3:.3g}", f"{kw / hw:.2f} ({kc / hc:.2f})"]


def grad_table(rows) -> str:
    """The Markdown table: ms of kernel / hand per mode, ratio of wall (of CPU) time."""
    peers = sorted({k.split(" ", 1)[1] for r in rows for k in r
                    if " " in k and k.split(" ", 1)[1] not in ("k", "h")})
    head = ["kernel", "dtype", "N"]
    for m in TARGETS:
        head += [f"{m} ms (k / h)", f"ratio (cpu) <= {TARGETS[m]}"]
    head += [f"{p} ms" for p in peers]
    lines = ["| " + " | ".join(head) + " |", "|---|---|" + "---:|" * (len(head) - 2)]
    for r in rows:
        cells = [r["kernel"], r["dtype"], f"{r['n']:.0e}"]
        for m in TARGETS:
            cells += _cell(r, m)
        for p in peers:
            v = [r[k][0] for k in (f"eager {p}", f"jit {p}") if k in r]
            cells.append(" ".join(f"{x * 1e3:.3g}" for x in v) or "-")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def facts_table(facts) -> str:
    lines = ["| kernel | torch.compile first call s (k / h) | ratio <= 1.5 | jax.jit first "
             "call s (k / h) | graph breaks (k / h) |", "|---|---:|---:|---:|---:|"]
    for name, f in facts.items():
        lines.append(f"| {name} | {f['compile k']:.2f} / {f['compile h']:.2f} | "
                     f"{f['compile k'] / f['compile h']:.2f} | {f['jit k']:.2f} / "
                     f"{f['jit h']:.2f} | {f['breaks k']} / {f['breaks h']} |")
    return "\n".join(lines)


def main(sizes=None, reps: int = 9) -> None:
    import jax
    import torch
    before = os.getloadavg()
    rows, facts = run_grad([int(s) for s in sizes or [1e3, 1e4, 1e5, 1e6]], reps)
    print(grad_table(rows))
    print()
    print(facts_table(facts))
    print(f"\nload average before {before[0]:.1f}, after {os.getloadavg()[0]:.1f} "
          f"({os.cpu_count()} cores); CPU: {platform.processor() or platform.machine()}; "
          f"torch {torch.__version__} ({torch.get_num_threads()} thread), "
          f"jax {jax.__version__}")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", nargs="+", type=float, default=None)
    ap.add_argument("--reps", type=int, default=9, help="timing samples (3 at N >= 1e6)")
    a = ap.parse_args()
    main(a.sizes, a.reps)
