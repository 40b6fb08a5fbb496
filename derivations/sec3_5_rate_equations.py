"""Sec. 3.5: the rates of N, L, H and of their left inverses as printed, Eqs. (3.96a)-(3.97e).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.5. The
declarations compare the printed forms with the rates obtained by differentiation along a
generic motion; the formula functions, the book symbols and the motion model are in
:mod:`rigidsym.derivations.sec3_5_rates`.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import Rel, Statement, angle, equation

from .common import I3, Mt
from .sec3_5_rates import (
    B_matrix,
    H_matrix_dot,
    H_tilde_dot,
    L_matrix_dot,
    L_tilde_dot,
    N_matrix_dot,
    N_tilde_dot,
    Rt,
    V_u,
    _book,
    _dot,
    omega_model,
    rates_model,
)

e, phi, phi_dot, e_dot, E = Mt.e, Mt.phi, Mt.phi_dot, Mt.e_dot, Mt.E
omega, Omega, Q, Q_dot = Mt.omega, Mt.Omega, Mt.Q, Mt.Q_dot
c_phi, s_phi = sp.cos(phi), sp.sin(phi)


# --------------------------------------------------------------------------- (3.96)
def _B_printed():
    """``B`` as printed in (3.96e), in the motion's ``e``, ``phi``, ``omega`` (3 x 3, rad/s)."""
    ew = _dot(e, omega)
    return (-2 * ew * I3 + 2 * (3 - c_phi) * ew * e * e.T - 2 * (1 + s_phi) * omega * e.T
            - (2 * c_phi + s_phi) * e * omega.T - s_phi * (Omega - ew * E))


@equation("3.96a", "Rate of N", section="3.5", expected="does-not-hold", cause="unknown",
          evidence="the factor 1/(4(1 - cos phi)) belongs to B alone: printed, it multiplies "
                   "the last row e_dot^T of N_dot as well (the rate of the row e^T of N); "
                   "with B as (3.96e) prints it (a book erratum there) the upper block fails "
                   "too",
          singular="phi = 0 (mod 2 pi)",
          latex=r"\dot{\mathbf{N}} = \frac{1}{4(1 - \cos \phi)} \begin{bmatrix} \mathbf{B} "
                r"\\ \dot{\mathbf{e}} \end{bmatrix}")
def rate_of_N() -> Statement:
    """``N_dot = [B; e_dot] / (4 (1 - cos phi))`` as printed; ``N_dot`` is 4 x 3 (1/s).

    Book: Sec. 3.5, Eq. (3.96a). The printed ``e_dot`` sits in the bottom row of a 4 x 3
    block, so it is read as the row ``e_dot^T`` (the only reading the block admits); the
    verdict does not depend on it. ``B`` is the page's: "B is defined as" (3.96e), so the
    printed relation has (3.96e)'s ``B`` (:func:`_B_printed`). Corrected: ``N_dot = [B /
    (4 (1 - cos phi)); e_dot^T]``, with ``B`` in closed form from :func:`B_matrix`
    (corrected (3.96e)).
    """
    k = 1 / (4 * (1 - c_phi))
    return Statement(
        [Rel(Rt.N_dot, k * sp.BlockMatrix([[_B_printed()], [e_dot.T]]))], omega_model(),
        corrected=[Rel(Rt.N_dot, _book(N_matrix_dot), "closed form, B written out")])


@equation("3.96b", "Rate of L", section="3.5",
          latex=r"\begin{aligned} \dot{\mathbf{L}} &= \begin{bmatrix} (1/2)[\mathbf{1tr}"
                r"(\dot{\mathbf{Q}}) - \dot{\mathbf{Q}}] \\ -(1/2)\boldsymbol{\omega}^T "
                r"[\mathbf{1tr}(\mathbf{Q}) - \mathbf{Q}^T] \end{bmatrix} \\ &= "
                r"\begin{bmatrix} -(\boldsymbol{\omega} \cdot \mathbf{u})\mathbf{1} - (1/2)"
                r"\boldsymbol{\Omega}\mathbf{Q} \\ -(1/2)\boldsymbol{\omega}^T [\mathbf{1tr}"
                r"(\mathbf{Q}) - \mathbf{Q}^T] \end{bmatrix} \end{aligned}")
