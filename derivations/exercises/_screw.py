"""Shared: screw of a finite displacement x -> Q x + c, via the chapter's Eq. (3.18)."""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import trace, vect

from ..sec3_2_1 import screw_axis_point


def screw_of_displacement(Q, a, a_prime):
    """Angle, unit axis, axis point closest to O, Plücker array ``[e; p0 x e]``."""
    phi = sp.acos(sp.radsimp((trace(Q) - 1) / 2))
    e = (vect(Q) / sp.sin(phi)).applyfunc(sp.radsimp)
    p0 = screw_axis_point(Q, a, a_prime, phi).applyfunc(lambda v: sp.radsimp(sp.expand(v)))
    n = p0.cross(e).applyfunc(lambda v: sp.radsimp(sp.expand(v)))
    return phi, e, p0, sp.Matrix.vstack(e, n)
