"""The accuracy bound of the C target's float functions, per kernel.

    python benchmarks/c_float_bounds.py [--kernel NAME ...] [--module M.py] [--seeds 0,1]
        [--random N] [--write]

The measuring is the package's (:mod:`rigidsym.codegen.accuracy.float_measure`, which
``rigidsym generate --target c --module M.py`` runs itself); this script records the book's.
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
import json
from pathlib import Path

from rigidsym.codegen.accuracy.float_measure import (  # noqa: F401  (the package's)
    N_RANDOM,
    STRICT,
    build_codes,
    measure_codes,
    register,
    runner,
    stated,
    worst,
)
from rigidsym.codegen.backends.c.target import FLOAT_BOUNDS
from rigidsym.codegen.generator import compile_many


def build(kernels, tmp: Path, where="rigidsym.derivations.kernels_spec"):
    """The C target of ``kernels`` built as a shared library: (ctypes library, codes)."""
    codes = compile_many(kernels, plan32=False)
    return build_codes(codes, where, tmp), codes


def measure(kernels, seeds=(0,), n_random: int = N_RANDOM, where=None,
            progress: bool = False) -> dict:
    """The package's ``measure_codes`` of ``kernels``, compiled here; ``where`` given: user
    kernels, registered with the harness first (``None``: the book's)."""
    if where is not None:
        register(kernels)
    codes = compile_many(kernels, plan32=False)
    return measure_codes(codes, where or "rigidsym.derivations.kernels_spec", seeds,
                         n_random, say=(lambda m: print(m, flush=True)) if progress else None)


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
