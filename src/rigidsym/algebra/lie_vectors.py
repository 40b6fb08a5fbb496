"""The exponential and logarithm of unconstrained exponents (issue 38): the rotation vector
``w`` of so(3) and the exponential coordinates ``[w; v]`` of se(3), in the norm ``theta =
sqrt(w^T w)``.

These are the forms of Solà, Deray & Atchuthan, "A micro Lie theory for state estimation in
robotics" (2018), App. B (SO(3)) and D (SE(3)), and Barfoot, *State Estimation for
Robotics* (2017), Sec. 7.1; they equal Modern Robotics' (3.51), (3.88) with ``w = theta
omega``. As printed they are singular at ``w = 0``, a removable singularity the code
generator replaces by its series (:mod:`rigidsym.codegen.removable.singularities`); the zero test
reads ``theta`` through the polar parametrisation ``w = theta e``
(:mod:`rigidsym.checking.deciding.branches`).
"""

from __future__ import annotations

import sympy as sp

__all__ = ["norm3", "exp_of_vector", "log_explicit", "log_se3_explicit"]


# the explicit formulas rigidsym.algebra.lie builds on: kept here, below it, so that the
# import goes one way
def explicit_cpm(w) -> sp.Matrix:
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def explicit_axial(A) -> sp.Matrix:
    h = sp.Rational(1, 2)
    return sp.Matrix([h * (A[2, 1] - A[1, 2]), h * (A[0, 2] - A[2, 0]), h * (A[1, 0] - A[0, 1])])


def explicit_transform(R, p) -> sp.Matrix:
    return sp.Matrix.vstack(sp.Matrix.hstack(sp.Matrix(R), sp.Matrix(p)),
                            sp.Matrix([[0, 0, 0, 1]]))


def log_explicit(R) -> sp.Matrix:
    """``theta / (2 sin theta) (R - R^T)``, ``theta = acos((tr R - 1) / 2)`` (MR (3.53)-(3.54)).

    ``sin theta`` is kept unevaluated (sympy would write ``sqrt(1 - c^2)`` for
    ``sin(acos(c))``), so that the zero test's principal branch
    (:mod:`rigidsym.checking.deciding.branches`) makes it ``sin b`` for an angle ``b`` on
    ``[0, pi]`` with ``cos b = (tr R - 1) / 2``.
    """
    R = sp.Matrix(R)
    theta = sp.acos((R.trace() - 1) / 2)
    s = sp.sin(theta, evaluate=False)
    return (R - R.T).applyfunc(lambda e: sp.Mul(theta, e, sp.Pow(2 * s, -1, evaluate=False),
                                                 evaluate=False))


def norm3(w) -> sp.Expr:
    """``theta = sqrt(w^T w)``, the angle of the rotation vector ``w`` (3 x 1).

    The zero test reads it through the polar parametrisation ``w = theta e`` (``theta`` an
    angle on ``[0, pi]``, ``e`` a unit vector: :mod:`rigidsym.checking.deciding.branches`);
    Solà, Deray & Atchuthan (2018), App. B, ``theta = ||theta u||``.

    Args:
        w: the rotation vector, 3 entries (a sympy Matrix or a sequence) [rad].

    Returns:
        The scalar ``sqrt(w1**2 + w2**2 + w3**2)`` [rad], a sympy expression.
    """
    w = sp.Matrix(w)
    return sp.sqrt(sum(x**2 for x in w))


def exp_of_vector(X) -> sp.Matrix:
    """``exp([w])`` (3 x 3) or ``exp([w, v]^)`` (4 x 4) of an unconstrained exponent.

    With ``theta = sqrt(w^T w)`` and ``W = [w]``: ``exp(W) = 1 + (sin theta / theta) W +
    ((1 - cos theta) / theta^2) W^2`` (Solà et al. 2018, "A micro Lie theory", App. B;
    Barfoot, *State Estimation for Robotics*, Sec. 7.1.3) and ``exp([[W, v], [0, 0]]) =
    [[exp(W), J_l(w) v], [0, 1]]`` with the left Jacobian ``J_l(w) = 1 + ((1 - cos
    theta) / theta^2) W + ((theta - sin theta) / theta^3) W^2`` (MR (3.88) with ``[w] =
    theta [omega]``; Solà App. D; Barfoot Sec. 7.1.4). Removable singularity at ``w = 0``.
    """
    X = sp.Matrix(X)
    w = explicit_axial(X[:3, :3])
    W, th = explicit_cpm(w), norm3(w)
    R = sp.eye(3) + sp.sin(th) / th * W + (1 - sp.cos(th)) / th**2 * W * W
    if X.shape == (3, 3):
        return R
    J = sp.eye(3) + (1 - sp.cos(th)) / th**2 * W + (th - sp.sin(th)) / th**3 * W * W
    return explicit_transform(R, J * X[:3, 3])


def log_se3_explicit(T) -> sp.Matrix:
    """The principal logarithm of a transform ``T = [[R, p], [0, 1]]``: ``[[Omega, J_l^-1
    p], [0, 0]]`` with ``Omega = log R`` (:func:`log_explicit`, ``[w] = Omega``, ``theta =
    acos((tr R - 1) / 2)``) and ``J_l^-1 = 1 - Omega / 2 + (1 / theta^2 - sin theta / (2
    theta (1 - cos theta))) Omega^2`` (MR (3.91)-(3.92); Solà App. D; Barfoot Sec. 7.1.4).
    Singular as printed at ``theta = 0`` and ``theta = pi`` (those of ``log R``).
    """
    T = sp.Matrix(T)
    Om = log_explicit(T[:3, :3])
    theta = sp.acos((T[:3, :3].trace() - 1) / 2)
    s = sp.sin(theta, evaluate=False)
    k = 1 / theta**2 - s / (2 * theta * (1 - sp.cos(theta)))
    Jinv = sp.eye(3) - Om / 2 + k * Om * Om
    return sp.Matrix.vstack(sp.Matrix.hstack(Om, Jinv * T[:3, 3]), sp.zeros(1, 4))
