"""Shared inertia helpers for the exercises: Steiner's theorem and the 6 x 6 dyads.

Thin wrappers over :mod:`rigidsym.algebra.primitives`; the chapter's formula is Eq. (3.133b),
``I_A = I_C + m (A - C)(A - C)^T = I_C - m CPM(a - c)^2``.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import block, cpm


def inertia_at_point(I_C, m, a, c) -> sp.Matrix:
    """``I_A = I_C + m (A - C)(A - C)^T`` (Eq. 3.133b), ``A - C = CPM(a - c)``."""
    D = cpm(sp.Matrix(a) - sp.Matrix(c))
    return sp.Matrix(I_C) + m * D * D.T


def inertia_dyad(I_C, m) -> sp.Matrix:
    """``M = [[I_C, O], [O, m 1]]`` (Eq. 3.138)."""
    return block([[sp.Matrix(I_C), sp.zeros(3)], [sp.zeros(3), m * sp.eye(3)]])


def angular_velocity_dyad(omega) -> sp.Matrix:
    """``W = [[Omega, O], [O, O]]`` (Eq. 3.140)."""
    return block([[cpm(omega), sp.zeros(3)], [sp.zeros(3), sp.zeros(3)]])