def rate_of_L() -> Statement:
    """``L_dot = [(1 tr(Q_dot) - Q_dot)/2; -w^T (1 tr(Q) - Q^T)/2] = [-(w.u) 1 - Omega Q/2; ...]``.

    Book: Sec. 3.5, Eq. (3.96b). 4 x 3 (1/s). The second member is :func:`L_matrix_dot`
    called with the book's symbols (it prints as the book's second member).
    """
    bottom = -omega.T * (sp.Trace(Q) * I3 - Q.T) / 2
    first = sp.BlockMatrix([[(sp.Trace(Q_dot) * I3 - Q_dot) / 2], [bottom]])
    return Statement([Rel(Rt.L_dot, first, "first member"),
                      Rel(Rt.L_dot, _book(L_matrix_dot), "second member")], rates_model())


@equation("3.96c", "Rate of H", section="3.5",
          latex=r"\dot{\mathbf{H}} = \frac{1}{2} \begin{bmatrix} \dot{r}_0\mathbf{1} - "
                r"\dot{\mathbf{R}} \\ -\dot{\mathbf{r}}^T \end{bmatrix}")
def rate_of_H() -> Statement:
    """``H_dot = 1/2 [r0_dot 1 - R_dot; -r_dot^T]`` (4 x 3, 1/s); ``R = cpm(r)``.

    Book: Sec. 3.5, Eq. (3.96c). The rhs is :func:`H_matrix_dot` called with the book's
    symbols (it prints as the book's rhs).
    """
    return Statement([Rel(Rt.H_dot, _book(H_matrix_dot))], rates_model())


@equation("3.96d", "Trace of the rotation rate", section="3.5",
          latex=r"\text{tr}(\dot{\mathbf{Q}}) \equiv \text{tr}(\boldsymbol{\Omega}\mathbf{Q})"
                r" \equiv -2\boldsymbol{\omega}^T \mathbf{u}")
def trace_of_rotation_rate() -> Statement:
    """``tr(Q_dot) = tr(Omega Q) = -2 w^T u`` (1/s), member by member.

    Book: Sec. 3.5, Eq. (3.96d) (derived in the book's Appendix A).
    """
    return Statement([Rel(sp.Trace(Q_dot), sp.Trace(Omega * Q), "tr(Omega Q)"),
                      Rel(sp.Trace(Q_dot), -2 * omega.T * Rt.u, "-2 omega^T u")],
                     rates_model())


@equation("3.96e", "Auxiliary matrix B of the rate of N", section="3.5",
          expected="does-not-hold", cause="erratum",
          evidence="4(1 - cos phi) times the upper block of N_dot has coefficients 2(2 + cos "
                   "phi), -2 cos phi, -2 and a term sin phi [(E omega) e^T + e (E omega)^T]",
          latex=r"\begin{aligned} \mathbf{B} &\equiv -2(\mathbf{e} \cdot "
                r"\boldsymbol{\omega})\mathbf{1} + 2(3 - \cos \phi)(\mathbf{e} \cdot "
                r"\boldsymbol{\omega})\mathbf{e}\mathbf{e}^T - 2(1 + \sin \phi)"
                r"\boldsymbol{\omega}\mathbf{e}^T \\ &\quad - (2 \cos \phi + \sin \phi)"
                r"\mathbf{e}\boldsymbol{\omega}^T - (\sin \phi)[\boldsymbol{\Omega} - "
                r"(\mathbf{e} \cdot \boldsymbol{\omega})\mathbf{E}] \end{aligned}")
def auxiliary_matrix_B() -> Statement:
    """``B`` as printed; ``B`` is 4 (1 - cos phi) times the upper block of ``N_dot`` (3.96a).

    Book: Sec. 3.5, Eq. (3.96e). 3 x 3 (rad/s). ``N`` (hence ``N_dot`` and ``B``) is unique
    (``nu_dot = N omega`` for every ``omega``), so no other reading makes the printed form
    hold. Corrected: :func:`B_matrix`.
    """
    return Statement([Rel(Rt.B, _B_printed())], omega_model(),
                     corrected=[Rel(Rt.B, _book(B_matrix))])


