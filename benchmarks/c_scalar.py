"""Scalar speed of the C target's functions against hand-written C.

    python benchmarks/c_scalar.py [--n 2000] [--cc gcc] [--results]

The seven kernels of examples/c (four book kernels, three of the example's own module), each
as the generated double and float function (examples/c/rigidsym_c, built by gcc -O2 -std=c99)
and as hand-written C of the same formula (benchmarks/c_scalar/hand.c), called one sample at
a time by benchmarks/c_scalar/bench.c on inputs that move each call. Two measures: the
instructions per call by ``valgrind --tool=callgrind`` (the function inclusive of its sin/cos
calls; independent of the machine's load), and the CPU time per call (the best of 7 runs of
--n calls; noisy on a shared machine). Built twice: the default (every input's range test,
the status of docs/c-api.md) and -DRIGIDSYM_C_TRUSTED_INPUTS (no input test: the outputs'
finiteness test only). ``--results`` writes the table into benchmarks/RESULTS.md (between
``<!-- c-scalar -->`` markers). Needs gcc and valgrind. ``--fast``: the time only, built at
-O3 and at -O3 -march=native, of the small kernels (its own table).
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HERE = ROOT / "benchmarks" / "c_scalar"
KERNELS = ROOT / "examples" / "c" / "rigidsym_c"
#: (kernel, the hand-written function's name)
CASES = [("rotation_from_natural_invariants", "hand_rotation"),
         ("twist_transfer", "hand_twist"), ("newton_euler_wrench", "hand_wrench"),
         ("quaternion_rotation", "hand_quat"),
         ("planar_arm_tip_with_jacobians", "hand_arm"), ("body_energy", "hand_energy"),
         ("wrench_transfer", "hand_wrench_transfer")]
#: input components per call (what the checked status's range test reads)
COMPONENTS = {"rotation_from_natural_invariants": 4, "twist_transfer": 12,
              "newton_euler_wrench": 19, "quaternion_rotation": 4,
              "planar_arm_tip_with_jacobians": 4, "body_energy": 16, "wrench_transfer": 12}


def build(out: Path, extra: list[str], cc: str = "gcc", opt: str = "-O2",
          kernels: Path = KERNELS, tag: str = "") -> Path:
    exe = out / ("bench" + tag + "".join(e.replace("-", "_").replace("=", "_")
                                         for e in [*extra, *opt.split()]))
    subprocess.run([cc, "-std=c99", *opt.split(), *extra, "-I", str(kernels), str(HERE / "bench.c"),
                    str(HERE / "hand.c"), *map(str, sorted(kernels.glob("*.c"))), "-o",
                    str(exe), "-lm"], check=True)
    return exe


def instructions(exe: Path, kernel: str, which: str, dtype: str, fn: str, n: int,
                 tmp: Path) -> float:
    """Instructions per call of ``fn`` (inclusive of its callees) by callgrind."""
    out = tmp / "cg.out"
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", str(exe),
                    kernel, which, dtype, str(n)], check=True, capture_output=True)
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", str(out)], check=True,
                          capture_output=True, text=True).stdout
    m = re.search(r"^\s*([\d,]+) \([^)]*\)\s+\S*:" + re.escape(fn) + r" ", text, re.M)
    if m is None:
        raise RuntimeError(f"{fn} not in the callgrind profile")
    return int(m.group(1).replace(",", "")) / (7 * n + 1)


def seconds(exe: Path, kernel: str, which: str, dtype: str, n: int) -> float:
    res = subprocess.run([str(exe), kernel, which, dtype, str(n)], check=True,
                         capture_output=True, text=True)
    return float(res.stdout.split()[0])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=2000, help="calls per run (default 2000)")
    ap.add_argument("--cc", default="gcc", help="the C compiler (default gcc; the table's)")
    ap.add_argument("--results", action="store_true", help="write benchmarks/RESULTS.md")
    ap.add_argument("--fast", action="store_true",
                    help="the time only, at -O3 and -O3 -march=native, of the small kernels "
                         "(twist, wrench transfer, Newton-Euler wrench): --runs interleaved "
                         "rounds of the best of 7, the least taken (the small kernels' table; no "
                         "valgrind)")
    ap.add_argument("--runs", type=int, default=15, help="with --fast: runs (default 15)")
    ap.add_argument("--before", metavar="DIR", default=None,
                    help="with --fast: also time the checked functions of this folder (an "
                         "older generation of examples/c/rigidsym_c), side by side")
    args = ap.parse_args(argv)
    if args.fast:
        return fast(args)
    if shutil.which(args.cc) is None or shutil.which("valgrind") is None:
        print(f"needs {args.cc} and valgrind", file=sys.stderr)
        return 2
    rows = []
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        exes = {"checked": build(tmp, [], args.cc),
                "trusted": build(tmp, ["-DRIGIDSYM_C_TRUSTED_INPUTS"], args.cc)}
        for kernel, hand in CASES:
            for dtype, sfx in (("f64", ""), ("f32", "_f32")):
                cell = {"kernel": kernel, "dtype": dtype}
                for mode, exe in exes.items():
                    cell[mode] = instructions(exe, kernel, "gen", dtype,
                                              f"rigidsym_c_{kernel}{sfx}", args.n, tmp)
                    cell[mode + "_ns"] = seconds(exe, kernel, "gen", dtype, 20 * args.n)
                cell["hand"] = instructions(exes["checked"], kernel, "hand", dtype, hand + sfx,
                                            args.n, tmp)
                cell["hand_ns"] = seconds(exes["checked"], kernel, "hand", dtype, 20 * args.n)
                rows.append(cell)
                print(f"{kernel:34s} {dtype}  generated {cell['checked']:7.1f} instr "
                      f"({cell['checked'] / cell['hand']:.2f}x), trusted {cell['trusted']:7.1f}"
                      f" ({cell['trusted'] / cell['hand']:.2f}x), hand {cell['hand']:7.1f}; "
                      f"ns {cell['checked_ns']:.1f} / {cell['trusted_ns']:.1f} / "
                      f"{cell['hand_ns']:.1f}", flush=True)
    if args.results:
        sys.path.insert(0, str(ROOT / "benchmarks"))
        from _results import write_section

        lines = ["<!-- c-scalar -->", "## C target: scalar functions against hand-written C "
                 "", "",
                 "`python benchmarks/c_scalar.py --results`: instructions per call by "
                 "callgrind (inclusive of sin/cos; load-independent) and CPU ns per call "
                 "(best of 7, gcc 12 -O2, this shared 2-core machine). *checked*: the "
                 "default status (every input component's range test: integer tests of "
                 "the bits, 2 doubles or 4 floats per SSE2 register, straight from the "
                 "arguments); *trusted*: `-DRIGIDSYM_C_TRUSTED_INPUTS` (the outputs' "
                 "finiteness test only). *test / comp.*: (checked - trusted) / the input "
                 "components, the range test's instructions per component.", "",
                 "| kernel | type | checked instr | trusted instr | hand instr | checked / "
                 "hand | trusted / hand | test / comp. | checked ns | trusted ns | hand ns |",
                 "|---|---|---|---|---|---|---|---|---|---|---|"]
        for c in rows:
            per = (c["checked"] - c["trusted"]) / COMPONENTS[c["kernel"]]
            lines.append(f"| {c['kernel']} | {c['dtype']} | {c['checked']:.0f} | "
                         f"{c['trusted']:.0f} | {c['hand']:.0f} | "
                         f"{c['checked'] / c['hand']:.2f} | {c['trusted'] / c['hand']:.2f} | "
                         f"{per:.1f} | {c['checked_ns']:.1f} | {c['trusted_ns']:.1f} | "
                         f"{c['hand_ns']:.1f} |")
        lo = {d: min((c["checked"] - c["trusted"]) / COMPONENTS[c["kernel"]] for c in rows
                     if COMPONENTS[c["kernel"]] >= 12 and c["dtype"] == d)
              for d in ("f64", "f32")}
        lines += ["", "The floor of the checked status on the tiny kernels: a sound range "
                  "test reads every input component (a non-finite one must be flagged, an "
                  "extreme one rescued), and the cheapest measured costs about "
                  f"{lo['f64']:.1f} instructions per component in double and {lo['f32']:.1f} "
                  "in float (the kernels of 12 or more components), so the twist transfer "
                  "(12 components, 30 instructions by hand) cannot come within 1.1x of the "
                  "hand-written formula with the status on: even one instruction per "
                  "component is 1.4x."]
        lines.append("<!-- /c-scalar -->")
        write_section(ROOT / "benchmarks" / "RESULTS.md", "\n".join(lines),
                      "<!-- c-scalar -->", "<!-- /c-scalar -->")
    return 0


#: the small kernels: (kernel, what the book calls it)
SMALL = [("twist_transfer", "twist transfer = velocity transfer (3.82)"),
         ("wrench_transfer", "wrench transfer"),
         ("newton_euler_wrench", "Newton-Euler wrench"),
         ("rotation_from_natural_invariants", "rotation (a sin/cos kernel, for scale)")]
#: the builds of the table: the wheel's default (-O3, x86-64's baseline SSE2) and the host's
OPTS = ["-O3", "-O3 -march=native"]


def fast(args) -> int:
    """The CPU time per call of the small kernels' checked and trusted scalar functions
    against the hand-written formula, built at -O3 and at -O3 -march=native: the least of
    ``--runs`` rounds, each the best of 7 loops of ``20 --n`` calls of every build, kernel,
    type and function in turn (interleaved: the machine is shared, and the least is the
    round least disturbed, for each function alike). ``--results`` writes the table between
    ``<!-- c-scalar-o3 -->`` markers."""
    if shutil.which(args.cc) is None:
        print(f"needs {args.cc}", file=sys.stderr)
        return 2
    best: dict[tuple, float] = {}
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        modes = []
        for opt in OPTS:
            checked = build(tmp, [], args.cc, opt)
            modes += [(opt, "checked", checked, "gen"),
                      (opt, "trusted", build(tmp, ["-DRIGIDSYM_C_TRUSTED_INPUTS"], args.cc, opt),
                       "gen"), (opt, "hand", checked, "hand")]
            if args.before:
                modes.append((opt, "before", build(tmp, [], args.cc, opt,
                                                   Path(args.before).resolve(), "_before"),
                              "gen"))
        for _ in range(args.runs):
            for opt, mode, exe, which in modes:
                for kernel, _what in SMALL:
                    for dtype in ("f64", "f32"):
                        key = (opt, kernel, dtype, mode)
                        best[key] = min(best.get(key, float("inf")),
                                        seconds(exe, kernel, which, dtype, 20 * args.n))
    rows = []
    for opt in OPTS:
        for kernel, what in SMALL:
            for dtype in ("f64", "f32"):
                cell = {"opt": opt, "kernel": kernel, "what": what, "dtype": dtype,
                        **{m: best[(opt, kernel, dtype, m)] for _o, m, _e, _w in modes
                           if _o == opt}}
                rows.append(cell)
                print(f"{opt:18s} {kernel:34s} {dtype}  checked {cell['checked']:.2f} ns "
                      f"({cell['checked'] / cell['hand']:.2f}x), trusted "
                      f"{cell['trusted']:.2f} ({cell['trusted'] / cell['hand']:.2f}x), hand "
                      f"{cell['hand']:.2f}" + (f", before {cell['before']:.2f} "
                                               f"({cell['before'] / cell['hand']:.2f}x)"
                                               if args.before else ""), flush=True)
    if args.results:
        sys.path.insert(0, str(ROOT / "benchmarks"))
        from _results import write_section

        cc = subprocess.run([args.cc, "--version"], capture_output=True,
                            text=True).stdout.splitlines()[0]
        lines = ["<!-- c-scalar-o3 -->", "### At -O3 and -O3 -march=native: the checked scalar "
                 "call against the hand-written formula", "",
                 f"`python benchmarks/c_scalar.py --fast --runs {args.runs}"
                 + (" --before DIR" if args.before else "") + " --results`: "
                 f"{cc}, CPU ns per call (the least of {args.runs} interleaved rounds, "
                 f"each the best of 7 loops of {20 * args.n} calls, the call inclusive of "
                 "the driver's making its inputs; this 2-core machine was shared with other "
                 "jobs, so the ratios move by about 0.05-0.1 from run to run). "
                 "*checked*: the default build; *trusted*: `-DRIGIDSYM_C_TRUSTED_INPUTS` "
                 "(no input range test)" + ("; *before*: the checked functions of the "
                 "folder given by --before (the generation before this one)"
                 if args.before else "") + ".", "",
                 "| build | kernel | type | " + ("checked ns before | before / hand | "
                                                 if args.before else "")
                 + "checked ns | trusted ns | hand ns | checked / hand | trusted / hand |",
                 "|---|---|---|" + ("---|---|" if args.before else "") + "---|---|---|---|---|"]
        for c in rows:
            old = (f"{c['before']:.2f} | {c['before'] / c['hand']:.2f} | "
                   if args.before else "")
            lines.append(f"| `{c['opt']}` | {c['kernel']} ({c['what']}) | {c['dtype']} | {old}"
                         f"{c['checked']:.2f} | {c['trusted']:.2f} | {c['hand']:.2f} | "
                         f"{c['checked'] / c['hand']:.2f} | {c['trusted'] / c['hand']:.2f} |")
        lines.append("<!-- /c-scalar-o3 -->")
        write_section(ROOT / "benchmarks" / "RESULTS.md", "\n".join(lines),
                      "<!-- c-scalar-o3 -->", "<!-- /c-scalar-o3 -->")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
