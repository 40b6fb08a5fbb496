"""The words of the vocabulary of rigid motions (issue 28): ``hat``, ``vee``, ``transform``,
``transform_inverse``, ``Ad``, ``ad``, ``ad_dual``, ``expm``, ``diff``.

Each returns an explicit matrix for explicit operands and the lazy operator of
:mod:`rigidsym.algebra.lie` for book symbols; the formulas, their sources and the orders of
6-vectors (:data:`rigidsym.algebra.lie.ORDERS`) are documented there.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.algebra.lie import (
    ORDERS,
    AdDual,
    AdT,
    AdV,
    Expm,
    Hat,
    Logm,
    Transform,
    TransformInverse,
    Vee,
    exp_explicit,
)
from rigidsym.algebra.operators import Diff, is_symbolic
from rigidsym.algebra.primitives import cpm, vect

__all__ = ["hat", "vee", "transform", "transform_inverse", "Ad", "ad", "ad_dual", "expm",
           "logm", "diff"]


def _order(order: str) -> int:
    if order not in ORDERS:
        raise ValueError(f"order: expected one of {', '.join(map(repr, ORDERS))}, "
                         f"got {order!r}")
    return ORDERS[order]


def _shape(x, name: str) -> tuple[int, int]:
    if not isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        raise ValueError(f"{name}: expected a matrix or vector, got {type(x).__name__}")
    return tuple(int(n) for n in x.shape)


# --------------------------------------------------------------------- the words
def _lazy_or(cls, args, flag=None):
    mats = list(args)
    extra = [sp.Integer(flag)] if flag is not None else []
    if any(is_symbolic(a) for a in mats):
        return cls(*mats, *extra)
    op = cls(*[sp.ImmutableMatrix(a) if isinstance(a, sp.MatrixBase) else a for a in mats],
             *extra)
    return sp.Matrix(op.value(*[sp.Matrix(a) for a in mats]))


def hat(x, order: str = "angeles"):
    """``[x]``: the so(3) matrix of a 3-vector (the cross-product matrix, Angeles (2.38),
    MR (3.30)) or the se(3) matrix ``[[[w], v], [0, 0]]`` of a twist (MR (3.85), MLS
    (2.36)).

    Args:
        x: a 3 x 1 vector or a 6 x 1 twist (explicit, or a book symbol).
        order: the twist's order (:data:`ORDERS`).

    Returns:
        3 x 3 or 4 x 4; explicit for explicit ``x``, the lazy :class:`Hat` for a symbol.

    Raises:
        ValueError: ``x`` is neither 3 x 1 nor 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    if Hat.shape_of([_shape(x, "x")]) == (3, 3):
        return cpm(x)  # so(3): the book's cross-product matrix, one word for one thing
    return _lazy_or(Hat, [x], lin)


def vee(X, order: str = "angeles"):
    """``X^vee``, the inverse of :func:`hat`: the axial vector of the skew part of a 3 x 3
    (= ``vect``, Angeles Sec. 2.3.3), the twist ``[w; v]`` of a 4 x 4 (MR (3.85)).

    Args:
        X: 3 x 3 or 4 x 4 (explicit, or a book symbol).
        order: the twist's order (:data:`rigidsym.algebra.lie.ORDERS`).

    Returns:
        3 x 1 or 6 x 1; lazy for a book symbol.

    Raises:
        ValueError: ``X`` is neither 3 x 3 nor 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    if Vee.shape_of([_shape(X, "X")]) == (3, 1):
        return vect(X)
    return _lazy_or(Vee, [X], lin)


def transform(R, p):
    """The homogeneous transform ``[[R, p], [0, 1]]`` (4 x 4; MR (3.62), Angeles (2.80)).

    Args:
        R: 3 x 3 rotation.
        p: 3 x 1 translation [m].

    Returns:
        4 x 4; lazy for book symbols.

    Raises:
        ValueError: shapes other than 3 x 3 and 3 x 1.
    """
    Transform.shape_of([_shape(R, "R"), _shape(p, "p")])
    return _lazy_or(Transform, [R, p])


def transform_inverse(T):
    """``T^-1 = [[R^T, -R^T p], [0, 1]]`` of a homogeneous transform (MR (3.64)); exact for
    a rotation block only (no general matrix inverse).

    Args:
        T: 4 x 4 homogeneous transform.

    Returns:
        4 x 4; lazy for a book symbol.

    Raises:
        ValueError: ``T`` is not 4 x 4.
    """
    TransformInverse.shape_of([_shape(T, "T")])
    return _lazy_or(TransformInverse, [T])


def Ad(T, order: str = "angeles"):
    """``[Ad_T]`` (6 x 6) of ``T = (R, p)``: ``[[R, 0], [[p] R, R]]`` on angular-first
    twists (MR (3.83), MLS (2.58)); wrenches transform by its transpose (MR (3.98)).

    Args:
        T: 4 x 4 homogeneous transform.
        order: the twists' order (:data:`rigidsym.algebra.lie.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``T`` is not 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    AdT.shape_of([_shape(T, "T")])
    return _lazy_or(AdT, [T], lin)


