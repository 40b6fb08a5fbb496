"""Constrained symbols: the atoms declarations are built from.

A declaration never writes ``e1**2 + e2**2 + e3**2 = 1`` anywhere: it asks for a
``unit_vector("e")`` and the zero test (:mod:`rigidsym.zero`) imposes the constraint exactly
by a rational parametrisation. The kinds of atoms:

- ``unit_vector``: ``e . e = 1`` (stereographic projection of two free rationals);
- ``angle``: ``cos^2 + sin^2 = 1`` (tangent of a fraction of the angle); the bare angle
  itself is kept as an independent variable, which is sound because an angle and its
  sine/cosine are algebraically independent functions;
- ``rotation``: ``Q^T Q = 1``, ``det Q = 1`` (rational quaternion parametrisation);
- ``vector``/``scalar``/``matrix``: free.

Each factory accepts ``t`` (the time symbol :data:`TIME`) to make the atoms functions of
time; their derivatives, taken by ``sympy.diff``, are jets that the zero test treats as
free variables (for unit vectors and rotations, through the jets of the parameters, so
``e . e_dot = 0`` and ``Q^T Q_dot + Q_dot^T Q = 0`` hold exactly).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = [
    "TIME",
    "Constraint",
    "constraint_of",
    "unit_vector",
    "angle",
    "rotation",
    "vector",
    "scalar",
    "matrix",
    "symmetric_matrix",
]

#: The time symbol for trajectories.
TIME = sp.Symbol("t", real=True)


@dataclass(frozen=True)
class Constraint:
    """A constraint on a group of atoms, keyed by the atoms' names.

    Attributes:
        kind: ``"unit"``, ``"angle"`` or ``"rotation"``.
        name: the group's book name (``"e"``, ``"phi"``, ``"Q"``).
        names: the names of the atoms (symbol or function names), row-major for matrices.
        timed: whether the atoms are functions of :data:`TIME`.
    """

    kind: str
    name: str
    names: tuple[str, ...]
    timed: bool


_CONSTRAINTS: dict[tuple[str, bool], Constraint] = {}


def _register(c: Constraint) -> None:
    # keyed by (name, timed): the static e and the e(t) of a motion are different atoms
    for n in c.names:
        old = _CONSTRAINTS.get((n, c.timed))
        if old is not None and old != c:
            raise ValueError(f"atom name {n!r} is already constrained as {old.kind} {old.name!r}")
        _CONSTRAINTS[(n, c.timed)] = c


def constraint_of(name: str, timed: bool = False) -> Constraint | None:
    """The constraint registered for an atom name, or ``None`` for a free atom."""
    return _CONSTRAINTS.get((name, timed))


def _atom(name: str, t: sp.Symbol | None):
    if t is None:
        return sp.Symbol(name, real=True)
    return sp.Function(name, real=True)(t)


def _components(name: str, n: int) -> list[str]:
    return [f"{name}_{i}" for i in range(1, n + 1)]


def unit_vector(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A 3 x 1 unit vector (``e . e = 1`` imposed exactly by the zero test)."""
    names = _components(name, 3)
    _register(Constraint("unit", name, tuple(names), t is not None))
    return sp.Matrix([_atom(n, t) for n in names])


def angle(name: str, t: sp.Symbol | None = None):
    """An angle in radians (``cos^2 + sin^2 = 1`` imposed exactly by the zero test)."""
    _register(Constraint("angle", name, (name,), t is not None))
    return _atom(name, t)


def rotation(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A generic 3 x 3 proper orthogonal matrix (entries ``name_ij``, row-major)."""
    names = [f"{name}_{i}{j}" for i in range(1, 4) for j in range(1, 4)]
    _register(Constraint("rotation", name, tuple(names), t is not None))
    return sp.Matrix(3, 3, [_atom(n, t) for n in names])


def vector(name: str, t: sp.Symbol | None = None, n: int = 3) -> sp.Matrix:
    """A free n x 1 vector (entries ``name_1 ... name_n``)."""
    return sp.Matrix([_atom(c, t) for c in _components(name, n)])


def scalar(name: str, t: sp.Symbol | None = None):
    """A free real scalar."""
    return _atom(name, t)


def matrix(name: str, rows: int = 3, cols: int = 3, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free rows x cols matrix (entries ``name_ij``)."""
    return sp.Matrix(rows, cols, [_atom(f"{name}_{i}{j}", t)
                                  for i in range(1, rows + 1) for j in range(1, cols + 1)])


def symmetric_matrix(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free symmetric 3 x 3 matrix (entries ``name_ij`` with i <= j)."""
    a = {(i, j): _atom(f"{name}_{min(i, j)}{max(i, j)}", t) for i in range(1, 4)
         for j in range(1, 4)}
    return sp.Matrix(3, 3, lambda i, j: a[(i + 1, j + 1)])
