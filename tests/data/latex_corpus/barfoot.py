"""T. D. Barfoot, *State Estimation for Robotics*, Cambridge University Press, 2017 (freely
available). Notation: \\mathbf{C} a rotation, \\mathbf{T} a transform; (\\cdot)^\\wedge the skew
matrix of a 3-vector and the 4x4 of a 6-vector, (\\cdot)^\\vee its inverse; \\exp the matrix
exponential; \\mathbf{1} the identity; ^\\mathsf{T} the transpose (an upright T); \\phi an
angle about the unit axis \\mathbf{a}; \\mathrm{Ad}(\\mathbf{T}) the adjoint."""

import numpy as np
from _num import I3, Ad, E, ddt, expm, hat, vee

BOOK = {"key": "barfoot", "title": "Barfoot, State Estimation for Robotics",
        "edition": "1st ed., Cambridge UP, 2017"}

TABLE = r"""
\mathbf{C}(t): rotation
\mathbf{a}: unit vector
\mathbf{u}: vector
\mathbf{v}: vector
\phi: angle
\mathbf{T}: transform
\mathbf{T}_1: transform
\mathbf{T}_2: transform
\boldsymbol{\xi}: 6-vector
"""


def _ex(v, s=1):
    a = v.a
    return (np.cos(v.phi) * I3 + (1 - np.cos(v.phi)) * a @ a.T + s * np.sin(v.phi) * hat(a))


def _J(v):
    a, p = v.a, v.phi
    return np.sin(p) / p * I3 + (1 - np.sin(p) / p) * a @ a.T + (1 - np.cos(p)) / p * hat(a)


_EXP = (r"\exp(\phi\mathbf{a}^\wedge) = \cos\phi\mathbf{1} + (1 - \cos\phi)\mathbf{a}"
        r"\mathbf{a}^\mathsf{T} + \sin\phi\mathbf{a}^\wedge")