def ad(V, order: str = "angeles"):
    """``[ad_V]`` (6 x 6) of a twist ``V = [w; v]``: ``[[[w], 0], [[v], [w]]]`` (MR (8.38)):
    ``ad(V1) V2`` is the Lie bracket ``vee([V1] [V2] - [V2] [V1])``.

    Args:
        V: 6 x 1 twist.
        order: its order (:data:`rigidsym.algebra.lie.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``V`` is not 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    AdV.shape_of([_shape(V, "V")])
    return _lazy_or(AdV, [V], lin)


def ad_dual(V, order: str = "angeles"):
    """``ad*_V = -[ad_V]^T`` (6 x 6), the dual acting on wrenches (Featherstone (2.20),
    ``v x*``); MR's ``[ad_V]^T`` is ``-ad_dual(V)``.

    Args:
        V: 6 x 1 twist.
        order: its order (:data:`rigidsym.algebra.lie.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``V`` is not 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    AdDual.shape_of([_shape(V, "V")])
    return _lazy_or(AdDual, [V], lin)


def expm(X, order: str = "angeles", *, unit_axis: bool = False):
    """The matrix exponential of ``theta [w]`` (so(3), a rotation) or ``theta [S]`` (se(3),
    a transform), in closed form (:func:`exp_explicit`: MR (3.51), (3.88); Angeles (2.49)).

    An angle times a generator with a unit axis ``|w| = 1`` (or ``w = 0``, ``|v| = 1``),
    proven exactly when the value is formed, takes MR's closed forms; any other exponent (a
    free rotation vector ``w``, exponential coordinates ``[w; v]``) those in the norm
    ``theta = sqrt(w^T w)`` (:func:`rigidsym.algebra.lie_vectors.exp_of_vector`, Solà et
    al. 2018 App. B and D), whose ``w = 0`` is a removable singularity.

    Args:
        X: 3 x 3 or 4 x 4: ``theta * hat(w)`` of book symbols (lazy), or explicit.
        order: unused by the matrix form; accepted for a uniform vocabulary.
        unit_axis: explicit ``X`` only: the caller asserts ``|w| = 1`` (a kernel's
            argument of kind ``"unit"``, validated at run time); a declaration's model
            never needs it (its unit vectors are known by construction).

    Returns:
        3 x 3 rotation or 4 x 4 transform; lazy for book symbols.

    Raises:
        ValueError: not 3 x 3 or 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    Expm.shape_of([_shape(X, "X")])
    if unit_axis and not is_symbolic(X):
        return exp_explicit(X, lin, unit=True)
    return _lazy_or(Expm, [X], lin)


def logm(R):
    """The principal logarithm of a rotation (MR (3.53)-(3.54), Algorithm of Sec. 3.2.3.3):
    ``[omega] theta = theta / (2 sin theta) (R - R^T)`` with ``theta = acos((tr R - 1) /
    2)`` in ``[0, pi]``.

    Singular set: ``theta = 0`` (the formula is ``0/0``; the log is ``O``) and ``theta =
    pi`` (``sin theta = 0``, the axis is determined only up to sign: MR's other branch).
    The zero test decides it where ``R``'s model is a rotation by an angle on ``[0, pi]``
    (``angle(..., range="[0, pi]")``); on the default range it is the log of the rotation
    by ``|theta|`` about ``sign(theta) omega``, which the split of ``acos`` handles.

    Of a transform ``T = [[R, p], [0, 1]]`` (4 x 4): ``[[log R, J_l^-1 p], [0, 0]]``
    (MR (3.91)-(3.92); :func:`rigidsym.algebra.lie_vectors.log_se3_explicit`).

    Args:
        R: 3 x 3 rotation or 4 x 4 transform (explicit, or a book symbol: lazy).

    Returns:
        3 x 3 skew matrix ``[omega] theta``, or the 4 x 4 se(3) matrix of a transform.

    Raises:
        ValueError: ``R`` is neither 3 x 3 nor 4 x 4.
    """
    Logm.shape_of([_shape(R, "R")])
    return _lazy_or(Logm, [R])


def diff(X, v):
    """``dX/dv`` of any modelled symbol or expression: matrices (lazily for book symbols,
    :class:`~rigidsym.algebra.operators.Diff`) and scalars; the book's dot accents are
    ``v = t`` (:data:`rigidsym.algebra.symbols.TIME`).

    Args:
        X: a scalar, an explicit matrix or a matrix expression of book symbols.
        v: the variable (a real symbol: an angle, time, a scalar).

    Returns:
        The derivative, of the shape of ``X``: lazy (``Diff`` or an unevaluated
        ``Derivative``) where ``X`` holds book symbols.

    Raises:
        ValueError: ``v`` is not a symbol.
    """
    if not isinstance(v, sp.Symbol):
        raise ValueError(f"v: expected a sympy symbol, got {type(v).__name__}")
    if isinstance(X, sp.MatrixExpr) and not isinstance(X, sp.MatrixBase):
        return Diff(X, v)
    if isinstance(X, sp.MatrixBase):
        return sp.Matrix(X).diff(v)
    return sp.Derivative(X, v) if X.atoms(sp.MatrixSymbol) else sp.diff(X, v)
