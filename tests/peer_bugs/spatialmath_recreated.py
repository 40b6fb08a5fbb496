"""spatialmath-python 1.1.18's ``base.trlog`` for a rotation, re-created: the angle by
``acos``, the rotation vector ``0`` where ``sin(theta)`` rounds to 0 (phi below ~1e-8), the
half-turn branch only within ``tol eps`` of ``tr Q = -1``, elsewhere near it the skew part
over ``sin(theta)``."""

import math

import numpy as np

__version__ = "1.1.18"
_eps = float(np.finfo(np.float64).eps)


def _skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def _vex(S):
    return 0.5 * np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]])


def trlog(T, check=True, twist=False, tol=20):
    """The logarithm of the rotation ``T``: the cross-product matrix, or with ``twist=True``
    the rotation vector, as spatialmath 1.1.18 computes it."""
    R = np.asarray(T, dtype=np.float64)
    if check and R.shape != (3, 3):
        raise ValueError("Expect SO(3) or SE(3) matrix")
    if abs(np.trace(R) + 1) < tol * _eps:
        diagonal = R.diagonal()
        k = diagonal.argmax()
        mx = diagonal[k]
        col = R[:, k] + np.eye(3)[:, k]
        w = col / np.sqrt(2 * (1 + mx))
        return w * math.pi if twist else _skew(w * math.pi)
    tr = (np.trace(R) - 1) / 2
    theta = math.acos(min(tr, 1.0))
    st = math.sin(theta)
    if st == 0:
        return np.zeros((3,)) if twist else np.zeros((3, 3))
    skw = (R - R.T) / 2 / st
    return _vex(skw * theta) if twist else skw * theta
