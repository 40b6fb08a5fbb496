"""The ninth blind trial, run once: the 61 statements of tests/data/blind_trial_i.json (ten
sources: Titterton & Weston, Jekeli, Wen & Kreutz-Delgado, Hibbeler, Beer & Johnston, Kleppner &
Kolenkow, Hand & Finch, Jose & Saletan, Fowles & Cassiday, Waldron & Kinzel; 24 of them one-edit
slips), each handed to ``rigidsym.check_latex`` exactly as typed and judged against the NumPy
truth (tests/blind_trial_i_truth.py) committed before the checker met it. The record,
benchmarks/results/blind_trial_i.json, counts the statements decided as typed, names every wrong
verdict (one the truth contradicts) and every refusal with the tool's reason, beside the commit,
host and load.

    PYTHONPATH=src python benchmarks/blind_trial_i.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # every trial judges and records through one runner

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_i.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_i.json"

#: what each statement that is not right as typed shows; written after the first run from its
#: record and the same statements respelt, the statements unchanged.
NOTES: dict[str, str] = {}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
