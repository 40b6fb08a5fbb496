"""Book symbols and first-principles models shared by the section modules.

Book symbols are ``sympy.MatrixSymbol`` / ``Symbol`` objects named as in ``NOTATION.md``
so that a printed equation transcribes readably (``(Q - 1)^T (Q a - a')``). A *model* maps
each book symbol to its first-principles value, built from constrained atoms
(:mod:`rigidsym.algebra.symbols`): the checker substitutes it before deciding.

First principles used here: a rigid-body displacement is the map ``x -> Q x + c`` with
``Q`` proper orthogonal (here given by its natural invariants, Eq. (2.49)) and ``c`` a
free translation; nothing else about screws, Plücker lines or pitches is assumed.

The book operators (``Cross``, ``Det``, ``Blocks``, ``vec``, ``mat``, ...) come from
:mod:`rigidsym.declare` and are re-exported here for the section modules.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    I3,
    MS,
    O3,
    TIME,
    Blocks,
    Cross,
    Det,
    angle,
    cpm,
    mat,
    rotation,
    rotation_from_natural_invariants,
    unit_vector,
    vec,
    vect,
    vector,
)

__all__ = ["MS", "I3", "O3", "vec", "mat", "Cross", "Det", "Blocks", "displacement_model", "Bk",
           "Mt", "motion_model"]

class Bk:
    """The book's symbols for a rigid-body displacement (Sec. 3.2)."""

    Q = mat("Q")
    E = mat("E")
    e = vec("e")
    phi = angle("phi")
    a = vec("a")
    a_prime = vec("a_prime")
    p = vec("p")
    p_prime = vec("p_prime")
    d_A = vec("d_A")
    d_P = vec("d_P")


def displacement_model() -> dict:
    """First-principles values of the displacement symbols (a fresh copy of a cached dict)."""
    return dict(_displacement_model())


@cache
def _displacement_model() -> dict:
    """First-principles values of the displacement symbols.

    ``Q`` from its natural invariants (2.49) with a constrained unit ``e`` and angle ``phi``;
    body points ``a``, ``p`` free; the displaced points from ``x' = Q x + c`` (``c`` free).
    ``d_A``, ``d_P`` are the displacements ``x' - x`` (definition (3.3)).
    """
    e = unit_vector("e")
    phi = Bk.phi
    Q = rotation_from_natural_invariants(e, phi)
    a, p, c = vector("a"), vector("p"), vector("c")
    a1, p1 = Q * a + c, Q * p + c
    im = sp.ImmutableMatrix
    return {Bk.Q: im(Q), Bk.E: im(cpm(e)), Bk.e: im(e), Bk.a: im(a), Bk.p: im(p),
            Bk.a_prime: im(a1), Bk.p_prime: im(p1), Bk.d_A: im(a1 - a), Bk.d_P: im(p1 - p)}


class Mt:
    """The book's symbols for a motion in time (Secs. 3.3-3.5): ``Q(t)``, its rates, points."""

    Q = mat("Q")
    Q_dot = mat("Qdot")
    Q_ddot = mat("Qddot")
    E = mat("E")
    e = vec("e")
    e_dot = vec("edot")
    phi = sp.Symbol("phi", real=True)
    phi_dot = sp.Symbol("phidot", real=True)
    Omega = mat("Omega")
    Omega_dot = mat("Omegadot")
    omega = vec("omega")
    omega_dot = vec("omegadot")
    a = vec("a")
    a_dot = vec("adot")
    a_ddot = vec("addot")
    p = vec("p")
    p_dot = vec("pdot")
    p_ddot = vec("pddot")


def motion_model(invariants: bool = True) -> dict:
    """First-principles values for a generic smooth rigid motion (see :func:`_motion_model`).

    Returns a fresh copy of a cached dict: the differentiation is done once per process.
    """
    return dict(_motion_model(invariants))


@cache
def _motion_model(invariants: bool) -> dict:
    """First-principles values for a generic smooth rigid motion.

    With ``invariants=False``, ``Q(t)`` is a generic rotation (rational quaternion jets):
    much smaller expressions, for statements that do not mention ``e`` or ``phi``; the
    ``e``, ``E``, ``phi`` entries are then absent from the model.

    ``e(t)`` a unit vector and ``phi(t)`` an angle (their jets are free, the constraint
    ``e.e = 1`` holds along the motion), ``Q(t)`` from (2.49), a reference point ``a(t)``
    free, and a body point moving rigidly: ``p(t) = a(t) + Q(t) (p0 - a0)`` with ``p0, a0``
    free constants, i.e. ``p(t) = a(t) + Q(t) r`` for a constant body vector ``r``.
    ``Omega = Q_dot Q^T`` and ``omega = vect(Omega)`` are *computed* from the motion.
    """
    t = TIME
    if invariants:
        e = unit_vector("e", t)
        phi = angle("phi", t)
        Q = rotation_from_natural_invariants(e, phi)
    else:
        Q = rotation("Q", t)
    Qd = Q.diff(t)
    Qdd = Qd.diff(t)
    Om = Qd * Q.T
    om = vect(Om)
    a = vector("a", t)
    r = vector("r")  # constant body-fixed vector p0 - a0, seen in the reference pose
    p = a + Q * r
    im = sp.ImmutableMatrix
    model = {Mt.Q: im(Q), Mt.Q_dot: im(Qd), Mt.Q_ddot: im(Qdd),
            Mt.Omega: im(Om), Mt.Omega_dot: im(Om.diff(t)), Mt.omega: im(om),
            Mt.omega_dot: im(om.diff(t)), Mt.a: im(a), Mt.a_dot: im(a.diff(t)),
            Mt.a_ddot: im(a.diff(t, 2)), Mt.p: im(p), Mt.p_dot: im(p.diff(t)),
            Mt.p_ddot: im(p.diff(t, 2))}
    if invariants:
        model.update({Mt.E: im(cpm(e)), Mt.e: im(e), Mt.e_dot: im(e.diff(t)), Mt.phi: phi,
                      Mt.phi_dot: phi.diff(t)})
    return model
