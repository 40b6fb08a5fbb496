"""sin/cos pairs, three ways side by side in one run (the C back-end's trig).

The generated header's ``rigidsym_sin``/``rigidsym_cos`` (``generated/c/rigidsym_common.h``),
glibc's libmvec and libm's scalar ``sin``/``cos``, each compiled from ``trig_pair.c`` with
the kernels' flags for every x86-64 path: ns per pair and the largest error in ulp against
long double per regime (4096 x 100 arguments each, both functions). Needs gcc and glibc.

Usage (from the repository root)::

    python benchmarks/trig_pair.py [--paths x86-64-v2,x86-64-v3,x86-64-v4]
"""

from __future__ import annotations

import argparse
import subprocess
import tempfile
from pathlib import Path

from rigidsym.kernels.cbuild.driver import KERNEL_FLAGS

ROOT = Path(__file__).resolve().parents[1]
FLAGS = list(KERNEL_FLAGS)   # the kernels' flags
WAYS = {"rigidsym (own)": (["-DOWN", "-fopenmp-simd"], ["-lm"]),
        "libmvec": (["-DMVEC", "-fopenmp-simd", "-fno-builtin-sin", "-fno-builtin-cos"],
                    ["-lmvec", "-lm"]),
        "libm scalar": ([], ["-lm"])}


def run(path: str, way: str, tmp: Path) -> list[str]:
    extra, libs = WAYS[way]
    exe = tmp / f"pair-{path}-{way.split()[0]}"
    subprocess.run(["gcc", *FLAGS, f"-march={path}", *extra, "-I", str(ROOT / "generated/c"),
                    str(ROOT / "benchmarks/trig_pair.c"), "-o", str(exe), *libs], check=True)
    return subprocess.run([str(exe)], check=True, capture_output=True,
                          text=True).stdout.splitlines()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--paths", default="x86-64-v2,x86-64-v3,x86-64-v4")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        out = {(p, w): run(p, w, Path(tmp)) for p in a.paths.split(",") for w in WAYS}
    print("| path | " + " | ".join(f"{w} ns/pair" for w in WAYS) + " |\n|---|"
          + "---|" * len(WAYS))
    for p in a.paths.split(","):
        print(f"| {p} | " + " | ".join(out[p, w][0].split()[1] for w in WAYS) + " |")
    path = a.paths.split(",")[-1]
    print(f"\nlargest error in ulp (mean), {path}, against long double sinl/cosl:\n\n| regime | "
          + " | ".join(WAYS) + " |\n|---|" + "---|" * len(WAYS))
    rows = {w: [line.split(";") for line in out[path, w][1:]] for w in WAYS}
    for i, r in enumerate(rows["libm scalar"]):
        cells = [f"{float(rows[w][i][1]):.3f} ({float(rows[w][i][2]):.3f})" for w in WAYS]
        print(f"| {r[0].removeprefix('regime ')} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
