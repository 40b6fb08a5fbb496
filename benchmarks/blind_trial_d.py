"""Run the fourth blind trial (tests/data/blind_trial_d.json) through ``rigidsym.check_latex`` and
write benchmarks/results/blind_trial_d.json: each statement's verdict as typed, judged by the
NumPy truth committed before the checker read it (right / WRONG / undecided, with the tool's
reason), the fraction decided as typed, and the machine it ran on.

    PYTHONPATH=src python benchmarks/blind_trial_d.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # the same answer, judged and recorded the same way

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
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
