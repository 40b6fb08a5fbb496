"""Which kernels run their float64 lanes across samples (``VEC_F64``): every kernel whose C
differs between two generated directories, timed in both builds side by side.

    python benchmarks/vec_lanes_select.py BASELINE/generated CANDIDATE/generated [--runs 2]
                                         [--kernels NAME ...]

BASELINE is a generation as committed; CANDIDATE the same with ``VEC_F64`` (in
``rigidsym.codegen.backends.extension.target``) temporarily set to every kernel whose vector
text is ``vectorisable`` (``rigidsym generate`` writes into the checkout's ``generated/``: copy
it aside, then ``git checkout generated``). Both directories are built as the wheel builds
them (``rigidsym.kernels.cbuild.driver``, the default paths), loaded into one process, and
each differing kernel's ``batch`` is timed on the same inputs, the two builds interleaved
(thread CPU time, minimum over rounds, float64, one thread) at N = 4096 (in cache) and
N = 2e5; the outputs' bytes are compared as well. Prints per kernel the ratio
candidate / baseline in each regime and in each run, and the kernels faster in both regimes
in every run (ratio < ``--below``): the list ``VEC_F64`` holds, measured on an AVX2 CPU (the
path the vector lanes compile on). ``--kernels`` names the kernels to time where the two
generations differ in their common header only (the lanes turned on for another build path
there, ``rigidsym_common.h``). Standard library, NumPy and the build driver only.
"""

from __future__ import annotations

import argparse
import filecmp
import importlib.util
import json
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

import numpy as np

from rigidsym.kernels.cbuild import driver

SIZES = ((4096, 150), (200_000, 9))


def build(gen: Path, out: Path):
    """The extension module of ``gen`` (built into ``out`` once), imported under its path."""
    so = out / ("_ckernels" + sysconfig.get_config_var("EXT_SUFFIX"))
    if not so.exists():
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryDirectory(dir=out) as tmp:
            driver.build(gen, Path(tmp) / so.name, driver.configure(native=False), Path(tmp))
            (Path(tmp) / so.name).replace(so)
    spec = importlib.util.spec_from_file_location("_ckernels", so)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def differing(base: Path, cand: Path) -> list[str]:
    """The kernels whose C source differs between the two generations."""
    return sorted(p.stem for p in (cand / "c").glob("*.c")
                  if not p.stem.startswith("rigidsym_")
                  and not filecmp.cmp(p, base / "c" / p.name, shallow=False))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("baseline", type=Path)
    ap.add_argument("candidate", type=Path)
    ap.add_argument("--runs", type=int, default=2)
    ap.add_argument("--below", type=float, default=0.97)
    ap.add_argument("--build-dir", type=Path, default=Path(tempfile.gettempdir()) / "vec_select")
    ap.add_argument("--kernels", nargs="+", default=None,
                    help="the kernels to time (default: those whose C source differs)")
    args = ap.parse_args(argv)
    names = sorted(args.kernels) if args.kernels else differing(args.baseline, args.candidate)
    meta = {k["name"]: k for k in
            json.loads((args.candidate / "kernels.json").read_text())["kernels"]}
    base = build(args.baseline, args.build_dir / "baseline")
    cand = build(args.candidate, args.build_dir / "candidate")
    print(f"{len(names)} kernels differ; path {base.path} / {cand.path}", flush=True)
    worst: dict[str, list[float]] = {n: [0.0, 0.0] for n in names}
    rng = np.random.default_rng(0)
    for run in range(args.runs):
        for name in names:
            cells = []
            for i, (n, rounds) in enumerate(SIZES):
                xs = [np.ascontiguousarray(rng.standard_normal((n, *a["shape"])))
                      for a in meta[name]["args"]]
                outs = {m: [np.zeros((n, *o["shape"])) for o in meta[name]["outputs"]]
                        for m in ("b", "c")}
                best = {"b": float("inf"), "c": float("inf")}
                for _ in range(rounds):
                    for tag, mod in (("b", base), ("c", cand)):
                        k = mod.kernels.index(name)
                        t0 = time.thread_time_ns()
                        mod.batch(k, False, n, 1, *xs, *outs[tag])
                        best[tag] = min(best[tag], (time.thread_time_ns() - t0) / n)
                if any(a.tobytes() != b.tobytes() for a, b in zip(outs["b"], outs["c"],
                                                                    strict=True)):
                    print(f"{name}: outputs differ at N = {n}", file=sys.stderr)
                    return 1
                ratio = best["c"] / best["b"]
                worst[name][i] = max(worst[name][i], ratio)
                cells.append(f"N={n}: {best['b']:.2f} -> {best['c']:.2f} ns ({ratio:.2f})")
            print(f"run {run + 1} {name:46s} " + "   ".join(cells), flush=True)
    faster = [n for n, (a, b) in worst.items() if a < args.below and b < args.below]
    print(f"faster in both regimes in every run ({len(faster)}):")
    print(json.dumps(faster))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