ENTRIES = [
    E("7.1.1", "(7.8)", r"\mathbf{C}^\mathsf{T}\mathbf{C} = \mathbf{1}", True,
      lambda v: (v.C.T @ v.C, I3)),
    E("7.1.1", "(7.9)", r"\det\mathbf{C} = 1", True, lambda v: (np.linalg.det(v.C), 1)),
    E("7.1.2", "(7.13)", r"\mathbf{u}^\wedge\mathbf{v} = -\mathbf{v}^\wedge\mathbf{u}", True,
      lambda v: (hat(v.u) @ v.v, -hat(v.v) @ v.u)),
    E("7.1.2", "(7.13)", r"\mathbf{u}^\wedge\mathbf{v} = \mathbf{v}^\wedge\mathbf{u}", False,
      lambda v: (hat(v.u) @ v.v, hat(v.v) @ v.u)),
    E("7.1.2", "(7.13)", r"\mathbf{u}^\wedge\mathbf{u} = \mathbf{0}", True,
      lambda v: (hat(v.u) @ v.u, np.zeros((3, 1)))),
    E("7.1.2", "(7.13)", r"(\mathbf{u}^\wedge)^\mathsf{T} = -\mathbf{u}^\wedge", True,
      lambda v: (hat(v.u).T, -hat(v.u))),
    E("7.1.2", "(7.14)", r"(\mathbf{C}\mathbf{u})^\wedge = \mathbf{C}\mathbf{u}^\wedge"
      r"\mathbf{C}^\mathsf{T}", True, lambda v: (hat(v.C @ v.u), v.C @ hat(v.u) @ v.C.T)),
    E("7.1.2", "(7.14)", r"(\mathbf{C}\mathbf{u})^\wedge = \mathbf{C}^\mathsf{T}\mathbf{u}^\wedge"
      r"\mathbf{C}", False, lambda v: (hat(v.C @ v.u), v.C.T @ hat(v.u) @ v.C)),
    E("7.1.2", "(7.15)", r"\left(\mathbf{C}^\mathsf{T}\mathbf{u}^\wedge\mathbf{C}\right)^\vee = "
      r"\mathbf{C}^\mathsf{T}\mathbf{u}", True,
      lambda v: (vee(v.C.T @ hat(v.u) @ v.C), v.C.T @ v.u)),
    E("7.1.2", "(7.13)", r"(\mathbf{u}^\wedge)^\vee = \mathbf{u}", True,
      lambda v: (vee(hat(v.u)), v.u)),
    E("7.1.2", "(7.13)", r"\mathbf{u}^\mathsf{T}\mathbf{u}^\wedge = \mathbf{0}^\mathsf{T}", True,
      lambda v: (v.u.T @ hat(v.u), np.zeros((1, 3)))),
    E("7.1.3", "(7.20)", r"\mathbf{a}^\wedge\mathbf{a}^\wedge = \mathbf{a}\mathbf{a}^\mathsf{T} "
      r"- \mathbf{1}", True, lambda v: (hat(v.a) @ hat(v.a), v.a @ v.a.T - I3)),
    E("7.1.3", "(7.20)", r"\mathbf{a}^\wedge\mathbf{a}^\wedge = \mathbf{1} - \mathbf{a}"
      r"\mathbf{a}^\mathsf{T}", False, lambda v: (hat(v.a) @ hat(v.a), I3 - v.a @ v.a.T)),
    E("7.1.3", "(7.21)",
      r"\mathbf{a}^\wedge\mathbf{a}^\wedge\mathbf{a}^\wedge = -\mathbf{a}^\wedge", True,
      lambda v: (hat(v.a) @ hat(v.a) @ hat(v.a), -hat(v.a))),
    E("7.1.3", "(7.19)", _EXP, True, lambda v: (expm(v.phi * hat(v.a)), _ex(v))),
    E("7.1.3", "(7.19)", _EXP.replace(r"+ \sin\phi", r"- \sin\phi"), False,
      lambda v: (expm(v.phi * hat(v.a)), _ex(v, -1))),
    E("7.1.3", "(7.19)", r"\exp(\phi\mathbf{a}^\wedge)\mathbf{a} = \mathbf{a}", True,
      lambda v: (expm(v.phi * hat(v.a)) @ v.a, v.a)),
    E("7.1.3", "(7.23)", r"\mathrm{tr}\left(\exp(\phi\mathbf{a}^\wedge)\right) = 2\cos\phi + 1",
      True, lambda v: (np.trace(expm(v.phi * hat(v.a))), 2 * np.cos(v.phi) + 1)),
    E("7.1.3", "(7.23)", r"\mathrm{tr}\left(\exp(\phi\mathbf{a}^\wedge)\right) = 2\cos\phi - 1",
      False, lambda v: (np.trace(expm(v.phi * hat(v.a))), 2 * np.cos(v.phi) - 1)),
    E("7.1.5", "(7.37)", r"\left(\frac{\sin\phi}{\phi}\mathbf{1} + \left(1 - \frac{\sin\phi}{\phi}"
      r"\right)\mathbf{a}\mathbf{a}^\mathsf{T} + \frac{1 - \cos\phi}{\phi}\mathbf{a}^\wedge\right)"
      r"\mathbf{a} = \mathbf{a}", True, lambda v: (_J(v) @ v.a, v.a)),
    E("7.1.8", "(7.51)", r"\mathbf{T}\boldsymbol{\xi}^\wedge\mathbf{T}^{-1} = \left(\mathrm{Ad}"
      r"(\mathbf{T})\boldsymbol{\xi}\right)^\wedge", True,
      lambda v: (v.T @ hat(v.xi) @ np.linalg.inv(v.T), hat(Ad(v.T) @ v.xi)),
      note="Barfoot orders xi as [rho; phi]; with his Ad the identity is the same"),
    E("7.1.8", "(7.52)", r"\mathrm{Ad}(\mathbf{T}_1\mathbf{T}_2) = \mathrm{Ad}(\mathbf{T}_1)"
      r"\mathrm{Ad}(\mathbf{T}_2)", True,
      lambda v: (Ad(v.T_1 @ v.T_2), Ad(v.T_1) @ Ad(v.T_2))),
    E("7.2.1", "(7.101)", r"\frac{d}{dt}\left(\mathbf{C}^\mathsf{T}\mathbf{C}\right) = "
      r"\dot{\mathbf{C}}^\mathsf{T}\mathbf{C} + \mathbf{C}^\mathsf{T}\dot{\mathbf{C}}", True,
      lambda v: (ddt(v, lambda p: p.C.T @ p.C), v.dot_C.T @ v.C + v.C.T @ v.dot_C),
      note="C(t) declared a function of time"),
    E("7.2.1", "(7.101)", r"\dot{\mathbf{C}}^\mathsf{T}\mathbf{C} + \mathbf{C}^\mathsf{T}"
      r"\dot{\mathbf{C}} = \mathbf{0}", True,
      lambda v: (v.dot_C.T @ v.C + v.C.T @ v.dot_C, np.zeros((3, 3)))),
    E("7.2.1", "(7.101)", r"\dot{\mathbf{C}}^\mathsf{T}\mathbf{C} + \dot{\mathbf{C}}"
      r"\mathbf{C}^\mathsf{T} = \mathbf{0}", False,
      lambda v: (v.dot_C.T @ v.C + v.dot_C @ v.C.T, np.zeros((3, 3)))),
]

_ = (ddt,)
