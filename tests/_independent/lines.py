"""Exercise 3.7 by linear algebra: the direction e solves the linear system
``[b - a]x e = n_A - n_B``, ``n_A.e = 0``, ``n_B.e = 0`` (an affine set by SVD), cut with
the unit sphere. Never imports rigidsym."""

from __future__ import annotations

import numpy as np

TOL = 1e-9


def _skew(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]], float)


def axis_from_two_moments(a, b, nA, nB):
    """``("lines", [(e, n_O), ...])`` (one or two oriented lines), ``("none", [])`` or
    ``("many", [])`` for the lines with moments ``nA`` about ``a`` and ``nB`` about ``b``."""
    a, b, nA, nB = (np.asarray(v, float) for v in (a, b, nA, nB))
    L = np.vstack([_skew(b - a), nA[None, :], nB[None, :]])
    r = np.concatenate([nA - nB, [0.0, 0.0]])
    scale = max(1.0, np.abs(L).max(), np.abs(r).max())
    e_p, *_ = np.linalg.lstsq(L, r, rcond=None)          # the minimum-norm solution
    if np.linalg.norm(L @ e_p - r) > TOL * scale:
        return "none", []
    _, sv, Vt = np.linalg.svd(L)
    rank = int((sv > TOL * scale).sum())
    N = Vt[rank:]                                         # the null space, rows
    q = 1.0 - e_p @ e_p                                   # e = e_p + N^T t, |t|^2 = q
    if q < -TOL:
        return "none", []
    if len(N) == 0:
        return ("lines", [_line(e_p, a, nA)]) if abs(q) <= TOL else ("none", [])
    if abs(q) <= TOL:
        return "lines", [_line(e_p, a, nA)]
    if len(N) >= 2:
        return "many", []
    t = np.sqrt(q)
    return "lines", [_line(e_p + t * N[0], a, nA), _line(e_p - t * N[0], a, nA)]


def _line(e, a, nA):
    e = e / np.linalg.norm(e)
    return e, nA + np.cross(a, e)
