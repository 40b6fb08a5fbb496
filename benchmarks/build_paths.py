"""The default (portable, dispatched) build against a ``-march=native`` build, K1-K6.

    python benchmarks/build_paths.py [--n 1000000] [--rounds 15] [--results]

The six kernels' generated C (copied from ``generated/c``, with the extension's own C
rendered for them) is built by the package's driver three ways and loaded in one process:
the default build the wheel ships (x86-64-v2, v3 and v4 objects, the dispatcher's choice;
``RIGIDSYM_DISPATCH=baseline`` times the baseline), the native build (``-march=native``, as
``rigidsym build-c --native``) and x86-64-v3 alone (what a CPU without AVX-512 runs; the
AVX-512 path is built because it measured faster than it). Each kernel is timed
alternately on them, one thread, caller-provided outputs, the same inputs; a cell is the
minimum over rounds of one call at N samples (ns/sample), timed by the thread's CPU time as
the peers benchmark does (on two cores shared with other jobs, wall time varies severalfold
from preemption alone). K1 rotation_from_euler_rodrigues, K2
rotation_from_natural_invariants, K3 screw_axis_point, K4 instant_screw_point_pitch,
K5 N_matrix, K6 newton_euler_wrench.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT / "src") not in sys.path:
    sys.path.insert(0, str(ROOT / "src"))

from rigidsym.core.draws import draw  # noqa: E402
from rigidsym.kernels.cbuild import driver as _build  # noqa: E402
from rigidsym.kernels.cbuild import extension as _ext  # noqa: E402

BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_wrench"}
#: the target of the default build within this factor of native on every kernel
TARGET = 1.10


def inputs(meta: dict, n: int, rng) -> list[np.ndarray]:
    """Valid inputs of every argument kind (unit vectors, angles away from 0 and pi,
    rotations, positive masses)."""
    out = []
    for a in meta["args"]:
        shape = tuple(a["shape"])
        if a["name"] == "m":
            v = rng.uniform(0.5, 5.0, n)
        else:
            v = draw(a["kind"], (n,) + shape, rng, phi=(0.2, 3.0), angle=(0.2, np.pi - 0.05))
        out.append(np.ascontiguousarray(v, dtype=np.float64))
    return out


def subset(dst: Path) -> Path:
    """A generated directory holding K1-K6 only: their C copied from ``generated/c``, the
    module, table and index rendered for them by the generator's templates."""
    from rigidsym.codegen.backends import environment
    from rigidsym.codegen.backends.extension.target import TEMPLATES, render_module

    gdir = _ext.generated_dir()
    data = json.loads((gdir / "kernels.json").read_text())
    metas = [m for m in data["kernels"] if m["name"] in BENCH.values()]
    (dst / "c").mkdir(parents=True)
    for m in metas:
        for ext in (".c", ".h"):
            shutil.copy(gdir / "c" / (m["name"] + ext), dst / "c")
    shutil.copy(gdir / "c" / "rigidsym_common.h", dst / "c")
    env, ver = environment(TEMPLATES), data["generator"]
    files = render_module(env, metas, ver)
    files["c/rigidsym_kernels.h"] = env.get_template("c_kernels_index.h.j2").render(
        kernels=metas, template="c_kernels_index.h.j2", **ver)
    for rel, text in files.items():
        (dst / rel).write_text(text)
    (dst / "kernels.json").write_text(json.dumps({"kernels": metas}))
    return dst


def modules(tmp: Path) -> dict:
    """K1-K6 built three ways by the package's driver: the default (dispatched x86-64-v2, v3
    and v4, as the wheel), native (-march=native, as build-c --native) and x86-64-v3 alone
    (what a CPU without AVX-512 runs)."""
    gdir = subset(tmp / "k")
    default = _build.configure()
    builds = {"default": default, "native": _build.configure(native=True)}
    if _build._x86():   # what a CPU without AVX-512 runs: the value of the x86-64-v4 path
        builds["x86-64-v3"] = dataclasses.replace(default, paths=(_build.X86_PATHS[1],))
    out = {}
    for tag, cfg in builds.items():
        so = _build.build(gdir, tmp / tag / "_ckernels.so", cfg, tmp / tag)
        spec = importlib.util.spec_from_file_location(f"_bench_{tag.replace('-', '_')}"
                                                      "._ckernels", so)
        mod = importlib.util.module_from_spec(spec)
        try:
            spec.loader.exec_module(mod)
        except ImportError as exc:          # e.g. no AVX-512 on this CPU
            print(f"{tag}: not run ({exc})", file=sys.stderr)
            continue
        out[tag] = mod
    return out


