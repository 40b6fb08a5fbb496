"""Accuracy of every generated kernel against the condition of the problem.

For each kernel (the public ones, their ``<name>_with_jacobians``, the Euler-angle
variants), each float type (float64, float32) and backend (C, NumPy), and each regime of
:mod:`rigidsym.codegen.accuracy.regimes` (random points; angles to 0 and pi from both sides,
exactly 0 and pi;
rotations to the identity and to a half turn; ||omega|| and ||f|| to 0; gimbal lock of each
Euler sequence; points scaled 1e-6 .. 1e6; nearly coincident points; unit vectors a few ulps
off their constraint): exact points, rounded to the float type, handed to the kernel; the
reference is the declared formula in ``arb`` ball arithmetic at the exact point
(:mod:`rigidsym.codegen.accuracy.harness.reference`). The judge and the search are the
package's (:mod:`rigidsym.codegen.accuracy.harness`), shared with the accuracy tests and
``rigidsym audit``; this script sweeps every kernel and writes the data and the tables.

Per output ``o`` of a sample: ``err = ||computed - ref|| / ||ref||`` and the condition
number ``kappa = sum_i ||J_oi|| ||x_i|| / ||ref||`` (``J_oi``: the derivative along the
tangent space of argument ``i``; a relative perturbation ``u`` of every argument moves the
output by at most ``u kappa``). Verdict **accurate** by the accuracy rule
(:mod:`rigidsym.codegen.accuracy.rule`): ``err <= 8 u (kappa + 1)`` (the absolute floor judges
outputs that are exactly zero) **and** ``err <= max(2 e_ref, 4 u)``, ``e_ref`` the smallest error of
the textbook formula (the declaration, naively, in the same type) and of each peer that has
the operation (``harness.yardsticks``; float64), the second half measured against the truth at
the input the kernel got (the unconstrained arguments as rounded); where it fails at the
point, it is decided by the medians of the kernel's and the yardsticks' errors over a cloud
of neighbouring inputs (``harness.cloud``: one input's error is luck where ``u kappa``
dominates it). A flagged sample (NaN,
``SingularConfigurationError`` in the API) is
**expected** where the exact result is undefined, kappa >= 1e12, kappa u >= 1/8 (the
rounding of the input can reach the singular set) or the result overflows the type, else
**spurious**. A finite sample with kappa u >= 1/8, or an output below ``tiny / u`` or past
float64, is not judged (``beyond``).

Usage (from the repository root)::

    python benchmarks/accuracy.py [--kernels A,B] [--dtypes float64,float32]
        [--backends c,numpy] [--random N] [--seeds auto|0,1] [--json PATH] [--md PATH]

The full sweep of the 134 kernels takes tens of minutes on one core; ``tests/test_accuracy.py``
runs a float64 subsample.
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import asdict
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _accuracy_seeds import DATA, merged, seeds_for  # noqa: E402
from _accuracy_tables import kernel_table, markdown, rule_table, synced  # noqa: E402

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.accuracy.harness.judge import kernel_names, summary, sweep  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kernels", default="", help="comma-separated names (default: all)")
    ap.add_argument("--dtypes", default="float64,float32")
    ap.add_argument("--backends", default="c,numpy")
    ap.add_argument("--random", type=int, default=8, help="random points per kernel")
    ap.add_argument("--seeds", default="auto", help="comma-separated seeds of the regimes' "
                    "points (tests/test_bounds_fresh.py re-measures at another); 'auto': 0 "
                    "and each kernel's own seeds in the data file (its 'seeds')")
    ap.add_argument("--no-jacobians", action="store_true")
    ap.add_argument("--json", default="", help="write every row here")
    ap.add_argument("--md", default="", help="write the markdown table here")
    ap.add_argument("--losses", action="store_true", help="print only the failing rows")
    ap.add_argument("--table", default="", help="print the per-kernel table of this "
                    "data file (docs/accuracy.md) and exit")
    ap.add_argument("--rule-table", default="", help="print the table of the rule (per "
                    "kernel, type, back-end) of this data file and exit")
    ap.add_argument("--docs", default="", help="write the tables of this data file into "
                    "docs/accuracy.md and benchmarks/RESULTS.md (their marked regions) "
                    "and exit")
    ap.add_argument("--data", default="", help="write the per-kernel rows (the data "
                    "`rigidsym generate` ships for kernels.accuracy) here")
    a = ap.parse_args(argv)
    if a.rule_table:
        print(rule_table(json.loads(Path(a.rule_table).read_text(encoding="utf-8"))), end="")
        return 0
    if a.docs:
        from rigidsym.core.files import write_atomic

        tables = synced(DATA.parents[1], json.loads(Path(a.docs).read_text("utf-8")))
        for rel, text in tables.items():
            write_atomic(DATA.parents[1] / rel, text)
        return 0
    if a.table:
        print(kernel_table(json.loads(Path(a.table).read_text(encoding="utf-8"))), end="")
        return 0
    names = a.kernels.split(",") if a.kernels else kernel_names(not a.no_jacobians)
    dtypes = [np.dtype(d).type for d in a.dtypes.split(",")]
    backends = a.backends.split(",")
    if "c" in backends and K.use_backend("c") != "c":
        backends.remove("c")

    def progress(name, rows):
        bad = [r for r in rows if r.kernel == name and not r.accurate]
        print(f"{name}: {'accurate' if not bad else f'{len(bad)} losing rows'}", flush=True)
        for r in bad:
            print(f"   {r.dtype} {r.backend} {r.regime}: rule {r.rule_ratio:.3g} vs e_ref "
                  f"{r.ref_ratio:.3g} ({r.ref_source}) ratio {r.worst_ratio:.3g} err "
                  f"{r.err:.2g} kappa {r.kappa:.2g} spurious {len(r.spurious)} at "
                  f"{(r.spurious or [r.worst_point])[0]}", flush=True)

    data_path = Path(a.data) if a.data else DATA
    old = json.loads(data_path.read_text(encoding="utf-8")) if data_path.is_file() else {}
    rows = []
    for name in names:
        rows += sweep([name], dtypes, backends, a.random, progress=progress,
                      seeds=seeds_for(name, old, a.seeds))
    if a.json:
        Path(a.json).write_text(json.dumps([asdict(r) for r in rows], indent=1))
    if a.data:
        from _accuracy_thresholds import thresholds

        from rigidsym.core.files import write_atomic

        write_atomic(Path(a.data), json.dumps(merged(old, summary(rows, thresholds())),
                                              indent=1, sort_keys=True) + "\n")
    if a.md:
        Path(a.md).write_text(markdown([r for r in rows if not a.losses or not r.accurate]))
    return 0 if all(r.accurate for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
