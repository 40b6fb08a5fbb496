"""L.-W. Tsai, *Robot Analysis: The Mechanics of Serial and Parallel Manipulators*, Wiley,
1999, sec. 3.4 and 3.7. Notation: \\$ a screw, [s; s_O] with
s_O = r x s + h s (the pitch h, a point r of the axis); \\$_1 o \\$_2 the reciprocal product
s_1 . s_O2 + s_2 . s_O1, written \\$_1^T Delta \\$_2 with Delta = [0 1; 1 0]. Truth by NumPy."""

import numpy as np
from _num import E, cross


def _f(x):
    """A 1 x 1 array (or a number) as a float."""
    return np.asarray(x, float).item()

BOOK = {"key": "tsai", "title": "Tsai, Robot Analysis", "edition": "Wiley, 1999"}

TABLE = r"""
\mathbf{s}: vector
\mathbf{r}: vector
h: scalar
"""

SCREW = r"\$ = \begin{bmatrix}\mathbf{s}\\ \mathbf{r}\times\mathbf{s} + h\mathbf{s}\end{bmatrix}"
LINE = r"\$ = \begin{bmatrix}\mathbf{s}\\ \mathbf{r}\times\mathbf{s}\end{bmatrix}"
DELTA = (r"\Delta = \begin{bmatrix}\mathbf{O} & \mathbf{1}\\ \mathbf{1} & \mathbf{O}"
         r"\end{bmatrix}")


def _screw(v, h=None):
    h = v.h if h is None else h
    return np.vstack([v.s, cross(v.r, v.s) + h * v.s])


_D = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])

ENTRIES = [
    E("3.7", "(3.94)", r"\$^T\Delta\$ = 2h\,\mathbf{s}^T\mathbf{s}", True,
      lambda v: (_f(_screw(v).T @ _D @ _screw(v)), 2 * v.h * _f(v.s.T @ v.s)),
      lets=(SCREW, DELTA)),
    E("3.7", "(3.94)", r"\$^T\Delta\$ = h\,\mathbf{s}^T\mathbf{s}", False,
      lambda v: (_f(_screw(v).T @ _D @ _screw(v)), v.h * _f(v.s.T @ v.s)),
      lets=(SCREW, DELTA)),
    E("3.4", "(3.61)", r"\$^T\Delta\$ = 0", True,
      lambda v: (_f(_screw(v, 0).T @ _D @ _screw(v, 0)), 0.0), lets=(LINE, DELTA)),
    E("3.4", "(3.58)", r"\$ = \begin{bmatrix}\mathbf{1} & \mathbf{O}\\ [\mathbf{r}]_\times & "
      r"\mathbf{1}\end{bmatrix}\begin{bmatrix}\mathbf{s}\\ h\mathbf{s}\end{bmatrix}", True,
      lambda v: (_screw(v), np.vstack([v.s, cross(v.r, v.s) + v.h * v.s])), lets=(SCREW,)),
    E("3.4", "(3.58)", r"\$ = \begin{bmatrix}\mathbf{1} & \mathbf{O}\\ -[\mathbf{r}]_\times & "
      r"\mathbf{1}\end{bmatrix}\begin{bmatrix}\mathbf{s}\\ h\mathbf{s}\end{bmatrix}", False,
      lambda v: (_screw(v), np.vstack([v.s, -cross(v.r, v.s) + v.h * v.s])), lets=(SCREW,)),
]
