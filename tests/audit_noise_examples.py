"""Functions for tests/test_audit_noise.py: the false findings a maintainer pushed back on,
re-created in a few lines each (NumPy only, sharing no code with rigidsym's kernels), and
the wrong outputs an audit must count. Importable as ``audit_noise_examples:NAME``."""

import math

import numpy as np

U = 2.0**-53


def vee(M):
    """The axial vector of the skew part of M."""
    return np.array([M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]]) / 2


def log(Q):
    """The logarithm of SO(3) through atan2 (accurate everywhere)."""
    Q = np.asarray(Q, dtype=np.float64)
    s, c = vee(Q), (np.trace(Q) - 1) / 2
    ns = np.linalg.norm(s)
    th = math.atan2(ns, c)
    if c > 0:
        return s if ns == 0 else th / ns * s
    B = (Q + Q.T) / 2 - c * np.eye(3)
    i = int(np.argmax(np.diag(B)))
    e = B[:, i] / np.linalg.norm(B[:, i])
    return th * (e if e @ s >= 0 else -e)


# SymForce's Rot3.to_tangent, its error re-created: a flat relative error of 2e-14 near the
# identity (an epsilon in the angle's formula), far inside the bound 8 u (kappa + 1) there
# (kappa ~ 1.2 / phi); judged with kappa taken as 0 below phi = 1.08e-15 (where kappa u
# passes 1/8) it looked like a window with "a threshold branch" at 1.08e-15
def log_flat_error(Q):
    w = log(Q)
    return w * (1 + 2e-14) if np.linalg.norm(w) < 1e-6 else w


# rowan's to_euler, its error re-created: a relative error of 16 u near a half turn, where
# the logarithm's condition number is about 0.6 (the bound 8 u (kappa + 1) ~ 13 u): 1.2x
# the bound, noise level; the same at 48 u (3.7x) is a finding
def log_near_noise(Q):
    w = log(Q)
    return w * (1 + 16 * U) if np.linalg.norm(w) > 2.5 else w


def log_past_noise(Q):
    w = log(Q)
    return w * (1 + 48 * U) if np.linalg.norm(w) > 2.5 else w


# pyquaternion's axis and angle: at the identity (the axis undefined there) the documented
# zero axis [0, 0, 0] with the angle 0; the book's (e, phi) elsewhere
def axis_angle_zero_axis(Q):
    w = log(Q)
    phi = float(np.linalg.norm(w))
    if phi == 0:
        return np.zeros(3), 0.0
    return w / phi, phi


def rotation_from_axis_angle(e, phi):
    """``Q = e e^T + cos(phi) (1 - e e^T) + sin(phi) E`` (2.49) with ``1 - cos(phi)`` as
    ``2 sin^2(phi / 2)`` (accurate everywhere)."""
    e = np.asarray(e, dtype=np.float64)
    E = np.array([[0.0, -e[2], e[1]], [e[2], 0.0, -e[0]], [-e[1], e[0], 0.0]])
    return np.eye(3) + math.sin(phi) * E + 2 * math.sin(phi / 2) ** 2 * E @ E


# a truncated series on a window between two decades: 1 - cos(phi) as phi^2 / 2 alone on
# 2e-3 < phi < 5e-3 (a threshold meant for the next term): right at 1e-3 and at 1e-2, about
# 1e3 x the bound at 3e-3 (the dropped phi^4 / 24 against 8 u (kappa + 1))
def rotation_series_between_decades(e, phi):
    e = np.asarray(e, dtype=np.float64)
    if 2e-3 < abs(phi) < 5e-3:
        E = np.array([[0.0, -e[2], e[1]], [e[2], 0.0, -e[0]], [-e[1], e[0], 0.0]])
        return np.eye(3) + math.sin(phi) * E + phi**2 / 2 * E @ E
    return rotation_from_axis_angle(e, phi)


def quaternion(Q):
    """The Euler-Rodrigues parameters [r; r0] of Q (r0 >= 0), from the logarithm."""
    w = log(Q)
    phi = float(np.linalg.norm(w))
    r = w * (math.sin(phi / 2) / phi) if phi else np.zeros(3)
    return np.array([*r, math.cos(phi / 2)])


# the other sign everywhere (r0 <= 0): the same rotation, a convention to name
def quaternion_negated(Q):
    return -quaternion(Q)


# ahrs' hughes, its batched path re-created: one matrix at a time right, a stack of them
# the conjugate quaternion [-r; r0] (the inverse rotation) of each
def quaternion_batched_conjugate(Q):
    Q = np.asarray(Q, dtype=np.float64)
    if Q.ndim == 3:
        return np.stack([quaternion(M) * np.array([-1.0, -1.0, -1.0, 1.0]) for M in Q])
    return quaternion(Q)
