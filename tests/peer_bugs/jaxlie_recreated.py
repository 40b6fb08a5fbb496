"""jaxlie 1.5.0's ``SO3.from_matrix(Q).log()`` (float64), re-created in NumPy: the quaternion
by Mike Day's four cases, the logarithm with ``pi / |xyz|`` where ``|w| < 1e-10``, which is
off by up to ``2 |w|`` in the angle within ~2e-10 of a half turn."""

import math

import numpy as np

__version__ = "1.5.0"


def so3_log(m):
    """The rotation vector of ``m`` (3 x 3) as jaxlie 1.5.0 computes it in float64."""
    m = np.asarray(m, dtype=np.float64)
    if m[2, 2] < 0:
        if m[0, 0] > m[1, 1]:
            t = 1 + m[0, 0] - m[1, 1] - m[2, 2]
            q = [m[2, 1] - m[1, 2], t, m[1, 0] + m[0, 1], m[0, 2] + m[2, 0]]
        else:
            t = 1 - m[0, 0] + m[1, 1] - m[2, 2]
            q = [m[0, 2] - m[2, 0], m[1, 0] + m[0, 1], t, m[2, 1] + m[1, 2]]
    elif m[0, 0] < -m[1, 1]:
        t = 1 - m[0, 0] - m[1, 1] + m[2, 2]
        q = [m[1, 0] - m[0, 1], m[0, 2] + m[2, 0], m[2, 1] + m[1, 2], t]
    else:
        t = 1 + m[0, 0] + m[1, 1] + m[2, 2]
        q = [t, m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]]
    wxyz = np.array(q) * 0.5 / math.sqrt(t)
    w, xyz = wxyz[0], wxyz[1:]
    norm_sq = xyz @ xyz
    if norm_sq < 1e-10:                           # get_epsilon(float64)
        factor = 2.0 / w - 2.0 / 3.0 * norm_sq / w**3
    elif abs(w) < 1e-10:
        factor = (1.0 if w > 0 else -1.0) * math.pi / math.sqrt(norm_sq)
    else:
        n = math.sqrt(norm_sq)
        factor = 2.0 * math.atan2(-n if w < 0 else n, abs(w)) / n
    return factor * xyz
