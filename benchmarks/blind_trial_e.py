"""Run the fifth blind trial (tests/data/blind_trial_e.json) through ``rigidsym.check_latex`` and
write benchmarks/results/blind_trial_e.json: each statement's verdict as typed, judged by the
NumPy truth committed before the checker read it (right / WRONG / undecided, with the tool's
reason), the fraction decided as typed, and the machine it ran on.

    PYTHONPATH=src python benchmarks/blind_trial_e.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # the same answer, judged and recorded the same way

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_e.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_e.json"

#: what each statement that is not right as typed shows; written after the run, the
#: statements unchanged (empty until then)
NOTES: dict[str, str] = {}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
