"""Sec. 3.4.1 (continued): the points of the ISA, Eqs. (3.60)-(3.63), and the ISA point
nearest the origin by least squares, Eqs. (3.64)-(3.70).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.1.

Split from :mod:`rigidsym.derivations.sec3_4_1` (same models, symbols and singular set): ``p'_0``
is the first-principles ISA point nearest the origin (minimising the distance along the
ISA, :func:`rigidsym.derivations.sec3_4.isa_point_nearest`); the overdetermined system ``A p'_0 =
b`` of (3.65)-(3.66), its normal equations and the closed form (3.70) are checked against
it. The kernel :func:`rigidsym.derivations.sec3_4_1.instant_screw_axis_point` stays in
:mod:`rigidsym.derivations.sec3_4_1` (it is also used there by ``instant_screw_plucker``).
Singular set: ``omega = 0`` (instantaneous translation, no ISA).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import Rel, Statement, equation

from .common import I3, MS, Mt
from .sec3_4 import cross, isa_point_nearest, velocity_field
from .sec3_4_1 import (
    _W,
    _Z3,
    _isa_model,
    _screw_model,
    instant_screw_axis_point,
    norm_omega,
    p0_isa,
    r_isa,
)

Omega, omega, a, a_dot, p, p_dot = Mt.Omega, Mt.omega, Mt.a, Mt.a_dot, Mt.p, Mt.p_dot
A_isa, b_isa = MS("A_isa", 4, 3), MS("b_isa", 4, 1)  # (3.66)

_im = sp.ImmutableMatrix


@equation("3.60", "Points with vanishing normal velocity", section="3.4.1", singular=_W,
          latex=r"\boldsymbol{\Omega}(\mathbf{p} - \mathbf{a}) - \frac{1}{\|\boldsymbol{\omega}"
                r"\|^2} \boldsymbol{\Omega}^2 \dot{\mathbf{a}} = \mathbf{0}")
def normal_velocity_vanishes() -> Statement:
    """``Omega (p - a) - Omega^2 adot / ||omega||^2 = 0`` for ``p`` on the ISA.

    Model: ``p`` a generic point of the first-principles ISA. Book: Sec. 3.4.1, Eq. (3.60).
    3-vector, m/s. Singular set: ``omega = 0``.
    """
    return Statement([Rel(Omega * (p - a) - Omega**2 * a_dot / norm_omega**2, _Z3)],
                     _isa_model())


@equation("3.61", "ISA condition, linear in p", section="3.4.1", singular=_W,
          latex=r"\boldsymbol{\Omega} \mathbf{p} = \boldsymbol{\Omega} \left( \mathbf{a} + "
                r"\frac{1}{\|\boldsymbol{\omega}\|^2} \boldsymbol{\Omega} \dot{\mathbf{a}} "
                r"\right)")
def isa_condition_linear() -> Statement:
    """``Omega p = Omega (a + Omega adot / ||omega||^2)`` for ``p`` on the ISA.

    Book: Sec. 3.4.1, Eq. (3.61). 3-vector, m/s. Singular set: ``omega = 0``.
    """
    return Statement([Rel(Omega * p, Omega * (a + Omega * a_dot / norm_omega**2))],
                     _isa_model())


@equation("3.62a", "ISA condition about r", section="3.4.1", singular=_W,
          latex=r"\boldsymbol{\Omega}(\mathbf{p} - \mathbf{r}) = \mathbf{0}")
def isa_condition_about_r() -> Statement:
    """``Omega (p - r) = 0`` for ``p`` on the ISA, ``r`` of Eq. (3.62b).

    Book: Sec. 3.4.1, Eq. (3.62a). 3-vector, m/s. Singular set: ``omega = 0``.
    """
    m = dict(_isa_model())
    m[r_isa] = _screw_model()[r_isa]
    return Statement([Rel(Omega * (p - r_isa), _Z3)], m)


@equation("3.62b", "A point r of the ISA", section="3.4.1", kind="definition", singular=_W,
          latex=r"\mathbf{r} \equiv \mathbf{a} + \frac{1}{\|\boldsymbol{\omega}\|^2} "
                r"\boldsymbol{\Omega} \dot{\mathbf{a}}")
def isa_point_r() -> Statement:
    """``r = a + Omega adot / ||omega||^2``. Checked: ``omega x v(r) = 0`` (``r`` lies on
    the ISA: its velocity, from the motion, is parallel to ``omega``).

    Book: Sec. 3.4.1, Eq. (3.62b). 3-vector, m. Singular set: ``omega = 0``.
    """
    m = _screw_model()
    w = sp.Matrix(m[omega])
    return Statement([Rel(r_isa, a + Omega * a_dot / norm_omega**2)], m, defines=("r_isa",),
                     claims=[Rel(cross(w, velocity_field(m[r_isa], m)), _Z3, "r on the ISA")])


@equation("3.63", "The ISA point r as a solution", section="3.4.1", singular=_W,
          latex=r"\mathbf{p} = \mathbf{r} = \mathbf{a} + \frac{1}{\|\boldsymbol{\omega}\|^2} "
                r"\boldsymbol{\Omega} \dot{\mathbf{a}}")
def isa_point_solution() -> Statement:
    """``p = r = a + Omega adot / ||omega||^2``.

    Model: ``p`` the first-principles ISA point nearest to A (the foot of the perpendicular
    from A: the solution the book picks). Also checked: the printed point lies on the ISA.

    Book: Sec. 3.4.1, Eq. (3.63). 3-vector, m. Singular set: ``omega = 0``.
    """
    m = dict(_screw_model())
    x = isa_point_nearest(m[a], m)
    m.update({p: _im(x), p_dot: _im(velocity_field(x, m))})
    expr = a + Omega * a_dot / norm_omega**2
    w = sp.Matrix(m[omega])
    return Statement([Rel(p, r_isa), Rel(p, expr)], m,
                     claims=[Rel(cross(w, velocity_field(m[r_isa], m)), _Z3, "on the ISA")])


# --------------------------------------------------------------------------- models
def _ab_model() -> dict:
    """``A``, ``b`` of (3.66) by their definitions, ``p'_0`` from first principles."""
    m = dict(_screw_model())
    w, am, adm, Om = (sp.Matrix(m[k]) for k in (omega, a, a_dot, Omega))
    m[A_isa] = _im(sp.Matrix.vstack(Om, w.T))
    m[b_isa] = _im(sp.Matrix.vstack(Om * am + Om**2 * adm / (w.T * w)[0], sp.zeros(1, 1)))
    return m


