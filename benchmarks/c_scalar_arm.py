"""Scalar cost of the C target's functions on Arm, against hand-written C.

    python benchmarks/c_scalar_arm.py [--n 40] [--results]

The six kernels of benchmarks/c_scalar.py (three book kernels, three of examples/c's own
module), generated (examples/c/rigidsym_c, checked and -DRIGIDSYM_C_TRUSTED_INPUTS) and
hand-written (benchmarks/c_scalar/hand.c), cross-built at -O2 for three Arm targets and run
under qemu's Linux user mode (no Arm machine here, so no time: qemu's timing says nothing of
a core's). Measured: the instructions each call executes, inclusive of its callees (sin/cos,
the C library's or the generated float ones), from qemu's trace of every executed
instruction (``-singlestep -d exec,nochain``): a run of 2n calls minus a run of n, counting
only instructions outside the driver (benchmarks/c_scalar/arm_main.c), over n. The
instruction count is what callgrind gives on x86-64 (benchmarks/c_scalar.py); it does not
depend on load, but on an in-order Cortex-M4 it is near the cycle count (loads, branches and
VFP divides and roots cost more than one cycle) and on a Cortex-A it is not.

Targets: ``cortex-m4f`` (arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard
-mfpu=fpv4-sp-d16, newlib, the float functions only: double is in software there),
``armhf`` (arm-linux-gnueabihf-gcc, static glibc; a target whose long double is double) and
``aarch64`` (aarch64-linux-gnu-gcc, static glibc). ``--results`` writes the table into
benchmarks/RESULTS.md (between ``<!-- c-scalar-arm -->`` markers). Needs the cross
compilers and qemu-arm / qemu-aarch64 (Debian: gcc-arm-none-eabi, gcc-arm-linux-gnueabihf,
gcc-aarch64-linux-gnu, qemu-user).
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HERE = ROOT / "benchmarks" / "c_scalar"
KERNELS = ROOT / "examples" / "c" / "rigidsym_c"
NAMES = ["rotation_from_natural_invariants", "twist_transfer", "newton_euler_wrench",
         "quaternion_rotation", "planar_arm_tip_with_jacobians", "body_energy"]
#: target: (compiler, its flags, qemu, the types measured)
TARGETS = {
    "cortex-m4f": ("arm-none-eabi-gcc", ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
                                         "-mfpu=fpv4-sp-d16", "-nostartfiles", "-DBARE"],
                   "qemu-arm", ("f32",)),
    "armhf": ("arm-linux-gnueabihf-gcc", ["-march=armv7-a", "-mfpu=neon", "-mfloat-abi=hard"],
              "qemu-arm", ("f64", "f32")),
    "aarch64": ("aarch64-linux-gnu-gcc", [], "qemu-aarch64", ("f64", "f32")),
}
#: the driver's own functions (its loop, the cases' inputs, the agreement check)
DRIVER = {"_start", "start_c", "main", "run", "run_f32", "disagree", "atoi_", "same"}


def build(cc: str, flags: list[str], out: Path, extra: list[str]) -> Path:
    """The driver, the hand-written functions and the generated sources, -O2, static."""
    exe = out / ("bench_" + cc + "".join(e.replace("-", "_") for e in extra))
    subprocess.run([cc, "-std=c99", "-O2", "-static", *flags, *extra, "-I", str(KERNELS),
                    "-I", str(HERE), str(HERE / "arm_main.c"), str(HERE / "hand.c"),
                    *map(str, sorted(KERNELS.glob("*.c"))), "-o", str(exe), "-lm"],
                   check=True)
    return exe


def traced(qemu: str, exe: Path, argv: list[str], tmp: Path) -> Counter:
    """Instructions executed per function (qemu's trace names the symbol of each)."""
    log = tmp / "trace.log"
    subprocess.run([qemu, "-singlestep", "-d", "exec,nochain", "-D", str(log), str(exe),
                    *argv], check=True)
    counts: Counter = Counter()
    with log.open() as fh:
        for line in fh:
            if line.startswith("Trace"):
                counts[line.rsplit(None, 1)[-1]] += 1
    return counts


def per_call(qemu: str, exe: Path, kernel: str, which: str, dtype: str, n: int,
             tmp: Path) -> float:
    """Instructions per call outside the driver: (run of 2n calls - run of n) / n."""
    runs = [traced(qemu, exe, [kernel, which, dtype, str(m)], tmp) for m in (n, 2 * n)]
    inside = [sum(v for k, v in c.items() if k not in DRIVER) for c in runs]
    return (inside[1] - inside[0]) / n


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=40, help="calls of the shorter run (default 40)")
    ap.add_argument("--results", action="store_true", help="write benchmarks/RESULTS.md")
    args = ap.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        for target, (cc, flags, qemu, dtypes) in TARGETS.items():
            if shutil.which(cc) is None or shutil.which(qemu) is None:
                print(f"{target}: skipped, needs {cc} and {qemu}", file=sys.stderr)
                continue
            exes = {"checked": build(cc, flags, tmp, []),
                    "trusted": build(cc, flags, tmp, ["-DRIGIDSYM_C_TRUSTED_INPUTS"])}
            for kernel in NAMES:
                for dtype in dtypes:
                    cell = {"target": target, "kernel": kernel, "dtype": dtype}
                    for mode, exe in exes.items():
                        cell[mode] = per_call(qemu, exe, kernel, "gen", dtype, args.n, tmp)
                    cell["hand"] = per_call(qemu, exes["checked"], kernel, "hand", dtype,
                                            args.n, tmp)
                    rows.append(cell)
                    print(f"{target:10s} {kernel:34s} {dtype}  checked {cell['checked']:7.1f}"
                          f" ({cell['checked'] / cell['hand']:.2f}x), trusted "
                          f"{cell['trusted']:7.1f} ({cell['trusted'] / cell['hand']:.2f}x), "
                          f"hand {cell['hand']:7.1f}", flush=True)
    if args.results:
        sys.path.insert(0, str(ROOT / "benchmarks"))
        from _results import write_section

        lines = ["<!-- c-scalar-arm -->",
                 "### The same on Arm, instructions under qemu", "",
                 "`python benchmarks/c_scalar_arm.py --results`: instructions per call, "
                 "inclusive of sin/cos, from qemu's trace of every executed instruction "
                 "(a run of 2n calls less a run of n), gcc 12 -O2 cross compilers, static. "
                 "No Arm machine here, so no time; on the in-order Cortex-M4 an instruction "
                 "is near a cycle. *cortex-m4f*: `-mcpu=cortex-m4 -mthumb -mfloat-abi=hard "
                 "-mfpu=fpv4-sp-d16`, newlib's `sinf`/`cosf` in the hand-written code, float "
                 "only; *armhf*: long double is double there; *aarch64*. Checked and trusted "
                 "as in the table above.", "",
                 "| target | kernel | type | checked | trusted | hand | checked / hand | "
                 "trusted / hand |", "|---|---|---|---|---|---|---|---|"]
        for c in rows:
            lines.append(f"| {c['target']} | {c['kernel']} | {c['dtype']} | "
                         f"{c['checked']:.0f} | {c['trusted']:.0f} | {c['hand']:.0f} | "
                         f"{c['checked'] / c['hand']:.2f} | {c['trusted'] / c['hand']:.2f} |")
        lines.append("<!-- /c-scalar-arm -->")
        write_section(ROOT / "benchmarks" / "RESULTS.md", "\n".join(lines),
                      "<!-- c-scalar-arm -->", "<!-- /c-scalar-arm -->")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
