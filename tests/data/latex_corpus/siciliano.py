"""B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, *Robotics: Modelling, Planning and
Control*, Springer, 2009. Notation: bold upright symbols (\\boldsymbol{R}, \\boldsymbol{p});
angles \\vartheta, \\varphi; \\boldsymbol{I}_3 the identity of size 3; transposes ^{T};
c_\\vartheta, s_\\vartheta for cos and sin; \\boldsymbol{S}(\\cdot) the skew-symmetric operator;
\\mathrm{Tr} the trace."""

import numpy as np
from _num import I3, E, cross, hat, rot, rotx, roty, rotz

BOOK = {"key": "siciliano", "title": "Siciliano, Sciavicco, Villani & Oriolo, Robotics: "
        "Modelling, Planning and Control", "edition": "Springer, 2009"}

TABLE = r"""
\boldsymbol{R}: rotation
\boldsymbol{r}: unit vector
\vartheta: angle
\varphi: angle
\psi: angle
\boldsymbol{\omega}: vector
\boldsymbol{p}: vector
\boldsymbol{a}: vector
\boldsymbol{b}: vector
"""

_CS = "needs Siciliano's reading of c_\\vartheta, s_\\vartheta as cos, sin"


def _rr(v, s=1):
    k = hat(v.r)
    return I3 + s * np.sin(v.vartheta) * k + (1 - np.cos(v.vartheta)) * k @ k


def _X(v):
    return cross(v.a, v.b)


