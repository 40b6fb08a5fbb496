"""An editable install's single path against a full build's dispatched paths, bit for bit.

An editable install compiles the best path this CPU runs, alone
(:func:`rigidsym.kernels.cbuild.paths.host_paths`): on an AVX-512 host every kernel at
x86-64-v4, where a full build (``pip install .``, the wheel) runs the kernels without sin/cos
at x86-64-v3. This script records every kernel's values and status codes (the C backend,
each kernel's inputs from ``tests/test_kernels.py`` at 257 points, seeds 0-2) under the
build installed now, and compares two such records bit for bit:

    RIGIDSYM_DISPATCH=x86-64-v3 python benchmarks/editable_paths.py record full-v3.npz
    python benchmarks/editable_paths.py record full.npz      # the full build, dispatched
    # ... reinstall editable (one path) ...
    python benchmarks/editable_paths.py record single.npz
    python benchmarks/editable_paths.py compare full.npz single.npz full-v3.npz --json F

``compare`` writes, for the first record against each other one, the kernels whose values
or status codes differ in any bit, with the builds' paths and compile times
(``build_info()["build"]``) as each record holds them.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SEEDS = (0, 1, 2)
POINTS = 257


def record(out: Path) -> None:
    """Every kernel's values and status codes under the installed build, into ``out``."""
    sys.path.insert(0, str(ROOT / "tests"))
    import test_kernels as T

    from rigidsym import kernels

    kernels.use_backend("c")
    arrays: dict[str, np.ndarray] = {}
    for name in T.PUBLIC + T.EULER:
        for seed in SEEDS:
            values, status = T.run(name, T.inputs(T.AVAILABLE[name], POINTS, seed=seed), "c")
            arrays[f"{name}/{seed}/values"] = np.asarray(values)
            arrays[f"{name}/{seed}/status"] = np.asarray(status)
    info = kernels.build_info()
    meta = {"path": info["path"], "paths": info["paths"], "forced": info["forced"],
            "build": info["build"], "cpu": info["cpu"]}
    np.savez(out, __meta__=np.array(json.dumps(meta)), **arrays)
    print(f"{out}: {len(arrays) // 2 // len(SEEDS)} kernels, path {meta['path']} of "
          f"{meta['paths']}")


def _bits(a: np.ndarray) -> np.ndarray:
    return a.view(np.uint8) if a.dtype.kind in "fciu" else a


def compare(first: Path, others: list[Path]) -> dict:
    """The kernels of ``first`` whose values or status differ in any bit in each of ``others``."""
    a = np.load(first)
    result = {"host": {"cpu": json.loads(str(a["__meta__"]))["cpu"], "cores": os.cpu_count(),
                       "machine": platform.machine()},
              "points_per_kernel": POINTS * len(SEEDS), "first": {
                  "file": first.name, **json.loads(str(a["__meta__"]))}, "against": []}
    for other in others:
        b = np.load(other)
        if set(a.files) != set(b.files):
            raise SystemExit(f"{other}: not the same kernels as {first}")
        differ = sorted({k.split("/")[0] for k in a.files if k != "__meta__"
                         and (a[k].shape != b[k].shape
                              or not np.array_equal(_bits(a[k]), _bits(b[k])))})
        kernels = len({k.split("/")[0] for k in a.files if k != "__meta__"})
        result["against"].append({"file": other.name, **json.loads(str(b["__meta__"])),
                                  "kernels": kernels, "differ_in_any_bit": differ})
    return result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("record", help="every kernel's values under the installed build")
    r.add_argument("out", type=Path)
    c = sub.add_parser("compare", help="the first record against each other one")
    c.add_argument("first", type=Path)
    c.add_argument("others", type=Path, nargs="+")
    c.add_argument("--json", type=Path, help="write the comparison here")
    args = ap.parse_args()
    if args.cmd == "record":
        record(args.out)
        return
    result = compare(args.first, args.others)
    text = json.dumps(result, indent=1)
    if args.json:
        args.json.write_text(text + "\n", encoding="utf-8")
    for o in result["against"]:
        print(f"{args.first.name} vs {o['file']} (path {o['path']} of {o['paths']}): "
              f"{len(o['differ_in_any_bit'])} of {o['kernels']} kernels differ "
              f"{o['differ_in_any_bit'][:8]}")


if __name__ == "__main__":
    main()
