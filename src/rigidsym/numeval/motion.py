"""Smooth motions of the symbols declared functions of time (``--let 'X(t): KIND'``), the
second semantics' own: a random curve of each kind through a random value,
quadratic in t (a rotation ``R_0 e^{[w_1 t + w_2 t^2]}``, a unit vector a normalised
quadratic), evaluated at any t; their derivatives are taken by the evaluator's differences."""

from __future__ import annotations

import random

import mpmath as mp

from rigidsym.numeval.sampler import kind_words, sample
from rigidsym.numeval.values import NotCovered, rodrigues, vee

__all__ = ["curve", "at", "through"]


def curve(kind: str, rng: random.Random) -> tuple:
    """The coefficients of a random motion of ``kind``: ``(kind, c0, c1, c2)``.

    Raises:
        NotCovered: a kind with no motion here."""
    t = kind_words(kind)
    if t in ("rotation", "rotation matrix"):
        return ("rotation", sample("rotation", rng), sample("vector", rng),
                sample("vector", rng))
    if t in ("unit vector", "unit 3-vector", "unit 4-vector"):
        n = 4 if "4" in t else 3
        return ("unit", sample(f"{n}-vector", rng), sample(f"{n}-vector", rng) / 4,
                sample(f"{n}-vector", rng) / 4)
    if t in ("transform",):
        return ("transform", sample("rotation", rng), sample("vector", rng),
                sample("vector", rng), sample("vector", rng), sample("vector", rng))
    if t in ("angle", "angle in [0, pi]", "scalar") or t.endswith("vector") or \
            t.endswith("matrix") or t in ("twist", "wrench"):
        return ("plain", sample(kind, rng), sample(kind, rng), sample(kind, rng))
    raise NotCovered(f"a motion of the kind {kind!r}")


def at(c: tuple, t):
    """The motion ``c`` at time ``t``."""
    if c[0] == "plain":
        return c[1] + c[2] * t + c[3] * t * t
    if c[0] == "unit":
        v = c[1] + c[2] * t + c[3] * t * t
        return v / mp.norm(v)
    if c[0] == "rotation":
        return c[1] * rodrigues(c[2] * t + c[3] * t * t)
    R = c[1] * rodrigues(c[2] * t + c[3] * t * t)
    p = c[4] + c[5] * t
    T = mp.eye(4)
    for i in range(3):
        for j in range(3):
            T[i, j] = R[i, j]
        T[i, 3] = p[i]
    return T


def through(c: tuple, x0, dot=None, ddot=None) -> tuple:
    """The motion ``c`` moved to pass through ``x0`` at t = 0, with the rate ``dot`` there
    (and, for a plain kind, the second derivative ``ddot``) where given: a given point's
    function of time (the symbolic path's counterexample fixes a value and its rates).

    Raises:
        ValueError: a rate this kind's motion cannot take here (a rotation's ``ddot``, a
            unit vector's or a transform's rate), or a rotation's rate that is not
            ``x0 [w]`` (its ``x0^T dot`` not skew): the point is not mapped, never bent.
    """
    if c[0] == "plain":
        return ("plain", x0, c[2] if dot is None else dot, c[3] if ddot is None else ddot / 2)
    if ddot is not None or (dot is not None and c[0] != "rotation"):
        raise ValueError(f"a {c[0]} motion through a given rate")
    if c[0] == "unit":
        return ("unit", x0, c[2], c[3])
    if c[0] == "rotation":
        if dot is None:
            return ("rotation", x0, c[2], c[3])
        s = x0.T * dot
        if mp.mnorm(s + s.T, 1) > mp.mpf(10) ** (-mp.mp.dps // 2) * (1 + mp.mnorm(s, 1)):
            raise ValueError("a rotation's rate that is not R [w]")
        return ("rotation", x0, vee((s - s.T) / 2), c[3])
    R = mp.matrix([[x0[i, j] for j in range(3)] for i in range(3)])
    return ("transform", R, c[2], c[3], mp.matrix([x0[i, 3] for i in range(3)]), c[5])
