"""the structure-of-arrays layout of the lanes function and of the range
test, measured against the generated C of today, side by side in one driver.

Three variants of a kernel's generated C (``generated/c/<name>.c``), compiled with the
kernels' flags (``rigidsym.kernels.cbuild.driver.KERNEL_FLAGS``, ``-fopenmp``,
``-march=x86-64-v3``) into one driver:

* ``today``: the file as generated (row-major lanes loop; the block's range test a second
  pass over the block's inputs);
* ``soa``: each lanes function (float64 and float32) first transposes its L samples' inputs
  into local column arrays, runs the sample function in an ``omp simd`` loop over them
  (contiguous loads: vectorised without gathers) into local output columns, and transposes
  those back; the range test stays the block's second pass;
* ``soa+test``: the same, with the range test over the local column arrays inside the lanes
  function (contiguous values in L1, no second pass over the block): a lane group with an
  extreme or non-finite input sets bit 62 of the lanes mask, which sends the block down the
  per-row path exactly as the second pass did.

Outputs of all three are compared bit for bit (``-ffp-contract=off``: vector and scalar
arithmetic are the same IEEE operations), and the flagged counts on data with extreme rows.
Timing: one thread, thread CPU time per call of N samples, interleaved rounds, minimum.

Usage (from the repository root)::

    python benchmarks/soa_check.py [--kernels K1,K4,K6] [--n 1000000] [--rounds 11]
        [--keep DIR]   # leave the variants' C and the driver in DIR (for callgrind)
"""

from __future__ import annotations

import argparse
import platform
import re
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import numpy as np

from rigidsym.core import draws as _draw
from rigidsym.kernels.cbuild import driver as _build
from rigidsym.kernels.runtime import state as _state

ROOT = Path(__file__).resolve().parents[1]
GEN = ROOT / "generated" / "c"
KS = {"K1": "rotation_from_euler_rodrigues", "K4": "instant_screw_point_pitch",
      "K6": "newton_euler_wrench"}
VARIANTS = ("today", "soa", "soatest")
RANGE = re.compile(r"^\s*any \|= rigidsym_any_extreme(_f32)?\(in_\w+, \d+ \* m\);\n", re.M)


def _lanes_soa(name: str, meta: dict, f32: bool, test: bool) -> str:
    """The structure-of-arrays lanes function of ``name`` (float32 when ``f32``)."""
    T, L, S = ("float", "RIGIDSYM_LANES_F32", "_f32") if f32 else ("double", "RIGIDSYM_LANES", "")
    ins = [(a["name"], int(np.prod(a["tshape"], dtype=int))) for a in meta["args"]]
    outs = [(o["name"], int(np.prod(o["tshape"], dtype=int))) for o in meta["outputs"]]
    p = [f"    const {T} *RIGIDSYM_RESTRICT in_{a}" for a, _ in ins]
    p += [f"    {T} *RIGIDSYM_RESTRICT out_{o}" for o, _ in outs]
    b = [f"static RIGIDSYM_NOINLINE int64_t rigidsym_{name}_lanes{S}(", ",\n".join(p), ")", "{",
         "    int64_t count = 0;"]
    b += [f"    RIGIDSYM_ALIGNED {T} c_{a}[{s}][{L}];" for a, s in ins]
    b += [f"    RIGIDSYM_ALIGNED {T} r_{o}_{c}[{L}];" for o, s in outs for c in range(s)]
    b.append(f"    for (int64_t j = 0; j < {L}; ++j) {{")
    b += [f"        c_{a}[{c}][j] = in_{a}[{s} * j + {c}];" for a, s in ins for c in range(s)]
    b.append("    }")
    if test:
        ex = "rigidsym_any_extreme_f32" if f32 else "rigidsym_any_extreme"
        b.append("    int ext = 0;")
        b += [f"    ext |= {ex}(&c_{a}[0][0], {s} * {L});" for a, s in ins]
    b += ["    /* a plain loop: gcc 12 with -fopenmp does not vectorise it under omp simd */",
          f"    for (int64_t j = 0; j < {L}; ++j) {{"]
    b += [f"        {T} x_{a}[{s}] = {{" + ", ".join(f"c_{a}[{c}][j]" for c in range(s)) + "};"
          for a, s in ins]
    b += [f"        {T} y_{o}[{s}];" for o, s in outs]
    call = ", ".join([f"x_{a}" for a, _ in ins] + [f"y_{o}" for o, _ in outs])
    b.append(f"        count += (int64_t)(rigidsym_{name}_sample{S}({call}) != 0) << j;")
    b += [f"        r_{o}_{c}[j] = y_{o}[{c}];" for o, s in outs for c in range(s)]
    b += ["    }", f"    for (int64_t j = 0; j < {L}; ++j) {{"]
    b += [f"        out_{o}[{s} * j + {c}] = r_{o}_{c}[j];" for o, s in outs for c in range(s)]
    b.append("    }")
    if test:
        b.append("    count |= (int64_t)ext << 62;")
    b += ["    return count;", "}"]
    return "\n".join(b) + "\n"


