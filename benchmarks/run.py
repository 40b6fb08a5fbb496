"""Benchmark the generated kernels: ns/sample at N = 1e3, 1e5, 1e6, one thread.

Columns: generated C (cffi batch loop), generated NumPy, hand-written vectorised NumPy
(the peers-bench reference where it exists), ``sympy.lambdify(cse=True)`` of the declared
expressions, and a plain ``sympy.cse`` + ``ccode`` C loop (gcc -O3 -march=native) of the same
expressions; plus each kernel's operation count. Writes ``benchmarks/RESULTS.md``.

Usage (from the repository root)::

    python benchmarks/run.py [--quick] [--kernels K1,K2]

Clock: thread CPU time; each cell is the median over rounds of (time of repeated calls until
>= 10 ms) / (calls * N). Outputs are allocated inside every timed call for every column.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp

ROOT = Path(__file__).resolve().parents[1]
os.environ.setdefault("OMP_NUM_THREADS", "1")

from rigidsym.derivations.kernels_spec import KERNELS  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.generator import _flatten  # noqa: E402
from rigidsym.codegen.spec import flat_symbols, input_symbols  # noqa: E402
from rigidsym.core.draws import draw  # noqa: E402
from rigidsym.kernels.runtime import state as _state  # noqa: E402

PEERS = ROOT.parent / "shared" / "peers-bench" / "peerbench" / "kernels.py"
#: benchmark id -> our kernel (K4 without the Plücker array, as the peers compute it)
BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_wrench"}
SPECS = {k.name: k for k in KERNELS}
META = None


def _peers():
    if not PEERS.exists():
        return None
    spec = importlib.util.spec_from_file_location("peer_kernels", PEERS)
    mod = importlib.util.module_from_spec(spec)
    sys.modules["peer_kernels"] = mod          # dataclasses look the module up
    spec.loader.exec_module(mod)
    return mod


def inputs(name: str, n: int, rng) -> list[np.ndarray]:
    k = SPECS[name]
    out = []
    for a in k.args:
        if a.name == "m":
            v = rng.uniform(0.5, 5.0, n)
        else:   # on the kind's manifold: unit, rotation, transform; angles off 0 and pi
            v = draw(a.kind, (n,) + a.shape, rng, phi=(0.2, 3.0), angle=(0.2, np.pi - 0.05))
        out.append(np.ascontiguousarray(v, dtype=np.float64))
    return out


def _alloc_call(f, name):
    k = SPECS[name]

    def call(*xs, out=None):
        n = xs[0].shape[0]
        outs = [np.empty((n,) + o.shape) for o in k.outputs] if out is None else out
        f(*xs, *outs)
        return outs
    return call


def col_generated(name: str, backend: str):
    return _alloc_call(K.batch_function(name, backend), name)


_FLOOR_SRC = """
#include <stdint.h>
#include <string.h>
uint64_t floor_read(const double *x, int64_t len) {
    uint64_t acc = 0;            /* integer xor: vectorises without reassociating floats */
    for (int64_t i = 0; i < len; ++i) { uint64_t b; memcpy(&b, x + i, 8); acc ^= b; }
    return acc;
}
void floor_write(double *x, int64_t len) {
    for (int64_t i = 0; i < len; ++i) x[i] = 0.0;
}
"""


def col_floor(name: str, build: Path):
    """Memory floor: allocate the outputs as the other columns do, read every input byte once
    and write every output byte once (no arithmetic). No kernel with the same inputs and
    outputs can go below it by much; a kernel at this floor is memory-bound."""
    import cffi

    ffi = cffi.FFI()
    ffi.cdef("uint64_t floor_read(const double *x, int64_t len);"
             "void floor_write(double *x, int64_t len);")
    ffi.set_source("_floor_io", _FLOOR_SRC, extra_compile_args=_cflags())
    lib = _load_cffi("_floor_io", ffi.compile(tmpdir=str(build), verbose=False))
    fb = lib.ffi.from_buffer

    def f(*arrays):
        nin = len(SPECS[name].args)
        for x in arrays[:nin]:
            lib.lib.floor_read(fb("double[]", x), x.size)
        for o in arrays[nin:]:
            lib.lib.floor_write(fb("double[]", o), o.size)
    return _alloc_call(f, name)


def _load_cffi(mod: str, so: str):
    spec = importlib.util.spec_from_file_location(mod, so)
    lib = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(lib)
    return lib


def _declared(name: str):
    k = SPECS[name]
    syms = input_symbols(k)
    flat = [s for _, ss in flat_symbols(k) for s in ss]
    return k, flat, _flatten(k, k.build(**syms))


def col_lambdify(name: str):
    k, flat, exprs = _declared(name)
    f = sp.lambdify(flat, exprs, modules="numpy", cse=True)

    def call(*xs):
        n = xs[0].shape[0]
        cols = [c for x in xs for c in (x.reshape(n, -1).T)]
        vals = f(*cols)
        res = np.empty((n, len(exprs)))
        for j, v in enumerate(vals):
            res[:, j] = v
        return res
    return call


def col_sympy_c(name: str, build: Path):
    """Plain sympy.cse + ccode loop over the declared expressions (no rewrites), built and
    called through cffi with the base flags of the generated C, so that the two C columns
    differ only in the code (not in call overhead or compiler flags)."""
    import cffi

    k, flat, exprs = _declared(name)
    temps, red = sp.cse(exprs)
    ins = k.args
    sig = (f"void plain_{name}(int64_t n, "
           + ", ".join(f"const double *in{i}" for i in range(len(ins))) + ", double *out)")
    lines = ["#include <math.h>", "#include <stdint.h>", sig + " {",
             "  for (int64_t i = 0; i < n; ++i) {"]
    for i, (_name, ss) in enumerate(flat_symbols(k)):
        for j, s in enumerate(ss):
            lines.append(f"    const double {s} = in{i}[{len(ss)} * i + {j}];")
    for s, v in temps:
        lines.append(f"    const double {s} = {sp.ccode(v)};")
    for j, v in enumerate(red):
        lines.append(f"    out[{len(red)} * i + {j}] = {sp.ccode(v)};")
    lines += ["  }", "}"]
    ffi = cffi.FFI()
    ffi.cdef(sig + ";")
    mod = f"_plain_{name}"
    ffi.set_source(mod, "\n".join(lines) + "\n", extra_compile_args=_cflags(),
                   libraries=["m"])
    so = ffi.compile(tmpdir=str(build), verbose=False)
    lib = _load_cffi(mod, so)
    fn, fb, m = getattr(lib.lib, f"plain_{name}"), lib.ffi.from_buffer, len(red)

    def call(*xs, out=None):
        n = xs[0].shape[0]
        out = np.empty((n, m)) if out is None else out
        fn(n, *[fb("double[]", x) for x in xs], fb("double[]", out))
        return out
    # counted as the generator counts its own (sympy.count_ops of the CSE'd program)
    call.ops = sum(int(sp.count_ops(v)) for _, v in temps) + sum(int(sp.count_ops(v))
                                                                   for v in red)
    return call


def _cflags() -> list[str]:
    """The kernels' flags and the dispatched path in use (``-march=x86-64-v3`` on an AVX2
    machine): the baselines are compiled as the package's own C runs."""
    from rigidsym.kernels.cbuild import driver as _build

    path = K.build_info()["path"]
    march = [] if path == "baseline" else [f"-march={path}"]
    return [*_build.kernel_flags(), *march]


