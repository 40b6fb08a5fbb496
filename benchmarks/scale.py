"""Kernels at scale: threads, float32, the memory floor, Dask, and N = 1 latency.

Writes its own section of ``benchmarks/RESULTS.md`` between ``<!-- scale -->`` and
``<!-- /scale -->`` (the rest of the file belongs to ``run.py``). Every ratio of a table is
measured side by side in one run; the load average of the machine is printed with it.

Usage (from the repository root; the full run takes a few minutes on 2 quiet cores)::

    python benchmarks/scale.py [--quick] [--skip dask,latency] [--dask-n 1e8] [--chunk 2e6]

Clock: wall time (threads); each cell is the median over rounds of (time of repeated calls
until >= 20 ms) / (calls * N), outputs caller-provided (``out=``-style buffers).
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import BENCH, SPECS, inputs  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym.core.draws import draw  # noqa: E402
from rigidsym.kernels.runtime import scale as _scale  # noqa: E402
from rigidsym.kernels.runtime import state as _state  # noqa: E402

RESULTS = ROOT / "benchmarks" / "RESULTS.md"
PEERS = ROOT.parent / "shared" / "peers-bench"
BEGIN, END = "<!-- scale -->", "<!-- /scale -->"


def timeit(f, rounds: int, n: int) -> float:
    """Median ns/sample over ``rounds`` of repeated calls (>= 20 ms each)."""
    f()
    out = []
    for _ in range(rounds):
        calls, t0 = 0, time.perf_counter()
        while True:
            f()
            calls += 1
            dt = time.perf_counter() - t0
            if dt >= 0.02:
                break
        out.append(dt / calls / n * 1e9)
    return statistics.median(out)


def _case(name: str, n: int, dtype=np.float64):
    xs = [x.astype(dtype) for x in inputs(name, n, np.random.default_rng(1))]
    outs = [np.empty((n,) + o.shape, dtype=dtype) for o in SPECS[name].outputs]
    return xs, outs


def kernel_call(name: str, n: int, threads: int, dtype=np.float64):
    xs, outs = _case(name, n, dtype)
    f = K.batch_function(name, "c", threads=threads, dtype=dtype)
    return lambda: f(*xs, *outs)


_FLOOR = """
#include <stdint.h>
#include <string.h>
/* read every input byte once, write every output byte once; no arithmetic. Per sample
 * blocks of the same size as the kernels' (so the thread split is the same). */
