"""The package's kernels built with GCC's precompiled ``rigidsym_common.h`` and without it,
side by side, each from an empty object cache.

Builds ``generated/`` as an editable install does (the best path this CPU runs,
:func:`rigidsym.kernels.cbuild.paths.host_paths`), once with the precompiled header (the
default under GCC) and once with ``RIGIDSYM_PCH=0`` (the header read as text by every
object), in that order or the other (``--text-first``), and records for each the objects
compiled, the build's wall seconds, the compilers' CPU seconds (the driver's ``stats``) and
the SHA-256 of the linked module: the two modules are the same bytes.

    python benchmarks/precompiled_header.py [--json benchmarks/results/precompiled_header.json]
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import json
import os
import tempfile
from pathlib import Path
from unittest import mock

from test_command import host

from rigidsym.kernels.cbuild import driver, objects, paths

ROOT = Path(__file__).resolve().parents[1]


def build_once(pch: bool) -> dict:
    """One cold build of ``generated/`` at this CPU's best path; the driver's figures and
    the module's digest."""
    cfg = driver.configure()
    cfg = dataclasses.replace(cfg, paths=paths.host_paths(cfg.paths))
    stats: dict = {}
    with tempfile.TemporaryDirectory() as tmp, mock.patch.dict(os.environ, {
            "RIGIDSYM_PCH": "1" if pch else "0",
            "RIGIDSYM_OBJECT_CACHE": str(Path(tmp) / "objects")}):
        out = driver.build(ROOT / "generated", Path(tmp) / "_ckernels.so", cfg,
                           Path(tmp) / "work", stats=stats)
        digest = hashlib.sha256(out.read_bytes()).hexdigest()
    return {"precompiled header": pch, "paths": [p.name for p in cfg.paths],
            "objects": stats["objects"], "compiled": stats["compiled"],
            "wall s": stats["seconds"], "cpu s": stats["cpu_seconds"], "module sha256": digest}


def main(argv: list[str] | None = None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", type=Path, help="write the record here")
    ap.add_argument("--text-first", action="store_true", help="build without it first")
    args = ap.parse_args(argv)
    cc = driver.compiler()
    if cc is None:
        raise SystemExit("no C compiler")
    order = (False, True) if args.text_first else (True, False)
    runs = [build_once(pch) for pch in order]
    by = {r["precompiled header"]: r for r in runs}
    rec = {"machine": {**host(), "compiler": objects.compiler_id(tuple(cc)).splitlines()[0],
                       "load before": list(os.getloadavg())},
           "runs": runs,
           "cpu ratio": round(by[True]["cpu s"] / by[False]["cpu s"], 3),
           "wall ratio": round(by[True]["wall s"] / by[False]["wall s"], 3),
           "same module": by[True]["module sha256"] == by[False]["module sha256"]}
    for r in runs:
        print(f"precompiled header {'yes' if r['precompiled header'] else 'no ':3}: "
              f"{r['compiled']} objects, {r['wall s']:.1f} s wall, {r['cpu s']:.1f} s CPU")
    print(f"CPU ratio {rec['cpu ratio']}, wall ratio {rec['wall ratio']}, "
          f"same module bytes: {rec['same module']}")
    if args.json:
        args.json.write_text(json.dumps(rec, indent=1) + "\n", encoding="utf-8")
    return rec


if __name__ == "__main__":
    main()
