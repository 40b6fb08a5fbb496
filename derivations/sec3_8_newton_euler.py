"""Sec. 3.8: Dynamics of rigid bodies, Eqs. (3.134a)-(3.148): Newton-Euler equations,
momenta, inertia and angular-velocity dyads, momentum screw, Steiner's theorem in dyad form.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.8.

First principles: the body of four point masses of :mod:`derivations.sec3_8` (see there why
it stands for every body), moving rigidly with an exactly orthogonal ``Q(t)``. The wrench
about C is the one the motion requires, ``f = sum m_i pddot_i``, ``n_C = sum m_i r_i x
pddot_i`` (internal forces cancel in pairs), ``omega = vect(Qdot Q^T)``, ``I_C(t)`` the sum
over the moving points, rates by differentiation in time. The inertia dyad at a point A is
the matrix of the kinetic energy in the twist at A: for a rigid velocity field
``pdot_i = v + omega x (p_i - a)`` with a free twist ``[omega; v]``,
``T_A = 1/2 sum m_i ||pdot_i||^2`` and ``M_A = Hessian(T_A)`` (``M_C`` the same at A = C).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import TIME, Rel, Statement, block, cpm, equation, vector

from .common import I3, MS, O3
from .sec3_8 import (
    POINT_BODY_WORDS,
    Dy,
    _sq,
    inertia_dyad_at_point,
    kinetic_energy,
    motion_model,
    moving_body,
    newton_euler_wrench,
    static_body,
    static_model,
    with_positive_masses,
)

_im = sp.ImmutableMatrix
m, T, c, c_dot, c_ddot, a, A, C = Dy.m, Dy.T, Dy.c, Dy.c_dot, Dy.c_ddot, Dy.a, Dy.A, Dy.C
I_C, I_A, I_C_dot = Dy.I_C, Dy.I_A, Dy.I_C_dot
omega, omega_dot, Omega, f, n_C = Dy.omega, Dy.omega_dot, Dy.Omega, Dy.f, Dy.n_C
momentum, h_C, momentum_dot, h_C_dot = Dy.momentum, Dy.h_C, Dy.momentum_dot, Dy.h_C_dot
M, M_dot, W = MS("M", 6, 6), MS("Mdot", 6, 6), MS("W", 6, 6)
t, t_dot, mu, mu_dot, w = MS("t", 6), MS("tdot", 6), MS("mu", 6), MS("mudot", 6), MS("w", 6)
M_A, M_C = MS("M_A", 6, 6), MS("M_C", 6, 6)
O6 = sp.ZeroMatrix(6, 1)


def _blk(rows):
    return sp.BlockMatrix(rows)


@cache
def dynamics_model() -> dict:
    """The motion model of :mod:`sec3_8` plus momenta, dyads, twist and wrench at C."""
    model = dict(motion_model())
    B, _, _ = moving_body()
    mass, Ic, om, cd = model[Dy.m], model[Dy.I_C], model[Dy.omega], model[Dy.c_dot]
    Mv = block([[Ic, sp.zeros(3, 3)], [sp.zeros(3, 3), mass * sp.eye(3)]])
    tv = block([[om], [cd]])
    mom, h = mass * cd, Ic * om  # definitions (3.135)
    model.update({
        momentum: _im(mom), h_C: _im(h), momentum_dot: _im(mom.diff(TIME)),
        h_C_dot: _im(h.diff(TIME)), M: _im(Mv), M_dot: _im(Mv.diff(TIME)),
        W: _im(block([[model[Dy.Omega], sp.zeros(3, 3)], [sp.zeros(3, 3), sp.zeros(3, 3)]])),
        t: _im(tv), t_dot: _im(tv.diff(TIME)), mu: _im(Mv * tv),
        mu_dot: _im((Mv * tv).diff(TIME)),
        w: _im(block([[model[Dy.n_C]], [model[Dy.f]]]))})
    return model


def _momentum_screw_first_principles(B, velocity, about):
    """``[sum m_i (p_i - about) x pdot_i; sum m_i pdot_i]`` for a point-mass body."""
    return block([[B.integral(lambda P: cpm(P.p - about) * velocity(P))],
                  [B.integral(velocity)]])


_TWIST_W, _TWIST_V = vector("s38_tw"), vector("s38_tv")


def _dyad_from_kinetic_energy(about) -> sp.Matrix:
    """Hessian of ``T = 1/2 sum m_i ||v + omega x (p_i - about)||^2`` in ``[omega; v]``."""
    B = static_body()
    T_A = B.integral(lambda P: _sq(_TWIST_V + cpm(_TWIST_W) * (P.p - about)) / 2)
    return sp.hessian(T_A, list(_TWIST_W) + list(_TWIST_V))


@cache
def dyad_model() -> dict:
    """The static model of :mod:`sec3_8` plus ``M_A`` and ``M_C`` (kinetic-energy Hessians)."""
    model = dict(static_model())
    model[M_A] = _im(_dyad_from_kinetic_energy(model[Dy.a]))
    model[M_C] = _im(_dyad_from_kinetic_energy(model[Dy.c]))
    return model


# --------------------------------------------------------------------------- declarations
@equation("3.134a", "Newton equation", section="3.8",
          latex=r"\mathbf{f} = m\ddot{\mathbf{c}}")
def newton_equation() -> Statement:
    """``f = m c_ddot``, ``f = sum m_i pddot_i``. Book: Sec. 3.8, Eq. (3.134a). 3x1, N.

    ``f`` is the sum over the particles as written, not expanded: its terms ``m_i Q_ddot
    rho_i`` cancel only in the checker's arithmetic, so the certificate keeps the body's
    shape and ``Q`` (the atoms ``f``'s line, the integral of ``rho p_ddot``, is read with).
    """
    model = dict(dynamics_model())
    model[f] = _im(moving_body()[0].integral(lambda P: P.p_ddot))
    return Statement([Rel(f, m * c_ddot)], model)


@equation("3.134b", "Euler equation", section="3.8",
          latex=r"\mathbf{n}_C = \mathbf{I}_C \dot{\boldsymbol{\omega}} + "
                r"\boldsymbol{\omega} \times \mathbf{I}_C \boldsymbol{\omega}")
def euler_equation() -> Statement:
    """``n_C = I_C omega_dot + omega x I_C omega``, ``n_C = sum m_i r_i x pddot_i``.

    Book: Sec. 3.8, Eq. (3.134b). 3x1, N m.
    """
    return Statement([Rel(n_C, I_C * omega_dot + cpm(omega) * (I_C * omega))],
                     dynamics_model())


@equation("3.135", "Momentum and angular momentum about C", section="3.8",
          kind="definition",
          latex=r"\mathbf{m} \equiv m\dot{\mathbf{c}}, \quad \mathbf{h}_C \equiv \mathbf{I}_C "
                r"\boldsymbol{\omega}")
def momenta() -> Statement:
    """``m = m c_dot`` (code name ``momentum``), ``h_C = I_C omega``.

    Claims: they are the momenta of the points, ``sum m_i pdot_i`` and
    ``sum m_i r_i x pdot_i``. Book: Sec. 3.8, Eq. (3.135) (definition). 3x1; kg m/s, kg m^2/s.
    """
    B, _, _ = moving_body()
    return Statement(
        [Rel(momentum, m * c_dot), Rel(h_C, I_C * omega)], dynamics_model(),
        defines=("momentum", "h_C"),
        claims=[Rel(m * c_dot, _im(B.integral(lambda P: P.p_dot).expand()), "sum m_i pdot_i"),
                Rel(I_C * omega, _im(B.integral(lambda P: cpm(P.r) * P.p_dot)),
                    "sum m_i r_i x pdot_i")])


@equation("3.136", "Rates of the momenta", section="3.8",
          latex=r"\dot{\mathbf{m}} = m\ddot{\mathbf{c}}, \quad \dot{\mathbf{h}}_C = "
                r"\mathbf{I}_C \dot{\boldsymbol{\omega}} + \boldsymbol{\omega} \times "
                r"\mathbf{I}_C \boldsymbol{\omega}")
def momenta_rates() -> Statement:
    """``mdot = m c_ddot``, ``hdot_C = I_C omega_dot + omega x I_C omega``.

    The rates are time derivatives of (3.135) along the motion, with ``I_C(t)`` the moving
    points' sum; the mechanism, ``Idot_C = Omega I_C - I_C Omega`` (Ex. 3.17), is a claim.
    Book: Sec. 3.8, Eq. (3.136). 3x1; N, N m.
    """
    return Statement(
        [Rel(momentum_dot, m * c_ddot, "mdot"),
         Rel(h_C_dot, I_C * omega_dot + cpm(omega) * (I_C * omega), "hdot_C")],
        dynamics_model(),
        claims=[Rel(I_C_dot, Omega * I_C - I_C * Omega, "Idot_C = Omega I_C - I_C Omega")])


@equation("3.137", "Newton-Euler equations as momentum balance", section="3.8",
          latex=r"\mathbf{f} = \dot{\mathbf{m}}, \quad \mathbf{n}_C = \dot{\mathbf{h}}_C")
def momentum_balance() -> Statement:
    """``f = mdot``, ``n_C = hdot_C``. Book: Sec. 3.8, Eq. (3.137). 3x1; N, N m."""
    return Statement([Rel(f, momentum_dot, "f"), Rel(n_C, h_C_dot, "n_C")], dynamics_model())


@equation("3.138", "Inertia dyad", section="3.8", kind="definition",
          latex=r"\mathbf{M} \equiv \begin{bmatrix} \mathbf{I}_C & \mathbf{O} \\ \mathbf{O} & "
                r"m\mathbf{1} \end{bmatrix}")
def inertia_dyad() -> Statement:
    """``M = diag(I_C, m 1)``. Book: Sec. 3.8, Eq. (3.138) (definition). 6x6."""
    return Statement([Rel(M, _blk([[I_C, O3], [O3, m * I3]]))], dynamics_model(),
                     defines=("M",))


@equation("3.139", "Newton-Euler equations in dyad form", section="3.8",
          latex=r"\mathbf{M}\dot{\mathbf{t}} + \mathbf{W}\mathbf{M}\mathbf{t} = \mathbf{w}")
def newton_euler_dyad_form() -> Statement:
    """``M t_dot + W M t = w``, ``t = [omega; c_dot]``, ``w = [n_C; f]``
    (:func:`newton_euler_wrench` gives ``w``). Book: Sec. 3.8, Eq. (3.139). 6x1."""
    return Statement([Rel(M * t_dot + W * M * t, w)], dynamics_model(),
                     claims=[Rel(w, newton_euler_wrench(I_C, m, omega, omega_dot, c_ddot),
                                 "w = newton_euler_wrench(...)")])


@equation("3.140", "Angular-velocity dyad", section="3.8", kind="definition",
          latex=r"\mathbf{W} \equiv \begin{bmatrix} \boldsymbol{\Omega} & \mathbf{O} \\ "
                r"\mathbf{O} & \mathbf{O} \end{bmatrix}")
def angular_velocity_dyad() -> Statement:
    """``W = diag(Omega, O)``, ``Omega = Qdot Q^T``. Book: Sec. 3.8, Eq. (3.140). 6x6."""
    return Statement([Rel(W, _blk([[Omega, O3], [O3, O3]]))], dynamics_model(),
                     defines=("W",), claims=[Rel(Omega, cpm(omega), "Omega = CPM(omega)")])


@equation("3.141", "The twist lies in the null space of W", section="3.8",
          latex=r"\mathbf{W}\mathbf{t} = \mathbf{0}")
def twist_in_null_space_of_W() -> Statement:
    """``W t = 0``. Book: Sec. 3.8, Eq. (3.141). 6x1."""
    return Statement([Rel(W * t, O6)], dynamics_model())


@equation("3.142", "Momentum screw", section="3.8", kind="definition",
          latex=r"\boldsymbol{\mu} \equiv \begin{bmatrix} \mathbf{I}_C \boldsymbol{\omega} \\ "
                r"m\dot{\mathbf{c}} \end{bmatrix} = \mathbf{M}\mathbf{t}")
def momentum_screw() -> Statement:
    """``mu = [I_C omega; m c_dot] = M t``; claims: the second member equals the first, and
    both are the points' ``[sum m_i r_i x pdot_i; sum m_i pdot_i]``.

    Book: Sec. 3.8, Eq. (3.142) (definition). 6x1.
    """
    B, _, _ = moving_body()
    first = _blk([[I_C * omega], [m * c_dot]])
    return Statement(
        [Rel(mu, first), Rel(mu, M * t)], dynamics_model(), defines=("mu",),
        claims=[Rel(first, M * t, "= M t"),
                Rel(M * t, _im(_momentum_screw_first_principles(B, lambda P: P.p_dot, B.c)),
                    "momenta of the points")])


@equation("3.143", "Rate of the momentum screw", section="3.8",
          latex=r"\dot{\boldsymbol{\mu}} = \mathbf{M}\dot{\mathbf{t}} + \mathbf{W}\boldsymbol{\mu}"
                r" = \mathbf{M}\dot{\mathbf{t}} + \mathbf{W}\mathbf{M}\mathbf{t}")
def momentum_screw_rate() -> Statement:
    """``mudot = M t_dot + W mu = M t_dot + W M t``, ``mudot`` the time derivative of
    ``M(t) t(t)``; claim ``Mdot = W M - M W`` (Ex. 3.17). Book: Sec. 3.8, Eq. (3.143). 6x1."""
    return Statement([Rel(mu_dot, M * t_dot + W * mu), Rel(mu_dot, M * t_dot + W * M * t)],
                     dynamics_model(), claims=[Rel(M_dot, W * M - M * W, "Mdot = W M - M W")])


@equation("3.144", "Kinetic energy (repeated)", section="3.8",
          latex=r"T = \frac{1}{2}m\|\dot{\mathbf{c}}\|^2 + \frac{1}{2}\boldsymbol{\omega}^T "
                r"\mathbf{I}_C \boldsymbol{\omega}")
def kinetic_energy_repeated() -> Statement:
    """``T = 1/2 m ||c_dot||^2 + 1/2 omega^T I_C omega``. Book: Sec. 3.8, Eq. (3.144). J."""
    return Statement([Rel(T, m * (c_dot.T * c_dot) / 2 + omega.T * I_C * omega / 2)],
                     dynamics_model())


@equation("3.145", "Kinetic energy as a quadratic form of the twist", section="3.8",
          latex=r"T = \frac{1}{2} \mathbf{t}^T \mathbf{M} \mathbf{t}")
def kinetic_energy_twist_form() -> Statement:
    """``T = 1/2 t^T M t`` (:func:`kinetic_energy`). Book: Sec. 3.8, Eq. (3.145). J."""
    return Statement([Rel(T, t.T * M * t / 2)], dynamics_model(),
                     claims=[Rel(T, kinetic_energy(I_C, m, omega, c_dot), "kinetic_energy")])


@equation("3.146", "Newton-Euler equations as the rate of the momentum screw", section="3.8",
          latex=r"\dot{\boldsymbol{\mu}} = \mathbf{w}")
def momentum_screw_balance() -> Statement:
    """``mudot = w``. Book: Sec. 3.8, Eq. (3.146). 6x1."""
    return Statement([Rel(mu_dot, w)], dynamics_model())


@equation("3.147", "Inertia dyad at a point A", section="3.8",
          latex=r"\mathbf{M}_A = \begin{bmatrix} \mathbf{I}_A & m(\mathbf{C} - \mathbf{A}) \\ "
                r"m(\mathbf{C} - \mathbf{A})^T & m\mathbf{1} \end{bmatrix}")
def inertia_dyad_at_point_form() -> Statement:
    """``M_A = [[I_A, m(C - A)], [m(C - A)^T, m 1]]``, ``M_A`` the kinetic-energy Hessian.

    Claims: ``M_A = inertia_dyad_at_point(I_C, m, c, a)``; ``M_A t_A`` is the momentum screw
    about A of the points; and the Gram form ``t_A^T M_A t_A = omega^T I_C omega +
    m ||v + omega x (c - a)||^2``: non-negative, and zero only for ``omega = 0`` (``I_C``
    positive definite) and then ``v = 0``, so ``M_A`` is positive definite whenever ``I_C``
    is (Exercise 3.20). Book: Sec. 3.8, Eq. (3.147). 6x6.
    """
    model = dyad_model()
    tA = block([[_TWIST_W], [_TWIST_V]])
    screw = _momentum_screw_first_principles(
        static_body(), lambda P: _TWIST_V + cpm(_TWIST_W) * (P.p - model[a]), model[a])
    vc = _TWIST_V + cpm(_TWIST_W) * (c - a)  # velocity of C
    quad = _TWIST_W.T * I_C * _TWIST_W + m * vc.T * vc
    return Statement(
        [Rel(M_A, _blk([[I_A, m * (C - A)], [m * (C - A).T, m * I3]]))], model,
        claims=[Rel(M_A, inertia_dyad_at_point(I_C, m, c, a), "inertia_dyad_at_point"),
                Rel(M_A * tA, _im(screw), "momentum screw about A"),
                Rel(tA.T * M_A * tA, quad, "Gram form")])


@equation("3.148", "Steiner's theorem in dyad form", section="3.8",
          latex=r"\mathbf{M}_A = \mathbf{M}_C + m\mathbf{P}\mathbf{P}^T",
          expected="does-not-hold", cause="erratum",
          evidence="M_A - M_C = m[[(A-C)(A-C)^T, C-A], [(C-A)^T, O]] has a zero diagonal "
                   "block but a non-zero off-diagonal one: indefinite, so no real P unless "
                   "a = c; M_A = diag(I_C, O) + m P P^T with P = [C - A; 1] holds")
def steiner_theorem_dyad_form() -> Statement:
    """``M_A = M_C + m P P^T`` with ``M_C = diag(I_C, m 1)`` (3.138): no real P exists.

    P is not given ("the reader is invited to find an expression for P"), so the printed
    statement is checked through what it implies. For any real P (6 x k) split into 3 x k
    blocks ``P_1``, ``P_2``, the lower-right block of ``P P^T`` is ``P_2 P_2^T``, whose trace
    is the sum of squares of ``P_2``; it must equal ``(M_A - M_C)_22 / m``, which is ``O``
    (member 1, holds), so ``P_2 = O`` and the off-diagonal block ``P_1 P_2^T`` is ``O``;
    but ``(M_A - M_C)_12 = m (C - A)`` (member 2) is not ``O`` unless ``a = c``. The claim
    makes the obstruction explicit: for ``x = [u; (A - C)^T u]`` (u free),
    ``x^T (M_A - M_C) x = -m ||u x (a - c)||^2 < 0``, while ``x^T m P P^T x >= 0``. The
    certificate holds the printed relation itself (``for_every``: P a fresh 6 x 6 array of
    free atoms), failing at one point for every real P by that x.

    Corrected (the decomposition Exercise 3.20 asks for): ``M_A = diag(I_C, O) + m P P^T``
    with ``P = [C - A; 1]`` (6 x 3), the same as ``m R R^T`` with the 6 x 6
    ``R = [[O, C - A], [O, 1]]`` (so Exercise 3.20's R exists), and the congruence
    ``M_A = U^T M_C U``, ``U = [[1, O], [A - C, 1]]`` (the twist transfer from A to C).
    ``M_A`` is positive definite by the congruence, not by an additive split with ``M_C``.

    The model is :func:`sec3_8.with_positive_masses` of the dyad model (``m_i = 1 + mu_i^2``),
    so the counterexample is a physical body: its point gives ``mu_i``, the masses are
    ``1 + mu_i^2 >= 1`` (e.g. ``mu = (-3/2, 1, 0, 0)``: ``m_i = (13/4, 2, 1, 1)``, ``m = 29/4``).

    Book: Sec. 3.8, Eq. (3.148). 6x6.
    """
    model = with_positive_masses(dyad_model())
    Av, Cv, Iv, z3 = model[A], model[C], model[I_C], sp.zeros(3, 3)
    u = vector("s38_u")
    # the witness x and the corrected decomposition's matrices, as symbols valued in the model
    x, P, R6, U, J = MS("x", 6), MS("P", 6, 3), MS("R", 6, 6), MS("U", 6, 6), MS("J", 6, 6)
    model.update({x: _im(block([[u], [(Av - Cv).T * u]])),
                  P: _im(block([[Cv - Av], [sp.eye(3)]])),
                  R6: _im(block([[z3, Cv - Av], [z3, sp.eye(3)]])),
                  U: _im(block([[sp.eye(3), z3], [Av - Cv, sp.eye(3)]])),
                  J: _im(block([[Iv, z3], [z3, z3]]))})
    D = M_A - M_C
    uxd = cpm(u) * (a - c)
    page_P = _im(6, 6, list(vector("s38_P", n=36)))  # the page's P: any real 6 x 6 (P P^T
    return Statement(  # then every positive semi-definite 6 x 6, so every 6 x k P's)
        [Rel(D[3:6, 3:6], O3, "lower-right block m P_2 P_2^T = O, so P_2 = O"),
         Rel(D[0:3, 3:6], O3, "upper-right block m P_1 P_2^T = O, since P_2 = O")],
        model,
        claims=[Rel(x.T * D * x, -m * uxd.T * uxd,
                    "x = [u; (A - C)^T u]: x^T (M_A - M_C) x = -m ||u x (a - c)||^2")],
        corrected=[Rel(M_A, J + m * P * P.T, "J = diag(I_C, O), P = [C - A; 1]"),
                   Rel(M_A, J + m * R6 * R6.T, "6x6 R = [[O, C - A], [O, 1]]"),
                   Rel(M_A, U.T * M_C * U, "U = [[1, O], [A - C, 1]]")],
        parametrisation=POINT_BODY_WORDS,
        for_every=(Rel(M_A, M_C + m * page_P * page_P.T, "printed, for every real P"), page_P,
                   x))
