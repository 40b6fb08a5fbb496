"""Sec. 3.4.2 (continued): screws and twists, Eqs. (3.71)-(3.75).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.2.

The screw array of a line with a pitch, the twist in ray coordinates, the twist of a pure
translation and the screw of infinite pitch, and the invariants as 4-arrays. The book
symbols and the motion model (:func:`derivations.sec3_4_2.rates_model`) are those of
:mod:`derivations.sec3_4_2`, which also holds the rate matrices (3.76)-(3.77).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import Rel, Statement, block, cpm, equation, eye3, trace, vect

from .common import MS
from .sec3_4_2 import E, P_cpm, Q, e, eta, lam, nu, omega, p, phi, rates_model, t, v

__all__: list[str] = []

_im = sp.ImmutableMatrix


# --------------------------------------------------------------------------- screws and twists
screw, s_inf, pitch = MS("s", 6), MS("s_inf", 6), sp.Symbol("pitch", real=True)
norm_v = sp.Symbol("norm_v", real=True)  # the book's ||v||
ZERO3 = sp.ZeroMatrix(3, 1)


@cache
def _static_model() -> dict:
    """A fixed line: unit ``e``, a point ``p`` on it, a pitch (free); ``P = CPM(p)``."""
    from rigidsym.declare import unit_vector, vector
    ev, pv = unit_vector("e"), vector("p")
    return {e: _im(ev), p: _im(pv), P_cpm: _im(cpm(pv)), E: _im(cpm(ev)),
            screw: _im(block([[ev], [pv.cross(ev) + pitch * ev]]))}


@cache
def _translation_model() -> dict:
    """A pure translation: ``Q`` constant, so ``Omega = Qdot Q^T = O`` and ``omega = 0``;
    ``v = sigma e`` with ``e`` unit and ``sigma = ||v|| >= 0`` (so ``norm_v -> sigma``)."""
    from rigidsym.declare import scalar, unit_vector
    ev, sigma = unit_vector("e"), scalar("sec342_sigma")
    om = vect(sp.zeros(3) * eye3())
    vv = sigma * ev
    return {e: _im(ev), v: _im(vv), norm_v: sigma, t: _im(block([[om], [vv]])),
            s_inf: _im(block([[sp.zeros(3, 1)], [ev]]))}


@equation("3.71", "Screw array of a line with a pitch", section="3.4.2", kind="definition",
          latex=r"\mathbf{s} \equiv \begin{bmatrix} \mathbf{e} \\ \mathbf{p} \times "
                r"\mathbf{e} + p\mathbf{e} \end{bmatrix}")
def screw_array() -> Statement:
    """``s = [e; p x e + pitch e]`` (6): Plücker array of the line plus the pitch.

    Book: Sec. 3.4.2, Eq. (3.71). ``p x e`` is transcribed ``P e`` with ``P = CPM(p)``;
    the book's scalar pitch ``p`` is ``pitch`` (m/rad).
    """
    return Statement([Rel(screw, sp.BlockMatrix([[e], [P_cpm * e + pitch * e]]))],
                     _static_model(), defines=("s",))


@equation("3.72", "Twist in ray coordinates", section="3.4.2", kind="definition",
          latex=r"\mathbf{t} \equiv \begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v} "
                r"\end{bmatrix}")
def twist_array() -> Statement:
    """``t = [omega; v]`` (6; rad/s, m/s), ``v`` the velocity of the reference point.

    Book: Sec. 3.4.2, Eq. (3.72).
    """
    return Statement([Rel(t, sp.BlockMatrix([[omega], [v]]))], rates_model(), defines=("t",))


@equation("3.73", "Twist of a pure translation", section="3.4.2",
          expected="definition",
          latex=r"\mathbf{t} \equiv \begin{bmatrix} \mathbf{0} \\ \mathbf{v} \end{bmatrix} = "
                r"\|\mathbf{v}\| \begin{bmatrix} \mathbf{0} \\ \mathbf{e} \end{bmatrix}")
def pure_translation_twist() -> Statement:
    """``t = [0; v] = ||v|| [0; e]`` for a pure translation along the unit vector ``e``.

    Book: Sec. 3.4.2, Eq. (3.73). The twist is computed from a motion with constant ``Q``.
    """
    return Statement([Rel(t, sp.BlockMatrix([[ZERO3], [v]]), "t = [0; v]"),
                      Rel(t, norm_v * sp.BlockMatrix([[ZERO3], [e]]), "t = ||v|| [0; e]")],
                     _translation_model())


@equation("3.74", "Screw of infinite pitch", section="3.4.2", kind="definition",
          latex=r"\mathbf{s}_\infty \equiv \begin{bmatrix} \mathbf{0} \\ \mathbf{e} "
                r"\end{bmatrix}")
def screw_infinite_pitch() -> Statement:
    """``s_inf = [0; e]`` (6); claim: the pure-translation twist is ``||v|| s_inf``.

    Book: Sec. 3.4.2, Eq. (3.74).
    """
    return Statement([Rel(s_inf, sp.BlockMatrix([[ZERO3], [e]]))], _translation_model(),
                     defines=("s_inf",), claims=[Rel(t, norm_v * s_inf)])


@equation("3.75", "Natural, linear and Euler-Rodrigues invariants as 4-arrays",
          section="3.4.2", kind="definition",
          latex=r"\boldsymbol{\nu} \equiv \begin{bmatrix} \mathbf{e} \\ \phi \end{bmatrix}, "
                r"\quad \boldsymbol{\lambda} \equiv \begin{bmatrix} (\sin \phi)\mathbf{e} \\ "
                r"\cos \phi \end{bmatrix}, \quad \boldsymbol{\eta} \equiv \begin{bmatrix} "
                r"[\sin(\phi/2)]\mathbf{e} \\ \cos(\phi/2) \end{bmatrix}")
def invariant_arrays() -> Statement:
    """``nu = [e; phi]``, ``lambda = [sin(phi) e; cos(phi)]``, ``eta = [sin(phi/2) e; cos(phi/2)]``.

    Book: Sec. 3.4.2, Eq. (3.75) (4-arrays, dimensionless / rad). Claims, from the rotation
    ``Q`` of (2.49): ``lambda = [vect(Q); (tr Q - 1)/2]``; ``eta`` rebuilds ``Q`` by the
    Euler-Rodrigues form; ``lambda`` and ``eta`` are unit 4-arrays.
    """
    from rigidsym.declare import rotation_from_euler_rodrigues
    m = rates_model()
    Qv, ev, ph = sp.Matrix(m[Q]), sp.Matrix(m[e]), m[phi]

    def one(x):
        return sp.Matrix([[x]])

    printed = [Rel(nu, sp.BlockMatrix([[e], [one(phi)]]), "nu"),
               Rel(lam, sp.BlockMatrix([[sp.sin(phi) * e], [one(sp.cos(phi))]]), "lambda"),
               Rel(eta, sp.BlockMatrix([[sp.sin(phi / 2) * e], [one(sp.cos(phi / 2))]]),
                   "eta")]
    claims = [Rel(lam, block([[vect(Qv)], [(trace(Qv) - 1) / 2]]), "lambda from Q"),
              Rel(Q, rotation_from_euler_rodrigues(sp.sin(ph / 2) * ev, sp.cos(ph / 2)),
                  "Q from eta"),
              Rel(lam.T * lam, sp.Identity(1), "|lambda| = 1"),
              Rel(eta.T * eta, sp.Identity(1), "|eta| = 1")]
    return Statement(printed, m, defines=("nu", "lambda", "eta"), claims=claims)

