"""Constrained symbols: the atoms declarations are built from.

A declaration never writes ``e1**2 + e2**2 + e3**2 = 1`` anywhere: it asks for a
``unit_vector("e")`` and the zero test (:mod:`rigidsym.zero.decide`) imposes the constraint exactly
by a rational parametrisation. The kinds of atoms:

- ``unit_vector``: ``e . e = 1`` (stereographic projection of two free rationals);
- ``unit_vector4``: ``x . x = 1`` in R^4 (stereographic projection of three rationals),
  e.g. the Euler-Rodrigues parameters;
- ``angle``: ``cos^2 + sin^2 = 1`` (tangent of a fraction of the angle); the bare angle
  itself is kept as an independent variable, which is sound because an angle and its
  sine/cosine are algebraically independent functions;
- ``rotation``: ``Q^T Q = 1``, ``det Q = 1`` (rational quaternion parametrisation);
- ``vector``/``scalar``/``matrix``: free.

Each factory accepts ``t`` (the time symbol :data:`TIME`) to make the atoms functions of
time; their derivatives, taken by ``sympy.diff``, are jets that the zero test treats as
free variables (for unit vectors and rotations, through the jets of the parameters, so
``e . e_dot = 0`` and ``Q^T Q_dot + Q_dot^T Q = 0`` hold exactly).

A constraint belongs to the atoms a factory returns (:class:`ConstrainedSymbol`, or an
undefined function carrying it), never to a name: a free ``vector("e")`` in a user module
stays free however many unit vectors named ``e`` other modules declare.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.core import kinds as _kinds

__all__ = [
    "TIME",
    "Constraint",
    "ConstrainedSymbol",
    "constraint_of",
    "constrained_atom",
    "constrained_group",
    "unit_vector",
    "unit_vector4",
    "angle",
    "ANGLE_RANGES",
    "twist",
    "wrench",
    "rotation",
    "vector",
    "scalar",
    "matrix",
    "symmetric_matrix",
]

#: The time symbol for trajectories.
TIME = sp.Symbol("t", real=True)


@dataclass(frozen=True, order=True)  # ordered: sympy's Basic.compare orders atom contents
class Constraint:
    """A constraint on a group of atoms; every atom of the group carries it.

    Attributes:
        kind: the name of a kind of :data:`rigidsym.core.kinds.KINDS` (``"unit"``,
            ``"unit4"``, ``"angle"``, ``"rotation"``).
        name: the group's book name (``"e"``, ``"phi"``, ``"Q"``).
        names: the names of the atoms (symbol or function names), row-major for matrices.
        timed: whether the atoms are functions of :data:`TIME`.
    """

    kind: str
    name: str
    names: tuple[str, ...]
    timed: bool


class ConstrainedSymbol(sp.Symbol):
    """A real symbol that carries its :class:`Constraint`.

    The constraint is part of the symbol's identity (like ``Dummy``'s index), so a free
    ``Symbol("e_1", real=True)`` declared anywhere else is a *different* atom and is never
    treated as a component of a unit vector: constraints are scoped to atoms, not to names.
    It prints and sorts exactly as the plain symbol of the same name.
    """

    __slots__ = ("constraint",)

    constraint: Constraint

    def __new__(cls, name: str, constraint: Constraint, **assumptions):
        cls._sanitize(assumptions, cls)
        obj = sp.Symbol.__xnew__(cls, name, **assumptions)
        obj.constraint = constraint
        return obj

    def __getnewargs_ex__(self):
        return ((self.name, self.constraint), self._assumptions_orig)

    def _hashable_content(self):
        return sp.Symbol._hashable_content(self) + (self.constraint,)


# sympy orders the factors of a product and dispatches printers by class *name*: named as
# the plain Symbol, a constrained atom sorts and prints exactly as before (same reports)
ConstrainedSymbol.__name__ = "Symbol"


def constraint_of(atom) -> Constraint | None:
    """The constraint an atom carries (a symbol or an applied function ``f(t)``), or ``None``
    for a free atom."""
    if isinstance(atom, ConstrainedSymbol):
        return atom.constraint
    if isinstance(atom, AppliedUndef):
        return getattr(atom.func, "constraint", None)
    return None


@cache  # one object per atom: identity comparisons stay cheap in sympy's hot paths
def constrained_atom(name: str, c: Constraint):
    """The atom ``name`` of the group ``c`` (equal to the one its factory returned)."""
    if c.timed:
        # extra keyword arguments of an undefined function take part in its equality
        return sp.Function(name, real=True, constraint=c)(TIME)
    return ConstrainedSymbol(name, c, real=True)


def _atom(name: str, t: sp.Symbol | None, c: Constraint | None = None):
    if c is not None:
        if t is not None and t != TIME:
            raise ValueError(f"t: expected rigidsym.algebra.symbols.TIME or None, got {t!r}")
        return constrained_atom(name, c)
    if t is None:
        return sp.Symbol(name, real=True)
    return sp.Function(name, real=True)(t)


def _components(name: str, n: int) -> list[str]:
    return [f"{name}_{i}" for i in range(1, n + 1)]


def constrained_group(kind: str, name: str, t: sp.Symbol | None = None):
    """The atoms of one group of the constraint ``kind`` (a row of
    :data:`rigidsym.core.kinds.KINDS`), shaped as the kind says.

    Args:
        kind: a kind name (``"unit"``, ``"unit4"``, ``"rotation"``, ``"angle"``, or one
            registered later).
        name: the group's book name; the atoms are ``Kind.components(name)``.
        t: :data:`TIME` for atoms that are functions of time, else ``None``.

    Returns:
        A scalar atom for a kind of shape ``()``, else a ``sympy.Matrix`` of that shape.

    Raises:
        ValueError: an unknown kind, or ``t`` neither ``TIME`` nor ``None``.
    """
    k = _kinds.get(kind)
    names = k.components(name)
    c = Constraint(kind, name, names, t is not None)
    atoms = [_atom(n, t, c) for n in names]
    if k.shape == ():
        return atoms[0]
    return sp.Matrix(*k.shape, atoms) if len(k.shape) == 2 else sp.Matrix(atoms)


def unit_vector(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A 3 x 1 unit vector (``e . e = 1`` imposed exactly by the zero test).

    Args:
        name: the book name; the entries are ``name_1``, ``name_2``, ``name_3``.
        t: :data:`TIME` for a unit vector that moves (entries are functions of time, and
            ``e . e_dot = 0`` holds exactly), else ``None``.

    Returns:
        3 x 1 ``sympy.Matrix`` of constrained atoms (dimensionless).

    Raises:
        ValueError: ``t`` is neither :data:`TIME` nor ``None``.
    """
    return constrained_group("unit", name, t)