uint64_t floor_io(int64_t n, int threads, int nin, const char **in, const int64_t *isz,
                  int nout, char **out, const int64_t *osz) {
    uint64_t acc = 0;
    #pragma omp parallel for schedule(static) num_threads(threads) reduction(^:acc) if(threads > 1)
    for (int64_t b = 0; b < (n + 255) / 256; ++b) {
        const int64_t i0 = b * 256, m = n - i0 < 256 ? n - i0 : 256;
        for (int k = 0; k < nin; ++k) {
            const uint64_t *p = (const uint64_t *)(in[k] + isz[k] * i0);
            for (int64_t j = 0; j < isz[k] * m / 8; ++j) acc ^= p[j];
        }
        for (int k = 0; k < nout; ++k)
            memset(out[k] + osz[k] * i0, 0, (size_t)(osz[k] * m));
    }
    return acc;
}
"""


def _floor_lib(build: Path):
    import cffi

    from rigidsym.kernels.cbuild import driver as _build

    path = K.build_info()["path"]
    march = [] if path == "baseline" else [f"-march={path}"]
    ffi = cffi.FFI()
    ffi.cdef("uint64_t floor_io(int64_t n, int threads, int nin, const char **in, "
             "const int64_t *isz, int nout, char **out, const int64_t *osz);")
    ffi.set_source("_scale_floor", _FLOOR, extra_compile_args=[*_build.kernel_flags(), *march,
                                                             *_build.OMP_FLAGS],
                   extra_link_args=list(_build.OMP_FLAGS))
    so = ffi.compile(tmpdir=str(build), verbose=False)
    spec = importlib.util.spec_from_file_location("_scale_floor", so)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def floor_call(lib, name: str, n: int, threads: int, dtype=np.float64):
    xs, outs = _case(name, n, dtype)
    ffi = lib.ffi
    keep = [ffi.from_buffer(a) for a in xs + outs]
    ins = ffi.new("const char *[]", [ffi.cast("const char *", p) for p in keep[:len(xs)]])
    ous = ffi.new("char *[]", [ffi.cast("char *", p) for p in keep[len(xs):]])
    isz = ffi.new("int64_t[]", [a.nbytes // n for a in xs])
    osz = ffi.new("int64_t[]", [a.nbytes // n for a in outs])
    return lambda: lib.lib.floor_io(n, threads, len(xs), ins, isz, len(outs), ous, osz)


def casadi_call(kid: str, n: int, threads: int):
    """CasADi's Function.map(N, "thread", t) (or "serial") on the peers-bench formula,
    through Function.buffer() on caller-provided numpy memory; None if unavailable."""
    try:
        import casadi  # noqa: F401
    except ImportError:
        return None
    if not (PEERS / "peerbench").is_dir():
        return None
    sys.path.insert(0, str(PEERS))
    from peerbench.kernels import KERNELS
    from peerbench.peers_casadi import make_function

    spec = KERNELS[kid]
    f = make_function(spec)
    F = f.map(n, "thread", threads) if threads > 1 else f.map(n, "serial")
    buf, evaluate = F.buffer()
    xs = spec.make_inputs(n)
    outs = [np.empty((n,) + s) for _, s in spec.outputs]
    for k, x in enumerate(xs):
        buf.set_arg(k, memoryview(np.ascontiguousarray(x)))
    for k, o in enumerate(outs):
        buf.set_res(k, memoryview(o))
    keep = (F, buf, xs, outs)          # the buffer and its memory must outlive the calls

    def call():
        evaluate()
        return keep
    return call


def table_threads(rounds: int, sizes: list[int]) -> list[str]:
    lines = ["| kernel | N | C 1 thread | C 2 threads | speed-up | CasADi map serial | "
             "CasADi map thread×2 | speed-up |", "|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        for kid, name in BENCH.items():
            t1 = timeit(kernel_call(name, n, 1), rounds, n)
            t2 = timeit(kernel_call(name, n, 2), rounds, n)
            c1 = casadi_call(kid, n, 1)
            c2 = casadi_call(kid, n, 2)
            ca = ["n/a"] * 3
            if c1 is not None:
                a, b = timeit(c1, rounds, n), timeit(c2, rounds, n)
                ca = [f"{a:.2f}", f"{b:.2f}", f"{a / b:.2f}×"]
            lines.append(f"| {kid} `{name}` | {n:.0e} | {t1:.2f} | {t2:.2f} | {t1 / t2:.2f}× | "
                         + " | ".join(ca) + " |")
    return lines


def table_threshold(rounds: int) -> list[str]:
    """1 against 2 threads around MIN_PARALLEL, through the C entry point itself (the checked
    API and batch_function run one thread below it)."""
    ffi, lib = _state.builtin().c_lib()
    lines = ["| kernel | " + " | ".join(f"N = {n}" for n in _THRESHOLD_N) + " |",
             "|---|" + "---|" * len(_THRESHOLD_N)]
    for kid in ("K1", "K2", "K5"):
        name = BENCH[kid]
        cells = []
        for n in _THRESHOLD_N:
            xs, outs = _case(name, n)
            ptrs = [ffi.from_buffer("double[]", a) for a in xs + outs]
            fn = getattr(lib, f"rigidsym_{name}_threads")
            t1 = timeit(lambda fn=fn, n=n, p=ptrs: fn(n, 1, *p), rounds, n)
            t2 = timeit(lambda fn=fn, n=n, p=ptrs: fn(n, 2, *p), rounds, n)
            cells.append(f"{t1 / t2:.2f}×")
        lines.append(f"| {kid} `{name}` | " + " | ".join(cells) + " |")
    return lines


_THRESHOLD_N = [512, 1024, 2048, 4096, 8192, 16384, 65536]


def table_float32(rounds: int, n: int) -> list[str]:
    lines = ["| kernel | float64 | float32 | speed-up |", "|---|---|---|---|"]
    for kid, name in BENCH.items():
        a = timeit(kernel_call(name, n, 1), rounds, n)
        b = timeit(kernel_call(name, n, 1, np.float32), rounds, n)
        lines.append(f"| {kid} `{name}` | {a:.2f} | {b:.2f} | {a / b:.2f}× |")
    return lines


def table_floor(rounds: int, n: int, build: Path) -> list[str]:
    lib = _floor_lib(build)
    head = ["| kernel | bytes/sample (f64) |"]
    cells = []
    for dt in ("float64", "float32"):
        for t in (1, 2):
            cells.append((dt, t))
            head.append(f" {dt} {t}T: kernel / floor (ns) |")
    lines = ["".join(head), "|---|---|" + "---|" * len(cells)]
    for kid, name in BENCH.items():
        xs, outs = _case(name, 1, np.float64)
        row = [f"| {kid} `{name}` | {sum(a.nbytes for a in xs + outs)} |"]
        for dt, t in cells:
            dtype = np.float32 if dt == "float32" else np.float64
            k = timeit(kernel_call(name, n, t, dtype), rounds, n)
            f = timeit(floor_call(lib, name, n, t, dtype), rounds, n)
            row.append(f" {k / f:.2f} ({k:.2f} / {f:.2f}) |")
        lines.append("".join(row))
    return lines


def _dask_pipeline(name: str, n: int, chunk: int):
    import dask.array as da

    rs = da.random.RandomState(3)
    args = []
    for a in SPECS[name].args:
        shape = (n,) + a.shape
        chunks = (chunk,) + a.shape
        if a.kind == "unit":
            v = rs.standard_normal(shape, chunks=chunks)
            v = v / da.linalg.norm(v, axis=-1, keepdims=True)
        elif a.kind == "angle":
            v = rs.uniform(0.2, np.pi - 0.05, shape, chunks=chunks)
        else:
            v = rs.standard_normal(shape, chunks=chunks)
        args.append(v)
    res = _state.call(name, tuple(args))
    res = res if isinstance(res, tuple) else (res,)
    return sum(r.sum() for r in res)


def table_dask(n_big: int, n_small: int, chunk: int) -> list[str]:
    import dask
    import distributed

    lines = ["| kernel | in-process, 1 thread: N, samples/s | 2 workers × 1 thread: N, "
             "samples/s | speed-up |", "|---|---|---|---|"]
    K.use_backend("c")                        # build before the workers start
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        for kid in ("K3", "K5"):
            name = BENCH[kid]
            t0 = time.perf_counter()
            dask.compute(_dask_pipeline(name, n_small, chunk), scheduler="synchronous")
            one = n_small / (time.perf_counter() - t0)
            client.compute(_dask_pipeline(name, 2 * chunk, chunk), sync=True)   # warm-up
            t0 = time.perf_counter()
            client.compute(_dask_pipeline(name, n_big, chunk), sync=True)
            two = n_big / (time.perf_counter() - t0)
            lines.append(f"| {kid} `{name}` | {n_small:.0e}, {one:.3g} | {n_big:.0e}, "
                         f"{two:.3g} | {two / one:.2f}× |")
    return lines


def table_latency(rounds: int) -> list[str]:
    lines = ["| kernel | N = 1 call (µs), C | NumPy |", "|---|---|---|"]
    rng = np.random.default_rng(0)
    for name in K.KERNEL_NAMES:
        meta = _state.meta()[name]
        xs = []
        for a in meta["args"]:
            v = draw(a["kind"], a["shape"], rng, phi=(0.7, 0.7),
                     free=lambda s: rng.uniform(0.5, 1.5, s))
            xs.append(v)
        f = getattr(K, name)
        cells = []
        for b in ("c", "numpy"):
            K.use_backend(b)
            cells.append(timeit(lambda f=f, xs=xs: f(*xs, on_singular="nan"), rounds, 1) / 1e3)
        lines.append(f"| `{name}` | {cells[0]:.1f} | {cells[1]:.1f} |")
    K.use_backend("c")
    return lines


def write_section(body: list[str]) -> None:
    from _results import write_section as write

    write(RESULTS, "\n".join([BEGIN, *body, END]), BEGIN, END)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="3 rounds, smaller Dask run")
    p.add_argument("--skip", default="", help="tables to skip: threads,float32,floor,dask,"
                                              "latency")
    p.add_argument("--dask-n", type=float, default=None,
                   help="samples of the 2-worker Dask run (default 1e8, 1e7 with --quick); "
                        "the in-process run has a tenth")
    p.add_argument("--chunk", type=float, default=1e6, help="Dask chunk (samples)")
    p.add_argument("--print-only", action="store_true", help="do not write RESULTS.md")
    args = p.parse_args(argv)
    skip = set(filter(None, args.skip.split(",")))
    rounds = 3 if args.quick else 7
    assert K.use_backend("c") == "c", "the benchmarks need the C backend"
    load0 = os.getloadavg()
    body = ["## Kernels at scale", "",
            f"`python benchmarks/scale.py{' --quick' if args.quick else ''}`; "
            f"OpenMP build: {K.build_info()['openmp']}; {os.cpu_count()} cores; load average "
            f"at the "
            f"start {load0[0]:.1f} (1 min), ns/sample unless stated; outputs caller-provided. "
            "Other work on the machine changes absolute numbers; ratios are side by side.", ""]
    with tempfile.TemporaryDirectory() as tmp:
        if "threads" not in skip:
            body += ["### Threads (C, OpenMP; CasADi `Function.map(N, \"thread\", 2)` as the "
                     "peer)", ""]
            body += table_threads(rounds, [10**3, 10**4, 10**6]) + [""]
            body += ["### Threads below and above `MIN_PARALLEL` "
                     f"({_scale.MIN_PARALLEL}): 2-thread speed-up of the C entry point", ""]
            body += table_threshold(rounds) + [""]
        if "float32" not in skip:
            body += ["### float32 against float64 (C, 1 thread, N = 1e6)", ""]
            body += table_float32(rounds, 10**6) + [""]
        if "floor" not in skip:
            body += ["### Memory floor (N = 1e6): kernel time over the time to read its "
                     "inputs and write its outputs once", ""]
            body += table_floor(rounds, 10**6, Path(tmp)) + [""]
    if "dask" not in skip:
        n_big = int(args.dask_n or (1e7 if args.quick else 1e8))
        chunk = int(args.chunk)
        body += [f"### Dask: `dask.array.random` → kernel → `.sum()`, chunks of {chunk:.0e} "
                 "samples", ""]
        body += table_dask(n_big, n_big // 10, chunk) + [""]
    if "latency" not in skip:
        body += ["### One call at N = 1 (validation and dispatch), public API", ""]
        body += table_latency(rounds) + [""]
    body.append(f"Load average at the end: {os.getloadavg()[0]:.1f}.")
    print("\n".join(body))
    if not args.print_only:
        write_section(body)
    return 0


if __name__ == "__main__":
    sys.exit(main())
