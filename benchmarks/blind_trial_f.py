"""The sixth blind trial, run once: each statement of tests/data/blind_trial_f.json (seven
sources: Schaub & Junkins, Hughes, Fossen, Beard & McLain, Nikravesh, Haug, Wertz) read by
``rigidsym.check_latex`` exactly as typed, its verdict judged by the NumPy truth committed
before the checker met it, and the record written to benchmarks/results/blind_trial_f.json:
how many are decided as typed, which verdicts are wrong (a verdict against the truth), and
each refusal's reason, with the commit, host and load it ran on.

    PYTHONPATH=src python benchmarks/blind_trial_f.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # one runner for every trial: the same judging and record

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_f.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_f.json"

#: what each statement that is not right as typed shows; empty until the first run's record
#: is read (the statements and the record stay as first run)
NOTES: dict[str, str] = {}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
