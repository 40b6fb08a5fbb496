"""The cost of the range test on ordinary data: the C batch function of a kernel as
generated, against the same file with the block's range test over its inputs removed (the
rescue's only work on a block that raised no floating-point exception flag), side by side.

Both variants are compiled from ``generated/c`` with the kernels' flags
(``rigidsym.kernels.cbuild.driver.KERNEL_FLAGS``) and ``-march=x86-64-v3`` (or the compiler's
default off x86) into one driver, which times them in interleaved rounds on the same inputs
(random valid samples from ``rigidsym.core.draws``, one thread, thread CPU time per call of N
samples); the ratio of the medians is the range test's cost. The variants' outputs are
compared bit for bit (ordinary data: the range test flags nothing).

Usage (from the repository root)::

    python benchmarks/rescue_cost.py [--kernels K1,...] [--n 1000000] [--rounds 11]
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
DEFAULT = ["rotation_from_euler_rodrigues", "rotation_from_natural_invariants",
           "screw_axis_point", "instant_screw_point_pitch", "N_matrix", "newton_euler_wrench",
           "plucker_from_points", "screw_of_displacement", "instant_screw_axis"]
#: the range test of a block function: `any |= rigidsym_any_extreme(in_x, size * m);`
RANGE = re.compile(r"^\s*any \|= rigidsym_any_extreme(_f32)?\(in_\w+, \d+ \* m\);\n", re.M)

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
static int cmp(const void *a, const void *b) {{
    double x = *(const double *)a, y = *(const double *)b; return (x > y) - (x < y);
}}
int main(int argc, char **argv) {{
    const int64_t n = atoll(argv[1]); const int rounds = atoi(argv[2]);
{body}
    return 0;
}}
"""


def _kernel_driver(name: str, meta: dict, idx: int, n: int, rounds: int) -> tuple[str, str]:
    """Declarations and the timing block of one kernel: inputs read from ``in_<idx>.bin``."""
    ins = [int(np.prod(a["tshape"], dtype=int)) for a in meta["args"]]
    outs = [int(np.prod(o["tshape"], dtype=int)) for o in meta["outputs"]]
    params = ", ".join(["const double *"] * len(ins) + ["double *"] * len(outs))
    decls = "\n".join(f"int64_t {name}_{v}_threads(int64_t, int, {params});"
                      for v in ("with", "without"))
    lines = [f"    {{ /* {name} */",
             f"    FILE *f = fopen(\"in_{idx}.bin\", \"rb\");"]
    for j, s in enumerate(ins):
        lines += [f"    double *x{j} = malloc(sizeof(double) * {s} * n);",
                  f"    if (fread(x{j}, sizeof(double), {s} * n, f) != (size_t)({s} * n))",
                  "        return 2;"]
    lines.append("    fclose(f);")
    for j, s in enumerate(outs):
        lines += [f"    double *a{j} = malloc(sizeof(double) * {s} * n);",
                  f"    double *b{j} = malloc(sizeof(double) * {s} * n);"]
    xs = ", ".join(f"x{j}" for j in range(len(ins)))
    a = ", ".join(f"a{j}" for j in range(len(outs)))
    b = ", ".join(f"b{j}" for j in range(len(outs)))
    same = " && ".join(f"!memcmp(a{j}, b{j}, sizeof(double) * {s} * n)"
                       for j, s in enumerate(outs))
    lines += ["    double tw[256], to[256]; int64_t fw = 0, fo = 0;",
              "    for (int r = 0; r < rounds; ++r) {",
              f"        double t0 = now(); fw += {name}_with_threads(n, 1, {xs}, {a});",
              "        tw[r] = now() - t0;",
              f"        t0 = now(); fo += {name}_without_threads(n, 1, {xs}, {b});",
              "        to[r] = now() - t0;",
              "    }",
              "    qsort(tw, rounds, sizeof(double), cmp); qsort(to, rounds, sizeof(double), cmp);",
              f"    printf(\"{name} %.4f %.4f %lld %lld %d\\n\", 1e3 * tw[rounds / 2], "
              f"1e3 * to[rounds / 2], (long long)fw, (long long)fo, {same});",
              "    }"]
    return decls, "\n".join(lines)


def _variant(src: str, name: str, tag: str, strip: bool) -> str:
    """The kernel's C with its exported names suffixed by ``tag`` (and no range test)."""
    if strip:
        src, k = RANGE.subn("", src)
        assert k >= 2, f"{name}: no range test found (the template changed?)"
    return re.sub(rf"\brigidsym_{name}(_f32)?_threads\b",
                  lambda m: f"{name}{m.group(1) or ''}_{tag}_threads", src)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kernels", default=",".join(DEFAULT))
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--rounds", type=int, default=11)
    args = ap.parse_args()
    cc = _build.compiler()
    if cc is None:
        sys.exit("no C compiler")
    meta = _state.builtin().meta
    names = args.kernels.split(",")
    march = ["-march=x86-64-v3"] if platform.machine() in ("x86_64", "AMD64") else []
    rng = np.random.default_rng(0)
    with tempfile.TemporaryDirectory() as tmp:
        t = Path(tmp)
        decls, bodies, objs = [], [], []
        for i, name in enumerate(names):
            m = meta[name]
            xs = [_draw.draw(s["kind"], (args.n,) + tuple(s["tshape"]), rng)
                  for s in m["args"]]
            with open(t / f"in_{i}.bin", "wb") as f:
                for x in xs:
                    np.ascontiguousarray(x, dtype=np.float64).tofile(f)
            src = (GEN / f"{name}.c").read_text()
            for tag, strip in (("with", False), ("without", True)):
                c = t / f"{name}_{tag}.c"
                c.write_text(_variant(src, name, tag, strip))
                o = c.with_suffix(".o")
                # the plain one-thread wrapper `rigidsym_<name>` of both variants, renamed
                subprocess.run([*cc, *_build.KERNEL_FLAGS, *march, "-I", str(GEN),
                                f"-Drigidsym_{name}={name}_{tag}_plain", "-c", str(c),
                                "-o", str(o)], check=True)
                objs.append(str(o))
            d, b = _kernel_driver(name, m, i, args.n, args.rounds)
            decls.append(d)
            bodies.append(b)
        drv = t / "driver.c"
        drv.write_text(textwrap.dedent(DRIVER).format(decls="\n".join(decls),
                                                      body="\n".join(bodies)))
        exe = t / "driver"
        subprocess.run([*cc, "-O2", "-std=c99", str(drv), *objs, "-lm", "-o", str(exe)],
                       check=True)
        out = subprocess.run([str(exe), str(args.n), str(args.rounds)], cwd=t, check=True,
                             capture_output=True, text=True).stdout
    print(f"N = {args.n:.0e}, one thread, {args.rounds} interleaved rounds, median thread CPU "
          f"time; with = as generated, without = the block's range test removed")
    print("| kernel | with ms | without ms | with / without | same outputs |")
    print("|---|---:|---:|---:|---|")
    for line in out.splitlines():
        name, w, wo, fw, fo, same = line.split()
        assert fw == fo == "0", line
        print(f"| `{name}` | {float(w):.2f} | {float(wo):.2f} | {float(w) / float(wo):.3f} | "
              f"{'yes' if same == '1' else 'NO'} |")


if __name__ == "__main__":
    main()
