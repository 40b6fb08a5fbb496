"""One run of the peer benchmark (``shared/peers-bench/run_all.py``) with rigidsym's column,
kept as a record under ``benchmarks/results/``: the harness's own JSON (every cell), the
host, the commit, the load average before and after, the command, and per kernel the ratio
of rigidsym's time to the fastest peer's in the same run.

Usage (from the repository root; ``PY`` a Python with the peers installed, see
``shared/peers-bench/README.md``)::

    python benchmarks/peers_record.py --python PY --out benchmarks/results/peers-1.json \\
        [--harness ../shared/peers-bench] [--N 1000000] [--pool] [--package-module]

``--pool``: the library's output pool on (``RIGIDSYM_OUTPUT_POOL=1``); ``--package-module``:
K4 and K6 (no public kernel) through the imported package's own compiled module
(``RIGIDSYM_PEERS_MODULE=package``, ``benchmarks/peers_adapter.py``). The peers are
``numpy, sf-cpp, c-sympy-cse, ca-c-batch, floor``; the fastest peer is the least of
``sf-cpp``, ``c-sympy-cse`` and ``ca-c-batch`` (``numpy`` is the reference, ``floor`` no
kernel).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PEERS = ("sf-cpp", "c-sympy-cse", "ca-c-batch")


def load() -> list[float]:
    """The load averages over 1, 5 and 15 minutes."""
    return [round(x, 2) for x in os.getloadavg()]


def summary(rows: list[dict], n: int) -> dict:
    """Per kernel at batch size ``n``: rigidsym's ns a sample, the fastest peer's and the ratio.

    Args:
        rows: the harness's JSON rows (``kernel``, ``N``, ``peer``, ``status``, ``ns``).
        n: the batch size to read.
    """
    out: dict = {}
    for k in sorted({r["kernel"] for r in rows}):
        cells = {r["peer"]: r["ns"] for r in rows
                 if r["kernel"] == k and r["N"] == n and r["status"] == "ok"}
        peers = {p: cells[p] for p in PEERS if p in cells}
        if "rigidsym-c" not in cells or not peers:
            continue
        best = min(peers, key=peers.get)
        out[k] = {"rigidsym_ns": round(cells["rigidsym-c"], 3), "fastest_peer": best,
                  "fastest_peer_ns": round(peers[best], 3),
                  "ratio": round(cells["rigidsym-c"] / peers[best], 3)}
    return out


def main(argv: list[str] | None = None) -> int:
    """Run the harness once and write the record; returns the exit status."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--python", required=True, help="a Python with the peers installed")
    ap.add_argument("--harness", default=str(ROOT.parent / "shared" / "peers-bench"))
    ap.add_argument("--N", type=int, default=1_000_000, help="the batch size (default 1e6)")
    ap.add_argument("--pool", action="store_true", help="RIGIDSYM_OUTPUT_POOL=1")
    ap.add_argument("--package-module", action="store_true",
                    help="K4/K6 through the imported package's module")
    ap.add_argument("--out", required=True, help="the record (JSON)")
    args = ap.parse_args(argv)
    harness = Path(args.harness)
    if not (harness / "run_all.py").is_file():
        ap.error(f"--harness: expected the peers-bench folder (with run_all.py), got {harness}")
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    if args.pool:
        env["RIGIDSYM_OUTPUT_POOL"] = "1"
    if args.package_module:
        env["RIGIDSYM_PEERS_MODULE"] = "package"
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "run.json"
        cmd = [args.python, "run_all.py", "--N", str(args.N),
               "--peers", "numpy,sf-cpp,c-sympy-cse,ca-c-batch,floor",
               "--extra", str(ROOT / "benchmarks" / "peers_adapter.py"),
               "--build-dir", str(Path(tmp) / "build"), "--json", str(raw)]
        before = load()
        proc = subprocess.run(cmd, cwd=harness, env=env, capture_output=True, text=True)
        after = load()
        if proc.returncode != 0 or not raw.exists():
            sys.stderr.write(proc.stderr[-4000:])
            return 1
        data = json.loads(raw.read_text())
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    flags = ((["RIGIDSYM_OUTPUT_POOL=1"] if args.pool else [])
             + (["RIGIDSYM_PEERS_MODULE=package"] if args.package_module else []))
    variant = next((ln.strip() for ln in proc.stderr.splitlines() if "rigidsym-c:" in ln), "")
    record = {"host": {"cpu": platform.processor() or data["env"][0], "cores": os.cpu_count(),
                       "python": platform.python_version(), "harness_env": data["env"]},
              "commit": commit, "load_before": before, "load_after": after,
              "command": " ".join(["PYTHONPATH=src", *flags, *cmd[1:]]),
              "variant": variant, "N": args.N, "summary": summary(data["rows"], args.N),
              "harness": data}
    Path(args.out).write_text(json.dumps(record, indent=1) + "\n")
    for k, v in record["summary"].items():
        print(f"{k}: rigidsym {v['rigidsym_ns']} ns, {v['fastest_peer']} {v['fastest_peer_ns']} ns,"
              f" ratio {v['ratio']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
