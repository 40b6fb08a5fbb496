"""Sec. 3.4: General instantaneous motion of a rigid body, Eqs. (3.47)-(3.51), Theorems
3.4.1 and 3.4.2, Corollary 3.4.1.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.

First principles used here (nothing about the instant screw is assumed):

- a rigid motion maps the reference configuration to the current one by
  ``x0 -> Q(t) x0 + c(t)``, ``Q(t)`` a generic smooth rotation, ``c(t)`` a free smooth
  translation (:func:`rigid_motion_model`, for (3.47)-(3.51) and Theorem 3.4.1);
- for statements about one instant, an explicit generic trajectory ``Q(t) = R(q + t u)``,
  ``a(t) = a + t adot`` whose 1-jets cover every pose and twist
  (:func:`instant_motion_model`); ``Omega = Qdot Q^T`` and ``omega = vect(Omega)`` are
  computed by differentiation in both models;
- the velocity of the body point that is at ``x`` at time ``t`` is obtained by
  differentiating ``p(t) = a(t) + Q(t) r`` at constant body vector ``r = Q^T (x - a)``
  (:func:`body_velocity`);
- the instant screw axis (ISA) is the set of points whose velocity is parallel to
  ``omega``; its point nearest to a given point is found by minimising the distance along
  that line (:func:`isa_point_nearest`). Both are derived with sympy from those defining
  properties, never from the book's closed forms.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    TIME,
    Rel,
    Statement,
    cancel_matrix,
    cpm,
    equation,
    rotation_from_quaternion,
    scalar,
    vect,
    vector,
)

from .common import Mt, motion_model, vec

Q, Q_dot, Omega, omega = Mt.Q, Mt.Q_dot, Mt.Omega, Mt.omega
a, a_dot, p, p_dot = Mt.a, Mt.a_dot, Mt.p, Mt.p_dot
#: positions of A and P in the reference configuration C0
a_0, p_0 = vec("a_0"), vec("p_0")

_im = sp.ImmutableMatrix


def cross(u, v):
    """The book's ``u x v``, transcribed as ``CPM(u) v`` (Eq. (2.38)); any 3 x 1 inputs.

    Eager, unlike the lazy book operator :class:`derivations.common.Cross` (which prints as
    ``Cross(u, v)`` and waits for ``doit()``): it returns an explicit 3 x 1 matrix at once,
    and is used both in printed members and on model values inside derivations here and in
    :mod:`derivations.sec3_4_1`. Different semantics, so it is kept, not merged into Cross.
    """
    return cpm(u) * v


# --------------------------------------------------------------------------- models
@cache
def rigid_motion_model() -> dict:
    """First-principles values for Eqs. (3.47)-(3.51): the map ``x0 -> Q(t) x0 + c(t)``.

    ``Q(t)`` a generic rotation (rational quaternion jets), ``c(t)`` free, ``a0, p0`` free
    constants; ``a = Q a0 + c``, ``p = Q p0 + c``; ``Omega = Qdot Q^T``, ``omega =
    vect(Omega)`` computed (from :func:`derivations.common.motion_model`).
    """
    base = motion_model(invariants=False)
    Qm = base[Mt.Q]
    a0, p0 = vector("s34_a0"), vector("s34_p0")
    c = vector("s34_c", TIME)
    am, pm = Qm * a0 + c, Qm * p0 + c
    model = {k: base[k] for k in (Mt.Q, Mt.Q_dot, Mt.Omega, Mt.omega)}
    model.update({a_0: _im(a0), p_0: _im(p0), a: _im(am), a_dot: _im(am.diff(TIME)),
                  p: _im(pm), p_dot: _im(pm.diff(TIME))})
    return model


#: how :func:`instant_motion_model` writes its own variables (shown with a counterexample)
INSTANT_MOTION_WORDS = ("Q(t) is the rotation of the quaternion q + t u, so that Q(t)ᵀQ(t) = 𝟏 "
                        "holds exactly for every t; a(t) = a + t ȧ, and a body point is "
                        "p(t) = a(t) + Q(t) r; q, u, a, ȧ and r are free rationals")


@cache
def _instant_motion_model() -> dict:
    """A generic motion through an instant, as an explicit trajectory (exact derivatives).

    ``Q(t) = R(q + t u)``, the rational quaternion rotation (exactly proper orthogonal for
    every ``t``), ``a(t) = a + t adot``, a body point ``p(t) = a(t) + Q(t) r`` (``r``
    constant); ``q, u`` (4 each), ``a, adot, r`` are free parameters, so the 1-jets at
    ``t = 0`` cover every pose, angular velocity and velocity. ``Qdot``, ``Omega = Qdot Q^T``
    and ``omega = vect(Omega)`` are computed by differentiation at ``t = 0`` and brought to
    lowest terms (``sympy.cancel``: exact, and keeps the expressions small).
    """
    t = TIME
    q, u = vector("s34_q", n=4), vector("s34_u", n=4)
    Qt = rotation_from_quaternion(q + t * u)
    # cancel_matrix: sympy.cancel's result, reduced by FLINT first (3x faster here)
    Qm = cancel_matrix(Qt.subs(t, 0))
    Qd = cancel_matrix(Qt.diff(t).subs(t, 0))
    Om = cancel_matrix(Qd * Qm.T)
    om = cancel_matrix(vect(Om))
    am, adm, r = vector("s34_a"), vector("s34_adot"), vector("s34_r")
    return {Mt.Q: _im(Qm), Mt.Q_dot: _im(Qd), Mt.Omega: _im(Om), Mt.omega: _im(om),
            Mt.a: _im(am), Mt.a_dot: _im(adm), Mt.p: _im(am + Qm * r),
            Mt.p_dot: _im(adm + Qd * r)}


def instant_motion_model() -> dict:
    """A fresh copy of :func:`_instant_motion_model` (callers may update it)."""
    return dict(_instant_motion_model())


def body_velocity(x, model: dict) -> sp.Matrix:
    """Velocity of the body point that is at ``x`` now: ``a_dot + (Qdot Q^T)(x - a)``.

    Derived from the motion: the point is ``a(t) + Q(t) r`` with the constant body vector
    ``r = Q^T (x - a)`` (``Q^T Q = 1``), whose time derivative is ``a_dot + Qdot r``; the
    product ``Qdot Q^T`` is the model's computed (cancelled) ``Omega`` entry.

    Args:
        x: 3 x 1 position (metres), any sympy entries.
        model: a motion model holding ``Omega`` (= ``Qdot Q^T``), ``a``, ``adot``.
    """
    return sp.Matrix(model[Mt.a_dot] + model[Mt.Omega] * (sp.Matrix(x) - model[Mt.a]))


@cache
def _isa_free():
    """The ISA on free symbols ``w`` (omega), ``A``, ``Ad`` (a, adot), ``X`` (a point).

    The velocity field is ``v(x) = Ad + CPM(w)(x - A)``, i.e. (3.49) with ``Omega =
    CPM(omega)`` (``Omega`` is skew, Theorem 3.3.1, and ``omega = vect(Omega)``, (3.45)).

    1. the ISA: points ``x`` whose velocity is parallel to ``w``: ``w x v(x) = 0``; sympy's
       ``linsolve`` gives the line, of which the point with free parameter 0 is taken;
    2. the point ``x1 + alpha w`` nearest to ``X``: ``d/dalpha ||x1 + alpha w - X||^2 = 0``;
    3. the velocity of that point, ``v(x)``.

    Returns ``(w, A, Ad, X, nearest point, its velocity)``, each cancelled to one fraction
    (compact: the checker then substitutes the motion's ``omega``, ``a``, ``adot``).
    """
    w, A, Ad, X = (sp.Matrix(sp.symbols(f"{n}1:4", real=True)) for n in ("w", "A", "Ad", "X"))
    x = sp.Matrix(sp.symbols("x1:4", real=True))
    sol = next(iter(sp.linsolve(list(cpm(w) * (Ad + cpm(w) * (x - A))), list(x))))
    x1 = sp.Matrix(sol).subs({s: 0 for s in x})
    alpha = sp.Symbol("alpha", real=True)
    dist2 = ((x1 + alpha * w - X).T * (x1 + alpha * w - X))[0]
    # the stationarity condition is linear in alpha, c1 alpha + c0 = 0 (sympy's solve
    # simplified its root for most of the time of this model; the cancelled point is the same)
    c1, c0 = sp.Poly(sp.diff(dist2, alpha), alpha).all_coeffs()
    near = cancel_matrix(x1 - c0 / c1 * w)
    vel = cancel_matrix(Ad + cpm(w) * (near - A))
    return w, A, Ad, X, near, vel


def _on_motion(expr: sp.Matrix, x_ref, model: dict) -> sp.Matrix:
    w, A, Ad, X, _, _ = _isa_free()
    sub = dict(zip(list(w) + list(A) + list(Ad) + list(X),
                   list(model[Mt.omega]) + list(model[Mt.a]) + list(model[Mt.a_dot])
                   + list(sp.Matrix(x_ref)), strict=True))
    return expr.xreplace(sub)


def isa_point_nearest(x_ref, model: dict) -> sp.Matrix:
    """First-principles point of the ISA nearest to ``x_ref`` (3 x 1, metres).

    Singular set: ``omega = 0`` (no ISA). See :func:`_isa_free`.
    """
    return _on_motion(_isa_free()[4], x_ref, model)


def isa_velocity(model: dict) -> sp.Matrix:
    """First-principles velocity of the points of the ISA (3 x 1, m/s). See :func:`_isa_free`.
    """
    return _on_motion(_isa_free()[5], sp.zeros(3, 1), model)


def velocity_field(x, model: dict) -> sp.Matrix:
    """``adot + CPM(omega)(x - a)``: (3.49) with ``Omega = CPM(omega)`` (Theorem 3.3.1,
    (3.45)); smaller than :func:`body_velocity`, used to test points for the ISA."""
    return sp.Matrix(model[Mt.a_dot]) + cpm(model[Mt.omega]) * (sp.Matrix(x) - model[Mt.a])


# --------------------------------------------------------------------------- Sec. 3.4
@equation("3.47", "Position of a body point under a general motion", section="3.4",
          latex=r"\mathbf{p}(t) = \mathbf{a}(t) + \mathbf{Q}(t)(\mathbf{p}_0 - \mathbf{a}_0)")
def body_point_position() -> Statement:
    """``p(t) = a(t) + Q(t) (p0 - a0)``. Book: Sec. 3.4, Eq. (3.47). 3-vectors, metres."""
    return Statement([Rel(p, a + Q * (p_0 - a_0))], rigid_motion_model())


@equation("3.48", "Velocity of a body point from the reference configuration", section="3.4",
          latex=r"\dot{\mathbf{p}}(t) = \dot{\mathbf{a}}(t) + \dot{\mathbf{Q}}(t)(\mathbf{p}_0 "
                r"- \mathbf{a}_0)")
def body_point_velocity_reference() -> Statement:
    """``pdot = adot + Qdot (p0 - a0)``. Book: Sec. 3.4, Eq. (3.48). 3-vectors, m/s."""
    return Statement([Rel(p_dot, a_dot + Q_dot * (p_0 - a_0))], rigid_motion_model())


@equation("3.49", "Velocity of a body point, angular-velocity matrix form", section="3.4",
          latex=r"\dot{\mathbf{p}} = \dot{\mathbf{a}} + \boldsymbol{\Omega}(\mathbf{p} - "
                r"\mathbf{a})")
def body_point_velocity_matrix() -> Statement:
    """``pdot = adot + Omega (p - a)``. Book: Sec. 3.4, Eq. (3.49). 3-vectors, m/s."""
    return Statement([Rel(p_dot, a_dot + Omega * (p - a))], rigid_motion_model())


@equation("3.50", "Velocity of a body point, angular-velocity vector form", section="3.4",
          latex=r"\dot{\mathbf{p}} = \dot{\mathbf{a}} + \boldsymbol{\omega} \times (\mathbf{p} "
                r"- \mathbf{a})")
def body_point_velocity_vector() -> Statement:
    """``pdot = adot + omega x (p - a)``. Book: Sec. 3.4, Eq. (3.50). 3-vectors, m/s."""
    return Statement([Rel(p_dot, a_dot + cross(omega, p - a))], rigid_motion_model())


@equation("3.51", "Relative velocity is normal to the joining line", section="3.4",
          latex=r"(\dot{\mathbf{p}} - \dot{\mathbf{a}}) \cdot (\mathbf{p} - \mathbf{a}) = 0")
def relative_velocity_normal() -> Statement:
    """``(pdot - adot) . (p - a) = 0``. Book: Sec. 3.4, Eq. (3.51). Scalar, m^2/s."""
    return Statement([Rel((p_dot - a_dot).T * (p - a), 0)], rigid_motion_model())


@equation("thm3.4.1", "Relative velocity of two body points is normal to their line",
          section="3.4", kind="claim",
          latex=r"The relative velocity of two points of the same rigid body is perpendicular "
                r"to the line joining them")
def relative_velocity_theorem() -> Statement:
    """Theorem 3.4.1: for any two body points A, P: ``(pdot - adot)^T (p - a) = 0``.

    Both points are generic (``a0``, ``p0`` free). Book: Sec. 3.4, Theorem 3.4.1.
    """
    m = rigid_motion_model()
    return Statement([Rel((p_dot - a_dot).T * (p - a), 0, "relative velocity . AP")], m)


@equation("cor3.4.1", "Velocities of all body points have the same projection on omega",
          section="3.4", kind="claim",
          latex=r"The projections of the velocities of all the points of a rigid body onto "
                r"the angular-velocity vector are identical")
def velocity_projection_on_omega() -> Statement:
    """Corollary 3.4.1 and the unnumbered ``omega . pdot = omega . adot`` before it.

    Book: Sec. 3.4, Corollary 3.4.1. Generic body points A, P; scalar, rad m/s^2.
    """
    return Statement([Rel(omega.T * p_dot, omega.T * a_dot, "omega . pdot = omega . adot")],
                     rigid_motion_model())


@equation("thm3.4.2", "Points of a line share the minimum velocity, parallel to omega",
          section="3.4", kind="claim", singular="omega = 0 (pure translation: no ISA)",
          latex=r"a set of its points located on a line  $\mathcal{L}'$  undergoes the "
                r"identical minimum-magnitude velocity  $\mathbf{v}_0$  parallel to the "
                r"angular velocity")
def minimum_velocity_line() -> Statement:
    """Theorem 3.4.2, with the line ``L' = {x1 + alpha omega}`` as witness.

    ``x1`` is the first-principles ISA point nearest to the origin
    (:func:`isa_point_nearest`); ``v(x)`` is the velocity field of the motion
    (:func:`body_velocity`). Checked: (i) ``v(x1 + alpha omega) = v(x1)`` for every
    ``alpha`` (identical velocity on the line); (ii) ``omega x v(x1) = 0`` (parallel to
    ``omega``); (iii) for every point ``x``, ``||v(x)||^2 - ||v(x1)||^2 =
    ||omega x (x - x1)||^2 >= 0``, zero iff ``x`` lies on ``L'`` (minimum magnitude), ``x``
    the motion's arbitrary point A (``a``, ``a-dot`` free): the relations the theorem's
    words state (``certcheck.words``).

    Book: Sec. 3.4, Theorem 3.4.2. Singular set: ``omega = 0``.
    """
    m = instant_motion_model()
    om = sp.Matrix(m[Mt.omega])
    x1 = isa_point_nearest(sp.zeros(3, 1), m)
    alpha = scalar("s34_alpha")
    x = sp.Matrix(m[Mt.a])  # the arbitrary point: the page's A, of velocity a-dot (3.50)
    v1 = body_velocity(x1, m)
    vx = body_velocity(x, m)
    d = cross(om, x - x1)
    return Statement([
        Rel(body_velocity(x1 + alpha * om, m), v1, "same velocity along L'"),
        Rel(cross(om, v1), sp.zeros(3, 1), "v0 parallel to omega"),
        Rel((vx.T * vx)[0] - (v1.T * v1)[0], (d.T * d)[0], "||v(x)||^2 - ||v0||^2"),
    ], m)
