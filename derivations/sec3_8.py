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

from rigidsym.declare import TIME, as_vector, block, cpm, rotation, scalar, vect, vector

from .common import mat, vec

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


#: how :func:`with_positive_masses` of the point-mass body writes its own variables (shown
#: with a counterexample)
POINT_BODY_WORDS = ("The body is four point masses m_i = 1 + μ_i² ≥ 1 at o + ρ_i, with body "
                    "coordinates ρ_i = m₄ s_i (i < 4) and ρ₄ = -(m₁ s₁ + m₂ s₂ + m₃ s₃), so "
                    "that its centre of mass is c = o and every value of μ, o, s_i is a "
                    "physical body")


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