# --------------------------------------------------------------------------- Sec. 3.4.1
@equation("3.64", "The ISA point nearest the origin is normal to omega", section="3.4.1",
          singular=_W, latex=r"\boldsymbol{\omega}^T \mathbf{p}'_0 = 0")
def isa_nearest_point_normal() -> Statement:
    """``omega^T p'_0 = 0``; ``p'_0`` by minimising the distance to the origin along the ISA.

    Book: Sec. 3.4.1, Eq. (3.64). Scalar. Singular set: ``omega = 0``.
    """
    return Statement([Rel(omega.T * p0_isa, 0)], _screw_model())


@equation("3.65", "Overdetermined system for p'_0", section="3.4.1", singular=_W,
          latex=r"\mathbf{A} \mathbf{p}'_0 = \mathbf{b}")
def isa_system() -> Statement:
    """``A p'_0 = b`` with ``A``, ``b`` of (3.66), ``p'_0`` first principles.

    Book: Sec. 3.4.1, Eq. (3.65). 4-vector. Singular set: ``omega = 0``.
    """
    return Statement([Rel(A_isa * p0_isa, b_isa)], _ab_model())


@equation("3.66", "The 4 x 3 system of the ISA", section="3.4.1", kind="definition",
          singular=_W,
          latex=r"\mathbf{A} \equiv \begin{bmatrix} \boldsymbol{\Omega} \\ \boldsymbol{\omega}"
                r"^T \end{bmatrix}, \quad \mathbf{b} \equiv \begin{bmatrix} \boldsymbol{\Omega} "
                r"\mathbf{a} + (1/\|\boldsymbol{\omega}\|^2) \boldsymbol{\Omega}^2 \dot{\mathbf"
                r"{a}} \\ 0 \end{bmatrix}")
def isa_system_matrices() -> Statement:
    """``A = [Omega; omega^T]`` (4 x 3), ``b = [Omega a + Omega^2 adot/||omega||^2; 0]``
    (4 x 1). Their properties are checked in (3.65), (3.67)-(3.69).

    Book: Sec. 3.4.1, Eq. (3.66). Singular set: ``omega = 0``.
    """
    b_top = Omega * a + Omega**2 * a_dot / norm_omega**2
    return Statement([Rel(A_isa, sp.BlockMatrix([[Omega], [omega.T]])),
                      Rel(b_isa, sp.BlockMatrix([[b_top], [sp.ZeroMatrix(1, 1)]]))],
                     _ab_model(), defines=("A_isa", "b_isa"))


