"""A does-not-hold certified on the printed relation itself where the page never gives one
of its glyphs (3.148's ``P``: "the reader is invited to find an expression for P"). The
declaration writes that glyph as a fresh array of free atoms (``Statement.for_every``); the
evidence is one point of the other atoms where the relation fails for every real value of
the array: a rational vector ``x`` with ``x^T (lhs - rhs) x = c + sum w_k L_k^2``, ``c`` a
non-zero constant and every weight ``w_k`` of its sign (completed squares of the array's
atoms), so ``x^T (lhs - rhs) x`` is never 0 (certcheck's ``for_every``,
``docs/certificates.md``). For 3.148, ``x = [u; (A - C)^T u]`` gives ``x^T (M_A - M_C) x =
-m ||u x (a - c)||^2 < 0`` while ``x^T m P P^T x = m ||P^T x||^2 >= 0``.
"""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp

from rigidsym.algebra.symbols import constraint_of
from rigidsym.checking.deciding.explicit import explicit

__all__ = ["for_every_evidence"]


def _squares(q, unknowns: list) -> tuple[list, object]:
    """``q = c + sum w_k L_k^2`` by completing squares in ``unknowns`` (each ``L_k`` monic
    in its first unknown): ``([(w_k, L_k)], c)``, c what is left (a number where q is
    such a sum)."""
    out = []
    for v in unknowns:
        p = sp.Poly(q, v)
        if p.degree() < 2:
            continue
        w = p.coeff_monomial(v ** 2)
        L = sp.expand(v + p.coeff_monomial(v) / (2 * w))
        out.append((w, L))
        q = sp.expand(q - w * L ** 2)
    return out, q


def for_every_evidence(pr, lhs, rhs, array, witness, model: dict, seed: int,
                       tries: int = 12) -> dict:
    """The evidence that ``lhs = rhs`` fails for every real value of ``array``'s atoms.

    Args:
        pr: the statement's printer (its atom names).
        lhs, rhs: the relation's sides, explicit (the model substituted).
        array: the fresh array of free atoms standing for the glyph the page never gives.
        witness: the vector ``x`` (in the model's symbols).
        model: the statement's model (``x``'s value).
        seed: the seed of the point's search (small rationals).
        tries: points tried.

    Raises:
        ValueError: constrained atoms beside the array, or no point found.
    """
    unknowns = list(array)
    x = sp.Matrix(explicit(witness, model))
    diff = sp.Matrix(lhs) - sp.Matrix(rhs)
    atoms = sorted((diff.free_symbols | x.free_symbols) - set(unknowns), key=str)
    if any(constraint_of(a) is not None for a in atoms):
        raise ValueError("for every value of an array: constrained atoms are not drawn here")
    rng = random.Random(seed)
    small = [Fraction(k, d) for k in range(-3, 4) for d in (1, 2, 3)]
    for _ in range(tries):
        pt = {a: sp.Rational(str(rng.choice(small))) for a in atoms}
        xv = x.subs(pt)
        squares, c = _squares(sp.expand((xv.T * diff.subs(pt) * xv)[0, 0]), unknowns)
        if c.is_Rational and c != 0 and all(w.is_Rational and w * c >= 0 for w, _ in squares):
            used = diff.free_symbols - set(unknowns)
            return {"type": "counterexample",
                    "point": dict(sorted((pr.atom(a), str(pt[a])) for a in used)),
                    "angles": {}, "for_every": [pr.atom(v) for v in unknowns],
                    "form": [str(v) for v in xv], "squares": [
                        [str(w), " + ".join(f"({L.coeff(v)})*{pr.atom(v)}" for v in unknowns
                                            if L.coeff(v) != 0)] for w, L in squares]}
    raise ValueError(f"no point where x^T (lhs - rhs) x is a non-zero constant plus squares "
                     f"of its sign ({tries} tried)")
