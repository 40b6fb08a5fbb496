"""The Euler-angle rates of Exercise 3.10 on the package's kernels: the rate matrix ``W``
(``omega = W eta_dot``) and the angle rates (``eta_dot = W^-1 omega``) of any of the twelve
intrinsic sequences, in the fixed or the body frame, each the generated kernel of that
sequence and frame; and the Euler angles of a rotation (either branch, the gimbal lock
flagged). Re-exported by :mod:`rigidsym.kernels`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.namespace import public

__all__ = ["euler_rate_matrix", "euler_angle_rates", "euler_angles_from_rotation"]


@public
def euler_rate_matrix(angles: ArrayLike, sequence: str, frame: str = "fixed", *,
                      out: NDArray[np.float64] | None = None, check: bool = True,
                      threads: int | None = None) -> NDArray[np.floating]:
    """Euler-angle rate matrix ``W`` with ``omega = W eta_dot`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3), the intrinsic Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".
        out, check, threads: see :mod:`rigidsym.kernels`.

    Returns:
        ndarray (..., 3, 3) [1].

    Raises:
        TypeError, ValueError: bad input, naming the argument (also a bad ``sequence`` or
            ``frame``).

    Example:
        >>> euler_rate_matrix([0.1, 0.2, 0.3], "ZYX").shape
        (3, 3)
    """
    return _state.call(_state.euler_name("euler_rate_matrix", sequence, frame), (angles,),
                       out=out, check=check, threads=threads)


@public
def euler_angle_rates(angles: ArrayLike, omega: ArrayLike, sequence: str,
                      frame: str = "fixed", *, out: NDArray[np.float64] | None = None,
                      check: bool = True, on_singular: str | None = None,
                      threads: int | None = None) -> NDArray[np.floating]:
    """Euler-angle rates ``eta_dot = W^-1 omega`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3) [rad].
        omega: array-like (..., 3) [rad/s], in the frame given by ``frame``.
        sequence: one of the twelve intrinsic sequences.
        frame: "fixed" or "body".
        out, check, on_singular, threads: see :mod:`rigidsym.kernels`.

    Returns:
        ndarray (..., 3) [rad/s].

    Raises:
        TypeError, ValueError: bad input, naming the argument.
        SingularConfigurationError: at gimbal lock (det W = 0), unless on_singular="nan".

    Example:
        >>> euler_angle_rates([0.1, 0.2, 0.3], [0.0, 0.0, 1.0], "ZYX").shape
        (3,)
    """
    return _state.call(_state.euler_name("euler_angle_rates", sequence, frame), (angles, omega),
                       out=out, check=check, on_singular=on_singular, threads=threads)


@public
def euler_angles_from_rotation(Q: ArrayLike, sequence: str, *, branch: str = "principal",
                               check: bool = True, threads: int | None = None,
                               ) -> tuple[NDArray[np.floating], NDArray[np.bool_]]:
    """The intrinsic Euler angles of a rotation and the gimbal-lock flag: the inverse of
    ``Q = R_i(a) R_j(b) R_k(c)`` (Exercise 3.10's sequences; derivations/euler_angles.py).

    Every angle is an atan2 (never asin or acos: no NaN past +-1, no half the digits lost
    at the lock); off the lock ``Q(angles) = Q`` to the rounding even where ``a`` and ``c``
    alone are ill-conditioned (``kappa ~ 1 / |cos b|`` Tait-Bryan, ``1 / |sin b|`` proper
    Euler). At the lock (the first angle's two entries of ``Q`` exactly 0) only ``a + c`` or
    ``a - c`` is defined: the member ``c = 0`` is returned, flagged, never NaN.

    Args:
        Q: array-like (..., 3, 3), rotation matrices.
        sequence: one of the twelve intrinsic sequences ("ZYX", "ZXZ", ...).
        branch: ``"principal"`` (``b`` in [-pi/2, pi/2] Tait-Bryan, [0, pi] proper Euler)
            or ``"other"`` (``(a + pi, pi - b, c + pi)`` Tait-Bryan, ``(a + pi, -b, c +
            pi)`` proper Euler, each in [-pi, pi]); the same at the lock.
        check, threads: see :mod:`rigidsym.kernels`.

    Returns:
        ``(angles, gimbal_lock)``: ndarray (..., 3) [rad] and ndarray (...) of bool.

    Raises:
        TypeError, ValueError: bad input, naming the argument (also a bad ``sequence`` or
            ``branch``).

    Example:
        >>> Q = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]   # a quarter turn about z
        >>> angles, lock = euler_angles_from_rotation(Q, "ZYX")
        >>> round(float(angles[0]), 12), bool(lock)        # yaw pi/2, pitch and roll 0
        (1.570796326795, False)
    """
    if branch not in ("principal", "other"):
        raise ValueError(f"branch: expected 'principal' or 'other', got {branch!r}")
    name = _state.euler_name("euler_rate_matrix", sequence, "fixed")
    seq = name[len("euler_rate_matrix_"):-len("_fixed")]
    angles, other, lock = _state.call(f"euler_angles_from_rotation_{seq}", (Q,),
                                      check=check, threads=threads)
    return (angles if branch == "principal" else other), np.asarray(lock) != 0
