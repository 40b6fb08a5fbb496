"""J. Diebel, "Representing attitude: Euler angles, unit quaternions, and rotation
vectors", Stanford, 2006. Notation: R_1(phi), R_2(theta), R_3(psi) the
rotations about the coordinate axes, functions of their angle (his (46)-(48), passive); the
Euler-angle matrix R_{123}(phi, theta, psi), a function of three parameters, and the same
declared as models that use models, top-down as he gives them. Truth by NumPy."""

import numpy as np
from _num import I3, E


def _f(x):
    """A 1 x 1 array (or a number) as a float."""
    return np.asarray(x, float).item()

BOOK = {"key": "diebel", "title": "Diebel, Representing attitude",
        "edition": "Stanford University, 2006"}

TABLE = r"""
\phi: angle
\theta: angle
\psi: angle
"""

R1 = (r"R_1(\alpha) = \begin{bmatrix}1 & 0 & 0\\ 0 & \cos\alpha & \sin\alpha\\ 0 & "
      r"-\sin\alpha & \cos\alpha\end{bmatrix}")
R2 = (r"R_2(\alpha) = \begin{bmatrix}\cos\alpha & 0 & -\sin\alpha\\ 0 & 1 & 0\\ \sin\alpha"
      r" & 0 & \cos\alpha\end{bmatrix}")
R3 = (r"R_3(\alpha) = \begin{bmatrix}\cos\alpha & \sin\alpha & 0\\ -\sin\alpha & \cos\alpha"
      r" & 0\\ 0 & 0 & 1\end{bmatrix}")
R123 = r"R_{123}(\phi,\theta,\psi) = R_1(\phi)R_2(\theta)R_3(\psi)"
FN = (R1, R2, R3, R123)
# the same as models, declared top-down (R first, its factors after; c_\psi after R_3)
TOP = (r"R = R_1 R_2 R_3",
       r"R_1 = \begin{bmatrix}1 & 0 & 0\\ 0 & c_\phi & s_\phi\\ 0 & -s_\phi & c_\phi"
       r"\end{bmatrix}",
       r"R_2 = \begin{bmatrix}c_\theta & 0 & -s_\theta\\ 0 & 1 & 0\\ s_\theta & 0 & c_\theta"
       r"\end{bmatrix}",
       r"R_3 = \begin{bmatrix}c_\psi & s_\psi & 0\\ -s_\psi & c_\psi & 0\\ 0 & 0 & 1"
       r"\end{bmatrix}",
       r"c_\phi = \cos\phi", r"s_\phi = \sin\phi", r"c_\theta = \cos\theta",
       r"s_\theta = \sin\theta", r"c_\psi = \cos\psi", r"s_\psi = \sin\psi")


def _r1(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])


def _r2(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, -s], [0, 1, 0], [s, 0, c]])


def _r3(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def _r(v):
    return _r1(v.phi) @ _r2(v.theta) @ _r3(v.psi)


ENTRIES = [
    E("5.2", "(57)", r"R_{123}(\phi,\theta,\psi)^T R_{123}(\phi,\theta,\psi) = I_3", True,
      lambda v: (_r(v).T @ _r(v), I3), lets=FN),
    E("5.2", "(57)", r"\det(R_{123}(\phi,\theta,\psi)) = 1", True,
      lambda v: (np.linalg.det(_r(v)), 1.0), lets=FN),
    E("5.2", "(57)", r"R_{123}(\phi,\theta,\psi) = R_3(\psi)R_2(\theta)R_1(\phi)", False,
      lambda v: (_r(v), _r3(v.psi) @ _r2(v.theta) @ _r1(v.phi)), lets=FN),
    E("5.1", "(46)", r"R_1(\phi)^T = R_1(-\phi)", True,
      lambda v: (_r1(v.phi).T, _r1(-v.phi)), lets=(R1,)),
    E("5.1", "(48)", r"R_3(\psi)R_3(\phi) = R_3(\psi + \phi)", True,
      lambda v: (_r3(v.psi) @ _r3(v.phi), _r3(v.psi + v.phi)), lets=(R3,)),
    E("5.1", "(48)", r"R_3(\psi)R_3(\phi) = R_3(\psi - \phi)", False,
      lambda v: (_r3(v.psi) @ _r3(v.phi), _r3(v.psi - v.phi)), lets=(R3,)),
    E("5.1", "(46)", r"R_1(\phi)R_2(\theta) = R_2(\theta)R_1(\phi)", False,
      lambda v: (_r1(v.phi) @ _r2(v.theta), _r2(v.theta) @ _r1(v.phi)), lets=(R1, R2)),
    E("5.2", "(57)", r"R_{123}(0,0,\psi) = R_3(\psi)", True,
      lambda v: (_r1(0) @ _r2(0) @ _r3(v.psi), _r3(v.psi)), lets=FN),
    E("5.2", "(57)", r"R^T R = I_3", True, lambda v: (_r(v).T @ _r(v), I3), lets=TOP),
    E("5.2", "(57)", r"R = R_3 R_2 R_1", False,
      lambda v: (_r(v), _r3(v.psi) @ _r2(v.theta) @ _r1(v.phi)), lets=TOP),
    E("5.1", "(48)", r"R_3(\psi)^T R_3(\psi) = I_3", True,
      lambda v: (_r3(v.psi).T @ _r3(v.psi), I3), lets=(TOP[3], *TOP[8:])),
]
