"""The accuracy bound of the C target's float functions, per kernel (issue 53 item 4).

    python benchmarks/c_float_bounds.py [--kernel NAME ...] [--module M.py] [--seeds 0,1]
        [--random N] [--write]

Generates the C target of the named kernels (and their Jacobian twins), builds it with gcc,
and hands each ``rigidsym_c_<kernel>_f32_batch`` function to the accuracy harness
(``benchmarks/accuracy.py``: its float32 regimes, the arb reference at the exact point, the
condition number ``kappa``) in place of the package's kernels. Per kernel, the worst
``err / (u (kappa + 1))`` over every regime and seed (``u = 2^-24``, ``err`` the normwise
relative error of an output) is the measured bound; the bound the header states is that,
doubled and rounded up to 1, 1.5, 2, 3, 5 times a power of ten (at least 1), so that fresh
points do not reach it (``tests/test_c_target.py`` checks them on other seeds).

``--write`` records ``{kernel: {hash, bound, measured, ...}}``: the book's kernels into
``src/rigidsym/codegen/backends/c/float_bounds.json`` (the generator reads it), a user
module's into ``M.float_bounds.json`` beside it (``rigidsym generate --target c --module
M.py`` reads that). A bound is used only while the kernel's declaration hash is the one
measured. Needs gcc.
"""

from __future__ import annotations

import argparse
import ctypes
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from rigidsym.codegen.accuracy.harness import judge as A  # noqa: E402
from rigidsym.codegen.accuracy.harness import reference as R  # noqa: E402
from rigidsym.codegen.backends.c.target import FLOAT_BOUNDS, generate_c  # noqa: E402

STRICT = ["-std=c99", "-Wall", "-Wextra", "-O2"]


def stated(measured: float) -> float:
    """The bound a header states for a measured worst: twice it, rounded up to 1, 1.5, 2,
    3 or 5 times a power of ten, at least 1."""
    want = max(1.0, 2.0 * measured)
    e = math.floor(math.log10(want))
    for m in (1.0, 1.5, 2.0, 3.0, 5.0, 10.0):
        if m * 10.0**e >= want * (1 - 1e-12):
            return m * 10.0**e
    raise AssertionError(want)


def build(kernels, tmp: Path, where="rigidsym.derivations.kernels_spec"):
    """The C target of ``kernels`` built as a shared library: (ctypes library, codes)."""
    from rigidsym.codegen.generator import compile_many

    codes = compile_many(kernels, plan32=False)
    out = tmp / "k"
    out.mkdir()
    for rel, text in generate_c(codes, where).items():
        (out / rel).write_text(text, encoding="utf-8")
    so = tmp / "lib.so"
    subprocess.run(["gcc", *STRICT, "-shared", "-fPIC", *map(str, sorted(out.glob("*.c"))),
                    "-o", str(so), "-lm"], check=True)
    return ctypes.CDLL(str(so)), codes


def runner(lib):
    """A runner for ``accuracy.judge``: the float batch function of the C target."""
    fp = ctypes.POINTER(ctypes.c_float)

    def run(name, arrays, dtype, backend):
        assert np.dtype(dtype) == np.float32
        k = R.kernel_of(name)
        n = arrays[0].shape[0]
        ins = [np.ascontiguousarray(a, np.float32) for a in arrays]
        outs = [np.zeros((n, o.size), np.float32) for o in k.outputs]
        fn = getattr(lib, f"rigidsym_c_{name}_f32_batch")
        fn.restype = ctypes.c_int
        fn(ctypes.c_size_t(n), *[a.ctypes.data_as(fp) for a in ins],
           *[o.ctypes.data_as(fp) for o in outs], None)
        return np.concatenate(outs, axis=1).astype(np.float64)
    return run


def worst(run, name: str, seeds=(0,), n_random: int = 8):
    """The worst ``err / (u (kappa + 1))`` of kernel ``name`` run by ``run`` over the
    harness's float32 regimes drawn with ``seeds``, and the harness's rows."""
    rows = A.sweep([name], [np.float32], ["c"], n_random=n_random, runner=run, seeds=seeds)
    return 8 * max(r.worst_ratio for r in rows), rows


def register(kernels) -> None:
    """Let the harness's reference see user kernels (and their twins) by name."""
    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels

    book = getattr(R, "_book_kernel_of", R.kernel_of)
    R._book_kernel_of = book
    extra = {k.name: k for k in kernels}
    extra.update({j.name: j for j in jacobian_kernels(list(kernels))})

    def kernel_of(name):
        return extra[name] if name in extra else book(name)
    R.kernel_of = kernel_of
    R.functions.cache_clear()


def measure(kernels, seeds=(0,), n_random: int = 8, where=None,
            progress: bool = False) -> dict:
    """``{kernel or twin: {hash, measured, bound, samples, spurious, worst_regime}}`` of the
    C target's float functions over the harness's float32 regimes."""
    if where is not None:
        register(kernels)
    with tempfile.TemporaryDirectory() as tmp:
        lib, codes = build(kernels, Path(tmp), where or "rigidsym.derivations.kernels_spec")
        run = runner(lib)
        out = {}
        for kc in codes:
            name = kc.kernel.name
            try:
                measured, rows = worst(run, name, seeds, n_random)
            except Exception as exc:  # noqa: BLE001  (the harness's own limit: said, skipped)
                print(f"{name}: not measured ({type(exc).__name__}: {exc})", flush=True)
                continue
            worst_row = max(rows, key=lambda r: r.worst_ratio)
            out[name] = {"hash": kc.hash, "measured": float(f"{measured:.3g}"),
                         "bound": stated(measured), "samples": sum(r.samples for r in rows),
                         "spurious": sum(len(r.spurious) for r in rows),
                         "worst_regime": worst_row.regime, "seeds": list(seeds)}
            if progress:
                print(f"{name:48s} measured {measured:8.3g}  bound {stated(measured):6g}",
                      flush=True)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kernel", action="append", default=[])
    ap.add_argument("--module")
    ap.add_argument("--seeds", default="0,1")
    ap.add_argument("--random", type=int, default=8)
    ap.add_argument("--write", action="store_true")
    a = ap.parse_args(argv)
    from rigidsym.codegen.usergen import select_kernels

    kernels, where = select_kernels([a.module] if a.module else None, a.kernel or None)
    if a.module:
        kernels = [k for k in kernels if where[k.name] != "rigidsym.derivations.kernels_spec"]
    seeds = tuple(int(s) for s in a.seeds.split(","))
    got = measure(kernels, seeds, a.random, where if a.module else None, progress=True)
    for name, r in got.items():
        print(f"{name:48s} {r['samples']} samples, worst in {r['worst_regime']}, "
              f"{r['spurious']} spurious")
    if a.write:
        path = Path(a.module).with_suffix(".float_bounds.json") if a.module else FLOAT_BOUNDS
        old = json.loads(path.read_text()) if path.is_file() else {}
        old.update(got)
        path.write_text("{\n" + ",\n".join(f" {json.dumps(k)}: {json.dumps(v)}"
                                           for k, v in sorted(old.items())) + "\n}\n")
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
