"""C kernels built several ways from the same generated C, side by side in one run.

``--trig`` (default): the trig kernels with three sin/cos, the package's (the generated
header's own vectorised ``rigidsym_sin``/``rigidsym_cos``), glibc's libmvec
(``RIGIDSYM_LIBMVEC=1``) and libm's scalar ``sin``/``cos`` (``-DRIGIDSYM_TRIG_LIBM``),
float64, median ms and median ratio to libmvec. ``--f32``: float32 kernels compiled without
FMA contraction (the package's: ``RIGIDSYM_F32_BEGIN`` in the generated header) against the
same C contracted (``-DRIGIDSYM_F32_CONTRACT``), and float64 time / float32 time. The other
builds go into the user cache: ``--trig`` on the one path the package's module runs its trig
kernels on (``RIGIDSYM_PATHS``: a single path builds in a third of the time), ``--f32`` on
all the package's paths. N = 1e6, one thread, interleaved rounds.

Usage (from the repository root)::

    python benchmarks/trig_speed.py [--f32] [--rounds 7] [--n 1000000]
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

from accuracy_speed import inputs, timer  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.accuracy.harness import reference as R  # noqa: E402
from rigidsym.core.config import generated_dir  # noqa: E402
from rigidsym.kernels.cbuild import driver as _build  # noqa: E402

TRIG = ["rotation_from_natural_invariants", "screw_axis_point", "N_matrix",
        "euler_angle_rates_zxz_body", "rotation_from_rotation_vector"]
F32 = ["rotation_from_euler_rodrigues", "instant_screw_axis", "wrench_axis",
       "newton_euler_wrench", "screw_axis_point"]


def variant(tmp: Path, label: str, env: dict[str, str]):
    """The package's generated directory copied to ``tmp/label`` and loaded (compiled on the
    package's path) with ``env`` set."""
    d = tmp / label
    shutil.copytree(generated_dir(), d, ignore=shutil.ignore_patterns("notebooks", "report"))
    env = {"RIGIDSYM_PATHS": K.build_info()["path"].removeprefix("x86-64-"), **env}
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        ns = K.load(d)
        ns.batch_function(TRIG[0], "c", threads=1)     # build now, under env
        return ns
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def interleaved(name: str, runs: list, a) -> list[list[float]]:
    """Seconds of each ``(namespace, dtype)`` of ``runs`` on ``name``'s inputs, ``a.rounds``
    interleaved rounds after one warm call each."""
    k = R.kernel_of(name)
    fs = []
    for space, dt in runs:
        arrays = inputs(name, a.n, dt)
        outs = [np.empty((a.n,) + o.shape, dtype=dt) for o in k.outputs]
        fs.append(timer(space.batch_function(name, "c", threads=1, dtype=dt), arrays, outs))
    for f in fs:
        f()
    ts: list[list[float]] = [[] for _ in fs]
    for _ in range(a.rounds):
        for f, t in zip(fs, ts, strict=True):
            t.append(f())
    return ts


def ratio(t: list[float], base: list[float]) -> float:
    return statistics.median(x / y for x, y in zip(t, base, strict=True))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--f32", action="store_true", help="float32 with and without contraction")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--n", type=int, default=10**6)
    a = ap.parse_args(argv)
    K.use_backend("c")
    path = K.build_info()["path"]
    with tempfile.TemporaryDirectory() as tmp:
        if a.f32:
            # every path of the package's: its kernels without sin/cos run on x86-64-v3
            fma = variant(Path(tmp), "fma", {"RIGIDSYM_CFLAGS": " ".join(
                [*_build.KERNEL_FLAGS, "-DRIGIDSYM_F32_CONTRACT"]), "RIGIDSYM_PATHS": ",".join(
                    p.removeprefix("x86-64-") for p in K.build_info()["paths"])})
            print(f"N = {a.n:.0e}, one thread, path {path}, {a.rounds} interleaved rounds, "
                  "median ms\n\n| kernel | float64 | float32 contracted | float32 "
                  "fp-contract=off | off / contracted | float64 / float32 off |\n"
                  "|---|---|---|---|---|---|")
            for name in F32:
                ts = interleaved(name, [(K, np.float64), (fma, np.float32),
                                        (K, np.float32)], a)
                med = [f"{1e3 * statistics.median(t):.2f}" for t in ts]
                print(f"| `{name}` | {' | '.join(med)} | {ratio(ts[2], ts[1]):.2f} | "
                      f"{ratio(ts[0], ts[2]):.2f} |", flush=True)
            return 0
        flags = " ".join([*_build.KERNEL_FLAGS, "-DRIGIDSYM_TRIG_LIBM"])
        spaces = {"libmvec": variant(Path(tmp), "mvec", {"RIGIDSYM_LIBMVEC": "1"}),
                  "libm scalar": variant(Path(tmp), "libm", {"RIGIDSYM_CFLAGS": flags}),
                  "rigidsym": K}
        print(f"N = {a.n:.0e}, one thread, float64, path {path}, {a.rounds} interleaved "
              "rounds, median ms (ratio to libmvec)\n")
        print("| kernel | " + " | ".join(spaces) + " |\n|---|" + "---|" * len(spaces))
        for name in TRIG:
            ts = interleaved(name, [(s, np.float64) for s in spaces.values()], a)
            cells = [f"{1e3 * statistics.median(t):.2f} ({ratio(t, ts[0]):.2f})" for t in ts]
            print(f"| `{name}` | " + " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
