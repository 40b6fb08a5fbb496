"""rigidsym's generated C kernels as an extra column of ../shared/peers-bench (``--extra``).

    python run_all.py --extra /path/to/rigidsym/benchmarks/peers_adapter.py

``setup(ctx)`` compiles ``generated/c/*.c`` with the harness's compiler and flags into
``ctx["build_dir"]`` (plain shared library, no cffi needed in the harness's environment), the
same way as ``rigidsym build-c``: the flags of ``rigidsym.kernels._build`` (``CFLAGS`` added to
the harness's ``-O3 -march=native``) and its build variants, libmvec's vectorised sin/cos
first (``MVEC_FLAGS``, ``-lmvec``; glibc only, ``RIGIDSYM_LIBMVEC=0`` turns it off), the plain
build as the fallback; ``VARIANT`` names the one built;
each K is one ctypes call of the batch function ``rigidsym_<kernel>`` (no validation, the
equivalent of ``check=False``), outputs allocated inside the call like every other peer.

K1 rotation_from_euler_rodrigues, K2 rotation_from_natural_invariants, K3 screw_axis_point,
K4 instant_screw_point_pitch (ISA point and pitch), K5 N_matrix, K6 newton_euler_residual
(``newton_euler_wrench(...) - [n; f]``).
"""

from __future__ import annotations

import ctypes
import hashlib
import json
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT / "src") not in sys.path:
    sys.path.insert(0, str(ROOT / "src"))

from rigidsym.kernels._build import CFLAGS, MVEC_FLAGS, build_variants  # noqa: E402

NAME = "rigidsym-c"
PER_SAMPLE_LOOP = False
GEN = ROOT / "generated"
BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_residual"}
_META = {k["name"]: k for k in json.loads((GEN / "kernels.json").read_text())["kernels"]}
OPS = {kid: _META[name]["ops"] for kid, name in BENCH.items() if name in _META}
KERNELS: dict = {}
VARIANT = ""


def _flags(cflags: list[str]) -> list[str]:
    """The harness's flags plus cbuild's (``-std=c99 -ffp-contract=fast``), no duplicates."""
    return list(cflags) + [f for f in CFLAGS if f not in cflags]


def _build(build_dir: Path, cc: str, cflags: list[str]) -> tuple[Path, str]:
    """Compile (cached by sources and flags); returns the library and its variant name."""
    global VARIANT
    srcs = [GEN / "c" / f"{name}.c" for name in BENCH.values() if name in _META]
    last = None
    for flags, libs in build_variants(_flags(cflags)):
        h = hashlib.sha256(" ".join([cc, *flags, *libs]).encode())
        for p in sorted((GEN / "c").glob("*")):
            h.update(p.read_bytes())
        so = Path(build_dir) / f"librigidsym_{h.hexdigest()[:12]}.so"
        VARIANT = "libmvec" if MVEC_FLAGS[0] in flags else "plain"
        if so.exists():
            return so, VARIANT
        so.parent.mkdir(parents=True, exist_ok=True)
        try:
            subprocess.run([cc, *flags, "-fPIC", "-shared", *map(str, srcs), "-I",
                            str(GEN / "c"), "-o", str(so), *(f"-l{x}" for x in libs)],
                           check=True, capture_output=True)
        except (subprocess.CalledProcessError, OSError) as exc:  # next variant: fallback
            last = exc
            continue
        return so, VARIANT
    raise last


def _wrap(lib, name: str):
    meta = _META[name]
    fn = getattr(lib, f"rigidsym_{name}")
    fn.argtypes = [ctypes.c_int64] + [ctypes.c_void_p] * (len(meta["args"])
                                                          + len(meta["outputs"]))
    fn.restype = ctypes.c_int64
    shapes = [tuple(o["shape"]) for o in meta["outputs"]]

    def call(*xs):
        n = xs[0].shape[0]
        outs = [np.empty((n,) + s) for s in shapes]
        fn(n, *[x.ctypes.data for x in xs], *[o.ctypes.data for o in outs])
        return outs[0] if len(outs) == 1 else tuple(outs)
    call.__name__ = name
    return call


def setup(ctx=None) -> None:
    """Compile (cached) and bind K1..K6; ``ctx`` as passed by the peers-bench harness."""
    ctx = ctx or {}
    build_dir = Path(ctx.get("build_dir") or (ROOT / "benchmarks" / ".build"))
    cflags = list(ctx.get("cflags") or ["-O3", "-march=native"])
    so, _ = _build(build_dir, ctx.get("cc", "gcc"), cflags)
    lib = ctypes.CDLL(str(so))
    for kid, name in BENCH.items():
        if name in _META:
            KERNELS[kid] = _wrap(lib, name)
