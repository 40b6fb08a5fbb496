"""Sec. 3.3: Rotation of a rigid body about a fixed point, Eqs. (3.41)-(3.46).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.3.

First principles: a rigid motion ``x0 -> Q(t) x0 + c(t)`` with ``Q(t)`` a generic smooth
rotation, given by its natural invariants ``e(t)``, ``phi(t)`` (Eq. (2.49); the zero test
then decides by exact evaluation, Schwartz-Zippel, about ten times faster than exact
cancellation over quaternion jets); the fixed point O is the origin, so ``Q O + c = O``
gives ``c = 0``. Velocities are time derivatives of the positions; ``Omega`` and ``omega``
are computed from ``Q(t)`` by their definitions.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    TIME,
    Rel,
    Statement,
    angle,
    equation,
    rotation_from_natural_invariants,
    unit_vector,
    vect,
    vector,
)

from .common import O3, Cross, Mt, vec

Q, Q_dot, Omega, omega, p, p_dot = Mt.Q, Mt.Q_dot, Mt.Omega, Mt.omega, Mt.p, Mt.p_dot
#: position of P in the original configuration
p_0 = vec("p_0")
_im = sp.ImmutableMatrix


@cache
def fixed_point_motion_model() -> dict:
    """``Q(t)`` from ``e(t)``, ``phi(t)``; ``p0`` a free constant; ``c(t) = o - Q(t) o``
    for the fixed point ``o = 0``; ``p(t) = Q p0 + c``, ``pdot`` its derivative;
    ``Omega = Qdot Q^T``, ``omega = vect(Omega)`` (definitions (3.44), (3.45))."""
    Qm = rotation_from_natural_invariants(unit_vector("e", TIME), angle("phi", TIME))
    p0 = vector("s33_p0")
    o = sp.zeros(3, 1)  # the fixed point O, at the origin
    c = o - Qm * o
    pm = Qm * p0 + c
    Qd = Qm.diff(TIME)
    Om = Qd * Qm.T
    model = {Q: _im(Qm), Q_dot: _im(Qd), p_0: _im(p0), p: _im(pm), p_dot: _im(pm.diff(TIME)),
             Omega: _im(Om), omega: _im(vect(Om))}
    return model


def _model() -> dict:
    return dict(fixed_point_motion_model())


@equation("3.41", "Position of a point of a body with a fixed point", section="3.3",
          expected="definition",
          latex=r"\mathbf{p}(t) = \mathbf{Q}(t)\mathbf{p}_0")
def fixed_point_position() -> Statement:
    """``p(t) = Q(t) p0``. Book: Sec. 3.3, Eq. (3.41). Shapes: 3 x 1, m."""
    return Statement([Rel(p, Q * p_0)], _model())


@equation("3.42", "Velocity from the original position", section="3.3",
          expected="definition",
          latex=r"\dot{\mathbf{p}}(t) = \dot{\mathbf{Q}}(t)\mathbf{p}_0")
def fixed_point_velocity_original() -> Statement:
    """``pdot(t) = Qdot(t) p0``. Book: Sec. 3.3, Eq. (3.42). Shapes: 3 x 1, m/s."""
    return Statement([Rel(p_dot, Q_dot * p_0)], _model())


@equation("3.43", "Velocity from the current position", section="3.3",
          latex=r"\dot{\mathbf{p}} = \dot{\mathbf{Q}}\mathbf{Q}^T\mathbf{p}")
def fixed_point_velocity_current() -> Statement:
    """``pdot = Qdot Q^T p``. Book: Sec. 3.3, Eq. (3.43). Shapes: 3 x 1, m/s."""
    return Statement([Rel(p_dot, Q_dot * Q.T * p)], _model())


@equation("3.44", "Angular-velocity matrix", section="3.3", kind="definition",
          latex=r"\boldsymbol{\Omega} \equiv \dot{\mathbf{Q}}\mathbf{Q}^T")
def angular_velocity_matrix() -> Statement:
    """``Omega = Qdot Q^T`` (3 x 3, 1/s). Book: Sec. 3.3, Eq. (3.44) (definition)."""
    return Statement([Rel(Omega, Q_dot * Q.T)], _model(), defines=("Omega",))


@equation("thm3.3.1", "The angular-velocity matrix is skew-symmetric", section="3.3",
          kind="claim", latex=r"The angular-velocity matrix is skew-symmetric.")
def angular_velocity_matrix_skew() -> Statement:
    """Theorem 3.3.1: ``Omega^T = -Omega`` (entry by entry), from ``Q Q^T = 1``.

    Book: Sec. 3.3, Theorem 3.3.1.
    """
    return Statement([Rel(Omega + Omega.T, O3)], _model())


@equation("3.45", "Angular-velocity vector", section="3.3", kind="definition",
          latex=r"\boldsymbol{\omega} \equiv \text{vect}(\boldsymbol{\Omega})")
def angular_velocity_vector() -> Statement:
    """``omega = vect(Omega)`` (3 x 1, rad/s). Book: Sec. 3.3, Eq. (3.45) (definition)."""
    return Statement([Rel(omega, vect(Omega))], _model(), defines=("omega",))


@equation("3.46", "Velocity of a point of a body with a fixed point", section="3.3",
          latex=r"\dot{\mathbf{p}} = \boldsymbol{\Omega}\mathbf{p} = \boldsymbol{\omega} "
                r"\times \mathbf{p}")
def fixed_point_velocity() -> Statement:
    """``pdot = Omega p = omega x p``, member by member; the text's consequence, ``pdot``
    perpendicular to ``OP`` (``p^T pdot = 0``), is checked as a claim.

    Book: Sec. 3.3, Eq. (3.46). Shapes: 3 x 1, m/s.
    """
    return Statement([Rel(p_dot, Omega * p, "Omega p"),
                      Rel(p_dot, Cross(omega, p), "omega x p")], _model(),
                     claims=[Rel(p.T * p_dot, sp.ZeroMatrix(1, 1), "pdot normal to OP")])
