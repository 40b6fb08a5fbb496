"""Sec. 3.6: Rigid-body motion referred to moving coordinate axes, Eqs. (3.98)-(3.105).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.6.

Frame tags are part of the symbol: ``[p]_F`` is ``p_F``, ``[rho]_M`` is ``rho_M``; a
quantity is never silently moved from one frame to the other.

First principles (the model of every declaration here): a fixed frame F, a moving frame M
whose origin has F-coordinates ``o(t)`` (free) and whose orientation is ``Q(t)``, an exactly
orthogonal generic rotation (rational quaternion jets), "taking F into the orientation of
M", so that the k-th axis of M has F-coordinates ``Q[:, k]``. A point P moves *arbitrarily*
relative to M: its M-coordinates ``[rho]_M(t)`` are free. The vector ``rho`` from the
origin of M to P is ``sum_k rho_k (axis k of M)``, so ``[rho]_F = sum_k rho_k Q[:, k]``
(a sum of columns, not the product of (3.99)) and ``[p]_F = [o]_F + [rho]_F``. Rates in a
frame are time derivatives of the coordinates in that frame; ``[Omega]_F = [Qdot]_F
[Q]_F^T`` (definition (3.44)). Nothing of (3.102)-(3.105) is assumed: the orthogonality
they rest on (``Q_dot = Q_dot Q^T Q``) is exact in ``Q(t)``.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import TIME, Rel, Statement, as_vector, cpm, equation, rotation, vect, vector

from .common import mat, vec

__all__ = ["moving_frame_acceleration"]

# Book symbols, tagged by the frame they are referred to.
p_F, o_F, rho_F, rho_M = vec("p_F"), vec("o_F"), vec("rho_F"), vec("rho_M")
pdot_F, odot_F, rhodot_M = vec("pdot_F"), vec("odot_F"), vec("rhodot_M")
pddot_F, oddot_F, rhoddot_M = vec("pddot_F"), vec("oddot_F"), vec("rhoddot_M")
Q_F, Qdot_F = mat("Q_F"), mat("Qdot_F")
Omega_F, Omegadot_F = mat("Omega_F"), mat("Omegadot_F")


def moving_frame_acceleration(o_ddot, Q, omega, omega_dot, rho_M, rho_dot_M, rho_ddot_M):
    """Acceleration of a point in the fixed frame F from its motion relative to M.

    ``[p_ddot]_F = [o_ddot]_F + (Omega_dot + Omega^2) Q [rho]_M + 2 Omega Q [rho_dot]_M
    + Q [rho_ddot]_M`` with ``Omega = cpm(omega)``: transport acceleration (first two
    terms), Coriolis acceleration ``2 omega x (Q rho_dot_M)``, relative acceleration.

    Book: Sec. 3.6, Eq. (3.105).

    Args:
        o_ddot: 3x1, acceleration of the origin of M, in F (m/s^2).
        Q: 3x3, orientation of M relative to F (proper orthogonal).
        omega, omega_dot: 3x1, angular velocity (rad/s) and acceleration (rad/s^2) of M
            relative to F, in F.
        rho_M, rho_dot_M, rho_ddot_M: 3x1, position (m), velocity and acceleration of the
            point as seen in M, M-coordinates.

    Returns:
        3x1 ``sympy.Matrix``: ``[p_ddot]_F`` in m/s^2. No singular set (polynomial).
    """
    Om = cpm(omega)
    Q = sp.Matrix(Q)
    return (as_vector(o_ddot) + (cpm(omega_dot) + Om * Om) * Q * as_vector(rho_M)
            + 2 * Om * Q * as_vector(rho_dot_M) + Q * as_vector(rho_ddot_M))


def _moving_frame_model() -> tuple[dict, dict]:
    """Model of the Sec. 3.6 symbols (see the module docstring) and extra explicit values."""
    t = TIME
    Q = rotation("Q", t)
    o = vector("s36_o", t)
    rM = vector("s36_rho", t)  # the point's coordinates in M: an arbitrary motion in M
    rF = sum((rM[k] * Q[:, k] for k in range(3)), sp.zeros(3, 1))  # sum rho_k (axis k of M)
    p = o + rF  # the point: origin of M plus its coordinates times the axes of M
    Qd = Q.diff(t)
    Om = Qd * Q.T
    im = sp.ImmutableMatrix
    model = {p_F: im(p), o_F: im(o), rho_F: im(rF), rho_M: im(rM), Q_F: im(Q),
             pdot_F: im(p.diff(t)), odot_F: im(o.diff(t)), rhodot_M: im(rM.diff(t)),
             Qdot_F: im(Qd), Omega_F: im(Om), Omegadot_F: im(Om.diff(t)),
             pddot_F: im(p.diff(t, 2)), oddot_F: im(o.diff(t, 2)),
             rhoddot_M: im(rM.diff(t, 2))}
    extra = {"omega": vect(Om), "omega_dot": vect(Om).diff(t)}
    return model, extra


@equation("3.98", "Position of P in F: origin of M plus relative position", section="3.6",
          expected="definition",
          latex=r"[\mathbf{p}]_{\mathcal{F}} = [\mathbf{o}]_{\mathcal{F}} + "
                r"[\boldsymbol{\rho}]_{\mathcal{F}}")
def position_in_fixed_frame() -> Statement:
    """``[p]_F = [o]_F + [rho]_F``: the vector triangle O_F, O_M, P of Fig. 3.7.

    Book: Sec. 3.6, Eq. (3.98). Shapes: 3x1, metres, F-coordinates.
    """
    model, _ = _moving_frame_model()
    return Statement([Rel(p_F, o_F + rho_F)], model)


@equation("3.99", "Relative position changed from M- to F-coordinates", section="3.6",
          expected="definition",
          latex=r"[\boldsymbol{\rho}]_{\mathcal{F}} = [\mathbf{Q}]_{\mathcal{F}}"
                r"[\boldsymbol{\rho}]_{\mathcal{M}}")
def relative_position_to_fixed_frame() -> Statement:
    """``[rho]_F = [Q]_F [rho]_M`` (holds because ``Q Q^T = 1`` exactly).

    Book: Sec. 3.6, Eq. (3.99). Shapes: 3x1 (metres), 3x3.
    """
    model, _ = _moving_frame_model()
    return Statement([Rel(rho_F, Q_F * rho_M)], model)


@equation("3.100", "Position of P in F from its M-coordinates", section="3.6",
          expected="definition",
          latex=r"[\mathbf{p}]_{\mathcal{F}} = [\mathbf{o}]_{\mathcal{F}} + "
                r"[\mathbf{Q}]_{\mathcal{F}}[\boldsymbol{\rho}]_{\mathcal{M}}")
def position_from_moving_coordinates() -> Statement:
    """``[p]_F = [o]_F + [Q]_F [rho]_M``. Book: Sec. 3.6, Eq. (3.100). 3x1, metres."""
    model, _ = _moving_frame_model()
    return Statement([Rel(p_F, o_F + Q_F * rho_M)], model)


@equation("3.101", "Velocity of P in F, by differentiating (3.100)", section="3.6",
          expected="definition",
          latex=r"[\dot{\mathbf{p}}]_{\mathcal{F}} = [\dot{\mathbf{o}}]_{\mathcal{F}} + "
                r"[\dot{\mathbf{Q}}]_{\mathcal{F}}[\boldsymbol{\rho}]_{\mathcal{M}} + "
                r"[\mathbf{Q}]_{\mathcal{F}}[\dot{\boldsymbol{\rho}}]_{\mathcal{M}}")
def velocity_in_fixed_frame_raw() -> Statement:
    """``[p_dot]_F = [o_dot]_F + [Q_dot]_F [rho]_M + [Q]_F [rho_dot]_M``.

    Book: Sec. 3.6, Eq. (3.101). Shapes: 3x1, m/s.
    """
    model, _ = _moving_frame_model()
    return Statement([Rel(pdot_F, odot_F + Qdot_F * rho_M + Q_F * rhodot_M)], model)


@equation("3.102", "Rate of the orientation of M", section="3.6",
          latex=r"[\dot{\mathbf{Q}}]_{\mathcal{F}} = [\boldsymbol{\Omega}]_{\mathcal{F}}"
                r"[\mathbf{Q}]_{\mathcal{F}}")
def orientation_rate() -> Statement:
    """``[Q_dot]_F = [Omega]_F [Q]_F``, from ``Omega = Q_dot Q^T`` and ``Q^T Q = 1``.

    Book: Sec. 3.6, Eq. (3.102). Shapes: 3x3, 1/s.
    """
    model, _ = _moving_frame_model()
    return Statement([Rel(Qdot_F, Omega_F * Q_F)], model)


@equation("3.103", "Velocity of P in F: transport plus relative velocity", section="3.6",
          latex=r"[\dot{\mathbf{p}}]_{\mathcal{F}} = [\dot{\mathbf{o}}]_{\mathcal{F}} + "
                r"[\boldsymbol{\Omega}]_{\mathcal{F}}[\mathbf{Q}]_{\mathcal{F}}"
                r"[\boldsymbol{\rho}]_{\mathcal{M}} + [\mathbf{Q}]_{\mathcal{F}}"
                r"[\dot{\boldsymbol{\rho}}]_{\mathcal{M}}")
def velocity_in_fixed_frame() -> Statement:
    """``[p_dot]_F = [o_dot]_F + [Omega]_F [Q]_F [rho]_M + [Q]_F [rho_dot]_M``.

    Book: Sec. 3.6, Eq. (3.103). Shapes: 3x1, m/s.
    """
    model, _ = _moving_frame_model()
    return Statement([Rel(pdot_F, odot_F + Omega_F * Q_F * rho_M + Q_F * rhodot_M)], model)


@equation("3.104", "Acceleration of P in F, by differentiating (3.103)", section="3.6",
          latex=r"\begin{aligned} [\ddot{\mathbf{p}}]_{\mathcal{F}} = & "
                r"[\ddot{\mathbf{o}}]_{\mathcal{F}} + [\dot{\boldsymbol{\Omega}}]_{\mathcal{F}}"
                r"[\mathbf{Q}]_{\mathcal{F}}[\boldsymbol{\rho}]_{\mathcal{M}} + "
                r"[\boldsymbol{\Omega}]_{\mathcal{F}}[\dot{\mathbf{Q}}]_{\mathcal{F}}"
                r"[\boldsymbol{\rho}]_{\mathcal{M}} \\ & + [\boldsymbol{\Omega}]_{\mathcal{F}}"
                r"[\mathbf{Q}]_{\mathcal{F}}[\dot{\boldsymbol{\rho}}]_{\mathcal{M}} + "
                r"[\dot{\mathbf{Q}}]_{\mathcal{F}}[\dot{\boldsymbol{\rho}}]_{\mathcal{M}} + "
                r"[\mathbf{Q}]_{\mathcal{F}}[\ddot{\boldsymbol{\rho}}]_{\mathcal{M}} "
                r"\end{aligned}")
def acceleration_in_fixed_frame_raw() -> Statement:
    """``[p_ddot]_F = [o_ddot] + [Omega_dot] Q rho + Omega Q_dot rho + Omega Q rho_dot
    + Q_dot rho_dot + Q rho_ddot`` (F-tags on o, Omega, Q; M-tags on rho).

    Book: Sec. 3.6, Eq. (3.104). Shapes: 3x1, m/s^2.
    """
    model, _ = _moving_frame_model()
    rhs = (oddot_F + Omegadot_F * Q_F * rho_M + Omega_F * Qdot_F * rho_M
           + Omega_F * Q_F * rhodot_M + Qdot_F * rhodot_M + Q_F * rhoddot_M)
    return Statement([Rel(pddot_F, rhs)], model)


@equation("3.105", "Acceleration of P in F with the Coriolis term", section="3.6",
          latex=r"\begin{aligned} [\ddot{\mathbf{p}}]_{\mathcal{F}} = & "
                r"[\ddot{\mathbf{o}}]_{\mathcal{F}} + ([\dot{\boldsymbol{\Omega}}]_{\mathcal{F}}"
                r" + [\boldsymbol{\Omega}^2]_{\mathcal{F}})[\mathbf{Q}]_{\mathcal{F}}"
                r"[\boldsymbol{\rho}]_{\mathcal{M}} \\ & + 2[\boldsymbol{\Omega}]_{\mathcal{F}}"
                r"[\mathbf{Q}]_{\mathcal{F}}[\dot{\boldsymbol{\rho}}]_{\mathcal{M}} + "
                r"[\mathbf{Q}]_{\mathcal{F}}[\ddot{\boldsymbol{\rho}}]_{\mathcal{M}} "
                r"\end{aligned}")
def acceleration_in_fixed_frame() -> Statement:
    """``[p_ddot]_F = [o_ddot]_F + ([Omega_dot]_F + [Omega^2]_F) [Q]_F [rho]_M
    + 2 [Omega]_F [Q]_F [rho_dot]_M + [Q]_F [rho_ddot]_M``.

    ``[Omega^2]_F`` is transcribed as ``[Omega]_F^2`` (a change of frame is a similarity,
    so the two agree). The claim checks the kernel :func:`moving_frame_acceleration`, fed
    with ``omega = vect(Q_dot Q^T)`` and its rate, against the same first-principles
    acceleration.

    Book: Sec. 3.6, Eq. (3.105). Shapes: 3x1, m/s^2.
    """
    model, extra = _moving_frame_model()
    rhs = (oddot_F + (Omegadot_F + Omega_F * Omega_F) * Q_F * rho_M
           + 2 * Omega_F * Q_F * rhodot_M + Q_F * rhoddot_M)
    kernel = moving_frame_acceleration(model[oddot_F], model[Q_F], extra["omega"],
                                       extra["omega_dot"], model[rho_M], model[rhodot_M],
                                       model[rhoddot_M])
    return Statement([Rel(pddot_F, rhs)], model, derived=None,
                     claims=[Rel(pddot_F, kernel, "kernel moving_frame_acceleration")])
