"""Benchmark: parse the chapter's 181 LaTeX strings with the lark reader (issue 29).

Target: <= 2 s in all on the 2-core machine. Run: ``python benchmarks/latex.py``.
Reports the parser's construction (once per process) apart from the parses themselves.
"""

from __future__ import annotations

import time


def main() -> None:
    from rigidsym.checking.deciding.registry import REGISTRY, load_all
    from rigidsym.latex import LatexError, parse_latex
    from rigidsym.latex.parser import parser

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


if __name__ == "__main__":
    main()