# --------------------------------------------------------------------------- (3.97)
THETA = angle("theta")  # the printed "sin theta" of (3.97a): a fresh symbol, never phi


@equation("3.97a", "Rate of the left inverse N~", section="3.5", expected="does-not-hold",
          cause="conversion",
          evidence="tilde lost (rate of the 3x4 N~, not of N), theta for phi, and even so "
                   "the term (1 - cos phi) E_dot of d/dt[(1 - cos phi) E] is missing. With a "
                   "printed copy, look at the left side: a tilde under the dot of N",
          singular="none in (e_dot, phi_dot); phi = 0 (mod 2 pi) once they come from N omega",
          latex=r"\dot{\mathbf{N}} = [\dot{\phi}(\cos \phi)\mathbf{1} + \dot{\phi}(\sin "
                r"\theta)\mathbf{E} \dot{\mathbf{e}}]")
def rate_of_N_tilde() -> Statement:
    """``N_dot = [phi_dot cos(phi) 1 + phi_dot sin(theta) E, e_dot]`` as printed (3 x 4).

    Book: Sec. 3.5, Eq. (3.97a). The printed lhs is ``N_dot`` (4 x 3); the rhs is 3 x 4, the
    shape of the rate of ``N~`` (3.77b). Corrected: ``N~_dot = [phi_dot (cos phi 1 +
    sin phi E) + (1 - cos phi) E_dot, e_dot]`` (:func:`N_tilde_dot`).
    """
    rhs = sp.BlockMatrix([[phi_dot * c_phi * I3 + phi_dot * sp.sin(THETA) * E, e_dot]])
    return Statement(
        [Rel(Rt.N_dot, rhs)], rates_model(),
        corrected=[Rel(Rt.Nt_dot, _book(N_tilde_dot))])


def _V_printed():
    U, u, u_dot = Rt.U, Rt.u, Rt.u_dot
    return Rt.U_dot - (u_dot * u.T + u * u_dot.T) - Rt.u0_dot / Rt.D * (U - u * u.T)


@equation("3.97b", "Rate of the left inverse L~", section="3.5", expected="does-not-hold",
          cause="erratum",
          evidence="as printed, [V/D u_dot] is the product (V/D) u_dot, a 3-vector, against "
                   "the 4 x 3 L_dot; read as the block row [V/D, u_dot], the rate of L~ "
                   "(3 x 4), it still fails: [V/D, -u_dot] is the rate of the other left "
                   "inverse [1 + (U - u u^T)/D, -u] of L, not of (3.77c); also tilde lost and "
                   "the sign of u_dot",
          singular="phi = pi (D = 0)",
          latex=r"\dot{\mathbf{L}} = [\mathbf{V}/D \dot{\mathbf{u}}]")
def rate_of_L_tilde() -> Statement:
    """``L_dot = [V / D u_dot]`` as printed: the product ``(V / D) u_dot`` (3 x 1), ``V`` as
    (3.97d) prints it ("V and D are defined below"), ``D`` from (3.97e).

    Book: Sec. 3.5, Eq. (3.97b). The printed lhs is ``L_dot`` (4 x 3), so the shapes differ;
    the bracket read as the block row ``[V / D, u_dot]`` (its column separator lost, the
    rate of ``L~``'s shape) fails too, as the corrected members show. Corrected: the
    rate of ``L~`` (3.77c) is ``[V / D, ((u0_dot / D) u - u_dot) / D]`` with
    ``V = U_dot - (u0_dot / D) U`` (:func:`L_tilde_dot`). The printed ``V`` (3.97d) and
    ``[V / D, -u_dot]`` are the rate of ``[1 + (U - u u^T) / D, -u]``, an equally valid left
    inverse of ``L`` (it differs from (3.77c) by a multiple of ``lambda^T``, the left null
    vector of ``L``): that member is verified too.
    """
    return Statement(
        [Rel(Rt.L_dot, _V_printed() / Rt.D * Rt.u_dot)], rates_model(),
        corrected=[Rel(Rt.Lt_dot, _book(L_tilde_dot), "rate of L~ (3.77c)"),
                   Rel(Rt.Lt_alt_dot, sp.BlockMatrix([[_V_printed() / Rt.D, -Rt.u_dot]]),
                       "rate of [1 + (U - u u^T)/D, -u]")])


