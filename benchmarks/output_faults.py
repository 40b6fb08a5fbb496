"""Where K1, K2, K3, K5's time goes at N = 1e6 with outputs allocated in every call: page
faults (``getrusage`` minor faults a call), allocated against caller-provided outputs, in cache
(N = 1e4) against N = 1e6, the public call against the bare batch call, beside the peer
benchmark's fastest compiled peer (c-sympy-cse, built by ``../shared/peers-bench``).

    python benchmarks/output_faults.py [--peers-bench /work/pb] [--rounds 9] [--N 10000,1000000]

Every variant of a kernel is timed in the same interleaved rounds (thread CPU time, which
includes the kernel time of page faults); columns (ns/sample, minimum and median of rounds):

* ``peer``: c-sympy-cse as the harness calls it (``np.empty`` outputs, one ctypes call);
* ``bare``: the compiled module's ``batch`` (no validation) into caller-provided outputs,
  the same arrays every call (recycled: no fault);
* ``adapter``: ``np.empty`` outputs + ``batch`` (``benchmarks/peers_adapter.py``);
* ``api``: the public kernel's C entry (what ``f(*inputs, check=False)`` runs with the
  output pool off): outputs allocated by the entry;
* ``api-out``: ``f(*inputs, check=False, out=...)``, the caller's recycled outputs;
* ``api-pool``: ``f(*inputs, check=False)`` with the output pool on
  (``rigidsym.kernels.set_output_pool``), when it exists;
* ``faults``: ``np.empty`` of the outputs + one store a 4 KiB page (the faults alone).

The process first frees one ~31 MB block, as the harness does (glibc's mmap threshold then
~31 MB: larger outputs are mmap'd, and faulted, on every call).
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
import resource
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
KIDS = ("K1", "K2", "K3", "K5")


def _adapter():
    spec = importlib.util.spec_from_file_location("rigidsym_peers_adapter",
                                                  ROOT / "benchmarks" / "peers_adapter.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _faults() -> int:
    return resource.getrusage(resource.RUSAGE_THREAD).ru_minflt


def _time(fn, args, number: int) -> tuple[float, float]:
    """Seconds a call (thread CPU time) and minor faults a call."""
    f0, t0 = _faults(), time.thread_time()
    for _ in range(number):
        fn(*args)
    t1, f1 = time.thread_time(), _faults()
    return (t1 - t0) / number, (f1 - f0) / number



def _variants(spec, N: int, ad, mod, peer, rk) -> dict:
    """The callables timed for kernel ``spec`` at N samples."""
    name = ad.BENCH[spec.kid]
    api = getattr(rk, name)
    entry = getattr(rk.load()._SPACE.entries(), name)   # the C entry, no pool
    k = mod.kernels.index(name)
    shapes = [tuple(o["shape"]) for o in ad._META[name]["outputs"]]
    outs = [np.empty((N,) + s) for s in shapes]
    out_arg = outs[0] if len(outs) == 1 else tuple(outs)
    step = 4096 // 8

    def faults_only(*_):
        ys = [np.empty((N,) + s) for s in shapes]
        for y in ys:
            y.reshape(-1)[::step] = 0.0
        return ys

    v = {
        "peer": peer[spec.kid],
        "bare": lambda *xs: mod.batch(k, False, N, 1, *xs, *outs),
        "adapter": ad.KERNELS[spec.kid],
        "api": lambda *xs: entry(*xs, None, False, None, None),
        "api-out": lambda *xs: api(*xs, check=False, out=out_arg),
        "faults": faults_only,
    }
    if hasattr(rk, "set_output_pool"):
        v["api-pool"] = lambda *xs: api(*xs, check=False)
    return v


def _cell(spec, N: int, a, ad, mod, peer, rk) -> None:
    xs = spec.make_inputs(N)
    variants = _variants(spec, N, ad, mod, peer, rk)
    number = {}
    for v, fn in variants.items():
        fn(*xs)
        t, _ = _time(fn, xs, 1)
        number[v] = max(1, int(a.target / max(t, 1e-9)))
    times = {v: [] for v in variants}
    flts = {v: [] for v in variants}
    gc.collect()
    gc.disable()
    names = list(variants)
    for r in range(a.rounds):
        for v in names[r % len(names):] + names[:r % len(names)]:
            t, f = _time(variants[v], xs, number[v])
            times[v].append(t / N * 1e9)
            flts[v].append(f)
    gc.enable()
    print(f"\n{spec.kid} {ad.BENCH[spec.kid]} N={N:g} (ns/sample min / median; minor faults "
          f"a call)")
    for v in names:
        print(f"  {v:9s} {min(times[v]):7.2f} / {statistics.median(times[v]):7.2f}"
              f"   faults {statistics.median(flts[v]):8.1f}")

def main(argv: list[str] | None = None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--peers-bench", default="/work/pb", type=Path)
    p.add_argument("--rounds", type=int, default=9)
    p.add_argument("--N", default="10000,1000000")
    p.add_argument("--kernels", default=",".join(KIDS))
    p.add_argument("--target", type=float, default=0.1, help="seconds a measurement")
    a = p.parse_args(argv)

    sys.path.insert(0, str(a.peers_bench))
    from peerbench import peers_sympy
    from peerbench.kernels import KERNELS

    x = np.empty((31 << 20) // 8)     # the harness's warm_malloc
    x[:] = 0.0
    del x

    import rigidsym.kernels as rk
    if hasattr(rk, "set_output_pool"):
        rk.set_output_pool(True)       # for api-pool; api calls the C entry itself
    ad = _adapter()
    ad.setup({"build_dir": a.peers_bench / "build"})
    specs = [KERNELS[k] for k in a.kernels.split(",")]
    peer = peers_sympy.build_c_loop(specs, a.peers_bench / "build", "gcc",
                                    ["-O3", "-march=native"])[0]
    mod = ad._build(a.peers_bench / "build", False)
    print(f"module path {mod.path}; load {open('/proc/loadavg').read().split()[:3]}")
    for spec in specs:
        for N in [int(float(s)) for s in a.N.split(",")]:
            _cell(spec, N, a, ad, mod, peer, rk)
    print(f"\nload {open('/proc/loadavg').read().split()[:3]}")


if __name__ == "__main__":
    main()
