"""The estimation and Lie-theory books' trial: every statement of
``tests/data/estimation_books_typed.py`` (Forster et al., Kok-Hol-Schön, Chirikjian, Eade)
through ``rigidsym.check_latex`` as typed, judged by the data file's own NumPy truth.

Writes ``benchmarks/results/latex_trial_lie_books.json``: per statement its book, section,
LaTeX, ``--let``s, whether it is a slip, the truth (holds at five random points or not), the
verdict, the answer (``right``: the verdict agrees with the truth; ``WRONG``; ``refused``:
bad input; ``undecided``), the message of a refusal or the reason of an undecided, and the
seconds it took; and the totals per book.

    PYTHONPATH=src python benchmarks/latex_trial_lie_books.py [--timeout S] [--only ID ...]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import resource
import time
from pathlib import Path

import numpy as np

import rigidsym
from rigidsym.report.markdown import undecided_reasons

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "data" / "estimation_books_typed.py"
OUT = ROOT / "benchmarks" / "results" / "latex_trial_lie_books.json"


def load_trial():
    """The data module of the trial (tests/data is no package)."""
    spec = importlib.util.spec_from_file_location("estimation_books_typed", DATA)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def holds(trial, case: dict, seed: int = 81, points: int = 5) -> bool:
    """The NumPy truth of ``case``: its residual below the trial's tolerance at ``points``
    random points drawn from ``seed``."""
    rng = np.random.default_rng(seed)
    return max(case["truth"](rng) for _ in range(points)) < trial.TRUTH_TOLERANCE


def judge(trial, case: dict, timeout: float | None = 60.0) -> dict:
    """One statement through ``rigidsym.check_latex`` (repairs off), judged by its truth.

    Returns:
        ``verdict`` (or ``refused``), ``answer`` (right / WRONG / refused / undecided),
        ``truth`` (True: it holds), ``message`` (a refusal's text or an undecided's reason,
        else empty) and ``cpu_s`` (process CPU seconds of the check)."""
    truth = holds(trial, case)
    t0 = time.process_time()
    message = ""
    try:
        r = rigidsym.check_latex(case["latex"], let=case["let"], repairs=False, timeout=timeout)
        verdict = r.verdict
        if verdict == "undecided":
            message = "; ".join(undecided_reasons(r.to_json()))
    except ValueError as e:
        verdict, message = "refused", str(e)
    cpu = time.process_time() - t0
    if verdict in ("refused", "undecided"):
        answer = verdict
    else:
        answer = "right" if (verdict in ("verified", "definition")) == truth else "WRONG"
    return {"verdict": verdict, "answer": answer, "truth": truth, "message": message[:600],
            "cpu_s": round(cpu, 2)}




def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--timeout", type=float, default=60.0, help="check_latex's limit, seconds")
    ap.add_argument("--only", nargs="*", default=None, help="case ids (default: all)")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args()
    from test_command import commit, host  # the host as the other records name it

    machine, load = host(), [round(x, 2) for x in os.getloadavg()]
    trial = load_trial()
    cases = [c for c in trial.CASES if args.only is None or c["id"] in args.only]
    rows = []
    for c in cases:
        row = {"id": c["id"], "book": c["book"], "where": c["where"], "slip": c["slip"],
               "latex": c["latex"], "let": c["let"], **judge(trial, c, args.timeout)}
        print(f"{row['answer']:9s} {row['verdict']:14s} {row['cpu_s']:6.1f}s {c['id']}", flush=True)
        rows.append(row)
    books: dict = {}
    for row in rows:
        b = books.setdefault(row["book"], {"statements": 0, "slips": 0, "right": 0, "WRONG": 0,
                                           "refused": 0, "undecided": 0})
        b["statements"] += 1
        b["slips"] += row["slip"]
        b[row["answer"]] += 1
    total = {k: sum(b[k] for b in books.values()) for k in
             ("statements", "slips", "right", "WRONG", "refused", "undecided")}
    total["decided_percent"] = round(100 * total["right"] / max(total["statements"], 1), 1)
    out = {"what": "tests/data/estimation_books_typed.py through rigidsym.check_latex as typed "
                   "(repairs off), judged by its NumPy truth",
           "commit": commit(), "host": machine, "load_before": load,
           "timeout_s": args.timeout,
           "max_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
           "total": total, "books": books, "cases": rows}
    if args.only is None:
        args.out.write_text(json.dumps(out, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    print(json.dumps(total))


if __name__ == "__main__":
    main()
