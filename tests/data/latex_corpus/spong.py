"""M. W. Spong, S. Hutchinson, M. Vidyasagar, *Robot Modeling and Control*, Wiley, 2006.
Notation: plain italic vectors and matrices; R_{z,\\theta} the basic rotation (its axis and
angle in the subscript, part of the name); c_i, s_i, c_{12} for cos and sin of joint
angles; H a homogeneous transform; I the identity (I_4 sized); \\dot\\theta a joint rate."""

import numpy as np
from _num import I3, E, cross, ddt, hat, rotz, transform

BOOK = {"key": "spong", "title": "Spong, Hutchinson & Vidyasagar, Robot Modeling and "
        "Control", "edition": "1st ed., Wiley, 2006"}

TABLE = r"""
R_{z,\theta}: rotation
R_{x,\phi}: rotation
R: rotation
\phi: angle
\theta_1: angle
\theta_2: angle
\theta(t): angle
a_1: scalar
a_2: scalar
a: vector
b: vector
d: vector
I_{xx}: scalar
I_{yy}: scalar
I_{zz}: scalar
"""


def _law(v, s=1):
    t1, t2 = v.theta_1, v.theta_2
    x = v.a_1 * np.cos(t1) + v.a_2 * np.cos(t1 + t2)
    y = v.a_1 * np.sin(t1) + v.a_2 * np.sin(t1 + t2)
    return x * x + y * y, v.a_1 ** 2 + v.a_2 ** 2 + s * 2 * v.a_1 * v.a_2 * np.cos(t2)


def _jdet(v):
    t1, t2 = v.theta_1, v.theta_2
    s1, c1, s12, c12 = np.sin(t1), np.cos(t1), np.sin(t1 + t2), np.cos(t1 + t2)
    return np.linalg.det(np.array([[-v.a_1 * s1 - v.a_2 * s12, -v.a_2 * s12],
                                   [v.a_1 * c1 + v.a_2 * c12, v.a_2 * c12]]))


def _H(v, s=-1, tr=True):
    Ri = v.R.T if tr else v.R
    return transform(v.R, v.d) @ transform(v.R.T, s * Ri @ v.d)


def _dg(v):
    return np.diag([v.I_xx, v.I_yy, v.I_zz])



_ROTZ = (r"\begin{bmatrix}\cos\theta & -\sin\theta & 0\\ \sin\theta & \cos\theta & 0\\ "
         r"0 & 0 & 1\end{bmatrix}\begin{bmatrix}\cos\phi & -\sin\phi & 0\\ \sin\phi & "
         r"\cos\phi & 0\\ 0 & 0 & 1\end{bmatrix} = \begin{bmatrix}\cos(\theta + \phi) & "
         r"-\sin(\theta + \phi) & 0\\ \sin(\theta + \phi) & \cos(\theta + \phi) & 0\\ 0 & 0 & 1"
         r"\end{bmatrix}")
_LAW = (r"(a_1\cos\theta_1 + a_2\cos(\theta_1 + \theta_2))^2 + (a_1\sin\theta_1 + "
        r"a_2\sin(\theta_1 + \theta_2))^2 = a_1^2 + a_2^2 + 2a_1a_2\cos\theta_2")
_JAC = (r"\det\begin{bmatrix}-a_1\sin\theta_1 - a_2\sin(\theta_1 + \theta_2) & "
        r"-a_2\sin(\theta_1 + \theta_2)\\ a_1\cos\theta_1 + a_2\cos(\theta_1 + \theta_2) & "
        r"a_2\cos(\theta_1 + \theta_2)\end{bmatrix} = a_1a_2\sin\theta_2")
_HINV = (r"\begin{bmatrix}R & d\\ 0 & 1\end{bmatrix}\begin{bmatrix}R^T & -R^T d\\ 0 & 1"
         r"\end{bmatrix} = I_4")

