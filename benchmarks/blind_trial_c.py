"""Run the third blind trial (tests/data/blind_trial_c.json) through ``rigidsym.check_latex`` and
write benchmarks/results/blind_trial_c.json: each statement's verdict as typed, judged by the
NumPy truth committed before the checker read it (right / WRONG / undecided, with the tool's
reason), and the fraction decided as typed.

    PYTHONPATH=src python benchmarks/blind_trial_c.py [--timeout S] [ID ...]
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

import rigidsym

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_c.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_c.json"


#: what each statement that is not right as typed shows (none of the NumPy truths was typed wrong)
NOTES = {
    "sz-product-otimes": "WRONG: Szeliski (2.41)-(2.42) stores q = (x, y, z, w), scalar last, and "
    "multiplies by Hamilton's rule (v0 x v1 + w0 v1 + w1 v0, w0 w1 - v0.v1), as Eigen and ROS do; "
    "the checker's readings of \\otimes tie the rule to the storage order (Hamilton: scalar "
    "first; JPL: scalar last, ij = -k), neither is the book's, both say does-not-hold, and the "
    "agreement is reported as a verdict. The same statement with the product written out "
    "(sz-product-written-out) is verified.",
    "jaz-omega-global": "refused: the dot of a frame-indexed name, {}^G\\dot{R}_B, is not read as "
    "the rate of the declared {}^G R_B(t) (it is an undeclared glyph of its own)",
    "jaz-omega-body": "refused: as jaz-omega-global",
    "sz-decomposition": "refused: the name \\mathbf{v}_\\times (Szeliski's v_x = n x v) cannot be "
    "declared: the subscript \\times is a parse error",
    "sl-euler-rates-slip": "undecided with a raw exception name (ZeroDivisionError while "
    "checking: tan(theta)); the true statement next to it is verified",
    "tm-angular-momentum": "refused: a thin space \\, inside parentheses, m(\\mathbf{r}^T"
    "\\mathbf{r}\\,I_3 - ...), is a parse error (\"unexpected ')' ... expected one of: , or "
    "\\quad\"); the same model without \\, reads",
    "tm-kinetic-energy": "refused: as tm-angular-momentum",
    "tm-kinetic-energy-slip": "refused: as tm-angular-momentum",
    "tm-rotated-inertia": "refused: as tm-angular-momentum",
    "tm-parallel-axis": "refused: as tm-angular-momentum",
    "tm-parallel-axis-slip": "refused: as tm-angular-momentum",
    "stw-jacobi": "refused: e^{A} of a 2x2 matrix is not read (only so(3)/se(3) exponents); "
    "Jacobi's formula det e^A = e^{tr A} of a general matrix cannot be stated",
}


def run_case(case: dict, timeout: float | None) -> dict:
    """The checker's answer to one case as typed, judged against its recorded truth."""
    t0 = time.process_time()
    try:
        r = rigidsym.check_latex(case["latex"], let=case["lets"], notation=case["notation"],
                                 repairs=False, timeout=timeout)
    except ValueError as exc:
        return {"id": case["id"], "verdict": "bad-input", "judged": "undecided",
                "reason": str(exc), "cpu_s": round(time.process_time() - t0, 2)}
    row = {"id": case["id"], "verdict": r.verdict, "cpu_s": round(time.process_time() - t0, 2)}
    if r.verdict == "undecided":
        row.update(judged="undecided", reason=r.detail or r.cause or "")
    else:
        said = r.verdict in ("verified", "definition")
        row["judged"] = "right" if said == case["truth"] else "WRONG"
        if row["judged"] == "WRONG":
            row["read_as"] = list(r.model)
    return row


def run_trial(data: Path, out: Path, notes: dict[str, str], *, provenance: bool = True) -> None:
    """The blind trials' one main (C, D, E): run each case of ``data`` as typed (or only the ids
    given), print a line each and, for a whole run, write the record to ``out``; with
    ``provenance`` the record names the commit, the host, the load and the wall/CPU time."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--timeout", type=float, default=60.0, help="CPU seconds per statement")
    ap.add_argument("--out", type=Path, default=None,
                    help="where a whole run's record goes (default: the trial's own record)")
    ap.add_argument("--note", default=None,
                    help="a note heading the record (an after-fix re-run says NOT BLIND and why)")
    ap.add_argument("ids", nargs="*")
    a = ap.parse_args()
    if a.out is not None:
        out = a.out
    head: dict = {"note": a.note} if a.note else {}
    head["data"] = data.relative_to(ROOT).as_posix()
    if provenance:
        from test_command import commit, host  # the host as the other records name it

        load = [round(x, 2) for x in os.getloadavg()]
        head.update(commit=commit(), host=host(), load_before=load)
    head["timeout_cpu_s"] = a.timeout
    cases = json.loads(data.read_text())["cases"]
    rows = []
    w0, c0 = time.perf_counter(), time.process_time()
    for case in cases:
        if a.ids and case["id"] not in a.ids:
            continue
        row = run_case(case, a.timeout)
        row["truth"] = case["truth"]
        if case["id"] in notes and not a.note:  # the blind run's notes, not an after-fix one's
            row["note"] = notes[case["id"]]
        rows.append(row)
        print(row["id"], row["verdict"], row["judged"], row["cpu_s"],
              row.get("reason", "")[:300].replace("\n", " | "), flush=True)
    n = len(rows)
    decided = sum(r["judged"] != "undecided" for r in rows)
    wrong = [r["id"] for r in rows if r["judged"] == "WRONG"]
    record = dict(head)
    if provenance:
        record.update(wall_s=round(time.perf_counter() - w0, 1),
                      cpu_s=round(time.process_time() - c0, 1))
    record.update(n=n, decided_as_typed=decided,
                  decided_fraction=round(decided / n, 4) if n else None, wrong=wrong, rows=rows)
    if not a.ids:
        out.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n")
    keys = ("n", "decided_as_typed", "decided_fraction", "wrong")
    print(json.dumps({k: record[k] for k in keys + (("wall_s", "cpu_s") if provenance else ())}))


def main() -> None:
    run_trial(DATA, OUT, NOTES, provenance=False)  # the third trial's record named no host


if __name__ == "__main__":
    main()
