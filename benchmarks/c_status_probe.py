"""The float status of the C target on small ordinary inputs, by compiler and flags.

Builds benchmarks/c_status_probe.c against a C target folder holding
``rotation_vector_from_rotation`` and ``screw_of_displacement`` (``--c-dir``; by default
``rigidsym generate --target c`` of the two into a temporary folder) with gcc and clang, the
library at ``-O2`` or ``-Ofast -fno-fast-math`` (the headers refuse ``__FAST_MATH__``) and the
application at ``-O2`` or ``-Ofast`` (linking with ``-Ofast`` adds crtfastmath.o, which sets
x86-64's FTZ and DAZ at start-up), then builds that take the causes apart: gcc ``-O2``
run with DAZ alone set by the caller (``SET_MXCSR=0x1fc0``); clang ``-O2`` with the library
built ``-fno-slp-vectorize``; gcc ``-O2`` and clang ``-Ofast`` with ``-DRIGIDSYM_C_NO_WIDE``
(the float cold path without its double evaluation: the detection by the exception flags
alone, against the double evaluation rounded once of the default builds); gcc ``-O2`` with
``-DRIGIDSYM_C_NO_FP_FLAGS`` (neither: a sample no rescaling takes keeps the range test's
flag, the prediction). Each run prints, per case (float logs of small rotations, screws of
a point 1 nm and 1 m from the origin), the samples flagged, those the range test sends to
the cold path, the exception flags the flagged calls raised, the log's worst relative error
and its silent wrongs (status 0, off by more than 16 u); the record keeps them per build.
x86-64 only (MXCSR).

    python benchmarks/c_status_probe.py --json benchmarks/results/c_status_probe.json
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
PROBE = Path(__file__).with_name("c_status_probe.c")
KERNELS = ("rotation_vector_from_rotation", "screw_of_displacement")
#: (compiler, library flags, application flags, environment, what the build isolates)
BUILDS = [
    ("gcc", ["-O2"], ["-O2"], {}, ""),
    ("gcc", ["-Ofast", "-fno-fast-math"], ["-Ofast"], {}, ""),
    ("clang", ["-O2"], ["-O2"], {}, ""),
    ("clang", ["-Ofast", "-fno-fast-math"], ["-Ofast"], {}, ""),
    ("gcc", ["-O2"], ["-O2"], {"SET_MXCSR": "0x1fc0"}, "DAZ alone set by the caller"),
    ("clang", ["-O2", "-fno-slp-vectorize"], ["-O2"], {}, "clang without the SLP vectorizer"),
    ("gcc", ["-O2", "-DRIGIDSYM_C_NO_WIDE"], ["-O2"], {},
     "the exception flags step alone (no double evaluation of a float sample)"),
    ("clang", ["-Ofast", "-fno-fast-math", "-DRIGIDSYM_C_NO_WIDE"], ["-Ofast"], {},
     "the exception flags step alone (no double evaluation of a float sample)"),
    ("gcc", ["-O2", "-DRIGIDSYM_C_NO_FP_FLAGS"], ["-O2"], {},
     "neither (no flags read, no double evaluation): the range test's prediction where no "
     "rescaling takes the sample"),
]


def generated(out: Path) -> Path:
    """``rigidsym generate --target c`` of :data:`KERNELS` into ``out``."""
    argv = [str(Path(sys.executable).with_name("rigidsym")), "generate", "--target", "c",
            *[a for k in KERNELS for a in ("--kernel", k)], "--out", str(out)]
    subprocess.run(argv, cwd=ROOT, check=True, capture_output=True, text=True)
    return out


def build_and_run(cdir: Path, tmp: Path, build: tuple, n: int) -> dict:
    """One build of the probe and its run: the build's settings and the cases' tallies."""
    cc, lib, app, env, note = build
    tag = "-".join([cc, *lib, *sorted(env)]).replace("=", "")
    objs = []
    for k in KERNELS:
        obj = tmp / f"{k}-{tag}.o"
        subprocess.run([cc, "-std=c99", *lib, "-I", str(cdir), "-c",
                        str(cdir / f"rigidsym_c_{k}.c"), "-o", str(obj)], check=True,
                       capture_output=True)
        objs.append(str(obj))
    exe = tmp / f"probe-{tag}"
    subprocess.run([cc, "-std=gnu99", *app, "-I", str(cdir), str(PROBE), *objs, "-lm", "-o",
                    str(exe)], check=True, capture_output=True)
    p = subprocess.run([str(exe), str(n)], env=dict(os.environ, **env), check=True,
                       capture_output=True, text=True)
    lines = [json.loads(line) for line in p.stdout.splitlines() if line.strip()]
    version = subprocess.run([cc, "--version"], capture_output=True, text=True).stdout
    return {"compiler": version.splitlines()[0], "library_flags": lib,
            "application_flags": app, "env": env, "isolates": note,
            "mxcsr_at_main": lines[0]["mxcsr_at_main"], "cases": lines[1:]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--c-dir", type=Path, help="a C target folder with both kernels "
                    "(default: generated now)")
    ap.add_argument("--n", type=int, default=20000, help="samples per case")
    ap.add_argument("--label", default="", help="what the C folder is (free text)")
    ap.add_argument("--json", type=Path, help="write the record here")
    args = ap.parse_args(argv)
    if platform.machine() not in ("x86_64", "AMD64"):
        print("c_status_probe: x86-64 only (it reads MXCSR)", file=sys.stderr)
        return 2
    missing = [cc for cc in ("gcc", "clang") if shutil.which(cc) is None]
    if missing:
        print(f"c_status_probe: no {missing[0]} on PATH", file=sys.stderr)
        return 2
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    doc = {"host": host(), "commit": commit, "label": args.label, "n": args.n, "builds": []}
    with tempfile.TemporaryDirectory(prefix="rigidsym-status-") as tmp:
        t = Path(tmp)
        cdir = args.c_dir or generated(t / "c")
        doc["c_dir"] = str(args.c_dir) if args.c_dir else "generated from this checkout"
        for build in BUILDS:
            rec = build_and_run(cdir.resolve(), t, build, args.n)
            doc["builds"].append(rec)
            print(f"== {rec['compiler']}: library {' '.join(rec['library_flags'])}, "
                  f"application {' '.join(rec['application_flags'])} {rec['env'] or ''} "
                  f"(MXCSR {rec['mxcsr_at_main']})")
            for c in rec["cases"]:
                print(f"   {c['case']:40s} flagged {c['flagged']:6d}/{c['n']}, range test "
                      f"{c['range_test_fires']:6d}, raised {c['flagged_raised']}, max rel err "
                      f"{c['max_rel_err']}, silent wrongs {c['silent_wrong_16u']}")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        part = args.json.with_suffix(".part")
        part.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
        part.replace(args.json)
    return 0


if __name__ == "__main__":
    sys.exit(main())
