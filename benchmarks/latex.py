"""Benchmark: parse the chapter's 181 LaTeX strings with the lark reader.

Target: <= 2 s in all on the 2-core machine. Run: ``python benchmarks/latex.py``.
Reports the parser's construction (once per process) apart from the parses themselves.

Then the wall time of ``rigidsym check --latex`` (target: ``verified`` in
under 2 s): the acceptance command run ``RUNS`` times as a fresh process, the imports alone
in a fresh process, and ``rigidsym.check_latex`` in this process.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time

RUNS = 5
ACCEPTANCE = ["check", "--latex", r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", "--let",
              r"\mathbf{Q}: rotation"]


def main() -> None:
    from rigidsym.latex import LatexError, parse_latex
    from rigidsym.latex.transformer.chapter import parser
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    eqs = list(REGISTRY.values())
    t0 = time.perf_counter()
    parser()
    t1 = time.perf_counter()
    ok = 0
    for eq in eqs:
        try:
            parse_latex(eq.latex, eq.section)
            ok += 1
        except LatexError:
            pass
    t2 = time.perf_counter()
    print(f"lark parser built in {t1 - t0:.2f} s; {len(eqs)} strings ({ok} parsed, the rest "
          f"prose, integrals or index notation) in {t2 - t1:.2f} s; total {t2 - t0:.2f} s")


def _wall(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    return time.perf_counter() - t0


def check_command() -> None:
    import rigidsym

    cmd = [sys.executable, "-m", "rigidsym", *ACCEPTANCE]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    assert "Verdict: verified" in out, out
    walls = [_wall(cmd) for _ in range(RUNS)]
    imports = [_wall([sys.executable, "-c", "import rigidsym.api, rigidsym.checking.checker, "
                      "rigidsym.latex.statement, rigidsym.report.show"]) for _ in range(RUNS)]
    t0 = time.perf_counter()
    r = rigidsym.check_latex(ACCEPTANCE[2], [ACCEPTANCE[4]])
    t1 = time.perf_counter()
    print(f"rigidsym check --latex (Q^T Q = 1, Q a rotation): {r.verdict}; wall time of the "
          f"command {statistics.median(walls):.2f} s median of {RUNS} (min {min(walls):.2f}, "
          f"max {max(walls):.2f}); its imports alone {statistics.median(imports):.2f} s; "
          f"check_latex in-process {t1 - t0:.2f} s")


if __name__ == "__main__":
    main()
    check_command()