def variant(name: str, meta: dict, tag: str) -> str:
    """The generated C of ``name`` as the variant ``tag``, its entry points suffixed."""
    src = (GEN / f"{name}.c").read_text()
    if tag != "today":
        for f32 in (False, True):
            S = "_f32" if f32 else ""
            pat = re.compile(rf"static RIGIDSYM_NOINLINE int64_t "
                             rf"rigidsym_{name}_lanes{S}\(.*?\n}}\n", re.S)
            src, k = pat.subn(lambda _m, f=f32: _lanes_soa(name, meta, f, tag == "soatest"), src,
                              count=1)
            assert k == 1, (name, S)
        if tag == "soatest":
            src, k = RANGE.subn("", src)
            assert k >= 2, f"{name}: no range test found (the template changed?)"
    return re.sub(rf"\brigidsym_{name}(_f32)?_threads\b",
                  lambda m: f"{name}{m.group(1) or ''}_{tag}_threads", src)


DRIVER = r"""
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
{decls}
static double now(void) {{
    struct timespec t; clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}}
static void *rd(FILE *f, size_t bytes) {{
    void *p = malloc(bytes); if (fread(p, 1, bytes, f) != bytes) exit(2); return p;
}}
int main(int argc, char **argv) {{
    const int64_t n = atoll(argv[1]); const int rounds = atoi(argv[2]);
    const char *only = argc > 3 ? argv[3] : "";
{body}
    return 0;
}}
"""


def _kernel_driver(name: str, meta: dict, idx: int) -> tuple[str, str]:
    """Declarations and the block of one kernel: float64 and float32, the three variants;
    inputs ``in_<idx>_<dt>.bin`` (ordinary) and ``x_<idx>_<dt>.bin`` (with extreme rows)."""
    ins = [int(np.prod(a["tshape"], dtype=int)) for a in meta["args"]]
    outs = [int(np.prod(o["tshape"], dtype=int)) for o in meta["outputs"]]
    decls, lines = [], [f"    {{ /* {name} */"]
    for T, S in (("double", ""), ("float", "_f32")):
        params = ", ".join([f"const {T} *"] * len(ins) + [f"{T} *"] * len(outs))
        decls += [f"int64_t {name}{S}_{v}_threads(int64_t, int, {params});" for v in VARIANTS]
        lines.append("    {")
        for data in ("in", "x"):
            lines.append(f"    {{ FILE *f = fopen(\"{data}_{idx}{S}.bin\", \"rb\");")
            lines += [f"    {data}{j} = rd(f, sizeof({T}) * {s} * n);" for j, s in enumerate(ins)]
            lines.append("    fclose(f); }")
        lines[-2 * (len(ins) + 2):-2 * (len(ins) + 2)] = [
            f"    {T} *in{j}, *x{j};" for j in range(len(ins))]
        for v in VARIANTS:
            lines += [f"    {T} *o_{v}{j} = malloc(sizeof({T}) * {s} * n);"
                      for j, s in enumerate(outs)]
        lines.append("    double best[3] = {1e9, 1e9, 1e9}; int64_t fl[3], fx[3];")
        for i, v in enumerate(VARIANTS):
            xs = ", ".join(f"x{j}" for j in range(len(ins)))
            os_ = ", ".join(f"o_{v}{j}" for j in range(len(outs)))
            lines.append(f"    fx[{i}] = {name}{S}_{v}_threads(n, 1, {xs}, {os_});")
        lines.append("    for (int r = 0; r < rounds; ++r) {")
        for i, v in enumerate(VARIANTS):
            ins_ = ", ".join(f"in{j}" for j in range(len(ins)))
            os_ = ", ".join(f"o_{v}{j}" for j in range(len(outs)))
            lines += [f"        if (!*only || !strcmp(only, \"{v}\")) {{",
                      f"        double t0 = now(); "
                      f"fl[{i}] = {name}{S}_{v}_threads(n, 1, {ins_}, {os_});",
                      f"        t0 = now() - t0; if (t0 < best[{i}]) best[{i}] = t0; }}"]
        lines.append("    }")
        same = " && ".join(f"!memcmp(o_today{j}, o_{v}{j}, sizeof({T}) * {s} * n)"
                           for v in VARIANTS[1:] for j, s in enumerate(outs))
        fmt = " ".join([name, T] + ["%.4f"] * 3 + ["%lld"] * 6 + ["%d"])
        lines.append(f"    printf(\"{fmt}\\n\", "
                     "1e3 * best[0], 1e3 * best[1], 1e3 * best[2], (long long)fl[0], "
                     "(long long)fl[1], (long long)fl[2], (long long)fx[0], (long long)fx[1], "
                     f"(long long)fx[2], !*only && ({same}));")
        lines.append("    }")
    lines.append("    }")
    return "\n".join(decls), "\n".join(lines)


