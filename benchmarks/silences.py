"""The longest silence of a command: how long a reader waits for its next line.

Starts ``--busy`` processes that spin (the load), runs each ``--command`` in bash with its
stdout and stderr merged into one pipe (what a log or CI shows; a terminal gets a live
display instead), and timestamps every line as it arrives (a line ends at ``\\n`` or
``\\r``). The record keeps the machine (CPU model, cores, Python), the commit, the load,
and per command its exit code, wall time, the wait for its first line, the longest gap
between two lines (the start and the exit count as lines) with the lines on both sides of
it, and the number of lines. The target (docs/setup.md, docs/commands.md) is no silence
over 3 s. ``benchmarks/first_hour.py`` replays the README's steps in a fresh clone with no
load; this script times any command under one.

    python benchmarks/silences.py --busy 2 --json benchmarks/results/silences.json \\
        --command 'rigidsym verify --sections 3.2' --command 'python -c "import rigidsym.cli"'
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
SPIN = "while True:\n    pass\n"


def watch(cmd: str, cwd: Path, timeout: float) -> dict:
    """Run ``cmd`` (bash), timestamping each line of its merged output; the silences."""
    t0 = time.perf_counter()
    p = subprocess.Popen(["bash", "-c", cmd], cwd=cwd, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    stamps: list[tuple[float, str]] = [(0.0, "(start)")]
    pending = b""
    while True:
        chunk = os.read(p.stdout.fileno(), 65536)
        now = time.perf_counter() - t0
        if not chunk:
            break
        pending += chunk.replace(b"\r", b"\n")
        *whole, pending = pending.split(b"\n")
        stamps.extend((now, line.decode("utf-8", "replace")) for line in whole)
        if now > timeout:
            p.kill()
            break
    rc = p.wait()
    end = time.perf_counter() - t0
    if pending:
        stamps.append((end, pending.decode("utf-8", "replace")))
    stamps.append((end, f"(exit {rc})"))
    gaps = [(b[0] - a[0], a, b) for a, b in zip(stamps, stamps[1:], strict=False)]
    longest, before, after = max(gaps, key=lambda g: g[0])
    return {"command": cmd, "rc": rc, "wall_s": round(end, 2),
            "first_line_s": round(stamps[1][0], 2),
            "longest_silence_s": round(longest, 2),
            "longest_silence_at_s": round(before[0], 2),
            "line_before": before[1][:200], "line_after": after[1][:200],
            "lines": len(stamps) - 2}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--busy", type=int, default=8,
                    help="spinning processes (default 8; on a shared machine fewer)")
    ap.add_argument("--command", action="append", required=True,
                    help="a command to run in bash in this checkout (repeatable)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per command")
    ap.add_argument("--json", type=Path, required=True)
    args = ap.parse_args(argv)
    spinners = [subprocess.Popen([sys.executable, "-c", SPIN]) for _ in range(args.busy)]
    runs = []
    try:
        time.sleep(2 if args.busy else 0)
        load_before = os.getloadavg()
        for cmd in args.command:
            r = watch(cmd, ROOT, args.timeout)
            print(f"{cmd}: rc {r['rc']}, {r['wall_s']} s, first line after "
                  f"{r['first_line_s']} s, longest silence {r['longest_silence_s']} s "
                  f"(before {r['line_after']!r})", flush=True)
            runs.append(r)
        load_after = os.getloadavg()
    finally:
        for s in spinners:
            s.kill()
            s.wait()
    doc = {"host": host(), "commit": subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT,
                                                   capture_output=True, text=True).stdout.strip(),
           "busy": args.busy, "load_before": load_before, "load_after": load_after,
           "runs": runs, "longest_silence_s": max(r["longest_silence_s"] for r in runs)}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    part = args.json.with_suffix(".part")
    part.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
    part.replace(args.json)
    return 1 if any(r["rc"] != 0 for r in runs) else 0


if __name__ == "__main__":
    sys.exit(main())