ENTRIES = [
    E("2.2", "(2.4)", r"\boldsymbol{R}^{T}\boldsymbol{R} = \boldsymbol{I}_3", True,
      lambda v: (v.R.T @ v.R, I3)),
    E("2.2", "(2.5)", r"\boldsymbol{R}^{T} = \boldsymbol{R}^{-1}", True,
      lambda v: (v.R.T, np.linalg.inv(v.R))),
    E("2.2", "(2.4)", r"\boldsymbol{R}\boldsymbol{R}^{T} = \boldsymbol{R}", False,
      lambda v: (v.R @ v.R.T, v.R), note="I_3 mistyped as R"),
    E("2.2.1", "(2.6)",
      r"\begin{bmatrix}\cos\vartheta & -\sin\vartheta & 0\\ \sin\vartheta & \cos\vartheta & 0"
      r"\\ 0 & 0 & 1\end{bmatrix}^{T}\begin{bmatrix}\cos\vartheta & -\sin\vartheta & 0\\ "
      r"\sin\vartheta & \cos\vartheta & 0\\ 0 & 0 & 1\end{bmatrix} = \boldsymbol{I}_3", True,
      lambda v: (rotz(v.vartheta).T @ rotz(v.vartheta), I3)),
    E("2.2.1", "(2.6)",
      r"\begin{bmatrix} c_\vartheta & -s_\vartheta & 0\\ s_\vartheta & c_\vartheta & 0\\ "
      r"0 & 0 & 1\end{bmatrix}\begin{bmatrix} c_\vartheta & s_\vartheta & 0\\ -s_\vartheta & "
      r"c_\vartheta & 0\\ 0 & 0 & 1\end{bmatrix} = \boldsymbol{I}_3", True,
      lambda v: (rotz(v.vartheta) @ rotz(v.vartheta).T, I3), note=_CS),
    E("2.2.1", "(2.6)",
      r"\begin{bmatrix} c_\vartheta & -s_\vartheta & 0\\ s_\vartheta & c_\vartheta & 0\\ "
      r"0 & 0 & 1\end{bmatrix}\begin{bmatrix} c_\vartheta & -s_\vartheta & 0\\ s_\vartheta & "
      r"c_\vartheta & 0\\ 0 & 0 & 1\end{bmatrix} = \boldsymbol{I}_3", False,
      lambda v: (rotz(v.vartheta) @ rotz(v.vartheta), I3), note=_CS),
    E("2.2.1", "cf. (2.7)",
      r"\begin{bmatrix}1 & 0 & 0\\ 0 & \cos\vartheta & -\sin\vartheta\\ 0 & \sin\vartheta & "
      r"\cos\vartheta\end{bmatrix}\begin{bmatrix}1 & 0 & 0\\ 0 & \cos\varphi & -\sin\varphi\\ "
      r"0 & \sin\varphi & \cos\varphi\end{bmatrix} = \begin{bmatrix}1 & 0 & 0\\ 0 & "
      r"\cos(\vartheta + \varphi) & -\sin(\vartheta + \varphi)\\ 0 & \sin(\vartheta + \varphi)"
      r" & \cos(\vartheta + \varphi)\end{bmatrix}", True,
      lambda v: (rotx(v.vartheta) @ rotx(v.varphi), rotx(v.vartheta + v.varphi))),
    E("2.2.1", "cf. (2.7)",
      r"\begin{bmatrix}\cos\vartheta & 0 & \sin\vartheta\\ 0 & 1 & 0\\ -\sin\vartheta & 0 & "
      r"\cos\vartheta\end{bmatrix}\begin{bmatrix}\cos\varphi & 0 & \sin\varphi\\ 0 & 1 & 0\\ "
      r"-\sin\varphi & 0 & \cos\varphi\end{bmatrix} = \begin{bmatrix}\cos(\vartheta - \varphi)"
      r" & 0 & \sin(\vartheta - \varphi)\\ 0 & 1 & 0\\ -\sin(\vartheta - \varphi) & 0 & "
      r"\cos(\vartheta - \varphi)\end{bmatrix}", False,
      lambda v: (roty(v.vartheta) @ roty(v.varphi), roty(v.vartheta - v.varphi))),
    E("2.5", "(2.25)",
      r"\boldsymbol{I}_3 + \sin\vartheta\,\boldsymbol{S}(\boldsymbol{r}) + (1 - \cos\vartheta)"
      r"\boldsymbol{S}^2(\boldsymbol{r}) = \boldsymbol{r}\boldsymbol{r}^{T} + \cos\vartheta"
      r"(\boldsymbol{I}_3 - \boldsymbol{r}\boldsymbol{r}^{T}) + \sin\vartheta\,"
      r"\boldsymbol{S}(\boldsymbol{r})", True,
      lambda v: (_rr(v), v.r @ v.r.T + np.cos(v.vartheta) * (I3 - v.r @ v.r.T)
                 + np.sin(v.vartheta) * hat(v.r)),
      note="needs Siciliano's S(.) as the skew-symmetric operator"),
    E("2.5", "(2.27)",
      r"\mathrm{Tr}\left(\boldsymbol{r}\boldsymbol{r}^{T} + \cos\vartheta(\boldsymbol{I}_3 - "
      r"\boldsymbol{r}\boldsymbol{r}^{T})\right) = 1 + 2\cos\vartheta", True,
      lambda v: (np.trace(v.r @ v.r.T + np.cos(v.vartheta) * (I3 - v.r @ v.r.T)),
                 1 + 2 * np.cos(v.vartheta))),
    E("2.5", "(2.27)",
      r"\mathrm{Tr}\left(\boldsymbol{r}\boldsymbol{r}^{T} + \cos\vartheta(\boldsymbol{I}_3 - "
      r"\boldsymbol{r}\boldsymbol{r}^{T})\right) = 2\cos\vartheta - 1", False,
      lambda v: (np.trace(v.r @ v.r.T + np.cos(v.vartheta) * (I3 - v.r @ v.r.T)),
                 2 * np.cos(v.vartheta) - 1)),
    E("3.1.1", "(3.9)",
      r"\boldsymbol{R}(\boldsymbol{a}\times\boldsymbol{b}) = \boldsymbol{R}\boldsymbol{a}"
      r"\times\boldsymbol{R}\boldsymbol{b}", True,
      lambda v: (v.R @ _X(v), cross(v.R @ v.a, v.R @ v.b))),
    E("3.1.1", "(3.9)",
      r"\boldsymbol{R}(\boldsymbol{a}\times\boldsymbol{b}) = \boldsymbol{R}^{T}\boldsymbol{a}"
      r"\times\boldsymbol{R}\boldsymbol{b}", False,
      lambda v: (v.R @ _X(v),
                 cross(v.R.T @ v.a, v.R @ v.b))),
    E("3.1.1", "cf. (3.7)", r"\boldsymbol{\omega}^{T}(\boldsymbol{\omega}\times\boldsymbol{p}) = 0",
      True, lambda v: (v.omega.T @ np.cross(v.omega.ravel(), v.p.ravel()), 0)),
    E("2.4", "cf. (2.18)",
      r"\left\|\boldsymbol{R}\boldsymbol{p}\right\|^2 = \boldsymbol{p}^{T}\boldsymbol{p}", True,
      lambda v: (np.linalg.norm(v.R @ v.p) ** 2, v.p.T @ v.p)),
    E("2.4", "cf. (2.18)",
      r"\left\|\boldsymbol{R}\boldsymbol{p}\right\|^2 = \boldsymbol{p}^{T}\boldsymbol{R}"
      r"\boldsymbol{p}", False,
      lambda v: (np.linalg.norm(v.R @ v.p) ** 2, v.p.T @ v.R @ v.p)),
    E("2.4", "cf. (2.18)", r"\tan\frac\vartheta2 = \frac{\sin\vartheta}{1 + \cos\vartheta}", True,
      lambda v: (np.tan(v.vartheta / 2), np.sin(v.vartheta) / (1 + np.cos(v.vartheta)))),
    E("2.2", "(2.4)", r"\det\boldsymbol{R} = 1 \quad \forall \boldsymbol{R} \in SO(3)", True,
      lambda v: (np.linalg.det(v.R), 1), note="a trailing declaration"),
]

_ = (rot,)
