"""What the build costs: `pip install .` in a fresh virtual environment, the build
step alone, a second build served by the object cache, and what each CPU path costs.

    python benchmarks/build.py [--results] [--skip-venv]

Every figure is one run, wall time and CPU time (user + system of every process the step
started: pip, the compilers), with the machine's 1-minute load average when the step began.
The build steps run with build isolation, as a user's `pip install .` does, and an object
cache of their own (``RIGIDSYM_OBJECT_CACHE``, empty at first): the reader's cache is never
read. ``--results`` writes the section ``build`` of ``benchmarks/RESULTS.md``.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT / "src") not in sys.path:
    sys.path.insert(0, str(ROOT / "src"))

from rigidsym.kernels.cbuild import driver as _build  # noqa: E402

BEGIN, END = "<!-- build -->", "<!-- /build -->"


def _timed(argv: list[str], env: dict, cwd: Path) -> tuple[float, float, float]:
    """(wall s, CPU s of the children, load average at the start) of one command."""
    load = os.getloadavg()[0]
    r0, t0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    p = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed:\n{p.stdout[-3000:]}{p.stderr[-3000:]}")
    return wall, r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime, load


def _copy(dest: Path) -> Path:
    skip = shutil.ignore_patterns(".git", "build", "dist", "*.egg-info", "__pycache__",
                                  ".venv", ".pytest_cache", ".ruff_cache", "_ckernels*")
    shutil.copytree(ROOT, dest, ignore=skip)
    return dest


def measure(skip_venv: bool) -> list[tuple[str, float, float, float]]:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        src = _copy(tmp / "src")
        env = dict(os.environ, RIGIDSYM_OBJECT_CACHE=str(tmp / "objects"))
        env.pop("RIGIDSYM_PATHS", None)
        if not skip_venv:
            subprocess.run([sys.executable, "-m", "venv", str(tmp / "venv")], check=True)
            pip = [str(tmp / "venv" / "bin" / "python"), "-m", "pip", "install", "-q"]
            rows.append(("`pip install .` in a fresh venv (dependencies from pip's cache), "
                         "empty object cache", *_timed([*pip, str(src)], env, tmp)))
            shutil.rmtree(tmp / "objects")
        wheel = [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w"]
        rows.append(("the build step (`pip wheel --no-deps .`), empty object cache",
                     *_timed([*wheel, str(tmp / "w1"), str(src)], env, tmp)))
        rows.append(("the same build again: every object from the object cache",
                     *_timed([*wheel, str(tmp / "w2"), str(src)], env, tmp)))
        gdir = ROOT / "generated"
        for path in _build.X86_PATHS if _build._x86() else (_build.BASELINE,):
            one = dict(os.environ, RIGIDSYM_OBJECT_CACHE="0", RIGIDSYM_PATHS=path.suffix)
            code = ("import sys; from pathlib import Path; from rigidsym.kernels import _build;"
                    f"_build.build(Path({str(gdir)!r}), Path(sys.argv[1]) / 'm.so',"
                    " _build.configure(), Path(sys.argv[1]))")
            work = tmp / f"path-{path.suffix}"
            work.mkdir()
            one["PYTHONPATH"] = str(ROOT / "src")
            rows.append((f"the {path.name} objects alone ({len(_build.kernel_sources(gdir / 'c'))}"
                         " sources and the module)",
                         *_timed([sys.executable, "-c", code, str(work)], one, tmp)))
    return rows


def _objects() -> str:
    """The objects a full build of this tree compiles, in words (``447 objects``)."""
    return f"{_build.object_count(ROOT / 'generated' / 'c', _build.configure())} objects"




def render(rows) -> str:
    from test_command import commit  # the checkout's commit, as the other records name it

    lines = [BEGIN, "## The build", "",
             "`python benchmarks/build.py --results`: one run of each step on "
             f"{os.cpu_count()} cores, {_objects()} at commit {commit()}; CPU = user + "
             "system of every process the step started (pip, the compilers).", "",
             "| step | wall s | CPU s | load at start |", "|---|---:|---:|---:|"]
    lines += [f"| {what} | {wall:.1f} | {cpu:.1f} | {load:.1f} |" for what, wall, cpu, load
              in rows]
    lines.append(END)
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--results", action="store_true", help="write RESULTS.md's section")
    ap.add_argument("--skip-venv", action="store_true", help="skip the fresh-venv install")
    args = ap.parse_args()
    block = render(measure(args.skip_venv))
    print(block)
    if args.results:
        from _results import write_section

        write_section(ROOT / "benchmarks" / "RESULTS.md", block, BEGIN, END)


if __name__ == "__main__":
    main()
