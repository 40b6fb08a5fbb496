"""The engine's tuning constants, in one place: the zero test's budgets, the numeric backing's
precision and points, the checker's agreement tolerances and the repair search's budget.

Each verdict depends on these values, so the verdict cache keys every stored result on all
of them (:func:`rigidsym.checking.verdict_cache.key_of`): a test or a user who changes one
(``ENGINE.numeric_points = 11``) gets results computed under it, never one stored under
another. The engine reads :data:`ENGINE` at each use, not at import.

Constants of an algorithm rather than tuning (the Schwartz-Zippel sample set of
:mod:`rigidsym.zero.decide`, the modulus of the repair search's fast filter) stay in their
modules; the cache keys on them too.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

__all__ = ["EngineSettings", "ENGINE"]


@dataclass
class EngineSettings:
    """The engine's tuning constants (one instance, :data:`ENGINE`, is read by the engine).

    Attributes:
        cancel_node_limit: node count of an entry above which exact cancellation is not
            attempted (:func:`rigidsym.zero.decide.decide_zero`).
        cancel_terms_limit: the work budget of exact cancellation, on the data (so the
            method recorded does not depend on the machine): no intermediate numerator or
            denominator may exceed this many terms; past it, Schwartz-Zippel decides.
            Measured on the chapter (python-flint 0.9): at most 44,924 terms, every family
            cancels, 5.9 s in all.
        cancel_product_limit: the same budget for a product: at most this many pairs of
            terms (at most 3.3e7 on the chapter; FLINT then decides in about a second).
        cancel_seconds: a safety net only (CPU seconds; not reached on the chapter), after
            which Schwartz-Zippel decides.
        sz_points: the points evaluated by the Schwartz-Zippel path.
        numeric_digits: the numeric backing's starting precision, in decimal digits
            (:mod:`rigidsym.checking.deciding.balls`).
        numeric_points: the constraint-satisfying points per backing.
        max_digits: the precision never rises above this many digits (then the ball stays
            undecided).
        certified_bound: a backing is certified when every relative residual is enclosed in
            ``[-r, r]`` with ``r`` at most this.
        agree_tol: the certified bound of the relative residual below which the numeric
            check agrees with "holds" (a wider ball at the highest precision turns the
            verdict undecided): ``10^-(numeric_digits - 15)``.
        differ_tol: the relative residual (midpoints) above which the numeric check agrees
            with "does not hold".
        repair_budget: candidates tried per failing member unless the run or the
            declaration says otherwise (:mod:`rigidsym.checking.repairing.repair`).
        keep: repairs kept per member (the count found is reported too).
        full_tests: full zero tests per member at most (survivors of the fast filter are
            rare; a member the filter cannot evaluate would otherwise send every candidate
            to the full test).
    """

    cancel_node_limit: int = 2500
    cancel_terms_limit: int = 200_000
    cancel_product_limit: int = 2 * 10**8
    cancel_seconds: float = 5.0
    sz_points: int = 12
    numeric_digits: int = 50
    numeric_points: int = 10
    max_digits: int = 800
    certified_bound: Fraction = Fraction(1, 10**40)
    agree_tol: Fraction = Fraction(1, 10 ** (50 - 15))
    differ_tol: float = 1e-12
    repair_budget: int = 5000
    keep: int = 5
    full_tests: int = 40


#: The settings the engine reads, at each use.
ENGINE = EngineSettings()
