"""`rigidsym generate --target cpp` cold: wall and CPU seconds of a few kernels' C and C++.

Each command runs as printed, in a fresh process with empty caches (a new ``RIGIDSYM_CACHE``
and ``XDG_CACHE_HOME``: no store of derived kernels, no object cache) and a new output
folder. CPU is user + sys of the whole process tree (the generator's pool workers
included); wall depends on what else the machine runs, so the load average before each run
is kept beside it. The commands: examples/c/README.md's (five book kernels and the three of
examples/c/my_kernels.py; its output compared with the committed examples/c/rigidsym_c)
and six book kernels of a controls application (the rotation, the screw, the twist
transfer, the Newton-Euler wrench, the rotation vector, the natural invariants).
``--per-kernel`` adds each kernel's derivation CPU (``compile_kernel`` as the C target
calls it, one process, serially): where the time of a run goes.

    python benchmarks/generate_cold.py --json benchmarks/results/generate_cold.json
"""

from __future__ import annotations

import argparse
import filecmp
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]

README_KERNELS = ["rotation_from_natural_invariants", "natural_invariants_from_rotation",
                  "twist_transfer", "newton_euler_wrench", "wrench_transfer"]
CONTROLS_KERNELS = ["rotation_from_natural_invariants", "screw_of_displacement",
                    "twist_transfer", "newton_euler_wrench", "rotation_vector_from_rotation",
                    "natural_invariants_from_rotation"]
COMMANDS = {
    "examples/c/README.md": ["--module", "examples/c/my_kernels.py",
                             *[a for k in README_KERNELS for a in ("--kernel", k)]],
    "six book kernels": [a for k in CONTROLS_KERNELS for a in ("--kernel", k)],
}

PER_KERNEL = """
import importlib, json, sys, time
from rigidsym.codegen.generator import compile_kernel
from rigidsym.core.config import KERNEL_SPEC
book = {k.name: k for k in importlib.import_module(KERNEL_SPEC).KERNELS}
from rigidsym.codegen.derivatives.jacobians import jacobian_kernels
ks = [book[n] for n in sys.argv[1:]]
out = {}
for k in sorted(ks + jacobian_kernels(ks), key=lambda k: k.name):
    t = time.process_time()
    compile_kernel(k, plan32=False)
    out[k.name] = round(time.process_time() - t, 2)
print(json.dumps(out))
"""


def _children_cpu() -> float:
    """User + sys seconds of this process's finished children (their trees included)."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _same_tree(a: Path, b: Path) -> bool:
    """Whether folders ``a`` and ``b`` hold the same files, byte for byte."""
    cmp = filecmp.dircmp(a, b)
    if cmp.left_only or cmp.right_only or cmp.funny_files:
        return False
    _, mismatch, errors = filecmp.cmpfiles(a, b, cmp.common_files, shallow=False)
    return not mismatch and not errors and all(
        _same_tree(a / d, b / d) for d in cmp.common_dirs)


def cold_run(name: str, rigidsym: str, env: dict) -> dict:
    """One cold run of the command ``name`` of :data:`COMMANDS`: wall and CPU seconds."""
    with tempfile.TemporaryDirectory(prefix="rigidsym-cold-") as tmp:
        t = Path(tmp)
        for d in ("cache", "xdg", "out"):
            (t / d).mkdir()
        run_env = dict(env, RIGIDSYM_CACHE=str(t / "cache"), XDG_CACHE_HOME=str(t / "xdg"))
        argv = [rigidsym, "generate", "--target", "cpp", *COMMANDS[name], "--out",
                str(t / "out")]
        load = os.getloadavg()
        c0, t0 = _children_cpu(), time.perf_counter()
        p = subprocess.run(argv, cwd=ROOT, env=run_env, capture_output=True, text=True)
        rec = {"command": "rigidsym " + " ".join(argv[1:-1]) + " --out DIR",
               "wall_s": round(time.perf_counter() - t0, 1),
               "cpu_s": round(_children_cpu() - c0, 1), "rc": p.returncode,
               "load_before": [round(x, 2) for x in load],
               "output_tail": (p.stdout + p.stderr)[-2000:]}
        if name == "examples/c/README.md":
            rec["same_as_examples_c_rigidsym_c"] = _same_tree(
                t / "out", ROOT / "examples" / "c" / "rigidsym_c")
    return rec


def per_kernel(env: dict, names: list[str]) -> dict:
    """``{kernel: CPU seconds of its derivation}`` for ``names`` and their twins."""
    with tempfile.TemporaryDirectory(prefix="rigidsym-cold-") as tmp:
        run_env = dict(env, RIGIDSYM_CACHE=tmp, XDG_CACHE_HOME=tmp)
        p = subprocess.run([sys.executable, "-c", PER_KERNEL, *names], cwd=ROOT,
                           env=run_env, capture_output=True, text=True, check=True)
    return json.loads(p.stdout.splitlines()[-1])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", type=Path, help="write the record here")
    ap.add_argument("--runs", type=int, default=1, help="cold runs of each command")
    ap.add_argument("--per-kernel", action="store_true",
                    help="also each kernel's derivation CPU (the six book kernels)")
    ap.add_argument("--label", default="", help="what the record measures (free text)")
    args = ap.parse_args(argv)
    rigidsym = str(Path(sys.executable).with_name("rigidsym"))
    env = dict(os.environ)
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    doc = {"host": host(), "commit": commit, "label": args.label, "runs": {}}
    for name in COMMANDS:
        doc["runs"][name] = [cold_run(name, rigidsym, env) for _ in range(args.runs)]
        for r in doc["runs"][name]:
            print(f"{name}: wall {r['wall_s']} s, CPU {r['cpu_s']} s (rc {r['rc']}, load "
                  f"{r['load_before'][0]})", flush=True)
    if args.per_kernel:
        doc["derivation_cpu_s"] = per_kernel(env, CONTROLS_KERNELS)
        print(json.dumps(doc["derivation_cpu_s"], indent=1))
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        part = args.json.with_suffix(".part")
        part.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
        part.replace(args.json)
    return 0 if all(r["rc"] == 0 for rs in doc["runs"].values() for r in rs) else 1


if __name__ == "__main__":
    sys.exit(main())
