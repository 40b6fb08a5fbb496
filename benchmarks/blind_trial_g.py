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

#: what each statement that is not right as typed shows (none of the NumPy truths was typed
#: wrong); written after the first run from its record, the docs and the same statements
#: respelt, the statements unchanged. No verdict is wrong; the 8 misses are refusals.
_BRACKET = (r"refused: Arnold's Lie bracket of two 3-vectors, [M, \Omega] (his cross product), "
            r"is bad input saying what to write (x \times y), but the message also names "
            r"B_{w}, the reader's own body velocity of B, which the user never wrote ('add "
            r"--let B_{w}: KIND'); written M \times \Omega it is decided rightly")
_CURTIS = (r"refused: Curtis' bracketed matrix name [\mathbf{Q}]_{Xx} (a two-letter subscript) "
           r"cannot be read ('unexpected Xx'), though [\mathbf{q}]_L is a name; the message "
           r"does not say what to write. Spelt \mathbf{Q}_{Xx} it is decided rightly")
_CHAIN = (r"refused, typed against the docs: the book's chain A = (1/Delta)[...] = (I - B)^{-1}"
          r"(I + B) with A undeclared (rule 10: A a scalar by the convention); the message asks "
          r"for --let 'A: KIND' or a model. Without 'A =' it is decided rightly; with --let "
          r"'A: matrix', as the message suggests first, the true statement is does-not-hold "
          r"(a free A is not the matrix: right under that reading, not what the book means)")
NOTES: dict[str, str] = {
    "ar-euler": _BRACKET,
    "ar-euler-slip": _BRACKET,
    "cu-kde": _CURTIS,
    "cu-kde-slip": _CURTIS,
    "cu-dcm": _CURTIS,
    "cu-dcm-slip": _CURTIS,
    "br-euler-params": _CHAIN,
    "br-euler-params-slip": _CHAIN,
}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