@equation("3.97c", "Rate of the left inverse H~", section="3.5", expected="does-not-hold",
          cause="conversion",
          evidence="tilde lost (rate of the 3x4 H~, not of H), and the factor 2 of H~ "
                   "(3.77d) is missing: d/dt H~ = 2 [r0_dot 1 + R_dot, -r_dot]. With a printed "
                   "copy, look at the left side: a tilde under the dot of H",
          latex=r"\dot{\mathbf{H}} = [\dot{r}_0\mathbf{1} + \dot{\mathbf{R}} - "
                r"\dot{\mathbf{r}}]")
def rate_of_H_tilde() -> Statement:
    """``H_dot = [r0_dot 1 + R_dot, -r_dot]`` as printed (3 x 4).

    Book: Sec. 3.5, Eq. (3.97c). The printed lhs is ``H_dot`` (4 x 3). Corrected:
    ``H~_dot = 2 [r0_dot 1 + R_dot, -r_dot]`` (:func:`H_tilde_dot`). The printed bracket
    is the rate of ``H~ / 2``, which maps ``eta_dot`` to ``omega / 2`` (not a left inverse).
    """
    rhs = sp.BlockMatrix([[Rt.r0_dot * I3 + Rt.R_dot, -Rt.r_dot]])
    return Statement(
        [Rel(Rt.H_dot, rhs)], rates_model(),
        corrected=[Rel(Rt.Ht_dot, _book(H_tilde_dot))])


@equation("3.97d", "Auxiliary matrix V of the rate of L~", section="3.5",
          expected="does-not-hold", cause="erratum",
          evidence="D times the rate of the block 1 + U/D of L~ (3.77c) is U_dot - (u0_dot/D) "
                   "U; the printed V is that of 1 + (U - u u^T)/D (another left inverse)",
          singular="phi = pi (D = 0)",
          latex=r"\mathbf{V} \equiv \dot{\mathbf{U}} - (\dot{\mathbf{u}}\mathbf{u}^T + "
                r"\mathbf{u}\dot{\mathbf{u}}^T) - \frac{\dot{u}_0}{D}(\mathbf{U} - "
                r"\mathbf{u}\mathbf{u}^T)")
def auxiliary_matrix_V() -> Statement:
    """``V = U_dot - (u_dot u^T + u u_dot^T) - (u0_dot / D)(U - u u^T)`` as printed (3 x 3).

    Book: Sec. 3.5, Eq. (3.97d). ``V`` is introduced by (3.97b): ``D`` times the upper
    block of the rate of ``L~`` (3.77c). Corrected: ``V = U_dot - (u0_dot / D) U``
    (:func:`V_u`); the printed expression is verified as ``V_alt``, the same quantity for
    the left inverse ``[1 + (U - u u^T)/D, -u]`` of ``L``.
    """
    return Statement([Rel(Rt.V, _V_printed())], rates_model(),
                     corrected=[Rel(Rt.V, _book(V_u), "for L~ of (3.77c)"),
                                Rel(Rt.V_alt, _V_printed(), "for [1 + (U - u u^T)/D, -u]")])


@equation("3.97e", "D = 1 + u0", section="3.5", kind="definition",
          singular="D = 0 at phi = pi",
          latex=r"D \equiv 1 + u_0")
def denominator_D() -> Statement:
    """``D = 1 + u0 = 1 + cos phi`` (dimensionless); claim: ``D = 2 r0^2``, zero at phi = pi.

    Book: Sec. 3.5, Eq. (3.97e).
    """
    return Statement([Rel(Rt.D, 1 + Rt.u0)], rates_model(), defines=("D",),
                     claims=[Rel(Rt.D, 2 * Rt.r0**2, "D = 2 r0^2")])
