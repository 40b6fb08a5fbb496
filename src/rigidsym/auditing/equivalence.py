"""Outputs that mean the same rotation: a user's output judged as one answer with every
output that denotes the same rotation under the operation's contract.

The classes follow from the book's statements, not from a list of peers' habits:

- the natural invariants ``(e, phi)`` of ``Q`` (2.49): ``Q(e, phi) = e e^T + cos(phi) (1 -
  e e^T) + sin(phi) E`` is unchanged by ``(e, phi) -> (-e, -phi)`` (cos even, sin and E
  odd) and by ``phi -> phi + 2 pi k``; at ``phi = 0`` (``Q = 1``) by any rotation of the
  unit axis (``Q = e e^T + 1 - e e^T = 1`` whatever ``e``), and the zero axis with the angle
  0 is a library's answer for the undefined axis there (its convention, which the audit
  names); at ``phi = pi`` the pair ``(e, pi)``, ``(-e, pi)`` is the first two composed.
  The contract asks ``|e| = 1``: a non-unit axis is not moved onto the class (its error
  stays).
- the Euler-Rodrigues parameters ``eta`` (2.3): ``Q`` is quadratic in ``eta``, so ``eta``
  and ``-eta`` are the same rotation everywhere.

:func:`nearest` moves a user's output by one of these symmetries (exact operations: a
negation, a shift by ``fl(2 pi)``, a whole turn as the user's float holds it, a rotation of
the axis at the identity) to the member of its class nearest an anchor (the truth, or
rigidsym's kernel there, a few ulps from it): what is left is the output's own error. An
angle of several turns, ``phi + 2 pi k`` in the user's float, holds ``phi`` to an absolute
error of its own ulp (two turns keep 9 digits of ``phi = 1e-7``): that much of the gap,
the representation's rounding, is not counted against the function; the rest is.
The rotation vector's ``w`` and ``-w`` at a half turn, and the Euler angles' branches, are
judged in :mod:`.worst`.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["KINDS", "nearest", "axis_angle_rotation"]

#: the output kinds with a class of equivalent outputs (a target's ``equivalent``)
KINDS = ("axis_angle", "quaternion")

#: the roundings of an angle of several turns the representation itself makes, in units of
#: u of its magnitude: the sum phi + 2 pi k, a conversion to degrees and back, the shift
_ROUNDINGS = 4

#: a whole turn as a float holds it: an output of fl(2 pi) k is a whole turn k, exactly
_TWO_PI = 6.283185307179586


def axis_angle_rotation(e, phi: float) -> np.ndarray:
    """``Q(e, phi) = e e^T + cos(phi) (1 - e e^T) + sin(phi) E`` (2.49), 3 x 3, float64: the
    rotation a pair of natural invariants denotes."""
    e = np.asarray(e, dtype=np.float64)
    E = np.array([[0.0, -e[2], e[1]], [e[2], 0.0, -e[0]], [-e[1], e[0], 0.0]])
    P = np.outer(e, e)
    return P + math.cos(phi) * (np.eye(3) - P) + math.sin(phi) * E


def _shift(phi: float, k: int) -> float:
    return phi - k * _TWO_PI


def _axis_angle(got: np.ndarray, anchor: np.ndarray, u: float) -> np.ndarray:
    e, phi = got[:3], float(got[3])
    ae, aphi = anchor[:3], float(anchor[3])
    if aphi == 0.0:
        # Q = 1: any unit axis (its length kept: |e| - 1 is the output's error), any 2 pi k;
        # the zero axis with the angle 0 is a library's documented answer for the undefined
        # axis (pyquaternion's): the same rotation, told as its convention (audit)
        n = float(np.linalg.norm(e))
        if n == 0.0 and phi == 0.0:
            return anchor.copy()
        k = round(phi / (2 * math.pi)) if math.isfinite(phi) else 0
        ax = ae * n if n > 0 else e
        return np.concatenate([ax, [_shift(phi, k)]])
    best, best_d = got, math.inf
    for s in (1.0, -1.0):
        p = s * phi
        k = round((p - aphi) / (2 * math.pi)) if math.isfinite(p) else 0
        q = _shift(p, k)
        if k:
            # the user's float holds phi + 2 pi k to its own ulp (and a degrees' round trip
            # to two more roundings): that much of the gap is the representation's, the
            # rest the function's
            q = aphi + math.copysign(max(0.0, abs(q - aphi) - _ROUNDINGS * u * abs(p)),
                                     q - aphi)
        cand = np.concatenate([s * e, [q]])
        d = float(np.linalg.norm(cand - anchor))
        if d < best_d:
            best, best_d = cand, d
    return best


def _quaternion(got: np.ndarray, anchor: np.ndarray) -> np.ndarray:
    return -got if np.linalg.norm(-got - anchor) < np.linalg.norm(got - anchor) else got


def nearest(kind: str, got, anchor, u: float = 2.0**-53) -> np.ndarray:
    """The member of ``got``'s class (outputs of the same rotation, :data:`KINDS`) nearest
    ``anchor``, both flat in the book's layout (``[e; phi]``, ``[r; r0]``); ``got`` itself
    where it is not finite or ``kind`` is "". ``u``: the unit roundoff of the user's float
    type (an angle of several turns is held to its own ulp: that part of the gap is not
    the function's).

    Raises:
        ValueError: ``kind`` not among :data:`KINDS` nor ""."""
    got = np.asarray(got, dtype=np.float64)
    anchor = np.asarray(anchor, dtype=np.float64)
    if kind == "":
        return got
    if kind not in KINDS:
        raise ValueError(f"kind: {kind!r}: expected one of {', '.join(KINDS)} or ''")
    if got.shape != anchor.shape or not np.isfinite(got).all() \
            or not np.isfinite(anchor).all():
        return got
    return _axis_angle(got, anchor, u) if kind == "axis_angle" else _quaternion(got, anchor)
