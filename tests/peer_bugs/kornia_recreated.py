"""kornia 0.8.3's ``geometry.conversions.axis_angle_to_rotation_matrix`` (float64; kornia
#3947, corrected by its PR #3989), re-created in NumPy: the axis ``w / (theta + 1e-6)`` (a
rotation shrunk by ``1e-6 / theta``) and, where ``theta^2 <= 1e-6``, the first-order
matrix ``1 + [w]x``."""

import math

import numpy as np

__version__ = "0.8.3"


def axis_angle_to_rotation_matrix(axis_angle, eps=1e-6):
    """The rotation of the rotation vector ``axis_angle`` (3) as kornia 0.8.3 computes it."""
    rx, ry, rz = np.asarray(axis_angle, dtype=np.float64)
    theta2 = rx * rx + ry * ry + rz * rz
    if not theta2 > 1e-6:
        return np.array([[1.0, -rz, ry], [rz, 1.0, -rx], [-ry, rx, 1.0]])
    theta = math.sqrt(max(theta2, 1e-12))
    wx, wy, wz = rx / (theta + eps), ry / (theta + eps), rz / (theta + eps)
    c, s = math.cos(theta), math.sin(theta)
    omc = 1.0 - c
    return np.array([[c + wx * wx * omc, wx * wy * omc - wz * s, wy * s + wx * wz * omc],
                     [wz * s + wx * wy * omc, c + wy * wy * omc, -wx * s + wy * wz * omc],
                     [-wy * s + wx * wz * omc, wx * s + wy * wz * omc, c + wz * wz * omc]])
