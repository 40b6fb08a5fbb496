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

#: what each statement that is not right as typed shows (none of the NumPy truths was typed
#: wrong); written after the run from the record and the docs, the statements and the record
#: (benchmarks/results/blind_trial_f.json, as first run, without these notes) unchanged. No
#: verdict is wrong; the 10 misses are refusals (bad input), none undecided.
_LABEL_FN = (r"refused: a --let function whose name carries a superscript frame label "
             r"(Beard's R_{v2}^b(\phi), R_v^{v1}(\psi), R_v^b(\phi,\theta,\psi)) cannot be "
             r"read ('unexpected b'), though a model of such a name reads (Groves' C_b^n); the "
             r"message does not say what to write. With the labels folded into the subscript "
             r"(R_{v2b}) it is decided rightly")
_UNUSED = (r"refused, typed against the docs: a --let of a symbol the statement never uses (one "
           r"set of declarations shared by the book's statements) is bad input naming it; with "
           r"that --let dropped it is decided rightly")
NOTES: dict[str, str] = {
    "bm-rvb": _LABEL_FN,
    "bm-quat-euler": _LABEL_FN,
    "bm-quat-euler-slip": _LABEL_FN,
    "nk-omega": _UNUSED,
    "nk-omega-slip": _UNUSED,
    "nk-body-omega": r"refused, typed against the docs: the unused --let of \mathbf{G} is bad "
    r"input; with it dropped, \tilde{\boldsymbol\omega}' (the book's tilde of omega') is read "
    r"as the glyph \tilde{\boldsymbol{\omega}}', so the declared \boldsymbol\omega' 'does not "
    r"occur' (the message lists the glyph, not what to write); \tilde{\boldsymbol\omega'} is "
    r"decided rightly",
    "hg-tilde-comm": r"refused: a tilde over a juxtaposed product, Haug's "
    r"\widetilde{\tilde{\mathbf{a}}\mathbf{b}}, is a syntax error ('expected one of: }'), "
    r"though a cross product under the tilde reads; the message does not point at "
    r"[\tilde{\mathbf{a}}\mathbf{b}]_\times or (\tilde{\mathbf{a}}\mathbf{b})^\wedge, both "
    r"decided rightly",
    "hg-tilde-comm-slip": "refused: as hg-tilde-comm",
    "hg-gdot": _UNUSED,
    "hg-pdot": _UNUSED,
}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
