"""Sec. 3.8: Dynamics of rigid bodies, Eqs. (3.123)-(3.133b): mass, centre of mass, kinetic
energy, moment of inertia and Steiner's theorem (the Newton-Euler part, (3.134)-(3.148), is
in :mod:`derivations.sec3_8_newton_euler`).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.8.

The body model (first principles of every declaration of Sec. 3.8). The book's body B of
density rho is replaced by ``N_POINTS = 4`` point masses ``m_1 ... m_4`` (free symbols) at
generic positions; an integral ``int_B rho f(p) dB`` becomes the sum ``sum_i m_i f(p_i)``
(:meth:`PointBody.integral`). In a motion the points move rigidly,
``p_i(t) = o(t) + Q(t) rho_i``, with ``Q(t) = rotation("Q", t)`` exactly orthogonal, ``o(t)``
free and ``rho_i`` constant body coordinates. These are written ``rho_i = m_4 sigma_i``
(i < 4), ``rho_4 = -sum_{i<4} m_i sigma_i`` with free ``sigma_i``: this reaches every
configuration of four points (when ``m_4 != 0``, take ``sigma_i = rho_i / m_4`` after moving
the origin ``o`` to the centre of mass) and keeps ``1/m`` out of the expressions, which the
zero test then decides fast. The centre of mass, ``I_C(t)``, ``omega``,
the momenta and the forces are all *computed* from the points (``c = sum m_i p_i / m``,
``omega = vect(Qdot Q^T)``, ``f = sum m_i pddot_i`` (expanded, a polynomial in the jets),
``n_C = sum m_i r_i x pddot_i``), so
``Idot_C = Omega I_C - I_C Omega`` comes out of the model, never assumed.

Why four point masses suffice. Every integrand of the section is a polynomial of degree at
most 2 in the position ``p`` (in a motion, in the body coordinates ``s``, since
``p = o + Q s``), so both sides of each statement depend on the body only through its mass
moments: ``m = int rho``, the first moment ``int rho p`` and the second moments
``int rho p p^T``, i.e. through the 4 x 4 moment matrix ``X = int rho [p; 1][p; 1]^T``,
symmetric positive semidefinite with ``X_44 = m > 0``. Conversely every such ``X`` is the
moment matrix of four point masses: write ``X = V V^T`` (V 4 x 4, e.g. the symmetric square
root), turn ``V`` by an orthogonal ``O`` taking its last row ``l^T`` (``|l|^2 = m``) to
``sqrt(m)/2 [1, 1, 1, 1]``, and read column k of ``V O`` as ``sqrt(m_k) [p_k; 1]``: here
``m_k = m/4`` and ``p_k`` = its first three entries divided by ``sqrt(m)/2``. Hence every
body, uniform or not, has the moments of some four-point body, and an identity that holds
for every four-point body holds for every body. The masses of this construction are all
positive (``m_k = m/4 > 0``), so positive point masses alone already reach every
positive-definite moment matrix ``X``. The checker decides the identities for symbolic
masses and positions (every real value, not only positive ones), which is more. Where a
statement fails, :func:`with_positive_masses` rewrites the masses as ``m_i = 1 + mu_i^2`` so
that the checker's exact counterexample is a physical body (all ``m_i >= 1``); it reaches
the open set ``m_i >= 1``, on which a rational identity holding means it holds everywhere,
so the verified members and corrections lose nothing.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

from rigidsym.primitives import as_vector, block, cpm, vect
from rigidsym.registry import Rel, Statement, equation
from rigidsym.symbols import TIME, rotation, scalar, vector

from .common import I3, mat, vec

__all__ = ["inertia_at_point", "inertia_dyad_at_point", "newton_euler_wrench",
           "kinetic_energy", "PointBody", "static_body", "moving_body", "Dy", "N_POINTS",
           "with_positive_masses"]

N_POINTS = 4
_im = sp.ImmutableMatrix


# --------------------------------------------------------------------------- formulas
def inertia_at_point(I_C, m, c, a) -> sp.Matrix:
    """Moment of inertia at a point A from the centroidal one (Steiner's theorem).

    ``I_A = I_C + m (||a - c||^2 1 - (a - c)(a - c)^T)``, equivalently
    ``I_C + m (A - C)(A - C)^T`` with ``A = CPM(a)``, ``C = CPM(c)``.

    Book: Sec. 3.8, Eqs. (3.133a), (3.133b).

    Args:
        I_C: 3x3 moment of inertia at the centre of mass C (kg m^2).
        m: mass (kg).
        c: 3x1 position of C (m).
        a: 3x1 position of A (m), same frame as ``c`` and ``I_C``.

    Returns:
        3x3 symmetric ``sympy.Matrix`` ``I_A`` (kg m^2). No singular set (polynomial).
    """
    d = as_vector(a, "a") - as_vector(c, "c")
    return sp.Matrix(I_C) + m * ((d.T * d)[0] * sp.eye(3) - d * d.T)


def inertia_dyad_at_point(I_C, m, c, a) -> sp.Matrix:
    """Inertia dyad at a point A: ``M_A = [[I_A, m(C - A)], [m(C - A)^T, m 1]]``.

    ``I_A`` from :func:`inertia_at_point`, ``A = CPM(a)``, ``C = CPM(c)``. It is the matrix
    of the kinetic energy ``T = 1/2 t_A^T M_A t_A`` in the twist at A, ``t_A = [omega; a_dot]``,
    and ``M_A = U^T M U`` with ``M = diag(I_C, m 1)`` and ``U = [[1, O], [A - C, 1]]``.

    Book: Sec. 3.8, Eq. (3.147) (corrected reading of (3.148) in :mod:`sec3_8_newton_euler`).

    Args:
        I_C: 3x3 centroidal moment of inertia (kg m^2).
        m: mass (kg).
        c: 3x1 centre of mass (m).
        a: 3x1 point A (m).

    Returns:
        6x6 symmetric ``sympy.Matrix`` (blocks in kg m^2, kg m, kg), twist order
        ``[omega; v]``. No singular set; positive definite when ``I_C`` is.
    """
    D = cpm(as_vector(c, "c") - as_vector(a, "a"))  # C - A
    return block([[inertia_at_point(I_C, m, c, a), m * D], [m * D.T, m * sp.eye(3)]])


def newton_euler_wrench(I_C, m, omega, omega_dot, c_ddot) -> sp.Matrix:
    """Wrench at the centre of mass that produces a given motion (Newton-Euler equations).

    ``w = [n_C; f] = [I_C omega_dot + omega x I_C omega; m c_ddot]``, i.e.
    ``M t_dot + W M t`` with ``M = diag(I_C, m 1)``, ``W = diag(Omega, O)``.

    Book: Sec. 3.8, Eqs. (3.134a), (3.134b), (3.139).

    Args:
        I_C: 3x3 centroidal moment of inertia (kg m^2), in the frame of the vectors.
        m: mass (kg).
        omega: 3x1 angular velocity (rad/s).
        omega_dot: 3x1 angular acceleration (rad/s^2).
        c_ddot: 3x1 acceleration of the centre of mass (m/s^2), inertial frame.

    Returns:
        6x1 ``sympy.Matrix`` ``[n_C; f]`` (N m; N), moment on top. No singular set.
    """
    I_C = sp.Matrix(I_C)
    om = as_vector(omega, "omega")
    n_C = I_C * as_vector(omega_dot, "omega_dot") + cpm(om) * (I_C * om)
    return block([[n_C], [m * as_vector(c_ddot, "c_ddot")]])


def kinetic_energy(I_C, m, omega, c_dot):
    """Kinetic energy of a rigid body: ``T = 1/2 t^T M t``, ``t = [omega; c_dot]``,
    ``M = diag(I_C, m 1)``; equals ``1/2 m ||c_dot||^2 + 1/2 omega^T I_C omega``.

    Book: Sec. 3.8, Eqs. (3.145), (3.144), (3.130).

    Args:
        I_C: 3x3 centroidal moment of inertia (kg m^2).
        m: mass (kg).
        omega: 3x1 angular velocity (rad/s).
        c_dot: 3x1 velocity of the centre of mass (m/s), inertial frame.

    Returns:
        scalar sympy expression (J). No singular set.
    """
    t = block([[as_vector(omega, "omega")], [as_vector(c_dot, "c_dot")]])
    M = block([[sp.Matrix(I_C), sp.zeros(3, 3)], [sp.zeros(3, 3), m * sp.eye(3)]])
    return (t.T * M * t)[0] / 2


# --------------------------------------------------------------------------- body model
@dataclass(frozen=True)
class Particle:
    """One point mass: mass, position ``p``, centroidal position ``r = p - c``, rates."""

    mass: sp.Expr
    p: sp.Matrix
    r: sp.Matrix
    p_dot: sp.Matrix | None = None
    p_ddot: sp.Matrix | None = None


@dataclass(frozen=True)
class PointBody:
    """A body of point masses (see the module docstring for why it stands for any body)."""

    particles: tuple[Particle, ...]
    m: sp.Expr
    c: sp.Matrix

    def integral(self, integrand):
        """``int_B rho f dB`` -> ``sum_i m_i f(particle_i)`` (``f`` gets a :class:`Particle`)."""
        terms = [P.mass * integrand(P) for P in self.particles]
        out = terms[0]
        for x in terms[1:]:
            out = out + x
        return out

    @property
    def I_C(self) -> sp.Matrix:
        """Centroidal moment of inertia, ``int rho (||r||^2 1 - r r^T)`` (3.130)."""
        return self.integral(lambda P: (P.r.T * P.r)[0] * sp.eye(3) - P.r * P.r.T)


def _masses():
    return [scalar(f"s38_m{i}") for i in range(1, N_POINTS + 1)]


def with_positive_masses(model: dict) -> dict:
    """The same model with every point mass written ``m_i = 1 + mu_i^2`` (free ``mu_i``).

    Positive at every real point, so a counterexample found in it is a physical body (the
    plain model lets the checker's witness search pick ``m_i <= 0``). Nothing is lost for the
    identities: the masses ``m_i >= 1`` it reaches form an open set, and a rational identity
    that holds on an open set holds for every value; dimensional homogeneity (a change of the
    unit of mass scales both members alike) also brings the ``m_k = m/4`` of the
    four-point construction above to ``m_k >= 1``.
    """
    sub = {mi: 1 + scalar(f"s38_mu{i}") ** 2 for i, mi in enumerate(_masses(), start=1)}
    return {k: v.xreplace(sub) for k, v in model.items()}


def _body_coordinates(ms) -> list[sp.Matrix]:
    """Body coordinates ``rho_i = m_4 sigma_i`` (i < 4), ``rho_4 = -sum_{i<4} m_i sigma_i``
    with free ``sigma_i``: every four-point configuration with ``m_4 != 0``, placed so that
    ``sum m_i rho_i = 0`` holds as a polynomial identity (no ``1/m`` in the expressions)."""
    sig = [vector(f"s38_s{i}") for i in range(1, N_POINTS)]
    rho = [ms[-1] * s for s in sig]
    rho.append(-sum((mi * s for mi, s in zip(ms, sig, strict=False)), sp.zeros(3, 1)))
    return rho


def _centre_of_mass(ms, ps) -> sp.Matrix:
    """``c = sum m_i p_i / m``, computed, then reduced by exact polynomial division."""
    q = sum((mi * p for mi, p in zip(ms, ps, strict=True)), sp.zeros(3, 1))
    return sp.Matrix([sp.cancel(sp.expand(x) / sum(ms)) for x in q])


@cache
def static_body() -> PointBody:
    """Four point masses at generic positions ``o + rho_i`` (one instant; no motion)."""
    ms = _masses()
    o = vector("s38_o")
    ps = [o + rho for rho in _body_coordinates(ms)]
    c = _centre_of_mass(ms, ps)
    return PointBody(tuple(Particle(mi, p, p - c) for mi, p in zip(ms, ps, strict=True)),
                     sum(ms), c)


@cache
def moving_body() -> tuple[PointBody, sp.Matrix, sp.Matrix]:
    """Four point masses moving rigidly, ``p_i(t) = o(t) + Q(t) rho_i``.

    Returns:
        the body (rates filled in), ``Q(t)``, and a generic body point ``o(t) + Q(t) s_P``.
    """
    t = TIME
    Q = rotation("Q", t)
    o = vector("s38_o", t)
    ms = _masses()
    ps = [o + Q * rho for rho in _body_coordinates(ms)]
    c = _centre_of_mass(ms, ps)
    parts = tuple(Particle(mi, p, p - c, p.diff(t), p.diff(t, 2))
                  for mi, p in zip(ms, ps, strict=True))
    return PointBody(parts, sum(ms), c), Q, o + Q * vector("s38_sP")


class Dy:
    """Book symbols of Sec. 3.8 (``m`` the mass; the momentum vector is ``momentum``)."""

    m = sp.Symbol("m", real=True)
    T = sp.Symbol("T", real=True)
    q_O, c, c_dot, c_ddot = vec("q_O"), vec("c"), vec("cdot"), vec("cddot")
    p, p_dot, r, a = vec("p"), vec("pdot"), vec("r"), vec("a")
    R, A, C = mat("R"), mat("A"), mat("C")
    I_C, I_A, I_C_dot = mat("I_C"), mat("I_A"), mat("Idot_C")
    omega, omega_dot, Omega = vec("omega"), vec("omegadot"), mat("Omega")
    f, n_C = vec("f"), vec("n_C")
    momentum, h_C, momentum_dot, h_C_dot = vec("momentum"), vec("h_C"), vec("momentumdot"), \
        vec("hdot_C")


@cache
def static_model() -> dict:
    """Model of the static symbols: mass, moments, ``c``, a generic body point ``p``, a
    point ``a`` (free), ``I_C``, ``I_A`` (definitions (3.123)-(3.131)), ``A``, ``C``."""
    B = static_body()
    p, a = vector("s38_pP"), vector("s38_a")
    I_A = B.integral(lambda P: ((P.p - a).T * (P.p - a))[0] * sp.eye(3)
                     - (P.p - a) * (P.p - a).T)
    return {Dy.m: B.m, Dy.q_O: _im(B.integral(lambda P: P.p)), Dy.c: _im(B.c),
            Dy.p: _im(p), Dy.r: _im(p - B.c), Dy.R: _im(cpm(p - B.c)), Dy.a: _im(a),
            Dy.I_C: _im(B.I_C), Dy.I_A: _im(I_A), Dy.A: _im(cpm(a)), Dy.C: _im(cpm(B.c))}


@cache
def motion_model() -> dict:
    """Model of the time-dependent symbols along the rigid motion of :func:`moving_body`."""
    t = TIME
    B, Q, p = moving_body()
    Om = Q.diff(t) * Q.T
    om = vect(Om)
    I_C = B.I_C
    r = p - B.c
    return {Dy.m: B.m, Dy.c: _im(B.c), Dy.c_dot: _im(B.c.diff(t)),
            Dy.c_ddot: _im(B.c.diff(t, 2)), Dy.p: _im(p), Dy.p_dot: _im(p.diff(t)),
            Dy.r: _im(r), Dy.R: _im(cpm(r)), Dy.Omega: _im(Om), Dy.omega: _im(om),
            Dy.omega_dot: _im(om.diff(t)), Dy.I_C: _im(I_C), Dy.I_C_dot: _im(I_C.diff(t)),
            Dy.T: B.integral(lambda P: (P.p_dot.T * P.p_dot)[0] / 2),
            Dy.f: _im(B.integral(lambda P: P.p_ddot).expand()),
            Dy.n_C: _im(B.integral(lambda P: cpm(P.r) * P.p_ddot))}


def _product(X, Y) -> sp.Matrix:
    """``X Y`` entrywise (no ``MatPow``: sympy's ``MatPow.doit`` runs a slow simplifier)."""
    return sp.Matrix(X) * sp.Matrix(Y)


def _sq(v):
    """``||v||^2`` of a 3x1 (explicit or symbolic) column, as a scalar."""
    return (v.T * v)[0, 0]


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
    """``p_dot = c_dot - R omega``, ``R = CPM(r)``. Book: Sec. 3.8, Eq. (3.128). 3x1, m/s."""
    return Statement([Rel(p_dot, c_dot - R * omega), Rel(R, cpm(r), "R (definition)")],
                     motion_model())


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
