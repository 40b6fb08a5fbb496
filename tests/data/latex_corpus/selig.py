"""J. M. Selig, *Geometric Fundamentals of Robotics*, 2nd ed., Springer, 2005, sec. 4.3
. Notation: the rotation R(n, theta) of the unit axis n and angle theta in
Rodrigues' form I + sin(theta) N + (1 - cos(theta)) N^2, N = [n]x, a function of a vector and
an angle; e^{theta [n]x} its exponential form. Truth by NumPy."""

import numpy as np
from _num import I3, E, expm, hat

BOOK = {"key": "selig", "title": "Selig, Geometric Fundamentals of Robotics",
        "edition": "2nd ed., Springer, 2005"}

TABLE = r"""
\mathbf{n}: unit vector
\theta: angle
Q: rotation
"""

R = (r"R(\mathbf{n},\theta) = I_3 + \sin\theta\,[\mathbf{n}]_\times + (1 - \cos\theta)"
     r"[\mathbf{n}]_\times^2")


def _r(n, t):
    return I3 + np.sin(t) * hat(n) + (1 - np.cos(t)) * hat(n) @ hat(n)


ENTRIES = [
    E("4.3", "(4.5)", r"R(\mathbf{n},\theta)R(\mathbf{n},-\theta) = I_3", True,
      lambda v: (_r(v.n, v.theta) @ _r(v.n, -v.theta), I3), lets=(R,)),
    E("4.3", "(4.6)", r"R(\mathbf{n},\theta) = e^{\theta[\mathbf{n}]_\times}", True,
      lambda v: (_r(v.n, v.theta), expm(v.theta * hat(v.n))), lets=(R,)),
    E("4.3", "(4.5)", r"R(\mathbf{n},\theta)^T = R(-\mathbf{n},\theta)", True,
      lambda v: (_r(v.n, v.theta).T, _r(-v.n, v.theta)), lets=(R,)),
    E("4.3", "(4.5)", r"R(\mathbf{n},\theta)^T = R(\mathbf{n},\theta)", False,
      lambda v: (_r(v.n, v.theta).T, _r(v.n, v.theta)), lets=(R,)),
    E("4.3", "cf. (4.5)", r"R(Q\mathbf{n},\theta) = Q R(\mathbf{n},\theta) Q^T", True,
      lambda v: (_r(v.Q @ v.n, v.theta), v.Q @ _r(v.n, v.theta) @ v.Q.T), lets=(R,)),
    E("4.3", "cf. (4.5)", r"R(Q\mathbf{n},\theta) = Q^T R(\mathbf{n},\theta) Q", False,
      lambda v: (_r(v.Q @ v.n, v.theta), v.Q.T @ _r(v.n, v.theta) @ v.Q), lets=(R,)),
    E("4.3", "(4.7)", r"\operatorname{tr} R(\mathbf{n},\theta) = 1 + 2\cos\theta", True,
      lambda v: (np.trace(_r(v.n, v.theta)), 1 + 2 * np.cos(v.theta)), lets=(R,)),
]
