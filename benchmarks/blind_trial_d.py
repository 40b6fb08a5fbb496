"""Run the fourth blind trial (tests/data/blind_trial_d.json) through ``rigidsym.check_latex`` and
write benchmarks/results/blind_trial_d.json: each statement's verdict as typed, judged by the
NumPy truth committed before the checker read it (right / WRONG / undecided, with the tool's
reason), the fraction decided as typed, and the machine it ran on.

    PYTHONPATH=src python benchmarks/blind_trial_d.py [--timeout S] [ID ...]
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

from blind_trial_c import run_case  # the same answer, judged the same way

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_d.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_d.json"


#: what each statement that is not right as typed shows (none of the NumPy truths was typed
#: wrong); written after the run, the statements unchanged. No verdict is wrong; the 10 misses
#: are refusals (bad input), none undecided.
NOTES = {
    "gin-ke-invariant": r"refused: Ginsberg's column-matrix braces \{\omega\} cannot be a "
    r"--let NAME nor read in the LaTeX ('unknown macro \{'); the braces draw a column matrix "
    "and group nothing",
    "mr-energy": r"refused: \mathbb{I} (Marsden & Ratiu's inertia tensor) cannot be a --let "
    r"NAME ('expected one symbol as NAME ... got \mathbb{I}'); the reader knows \mathbb{I} only "
    "as Chirikjian's identity block",
    "mr-energy-slip": "refused: as mr-energy",
    "mhp-vex-pa": r"refused: \mathrm{vex} cannot name a --let function ('unknown operator "
    r"vex'), though \mathrm{Exp} and \mathrm{Log} can (docs/check-latex.md); MHP's vex has no "
    r"spelling but (.)^\vee",
    "mhp-measurement": "refused: as mhp-vex-pa",
    "mhp-error-dynamics": r"refused: a dot over an accented glyph is mis-keyed: the rate model "
    r"\dot{\hat{R}} is read as the glyph \hat\dot{\hat{R}} and the statement's "
    r"\dot{\tilde{R}} (the rate of the model \tilde{R}) as \tilde\dot{\tilde{R}} (the message "
    r"names these doubled glyphs); \dot{E} of a model E reads",
    "mhp-error-dynamics-slip": "refused: as mhp-error-dynamics",
    "gal-se3-exp": "refused with sympy's raw exception text ('a matrix whose blocks do not fit: "
    "When there are not the same number of rows ... see Matrix.irregular'): the bottom row "
    r"0 & 0 of two plain zeros under [B & U] is not sized; written \mathbf{0}^T & 0 the "
    "statement is verified (a probe, not recorded)",
    "gal-se3-exp-slip": "refused: as gal-se3-exp",
    "gal-jacobi": "refused as documented: e^{tr B} is a scalar exponential, which the engine "
    "does not decide; the message gives the value to write (det e^X = 1 for X in so(3))",
}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--timeout", type=float, default=60.0, help="CPU seconds per statement")
    ap.add_argument("ids", nargs="*")
    a = ap.parse_args()
    from test_command import commit, host  # the host as the other records name it

    machine, load = host(), [round(x, 2) for x in os.getloadavg()]
    cases = json.loads(DATA.read_text())["cases"]
    rows = []
    w0, c0 = time.perf_counter(), time.process_time()
    for case in cases:
        if a.ids and case["id"] not in a.ids:
            continue
        row = run_case(case, a.timeout)
        row["truth"] = case["truth"]
        if case["id"] in NOTES:
            row["note"] = NOTES[case["id"]]
        rows.append(row)
        print(row["id"], row["verdict"], row["judged"], row["cpu_s"],
              row.get("reason", "")[:300].replace("\n", " | "), flush=True)
    n = len(rows)
    decided = sum(r["judged"] != "undecided" for r in rows)
    wrong = [r["id"] for r in rows if r["judged"] == "WRONG"]
    record = {"data": "tests/data/blind_trial_d.json", "commit": commit(), "host": machine,
              "load_before": load, "timeout_cpu_s": a.timeout,
              "wall_s": round(time.perf_counter() - w0, 1),
              "cpu_s": round(time.process_time() - c0, 1),
              "n": n, "decided_as_typed": decided,
              "decided_fraction": round(decided / n, 4) if n else None,
              "wrong": wrong, "rows": rows}
    if not a.ids:
        OUT.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n")
    print(json.dumps({k: record[k] for k in ("n", "decided_as_typed", "decided_fraction",
                                              "wrong", "wall_s", "cpu_s")}))


if __name__ == "__main__":
    main()
