"""Book symbols and first-principles models shared by the section modules.

Book symbols are ``sympy.MatrixSymbol`` / ``Symbol`` objects named as in ``NOTATION.md``
so that a printed equation transcribes readably (``(Q - 1)^T (Q a - a')``). A *model* maps
each book symbol to its first-principles value, built from constrained atoms
(:mod:`rigidsym.symbols`): the checker substitutes it before deciding.

First principles used here: a rigid-body displacement is the map ``x -> Q x + c`` with
``Q`` proper orthogonal (here given by its natural invariants, Eq. (2.49)) and ``c`` a
free translation; nothing else about screws, Plücker lines or pitches is assumed.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.primitives import cpm, rotation_from_natural_invariants
from rigidsym.symbols import angle, unit_vector, vector

__all__ = ["MS", "I3", "O3", "vec", "mat", "displacement_model", "Bk"]

I3 = sp.Identity(3)
O3 = sp.ZeroMatrix(3, 3)


def MS(name: str, rows: int = 3, cols: int = 1) -> sp.MatrixSymbol:
    """A book matrix symbol (vector by default)."""
    return sp.MatrixSymbol(name, rows, cols)


def vec(name: str) -> sp.MatrixSymbol:
    """A book 3-vector symbol."""
    return sp.MatrixSymbol(name, 3, 1)


def mat(name: str) -> sp.MatrixSymbol:
    """A book 3 x 3 matrix symbol."""
    return sp.MatrixSymbol(name, 3, 3)


class Bk:
    """The book's symbols for a rigid-body displacement (Sec. 3.2)."""

    Q = mat("Q")
    E = mat("E")
    e = vec("e")
    phi = angle("phi")
    a = vec("a")
    a_prime = vec("a_prime")
    p = vec("p")
    p_prime = vec("p_prime")
    d_A = vec("d_A")
    d_P = vec("d_P")


def displacement_model() -> dict:
    """First-principles values of the displacement symbols.

    ``Q`` from its natural invariants (2.49) with a constrained unit ``e`` and angle ``phi``;
    body points ``a``, ``p`` free; the displaced points from ``x' = Q x + c`` (``c`` free).
    ``d_A``, ``d_P`` are the displacements ``x' - x`` (definition (3.3)).
    """
    e = unit_vector("e")
    phi = Bk.phi
    Q = rotation_from_natural_invariants(e, phi)
    a, p, c = vector("a"), vector("p"), vector("c")
    a1, p1 = Q * a + c, Q * p + c
    im = sp.ImmutableMatrix
    return {Bk.Q: im(Q), Bk.E: im(cpm(e)), Bk.e: im(e), Bk.a: im(a), Bk.p: im(p),
            Bk.a_prime: im(a1), Bk.p_prime: im(p1), Bk.d_A: im(a1 - a), Bk.d_P: im(p1 - p)}
