"""SciPy 1.17.1's ``Rotation.from_matrix(R).as_euler("xyz")``, re-created: the quaternion by
the largest of the diagonal and the trace, the angles by Bernardes and Viollet's method
(2022), and where the middle angle is within 1e-7 of the lock "gimbal lock detected": the
third angle set to 0, so that the angles' rotation is off ``R`` by up to ~1e-7 where the
angles are determined far better."""

import math

import numpy as np

__version__ = "1.17.1"


def as_euler_xyz(matrix):
    """The extrinsic x-y-z angles of ``matrix`` (3 x 3) as SciPy 1.17.1 computes them."""
    m = np.asarray(matrix, dtype=np.float64)
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    choice = int(np.argmax([m[0, 0], m[1, 1], m[2, 2], tr]))
    if choice == 0:
        q = [1 - tr + 2 * m[0, 0], m[1, 0] + m[0, 1], m[2, 0] + m[0, 2], m[2, 1] - m[1, 2]]
    elif choice == 1:
        q = [m[1, 0] + m[0, 1], 1 - tr + 2 * m[1, 1], m[2, 1] + m[1, 2], m[0, 2] - m[2, 0]]
    elif choice == 2:
        q = [m[2, 0] + m[0, 2], m[2, 1] + m[1, 2], 1 - tr + 2 * m[2, 2], m[1, 0] - m[0, 1]]
    else:
        q = [m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1], 1 + tr]
    q = np.array(q) / np.linalg.norm(q)         # x, y, z, w
    i, j, k = 0, 1, 2                           # extrinsic "xyz": not symmetric, sign 1
    sign = (i - j) * (j - k) * (k - i) // 2
    a, b = q[3] - q[j], q[i] + q[k] * sign
    c, d = q[j] + q[3], q[k] * sign - q[i]
    eps = 1e-7
    half_sum, half_diff = math.atan2(b, a), math.atan2(d, c)
    angles = np.zeros(3)
    angles[1] = 2 * math.atan2(math.hypot(c, d), math.hypot(a, b))
    case1 = abs(angles[1]) <= eps
    case2 = abs(angles[1] - math.pi) <= eps
    angles[0] = 2 * half_sum if case1 else -2 * half_diff
    if not (case1 or case2):
        angles[0] = half_sum - half_diff
        angles[2] = half_sum + half_diff
    angles[2] *= sign
    angles[1] -= math.pi / 2
    return (angles + math.pi) % (2 * math.pi) - math.pi
