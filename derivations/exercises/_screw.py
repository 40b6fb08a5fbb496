"""Shared: screw of a finite displacement x -> Q x + c, via the chapter's Eq. (3.18)."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import is_zero, values_only
from rigidsym.declare import trace, vect

from ..sec3_2_1 import screw_axis_point


def _radsimp(v):
    """``sympy.radsimp(v)``; ``v`` itself in a replay for its values only (floats)."""
    return v if values_only() else sp.radsimp(v)


def _expanded(v):
    """``v`` expanded with radicals simplified; ``v`` itself in a replay for its values only."""
    return v if values_only() else sp.radsimp(sp.expand(v))


def angle_axis(Q):
    """``(phi, e)`` of a rotation, ``0 < phi <= pi``; ``None`` for ``Q = 1``.

    ``cos(phi) = (tr Q - 1)/2``; ``e = vect(Q)/sin(phi)``, or for a half turn
    (``vect(Q) = 0``) a non-zero column of ``(Q + 1)/2 = e e^T`` normalised.
    """
    c = _radsimp((trace(Q) - 1) / 2)
    phi = sp.acos(c)
    v = vect(Q)
    if not is_zero(v):
        return phi, (v / sp.sin(phi)).applyfunc(_radsimp)
    if is_zero(c - 1):
        return None
    M = (Q + sp.eye(3)) / 2
    j = next(j for j in range(3) if not is_zero(M[j, j]))
    return phi, (M[:, j] / sp.sqrt(M[j, j])).applyfunc(_radsimp)


def screw_of_displacement(Q, a, a_prime):
    """Angle, unit axis, axis point closest to O, Plücker array ``[e; p0 x e]``; ``None``
    for a pure translation (``Q = 1``: no axis is singled out)."""
    ax = angle_axis(Q)
    if ax is None:
        return None
    phi, e = ax
    p0 = screw_axis_point(Q, a, a_prime, phi).applyfunc(_expanded)
    n = p0.cross(e).applyfunc(_expanded)
    return phi, e, p0, sp.Matrix.vstack(e, n)


def rotation_defect(Q) -> str:
    """"" when ``Q`` is exactly proper orthogonal, else what fails, in words."""
    if not is_zero(Q.T * Q - sp.eye(3)):
        return "Q^T Q != 1"
    if not is_zero(Q.det() - 1):
        return "det Q = -1 (a reflection)"
    return ""
