"""P. Corke, *Robotics, Vision and Control*, 2nd ed., Springer, 2017. Notation: a leading
superscript names the reference frame and a trailing subscript the frame described
({}^A\\mathbf{R}_B, {}^A\\boldsymbol{p}); ^\\top the transpose; [\\cdot]_\\times the skew matrix;
\\mathbf{1} the identity (\\mathbf{1}_{3\\times 3} sized); \\vec{} for a coordinate vector in the
early chapters."""

import numpy as np
from _num import I3, E, cross, expm, hat, transform

BOOK = {"key": "corke", "title": "Corke, Robotics, Vision and Control",
        "edition": "2nd ed., Springer, 2017"}

TABLE = r"""
{}^A\mathbf{R}_B: rotation
{}^B\boldsymbol{p}: vector
\mathbf{R}: rotation
\hat{\boldsymbol{v}}: unit vector
\theta: angle
\boldsymbol{\omega}: vector
\boldsymbol{v}: vector
\boldsymbol{t}: vector
\vec{a}: vector
\vec{b}: vector
"""


def _rod(v, s=1):
    k = hat(v.hat_v)
    return I3 + s * np.sin(v.theta) * k + (1 - np.cos(v.theta)) * k @ k



_TINV = (r"\begin{pmatrix}\mathbf{R} & \boldsymbol{t}\\ \mathbf{0}_{1\times 3} & 1\end{pmatrix}"
         r"^{-1} = \begin{pmatrix}\mathbf{R}^\top & -\mathbf{R}^\top\boldsymbol{t}\\ "
         r"\mathbf{0}_{1\times 3} & 1\end{pmatrix}")
_ROD = (r"e^{\theta[\hat{\boldsymbol{v}}]_\times} = \mathbf{1}_{3\times 3} + \sin\theta"
        r"[\hat{\boldsymbol{v}}]_\times + (1 - \cos\theta)[\hat{\boldsymbol{v}}]_\times^2")

ENTRIES = [
    E("2.2.1.1", "(2.13)", r"({}^A\mathbf{R}_B)^\top\,{}^A\mathbf{R}_B = \mathbf{1}", True,
      lambda v: (v.A_R_B.T @ v.A_R_B, I3)),
    E("2.2.1.1", "(2.14)", r"({}^A\mathbf{R}_B)^{-1} = ({}^A\mathbf{R}_B)^\top", True,
      lambda v: (np.linalg.inv(v.A_R_B), v.A_R_B.T)),
    E("2.2.1.1", "(2.14)", r"({}^A\mathbf{R}_B)^{-1} = -({}^A\mathbf{R}_B)^\top", False,
      lambda v: (np.linalg.inv(v.A_R_B), -v.A_R_B.T)),
    E("2.2.1.1", "(2.13)", r"\det({}^A\mathbf{R}_B) = +1", True,
      lambda v: (np.linalg.det(v.A_R_B), 1)),
    E("2.2.1.1", "cf. (2.16)",
      r"\left\|{}^A\mathbf{R}_B\,{}^B\boldsymbol{p}\right\| = \left\|{}^B\boldsymbol{p}\right\|",
      True, lambda v: (np.linalg.norm(v.A_R_B @ v.B_p), np.linalg.norm(v.B_p))),
    E("2.2.1.1", "cf. (2.16)",
      r"\left\|{}^A\mathbf{R}_B\,{}^B\boldsymbol{p}\right\| = \left\|{}^B\boldsymbol{p}\right\|^2",
      False, lambda v: (np.linalg.norm(v.A_R_B @ v.B_p), np.linalg.norm(v.B_p) ** 2)),
    E("2.2.1.1", "(2.17)", r"(\mathbf{R}\boldsymbol{v})^\top = \boldsymbol{v}^\top\mathbf{R}^\top",
      True, lambda v: ((v.R @ v.v).T, v.v.T @ v.R.T)),
    E("2.2.1.1", "(2.17)", r"(\mathbf{R}\boldsymbol{v})^\top = \mathbf{R}^\top\boldsymbol{v}^\top",
      False, lambda v: ((v.R @ v.v).T, v.R.T @ v.v.T), note="a shape slip: 3x3 times 1x3"),
    E("2.2.1.7", "(2.22)", r"[\boldsymbol{\omega}]_\times\boldsymbol{v} = \boldsymbol{\omega}"
      r"\times\boldsymbol{v}", True, lambda v: (hat(v.omega) @ v.v, cross(v.omega, v.v))),
    E("2.2.1.7", "(2.22)", r"[\boldsymbol{\omega}]_\times^\top = -[\boldsymbol{\omega}]_\times",
      True, lambda v: (hat(v.omega).T, -hat(v.omega))),
    E("2.2.1.7", "(2.23)", _ROD, True, lambda v: (expm(v.theta * hat(v.hat_v)), _rod(v))),
    E("2.2.1.7", "(2.23)", _ROD.replace(r"+ \sin", r"- \sin"), False,
      lambda v: (expm(v.theta * hat(v.hat_v)), _rod(v, -1))),
    E("2.2.1.7", "cf. (2.23)",
      r"\mathrm{tr}\left(e^{\theta[\hat{\boldsymbol{v}}]_\times}\right) = 1 + 2\cos\theta", True,
      lambda v: (np.trace(expm(v.theta * hat(v.hat_v))), 1 + 2 * np.cos(v.theta))),
    E("2.2.2", "(2.25)", _TINV, True,
      lambda v: (np.linalg.inv(transform(v.R, v.t)), transform(v.R.T, -v.R.T @ v.t))),
    E("2.2.2", "(2.25)", _TINV.replace(r"-\mathbf{R}^\top\boldsymbol{t}", r"-\mathbf{R}"
                                       r"\boldsymbol{t}"), False,
      lambda v: (np.linalg.inv(transform(v.R, v.t)), transform(v.R.T, -v.R @ v.t))),
    E("2.1.1", "(2.1)", r"\vec{a}\times\vec{b} = -\vec{b}\times\vec{a}", True,
      lambda v: (cross(v.a, v.b), -cross(v.b, v.a))),
    E("2.1.1", "(2.1)", r"\vec{a}\cdot(\vec{a}\times\vec{b}) = 0", True,
      lambda v: (v.a.T @ cross(v.a, v.b), 0)),
    E("2.2.1.1", "(2.13)", r"\mathbf{R}^\top\mathbf{R} = \mathbf{1}, \quad \mathbf{R} \in SO(3)",
      True, lambda v: (v.R.T @ v.R, I3), note="a trailing declaration"),
]
