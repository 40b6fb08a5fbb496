"""J. Solà, J. Deray, D. Atchuthan, *A micro Lie theory for state estimation in robotics*,
arXiv:1812.01537 (v9, 2021; freely available). Notation: bold upright \\mathbf{R}, \\mathbf{M};
^\\top the transpose; [\\cdot]_\\times the skew matrix; (\\cdot)^\\wedge, (\\cdot)^\\vee the hat
and vee; \\exp the matrix exponential; \\mathbf{Ad}_{\\mathcal{X}} the adjoint matrix;
\\mathbf{I} the identity; \\theta an angle about the unit axis \\mathbf{u}."""

import numpy as np
from _num import I3, Ad, E, cross, expm, hat, vee

BOOK = {"key": "sola", "title": "Solà, Deray & Atchuthan, A micro Lie theory",
        "edition": "arXiv:1812.01537v9, 2021"}

TABLE = r"""
\mathbf{R}: rotation
\mathbf{u}: unit vector
\theta: angle
\mathbf{a}: vector
\mathbf{b}: vector
\boldsymbol{\omega}: vector
\mathbf{M}: transform
\mathbf{M}_1: transform
\mathbf{M}_2: transform
\boldsymbol{\tau}: 6-vector
"""


def _rod(v, sq=2):
    k = hat(v.u)
    return I3 + np.sin(v.theta) * k + (1 - np.cos(v.theta)) * np.linalg.matrix_power(k, sq)



_ROD = (r"\exp(\theta[\mathbf{u}]_\times) = \mathbf{I} + \sin\theta[\mathbf{u}]_\times + "
        r"(1 - \cos\theta)[\mathbf{u}]_\times^2")

ENTRIES = [
    E("A.1", "(105)", r"\mathbf{R}^\top\mathbf{R} = \mathbf{I}", True,
      lambda v: (v.R.T @ v.R, I3)),
    E("A.1", "(105)", r"\mathbf{R}^\top\mathbf{R} = \mathbf{I} = \mathbf{R}\mathbf{R}^\top", True,
      lambda v: (v.R.T @ v.R, v.R @ v.R.T)),
    E("A.1", "(109)", r"[\mathbf{a}]_\times\mathbf{b} = \mathbf{a}\times\mathbf{b}", True,
      lambda v: (hat(v.a) @ v.b, cross(v.a, v.b))),
    E("A.1", "(109)", r"[\mathbf{a}]_\times\mathbf{b} = \mathbf{b}\times\mathbf{a}", False,
      lambda v: (hat(v.a) @ v.b, cross(v.b, v.a))),
    E("A.1", "(108)", r"[\mathbf{a}]_\times^\top = -[\mathbf{a}]_\times", True,
      lambda v: (hat(v.a).T, -hat(v.a))),
    E("A.1", "(108)", r"\mathbf{a}^\wedge = [\mathbf{a}]_\times", True,
      lambda v: (hat(v.a), hat(v.a))),
    E("A.1", "(108)", r"\left([\mathbf{a}]_\times\right)^\vee = \mathbf{a}", True,
      lambda v: (vee(hat(v.a)), v.a)),
    E("A.1", "(108)", r"(\theta\mathbf{u})^\wedge = \theta[\mathbf{u}]_\times", True,
      lambda v: (hat(v.theta * v.u), v.theta * hat(v.u))),
    E("A.1", "(112)", _ROD, True, lambda v: (expm(v.theta * hat(v.u)), _rod(v))),
    E("A.1", "(112)", _ROD.replace(r"[\mathbf{u}]_\times^2", r"[\mathbf{u}]_\times"), False,
      lambda v: (expm(v.theta * hat(v.u)), _rod(v, sq=1))),
    E("A.1", "(112)", r"\exp(\theta[\mathbf{u}]_\times)\mathbf{u} = \mathbf{u}", True,
      lambda v: (expm(v.theta * hat(v.u)) @ v.u, v.u)),
    E("A.1", "cf. (114)", r"\operatorname{tr}(\exp(\theta[\mathbf{u}]_\times)) = 1 + 2\cos\theta",
      True, lambda v: (np.trace(expm(v.theta * hat(v.u))), 1 + 2 * np.cos(v.theta))),
    E("A.1", "(117)", r"\mathbf{R}[\boldsymbol{\omega}]_\times\mathbf{R}^\top = "
      r"[\mathbf{R}\boldsymbol{\omega}]_\times", True,
      lambda v: (v.R @ hat(v.omega) @ v.R.T, hat(v.R @ v.omega))),
    E("A.1", "(117)", r"\mathbf{R}^\top[\boldsymbol{\omega}]_\times\mathbf{R} = "
      r"[\mathbf{R}\boldsymbol{\omega}]_\times", False,
      lambda v: (v.R.T @ hat(v.omega) @ v.R, hat(v.R @ v.omega))),
    E("3.1", "(30)", r"\mathbf{M}\boldsymbol{\tau}^\wedge\mathbf{M}^{-1} = "
      r"(\mathbf{Ad}_{\mathbf{M}}\boldsymbol{\tau})^\wedge", True,
      lambda v: (v.M @ hat(v.tau) @ np.linalg.inv(v.M), hat(Ad(v.M) @ v.tau)),
      note="Solà orders tau as [rho; theta]; with his Ad the identity is the same"),
    E("3.1", "(32)", r"\mathbf{Ad}_{\mathbf{M}_1\mathbf{M}_2} = \mathbf{Ad}_{\mathbf{M}_1}"
      r"\mathbf{Ad}_{\mathbf{M}_2}", True,
      lambda v: (Ad(v.M_1 @ v.M_2), Ad(v.M_1) @ Ad(v.M_2))),
    E("3.1", "(32)", r"\mathbf{Ad}_{\mathbf{M}^{-1}} = \mathbf{Ad}_{\mathbf{M}}^\top", False,
      lambda v: (Ad(np.linalg.inv(v.M)), Ad(v.M).T),
      note="true on SO(3) (Ad_R = R), not on SE(3)"),
    E("3.1", "(32)", r"\mathbf{Ad}_{\mathbf{M}^{-1}} = \mathbf{Ad}_{\mathbf{M}}^{-1}", True,
      lambda v: (Ad(np.linalg.inv(v.M)), np.linalg.inv(Ad(v.M)))),
]
