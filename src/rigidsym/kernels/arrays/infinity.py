"""Screws at infinity on the array back-ends (PyTorch, JAX): a pure translation (a pure
couple) answered in the library's own array operations, traceable under ``torch.compile``,
``jax.jit`` and the derivative transforms.

The rule is :mod:`rigidsym.kernels.runtime.screw_at_infinity`'s (Angeles, Sec. 3.2, 3.4.1,
3.7; pytransform3d's and Modern Robotics' translation screw): at Q = 1 with a' != a
(``screw_of_displacement``), omega = 0 with a_dot != 0 (``instant_screw_axis``) and f = 0
with n_A != 0 (``wrench_axis``) the screw has direction ``e = t / ||t||`` of the
translation (the couple) ``t``, ``p0 = 0``, ``pitch = +inf`` and Plücker array ``[0; e]``;
without motion (load) every output but ``phi`` is undetermined: NaN there, and under
``on_singular="raise"`` (eager only) a
:class:`~rigidsym.kernels.runtime.errors.SingularConfigurationError` naming the argument,
as the NumPy kernels. Every value is selected by ``where`` from finite operands (the
safe-``where`` idiom), so a derivative through a batch with such rows stays finite; the
rows answered here have a zero derivative in ``Q``, ``omega`` or ``f`` (the screw at
infinity does not depend on them) and ``e``'s derivative in ``t``.
No import of either library.
"""

from __future__ import annotations

import numpy as np

from rigidsym.kernels.runtime.screw_at_infinity import COMPLETED, no_motion

__all__ = ["COMPLETED", "complete"]


def _components(x) -> list:
    return [x[..., i] for i in range(x.shape[-1])]


def _translation(xp, a: list, b: list) -> list:
    """``b - a`` by component; where it overflows (finite inputs), ``b/2 - a/2`` (exact
    halving: only the direction is used)."""
    t = [bi - ai for ai, bi in zip(a, b, strict=True)]
    over = None
    for ti in t:
        o = xp.isinf(ti)
        over = o if over is None else over | o
    return [xp.where(over, 0.5 * bi - 0.5 * ai, ti) for ai, bi, ti in zip(a, b, t, strict=True)]


def _direction(xp, t: list, moving) -> list:
    """``t / ||t||`` in the ``moving`` samples (scaled by the largest component first: no
    overflow or underflow of the squares); 1 / sqrt(3) elsewhere, on finite operands."""
    one = xp.ones_like(t[0])
    t = [xp.where(moving, ti, one) for ti in t]
    m = xp.maximum(xp.maximum(xp.abs(t[0]), xp.abs(t[1])), xp.abs(t[2]))
    u = [ti / m for ti in t]
    n = xp.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
    return [ui / n for ui in u]


def _put(xp, mask, value, r):
    """``r`` with ``value`` (an array of ``r``'s shape, or a float) in the samples of the
    batch ``mask``."""
    m = mask.reshape(tuple(mask.shape) + (1,) * (r.ndim - mask.ndim))
    return xp.where(m, value, r)


def complete(lib, name: str, full: list, res: list, sing, batch: tuple, on_singular: str,
             traced: bool):
    """Answer the screws at infinity of kernel ``name``'s batch.

    Args:
        lib: the back-end (:class:`rigidsym.kernels.arrays.evaluation.Library`).
        name: the kernel (one of :data:`COMPLETED`; any other is returned as it is).
        full: its inputs, broadcast to ``batch + shape``.
        res: its outputs ``batch + shape``, as the generated program computed them.
        sing: the batch mask of its singular samples.
        batch: the batch shape.
        on_singular: ``"raise"`` or ``"nan"`` (``"nan"`` while traced).
        traced: an input is traced (no host reads).

    Returns:
        ``(outputs, singular mask, answered mask)``: the rows answered here (the answered
        mask: a screw at infinity, or NaN but ``phi`` without motion), no longer singular
        and whose inf (pitch) or NaN is the answer, not an overflow; the answered mask is
        None where no row is a candidate (known without a device read).

    Raises:
        SingularConfigurationError: eager, ``on_singular="raise"``, a row without motion
            (load), naming the argument of
            :data:`rigidsym.kernels.runtime.screw_at_infinity.NO_MOTION`.
    """
    xp = lib.xp
    if name == "screw_of_displacement":
        _, a, b = full
        cand = (res[1] == 0) & ~sing
    elif name in ("instant_screw_axis", "wrench_axis"):
        if name == "instant_screw_axis":    # omega = 0: every point moves at a_dot
            zero, point, b = full
        else:                               # f = 0: the moment is n_A about every point
            w_A, point = full
            zero, b = w_A[..., 3:], w_A[..., :3]
        cand = sing & (zero == 0).all(-1) & xp.isfinite(point).all(-1)
        a = xp.zeros_like(b)
    else:
        return res, sing, None
    if lib.clear(cand):
        return res, sing, None
    t = _translation(xp, _components(a), _components(b))
    finite = xp.isfinite(t[0]) & xp.isfinite(t[1]) & xp.isfinite(t[2])
    nonzero = (t[0] != 0) | (t[1] != 0) | (t[2] != 0)
    moving = cand & finite & nonzero
    still = cand & finite & ~nonzero
    if on_singular == "raise" and not traced and bool(still.any()):
        no_motion(name, np.flatnonzero(np.asarray(lib.host(still)).reshape(-1)), batch)
    e = xp.stack(_direction(xp, t, moving), -1)
    nan, inf = float("nan"), float("inf")
    undetermined = cand & ~moving
    out = list(res)
    k = 0
    if name == "screw_of_displacement":
        out[0] = _put(xp, undetermined, nan, _put(xp, moving, e, res[0]))
        k = 2
    p0, pitch, kappa = res[k:]
    out[k] = _put(xp, undetermined, nan, _put(xp, moving, 0.0, p0))
    out[k + 1] = _put(xp, undetermined, nan, _put(xp, moving, inf, pitch))
    screw = xp.concatenate([xp.zeros_like(e), e], -1)
    out[k + 2] = _put(xp, undetermined, nan, _put(xp, moving, screw, kappa))
    return out, sing & ~cand, cand
