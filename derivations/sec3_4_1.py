"""Sec. 3.4.1: The instant screw of a rigid-body motion, Eqs. (3.52)-(3.63).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.1.

Models: a generic smooth motion (:func:`derivations.sec3_4.instant_motion_model`:
``Q(t)`` a generic rotation, ``a(t)`` free, a body point ``p = a + Q r``; ``Omega = Qdot
Q^T`` and ``omega = vect(Omega)`` computed). Points of the instant screw axis (ISA) come
from its defining property (velocity parallel to ``omega``) and the point nearest the
origin from minimising the distance along the ISA (:func:`derivations.sec3_4.
isa_point_nearest`), never from the book's closed forms, which are checked against them.

``||omega||`` is a book symbol whose model is ``sqrt(omega . omega)``. The zero test
decides rational expressions only, so every checked relation is written so that the square
roots cancel structurally (``||omega||^2``, ``||omega|| e'``, ``e' . n'``).
Singular set of the whole subsection: ``omega = 0`` (instantaneous translation, no ISA).
Eqs. (3.64)-(3.70) (least squares for the ISA point): :mod:`derivations.sec3_4_1_isa_point`.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import Rel, Statement, cpm, equation, scalar

from .common import I3, MS, Mt, vec
from .sec3_4 import (
    INSTANT_MOTION_WORDS,
    cross,
    instant_motion_model,
    isa_point_nearest,
    isa_velocity,
)

Omega, omega, a, a_dot, p, p_dot = Mt.Omega, Mt.omega, Mt.a, Mt.a_dot, Mt.p, Mt.p_dot
norm_omega = sp.Symbol("norm_omega", positive=True)  # the book's ||omega||
v_0 = vec("v_0")  # minimum-magnitude velocity (vector), Theorem 3.4.2
v0 = sp.Symbol("v0", real=True)  # its signed magnitude (3.52)
pitch = sp.Symbol("p'", real=True)  # pitch of the instant screw, m/rad (3.53)
pitch_turn = sp.Symbol("p'_turn", real=True)  # the same in m/turn (3.53)
e_isa, n_isa = vec("e'"), vec("n'")  # direction and moment of the ISA (3.55)
plucker_isa = MS("p_L'", 6, 1)  # Pluecker array of the ISA (3.54)
adot_par, adot_perp = vec("adot_par"), vec("adot_perp")  # (3.56)
pdot_par, pdot_perp = vec("pdot_par"), vec("pdot_perp")  # (3.59)
r_isa = vec("r_isa")  # (3.62b)
p0_isa = vec("p'_0")  # ISA point nearest the origin (3.64)

_im = sp.ImmutableMatrix
_Z3 = sp.zeros(3, 1)


# --------------------------------------------------------------------------- kernels
def instant_screw_axis_point(omega, a, a_dot) -> sp.Matrix:
    """Point of the instant screw axis nearest to the origin.

    ``p0' = omega x (a_dot - omega x a) / ||omega||^2 = Omega (a_dot - Omega a) /
    ||omega||^2``.

    Book: Sec. 3.4.1, Eq. (3.70).

    Args:
        omega: angular velocity, 3 x 1, rad/s.
        a: position of a body point A, 3 x 1, m.
        a_dot: velocity of A, 3 x 1, m/s.

    Returns:
        ``p0'``, 3 x 1, m.

    Notes:
        Singular set: ``omega = 0`` (pure translation: the ISA is not defined).
    """
    w, a, a_dot = sp.Matrix(omega), sp.Matrix(a), sp.Matrix(a_dot)
    W = cpm(w)
    return W * (a_dot - W * a) / (w.T * w)[0]


def instant_screw_pitch(omega, a_dot):
    """Pitch of the instant screw: ``p' = a_dot . omega / ||omega||^2`` (any body point).

    Book: Sec. 3.4.1, Eq. (3.53) (m/rad; the m/turn variant is ``2 pi`` times this).

    Args:
        omega: angular velocity, 3 x 1, rad/s.
        a_dot: velocity of any body point, 3 x 1, m/s.

    Returns:
        ``p'``, scalar, m/rad.

    Notes:
        Singular set: ``omega = 0``.
    """
    w, a_dot = sp.Matrix(omega), sp.Matrix(a_dot)
    return (a_dot.T * w)[0] / (w.T * w)[0]


def instant_screw_plucker(omega, a, a_dot) -> sp.Matrix:
    """Pluecker array of the instant screw axis: ``[e'; p0' x e']``, ``e' = omega/||omega||``.

    Book: Sec. 3.4.1, Eqs. (3.54)-(3.55), with ``p0'`` of Eq. (3.70).

    Args:
        omega: angular velocity, 3 x 1, rad/s.
        a: position of a body point A, 3 x 1, m.
        a_dot: velocity of A, 3 x 1, m/s.

    Returns:
        6 x 1 ``[e'; n']`` (``e'`` dimensionless unit vector, ``n'`` in m); contains
        ``sqrt(omega . omega)``.

    Notes:
        Singular set: ``omega = 0`` (the book then takes ``e'`` along the common velocity).
    """
    w = sp.Matrix(omega)
    nw = sp.sqrt((w.T * w)[0])
    p0 = instant_screw_axis_point(w, a, a_dot)
    return sp.Matrix.vstack(w / nw, (cpm(p0) * w) / nw)


# --------------------------------------------------------------------------- models
@cache
def _model() -> dict:
    """Generic motion plus ``||omega||`` and the projector ``e e^T`` pieces."""
    m = dict(instant_motion_model())
    w = sp.Matrix(m[omega])
    m[norm_omega] = sp.sqrt((w.T * w)[0])
    return m


def _unit_omega(m) -> sp.Matrix:
    return sp.Matrix(m[omega]) / m[norm_omega]


@cache
def _isa_model() -> dict:
    """``p`` a generic point of the ISA: ``x1 + alpha omega`` (``x1`` first principles,
    ``alpha`` free); ``pdot`` its velocity from the motion."""
    m = dict(_model())
    w = sp.Matrix(m[omega])
    x = isa_point_nearest(_Z3, m) + scalar("s341_alpha") * w
    m.update({p: _im(x), p_dot: _im(isa_velocity(m))})
    return m


@cache
def _screw_model() -> dict:
    """``v_0``, ``v0``, ``p'``, ``e'``, ``n'``, ``p_L'``, ``p'_0`` and ``r``."""
    m = dict(_model())
    w, am, adm = (sp.Matrix(m[k]) for k in (omega, a, a_dot))
    Om = sp.Matrix(m[Omega])
    x0 = isa_point_nearest(_Z3, m)
    v = isa_velocity(m)  # Theorem 3.4.2: the common velocity of the ISA points
    x = x0 + scalar("s341_alpha") * w  # any point of the ISA
    e = _unit_omega(m)
    n = (cpm(x) * w) / m[norm_omega]  # x cross e'
    m.update({v_0: _im(v), v0: (v.T * w)[0] / m[norm_omega],
              pitch: instant_screw_pitch(w, adm),
              pitch_turn: 2 * sp.pi * instant_screw_pitch(w, adm),
              e_isa: _im(e), n_isa: _im(n), plucker_isa: _im(sp.Matrix.vstack(e, n)),
              p0_isa: _im(x0), r_isa: _im(am + Om * adm / (w.T * w)[0]),
              p: _im(x), p_dot: _im(v)})
    return m


def _projector_model(vel_sym, par, perp, base: dict) -> dict:
    """Components of a velocity along and normal to ``omega`` (Eqs. (2.6a), (2.6b))."""
    m = dict(base)
    e = _unit_omega(m)
    P = e * e.T
    v = sp.Matrix(m[vel_sym])
    m.update({par: _im(P * v), perp: _im((sp.eye(3) - P) * v)})
    return m


_W = "omega = 0 (instantaneous translation: no ISA)"


# --------------------------------------------------------------------------- Sec. 3.4.1
@equation("3.52", "Minimum velocity along omega, signed magnitude v0", section="3.4.1",
          singular=_W,
          latex=r"\mathbf{v}_0 = v_0 \frac{\boldsymbol{\omega}}{\|\boldsymbol{\omega}\|}")
def minimum_velocity_along_omega() -> Statement:
    """``v_0 = v0 omega / ||omega||``.

    Model: ``v_0`` is the velocity of the first-principles ISA point (common to all ISA
    points, Theorem 3.4.2); ``v0`` its signed magnitude for the direction ``omega``:
    ``v_0 . omega / ||omega||``. Also checked: ``v0^2 = ||v_0||^2`` (the magnitude is right,
    which with the printed relation says ``v_0`` is parallel to ``omega``).

    Book: Sec. 3.4.1, Eq. (3.52). 3-vector, m/s. Singular set: ``omega = 0``.
    """
    return Statement([Rel(v_0, v0 * omega / norm_omega)], _screw_model(),
                     claims=[Rel(v0**2, v_0.T * v_0, "|v0| = ||v_0||")])


@equation("3.53", "Pitch of the instant screw", section="3.4.1", kind="definition",
          singular=_W,
          latex=r"p' \equiv \frac{v_0}{\|\boldsymbol{\omega}\|} \equiv \frac{\dot{\mathbf{p}} "
                r"\cdot \boldsymbol{\omega}}{\|\boldsymbol{\omega}\|^2} \quad \text{or} \quad p' "
                r"\equiv \frac{2\pi v_0}{\|\boldsymbol{\omega}\|}")
def instant_screw_pitch_definition() -> Statement:
    """``p' = v0 / ||omega|| = pdot . omega / ||omega||^2`` (m/rad), ``2 pi v0 / ||omega||``
    (m/turn, a second quantity ``p'_turn``).

    Model of ``p'``: :func:`instant_screw_pitch` (``omega``, velocity of A). Checked: both
    members of the chain, for a generic body point P, and the m/turn variant.

    Book: Sec. 3.4.1, Eq. (3.53). Scalars. Singular set: ``omega = 0``.
    """
    m = dict(_screw_model())
    gen = instant_motion_model()  # a generic body point P, not on the ISA
    m.update({p: gen[p], p_dot: gen[p_dot]})
    return Statement(
        [Rel(pitch, v0 / norm_omega, "p' in m/rad"),
         Rel(pitch, (p_dot.T * omega) / norm_omega**2, "p' in m/rad"),
         Rel(pitch_turn, 2 * sp.pi * v0 / norm_omega, "p' in m/turn")], m,
        defines=("p'", "p'_turn"),
        claims=[Rel(pitch, v0 / norm_omega, "p' = v0/||omega||"),
                Rel(pitch, (p_dot.T * omega) / norm_omega**2, "p' = pdot.omega/||omega||^2"),
                Rel(pitch_turn, 2 * sp.pi * v0 / norm_omega, "m/turn variant")])


@equation("3.54", "Plücker array of the ISA", section="3.4.1", kind="definition",
          singular=_W,
          latex=r"\mathbf{p}_{\mathcal{L}'} \equiv \begin{bmatrix} \mathbf{e}' \\ \mathbf{n}' "
                r"\end{bmatrix}")
def isa_plucker_array() -> Statement:
    """``p_L' = [e'; n']`` (6 x 1; ``e'`` unit, ``n'`` in m).

    Checked: ``||omega|| p_L' = ||omega|| instant_screw_plucker(omega, a, adot)`` (the
    kernel, with ``n'`` taken at a generic ISA point).

    Book: Sec. 3.4.1, Eq. (3.54). Singular set: ``omega = 0``.
    """
    m = _screw_model()
    w, am, adm = (sp.Matrix(m[k]) for k in (omega, a, a_dot))
    return Statement([Rel(plucker_isa, sp.BlockMatrix([[e_isa], [n_isa]]))], m,
                     defines=("p_L'",),
                     claims=[Rel(norm_omega * plucker_isa,
                                 m[norm_omega] * instant_screw_plucker(w, am, adm),
                                 "||omega|| p_L' = ||omega|| [e'; p'_0 x e']")])


@equation("3.55", "Direction and moment of the ISA", section="3.4.1", kind="definition",
          singular=_W,
          latex=r"\mathbf{e}' \equiv \frac{\boldsymbol{\omega}}{\|\boldsymbol{\omega}\|}, \quad "
                r"\mathbf{n}' \equiv \mathbf{p} \times \mathbf{e}'")
def isa_direction_and_moment() -> Statement:
    """``e' = omega / ||omega||``, ``n' = p x e'`` with ``p`` any point of the ISA.

    Checked (square-free): ``e' . e' = 1``, ``e' . n' = 0`` (Pluecker constraint) and
    ``||omega|| n' = p'_0 x omega`` for a generic ISA point ``p`` (the moment does not
    depend on the point chosen on the ISA).

    Book: Sec. 3.4.1, Eq. (3.55). 3-vectors (``n'`` in m). Singular set: ``omega = 0``.
    """
    m = _screw_model()
    return Statement([Rel(e_isa, omega / norm_omega), Rel(n_isa, cross(p, e_isa))], m,
                     defines=("e'", "n'"),
                     claims=[Rel(e_isa.T * e_isa, 1, "unit e'"),
                             Rel(e_isa.T * n_isa, 0, "e' . n' = 0"),
                             Rel(norm_omega * n_isa, cross(p0_isa, omega), "point-free")])


@equation("3.56", "Axial and normal components of the velocity of A", section="3.4.1",
          singular=_W, latex=r"\dot{\mathbf{a}} \equiv \dot{\mathbf{a}}_{\parallel} + "
                             r"\dot{\mathbf{a}}_{\perp}")
def velocity_split() -> Statement:
    """``adot = adot_par + adot_perp``; model from Eqs. (2.6a/b) with ``e = omega/||omega||``.

    Also checked: ``omega x adot_par = 0`` and ``omega . adot_perp = 0``.

    Book: Sec. 3.4.1, Eq. (3.56). 3-vectors, m/s. Singular set: ``omega = 0``.
    """
    m = _projector_model(a_dot, adot_par, adot_perp, _model())
    return Statement([Rel(a_dot, adot_par + adot_perp)], m,
                     claims=[Rel(cross(omega, adot_par), _Z3, "parallel to omega"),
                             Rel(omega.T * adot_perp, 0, "normal to omega")])


def _adot_parallel_corrected():
    return omega * (a_dot.T * omega) / norm_omega**2


@equation("3.57", "Axial and normal components of adot", section="3.4.1", singular=_W,
          expected="does-not-hold", cause="unknown",
          evidence="the trailing factor omega is missing: the first member "
                   "a_dot . omega/||omega||^2 is a scalar for the vector adot_par",
          latex=r"\dot{\mathbf{a}}_{\parallel} \equiv \dot{\mathbf{a}} \cdot \frac{\boldsymbol"
                r"{\omega}}{\|\boldsymbol{\omega}\|^2} \equiv \frac{\boldsymbol{\omega} "
                r"\boldsymbol{\omega}^T}{\|\boldsymbol{\omega}\|^2} \dot{\mathbf{a}}, \quad "
                r"\dot{\mathbf{a}}_{\perp} \equiv \left( \mathbf{1} - \frac{\boldsymbol{\omega}"
                r" \boldsymbol{\omega}^T}{\|\boldsymbol{\omega}\|^2} \right) \dot{\mathbf{a}} "
                r"\equiv -\frac{1}{\|\boldsymbol{\omega}\|^2} \boldsymbol{\Omega}^2 "
                r"\dot{\mathbf{a}}")
def velocity_components() -> Statement:
    """``adot_par = adot . omega/||omega||^2 (sic) = omega omega^T adot/||omega||^2``,
    ``adot_perp = (1 - omega omega^T/||omega||^2) adot = -Omega^2 adot/||omega||^2``.

    Model: projections of Eqs. (2.6a/b) onto ``e = omega/||omega||``. The first member is a
    scalar, not a vector; corrected: ``(adot . omega/||omega||^2) omega``.

    Book: Sec. 3.4.1, Eq. (3.57). 3-vectors, m/s. Singular set: ``omega = 0``.
    """
    m = _projector_model(a_dot, adot_par, adot_perp, _model())
    s = norm_omega**2
    rest = [Rel(adot_par, omega * omega.T * a_dot / s, "omega omega^T adot/||omega||^2"),
            Rel(adot_perp, (I3 - omega * omega.T / s) * a_dot, "(1 - ...) adot"),
            Rel(adot_perp, -Omega**2 * a_dot / s, "-Omega^2 adot/||omega||^2")]
    return Statement([Rel(adot_par, (a_dot.T * omega) / s, "adot . omega/||omega||^2")] + rest,
                     m, corrected=[Rel(adot_par, _adot_parallel_corrected(),
                                       "(adot . omega/||omega||^2) omega")] + rest,
                     parametrisation=INSTANT_MOTION_WORDS)


@equation("3.58", "Square of the angular-velocity matrix", section="3.4.1",
          latex=r"\boldsymbol{\Omega}^2 \equiv \boldsymbol{\omega} \boldsymbol{\omega}^T - "
                r"\|\boldsymbol{\omega}\|^2 \mathbf{1}")
def omega_matrix_squared() -> Statement:
    """``Omega^2 = omega omega^T - ||omega||^2 1`` (Eq. (2.40) for ``Omega = Qdot Q^T``).

    Book: Sec. 3.4.1, Eq. (3.58). 3 x 3, rad^2/s^2. No singular set.
    """
    return Statement([Rel(Omega**2, omega * omega.T - norm_omega**2 * I3)], _model())


@equation("3.59", "Axial and normal components of the velocity of P", section="3.4.1",
          singular=_W, expected="does-not-hold", cause="unknown",
          evidence="the first term of the braced pdot_perp has the wrong sign: the minus "
                   "sign sits outside the braced group, which reads "
                   "+Omega^2 adot/||omega||^2 + Omega(p - a)",
          latex=r"\dot{\mathbf{p}} = \underbrace{\frac{\boldsymbol{\omega} \boldsymbol{\omega}"
                r"^T}{\|\boldsymbol{\omega}\|^2} \dot{\mathbf{a}}}_{\dot{\mathbf{p}}_{\parallel}}"
                r" - \underbrace{\frac{1}{\|\boldsymbol{\omega}\|^2} \boldsymbol{\Omega}^2 "
                r"\dot{\mathbf{a}} + \boldsymbol{\Omega}(\mathbf{p} - \mathbf{a})}_{\dot"
                r"{\mathbf{p}}_{\perp}}")
def velocity_axial_normal() -> Statement:
    """``pdot = omega omega^T adot/||omega||^2 - Omega^2 adot/||omega||^2 + Omega (p - a)``,
    with the underbraces ``pdot_par`` (first term) and ``pdot_perp`` (the rest).

    Model: a generic body point P; ``pdot_par``, ``pdot_perp`` the projections of ``pdot``
    (Eqs. (2.6a/b)). The whole equation holds; the ``pdot_perp`` brace, read literally,
    holds ``+Omega^2 adot/||omega||^2 + Omega (p - a)``: its first term has the wrong sign.

    Book: Sec. 3.4.1, Eq. (3.59). 3-vectors, m/s. Singular set: ``omega = 0``.
    """
    m = _projector_model(p_dot, pdot_par, pdot_perp, _model())
    s = norm_omega**2
    par = omega * omega.T * a_dot / s
    head = [Rel(p_dot, par - Omega**2 * a_dot / s + Omega * (p - a), "pdot"),
            Rel(pdot_par, par, "pdot_par brace")]
    return Statement(
        head + [Rel(pdot_perp, Omega**2 * a_dot / s + Omega * (p - a), "pdot_perp brace")], m,
        corrected=head + [Rel(pdot_perp, -Omega**2 * a_dot / s + Omega * (p - a),
                              "pdot_perp = -Omega^2 adot/||omega||^2 + Omega (p - a)")],
        parametrisation=INSTANT_MOTION_WORDS)
