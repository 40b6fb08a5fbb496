"""The measured accuracy bound of the C target's float functions, per kernel.

Builds the C target of some kernels (and their Jacobian twins) with the C compiler and hands
each ``rigidsym_c_<kernel>_f32_batch`` function to the accuracy harness
(:mod:`rigidsym.codegen.accuracy.harness`: its float32 regimes, the arb reference at the exact
point, the condition number ``kappa``) in place of the package's kernels. Per kernel, the
worst ``err / (u (kappa + 1))`` over every regime and seed (``u = 2^-24``, ``err`` the
normwise relative error of an output) is the measured bound; the bound a header states is
that, doubled and rounded up to 1, 1.5, 2, 3, 5 times a power of ten (at least 1), so that
fresh points do not reach it (``tests/test_c_target.py`` checks them on other seeds).

``rigidsym generate --target c --module M.py`` measures the module's kernels with
:func:`measure_codes` (``--no-measure`` skips it); ``benchmarks/c_float_bounds.py`` measures
the book's and records them. It takes kernels compiled by its caller
(:func:`rigidsym.codegen.generator.compile_many`): the generator sits above the accuracy
package, which it uses. docs/c-api.md ("Each header states its float functions' bound").
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np

from rigidsym.codegen.backends.c.target import stated

__all__ = ["STRICT", "SEEDS", "N_RANDOM", "compiler", "stated", "build_codes", "runner",
           "worst", "register", "measure_codes"]

#: the flags the measured library is built with (no -march: the bound is the portable code's)
STRICT = ["-std=c99", "-Wall", "-Wextra", "-O2"]
#: the harness's seeds and random points per regime a stated bound is measured on
SEEDS = (0, 1)
N_RANDOM = 8


def compiler() -> str | None:
    """The C compiler the measurement builds with: ``$CC``, else gcc, else cc; ``None`` when
    there is none on ``PATH``."""
    for name in (os.environ.get("CC"), "gcc", "cc"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def build_codes(codes, where, tmp: Path):
    """The C target of compiled kernels ``codes`` (:func:`~rigidsym.codegen.generator.
    compile_many`; ``where``: a module name or ``{kernel: module}``) built in ``tmp`` as a
    shared library, loaded with ctypes.

    Raises:
        FileNotFoundError: no C compiler (:func:`compiler`).
        subprocess.CalledProcessError: the compiler failed.
    """
    from rigidsym.codegen.backends.c.target import generate_c

    cc = compiler()
    if cc is None:
        raise FileNotFoundError("no C compiler (gcc or cc, or $CC) on PATH")
    out = tmp / "k"
    out.mkdir()
    for rel, text in generate_c(codes, where, bounds={}).items():
        (out / rel).write_text(text, encoding="utf-8")
    so = tmp / "lib.so"
    subprocess.run([cc, *STRICT, "-shared", "-fPIC", *map(str, sorted(out.glob("*.c"))),
                    "-o", str(so), "-lm"], check=True, capture_output=True)
    return ctypes.CDLL(str(so))


def runner(lib):
    """A runner for the harness's ``judge``: the float batch function of the C target in
    ``lib`` (float32 arrays in, the outputs concatenated as float64 out)."""
    from rigidsym.codegen.accuracy.harness import reference as R

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


def worst(run, name: str, seeds=(0,), n_random: int = N_RANDOM):
    """The worst ``err / (u (kappa + 1))`` of kernel ``name`` run by ``run`` over the
    harness's float32 regimes drawn with ``seeds``, and the harness's rows."""
    from rigidsym.codegen.accuracy.harness import judge as A

    rows = A.sweep([name], [np.float32], ["c"], n_random=n_random, runner=run, seeds=seeds)
    return 8 * max(r.worst_ratio for r in rows), rows


def register(kernels) -> None:
    """Let the harness's reference see user kernels (and their twins) by name."""
    from rigidsym.codegen.accuracy.harness.reference import register_kernels

    register_kernels(kernels)


def _entry(kc, measured: float, rows, seeds) -> dict:
    worst_row = max(rows, key=lambda r: r.worst_ratio)
    return {"hash": kc.hash, "measured": float(f"{measured:.3g}"),
            "bound": stated(measured), "samples": sum(r.samples for r in rows),
            "spurious": sum(len(r.spurious) for r in rows),
            "worst_regime": worst_row.regime, "seeds": list(seeds)}


def measure_codes(codes, where, seeds=SEEDS, n_random: int = N_RANDOM, only=None,
                  say=None) -> dict:
    """``{kernel or twin: {hash, measured, bound, samples, spurious, worst_regime, seeds}}``
    of the float functions of compiled kernels ``codes`` (those named in ``only``, default
    all) over the harness's float32 regimes; ``where`` as for :func:`build_codes`. A kernel
    the harness cannot judge is left out and said through ``say`` (a ``print``-like
    callable; default silent), as is each measured one.

    Raises:
        FileNotFoundError: no C compiler.
    """
    say = say or (lambda *_: None)
    want = [kc for kc in codes if only is None or kc.kernel.name in only]
    if not want:
        return {}
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        run = runner(build_codes(codes, where, Path(tmp)))
        for kc in want:
            name = kc.kernel.name
            try:
                measured, rows = worst(run, name, seeds, n_random)
            except Exception as exc:  # noqa: BLE001  (the harness's own limit: said, skipped)
                say(f"{name}: not measured ({type(exc).__name__}: {exc})")
                continue
            out[name] = _entry(kc, measured, rows, seeds)
            say(f"{name:48s} measured {measured:8.3g}  bound {stated(measured):6g}")
    return out