ENTRIES = [
    E("2.2", "(2.6)", r"R_{z,\theta}^T R_{z,\theta} = I", True,
      lambda v: (v.R_z_theta.T @ v.R_z_theta, I3)),
    E("2.2", "(2.7)", r"\det R_{x,\phi} = 1", True, lambda v: (np.linalg.det(v.R_x_phi), 1)),
    E("2.2", "(2.6)", r"R_{z,\theta}^{-1} = R_{z,\theta}", False,
      lambda v: (np.linalg.inv(v.R_z_theta), v.R_z_theta)),
    E("2.3.1", "(2.9)", r"R_{x,\phi}^{-1} = R_{x,\phi}^T", True,
      lambda v: (np.linalg.inv(v.R_x_phi), v.R_x_phi.T)),
    E("2.4", "cf. (2.15)", _ROTZ, True,
      lambda v: (rotz(v.theta) @ rotz(v.phi), rotz(v.theta + v.phi))),
    E("2.4", "cf. (2.15)", _ROTZ.replace(r"\\ \sin\phi & \cos\phi", r"\\ -\sin\phi & \cos\phi"),
      False, lambda v: (rotz(v.theta) @ np.array([[np.cos(v.phi), -np.sin(v.phi), 0],
                                                    [-np.sin(v.phi), np.cos(v.phi), 0],
                                                    [0, 0, 1]]), rotz(v.theta + v.phi))),
    E("3.3.1", "cf. (3.39)", _LAW, True, lambda v: _law(v)),
    E("3.3.1", "cf. (3.39)", _LAW.replace("+ 2a_1", "- 2a_1"), False,
      lambda v: _law(v, s=-1)),
    E("3.3.1", "cf. (3.39)",
      r"(a_1c_1 + a_2c_{12})^2 + (a_1s_1 + a_2s_{12})^2 = a_1^2 + a_2^2 + 2a_1a_2c_2", True,
      lambda v: _law(v), note="needs Spong's reading of c_1, s_{12} as cos, sin"),
    E("4.10", "cf. (4.92)", _JAC, True, lambda v: (_jdet(v), v.a_1 * v.a_2 * np.sin(v.theta_2))),
    E("4.10", "cf. (4.92)", _JAC.replace(r"= a_1a_2\sin\theta_2", r"= a_1a_2\cos\theta_2"),
      False, lambda v: (_jdet(v), v.a_1 * v.a_2 * np.cos(v.theta_2))),
    E("2.7", "(2.66)", _HINV, True, lambda v: (_H(v), np.eye(4))),
    E("2.7", "(2.66)", _HINV.replace("-R^T d", "-R d"), False,
      lambda v: (_H(v, tr=False), np.eye(4))),
    E("4.1", "(4.5)",
      r"\frac{d}{d\theta}\begin{bmatrix}\cos\theta & -\sin\theta\\ \sin\theta & \cos\theta"
      r"\end{bmatrix} = \begin{bmatrix}0 & -1\\ 1 & 0\end{bmatrix}\begin{bmatrix}\cos\theta & "
      r"-\sin\theta\\ \sin\theta & \cos\theta\end{bmatrix}", True,
      lambda v: (np.array([[-np.sin(v.theta), -np.cos(v.theta)],
                           [np.cos(v.theta), -np.sin(v.theta)]]),
                 np.array([[0, -1], [1, 0]]) @ rotz(v.theta)[:2, :2])),
    E("4.2", "cf. (4.18)", r"\frac{d}{dt}\cos\theta = -\dot\theta\sin\theta", True,
      lambda v: (ddt(v, lambda p: np.cos(p.theta)), -v.dot_theta * np.sin(v.theta))),
    E("4.2", "cf. (4.18)", r"\frac{d}{dt}\sin\theta = -\dot\theta\cos\theta", False,
      lambda v: (ddt(v, lambda p: np.sin(p.theta)), -v.dot_theta * np.cos(v.theta))),
    E("4.1", "(4.4)", r"R(a \times b) = Ra \times Rb", True,
      lambda v: (v.R @ cross(v.a, v.b), cross(v.R @ v.a, v.R @ v.b))),
    E("4.1", "(4.4)", r"R(a \times b) = Rb \times Ra", False,
      lambda v: (v.R @ cross(v.a, v.b), cross(v.R @ v.b, v.R @ v.a))),
    E("7.2", "(7.44)",
      r"\operatorname{tr}\left(R\operatorname{diag}(I_{xx}, I_{yy}, I_{zz})R^T\right) = "
      r"I_{xx} + I_{yy} + I_{zz}", True,
      lambda v: (np.trace(v.R @ _dg(v) @ v.R.T), v.I_xx + v.I_yy + v.I_zz)),
    E("7.2", "(7.44)",
      r"\det\operatorname{diag}(I_{xx}, I_{yy}, I_{zz}) = I_{xx}I_{yy}I_{zz}", True,
      lambda v: (np.linalg.det(_dg(v)), v.I_xx * v.I_yy * v.I_zz)),
    E("3.3", "cf. (3.22)", r"\sec^2\theta = 1 + \tan^2\theta", True,
      lambda v: (1 / np.cos(v.theta) ** 2, 1 + np.tan(v.theta) ** 2)),
    E("3.3", "cf. (3.22)", r"\sec^2\theta = 1 - \tan^2\theta", False,
      lambda v: (1 / np.cos(v.theta) ** 2, 1 - np.tan(v.theta) ** 2)),
    E("3.3", "cf. (3.22)", r"\csc^2\theta = 1 + \cot^2\theta", True,
      lambda v: (1 / np.sin(v.theta) ** 2, 1 + 1 / np.tan(v.theta) ** 2)),
    E("3.3", "cf. (3.22)", r"\cos^2\theta + \sin^2\theta = 1 \quad \forall \theta", True,
      lambda v: (np.cos(v.theta) ** 2 + np.sin(v.theta) ** 2, 1),
      note="a trailing declaration"),
    E("3.3", "cf. (3.22)", r"\csc\theta\,\sin\theta = \cos\theta\,\sec\theta", True,
      lambda v: (np.sin(v.theta) / np.sin(v.theta), np.cos(v.theta) / np.cos(v.theta))),
]

_ = (hat,)