def _mvec() -> bool:
    """Whether the generated C in use calls libmvec's vector sin/cos."""
    return bool(K.build_info()["libmvec"])


def timeit(f, xs, n: int, rounds: int) -> float:
    f(*xs)
    res = []
    for _ in range(rounds):
        calls = 0
        t0 = time.thread_time()
        while True:
            f(*xs)
            calls += 1
            t = time.thread_time() - t0
            if t >= 0.01:
                break
        res.append(t / calls / n * 1e9)
    return statistics.median(res)


def _flat_out(o, n):
    o = o if isinstance(o, (list, tuple)) else [o]
    return np.concatenate([np.asarray(x).reshape(n, -1) for x in o], axis=1)


ALLOC_COLS = ["generated C", "generated NumPy", "hand NumPy", "lambdify-cse", "sympy-cse C",
              "memory floor"]
#: columns that can write into caller-provided outputs
PRE_COLS = ["generated C", "generated NumPy", "sympy-cse C", "memory floor"]


def _outputs(name: str, col: str, n: int):
    k = SPECS[name]
    if col == "sympy-cse C":
        return np.empty((n, sum(o.size for o in k.outputs)))
    return [np.empty((n,) + o.shape) for o in k.outputs]


def _measure(name, funcs, xs, n, rounds):
    """Both regimes for one kernel and one N: {regime: {column: ns/sample or a note}}."""
    ref = _flat_out(funcs["generated C"](*xs), n)
    res = {"allocated": {}, "caller-provided outputs": {}}
    for c in ALLOC_COLS:
        if c not in funcs:
            res["allocated"][c] = "n/a"
            continue
        if c != "memory floor":
            got = _flat_out(funcs[c](*xs), n)
            scale = np.maximum(np.abs(ref).max(axis=1), 1e-300)
            err = (np.abs(got - ref).max(axis=1) / scale).max()
            if err > 1e-10:
                res["allocated"][c] = f"mismatch {err:.1e}"
                continue
        res["allocated"][c] = timeit(funcs[c], xs, n, rounds)
        if c in PRE_COLS:
            outs = _outputs(name, c, n)
            res["caller-provided outputs"][c] = timeit(
                lambda *a, _f=funcs[c], _o=outs: _f(*a, out=_o), xs, n, rounds)
    return res


