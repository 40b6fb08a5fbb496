"""transforms3d 0.4.2's ``axangles.mat2axangle``, re-created: the axis a unit eigenvector of
``Q`` for an eigenvalue within ``unit_thresh`` = 1e-5 of 1 (the last such), the angle signed
in ``(-pi, pi]``. Below phi ~ 1e-5 all three eigenvalues are within 1e-5 of 1 and the
eigenvector taken need not be the axis."""

import math

import numpy as np

__version__ = "0.4.2"


def mat2axangle(mat, unit_thresh=1e-5):
    """``(direction, angle)`` of the rotation ``mat`` as transforms3d 0.4.2 computes them."""
    M = np.asarray(mat, dtype=np.float64)
    L, W = np.linalg.eig(M.T)
    i = np.where(np.abs(L - 1.0) < unit_thresh)[0]
    if not len(i):
        raise ValueError("no unit eigenvector corresponding to eigenvalue 1")
    direction = np.real(W[:, i[-1]]).squeeze()
    cosa = (np.trace(M) - 1.0) / 2.0
    if abs(direction[2]) > 1e-8:
        sina = (M[1, 0] + (cosa - 1.0) * direction[0] * direction[1]) / direction[2]
    elif abs(direction[1]) > 1e-8:
        sina = (M[0, 2] + (cosa - 1.0) * direction[0] * direction[2]) / direction[1]
    else:
        sina = (M[2, 1] + (cosa - 1.0) * direction[1] * direction[2]) / direction[0]
    return direction, math.atan2(sina, cosa)