def _inputs(meta: dict, n: int, rng, dtype) -> tuple[list, list]:
    xs = [np.ascontiguousarray(_draw.draw(s["kind"], (n,) + tuple(s["tshape"]), rng),
                               dtype=dtype) for s in meta["args"]]
    ext = [x.copy() for x in xs]          # every 997th row: one input value extreme
    for k, x in enumerate(ext):
        flat = x.reshape(n, -1)
        flat[k::997 * len(ext), 0] = 1e-35 if dtype == np.float32 else 1e-300
        flat[(k + 500)::997 * len(ext), -1] = np.inf
    return xs, ext


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kernels", default="K1,K4,K6")
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=11)
    ap.add_argument("--keep", default=None)
    args = ap.parse_args()
    cc = _build.compiler()
    if cc is None:
        sys.exit("no C compiler")
    meta = _state.builtin().meta
    names = [KS.get(k, k) for k in args.kernels.split(",")]
    march = ["-march=x86-64-v3"] if platform.machine() in ("x86_64", "AMD64") else []
    rng = np.random.default_rng(0)
    tmp = tempfile.TemporaryDirectory()
    t = Path(args.keep or tmp.name)
    t.mkdir(parents=True, exist_ok=True)
    decls, bodies, objs = [], [], []
    for i, name in enumerate(names):
        m = meta[name]
        for dt, S in ((np.float64, ""), (np.float32, "_f32")):
            xs, ext = _inputs(m, args.n, rng, dt)
            for tag, arrs in (("in", xs), ("x", ext)):
                with open(t / f"{tag}_{i}{S}.bin", "wb") as f:
                    for x in arrs:
                        x.tofile(f)
        for v in VARIANTS:
            c = t / f"{name}_{v}.c"
            c.write_text(variant(name, m, v))
            o = c.with_suffix(".o")
            subprocess.run([*cc, *_build.KERNEL_FLAGS, "-fopenmp", *march, "-I", str(GEN),
                            f"-Drigidsym_{name}={name}_{v}_plain", "-c", str(c), "-o", str(o)],
                           check=True)
            objs.append(str(o))
        d, b = _kernel_driver(name, m, i)
        decls.append(d)
        bodies.append(b)
    drv = t / "driver.c"
    drv.write_text(textwrap.dedent(DRIVER).format(decls="\n".join(decls), body="\n".join(bodies)))
    exe = t / "driver"
    subprocess.run([*cc, "-O2", "-std=c99", str(drv), *objs, "-fopenmp", "-lm", "-o", str(exe)],
                   check=True)
    out = subprocess.run([str(exe), str(args.n), str(args.rounds)], cwd=t, check=True,
                         capture_output=True, text=True).stdout
    print(f"N = {args.n:.0e}, one thread, {args.rounds} interleaved rounds, minimum thread CPU "
          "time (ms); today = as generated, soa = lanes on transposed columns, soa+test = "
          "and the range test on the columns (no second pass)")
    print("| kernel | dtype | today | soa | soa+test | soa / today | soa+test / today | "
          "same bits | flagged (extreme data) |")
    print("|---|---|---:|---:|---:|---:|---:|---|---|")
    for line in out.splitlines():
        name, T, a, b, c, f0, f1, f2, x0, x1, x2, same = line.split()
        a, b, c = float(a), float(b), float(c)
        assert f0 == f1 == f2 == "0", line
        fl = f"{x0}" if x0 == x1 == x2 else f"DIFFER {x0}/{x1}/{x2}"
        print(f"| `{name}` | {T} | {a:.2f} | {b:.2f} | {c:.2f} | {b / a:.3f} | {c / a:.3f} | "
              f"{'yes' if same == '1' else 'NO'} | {fl} |")


if __name__ == "__main__":
    main()