@equation("3.67", "Normal equations for p'_0", section="3.4.1", singular=_W,
          latex=r"\mathbf{A}^T \mathbf{A} \mathbf{p}'_0 = \mathbf{A}^T \mathbf{b}")
def isa_normal_equations() -> Statement:
    """``A^T A p'_0 = A^T b``. Book: Sec. 3.4.1, Eq. (3.67). 3-vector. Singular: ``omega = 0``.
    """
    return Statement([Rel(A_isa.T * A_isa * p0_isa, A_isa.T * b_isa)], _ab_model())


@equation("3.68", "A^T A in terms of Omega", section="3.4.1",
          latex=r"\mathbf{A}^T \mathbf{A} = \boldsymbol{\Omega}^T \boldsymbol{\Omega} + "
                r"\boldsymbol{\omega} \boldsymbol{\omega}^T = -\boldsymbol{\Omega}^2 + "
                r"\boldsymbol{\omega} \boldsymbol{\omega}^T")
def isa_gram_matrix() -> Statement:
    """``A^T A = Omega^T Omega + omega omega^T = -Omega^2 + omega omega^T``.

    Book: Sec. 3.4.1, Eq. (3.68). 3 x 3, rad^2/s^2.
    """
    return Statement([Rel(A_isa.T * A_isa, Omega.T * Omega + omega * omega.T),
                      Rel(A_isa.T * A_isa, -Omega**2 + omega * omega.T)], _ab_model())


@equation("3.69", "A^T A and A^T b reduced", section="3.4.1", singular=_W,
          latex=r"\mathbf{A}^T \mathbf{A} = \|\boldsymbol{\omega}\|^2 \mathbf{1}, \quad "
                r"\mathbf{A}^T \mathbf{b} = \boldsymbol{\Omega} (\dot{\mathbf{a}} - "
                r"\boldsymbol{\Omega} \mathbf{a})")
def isa_gram_reduced() -> Statement:
    """``A^T A = ||omega||^2 1``, ``A^T b = Omega (adot - Omega a)``.

    Book: Sec. 3.4.1, Eq. (3.69). Singular set (of ``b``): ``omega = 0``.
    """
    return Statement([Rel(A_isa.T * A_isa, norm_omega**2 * I3),
                      Rel(A_isa.T * b_isa, Omega * (a_dot - Omega * a))], _ab_model())


@equation("3.70", "ISA point nearest the origin", section="3.4.1", singular=_W,
          latex=r"\mathbf{p}'_0 = \frac{\boldsymbol{\Omega} (\dot{\mathbf{a}} - \boldsymbol"
                r"{\Omega} \mathbf{a})}{\|\boldsymbol{\omega}\|^2} \equiv \frac{\boldsymbol"
                r"{\omega} \times (\dot{\mathbf{a}} - \boldsymbol{\omega} \times \mathbf{a})}"
                r"{\|\boldsymbol{\omega}\|^2}")
def isa_nearest_point() -> Statement:
    """``p'_0 = Omega (adot - Omega a)/||omega||^2 = omega x (adot - omega x a)/||omega||^2``.

    Model: ``p'_0`` by first principles (ISA from ``omega x v(x) = 0``, nearest point by
    minimisation). Also checked on the kernel :func:`instant_screw_axis_point`: it equals
    ``p'_0``, its velocity is parallel to ``omega`` and it is normal to ``omega``.

    Book: Sec. 3.4.1, Eq. (3.70). 3-vector, m. Singular set: ``omega = 0``.
    """
    m = _screw_model()
    w, am, adm = (sp.Matrix(m[k]) for k in (omega, a, a_dot))
    k = instant_screw_axis_point(w, am, adm)
    return Statement(
        [Rel(p0_isa, Omega * (a_dot - Omega * a) / norm_omega**2),
         Rel(p0_isa, cross(omega, a_dot - cross(omega, a)) / norm_omega**2)], m,
        derived=k,
        claims=[Rel(p0_isa, k, "kernel instant_screw_axis_point"),
                Rel(cross(w, velocity_field(k, m)), _Z3, "kernel point on the ISA"),
                Rel(w.T * k, sp.zeros(1, 1), "kernel point normal to omega")])
