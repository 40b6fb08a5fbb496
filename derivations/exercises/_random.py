"""Readable exact draws for the exercises' random variants (an exam's draws):
rotations by Cayley's formula of small rationals, unit vectors from Pythagorean
quadruples. Each takes a ``random.Random`` so that a spec and seed give the same exam."""

from __future__ import annotations

import sympy as sp

#: primitive Pythagorean quadruples (a, b, c; d) with a^2 + b^2 + c^2 = d^2, d <= 11
_QUADRUPLES = ((1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (4, 4, 7, 9), (2, 6, 9, 11),
               (6, 6, 7, 11), (0, 3, 4, 5), (0, 5, 12, 13))


def cayley(rng) -> sp.Matrix:
    """A rotation with small rational entries: Cayley's formula of a small rational
    vector, ``Q = (1 - C)^-1 (1 + C)`` (C its cross-product matrix)."""
    c = sp.Matrix([sp.Rational(rng.randint(-2, 2), rng.randint(1, 2)) for _ in range(3)])
    C = sp.Matrix([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
    return (sp.eye(3) - C).inv() * (sp.eye(3) + C)


def unit_vector(rng) -> sp.Matrix:
    """A unit vector with rational components: a Pythagorean quadruple, its components
    permuted and signed at random (e.g. [2/3, -1/3, 2/3])."""
    *abc, d = rng.choice(_QUADRUPLES)
    rng.shuffle(abc)
    return sp.Matrix([sp.Rational(rng.choice((1, -1)) * x, d) for x in abc])


def small_vector(rng, low: int = -3, high: int = 3) -> sp.Matrix:
    """Three small integers."""
    return sp.Matrix([rng.randint(low, high) for _ in range(3)])


def cayley_small(rng, halves: bool = True) -> sp.Matrix:
    """A rotation with entries of denominator 3 (or 9 with ``halves``), about no coordinate
    axis and no cube diagonal: Cayley's formula of a vector with exactly two non-zero
    components, each +-1 (or +-1/2 with ``halves``). A quarter turn about an axis, or a third
    of a turn about a diagonal, would only permute the coordinates. For data a student
    reads by hand."""
    c = [sp.Rational(rng.choice((-2, -1, 1, 2) if halves else (-2, 2)), 2)
         for _ in range(2)] + [0]
    rng.shuffle(c)
    C = sp.Matrix([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
    return (sp.eye(3) - C).inv() * (sp.eye(3) + C)
