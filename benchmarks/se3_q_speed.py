"""Speed of the SE(3) kernels whose forms were rewritten (Barfoot's ``Q`` and ``J_l(w) v``
without their cancellation): each kernel of a git revision (default: d987a31e, before) and
of this checkout side by side in one run.

Loads ``generated/`` of ``--rev`` with ``kernels.load`` beside the package's kernels (as
``benchmarks/accuracy_speed.py`` does) and times the batch function of each kernel, C at
N = 1e6 on one thread and NumPy at N = 2e5, float64 and float32, in interleaved rounds
(before, after, before, ...): the median over rounds of after/before. Thread CPU time
around one call; the machine is shared, so the interleaved medians are what to read.
``rotation_vector_left_jacobian`` (unchanged) is the control.

Usage (from the repository root)::

    python benchmarks/se3_q_speed.py [--rev d987a31e] [--rounds 9]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import accuracy_speed as S  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.accuracy.harness import reference as R  # noqa: E402

NAMES = ["exponential_coordinates_left_jacobian", "exponential_coordinates_left_jacobian_inverse",
         "transform_from_exponential_coordinates",
         "exponential_coordinates_left_jacobian_with_jacobians",
         "exponential_coordinates_left_jacobian_inverse_with_jacobians",
         "transform_from_exponential_coordinates_with_jacobians",
         "rotation_vector_left_jacobian"]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rev", default="d987a31e")
    ap.add_argument("--rounds", type=int, default=9)
    a = ap.parse_args(argv)
    K.use_backend("c")
    with tempfile.TemporaryDirectory() as tmp:
        old = K.load(S.old_generated(a.rev, Path(tmp)))
        print(f"| kernel | back-end | type | N | {a.rev} ms | now ms | now/{a.rev} |\n"
              "|---|---|---|---|---|---|---|")
        for be, n in (("c", 10**6), ("numpy", 2 * 10**5)):
            for dt in (np.float64, np.float32):
                for name in NAMES:
                    if be == "numpy" and name.endswith("_with_jacobians"):
                        continue
                    k = R.kernel_of(name)
                    arrays = S.inputs(name, n, dt)
                    outs = [np.empty((n,) + o.shape, dtype=dt) for o in k.outputs]
                    kw = {"threads": 1} if be == "c" else {}
                    fs = [S.timer(s.batch_function(name, be, dtype=dt, **kw), arrays, outs)
                          for s in (old, K)]
                    for f in fs:      # warm
                        f()
                    ts: list[list[float]] = [[], []]
                    for _ in range(a.rounds):
                        for f, t in zip(fs, ts, strict=True):
                            t.append(f())
                    r = statistics.median(b / o for o, b in zip(*ts, strict=True))
                    print(f"| `{name}` | {be} | {np.dtype(dt).name} | {n:.0e} | "
                          f"{1e3 * statistics.median(ts[0]):.2f} | "
                          f"{1e3 * statistics.median(ts[1]):.2f} | {r:.3f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
