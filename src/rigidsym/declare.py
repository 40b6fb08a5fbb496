"""The declaration vocabulary: everything a user module needs to declare equations.

All of it is re-exported from :mod:`rigidsym` (``from rigidsym import equation, ...``).

- Declaring: :func:`equation` (decorator), :class:`Statement`, :class:`Rel`.
- Constrained atoms (the zero test imposes their constraints exactly):
  :func:`unit_vector` (``e . e = 1``), :func:`unit_vector4` (a unit 4-vector, e.g. the
  Euler-Rodrigues parameters ``[r; r0]``), :func:`rotation` (``Q^T Q = 1``, ``det Q = 1``),
  :func:`angle` (``cos^2 + sin^2 = 1``), :func:`rigid_motion` (a rotation and a translation
  as functions of :data:`TIME`, with their time derivatives).
- Free atoms: :func:`vector`, :func:`scalar`, :func:`matrix`, :func:`symmetric_matrix`.
- Book symbols, for printed forms that read like the book: :func:`vec` (3-vector),
  :func:`mat` (3 x 3), :func:`MS` (any shape), ``I3``, ``O3``.
- Operators printed forms use: :func:`cpm` (cross-product matrix), :func:`vect` (axial
  vector), :func:`trace`, :class:`Cross`, :class:`Det`, :class:`Blocks` (lazy book
  operators, explicit once the model is substituted), and the chapter-2 formulas
  :func:`rotation_from_natural_invariants` (2.49), :func:`rotation_from_euler_rodrigues`,
  :func:`rotation_from_quaternion`, :func:`linear_invariants`,
  :func:`euler_rodrigues_parameters`.
- Rigid motions (Modern Robotics ch. 3, Murray-Li-Sastry ch. 2): :func:`twist`,
  :func:`wrench`, :func:`hat`, :func:`vee`, :func:`transform`, :func:`transform_inverse`,
  :func:`Ad`, :func:`ad`, :func:`ad_dual` (6-vector orders named per word, :data:`ORDERS`),
  :func:`expm`, :func:`logm`, :func:`diff`, :data:`acos`, :data:`atan2` and
  ``angle(..., range="[0, pi]")`` (see ``docs/rigid-motions.md``).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rigidsym.algebra import operators as _operators
from rigidsym.algebra import rigid_motions as _rigid_motions
from rigidsym.algebra import symbols as _symbols
from rigidsym.algebra.operators import MS, Blocks, Cross, Det, mat, vec
from rigidsym.algebra.primitives import (
    as_vector,
    block,
    cpm,
    euler_rodrigues_parameters,
    eye3,
    linear_invariants,
    rotation_from_euler_rodrigues,
    rotation_from_natural_invariants,
    rotation_from_quaternion,
    trace,
    vect,
)
from rigidsym.algebra.rigid_motions import (
    Ad,
    ad,
    ad_dual,
    diff,
    expm,
    hat,
    logm,
    norm3,
    transform,
    transform_inverse,
    vee,
)
from rigidsym.algebra.symbols import (
    angle,
    matrix,
    rotation,
    scalar,
    symmetric_matrix,
    twist,
    unit_vector,
    unit_vector4,
    vector,
    wrench,
)
from rigidsym.registry import declarations as _registry
from rigidsym.registry.declarations import Rel, Statement, equation

__all__ = [
    "equation", "Statement", "Rel",
    "TIME", "unit_vector", "unit_vector4", "rotation", "angle", "rigid_motion", "RigidMotion",
    "vector", "scalar", "matrix", "symmetric_matrix",
    "vec", "mat", "MS", "I3", "O3",
    "cpm", "vect", "trace", "Cross", "Det", "Blocks",
    "rotation_from_natural_invariants", "rotation_from_euler_rodrigues",
    "rotation_from_quaternion", "linear_invariants", "euler_rodrigues_parameters",
    "as_vector", "block", "eye3", "cancel_matrix",
    # the vocabulary of rigid motions (rigidsym.algebra.rigid_motions)
    "twist", "wrench", "hat", "vee", "transform", "transform_inverse", "Ad", "ad", "ad_dual",
    "expm", "logm", "diff", "acos", "atan2", "ORDERS",
    # the angle of a rotation vector, read through w = theta e by the zero test
    "norm3",
]

def _printed_from_latex(eq, st):
    """The printed relations of a declaration with ``latex=`` and no printed form: its LaTeX
    read by :mod:`rigidsym.latex`, each glyph named and shaped as the model's symbol of that
    name (``\\mathbf{R}`` is the model's ``R``), else as a symbol of its module of that name
    (a constrained atom such as ``theta = angle("theta")`` stands for itself)."""
    import sys

    from rigidsym.latex.lets import module_symbols
    from rigidsym.latex.statement import read_statement

    mod = sys.modules.get(eq.module)
    lend = module_symbols(vars(mod)) if mod is not None else {}
    lend.update({s.name: (s, None) for s in st.model
                 if isinstance(s, sp.Symbol | sp.MatrixSymbol)})
    printed = read_statement(eq.latex, [], None, lend).statement.printed
    own = {sp.Symbol(n, real=True): v for n, (s, v) in lend.items()
           if v is s and isinstance(s, sp.Symbol)}  # the module's constrained scalars
    return [type(r)(r.lhs.xreplace(own), r.rhs.xreplace(own), r.label) if own else r
            for r in printed]


_registry.PRINTED_FROM_LATEX = _printed_from_latex

#: The time symbol ``t`` (real) of trajectories: atoms made with ``t=TIME`` are functions
#: of it, and derivatives along a motion are taken with respect to it.
TIME = _symbols.TIME
#: The book's 3 x 3 identity ``1`` as a matrix expression (``sympy.Identity(3)``).
I3 = _operators.I3
#: The book's 3 x 3 zero matrix ``O`` as a matrix expression (``sympy.ZeroMatrix(3, 3)``).
O3 = _operators.O3
#: The orders of twists and wrenches by name (``"angeles"``, ``"modern-robotics"``,
#: ``"featherstone"``: the angular part first, 0; ``"pinocchio"``, ``"ros"``: the linear
#: part first, 1), as the words of rigid motions take them (``order=``).
ORDERS = _rigid_motions.ORDERS


def acos(x):
    """``acos(x)`` on its principal branch ``[0, pi]`` (sympy's ``acos``).

    The zero test rewrites ``acos(cos b)`` as ``b`` for an angle on ``[0, pi]``
    (``angle(..., range="[0, pi]")``) and splits a default angle into ``theta`` and
    ``-theta`` (``acos(cos theta) = |theta|``); elsewhere it is undecided, never guessed
    (``docs/rigid-motions.md``). Source: MR (3.54).

    Args:
        x: a scalar expression.

    Returns:
        ``sympy.acos(x)`` [rad].
    """
    return sp.acos(x)


def atan2(y, x):
    """``atan2(y, x)`` on its principal branch ``(-pi, pi]`` (sympy's ``atan2``).

    The zero test rewrites ``atan2(k sin a, k cos a)`` as ``a`` for an angle ``a`` and a
    positive constant ``k`` proven exactly (``docs/rigid-motions.md``).

    Args:
        y: the sine side (a scalar expression).
        x: the cosine side.

    Returns:
        ``sympy.atan2(y, x)`` [rad].
    """
    return sp.atan2(y, x)


@dataclass(frozen=True)
class RigidMotion:
    """A generic smooth rigid motion ``x(t) = Q(t) x0 + c(t)`` and its time derivatives.

    Attributes:
        Q, Q_dot, Q_ddot: the rotation (3 x 3, proper orthogonal at every ``t``) and its
            first two derivatives.
        Omega, omega: the angular-velocity matrix ``Q_dot Q^T`` (skew) and vector
            ``vect(Omega)`` [rad/s].
        omega_dot: the angular acceleration [rad/s^2].
        c, c_dot, c_ddot: the translation (3 x 1) [m] and its derivatives.
        e, phi: the axis (unit) and angle when built from natural invariants, else None.
    """

    Q: sp.Matrix
    Q_dot: sp.Matrix
    Q_ddot: sp.Matrix
    Omega: sp.Matrix
    omega: sp.Matrix
    omega_dot: sp.Matrix
    c: sp.Matrix
    c_dot: sp.Matrix
    c_ddot: sp.Matrix
    e: sp.Matrix | None = None
    phi: sp.Expr | None = None


def rigid_motion(name: str = "Q", translation: str = "c", *,
                 invariants: bool = False) -> RigidMotion:
    """A rigid motion along which every constraint holds at every instant.

    Args:
        name: the rotation's name (atoms ``name_ij(t)``; with ``invariants=True`` the axis
            and angle are ``name_e`` and ``name_phi``).
        translation: the translation's name (atoms ``translation_i(t)``).
        invariants: build ``Q(t)`` from a unit axis ``e(t)`` and an angle ``phi(t)`` (2.49)
            instead of a generic rotation (rational quaternion): larger expressions, for
            identities that mention the axis or the angle.

    Returns:
        A :class:`RigidMotion` of explicit sympy matrices in the time symbol :data:`TIME`.

    Example:
        >>> m = rigid_motion()
        >>> (m.Omega + m.Omega.T).shape  # Omega is skew: the zero test decides it is 0
        (3, 3)
    """
    t = TIME
    e = phi = None
    if invariants:
        e, phi = unit_vector(f"{name}_e", t), angle(f"{name}_phi", t)
        Q = rotation_from_natural_invariants(e, phi)
    else:
        Q = rotation(name, t)
    Q_dot = Q.diff(t)
    Omega = Q_dot * Q.T
    omega = vect(Omega)
    c = vector(translation, t)
    return RigidMotion(Q, Q_dot, Q_dot.diff(t), Omega, omega, omega.diff(t), c, c.diff(t),
                       c.diff(t, 2), e, phi)


def cancel_matrix(m) -> sp.Matrix:
    """Every entry of a matrix of rational functions brought to lowest terms, exactly.

    The result is what ``m.applyfunc(sympy.cancel)`` returns, the same expression trees,
    computed faster: the fractions are first reduced with python-flint's multivariate
    polynomials (FLINT's gcd), and ``sympy.cancel``'s own last step makes them canonical.
    An entry that is not a rational function of its atoms (a root, a sine) goes to
    ``sympy.cancel`` as it is. Used by the book's Sec. 3.4 models; a user module may use
    it for its own large models.

    Args:
        m: a sympy matrix (any shape) of rational functions of its atoms.

    Returns:
        A new mutable ``sympy.Matrix`` of the same shape.

    Raises:
        TypeError: ``m`` is not a matrix (nor a list of rows of expressions).
    """
    from rigidsym.zero.cancel import cancel_matrix as _cancel_matrix  # python-flint: lazily

    if isinstance(m, str | bytes) or m is None:
        raise TypeError(f"m: expected a sympy matrix, got {type(m).__name__}")
    try:
        m = sp.Matrix(m)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"m: expected a sympy matrix or a list of rows of expressions, "
                        f"got {type(m).__name__}") from exc
    return _cancel_matrix(m)
