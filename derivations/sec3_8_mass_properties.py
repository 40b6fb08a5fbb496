"""Sec. 3.8: mass properties of a rigid body, Eqs. (3.123)-(3.133b).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.8. The body
model (a finite set of point masses, rigidly moving) and the formula functions are in
:mod:`rigidsym.derivations.sec3_8`; the Newton-Euler equations in
:mod:`rigidsym.derivations.sec3_8_newton_euler`.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import Rel, Statement, cpm, equation, vector

from .common import I3
from .sec3_8 import (
    Dy,
    _im,
    _product,
    _sq,
    inertia_at_point,
    motion_model,
    moving_body,
    static_body,
    static_model,
)

m, T, q_O, c, c_dot, p, p_dot, r, R = (Dy.m, Dy.T, Dy.q_O, Dy.c, Dy.c_dot, Dy.p, Dy.p_dot,
                                       Dy.r, Dy.R)
I_C, I_A, a, A, C, omega = Dy.I_C, Dy.I_A, Dy.a, Dy.A, Dy.C, Dy.omega

# --------------------------------------------------------------------------- declarations
@equation("3.123", "Mass of a body", section="3.8", kind="definition",
          latex=r"m = \int_{\mathcal{B}} \rho d\mathcal{B}")
def body_mass() -> Statement:
    """``m = int_B rho dB`` (the point-mass body: ``sum_i m_i``).

    Book: Sec. 3.8, Eq. (3.123) (definition). Scalar, kg.
    """
    return Statement([Rel(m, static_body().integral(lambda P: sp.Integer(1)))],
                     static_model(), defines=("m",))


@equation("3.124", "Mass first moment about O", section="3.8", kind="definition",
          latex=r"\mathbf{q}_O \equiv \int_{\mathcal{B}} \rho \mathbf{p} d\mathcal{B}")
def mass_first_moment() -> Statement:
    """``q_O = int_B rho p dB``. Book: Sec. 3.8, Eq. (3.124) (definition). 3x1, kg m."""
    return Statement([Rel(q_O, static_body().integral(lambda P: P.p))], static_model(),
                     defines=("q_O",))


@equation("3.125", "Centre of mass", section="3.8", kind="definition",
          latex=r"\mathbf{c} \equiv \frac{\mathbf{q}_O}{m}", singular="m = 0")
def centre_of_mass() -> Statement:
    """``c = q_O / m``, with the mean-value statement ``int_B rho p dB = m c`` as a claim.

    Book: Sec. 3.8, Eq. (3.125) (definition). 3x1, m.
    """
    return Statement([Rel(c, q_O / m)], static_model(), defines=("c",),
                     claims=[Rel(static_body().integral(lambda P: P.p), m * c,
                                 "int rho p dB = m c")])


@equation("3.126", "Kinetic energy", section="3.8", kind="definition",
          latex=r"T \equiv \int_{\mathcal{B}} \frac{1}{2} \rho \|\dot{\mathbf{p}}\|^2 "
                r"d\mathcal{B}")
def kinetic_energy_definition() -> Statement:
    """``T = int_B 1/2 rho ||p_dot||^2 dB`` along a rigid motion.

    Book: Sec. 3.8, Eq. (3.126) (definition). Scalar, J.
    """
    B, _, _ = moving_body()
    return Statement([Rel(T, B.integral(lambda P: _sq(P.p_dot) / 2))], motion_model(),
                     defines=("T",))


@equation("3.127", "Velocity of a body point from the centre of mass", section="3.8",
          latex=r"\dot{\mathbf{p}} = \dot{\mathbf{c}} + \boldsymbol{\omega} \times \mathbf{r}, "
                r"\quad \mathbf{r} \equiv \mathbf{p} - \mathbf{c}")
def point_velocity_from_centre() -> Statement:
    """``p_dot = c_dot + omega x r``, ``r = p - c``, for a generic body point P.

    ``c`` is the computed centre of mass of the moving point masses, ``omega =
    vect(Qdot Q^T)``. Book: Sec. 3.8, Eq. (3.127). 3x1, m/s.
    """
    return Statement([Rel(p_dot, c_dot + cpm(omega) * r, "p_dot"),
                      Rel(r, p - c, "r (definition)")], motion_model())


@equation("3.128", "Velocity of a body point with R = CPM(r)", section="3.8",
          latex=r"\dot{\mathbf{p}} = \dot{\mathbf{c}} - \mathbf{R}\boldsymbol{\omega}")
def point_velocity_cpm_form() -> Statement:
    """``p_dot = c_dot - R omega``, ``R = CPM(r)``. Book: Sec. 3.8, Eq. (3.128). 3x1, m/s.

    The page prints one relation; ``R = CPM(r)`` it says in words before it, so that is a
    claim, not a printed member.
    """
    return Statement([Rel(p_dot, c_dot - R * omega)], motion_model(),
                     claims=[Rel(R, cpm(r), "R (definition)")])


@equation("3.129", "Kinetic energy as three integrals", section="3.8",
          latex=r"T = \frac{1}{2} \|\dot{\mathbf{c}}\|^2 \underbrace{\int_{\mathcal{B}} \rho "
                r"d\mathcal{B}}_m - \dot{\mathbf{c}}^T \left( \int_{\mathcal{B}} \rho \mathbf{R} "
                r"d\mathcal{B} \right) \boldsymbol{\omega} + \frac{1}{2} \boldsymbol{\omega}^T "
                r"\left( \int_{\mathcal{B}} \rho \underbrace{\mathbf{R}^T \mathbf{R}}"
                r"_{-\mathbf{R}^2} d\mathcal{B} \right) \boldsymbol{\omega}")
def kinetic_energy_three_integrals() -> Statement:
    """``T = 1/2 ||c_dot||^2 int rho - c_dot^T (int rho R) omega + 1/2 omega^T (int rho R^T R)
    omega``, with the underbraces ``int rho dB = m`` and ``R^T R = -R^2``.

    Book: Sec. 3.8, Eq. (3.129). Scalar, J.
    """
    B, _, _ = moving_body()
    mass = B.integral(lambda P: sp.Integer(1))
    int_R = _im(B.integral(lambda P: cpm(P.r)))
    int_RtR = _im(B.integral(lambda P: cpm(P.r).T * cpm(P.r)))
    rhs = (c_dot.T * c_dot) * mass / 2 - c_dot.T * int_R * omega \
        + omega.T * int_RtR * omega / 2
    return Statement([Rel(T, rhs, "T"), Rel(mass, m, "int rho dB = m"),
                      Rel(R.T * R, -_product(R, R), "R^T R = -R^2")], motion_model())


@equation("3.130", "Kinetic energy: translation plus rotation about C", section="3.8",
          latex=r"T \equiv \frac{1}{2} m \|\dot{\mathbf{c}}\|^2 + \frac{1}{2} "
                r"\boldsymbol{\omega}^T \underbrace{\left[ \int_{\mathcal{B}} \rho "
                r"(\|\mathbf{r}\|^2 \mathbf{1} - \mathbf{r}\mathbf{r}^T) d\mathcal{B} \right]}"
                r"_{\mathbf{I}_C} \boldsymbol{\omega}")
def kinetic_energy_centroidal() -> Statement:
    """``T = 1/2 m ||c_dot||^2 + 1/2 omega^T I_C omega``, ``I_C = int rho (||r||^2 1 - r r^T)``.

    Claims of the text, checked: ``int rho R dB = O`` (the middle term of (3.129) vanishes),
    the integrand ``||r||^2 1 - r r^T = R R^T``, and the
    Gram form ``x^T I_C x = sum_i m_i ||r_i x x||^2`` for a free ``x``: with positive masses
    a sum of squares, so ``I_C`` is positive semidefinite; it vanishes only if every ``r_i``
    is parallel to ``x``, i.e. for a body on a line through C (nullity 1, as the book says).

    Book: Sec. 3.8, Eq. (3.130). Scalar, J; ``I_C`` 3x3, kg m^2.
    """
    B, _, _ = moving_body()
    int_IC = _im(B.I_C)
    x = vector("s38_x")
    gram = B.integral(lambda P: _sq(cpm(P.r) * x))
    return Statement(
        [Rel(T, m * (c_dot.T * c_dot) / 2 + omega.T * int_IC * omega / 2, "T"),
         Rel(I_C, int_IC, "I_C (underbrace)")], motion_model(),
        claims=[Rel(_im(B.integral(lambda P: cpm(P.r))), sp.zeros(3, 3), "int rho R dB = O"),
                Rel(_sq(r) * I3 - r * r.T, R * R.T, "||r||^2 1 - r r^T = R R^T"),
                Rel(x.T * I_C * x, gram, "x^T I_C x = sum m_i ||r_i x x||^2 (Gram form)")])


@equation("3.131", "Moment of inertia about a point A", section="3.8", kind="definition",
          latex=r"\mathbf{I}_A \equiv \int_{\mathcal{B}} \rho [\|\mathbf{p} - \mathbf{a}\|^2 "
                r"\mathbf{1} - (\mathbf{p} - \mathbf{a})(\mathbf{p} - \mathbf{a})^T] d\mathcal{B}")
def inertia_about_point_definition() -> Statement:
    """``I_A = int rho (||p - a||^2 1 - (p - a)(p - a)^T) dB`` for a free point A.

    Book: Sec. 3.8, Eq. (3.131) (definition). 3x3, kg m^2.
    """
    model = static_model()
    av = model[a]
    rhs = static_body().integral(lambda P: _sq(P.p - av) * sp.eye(3)
                                 - (P.p - av) * (P.p - av).T)
    return Statement([Rel(I_A, _im(rhs))], model, defines=("I_A",))


@equation("3.132", "Position relative to A through the centre of mass", section="3.8",
          latex=r"\mathbf{p} - \mathbf{a} = \mathbf{r} - (\mathbf{a} - \mathbf{c})")
def position_relative_to_point() -> Statement:
    """``p - a = r - (a - c)`` for generic P, A. Book: Sec. 3.8, Eq. (3.132). 3x1, m."""
    return Statement([Rel(p - a, r - (a - c))], static_model())


@equation("3.133a", "Steiner's theorem", section="3.8",
          latex=r"\mathbf{I}_A = \mathbf{I}_C + m[\|\mathbf{a} - \mathbf{c}\|^2 \mathbf{1} - "
                r"(\mathbf{a} - \mathbf{c})(\mathbf{a} - \mathbf{c})^T]")
def steiner_theorem() -> Statement:
    """``I_A = I_C + m (||a - c||^2 1 - (a - c)(a - c)^T)`` (:func:`inertia_at_point`).

    ``I_A`` and ``I_C`` are the integrals (3.131), (3.130) over the point-mass body, A free.
    Book: Sec. 3.8, Eq. (3.133a). 3x3, kg m^2.
    """
    return Statement([Rel(I_A, inertia_at_point(I_C, m, c, a))], static_model())


@equation("3.133b", "Steiner's theorem with cross-product matrices", section="3.8",
          latex=r"\mathbf{I}_A = \mathbf{I}_C + m(\mathbf{A} - \mathbf{C})(\mathbf{A} - "
                r"\mathbf{C})^T")
def steiner_theorem_cpm_form() -> Statement:
    """``I_A = I_C + m (A - C)(A - C)^T``, ``A = CPM(a)``, ``C = CPM(c)``.

    The book does not define ``A``, ``C`` here; "in light of Eq. (2.39)" and its convention
    ``R = CPM(r)`` make them the cross-product matrices of ``a`` and ``c``. The step (2.39),
    ``(A - C)(A - C)^T = ||a - c||^2 1 - (a - c)(a - c)^T``, is checked as a claim.
    Book: Sec. 3.8, Eq. (3.133b). 3x3, kg m^2.
    """
    return Statement([Rel(I_A, I_C + m * (A - C) * (A - C).T)], static_model(),
                     claims=[Rel((A - C) * (A - C).T,
                                 _sq(a - c) * I3 - (a - c) * (a - c).T, "(2.39)")])