def unit_vector4(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A 4 x 1 unit vector, entries ``name_1 ... name_4`` (``x . x = 1`` imposed exactly).

    The Euler-Rodrigues parameters ``eta = [r; r0]`` of a rotation are one (Sec. 2.3:
    ``r . r + r0^2 = 1``).

    Args:
        name: the book name.
        t: :data:`TIME` for entries that are functions of time, else ``None``.

    Returns:
        4 x 1 ``sympy.Matrix`` of constrained atoms.

    Raises:
        ValueError: ``t`` is neither :data:`TIME` nor ``None``.
    """
    return constrained_group("unit4", name, t)


#: the ranges an angle may be declared on, and their kinds
ANGLE_RANGES = {"(-pi, pi)": "angle", "[0, pi]": "angle_pi"}


def angle(name: str, t: sp.Symbol | None = None, range: str = "(-pi, pi)"):  # noqa: A002
    """An angle in radians (``cos^2 + sin^2 = 1`` imposed exactly by the zero test).

    Args:
        name: the book name (``"phi"``).
        t: :data:`TIME` for an angle that is a function of time, else ``None``.
        range: ``"(-pi, pi)"`` (the default: ``theta = 2 atan(tau)``) or ``"[0, pi]"``
            (MR's ``theta = acos((tr R - 1) / 2)`` holds there, and only there: the zero
            test rewrites ``acos(cos theta)`` as ``theta`` for such an angle, and splits a
            default one into ``theta`` and ``-theta``).

    Returns:
        A real constrained atom (a symbol, or ``name(t)``) [rad].

    Raises:
        ValueError: ``t`` is neither :data:`TIME` nor ``None``, or an unknown ``range``.
    """
    if range not in ANGLE_RANGES:
        raise ValueError(f"range: expected one of {', '.join(map(repr, ANGLE_RANGES))}, "
                         f"got {range!r}")
    return constrained_group(ANGLE_RANGES[range], name, t)


def twist(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free twist, a 6 x 1 vector ``name_1 ... name_6``: ``[omega; v]`` for the words of
    :mod:`rigidsym.algebra.rigid_motions` with an angular-first order (the default), ``[v; omega]``
    with ``order="pinocchio"`` (the order is the word's, never the vector's).

    Args:
        name: the book name (``"V"``).
        t: :data:`TIME` or ``None``.

    Returns:
        6 x 1 ``sympy.Matrix`` of real atoms [rad/s; m/s].
    """
    return vector(name, t, 6)


def wrench(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free wrench, a 6 x 1 vector ``[n; f]`` (moment first, Angeles' order; see
    :func:`twist` for the order of the words that read it).

    Args:
        name: the book name (``"F"``).
        t: :data:`TIME` or ``None``.

    Returns:
        6 x 1 ``sympy.Matrix`` of real atoms [N m; N].
    """
    return vector(name, t, 6)


def rotation(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A generic 3 x 3 proper orthogonal matrix (``Q^T Q = 1``, ``det Q = 1`` imposed
    exactly by the zero test through a rational quaternion).

    Args:
        name: the book name; the entries are ``name_ij``, row-major, from 1.
        t: :data:`TIME` for a rotation that moves (``Q^T Q_dot`` is then skew exactly),
            else ``None``.

    Returns:
        3 x 3 ``sympy.Matrix`` of constrained atoms.

    Raises:
        ValueError: ``t`` is neither :data:`TIME` nor ``None``.
    """
    return constrained_group("rotation", name, t)


def vector(name: str, t: sp.Symbol | None = None, n: int = 3) -> sp.Matrix:
    """A free n x 1 vector (no constraint).

    Args:
        name: the book name; the entries are ``name_1 ... name_n``.
        t: :data:`TIME` for entries that are functions of time, else ``None``.
        n: the number of entries.

    Returns:
        n x 1 ``sympy.Matrix`` of real atoms.
    """
    return sp.Matrix([_atom(c, t) for c in _components(name, n)])


def scalar(name: str, t: sp.Symbol | None = None):
    """A free real scalar.

    Args:
        name: the book name.
        t: :data:`TIME` for a function of time, else ``None``.

    Returns:
        A real symbol, or the applied function ``name(t)``.
    """
    return _atom(name, t)


def matrix(name: str, rows: int = 3, cols: int = 3, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free rows x cols matrix.

    Args:
        name: the book name; the entries are ``name_ij``, row-major, from 1.
        rows: number of rows.
        cols: number of columns.
        t: :data:`TIME` for entries that are functions of time, else ``None``.

    Returns:
        rows x cols ``sympy.Matrix`` of real atoms.
    """
    return sp.Matrix(rows, cols, [_atom(f"{name}_{i}{j}", t)
                                  for i in range(1, rows + 1) for j in range(1, cols + 1)])


def symmetric_matrix(name: str, t: sp.Symbol | None = None) -> sp.Matrix:
    """A free symmetric 3 x 3 matrix (an inertia matrix, say).

    Args:
        name: the book name; the six atoms are ``name_ij`` with ``i <= j``.
        t: :data:`TIME` for entries that are functions of time, else ``None``.

    Returns:
        3 x 3 symmetric ``sympy.Matrix``.
    """
    a = {(i, j): _atom(f"{name}_{min(i, j)}{max(i, j)}", t) for i in range(1, 4)
         for j in range(1, 4)}
    return sp.Matrix(3, 3, lambda i, j: a[(i + 1, j + 1)])
