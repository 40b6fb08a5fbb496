"""J. J. Craig, *Introduction to Robotics: Mechanics and Control*, 3rd ed., Pearson, 2005.
Notation: a rotation or transform carries its frames as left indices, {}^A_B R (frame B
relative to A), a position vector its frame as a left superscript ({}^B P); primed frame
names for Euler angles (R_{Z'Y'X'}); Atan2; I_3, I_4 identities; plain italic symbols."""

import numpy as np
from _num import I3, E, roty, transform

BOOK = {"key": "craig", "title": "Craig, Introduction to Robotics: Mechanics and Control",
        "edition": "3rd ed., Pearson, 2005"}

TABLE = r"""
{}^A_B R: rotation
{}^B P: vector
{}^A P_{BORG}: vector
R_{Z'Y'X'}: rotation
R_{Z'Y'Z'}: rotation
\theta: angle
\theta_1: angle
\theta_2: angle
\alpha: angle
\beta: angle
l_1: scalar
l_2: scalar
"""

_T = (r"\begin{bmatrix}{}^A_B R & {}^A P_{BORG}\\ 0 & 1\end{bmatrix}\begin{bmatrix}"
      r"{}^A_B R^T & -{}^A_B R^T\,{}^A P_{BORG}\\ 0 & 1\end{bmatrix} = I_4")
_RY = (r"\begin{bmatrix}\cos\theta & 0 & \sin\theta\\ 0 & 1 & 0\\ -\sin\theta & 0 & "
       r"\cos\theta\end{bmatrix}")
_ZY = (r"\begin{bmatrix}\cos\alpha & -\sin\alpha & 0\\ \sin\alpha & \cos\alpha & 0\\ 0 & 0 & 1"
       r"\end{bmatrix}\begin{bmatrix}\cos\beta & 0 & \sin\beta\\ 0 & 1 & 0\\ -\sin\beta & 0 & "
       r"\cos\beta\end{bmatrix} = \begin{bmatrix}\cos\alpha\cos\beta & -\sin\alpha & "
       r"\cos\alpha\sin\beta\\ \sin\alpha\cos\beta & \cos\alpha & \sin\alpha\sin\beta\\ "
       r"-\sin\beta & 0 & \cos\beta\end{bmatrix}")


def _rz(a):
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1.0]])


def _zy(a, b, s=1):
    ca, sa, cb, sb = np.cos(a), np.sin(a), np.cos(b), np.sin(b)
    return np.array([[ca * cb, -sa, ca * sb], [sa * cb, ca, sa * sb], [-s * sb, 0, cb]])


def _jd(v):
    t2 = v.theta_2
    return np.linalg.det(np.array([[v.l_1 * np.sin(t2), 0],
                                   [v.l_1 * np.cos(t2) + v.l_2, v.l_2]]))


