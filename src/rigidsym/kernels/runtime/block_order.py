"""The order of the 3-blocks of twists and wrenches: the book's ``[omega; v]`` and ``[n; f]``
against ``[v; omega]`` and ``[f; n]`` (Pinocchio, ROS), for vectors and 6x6 operators.
Re-exported by :mod:`rigidsym.kernels`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime.inputs import as_array
from rigidsym.kernels.runtime.namespace import public

__all__ = ["swap_blocks"]


@public
def swap_blocks(x: ArrayLike, matrix: bool = False) -> NDArray[np.floating]:
    """Swap the 3-blocks of 6-arrays: ``[omega; v] <-> [v; omega]``, ``[n; f] <-> [f; n]``.

    Converts to and from the order of Pinocchio and ROS. With ``matrix=True`` a
    ``(..., 6, 6)`` operator is converted (rows and columns).

    Args:
        x: array-like (..., 6), or (..., 6, 6) with ``matrix=True``.
        matrix: convert an operator instead of a vector.

    Returns:
        ndarray of the shape of ``x``.

    Raises:
        TypeError, ValueError: ``x`` not real numbers, or of the wrong trailing shape;
            ``matrix`` not a bool.

    Example:
        >>> swap_blocks([1, 2, 3, 4, 5, 6]).tolist()
        [4.0, 5.0, 6.0, 1.0, 2.0, 3.0]
    """
    shape = (6, 6) if _names.flag(matrix, "matrix") else (6,)
    a = as_array(x, {"name": "x", "tshape": shape})
    perm = [3, 4, 5, 0, 1, 2]
    return a[..., perm, :][..., perm] if matrix else a[..., perm]

