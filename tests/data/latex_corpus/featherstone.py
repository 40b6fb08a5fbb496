"""R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer, 2008. Notation: spatial
(6D) motion and force vectors in bold (\\boldsymbol{v}, \\boldsymbol{m}, \\boldsymbol{f});
{}^B X_A the Plücker transform of motion vectors from A to B, {}^B X_A^* = {}^B X_A^{-T} its
dual for forces; \\boldsymbol{v}\\times and \\boldsymbol{v}\\times^* the spatial cross products
(crm, crf); \\boldsymbol{r}\\times the 3x3 cross-product matrix; \\boldsymbol{E} a rotation;
\\underline{} a coordinate vector; \\boldsymbol{1}, \\boldsymbol{0} identity and zero."""

import numpy as np
from _num import E, crf, crm, hat, plucker

BOOK = {"key": "featherstone", "title": "Featherstone, Rigid Body Dynamics Algorithms",
        "edition": "Springer, 2008"}

TABLE = r"""
{}^B X_A: spatial transform
{}^C X_B: spatial transform
\boldsymbol{v}: 6-vector
\boldsymbol{m}: 6-vector
\boldsymbol{f}: 6-vector
\underline{\boldsymbol{m}}: 6-vector
\underline{\boldsymbol{f}}: 6-vector
\boldsymbol{E}: rotation
\boldsymbol{r}: vector
\boldsymbol{\omega}: vector
\boldsymbol{v}_O: vector
"""


def _X(v):
    return v.B_X_A


def _Xs(v):
    return np.linalg.inv(v.B_X_A).T


def _dot(a, b):
    return (a.T @ b).item()


def _pinv(v, s=1):
    out = np.zeros((6, 6))
    Et = v.E.T
    out[:3, :3], out[3:, 3:], out[3:, :3] = Et, Et, s * hat(v.r) @ Et
    return out


def _blk(v, swap=False):
    w, vo = (v.v_O, v.omega) if swap else (v.omega, v.v_O)
    out = np.zeros((6, 6))
    out[:3, :3], out[3:, 3:], out[3:, :3] = hat(w), hat(w), hat(vo)
    return out


_PL = (r"\begin{bmatrix}\boldsymbol{E} & \boldsymbol{0}\\ -\boldsymbol{E}\boldsymbol{r}\times"
       r" & \boldsymbol{E}\end{bmatrix}^{-1} = \begin{bmatrix}\boldsymbol{E}^T & \boldsymbol{0}"
       r"\\ \boldsymbol{r}\times\boldsymbol{E}^T & \boldsymbol{E}^T\end{bmatrix}")
_CRM = (r"\begin{bmatrix}\boldsymbol{\omega}\\ \boldsymbol{v}_O\end{bmatrix}\times\boldsymbol{m}"
        r" = \begin{bmatrix}\boldsymbol{\omega}\times & \boldsymbol{0}\\ \boldsymbol{v}_O\times"
        r" & \boldsymbol{\omega}\times\end{bmatrix}\boldsymbol{m}")

