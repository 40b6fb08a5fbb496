"""The README's test command as a newcomer runs it.

A fresh clone of this checkout's HEAD into a temporary folder (``shared/`` linked beside it,
as CI has it), a fresh virtual environment, empty caches (the object cache under an empty
``XDG_CACHE_HOME``, no ``RIGIDSYM_CACHE``), then the README's command verbatim, one ``&&``
part at a time so that each part's wall and CPU time (its children's user + system) is
known; pytest gets ``--durations=50`` appended, which changes what it prints, not what runs.
Prints the host (CPU model, cores, load average before and after) and a table; ``--json F``
writes the same figures. pip's own download cache is kept unless ``--cold-pip`` (the
registry's speed is not the project's).

    python benchmarks/test_command.py [--json out.json] [--cold-pip] [--keep]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def readme_command(readme: Path) -> str:
    """The README's test command, found as .ci/run finds it."""
    for line in readme.read_text(encoding="utf-8").splitlines():
        m = re.match(r'^    (pip install (?:-v )?-e "\.\[test\]".*)$', line)
        if m:
            return m.group(1)
    raise SystemExit("README.md has no test command")


def commit() -> str:
    """The checkout's short commit, or "unknown" outside a git checkout."""
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, text=True,
                              capture_output=True, check=True).stdout.strip() or "unknown"
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def host() -> dict:
    model = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {"cpu": model, "cores": os.cpu_count(), "python": sys.version.split()[0]}


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_part(cmd: str, cwd: Path, env: dict) -> dict:
    """One part of the command in bash; wall, CPU of its process tree, exit code, output."""
    c0, t0 = _children_cpu(), time.perf_counter()
    p = subprocess.run(["bash", "-c", cmd], cwd=cwd, env=env, capture_output=True, text=True)
    return {"command": cmd, "wall_s": round(time.perf_counter() - t0, 1),
            "cpu_s": round(_children_cpu() - c0, 1), "rc": p.returncode,
            "output_tail": (p.stdout + p.stderr)[-6000:]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", type=Path, help="write the figures here")
    ap.add_argument("--cold-pip", action="store_true", help="an empty pip cache too")
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder")
    args = ap.parse_args(argv)

    tmp = Path(tempfile.mkdtemp(prefix="rigidsym-newcomer-"))
    try:
        clone = tmp / "rigidsym"
        subprocess.run(["git", "clone", "-q", "--no-hardlinks", str(ROOT), str(clone)],
                       check=True)
        shared = ROOT.parent / "shared"
        if shared.is_dir():
            (tmp / "shared").symlink_to(shared)
        cache = tmp / "xdg-cache"
        cache.mkdir()
        env = {k: v for k, v in os.environ.items()
               if not k.startswith(("RIGIDSYM_", "VIRTUAL_ENV", "PYTHON"))}
        env["XDG_CACHE_HOME"] = str(cache)
        if args.cold_pip:
            env["PIP_NO_CACHE_DIR"] = "1"
        venv = tmp / "venv"
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
        env["PATH"] = f"{venv / 'bin'}:{env.get('PATH', '')}"
        env["VIRTUAL_ENV"] = str(venv)
        cmd = readme_command(clone / "README.md")
        parts = [p.strip() for p in cmd.split("&&")]
        commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=clone, capture_output=True,
                                text=True, check=True).stdout.strip()
        info = {"host": host(), "commit": commit, "load_before": os.getloadavg(),
                "command": cmd, "parts": []}
        t0 = time.perf_counter()
        for part in parts:
            if "pytest" in part:
                part += " --durations=50"
            res = run_part(part, clone, env)
            info["parts"].append(res)
            print(f"[{res['wall_s']:7.1f} s wall, {res['cpu_s']:7.1f} s CPU, rc {res['rc']}] "
                  f"{part}", flush=True)
            if res["rc"] != 0:
                print(res["output_tail"])
                break
        info["wall_s"] = round(time.perf_counter() - t0, 1)
        info["load_after"] = os.getloadavg()
        pytest_out = next((p["output_tail"] for p in info["parts"] if "pytest" in p["command"]),
                          "")
        print(f"\nhost: {info['host']['cpu']}, {info['host']['cores']} cores; load average "
              f"before {info['load_before'][0]:.2f}, after {info['load_after'][0]:.2f}")
        print(f"in all: {info['wall_s']} s wall\n")
        print(pytest_out[-5000:])
        if args.json:
            args.json.write_text(json.dumps(info, indent=1) + "\n", encoding="utf-8")
        return 0 if all(p["rc"] == 0 for p in info["parts"]) else 1
    finally:
        if args.keep:
            print(f"kept {tmp}")
        else:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