ENTRIES = [
    E("2.3", "(2.6)", r"{}^A_B R^T\,{}^A_B R = I_3", True, lambda v: (v.A_B_R.T @ v.A_B_R, I3)),
    E("2.3", "(2.6)", r"{}^A_B R^{-1} = {}^A_B R^T", True,
      lambda v: (np.linalg.inv(v.A_B_R), v.A_B_R.T)),
    E("2.3", "(2.6)", r"{}^A_B R\,{}^A_B R^T = I_4", False,
      lambda v: (v.A_B_R @ v.A_B_R.T, np.eye(4)),
      note="a shape slip: I_4 for I_3"),
    E("2.8", "cf. (2.9)", r"\det\left({}^A_B R\right) = 1", True,
      lambda v: (np.linalg.det(v.A_B_R), 1)),
    E("2.3", "(2.13)", r"\|{}^A_B R\,{}^B P\| = \|{}^B P\|", True,
      lambda v: (np.linalg.norm(v.A_B_R @ v.B_P), np.linalg.norm(v.B_P))),
    E("2.3", "(2.13)", r"\left|{}^A_B R\,{}^B P\right| = \left|{}^B P\right|", True,
      lambda v: (np.linalg.norm(v.A_B_R @ v.B_P), np.linalg.norm(v.B_P)),
      note="Craig's |P|, the magnitude of a vector"),
    E("2.7", "(2.45)", _T, True,
      lambda v: (transform(v.A_B_R, v.A_P_BORG) @ transform(v.A_B_R.T, -v.A_B_R.T @ v.A_P_BORG),
                 np.eye(4))),
    E("2.7", "(2.45)", _T.replace(r"-{}^A_B R^T\,", r"{}^A_B R^T\,"), False,
      lambda v: (transform(v.A_B_R, v.A_P_BORG) @ transform(v.A_B_R.T, v.A_B_R.T @ v.A_P_BORG),
                 np.eye(4))),
    E("2.8", "(2.66)", r"R_{Z'Y'X'}^T R_{Z'Y'X'} = I_3", True,
      lambda v: (v.R_ZpYpXp.T @ v.R_ZpYpXp, I3)),
    E("2.8", "(2.71)", r"\det R_{Z'Y'Z'} = 1", True, lambda v: (np.linalg.det(v.R_ZpYpZp), 1)),
    E("2.8", "(2.64)", _ZY, True, lambda v: (_rz(v.alpha) @ roty(v.beta), _zy(v.alpha, v.beta))),
    E("2.8", "(2.64)", _ZY.replace(r"\sin\alpha\sin\beta\\ -\sin\beta",
                                   r"\sin\alpha\sin\beta\\ \sin\beta"), False,
      lambda v: (_rz(v.alpha) @ roty(v.beta), _zy(v.alpha, v.beta, s=-1))),
    E("2.8", "cf. (2.72)", _RY + "^T = " + _RY + "^{-1}", True,
      lambda v: (roty(v.theta).T, np.linalg.inv(roty(v.theta)))),
    E("2.8", "cf. (2.72)", _RY + " = " + _RY + "^{-1}", False,
      lambda v: (roty(v.theta), np.linalg.inv(roty(v.theta)))),
    E("2.8", "(2.74)", r"\operatorname{Atan2}(\sin\theta, \cos\theta) = \theta", True,
      lambda v: (np.arctan2(np.sin(v.theta), np.cos(v.theta)), v.theta)),
    E("3.6", "(3.8)", r"\cos(\theta_1 + \theta_2) = \cos\theta_1\cos\theta_2 - "
      r"\sin\theta_1\sin\theta_2", True,
      lambda v: (np.cos(v.theta_1 + v.theta_2),
                 np.cos(v.theta_1) * np.cos(v.theta_2) - np.sin(v.theta_1) * np.sin(v.theta_2))),
    E("3.6", "(3.8)", r"\cos(\theta_1 + \theta_2) = \cos\theta_1\cos\theta_2 + "
      r"\sin\theta_1\sin\theta_2", False,
      lambda v: (np.cos(v.theta_1 + v.theta_2),
                 np.cos(v.theta_1) * np.cos(v.theta_2) + np.sin(v.theta_1) * np.sin(v.theta_2))),
    E("5.9", "(5.66)", r"\det\begin{bmatrix}l_1\sin\theta_2 & 0\\ l_1\cos\theta_2 + l_2 & l_2"
      r"\end{bmatrix} = l_1 l_2\sin\theta_2", True,
      lambda v: (_jd(v), v.l_1 * v.l_2 * np.sin(v.theta_2))),
    E("5.9", "(5.66)", r"\det\begin{bmatrix}l_1\sin\theta_2 & 0\\ l_1\cos\theta_2 + l_2 & l_2"
      r"\end{bmatrix} = l_1 l_2\cos\theta_2", False,
      lambda v: (_jd(v), v.l_1 * v.l_2 * np.cos(v.theta_2))),
    E("2.3", "(2.13)", r"\left|{}^A_B R^T\,{}^B P\right| = \left|{}^B P\right|", True,
      lambda v: (np.linalg.norm(v.A_B_R.T @ v.B_P), np.linalg.norm(v.B_P))),
]
