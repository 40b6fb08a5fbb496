"""Sec. 3.5: acceleration analysis of rigid-body motions, Eqs. (3.84)-(3.95b).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.5.

First principles: a generic smooth motion (:func:`derivations.common.motion_model`), a body
point ``p(t) = a(t) + Q(t) r``; ``Omega = Q_dot Q^T``, ``omega = vect(Omega)`` and all
derivatives computed along it. (3.84)-(3.90) use a generic rotation ``Q(t)``; (3.91)-(3.94)
need the invariants ``e(t)``, ``phi(t)`` and use the pose ``s = [q; q0; d_A]`` of (3.34)
with ``d_A = a(t) - a0``, the twist ``t = [omega; a_dot]`` at the landmark point ``A``, and
the three choices ``F = N, L, H`` (``F~ = N~, L~, H~``) of (3.76)-(3.77).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    TIME,
    Rel,
    Statement,
    angle,
    as_vector,
    block,
    cpm,
    equation,
    matrix,
    unit_vector,
    vect,
    vector,
)

from .common import I3, MS, O3, Mt, mat, motion_model, vec
from .sec3_4_2 import S_matrix, T_matrix
from .sec3_5_rates import LEFT_INVERSES, RATE_MATRICES, Rt, rates_model

__all__ = ["point_acceleration"]


def point_acceleration(a_ddot, omega, omega_dot, p, a) -> sp.Matrix:
    """Acceleration of a body point: ``p_ddot = a_ddot + w_dot x (p - a) + w x [w x (p - a)]``.

    Book: Sec. 3.5, Eq. (3.89).

    Args:
        a_ddot: acceleration of the body point A, 3 x 1 (m/s^2).
        omega: angular velocity, 3 x 1 (rad/s).
        omega_dot: angular acceleration, 3 x 1 (rad/s^2).
        p: position of the point P, 3 x 1 (m).
        a: position of the point A, 3 x 1 (m).

    Returns:
        3 x 1 ``sympy.Matrix``: the acceleration of P (m/s^2). No singularity.
    """
    a_ddot, w, w_dot = as_vector(a_ddot, "a_ddot"), as_vector(omega, "omega"), \
        as_vector(omega_dot, "omega_dot")
    d = as_vector(p, "p") - as_vector(a, "a")
    return a_ddot + w_dot.cross(d) + w.cross(w.cross(d))


# --------------------------------------------------------------------------- models
p, a, p_dot, a_dot, p_ddot, a_ddot = Mt.p, Mt.a, Mt.p_dot, Mt.a_dot, Mt.p_ddot, Mt.a_ddot
Omega, Omega_dot, omega, omega_dot = Mt.Omega, Mt.Omega_dot, Mt.omega, Mt.omega_dot
W = mat("W")  # angular-acceleration matrix (3.86)
t_dot, v_dot = MS("tdot", 6), vec("vdot")


@cache
def _generic() -> dict:
    """Generic rotation Q(t) and body points; W from its definition (3.86)."""
    m = dict(motion_model(invariants=False))
    m[W] = sp.ImmutableMatrix(m[Omega_dot] + m[Omega] ** 2)
    m[v_dot] = m[p_ddot]
    m[t_dot] = sp.ImmutableMatrix(block([[m[omega]], [m[p_dot]]]).diff(TIME))
    m[I3] = sp.ImmutableMatrix(sp.eye(3))
    return m


# --------------------------------------------------------------------------- (3.84)-(3.90)
@equation("3.84", "Acceleration of a body point", section="3.5",
          latex=r"\ddot{\mathbf{p}} = \ddot{\mathbf{a}} + \dot{\boldsymbol{\Omega}}(\mathbf{p} "
                r"- \mathbf{a}) + \boldsymbol{\Omega}(\dot{\mathbf{p}} - \dot{\mathbf{a}})")
def acceleration_by_differentiation() -> Statement:
    """``p_ddot = a_ddot + Omega_dot (p - a) + Omega (p_dot - a_dot)`` (m/s^2, 3 x 1).

    Book: Sec. 3.5, Eq. (3.84).
    """
    return Statement([Rel(p_ddot, a_ddot + Omega_dot * (p - a) + Omega * (p_dot - a_dot))],
                     _generic())


@equation("3.85", "Acceleration through the angular-acceleration matrix", section="3.5",
          latex=r"\ddot{\mathbf{p}} = \ddot{\mathbf{a}} + (\dot{\boldsymbol{\Omega}} + "
                r"\boldsymbol{\Omega}^2)(\mathbf{p} - \mathbf{a})")
def acceleration_with_angular_acceleration_matrix() -> Statement:
    """``p_ddot = a_ddot + (Omega_dot + Omega^2)(p - a)`` (m/s^2). Book: Sec. 3.5, Eq. (3.85)."""
    return Statement([Rel(p_ddot, a_ddot + (Omega_dot + Omega**2) * (p - a))], _generic())


@equation("3.86", "Angular-acceleration matrix", section="3.5", kind="definition",
          latex=r"\mathbf{W} \equiv \dot{\boldsymbol{\Omega}} + \boldsymbol{\Omega}^2")
def angular_acceleration_matrix() -> Statement:
    """``W = Omega_dot + Omega^2`` (3 x 3, 1/s^2).

    Book: Sec. 3.5, Eq. (3.86). Claims (the text around it): ``p_ddot = a_ddot + W (p - a)``
    and ``Omega^2`` is symmetric. (That ``Omega_dot`` is skew-symmetric is not restated:
    the exact-cancel path of the zero test needs ~30 s for it; (3.87) relies on it and is
    checked.)
    """
    return Statement([Rel(W, Omega_dot + Omega**2)], _generic(), defines=("W",),
                     claims=[Rel(p_ddot, a_ddot + W * (p - a), "p_ddot = a_ddot + W (p - a)"),
                             Rel((Omega**2).T, Omega**2, "Omega^2 symmetric")])


@equation("3.87", "Axial vector of W is the angular acceleration", section="3.5",
          latex=r"\text{vect}(\mathbf{W}) = \text{vect}(\dot{\boldsymbol{\Omega}}) = "
                r"\dot{\boldsymbol{\omega}}")
def axial_vector_of_W() -> Statement:
    """``vect(W) = vect(Omega_dot) = omega_dot`` (rad/s^2), member by member.

    Book: Sec. 3.5, Eq. (3.87).
    """
    return Statement([Rel(vect(W), vect(Omega_dot), "vect(Omega_dot)"),
                      Rel(vect(W), omega_dot, "omega_dot")], _generic())


@equation("3.88", "Trace of W", section="3.5",
          latex=r"\begin{aligned} \text{tr}(\mathbf{W}) &= \text{tr}(\boldsymbol{\Omega}^2) = "
                r"\text{tr}(-\|\boldsymbol{\omega}\|^2 \mathbf{1} + \boldsymbol{\omega} "
                r"\boldsymbol{\omega}^T) \\ &= -\|\boldsymbol{\omega}\|^2 \text{tr}(\mathbf{1}) "
                r"+ \boldsymbol{\omega} \cdot \boldsymbol{\omega} = -2\|\boldsymbol{\omega}\|^2 "
                r"\end{aligned}")
def trace_of_W() -> Statement:
    """``tr W = tr Omega^2 = tr(-|w|^2 1 + w w^T) = -|w|^2 tr 1 + w.w = -2 |w|^2`` (1/s^2).

    Book: Sec. 3.5, Eq. (3.88); ``|w|^2`` is written ``w^T w``, ``tr 1 = 3``.
    """
    n2 = (omega.T * omega)[0, 0]
    trW = sp.Trace(W)
    return Statement([Rel(trW, sp.Trace(Omega**2), "tr(Omega^2)"),
                      Rel(trW, sp.Trace(-n2 * I3 + omega * omega.T), "tr(-|w|^2 1 + w w^T)"),
                      Rel(trW, -n2 * sp.Trace(I3) + n2, "-|w|^2 tr(1) + w.w"),
                      Rel(trW, -2 * n2, "-2 |w|^2")], _generic())


@equation("3.89", "Acceleration with cross products", section="3.5",
          latex=r"\ddot{\mathbf{p}} = \ddot{\mathbf{a}} + \dot{\boldsymbol{\omega}} \times "
                r"(\mathbf{p} - \mathbf{a}) + \boldsymbol{\omega} \times [\boldsymbol{\omega} "
                r"\times (\mathbf{p} - \mathbf{a})]")
def acceleration_with_cross_products() -> Statement:
    """``p_ddot = a_ddot + w_dot x (p - a) + w x [w x (p - a)]`` (:func:`point_acceleration`).

    Book: Sec. 3.5, Eq. (3.89).
    """
    return Statement([Rel(p_ddot, point_acceleration(a_ddot, omega, omega_dot, p, a))],
                     _generic())


@equation("3.90", "Twist rate", section="3.5", kind="definition",
          latex=r"\dot{\mathbf{t}} \equiv \begin{bmatrix} \dot{\boldsymbol{\omega}} \\ "
                r"\dot{\mathbf{v}} \end{bmatrix}")
def twist_rate() -> Statement:
    """``t_dot = [omega_dot; v_dot]`` (6 x 1), ``v_dot`` the acceleration of a body point.

    Book: Sec. 3.5, Eq. (3.90). Claims: it is the time derivative of the twist
    ``t = [omega; p_dot]`` (3.72), and ``v_dot`` is given by (3.89).
    """
    return Statement([Rel(t_dot, sp.BlockMatrix([[omega_dot], [v_dot]]))], _generic(),
                     defines=("tdot",),
                     claims=[Rel(v_dot, point_acceleration(a_ddot, omega, omega_dot, p, a),
                                 "v_dot by (3.89)")])


# --------------------------------------------------------------------------- (3.91)-(3.94)
CHOICES = ("N", "L", "H")
F_DOT = {"N": Rt.N_dot, "L": Rt.L_dot, "H": Rt.H_dot}
FT_DOT = {"N": Rt.Nt_dot, "L": Rt.Lt_dot, "H": Rt.Ht_dot}
T_of = {n: MS(f"T_{n}", 7, 6) for n in CHOICES}
Tdot_of = {n: MS(f"Tdot_{n}", 7, 6) for n in CHOICES}
S_of = {n: MS(f"S_{n}", 6, 7) for n in CHOICES}
Sdot_of = {n: MS(f"Sdot_{n}", 6, 7) for n in CHOICES}
sdot_of = {n: MS(f"sdot_{n}", 7) for n in CHOICES}
sddot_of = {n: MS(f"sddot_{n}", 7) for n in CHOICES}
twist = MS("t", 6)
F_DOT_394 = MS("Fdot", 3, 4)  # the printed F_dot of (3.94) in a 3 x 4 slot (see there)
O43, O34 = sp.ZeroMatrix(4, 3), sp.ZeroMatrix(3, 4)


@cache
def _pose() -> dict:
    """Pose ``s_F = [q_F; d_A]`` (``d_A = a(t) - a0``), twist ``[omega; a_dot]``, T_F, S_F."""
    m = dict(rates_model())
    e, phi, t = m[Mt.e], m[Mt.phi], TIME
    im = sp.ImmutableMatrix
    q = {"N": block([[e], [phi]]), "L": block([[sp.sin(phi) * e], [sp.cos(phi)]]),
         "H": block([[sp.sin(phi / 2) * e], [sp.cos(phi / 2)]])}
    d_A = m[Mt.a] - vector("a0")
    tw = block([[m[Mt.omega]], [m[Mt.a_dot]]])
    m[twist], m[t_dot] = im(tw), im(tw.diff(t))
    m[F_DOT_394] = im(matrix("Fdot394", 3, 4))  # fresh: free entries
    for n in CHOICES:
        s = block([[q[n]], [d_A]])
        T = T_matrix(RATE_MATRICES[n](e, phi))
        S = S_matrix(LEFT_INVERSES[n](e, phi))
        m.update({T_of[n]: im(T), Tdot_of[n]: im(T.diff(t)), S_of[n]: im(S),
                  Sdot_of[n]: im(S.diff(t)), sdot_of[n]: im(s.diff(t)),
                  sddot_of[n]: im(s.diff(t, 2))})
    return m


@equation("3.91", "Second derivative of the pose", section="3.5",
          singular="F = N: phi = 0 (mod 2 pi)",
          latex=r"\ddot{\mathbf{s}} = \mathbf{T}\dot{\mathbf{t}} + \dot{\mathbf{T}}\mathbf{t}")
def pose_second_derivative() -> Statement:
    """``s_ddot = T t_dot + T_dot t`` (7 x 1) for ``F = N, L, H``, one member each.

    Book: Sec. 3.5, Eq. (3.91). ``T`` from (3.79); ``s_ddot``, ``T_dot``, ``t_dot`` computed
    along the motion.
    """
    return Statement([Rel(sddot_of[n], T_of[n] * t_dot + Tdot_of[n] * twist, f"F = {n}")
                      for n in CHOICES], _pose())


@equation("3.92", "Rate of T", section="3.5",
          expected="definition", singular="F = N: phi = 0 (mod 2 pi)",
          latex=r"\dot{\mathbf{T}} \equiv \begin{bmatrix} \dot{\mathbf{F}} & \mathbf{O}_{43} "
                r"\\ \mathbf{O} & \mathbf{O} \end{bmatrix}")
def rate_of_T() -> Statement:
    """``T_dot = [[F_dot, O_43], [O, O]]`` (7 x 6) for ``F = N, L, H``.

    Book: Sec. 3.5, Eq. (3.92). ``F_dot`` is the rate of F along the motion (3.96a-c).
    """
    return Statement([Rel(Tdot_of[n], sp.BlockMatrix([[F_DOT[n], O43], [O3, O3]]),
                          f"F = {n}") for n in CHOICES], _pose())


@equation("3.93", "Twist rate from the pose", section="3.5",
          singular="F~ = L~: phi = pi",
          latex=r"\dot{\mathbf{t}} = \mathbf{S}\ddot{\mathbf{s}} + "
                r"\dot{\mathbf{S}}\dot{\mathbf{s}}")
def twist_rate_from_pose() -> Statement:
    """``t_dot = S s_ddot + S_dot s_dot`` (6 x 1) for ``F~ = N~, L~, H~``.

    Book: Sec. 3.5, Eq. (3.93). ``S`` from (3.80b); everything computed along the motion.
    """
    return Statement([Rel(t_dot, S_of[n] * sddot_of[n] + Sdot_of[n] * sdot_of[n],
                          f"F~ = {n}~") for n in CHOICES], _pose())


@equation("3.94", "Rate of S", section="3.5", expected="does-not-hold", cause="conversion",
          singular="F~ = L~: phi = pi",
          evidence="the upper-left block of S_dot is the 3x4 rate of F~ (N~, L~, H~); the "
                   "printed F_dot (= N_dot, L_dot, H_dot, 4x3) lost its tilde. With a printed "
                   "copy, look at the upper-left block: a tilde under the dot of F",
          latex=r"\dot{\mathbf{S}} = \begin{bmatrix} \dot{\mathbf{F}} & \mathbf{O} \\ "
                r"\mathbf{O}_{34} & \mathbf{O} \end{bmatrix}")
def rate_of_S() -> Statement:
    """``S_dot = [[F_dot, O], [O_34, O]]`` as printed (6 x 7), for the three choices.

    Book: Sec. 3.5, Eq. (3.94). The printed ``F_dot`` is, per the text, one of ``N_dot,
    L_dot, H_dot`` (4 x 3), which cannot fill the 3 x 4 slot: it is transcribed as a fresh
    3 x 4 symbol ``Fdot`` with free entries. Corrected: ``S_dot = [[F~_dot, O], [O_34, O]]``
    with ``F~_dot`` the rates (3.97a-c, corrected) of ``N~, L~, H~``.
    """
    return Statement(
        [Rel(Sdot_of[n], sp.BlockMatrix([[F_DOT_394, O3], [O34, O3]]), f"F~ = {n}~")
         for n in CHOICES], _pose(),
        corrected=[Rel(Sdot_of[n], sp.BlockMatrix([[FT_DOT[n], O3], [O34, O3]]),
                       f"F~ = {n}~") for n in CHOICES])


# --------------------------------------------------------------------------- (3.95)
@cache
def _static_invariants() -> dict:
    """Static ``e`` (unit), ``phi``: lambda, eta by (3.75) and u, u0, r, r0 by (3.95b)."""
    e, phi = unit_vector("e"), angle("phi")
    im = sp.ImmutableMatrix
    return {Rt.u: im(sp.sin(phi) * e), Rt.u0: sp.cos(phi), Rt.r: im(sp.sin(phi / 2) * e),
            Rt.r0: sp.cos(phi / 2), Mt.e: im(e), Mt.phi: phi, Rt.U: im(cpm(sp.sin(phi) * e)),
            LAM: im(block([[sp.sin(phi) * e], [sp.cos(phi)]])),
            ETA: im(block([[sp.sin(phi / 2) * e], [sp.cos(phi / 2)]]))}


LAM, ETA = MS("lambda", 4), MS("eta", 4)


@equation("3.95a", "Linear invariants and Euler-Rodrigues parameters split", section="3.5",
          expected="definition",
          latex=r"\boldsymbol{\lambda} \equiv \begin{bmatrix} \mathbf{u} \\ u_0 \end{bmatrix}, "
                r"\quad \boldsymbol{\eta} \equiv \begin{bmatrix} \mathbf{r} \\ r_0 \end{bmatrix}")
def invariant_arrays_split() -> Statement:
    """``lambda = [u; u0]``, ``eta = [r; r0]`` (4 x 1), lambda and eta as in (3.75).

    Book: Sec. 3.5, Eq. (3.95a): names for the parts, with u, u0, r, r0 from (3.95b).
    """
    one = sp.ImmutableMatrix
    return Statement([Rel(LAM, sp.BlockMatrix([[Rt.u], [one([[Rt.u0]])]]), "lambda"),
                      Rel(ETA, sp.BlockMatrix([[Rt.r], [one([[Rt.r0]])]]), "eta")],
                     _static_invariants())


@equation("3.95b", "u, u0, r, r0", section="3.5", kind="definition",
          latex=r"\mathbf{u} \equiv \sin \phi \mathbf{e}, \quad u_0 \equiv \cos \phi, \quad "
                r"\mathbf{r} \equiv \sin \left( \frac{\phi}{2} \right) \mathbf{e}, \quad r_0 "
                r"\equiv \cos \left( \frac{\phi}{2} \right)")
def linear_invariants_and_euler_rodrigues() -> Statement:
    """``u = sin(phi) e``, ``u0 = cos phi``, ``r = sin(phi/2) e``, ``r0 = cos(phi/2)``.

    Book: Sec. 3.5, Eq. (3.95b). Claims: ``u.u + u0^2 = 1`` and ``r.r + r0^2 = 1`` (3.35).
    """
    e, phi = Mt.e, Mt.phi
    return Statement([Rel(Rt.u, sp.sin(phi) * e), Rel(Rt.u0, sp.cos(phi)),
                      Rel(Rt.r, sp.sin(phi / 2) * e), Rel(Rt.r0, sp.cos(phi / 2))],
                     _static_invariants(), defines=("u", "u0", "r", "r0"),
                     claims=[Rel((Rt.u.T * Rt.u)[0, 0] + Rt.u0**2, 1, "|u|^2 + u0^2 = 1"),
                             Rel((Rt.r.T * Rt.r)[0, 0] + Rt.r0**2, 1, "|r|^2 + r0^2 = 1")])