ENTRIES = [
    E("2.8", "(2.29)", r"{}^B X_A^{*} = {}^B X_A^{-T}", True, lambda v: (_Xs(v), _Xs(v))),
    E("2.8", "(2.29)", r"{}^B X_A^{*} = {}^B X_A^{T}", False, lambda v: (_Xs(v), _X(v).T)),
    E("2.8", "(2.29)", r"({}^B X_A^{*})^T\,{}^B X_A = \boldsymbol{1}", True,
      lambda v: (_Xs(v).T @ _X(v), np.eye(6))),
    E("2.8", "(2.29)", r"({}^B X_A^{*})^T\,{}^B X_A^{*} = \boldsymbol{1}", False,
      lambda v: (_Xs(v).T @ _Xs(v), np.eye(6))),
    E("2.8", "(2.24)", _PL, True, lambda v: (np.linalg.inv(plucker(v.E, v.r)), _pinv(v))),
    E("2.8", "(2.24)", _PL.replace(r"\\ \boldsymbol{r}\times", r"\\ -\boldsymbol{r}\times"),
      False, lambda v: (np.linalg.inv(plucker(v.E, v.r)), _pinv(v, -1))),
    E("2.9", "(2.31)", _CRM, True, lambda v: (crm(np.vstack([v.omega, v.v_O])) @ v.m,
                                             _blk(v) @ v.m)),
    E("2.9", "(2.31)", _CRM.replace(r"\\ \boldsymbol{v}_O\times & \boldsymbol{\omega}\times",
                                    r"\\ \boldsymbol{\omega}\times & \boldsymbol{v}_O\times"),
      False, lambda v: (crm(np.vstack([v.omega, v.v_O])) @ v.m,
                        np.block([[hat(v.omega), np.zeros((3, 3))],
                                  [hat(v.omega), hat(v.v_O)]]) @ v.m)),
    E("2.9", "(2.32)", r"\boldsymbol{v}\times\boldsymbol{m} = -\boldsymbol{m}\times\boldsymbol{v}",
      True, lambda v: (crm(v.v) @ v.m, -crm(v.m) @ v.v)),
    E("2.9", "(2.32)", r"\boldsymbol{v}\times\boldsymbol{v} = \boldsymbol{0}", True,
      lambda v: (crm(v.v) @ v.v, np.zeros((6, 1)))),
    E("2.9", "(2.33)", r"\boldsymbol{v}\times^*\boldsymbol{f} = -(\boldsymbol{v}\times)^T"
      r"\boldsymbol{f}", True, lambda v: (crf(v.v) @ v.f, -crm(v.v).T @ v.f)),
    E("2.9", "(2.33)", r"\boldsymbol{v}\times^*\boldsymbol{f} = (\boldsymbol{v}\times)^T"
      r"\boldsymbol{f}", False, lambda v: (crf(v.v) @ v.f, crm(v.v).T @ v.f)),
    E("2.9", "(2.33)", r"\boldsymbol{v}\times^* = -(\boldsymbol{v}\times)^T", True,
      lambda v: (crf(v.v), -crm(v.v).T)),
    E("2.9", "(2.34)", r"\boldsymbol{m}\cdot(\boldsymbol{v}\times^*\boldsymbol{f}) = "
      r"-(\boldsymbol{v}\times\boldsymbol{m})\cdot\boldsymbol{f}", True,
      lambda v: (_dot(v.m, crf(v.v) @ v.f), -_dot(crm(v.v) @ v.m, v.f))),
    E("2.9", "(2.34)", r"\boldsymbol{v}\cdot(\boldsymbol{v}\times^*\boldsymbol{f}) = 0", True,
      lambda v: (_dot(v.v, crf(v.v) @ v.f), 0)),
    E("2.9", "(2.34)", r"\boldsymbol{f}\cdot(\boldsymbol{v}\times^*\boldsymbol{f}) = 0", False,
      lambda v: (_dot(v.f, crf(v.v) @ v.f), 0)),
    E("2.9", "(2.35)", r"{}^B X_A(\boldsymbol{v}\times\boldsymbol{m}) = ({}^B X_A\boldsymbol{v})"
      r"\times({}^B X_A\boldsymbol{m})", True,
      lambda v: (_X(v) @ crm(v.v) @ v.m, crm(_X(v) @ v.v) @ _X(v) @ v.m)),
    E("2.9", "(2.35)", r"{}^B X_A(\boldsymbol{v}\times\boldsymbol{m}) = ({}^B X_A\boldsymbol{v})"
      r"\times({}^B X_A^{*}\boldsymbol{m})", False,
      lambda v: (_X(v) @ crm(v.v) @ v.m, crm(_X(v) @ v.v) @ _Xs(v) @ v.m)),
    E("2.9", "(2.35)", r"{}^B X_A^{*}(\boldsymbol{v}\times^*\boldsymbol{f}) = ({}^B X_A"
      r"\boldsymbol{v})\times^*({}^B X_A^{*}\boldsymbol{f})", True,
      lambda v: (_Xs(v) @ crf(v.v) @ v.f, crf(_X(v) @ v.v) @ _Xs(v) @ v.f)),
    E("2.6", "(2.19)", r"({}^B X_A\boldsymbol{m})\cdot({}^B X_A^{*}\boldsymbol{f}) = "
      r"\boldsymbol{m}\cdot\boldsymbol{f}", True,
      lambda v: (_dot(_X(v) @ v.m, _Xs(v) @ v.f), _dot(v.m, v.f))),
    E("2.6", "(2.19)", r"({}^B X_A\boldsymbol{m})\cdot({}^B X_A\boldsymbol{f}) = "
      r"\boldsymbol{m}\cdot\boldsymbol{f}", False,
      lambda v: (_dot(_X(v) @ v.m, _X(v) @ v.f), _dot(v.m, v.f))),
    E("2.6", "(2.19)", r"({}^B X_A\underline{\boldsymbol{m}})^T{}^B X_A^{*}"
      r"\underline{\boldsymbol{f}} = \underline{\boldsymbol{m}}^T\underline{\boldsymbol{f}}",
      True, lambda v: ((_X(v) @ v.m).T @ _Xs(v) @ v.f, v.m.T @ v.f)),
    E("2.6", "(2.19)", r"({}^B X_A\underline{\boldsymbol{m}})^T{}^B X_A"
      r"\underline{\boldsymbol{f}} = \underline{\boldsymbol{m}}^T\underline{\boldsymbol{f}}",
      False, lambda v: ((_X(v) @ v.m).T @ _X(v) @ v.f, v.m.T @ v.f)),
    E("2.8", "(2.26)", r"{}^B X_A^{-T} = ({}^B X_A^{-1})^T", True,
      lambda v: (_Xs(v), np.linalg.inv(_X(v)).T)),
]
