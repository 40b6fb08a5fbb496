"""Pinocchio 4.1.0's ``log3`` (``include/pinocchio/src/spatial/log.hxx``, ``log3_impl``),
re-created in NumPy: the angle is ``sqrt(2 (1 - cos))``, a series truncated after its first
term, where ``tr Q > 3 - eps^(1/3)`` (phi below 2.46e-3), ``acos`` elsewhere; the rotation
vector is ``theta / sin(theta)`` times the skew part of the renormalized ``Q``."""

import math

import numpy as np

__version__ = "4.1.0"
EPS = float(np.finfo(np.float64).eps)      # Eigen's NumTraits<double>::epsilon()


def _renormalize(R):
    c0 = R[:, 0] / np.linalg.norm(R[:, 0])
    c1 = R[:, 1] / np.linalg.norm(R[:, 1])
    c2 = np.cross(c0, c1)
    c0 = np.cross(c1, c2)
    return np.column_stack([c0, c1, c2])


def _theta_axis(i0, val, R):
    i1, i2 = (i0 + 1) % 3, (i0 + 2) % 3
    s = math.sqrt(val + EPS + EPS * EPS) * (1.0 if R[i2, i1] >= R[i1, i2] else -1.0)
    axis = np.empty(3)
    axis[i0] = s / 2
    axis[i1] = 1 / (2 * s) * (R[i1, i0] + R[i0, i1])
    axis[i2] = 1 / (2 * s) * (R[i2, i0] + R[i0, i2])
    w = 1 / (2 * s) * (R[i2, i1] - R[i1, i2])
    n = np.linalg.norm(axis)
    return 2 * math.atan2(n, w), axis / n


def log3(R):
    """The rotation vector of ``R`` (3 x 3) as Pinocchio 4.1.0 computes it."""
    Rn = _renormalize(np.asarray(R, dtype=np.float64))
    tr = Rn[0, 0] + Rn[1, 1] + Rn[2, 2]
    cos_value = (tr - 1) / 2
    prec = EPS ** (1 / 3)                 # TaylorSeriesExpansion<double>::precision<2>()
    acos_expansion = math.sqrt(2 * (1 - cos_value) + EPS * EPS)
    if tr <= 3 - prec:
        theta = math.acos(cos_value) if tr >= -1 + prec else math.pi - acos_expansion
    else:
        theta = acos_expansion
    a = np.array([Rn[2, 1] - Rn[1, 2], Rn[0, 2] - Rn[2, 0], Rn[1, 0] - Rn[0, 1]]) / 2
    n2 = a @ a
    t = theta / math.sin(theta) if theta >= prec else 1 + n2 / 6 + n2 * n2 * 3 / 40
    if cos_value >= -1 + prec:
        return t * a
    val = 2 * np.diag(Rn) - tr + 1
    k = int(np.argmax(val))
    theta_s, axis = _theta_axis(k, val[k], Rn)
    return theta_s * axis
