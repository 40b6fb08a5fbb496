"""Machine checks of a worked solution's answers (:class:`Check`), decided soundly and
never by ``simplify()``: identities by :func:`rigidsym.zero.decide.decide_zero` (with an
exact counterexample when one fails), closed algebraic numbers by their minimal polynomial.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rigidsym.zero.decide import decide_zero

__all__ = ["Check", "identity_check", "nonidentity_check", "algebraic_zero", "exact_check",
           "truth_check", "is_zero"]

_X = sp.Symbol("x_minpoly")


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

    Uses the minimal polynomial over Q: ``e == 0`` iff that polynomial is ``x``.
    """
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
    """Check that closed algebraic expressions (entries of matrices too) are all zero."""
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
    (the minimal polynomial, as :func:`algebraic_zero`)."""
    return all(algebraic_zero(x) for x in (list(v) if isinstance(v, sp.MatrixBase) else [v]))
