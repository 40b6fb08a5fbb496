"""H. Goldstein, C. Poole and J. Safko, *Classical Mechanics*, 3rd ed., Addison-Wesley, 2002,
sec. 4.4. Notation: the Euler angles (phi, theta, psi) of the x-convention,
D(phi) and B(psi) rotations about z and C(theta) about x, functions of their angle ((4.43)-
(4.45), passive), A(phi, theta, psi) = B(psi) C(theta) D(phi) (4.46), a function of three
parameters. Truth by NumPy."""

import numpy as np
from _num import I3, E

BOOK = {"key": "goldstein", "title": "Goldstein, Poole & Safko, Classical Mechanics",
        "edition": "3rd ed., Addison-Wesley, 2002"}

TABLE = r"""
\phi: angle
\theta: angle
\psi: angle
"""

D = (r"D(\alpha) = \begin{bmatrix}\cos\alpha & \sin\alpha & 0\\ -\sin\alpha & \cos\alpha & 0"
     r"\\ 0 & 0 & 1\end{bmatrix}")
B = D.replace("D(", "B(", 1)
C = (r"C(\alpha) = \begin{bmatrix}1 & 0 & 0\\ 0 & \cos\alpha & \sin\alpha\\ 0 & -\sin\alpha"
     r" & \cos\alpha\end{bmatrix}")
A = r"A(\phi,\theta,\psi) = B(\psi)C(\theta)D(\phi)"
ALL = (D, B, C, A)


def _z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def _x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])


def _a(p, t, s):
    return _z(s) @ _x(t) @ _z(p)


ENTRIES = [
    E("4.4", "(4.46)", r"A(\phi,\theta,\psi)^T A(\phi,\theta,\psi) = I_3", True,
      lambda v: (_a(v.phi, v.theta, v.psi).T @ _a(v.phi, v.theta, v.psi), I3), lets=ALL),
    E("4.4", "(4.46)", r"\det(A(\phi,\theta,\psi)) = 1", True,
      lambda v: (np.linalg.det(_a(v.phi, v.theta, v.psi)), 1.0), lets=ALL),
    E("4.4", "(4.46)", r"A(\phi,\theta,\psi) = D(\phi)C(\theta)B(\psi)", False,
      lambda v: (_a(v.phi, v.theta, v.psi), _z(v.phi) @ _x(v.theta) @ _z(v.psi)), lets=ALL),
    E("4.4", "(4.43)", r"D(\phi)^T = D(-\phi)", True, lambda v: (_z(v.phi).T, _z(-v.phi)),
      lets=(D,)),
    E("4.4", "(4.46)", r"A(\phi,0,\psi) = B(\psi + \phi)", True,
      lambda v: (_a(v.phi, 0, v.psi), _z(v.psi + v.phi)), lets=ALL),
    E("4.4", "(4.46)", r"A(\phi,0,\psi) = B(\psi - \phi)", False,
      lambda v: (_a(v.phi, 0, v.psi), _z(v.psi - v.phi)), lets=ALL),
    E("4.4", "(4.47)", r"A(\phi,\theta,\psi)^T = A(-\psi,-\theta,-\phi)", True,
      lambda v: (_a(v.phi, v.theta, v.psi).T, _a(-v.psi, -v.theta, -v.phi)), lets=ALL),
    E("4.4", "(4.47)", r"A(\phi,\theta,\psi)^T = A(-\phi,-\theta,-\psi)", False,
      lambda v: (_a(v.phi, v.theta, v.psi).T, _a(-v.phi, -v.theta, -v.psi)), lets=ALL),
]
