"""Trig kernels with three sin/cos, side by side in one run (issue 37, the C back-end).

The package's C kernels (the generated header's own vectorised ``rigidsym_sin``/
``rigidsym_cos``) against the same generated C built twice more into the user cache: with
glibc's libmvec (``RIGIDSYM_LIBMVEC=1``) and with libm's scalar ``sin``/``cos``
(``-DRIGIDSYM_TRIG_LIBM`` in ``RIGIDSYM_CFLAGS``), both on the one path the package's module
runs (``RIGIDSYM_PATHS``: a single path builds in a third of the time). N = 1e6, one thread,
float64, interleaved rounds, median time and median ratio to libmvec.

Usage (from the repository root)::

    python benchmarks/trig_speed.py [--rounds 7] [--n 1000000]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

os.environ.setdefault("OMP_NUM_THREADS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent))

import _accuracy_ref as R  # noqa: E402
from accuracy_speed import inputs, timer  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym._config import generated_dir  # noqa: E402
from rigidsym.kernels import _build  # noqa: E402

KERNELS = ["rotation_from_natural_invariants", "screw_axis_point", "N_matrix",
           "euler_angle_rates_zxz_body", "rotation_from_rotation_vector"]


def variant(tmp: Path, label: str, env: dict[str, str]):
    """The package's generated directory copied to ``tmp/label`` and loaded (compiled) with
    ``env`` set."""
    d = tmp / label
    shutil.copytree(generated_dir(), d, ignore=shutil.ignore_patterns("notebooks", "report"))
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        ns = K.load(d)
        ns.batch_function(KERNELS[0], "c", threads=1)     # build now, under env
        return ns
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--n", type=int, default=10**6)
    a = ap.parse_args(argv)
    K.use_backend("c")
    path = K.build_info()["path"]
    suffix = path.removeprefix("x86-64-")
    flags = " ".join([*_build.KERNEL_FLAGS, "-DRIGIDSYM_TRIG_LIBM"])
    with tempfile.TemporaryDirectory() as tmp:
        spaces = {"libmvec": variant(Path(tmp), "mvec", {"RIGIDSYM_LIBMVEC": "1",
                                                          "RIGIDSYM_PATHS": suffix}),
                  "libm scalar": variant(Path(tmp), "libm", {"RIGIDSYM_CFLAGS": flags,
                                                              "RIGIDSYM_PATHS": suffix}),
                  "rigidsym": K}
        print(f"N = {a.n:.0e}, one thread, float64, path {path}, {a.rounds} interleaved "
              "rounds, median ms (ratio to libmvec)\n")
        print("| kernel | " + " | ".join(spaces) + " |\n|---|" + "---|" * len(spaces))
        for name in KERNELS:
            k = R.kernel_of(name)
            arrays = inputs(name, a.n, np.float64)
            outs = [np.empty((a.n,) + o.shape) for o in k.outputs]
            fs = [timer(s.batch_function(name, "c", threads=1), arrays, outs)
                  for s in spaces.values()]
            for f in fs:
                f()
            ts: list[list[float]] = [[] for _ in fs]
            for _ in range(a.rounds):
                for f, t in zip(fs, ts, strict=True):
                    t.append(f())
            cells = [f"{1e3 * statistics.median(t):.2f} "
                     f"({statistics.median(x / y for x, y in zip(t, ts[0], strict=True)):.2f})"
                     for t in ts]
            print(f"| `{name}` | " + " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
