"""A newcomer's first hour, replayed: the longest silence of each step.

A fresh clone of this checkout's HEAD (``shared/`` linked beside it, as CI has it), a fresh
virtual environment and empty caches (``XDG_CACHE_HOME``: the object cache; no
``RIGIDSYM_CACHE``), then the steps a reader of README.md takes, each as printed there: the
README's install (``pip install -v .``, the wheel's build of every path), ``rigidsym
verify``, ``rigidsym show 3.96e``, ``rigidsym report --out notes/``, a kernel called by
keyword from Python, and the README's two ``check --latex`` examples. Each step's output
(stdout and stderr through one pipe, as a terminal shows them, ``\\r`` ending a line too) is
read as it comes; the record keeps each step's wall time, exit code, number of lines, and
its longest silence: the largest gap between the start, each line and the exit. The target
is no silence over 3 s (the progress lines of the build, of ``verify`` and ``report``).

    python benchmarks/first_hour.py --json benchmarks/results/first_hour.json

pip's own download cache is kept (the registry's speed is not the project's).
"""

from __future__ import annotations

import argparse
import json
import os
import selectors
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]

KERNEL_CALL = ("import numpy as np\n"
               "from rigidsym import kernels\n"
               "Q = kernels.rotation_from_natural_invariants(e=[0.0, 0.6, 0.8], "
               "phi=np.linspace(0.5, 3, 5))\n"
               "print(Q.shape)\n")
LATEX_VERIFIED = ["rigidsym", "check", "--latex", r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}",
                  "--let", r"\mathbf{Q}: rotation"]
LATEX_SLIP = ["rigidsym", "check", "--latex",
              r"\mathbf{Q} = \mathbf{1} - \sin\phi\,\mathbf{E} + (1-\cos\phi)\mathbf{E}^2",
              "--let", r"\mathbf{e}: unit vector; \phi: angle",
              "--let", r"\mathbf{E} = \mathrm{CPM}(\mathbf{e})",
              "--let", r"\mathbf{Q} = \mathbf{e}\mathbf{e}^T + \cos\phi(\mathbf{1} - "
                       r"\mathbf{e}\mathbf{e}^T) + \sin\phi\,\mathbf{E}"]


def steps(py: Path) -> list[tuple[str, list[str], set[int]]]:
    """(name, argv, the exit codes README.md gives) of each step, ``py`` the venv's Python."""
    bin_ = py.parent
    return [
        ("pip install -v .", [str(py), "-m", "pip", "install", "-v", "."], {0}),
        ("rigidsym verify", [str(bin_ / "rigidsym"), "verify"], {0}),
        ("rigidsym show 3.96e", [str(bin_ / "rigidsym"), "show", "3.96e"], {0}),
        ("rigidsym report --out notes/", [str(bin_ / "rigidsym"), "report", "--out", "notes"],
         {0}),
        ("a kernel by keyword", [str(py), "-c", KERNEL_CALL], {0}),
        ("check --latex (verified)", [str(bin_ / "rigidsym"), *LATEX_VERIFIED[1:]], {0}),
        ("check --latex (a slip)", [str(bin_ / "rigidsym"), *LATEX_SLIP[1:]], {1}),
    ]


def watch(argv: list[str], cwd: Path, env: dict) -> dict:
    """Run ``argv``; its wall time, exit code, lines and longest silence (seconds)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(argv, cwd=cwd, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    sel = selectors.DefaultSelector()
    sel.register(p.stdout, selectors.EVENT_READ)
    last, longest, where, lines, tail = t0, 0.0, "before the first line", 0, b""
    while True:
        if not sel.select(timeout=0.2):
            continue
        chunk = os.read(p.stdout.fileno(), 65536)
        now = time.perf_counter()
        if not chunk:
            break
        ends = chunk.count(b"\n") + chunk.count(b"\r")
        if ends:
            if now - last > longest:
                longest, where = now - last, tail.decode(errors="replace")[-120:] or where
            lines += ends
            last = now
            tail = chunk.replace(b"\r", b"\n").rstrip(b"\n").rsplit(b"\n", 1)[-1]
    rc = p.wait()
    end = time.perf_counter()
    if end - last > longest:
        longest, where = end - last, "after the last line: " + tail.decode(errors="replace")[-100:]
    return {"wall_s": round(end - t0, 2), "rc": rc, "lines": lines,
            "longest_silence_s": round(longest, 2), "silence_after": where}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", type=Path, help="write the record here")
    ap.add_argument("--limit", type=float, default=3.0, help="the longest silence allowed")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="rigidsym-first-hour-") as t:
        tmp = Path(t)
        clone = tmp / "rigidsym"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        if (ROOT.parent / "shared").is_dir():
            (tmp / "shared").symlink_to(ROOT.parent / "shared")
        env = {k: v for k, v in os.environ.items()
               if not k.startswith(("RIGIDSYM_", "VIRTUAL_ENV", "PYTHON"))}
        env["XDG_CACHE_HOME"] = str(tmp / "xdg-cache")
        subprocess.run([sys.executable, "-m", "venv", str(tmp / "venv")], check=True)
        env["PATH"] = f"{tmp / 'venv' / 'bin'}:{env.get('PATH', '')}"
        env["VIRTUAL_ENV"] = str(tmp / "venv")
        doc = {"host": host(), "load_before": os.getloadavg(), "commit": subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=clone, capture_output=True, text=True).stdout.strip(),
            "limit_s": args.limit, "steps": []}
        for name, cmd, ok in steps(tmp / "venv" / "bin" / "python"):
            r = {"step": name, **watch(cmd, clone, env)}
            r["as_documented"] = r["rc"] in ok
            doc["steps"].append(r)
            print(f"{name:32s} {r['wall_s']:7.1f} s  rc {r['rc']}  {r['lines']:5d} lines  "
                  f"longest silence {r['longest_silence_s']:5.1f} s ({r['silence_after'][:60]})",
                  flush=True)
        doc["load_after"] = os.getloadavg()
        doc["longest_silence_s"] = max(s["longest_silence_s"] for s in doc["steps"])
        doc["all_as_documented"] = all(s["as_documented"] for s in doc["steps"])
        shutil.rmtree(clone / "notes", ignore_errors=True)
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        part = args.json.with_suffix(".part")
        part.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
        part.replace(args.json)
    return 0 if doc["all_as_documented"] and doc["longest_silence_s"] <= args.limit else 1


if __name__ == "__main__":
    sys.exit(main())