def _table(rows, N, regime, cols):
    text = [f"### {regime}", "",
            "| kernel | ours | ops | sympy-cse ops | " + " | ".join(cols)
            + " | C / sympy-cse C |",
            "|---|---|---:|---:|" + "---:|" * (len(cols) + 1)]
    for kid, name, n, ops, res in rows:
        if n != N:
            continue
        cells = res[regime]
        fmt = [f"{v:.3g}" if isinstance(v, float) else v for v in (cells[c] for c in cols)]
        a, b = cells.get("generated C"), cells.get("sympy-cse C")
        ratio = f"{a / b:.2f}" if isinstance(a, float) and isinstance(b, float) else "n/a"
        text.append(f"| {kid} | `{name}` | {ops[0]} | {ops[1]} | " + " | ".join(fmt)
                    + f" | {ratio} |")
    return text + [""]


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="N = 1e3, 1e5 and 3 rounds")
    p.add_argument("--kernels", default=",".join(BENCH), help="K1,...,K6")
    p.add_argument("--out", default=str(ROOT / "benchmarks" / "RESULTS.md"))
    args = p.parse_args(argv)
    K.use_backend("c")
    # glibc malloc into its steady large-array regime (as peers-bench does): freeing one
    # ~31 MB block raises the dynamic mmap threshold, so NumPy temporaries are not mmapped
    # and page-faulted on every call
    big = np.ones(4_000_000)
    del big
    peers = _peers()
    Ns = [1000, 100000] if args.quick else [1000, 100000, 1000000]
    rng = np.random.default_rng(1)
    rows = []
    meta = _state.meta()
    with tempfile.TemporaryDirectory() as tmp:
        build = Path(tmp)
        for kid in args.kernels.split(","):
            name = BENCH[kid]
            funcs = {"generated C": col_generated(name, "c"),
                     "generated NumPy": col_generated(name, "numpy"),
                     "lambdify-cse": col_lambdify(name),
                     "sympy-cse C": col_sympy_c(name, build),
                     "memory floor": col_floor(name, build)}
            if peers is not None:
                hand = getattr(peers, f"np_{kid.lower()}")
                if kid == "K6":     # the peers' residual with n = f = 0 is the wrench
                    def hand(*xs, _f=hand):
                        z = np.zeros((xs[0].shape[0], 3))
                        return _f(*xs, z, z)
                funcs["hand NumPy"] = hand
            for N in Ns:
                xs = inputs(name, N, rng)
                rounds = 3 if args.quick else 7
                res = _measure(name, funcs, xs, N, rounds)
                rows.append((kid, name, N, (meta[name]["ops"], funcs["sympy-cse C"].ops), res))
                for regime, cells in res.items():
                    print(kid, N, regime, {c: (f"{v:.1f}" if isinstance(v, float) else v)
                                           for c, v in cells.items()}, file=sys.stderr)
    text = ["# Benchmarks: generated kernels vs. plain SymPy paths", "",
            f"- host: {platform.machine()}, {os.cpu_count()} logical cores (shared), "
            f"Python {platform.python_version()}, numpy {np.__version__}, sympy {sp.__version__}",
            "- one thread; clock: thread CPU time; each cell the median over rounds of repeated "
            "calls for >= 10 ms; glibc malloc put in its steady large-array regime first "
            "(as peers-bench)",
            "- two regimes: *allocated* (outputs allocated inside each timed call, as "
            "peers-bench does) and *caller-provided outputs* (`out=`: the kernel alone)",
            "- C: gcc -O3 -march=native -ffp-contract=fast (no -ffast-math), both C columns "
            "built and called through cffi; `generated C` includes the per-sample "
            "singular/finiteness checks of kernels with a singular set; kernels calling "
            "sin/cos run in blocks of 64 samples (a loop computing the sin/cos values into "
            "stack arrays, then the per-sample loop)"
            + (", built against glibc's libmvec (that first loop SIMD with vectorised sin/cos)"
               if _mvec() else ""),
            "- `generated NumPy` evaluates in blocks of "
            f"{_numpy_chunk()} samples (temporaries stay in cache)",
            "- `hand NumPy` is the peers-bench reference (a); "
            "`sympy-cse C` is a plain sympy.cse + ccode loop over the declared expressions; "
            "`memory floor` allocates the outputs like the others, reads every input byte "
            "once and writes every output byte once, with no arithmetic: a kernel near it is "
            "bound by memory (and, when allocated, by the kernel zeroing fresh pages), not "
            "by its code",
            "- regenerate: `python benchmarks/run.py`", ""]
    for N in Ns:
        text += [f"## N = {N:.0e}: ns/sample", ""]
        text += _table(rows, N, "allocated", ALLOC_COLS)
        text += _table(rows, N, "caller-provided outputs", PRE_COLS)
    out = Path(args.out)
    out.write_text("\n".join(text) + _other_sections(out))
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def _other_sections(path: Path) -> str:
    """The sections other scripts keep in RESULTS.md between ``<!-- x -->`` and
    ``<!-- /x -->`` markers (e.g. benchmarks/jacobians.py), to carry over on a rewrite."""
    import re

    old = path.read_text(encoding="utf-8") if path.exists() else ""
    found = re.findall(r"\n?(<!-- ([\w-]+) -->.*?<!-- /\2 -->)", old, flags=re.S)
    return "".join("\n" + block + "\n" for block, _ in found)


def _numpy_chunk() -> int:
    from rigidsym.codegen.backends.numpy.target import NUMPY_CHUNK
    return NUMPY_CHUNK


if __name__ == "__main__":
    sys.exit(main())
