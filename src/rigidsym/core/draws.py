"""Valid float inputs of a kernel argument, by its kind: one place for the tests and the
benchmarks (the float32 planner keeps its own adversarial draws, and the accuracy regimes
their exact ones, :mod:`rigidsym.codegen.accuracy.regimes`).

A kind's values lie on its manifold: unit vectors on the sphere, rotations proper
orthogonal (Rodrigues' formula, Angeles (2.48)), homogeneous transforms ``[[R, p], [0,
1]]``. A free argument is standard normal. Four copies of this, each drawing a transform its
own way, once fed the log of SE(3) a random 4 x 4 (the CI failure of stop 42).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

__all__ = ["units", "rotations", "transforms", "draw"]


def units(rng: np.random.Generator, shape: Sequence[int]) -> np.ndarray:
    """Unit vectors of shape ``shape`` (the last axis normalised), uniform on the sphere."""
    x = rng.standard_normal(tuple(shape))
    return x / np.linalg.norm(x, axis=-1, keepdims=True)


def rotations(e: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Rotation matrices ``(..., 3, 3)`` from unit axes ``e`` ``(..., 3)`` and angles ``phi``
    ``(...)`` in rad: ``e e^T + cos(phi) (1 - e e^T) + sin(phi) [e]x`` (Angeles (2.48))."""
    e, phi = np.asarray(e, dtype=np.float64), np.asarray(phi, dtype=np.float64)
    c, s = np.cos(phi)[..., None, None], np.sin(phi)[..., None, None]
    x = np.zeros(e.shape[:-1] + (3, 3))
    x[..., 0, 1], x[..., 0, 2], x[..., 1, 2] = -e[..., 2], e[..., 1], -e[..., 0]
    x -= np.swapaxes(x, -1, -2)
    ee = e[..., :, None] * e[..., None, :]
    return ee + c * (np.eye(3) - ee) + s * x


def transforms(R: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Homogeneous transforms ``[[R, p], [0, 1]]`` ``(..., 4, 4)`` from ``R`` ``(..., 3, 3)``
    and ``p`` ``(..., 3)``."""
    R, p = np.asarray(R, dtype=np.float64), np.asarray(p, dtype=np.float64)
    T = np.zeros(R.shape[:-2] + (4, 4))
    T[..., :3, :3], T[..., :3, 3], T[..., 3, 3] = R, p, 1.0
    return T


def draw(kind: str, shape: Sequence[int], rng: np.random.Generator, *,
         phi: tuple[float, float] = (0.05, 3.0),
         angle: tuple[float, float] = (0.05, np.pi - 0.05),
         free: Callable[[tuple], np.ndarray] | None = None) -> np.ndarray:
    """Random valid values of an argument of kind ``kind``, float64.

    Args:
        kind: the argument's spec kind (``Arg.kind``, ``kernels.json``'s ``"kind"``):
            ``"unit"``, ``"rotation"``, ``"transform"``, ``"angle"``, ``"angle_0_pi"``;
            any other (``"any"``, ``"twist"``, ``"wrench"``) is free.
        shape: the full shape, batch first then the argument's own (``(n, 3, 3)``).
        rng: the generator.
        phi: the range of a rotation's (or a transform's rotation's) angle, rad, uniform;
            the axis is uniform on the sphere.
        angle: the range of an angle argument, rad, uniform (``angle_0_pi`` is clipped to
            ``[0, pi]``).
        free: draws a free argument of the given shape (default standard normal).

    Returns:
        An array of shape ``shape``.

    Raises:
        ValueError: ``shape`` does not end in the kind's own shape.
    """
    shape = tuple(int(s) for s in shape)
    own = {"rotation": (3, 3), "transform": (4, 4)}.get(kind)
    if own and shape[-2:] != own:
        raise ValueError(f"shape: a {kind} ends in {own}, got {shape}")
    if kind == "unit":
        return units(rng, shape)
    if kind in ("rotation", "transform"):
        batch = shape[:-2]
        R = rotations(units(rng, batch + (3,)), rng.uniform(*phi, batch))
        return R if kind == "rotation" else transforms(R, rng.standard_normal(batch + (3,)))
    if kind in ("angle", "angle_0_pi"):
        lo, hi = angle if kind == "angle" else (max(angle[0], 0.0), min(angle[1], np.pi))
        return rng.uniform(lo, hi, shape)
    return free(shape) if free else rng.standard_normal(shape)
