"""pytransform3d 3.17.0's ``rotations.compact_axis_angle_from_matrix`` (through
``axis_angle_from_matrix``, ``check=False``), re-created: within 1e-6 of a half turn the
axis from the square roots of the diagonal of the symmetric part, whose rounding the
square root magnifies."""

import numpy as np

__version__ = "3.17.0"


def compact_axis_angle_from_matrix(R):
    """The rotation vector of ``R`` (3 x 3) as pytransform3d 3.17.0 computes it."""
    R = np.asarray(R, dtype=np.float64)
    axis_unnormalized = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    axis_norm = np.linalg.norm(axis_unnormalized)
    angle = np.arctan2(0.5 * axis_norm, (np.trace(R) - 1.0) / 2.0)
    if angle == 0.0:
        return np.zeros(3)
    if abs(angle - np.pi) < 1e-6:
        R_sym = 0.5 * (R + R.T)
        eeT_diag = np.clip(0.5 * (np.diag(R_sym) + 1.0), 0.0, 1.0)
        k = np.argmax(eeT_diag)
        signs = np.where(R_sym[k] >= 0, 1, -1)
        signs[k] = 1.0
        axis = np.sqrt(eeT_diag) * signs
        if angle < np.pi and np.dot(axis, axis_unnormalized) < 0.0:
            axis = -axis
        axis_norm = np.linalg.norm(axis)
    else:
        axis = axis_unnormalized
    return axis / axis_norm * angle
