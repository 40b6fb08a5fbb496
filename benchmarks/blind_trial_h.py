"""The eighth blind trial, run once: the 56 statements of tests/data/blind_trial_h.json (nine
sources: Rao, Meriam & Kraige, Kasdin & Paley, Uicker-Pennock-Shigley, Mason, Dai, Shoemake,
Horn, Zipfel; 23 of them one-edit slips), each handed to ``rigidsym.check_latex`` exactly as
typed and judged against the NumPy truth (tests/blind_trial_h_truth.py) committed before the
checker met it. The record, benchmarks/results/blind_trial_h.json, counts the statements
decided as typed, names every wrong verdict (one the truth contradicts) and every refusal with
the tool's reason, beside the commit, host and load.

    PYTHONPATH=src python benchmarks/blind_trial_h.py [--timeout S] [ID ...]
"""

from __future__ import annotations

from pathlib import Path

from blind_trial_c import run_trial  # every trial judges and records through one runner

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "blind_trial_h.json"
OUT = ROOT / "benchmarks" / "results" / "blind_trial_h.json"

#: what each statement that is not right as typed shows (none of the NumPy truths was typed
#: wrong); written after the first run from its record and the same statements respelt, the
#: statements unchanged. One verdict is wrong; the 20 misses are refusals.
_WRONG = (r"WRONG: the slip d/dt |omega|^2 = 0 of torque-free motion (the angular momentum "
          r"I omega typed omega) is verified: in the rate's model \dot{\boldsymbol\omega} = "
          r"-\mathbf{I}^{-1}(\boldsymbol\omega\times\mathbf{I}\boldsymbol\omega) the reader "
          r"takes \mathbf{I} for the identity ('no --let declares \mathbf{I}') and drops --let "
          r"'\mathbf{I} = \operatorname{diag}(I_1, I_2, I_3)' as 'not used' (a rate's model is "
          r"not searched for the names it uses); the second semantics is handed the same "
          r"reading, so omega dot = 0 and both agree. Spelt \mathbf{J} (and I_1..I_3 declared "
          r"scalars) it is does-not-hold")
_INERTIA = (r"refused, the message wrong twice: '\mathbf{I} does not occur in the LaTeX nor in a "
            r"model' (it is in the model of \mathbf{H}), 'the LaTeX's I_{xx}, ..., which no --let "
            r"declares' (still said with --let 'I_{xx}: scalar' for each, as the message asks); "
            r"with \mathbf{I} spelt \mathbf{J} it is decided rightly")
_KP_NAME = (r"refused: Kasdin & Paley's {}^{\mathcal{A}}\boldsymbol\omega^{\mathcal{B}} (a "
            r"calligraphic left index and label) 'cannot be read: unexpected }' at position 1', "
            r"which does not say what to write; {}^{A}\boldsymbol\omega^{B} is decided rightly")
_PRINCIPAL = (r"refused, typed against the docs (rule 6: I_3 is the identity of size 3): the "
              r"principal moments I_1, I_2, I_3 are identities, diag(I_1, I_2, I_3) a 6x6 "
              r"identity, and the message ('juxtaposition of a 1x3 matrix and a 6x6 matrix: no "
              r"product fits') names neither I_1 nor the --let; with --let 'I_1: scalar; ...' "
              r"it is verified, but only because the rate's \mathbf{I} is still read as the "
              r"identity (omega dot = 0); spelt \mathbf{J} it is decided rightly for the reason")
_SINES = (r"refused, typed against the docs (rule 9): Shoemake's scalar parts s_1, s_2 read as "
          r"Siciliano's sines; the message names --let 's_{1}: scalar', which decides it rightly")
_MRING = (r"refused: Horn's \mathring{q} is an unknown macro and the message does not say what to "
          r"write; spelt \bar{q} it is decided rightly")
_ZIPFEL = (r"refused: Zipfel's [T]^{BL} (a bracketed name with a two-letter superscript frame "
           r"label; T^{BL} and \boldsymbol\omega^{BI} are refused too) 'cannot be read: "
           r"unexpected BL', which does not say what to write (and for \boldsymbol\omega^{BI} "
           r"quotes a --let the user did not write, the reader's expansion of 'body angular "
           r"velocity of'); spelt T_{BL} (or T^{(BL)}) it is decided rightly")
NOTES: dict[str, str] = {
    "kp-momentum-conserved-slip": _WRONG,
    "mk-angmom": _INERTIA,
    "mk-kinetic": _INERTIA,
    "mk-kinetic-slip": _INERTIA,
    "kp-313": _KP_NAME,
    "kp-313-slip": _KP_NAME,
    "kp-energy-conserved": _PRINCIPAL,
    "kp-momentum-conserved": _PRINCIPAL,
    "sh-product": _SINES,
    "sh-product-slip": _SINES,
    **{i: _MRING for i in ("hn-dot-mult", "hn-dot-swap", "hn-dot-swap-slip", "hn-matrix",
                           "hn-matrix-bar", "hn-matrix-bar-slip", "hn-orthogonal")},
    **{i: _ZIPFEL for i in ("zp-euler", "zp-euler-slip", "zp-dcm-rate", "zp-dcm-rate-slip")},
}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
