"""Value + gradient of the kernels against a hand-written formula.

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

``--first [KERNEL ...] --reps R``: only the first ``torch.compile`` call, ``R`` times in one
process, kernel and hand alternated, and the node counts of the forward and backward graphs.
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


def run_grad(sizes, reps: int = 9, modes=tuple(TARGETS)) -> tuple[list[dict], dict]:
    """Rows (one per kernel, dtype, N: seconds per mode and candidate) and the compile
    facts (first-call seconds, graph breaks), of the ``modes`` (of ``TARGETS``)."""
    import jax

    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as rj
    torch = None
    if set(modes) - {"jit"}:  # PyTorch only for its modes
        import torch

        from rigidsym.kernels import torch as rk
        torch.set_num_threads(1)

    rows, facts = [], {}
    if "compiled" in modes:
        _warm_inductor(torch)
    jax.block_until_ready(jax.jit(jax.grad(lambda v: (jax.numpy.sin(v) * v).sum()))(
        jax.numpy.ones(8)))  # and JAX's start
    for name in KERNELS:
        tpeer, jpeer = _peers(name)
        f = None if torch is None else getattr(rk, name)
        eager = {} if torch is None else {
            "k": lambda *a, f=f: f(*a, check=False), "h": _hand(torch, name), **tpeer}
        jfns = {"k": getattr(rj, name), "h": _hand(jax.numpy, name), **jpeer}
        nargs = len(_inputs(name, 1, float))
        jits = {k: jax.jit(jax.value_and_grad(lambda *a, fn=fn: _loss(fn(*a)),
                                              argnums=tuple(range(nargs))))
                for k, fn in jfns.items()}
        first = [] if torch is None else [torch.from_numpy(x)
                                          for x in _inputs(name, sizes[0], np.float64)]
        firstj = [jax.device_put(x) for x in _inputs(name, sizes[0], np.float64)]
        comp, fact = {}, {}
        for k in ("h", "k") if "compiled" in modes else ():
            g = [t.clone().requires_grad_(True) for t in first]
            fact[f"breaks {k}"] = torch._dynamo.explain(eager[k])(*g).graph_break_count
            torch._dynamo.reset()
            with torch._inductor.config.patch(force_disable_caches=True):
                comp[k] = torch.compile(eager[k], dynamic=True)
                fact[f"compile {k}"] = _first(lambda c=comp[k]: _loss(c(*[
                    t.clone().requires_grad_(True) for t in first])).backward())
        for k in ("h", "k"):
            fact[f"jit {k}"] = _first(lambda j=jits[k]: jax.block_until_ready(j(*firstj)))
        facts[name] = fact
        for dtype in (np.float64, np.float32):
            for n in sizes:
                xs = _inputs(name, n, dtype)
                ts = [] if torch is None else [torch.from_numpy(x) for x in xs]
                js = [jax.device_put(x) for x in xs]
                row = {"kernel": name, "dtype": np.dtype(dtype).name, "n": n}
                r = max(3, reps if n < 1e6 else 3)

                def steps(fns):
                    return {k: (lambda fn=fn: _loss(fn(*[t.clone().requires_grad_(True)
                                                         for t in ts])).backward())
                            for k, fn in fns.items()}
                timed = {"eager": lambda: _interleaved(steps(eager), n, r),
                         "compiled": lambda: _interleaved(steps(comp), n, r),
                         "jit": lambda: _interleaved({k: (lambda j=j: jax.block_until_ready(
                             j(*js))) for k, j in jits.items()}, n, r)}
                for mode in modes:
                    for k, v in timed[mode]().items():
                        row[f"{mode} {k}"] = v
                rows.append(row)
                print({k: (f"{v[0] * 1e3:.3g}" if isinstance(v, tuple) else v)
                       for k, v in row.items()}, flush=True)
    return rows, facts


def _graph_nodes(torch, fn, xs) -> tuple[int, int]:
    """``(forward, backward)``: the nodes of the ATen graphs AOTAutograd hands inductor for
    the value + gradient of ``fn`` (``dynamic=True``; no compile, the graphs only)."""
    from torch._dynamo.backends.common import aot_autograd

    counts = []

    def count(gm, _inputs):
        counts.append(len(gm.graph.nodes))
        return gm.forward

    torch._dynamo.reset()
    c = torch.compile(fn, dynamic=True, backend=aot_autograd(fw_compiler=count,
                                                              bw_compiler=count))
    _loss(c(*[t.clone().requires_grad_(True) for t in xs])).backward()
    torch._dynamo.reset()
    return counts[0], sum(counts[1:])


def _cpu() -> float:
    """CPU seconds of this process and its waited-for children (the C++ compiler)."""
    import resource

    me, kids = (resource.getrusage(w) for w in (resource.RUSAGE_SELF,
                                                   resource.RUSAGE_CHILDREN))
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


#: inductor's phases of a first call (``torch._dynamo.utils.compilation_time_metrics``)
PHASES = {"all": "_compile.compile_inner", "aot trace": "aot_trace_joint_graph",
          "forward": "compile_fx.<locals>.fw_compiler_base",
          "backward": "compile_fx.<locals>.bw_compiler", "schedule": "Scheduler.__init__",
          "codegen": "Scheduler.codegen", "c++": "compile_file"}


def run_first(names, n: int, reps: int) -> dict:
    """``{kernel: {"k": [(wall s, cpu s, {phase: s}), ...], "h": [...], "nodes k": (fw, bw),
    "nodes h": ...}}``: the first call of ``torch.compile`` (inductor, ``dynamic=True``,
    value + gradient, caches off: trace, compile, run), ``reps`` times, kernel and hand
    alternated (which one goes first alternating too), after one small compile that pays
    inductor's start; ``compile_threads=1`` so that the C++ compiler is a child of this
    process and its CPU time is counted (the CPU time: robust to the load of a shared
    machine, where the wall time of one first call moves by 2x)."""
    import torch
    from torch._dynamo.utils import compilation_time_metrics as metrics

    from rigidsym.kernels import torch as rk

    torch.set_num_threads(1)
    _warm_inductor(torch)
    out = {}
    for name in names:
        f = getattr(rk, name)
        fns = {"k": lambda *a, f=f: f(*a, check=False), "h": _hand(torch, name)}
        xs = [torch.from_numpy(x) for x in _inputs(name, n, np.float64)]
        got: dict = {k: [] for k in fns}
        for r in range(reps):
            for k in (("k", "h") if r % 2 == 0 else ("h", "k")):
                torch._dynamo.reset()
                metrics.clear()
                with torch._inductor.config.patch(force_disable_caches=True,
                                                  compile_threads=1):
                    c = torch.compile(fns[k], dynamic=True)
                    cpu = _cpu()
                    wall = _first(lambda c=c: _loss(c(*[
                        t.clone().requires_grad_(True) for t in xs])).backward())
                    got[k].append((wall, _cpu() - cpu, {p: sum(metrics.get(m, [0.0]))
                                                        for p, m in PHASES.items()}))
        for k, fn in fns.items():
            got[f"nodes {k}"] = _graph_nodes(torch, fn, xs)
        out[name] = got
        for k in fns:
            print(name, k, "wall", [round(w, 2) for w, _, _ in got[k]], "cpu",
                  [round(c, 2) for _, c, _ in got[k]], "phases", [
                      {p: round(v, 2) for p, v in ph.items()} for _, _, ph in got[k]],
                  flush=True)
        print(name, "graph nodes (forward, backward): k", got["nodes k"], "h", got["nodes h"])
    return out


def _cell(r, mode):
    (kw, kc), (hw, hc) = r[f"{mode} k"], r[f"{mode} h"]
    return [f"{kw * 1e3:.3g} / {hw * 1e3:.3g}", f"{kw / hw:.2f} ({kc / hc:.2f})"]


def grad_table(rows) -> str:
    """The Markdown table: ms of kernel / hand per mode, ratio of wall (of CPU) time."""
    peers = sorted({k.split(" ", 1)[1] for r in rows for k in r
                    if " " in k and k.split(" ", 1)[1] not in ("k", "h")})
    modes = [m for m in TARGETS if rows and f"{m} k" in rows[0]]
    head = ["kernel", "dtype", "N"]
    for m in modes:
        head += [f"{m} ms (k / h)", f"ratio (cpu) <= {TARGETS[m]}"]
    head += [f"{p} ms" for p in peers]
    lines = ["| " + " | ".join(head) + " |", "|---|---|" + "---:|" * (len(head) - 2)]
    for r in rows:
        cells = [r["kernel"], r["dtype"], f"{r['n']:.0e}"]
        for m in modes:
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
        comp = (f"{f['compile k']:.2f} / {f['compile h']:.2f} | "
                f"{f['compile k'] / f['compile h']:.2f}") if "compile k" in f else "- | -"
        breaks = f"{f['breaks k']} / {f['breaks h']}" if "breaks k" in f else "-"
        lines.append(f"| {name} | {comp} | {f['jit k']:.2f} / {f['jit h']:.2f} | {breaks} |")
    return "\n".join(lines)


def main(sizes=None, reps: int = 9, modes=tuple(TARGETS)) -> None:
    import jax
    before = os.getloadavg()
    rows, facts = run_grad([int(s) for s in sizes or [1e3, 1e4, 1e5, 1e6]], reps, modes)
    print(grad_table(rows))
    print()
    print(facts_table(facts))
    torch = sys.modules.get("torch")
    print(f"\nload average before {before[0]:.1f}, after {os.getloadavg()[0]:.1f} "
          f"({os.cpu_count()} cores, {len(os.sched_getaffinity(0))} used); "
          f"CPU: {platform.processor() or platform.machine()}; "
          + (f"torch {torch.__version__} ({torch.get_num_threads()} thread), "
             if torch else "") + f"jax {jax.__version__}")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", nargs="+", type=float, default=None)
    ap.add_argument("--reps", type=int, default=9, help="timing samples (3 at N >= 1e6)")
    ap.add_argument("--modes", nargs="+", choices=list(TARGETS), default=list(TARGETS),
                    help="the modes timed (default all)")
    ap.add_argument("--one-core", action="store_true",
                    help="pin the process to one CPU core before JAX starts: XLA then splits "
                    "no fusion into parallel tasks (on 2 shared cores a split "
                    "fusion waits for the second one), as torch runs on one thread here")
    ap.add_argument("--first", nargs="*", metavar="KERNEL", default=None,
                    help="only the first torch.compile call (--reps times, kernel and hand "
                    "alternated, N = the first of --sizes) and the graphs' node counts, of "
                    "these kernels (default: both)")
    a = ap.parse_args()
    if a.one_core:
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
    if a.first is not None:
        before = os.getloadavg()[0]
        run_first(a.first or KERNELS, int((a.sizes or [1e3])[0]), a.reps)
        print(f"load average before {before:.1f}, after {os.getloadavg()[0]:.1f}")
    else:
        main(a.sizes, a.reps, tuple(a.modes))
