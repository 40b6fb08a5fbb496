"""The seventh blind trial, run once: the 51 statements of tests/data/blind_trial_g.json (seven
sources: Paul, Altmann, Arnold, Curtis, Sidi, Vince, Bottema & Roth; 20 of them slips), each
handed to ``rigidsym.check_latex`` exactly as typed and judged against the NumPy truth that
was committed before the checker met it. The record, benchmarks/results/blind_trial_g.json,
counts the statements decided as typed and names every wrong verdict (a verdict the truth
contradicts) and every refusal with the tool's reason, beside the commit, host and load.

    PYTHONPATH=src python benchmarks/blind_trial_g.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # every trial judges and records through one runner

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_g.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_g.json"

#: what each statement that is not right as typed shows, written after the run
NOTES: dict[str, str] = {}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
