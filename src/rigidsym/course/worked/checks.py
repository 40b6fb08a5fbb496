"""Machine checks of a worked solution's answers (:class:`Check`), decided soundly and
never by ``simplify()``: identities by :func:`rigidsym.zero.decide.decide_zero` (with an
exact counterexample when one fails), closed algebraic numbers by their minimal polynomial.

A replay for its values only (:func:`values_only`; :func:`rigidsym.course.worked.solve_values`)
runs a solver on its data as :data:`DIGITS`-digit floats: there :func:`exact_check` is not
run, and :func:`is_zero`, :func:`algebraic_zero` and :func:`settled` decide a value only
when it is farther than :data:`MARGIN` from 0, raising :class:`Undecided` otherwise (the
caller then solves exactly).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass

import sympy as sp

from rigidsym.zero.decide import decide_zero

__all__ = ["Check", "identity_check", "nonidentity_check", "algebraic_zero", "exact_check",
           "truth_check", "is_zero", "values_only", "for_values", "settled", "Undecided",
           "DIGITS", "MARGIN", "ZERO"]

_X = sp.Symbol("x_minpoly")

#: the significant digits of the data and arithmetic of a replay for its values only
DIGITS = 50
#: how far from 0 a value of such a replay must be for a decision (zero or not, a sign): a
#: value within it may be 0 and is left to the exact solve. The solvers divide by no
#: decided value to a power above 2, so a quotient keeps 50 - 20 digits and more: the data
#: of the chapter's exercises (magnitudes far below 1e10, slips included) keep the rounding
#: of 50-digit arithmetic below 1e-25 in every answer
MARGIN = sp.Float("1e-10", DIGITS)
#: an answer's entry of such a replay within this of 0 is written 0 (the exact value is 0 or
#: far below the grader's absolute tolerance, 1e-12)
ZERO = 1e-20

_VALUES_ONLY: ContextVar[bool] = ContextVar("rigidsym_values_only", default=False)


class Undecided(BaseException):  # noqa: N818 -- a signal, as KeyboardInterrupt
    """A decision that a replay for its values only leaves to the exact solve: a value
    within :data:`MARGIN` of 0. A BaseException, so that no solver's ``except Exception``
    takes it for a failure of the data."""


def values_only() -> bool:
    """True inside :func:`for_values`: the solver runs on floating data for its answers'
    values; checks are not run and closed forms need not be simplified."""
    return _VALUES_ONLY.get()


@contextmanager
def for_values() -> Iterator[None]:
    """The block runs as a replay for its values only (see :func:`values_only`)."""
    token = _VALUES_ONLY.set(True)
    try:
        yield
    finally:
        _VALUES_ONLY.reset(token)


def _numeric(x: sp.Expr) -> sp.Float:
    """``x`` as a :data:`DIGITS`-digit float.

    Raises:
        ValueError: ``x`` is no closed number.
    """
    v = sp.sympify(x)
    if not v.is_Float:
        v = v.evalf(DIGITS)
    if not v.is_Number:
        raise ValueError(f"not a closed number: {x}")
    return v


def settled(x: sp.Expr) -> sp.Expr:
    """``x`` itself; in a replay for its values only, first checked to be farther than
    :data:`MARGIN` from 0, so that its sign (a comparison the solver makes) is the exact
    value's.

    Raises:
        Undecided: in such a replay, ``x`` within the margin of 0.
        ValueError: in such a replay, ``x`` is no closed number.
    """
    if values_only() and abs(_numeric(x)) <= MARGIN:
        raise Undecided(f"{x} is within {MARGIN} of 0")
    return x


@dataclass
class Check:
    """A machine check: its name, whether it passed, and how it was decided."""

    name: str
    passed: bool
    detail: str = ""


def identity_check(name: str, exprs, seed: int = 0) -> Check:
    """Decide soundly that every expression in ``exprs`` vanishes identically.

    Matrices are flattened. Constrained atoms (unit vectors, angles, rotations from
    :mod:`rigidsym.algebra.symbols`) are parametrised exactly by the zero test.
    """
    flat = []
    for e in exprs if isinstance(exprs, list | tuple) else [exprs]:
        if isinstance(e, sp.MatrixBase):
            flat.extend(list(e))
        else:
            flat.append(e)
    r = decide_zero(flat, seed=seed)
    detail = f"{r.method}: {r.detail}"
    if r.zero is False and r.witness is not None:
        detail += f" (entry {r.entry} non-zero at an exact point)"
    return Check(name, r.zero is True, detail)


def nonidentity_check(name: str, exprs, seed: int = 0) -> Check:
    """Passes when the zero test *refutes* the identity with an exact counterexample."""
    c = identity_check(name, exprs, seed)
    refuted = not c.passed and c.detail.startswith("counterexample")
    return Check(name, refuted, ("refuted by an exact rational counterexample: " if refuted
                                 else "not refuted: ") + c.detail)


def algebraic_zero(e) -> bool:
    """Exactly decide that a closed expression (an algebraic number) is zero.

    Uses the minimal polynomial over Q: ``e == 0`` iff that polynomial is ``x``. In a
    replay for its values only (:func:`values_only`), False for a value farther than
    :data:`MARGIN` from 0.

    Raises:
        ValueError: ``e`` is no closed number.
        Undecided: in such a replay, ``e`` within the margin of 0.
    """
    if values_only():
        return is_zero(e)
    e = sp.nsimplify(e) if isinstance(e, sp.Float) else sp.sympify(e)
    if e.free_symbols:
        raise ValueError(f"not a closed number: {e}")
    e = sp.expand(e)
    if e == 0:
        return True
    if e.is_Rational:
        return False
    return sp.minimal_polynomial(e, _X) == _X


def exact_check(name: str, exprs) -> Check:
    """Check that closed algebraic expressions (entries of matrices too) are all zero; in a
    replay for its values only (:func:`values_only`), not run (a failed check saying so)."""
    if values_only():
        return Check(name, False, "not run: a replay for its values only")
    flat = []
    for e in exprs if isinstance(exprs, list | tuple) else [exprs]:
        flat.extend(list(e) if isinstance(e, sp.MatrixBase) else [e])
    bad = [i for i, e in enumerate(flat) if not algebraic_zero(e)]
    if bad:
        return Check(name, False, f"entries {bad} are not zero (minimal polynomial)")
    return Check(name, True, f"{len(flat)} closed algebraic entries are 0 (minimal polynomial)")


def truth_check(name: str, ok: bool, detail: str) -> Check:
    """A check decided by exact comparison done by the caller (rationals, signs)."""
    return Check(name, bool(ok), detail)


def is_zero(v) -> bool:
    """Exactly decide that a closed number, or every entry of a closed matrix, is zero
    (the minimal polynomial, as :func:`algebraic_zero`). In a replay for its values only
    (:func:`values_only`): False when an entry is farther than :data:`MARGIN` from 0.

    Raises:
        ValueError: an entry is no closed number.
        Undecided: in such a replay, every entry within the margin of 0.
    """
    entries = list(v) if isinstance(v, sp.MatrixBase) else [v]
    if values_only():
        if any(abs(_numeric(x)) > MARGIN for x in entries):
            return False
        raise Undecided(f"every entry of {v} is within {MARGIN} of 0")
    return all(algebraic_zero(x) for x in entries)
