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

#: what each statement that is not right as typed shows (none of the NumPy truths was typed
#: wrong); written after the run from the reader's code, the statements and the record
#: (benchmarks/results/blind_trial_e.json, as first run, without these notes) unchanged. No
#: verdict is wrong; the 25 misses are refusals (bad input), none undecided.
_DOT_LABEL = (r"refused: grammar.lark's 'accented' glyph (\dot{C}) takes a subscript but no "
              r"SUPLABEL, so Savage's \dot{C}_B^N is a syntax error at ^N (C_B^N alone reads)")
_STAR = (r"refused: ^* of anything but a 4-vector is only Featherstone's dual of a declared "
         r"spatial transform (transformer/book_notations.py book_power); Jain's phi^* is the "
         r"transpose (reading it as the dual, phi^{-T}, would be wrong), and the message names "
         r"the argument \mathbf{l} as the matrix")
_OCCURS = (r"refused: statement.py _read's 'does not occur' guard counts \dot X as a use of X "
           r"only for an angle or scalar kind, not for a model whose only use is its rate")
_VEE = (r"refused: grammar.lark's apply_pre (post ^ sup ( expr )) makes x^T(A - A^T) one node, "
        r"so the following ^\vee binds to the 1x3 product, not to (A - A^T) as TeX means")
_HAT2 = (r"refused: an internal error: transformer/chapter.py power() takes x ** 2 of the 3x1 "
         r"unit-vector reading of \hat{\mathbf{u}} (sympy's error, not a LatexError 'shapes'), "
         r"so the hat choice point cannot drop that reading (docs' own \hat{\mathbf{v}}^2 fails "
         r"the same way, also under --notation murray-li-sastry)")
_STARMACRO = (r"refused: \star (Hanson's quaternion product) is an unknown macro; only "
              r"\otimes, \odot")
NOTES: dict[str, str] = {
    "kl-omega-eps": r"refused by the second semantics: numeval/evaluator.py _declared_only finds "
    r"no declaration of \epsilon_1 under the dot of \dot\epsilon_1 (an entry of the free "
    r"tangent rate of \epsilon(t): unit 4-vector, inside a --let model), which the symbolic "
    r"side reads; respell.py respells an entry's rate only where a --let declares the rate",
    "llm-trace": _VEE,
    "llm-trace-slip": _VEE,
    "llm-hat-sym": r"refused: \{ ... \} as grouping braces (Lee's {tr[A] I - A}x) is an "
    r"unknown macro; braces read only as Ginsberg's declared column matrix \{\omega\}",
    "llm-er-rate": _OCCURS + r" (e_R occurs only as \dot{e}_R)",
    "llm-er-rate-slip": _OCCURS + r" (e_R occurs only as \dot{e}_R)",
    "holm-double-hat": _HAT2,
    "holm-double-hat-slip": _HAT2,
    "sav-cbn-rate": _DOT_LABEL,
    "sav-cbn-rate-slip": _DOT_LABEL,
    "sav-bortz": _DOT_LABEL,
    "sav-bortz-slip": _DOT_LABEL,
    "jain-inverse-slip": _STAR,
    "jain-velocity": _STAR,
    "jain-inertia": _STAR,
    "jain-inertia-slip": _STAR,
    "jain-power": r"refused: \mathfrak (Jain's spatial force \mathfrak{f}) is not in "
    r"grammar.lark's FONT token (\mathsf, \mathtt, \mathit, \mathbb); V^* of a 6-vector "
    "would be refused next (as jain-velocity)",
    "tay-top": _OCCURS + r" (\omega_1 occurs only as \dot\omega_1)",
    "tay-top-slip": _OCCURS + r" (\omega_1 occurs only as \dot\omega_1)",
    "han-rotate": r"refused: entries.py counts q_k of the unit 4-vector q from 1 and raises for "
    r"the q_0 of the --let model R; the count is settled by the LaTeX's own q_k (han-trace, "
    r"which writes q_0, reads the same R), a model's failure is not a dropped reading; "
    r"\star would refuse next",
    "han-axis-angle": _OCCURS.replace(r"a model whose only use is its rate",
                                      r"a model vector used only through its entries q_0..q_3 "
                                      r"in another model (R)"),
    "han-axis-angle-slip": "refused: as han-axis-angle",
    "han-norm": _STARMACRO,
    "han-compose": _STARMACRO,
    "han-compose-slip": _STARMACRO,
}


def main() -> None:
    run_trial(DATA, OUT, NOTES)


if __name__ == "__main__":
    main()