def measure(n: int, rounds: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        mods = modules(Path(tmp))
        metas = {k["name"]: k for k in
                 json.loads((_ext.generated_dir() / "kernels.json").read_text())["kernels"]}
        rng = np.random.default_rng(0)
        rows = {}
        for kid, name in BENCH.items():
            meta = metas[name]
            xs = inputs(meta, n, rng)
            outs = {w: [np.empty((n,) + tuple(o["shape"])) for o in meta["outputs"]]
                    for w in mods}
            best = dict.fromkeys(mods, float("inf"))
            for _ in range(rounds):                # alternately: fair on a loaded machine
                for w, m in mods.items():
                    k = m.kernels.index(name)
                    t0 = time.thread_time()
                    flagged = m.batch(k, False, n, 1, *xs, *outs[w])
                    best[w] = min(best[w], time.thread_time() - t0)
                    assert flagged == 0, (name, w, flagged)
            for w in mods:                         # the same results, normwise
                for a, b in zip(outs[w], outs["default"], strict=True):
                    assert np.abs(a - b).max() <= 1e-13 * np.abs(b).max(), (name, w)
            rows[kid] = {"kernel": name, **{w: best[w] / n * 1e9 for w in mods}}
        return {"rows": rows, "columns": list(mods), "default_path": mods["default"].path,
                "native_flags": mods["native"].build, "n": n, "rounds": rounds,
                "load": os.getloadavg()[0]}


def table(res: dict) -> str:
    extra = [c for c in res["columns"] if c not in ("default", "native")]
    lines = [f"| K | kernel | default ({res['default_path']}) | native | default / native |"
             + "".join(f" {c} | {c} / default |" for c in extra),
             "|---|---|---:|---:|---:|" + "---:|---:|" * len(extra)]
    for kid, r in res["rows"].items():
        ratio = r["default"] / r["native"]
        mark = "" if ratio <= TARGET else " (over 1.10)"
        lines.append(f"| {kid} | `{r['kernel']}` | {r['default']:.2f} | {r['native']:.2f} | "
                     f"{ratio:.3f}{mark} |"
                     + "".join(f" {r[c]:.2f} | {r[c] / r['default']:.3f} |" for c in extra))
    return "\n".join(lines)


MARK, END = "<!-- build-paths -->", "<!-- /build-paths -->"


def write_section(res: dict, path: Path, notes: list[str]) -> None:
    """Replace (or append) this benchmark's section of RESULTS.md, between its markers
    (benchmarks/run.py carries such sections over when it rewrites the file)."""
    lines = [MARK, "## Default build against native", "",
             f"`python benchmarks/build_paths.py --results`: N = {res['n']:.0e}, one thread, "
             f"ns/sample (thread CPU time), caller-provided outputs, minimum of {res['rounds']} "
             f"alternating rounds; load average {res['load']:.1f} at the start. Native flags: "
             f"`{res['native_flags']}`.", "", table(res), "", *notes, END]
    from _results import write_section as write

    write(path, "\n".join(lines), MARK, END)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=1_000_000)
    p.add_argument("--rounds", type=int, default=7)
    p.add_argument("--json", default=None, help="also write the numbers here")
    p.add_argument("--results", action="store_true",
                   help="write the table into benchmarks/RESULTS.md (its own section)")
    p.add_argument("--note", action="append", default=[], help="a line under the table")
    a = p.parse_args(argv)
    res = measure(a.n, a.rounds)
    print(f"N = {a.n:.0e}, one thread, ns/sample (thread CPU time), minimum of {a.rounds} "
          f"alternating rounds; "
          f"load average {res['load']:.1f} at the start")
    print(table(res))
    if a.json:
        Path(a.json).write_text(json.dumps(res, indent=1))
    if a.results:
        write_section(res, ROOT / "benchmarks" / "RESULTS.md", a.note)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
