"""R. M. Murray, Z. Li, S. S. Sastry, *A Mathematical Introduction to Robotic Manipulation*,
CRC Press, 1994 (freely available). Notation: \\hat\\omega is the skew-symmetric matrix of
\\omega (not a unit vector as in Lynch-Park); (\\cdot)^\\wedge and (\\cdot)^\\vee the hat and
its inverse; g a rigid motion (a 4x4 homogeneous transform); Ad_g; \\xi a twist [v; \\omega]."""

import numpy as np
from _num import I3, Ad, E, expm, hat, vee

BOOK = {"key": "murray-li-sastry", "title": "Murray, Li & Sastry, A Mathematical "
        "Introduction to Robotic Manipulation", "edition": "CRC Press, 1994"}

TABLE = r"""
R: rotation
\omega: unit vector
\theta: angle
a: vector
b: vector
x: vector
g: transform
g_1: transform
g_2: transform
\xi: twist
\hat\xi: se(3)
"""

# MLS's \hat\omega is hat(omega): a reading of the book's notation, not a
# kind; entries that need it say so in their note.
_MLS = "needs MLS's reading of \\hat\\omega as the skew matrix of \\omega"


def _rod(v, s=1, sq=1):
    w = hat(v.omega)
    return I3 + s * w * np.sin(v.theta) + sq * w @ w * (1 - np.cos(v.theta))


ENTRIES = [
    E("2.2", "(2.14)",
      r"e^{\hat\omega\theta} = I + \hat\omega\sin\theta + \hat\omega^2(1 - \cos\theta)", True,
      lambda v: (expm(hat(v.omega) * v.theta), _rod(v)), note=_MLS),
    E("2.2", "(2.14)",
      r"e^{\hat\omega\theta} = I + \hat\omega\sin\theta - \hat\omega^2(1 - \cos\theta)", False,
      lambda v: (expm(hat(v.omega) * v.theta), _rod(v, sq=-1)), note=_MLS),
    E("2.2", "(2.9)", r"\hat\omega^3 = -\hat\omega", True,
      lambda v: (np.linalg.matrix_power(hat(v.omega), 3), -hat(v.omega)), note=_MLS),
    E("2.2", "(2.6)", r"\hat\xi^T = -\hat\xi", False,
      lambda v: (v.hat_xi.T, -v.hat_xi), note="an se(3) matrix is not skew (a slip of so(3)'s)"),
    E("2.2", "Lemma 2.3", r"R\omega^\wedge R^T = (R\omega)^\wedge", True,
      lambda v: (v.R @ hat(v.omega) @ v.R.T, hat(v.R @ v.omega))),
    E("2.2", "Lemma 2.3", r"R^T\omega^\wedge R = (R\omega)^\wedge", False,
      lambda v: (v.R.T @ hat(v.omega) @ v.R, hat(v.R @ v.omega))),
    E("2.2", "Lemma 2.3", r"\left(R a^\wedge R^T\right)^\vee = R a", True,
      lambda v: (vee(v.R @ hat(v.a) @ v.R.T), v.R @ v.a)),
    E("2.2", "(2.5)", r"a^\wedge b = a \times b", True,
      lambda v: (hat(v.a) @ v.b, np.cross(v.a.ravel(), v.b.ravel()).reshape(3, 1))),
    E("2.2", "(2.5)", r"a^\wedge b = b \times a", False,
      lambda v: (hat(v.a) @ v.b, np.cross(v.b.ravel(), v.a.ravel()).reshape(3, 1))),
    E("2.2", "(2.5)", r"(a^\wedge)^T = -a^\wedge", True,
      lambda v: (hat(v.a).T, -hat(v.a))),
    E("2.2", "(2.2)", r"\det R = +1", True, lambda v: (np.linalg.det(v.R), 1)),
    E("2.2", "(2.2)", r"R R^T = I", True, lambda v: (v.R @ v.R.T, I3)),
    E("2.2", "(2.3)", r"\|R x\| = \|x\|", True,
      lambda v: (np.linalg.norm(v.R @ v.x), np.linalg.norm(v.x))),
    E("2.2", "(2.3)", r"\|R x\| = \|x\|^2", False,
      lambda v: (np.linalg.norm(v.R @ v.x), np.linalg.norm(v.x) ** 2)),
    E("2.3", "(2.58)", r"\mathrm{Ad}_g^{-1} = \mathrm{Ad}_{g^{-1}}", True,
      lambda v: (np.linalg.inv(Ad(v.g)), Ad(np.linalg.inv(v.g)))),
    E("2.3", "(2.58)", r"\mathrm{Ad}_{g_1 g_2} = \mathrm{Ad}_{g_1}\mathrm{Ad}_{g_2}", True,
      lambda v: (Ad(v.g_1 @ v.g_2), Ad(v.g_1) @ Ad(v.g_2))),
    E("2.3", "(2.58)", r"\mathrm{Ad}_{g_1 g_2} = \mathrm{Ad}_{g_2}\mathrm{Ad}_{g_1}", False,
      lambda v: (Ad(v.g_1 @ v.g_2), Ad(v.g_2) @ Ad(v.g_1))),
    E("2.3", "(2.57)", r"g\xi^\wedge g^{-1} = (\mathrm{Ad}_g\xi)^\wedge", True,
      lambda v: (v.g @ hat(v.xi) @ np.linalg.inv(v.g), hat(Ad(v.g) @ v.xi))),
    E("2.3", "(2.57)", r"\left(g\xi^\wedge g^{-1}\right)^\vee = \mathrm{Ad}_g\xi", True,
      lambda v: (vee(v.g @ hat(v.xi) @ np.linalg.inv(v.g)), Ad(v.g) @ v.xi)),
    E("2.3", "(2.57)", r"\left(g^{-1}\xi^\wedge g\right)^\vee = \mathrm{Ad}_g\xi", False,
      lambda v: (vee(np.linalg.inv(v.g) @ hat(v.xi) @ v.g), Ad(v.g) @ v.xi)),
    E("2.2", "(2.10)", r"\det R = 1, \quad R \in SO(3)", True,
      lambda v: (np.linalg.det(v.R), 1), note="a trailing declaration"),
]
