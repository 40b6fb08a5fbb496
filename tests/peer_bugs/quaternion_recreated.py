"""numpy-quaternion 2024.0.13's ``as_rotation_vector(from_rotation_matrix(Q))``, re-created:
the quaternion an eigenvector of Bar-Itzhack's 4 x 4 matrix (SciPy's ``eigh``, whose sign
is arbitrary), the rotation vector ``2 log q`` with ``atan2(|v|, w)`` (its C
``quaternion_log``), so that where the eigenvector comes out with ``w < 0`` the vector is
``w - 2 pi w/|w|``, not the principal logarithm."""

import math

import numpy as np

__version__ = "2024.0.13"


def rotation_vector(rot):
    """The rotation vector of ``rot`` (3 x 3) as numpy-quaternion 2024.0.13 computes it."""
    from scipy import linalg

    r = np.asarray(rot, dtype=np.float64)
    K3 = np.empty((4, 4))
    K3[0, 0] = (r[0, 0] - r[1, 1] - r[2, 2]) / 3.0
    K3[0, 1] = (r[1, 0] + r[0, 1]) / 3.0
    K3[0, 2] = (r[2, 0] + r[0, 2]) / 3.0
    K3[0, 3] = (r[1, 2] - r[2, 1]) / 3.0
    K3[1, 0] = K3[0, 1]
    K3[1, 1] = (r[1, 1] - r[0, 0] - r[2, 2]) / 3.0
    K3[1, 2] = (r[2, 1] + r[1, 2]) / 3.0
    K3[1, 3] = (r[2, 0] - r[0, 2]) / 3.0
    K3[2, 0], K3[2, 1] = K3[0, 2], K3[1, 2]
    K3[2, 2] = (r[2, 2] - r[0, 0] - r[1, 1]) / 3.0
    K3[2, 3] = (r[0, 1] - r[1, 0]) / 3.0
    K3[3, 0], K3[3, 1], K3[3, 2] = K3[0, 3], K3[1, 3], K3[2, 3]
    K3[3, 3] = (r[0, 0] + r[1, 1] + r[2, 2]) / 3.0
    _, vecs = linalg.eigh(K3.T, subset_by_index=(3, 3))
    q = np.array([vecs[-1, 0], *(-vecs[:-1].flatten())])
    q = q / math.sqrt(q @ q)                     # np.normalized
    w, v = q[0], q[1:]
    b = math.sqrt(v @ v)
    if abs(b) <= 1.1102230246251565e-16 * abs(w):    # _QUATERNION_EPS
        return np.array([2 * math.pi, 0.0, 0.0]) if w < 0 else np.zeros(3)
    return 2 * (math.atan2(b, w) / b) * v
