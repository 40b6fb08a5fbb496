"""The checks of a kernel call's inputs (:meth:`rigidsym.kernels.runtime.space.KernelSpace.call`):
the common keywords, each argument made an array of the right trailing shape (errors name
the argument), finite and within its kind's constraint (unit vector, rotation: the row of
:mod:`rigidsym.core.kinds`), and the batch shapes broadcast.
"""

from __future__ import annotations

import math
import sys
import warnings
from typing import Any

import numpy as np

from rigidsym.core import kinds as _kinds
from rigidsym.kernels.runtime.errors import BroadcastWarning
from rigidsym.kernels.runtime.scale import check_threads

__all__ = ["UNIT_TOL", "ORTHO_TOL", "UNIT_AS_IS_EPS", "check_keywords", "as_array",
           "validate", "normalise", "check_inertia", "BODY_KERNELS", "batch_shape"]

#: tolerance on | ||e|| - 1 | for unit-vector arguments (e, eta), from the kind table.
UNIT_TOL = _kinds.get("unit").tol
#: tolerance on max |Q^T Q - 1| for rotation arguments (and det Q > 0), from the kind table.
ORTHO_TOL = _kinds.get("rotation").tol

_DTYPE_WORDS = {"b": "bool", "c": "complex", "O": "Python objects", "U": "str", "S": "bytes",
                "M": "datetime", "m": "timedelta", "V": "structured"}


def check_keywords(check: bool, on_singular: str, threads: int | None) -> None:
    """Validate the common keywords (``out`` is checked against the batch shape later).

    Raises:
        TypeError: ``check`` not a bool, ``threads`` not an int.
        ValueError: ``on_singular`` not "raise"/"nan", ``threads`` < 1.
    """
    if on_singular != "raise" and on_singular != "nan":
        raise ValueError(f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    if check is not True and check is not False:
        raise TypeError(f"check: expected True or False, got {check!r}")
    if threads is not None:
        check_threads(threads, "threads")


def as_array(x: Any, spec: dict, dtype=np.float64) -> np.ndarray:
    """``x`` as a float64 array with the trailing shape of ``spec``; errors name the argument.

    Raises:
        TypeError: str, bytes, arbitrary objects, complex or bool values.
        ValueError: a ragged nested sequence, a wrong trailing shape.
    """
    name = spec["name"]
    if type(x) is not np.ndarray:
        if isinstance(x, str | bytes):
            raise TypeError(f"{name}: expected an array-like of real numbers, "
                            f"got {type(x).__name__} {x!r:.40}")
        try:
            x = np.asarray(x)
        except ValueError as exc:      # NumPy's message for a ragged nested sequence
            raise ValueError(f"{name}: expected a rectangular array-like of real numbers "
                             f"(a ragged nested sequence?): {exc}") from None
        except Exception as exc:  # noqa: BLE001 - any failure to convert is a type error
            raise TypeError(f"{name}: expected an array-like of real numbers, "
                            f"got {type(x).__name__} ({exc})") from None
    if x.dtype != dtype:
        kind = x.dtype.kind
        if kind not in "fiu":
            what = _DTYPE_WORDS.get(kind, str(x.dtype))
            raise TypeError(f"{name}: expected real numbers (float or int), got {what} "
                            f"values (dtype {x.dtype})")
        x = x.astype(dtype)
    shape = spec["tshape"]
    k = len(shape)
    if x.ndim < k or x.shape[x.ndim - k:] != shape:
        raise ValueError(f"{name}: expected shape (..., {', '.join(map(str, shape))})"
                         f"{'' if k else ' (a scalar per sample)'}, got {x.shape}")
    return x


def validate(a: np.ndarray, spec: dict, given=None) -> None:
    """Finiteness, and the constraint of ``spec["kind"]`` (unit vector, rotation: the check
    and tolerance of its row in :mod:`rigidsym.core.kinds`), with the tolerance of the dtype
    ``given`` (the argument's own: float32 values in a float64 call keep the float32 one).

    Raises:
        ValueError: naming the argument and what was expected.
    """
    name, kind = spec["name"], spec["kind"]
    prec = given if given is not None and given.kind == "f" and given.itemsize < 8 else a.dtype
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: non-finite values (NaN or inf); expected finite values")
    k = _kinds.for_spec(kind, spec["tshape"])
    if k is not None and k.check is not None:
        msg = k.check(a, name, k.tolerance(prec))
        if msg:
            raise ValueError(msg)


#: a unit vector within this many machine epsilons of its dtype of norm 1 is taken as it is
#: (unit to rounding: dividing by its norm would change bits, not accuracy); the C entry
#: points check unit vectors to this tolerance and leave the others to the Python path
UNIT_AS_IS_EPS = 2


def normalise(a: np.ndarray, spec: dict) -> np.ndarray:
    """A unit-vector argument (kind "unit": axes, Euler-Rodrigues parameters) already
    accepted by :func:`validate` (| ||a|| - 1 | within the tolerance), divided by its norm in
    its own dtype, as pytransform3d and spatialmath do, where | ||a|| - 1 | exceeds
    ``UNIT_AS_IS_EPS`` eps (the norm formed in float64, in the order of the C entry's check,
    so that both take the same rows): the result is then the rotation about ``a / ||a||`` to
    the kernel's bound, and the next kernel's check accepts it (without it, ||e|| - 1 = 1e-8
    gave Q^T Q - 1 = 1.5e-8, refused). A new array where a row changes; other kinds as given.

    Args:
        a: the argument, shape ``(..., n)`` (``n`` the kind's length).
        spec: its spec (``name``, ``kind``, ``tshape``).

    Returns:
        ``a`` with those rows divided by their norm, or ``a`` itself.
    """
    k = _kinds.for_spec(spec["kind"], spec["tshape"])
    if k is None or len(k.shape) != 1 or k.check is None or not a.size:
        return a
    x = a.astype(np.float64)
    q = x[..., 0] * x[..., 0]
    for c in range(1, a.shape[-1]):
        q = q + x[..., c] * x[..., c]
    off = np.abs(np.sqrt(q) - 1.0) > UNIT_AS_IS_EPS * float(np.finfo(a.dtype).eps)
    if not off.any():
        return a
    s = a[..., 0] * a[..., 0]
    for c in range(1, a.shape[-1]):       # the norm in the dtype
        s = s + a[..., c] * a[..., c]
    return np.where(off[..., None], a / np.sqrt(s)[..., None], a)


#: the kernels whose arguments I_C and m are a rigid body's centroidal inertia and mass
BODY_KERNELS = frozenset({"inertia_at_point", "inertia_dyad_at_point"})


def check_inertia(I_C: np.ndarray, m: np.ndarray, tol: float) -> None:
    """A rigid body's centroidal inertia matrix and mass (Angeles Sec. 3.8): m > 0, I_C
    symmetric (max |I_C - I_C^T| <= tol max |I_C|), positive semi-definite, and its principal
    moments obey the triangle inequality (I_i + I_j >= I_k, a mass distribution's moments:
    I_1 = integral of y^2 + z^2 ...), each eigenvalue inequality within tol trace(I_C).

    Args:
        I_C: (..., 3, 3) inertia matrices [kg m^2]; m: (...) masses [kg].
        tol: the relative tolerance (the unit kind's, per dtype).

    Raises:
        ValueError: naming ``m`` or ``I_C`` and what was expected.
    """
    if m.size and not (m > 0).all():
        raise ValueError(f"m: expected a positive mass, got {np.min(m):.6g}")
    if not I_C.size:
        return
    scale = np.abs(I_C).max(axis=(-2, -1))
    asym = np.abs(I_C - np.swapaxes(I_C, -1, -2)).max(axis=(-2, -1))
    if (asym > tol * scale).any():
        raise ValueError(f"I_C: not symmetric (max |I_C - I_C^T| = {asym.max():.3g} > "
                         f"{tol:.3g} max |I_C|)")
    lam = np.linalg.eigvalsh((I_C + np.swapaxes(I_C, -1, -2)) / 2)
    slack = tol * np.abs(lam).sum(-1)
    if (lam[..., 0] < -slack).any():
        raise ValueError(f"I_C: not positive semi-definite (principal moment "
                         f"{lam[..., 0].min():.3g})")
    if (lam[..., 0] + lam[..., 1] < lam[..., 2] - slack).any():
        raise ValueError("I_C: principal moments violate the triangle inequality "
                         "(I_1 + I_2 >= I_3 for every rigid body)")


def batch_shape(arrs: list[np.ndarray], specs: list[dict], kernel: str = "") -> tuple[int, ...]:
    """The broadcast batch shape; the error names the first argument that does not fit.

    Args:
        arrs: the arguments, as arrays (batch axes first, then the argument's own shape).
        specs: their specifications (``name``, ``tshape``).
        kernel: the kernel's name, for the warning.

    Returns:
        tuple: the batch shape all arguments broadcast to (NumPy's rules).

    Raises:
        ValueError: the batch shapes do not broadcast (each argument's named).

    Warns:
        BroadcastWarning: the batch shape holds more samples than any argument's, i.e. two
            arguments' different batch shapes made a new batch axis (``e`` (5, 3) and
            ``phi`` (5, 1) -> batch (5, 5)); the result is NumPy's broadcast all the same.
    """
    shapes = [a.shape[:a.ndim - len(s["tshape"])] for a, s in zip(arrs, specs, strict=True)]
    try:
        batch = np.broadcast_shapes(*shapes)
    except ValueError:
        acc: tuple = ()
        for i, b in enumerate(shapes):
            try:
                acc = np.broadcast_shapes(acc, b)
            except ValueError:
                # name every argument with a batch so far: which one is wrong is the caller's
                names = [s["name"] for s, c in zip(specs[:i + 1], shapes, strict=False) if c]
                raise ValueError(f"{', '.join(names)}: batch shapes do not broadcast ("
                                 + ", ".join(f"{s['name']} {c}" for s, c in
                                             zip(specs[:i + 1], shapes, strict=False) if c)
                                 + ")") from None
        raise
    n = math.prod(batch)
    if n and n > max(math.prod(b) for b in shapes):
        _warn_new_axis(kernel, arrs, specs, shapes, batch)
    return batch


def _warn_new_axis(kernel, arrs, specs, shapes, batch) -> None:
    """The :class:`BroadcastWarning` of :func:`batch_shape`, naming each argument with a
    batch of its own, its shape and its batch shape, at the caller's line."""
    given = [(s["name"], a.shape, b) for a, s, b in zip(arrs, specs, shapes, strict=True) if b]
    parts = " and ".join(f"{n} of shape {sh} (batch {b})" for n, sh, b in given)
    sizes = " and ".join(str(math.prod(b)) for *_, b in given)
    warnings.warn(
        f"{kernel + ': ' if kernel else ''}{parts} broadcast to a new batch shape {batch} "
        f"({math.prod(batch)} samples from {sizes}); if that is meant, np.broadcast_to the "
        f"arguments first; if not, give them the same batch shape", BroadcastWarning,
        stacklevel=_outside_rigidsym())


def _outside_rigidsym() -> int:
    """The ``stacklevel`` of the first frame outside rigidsym (its package and the kernel
    spaces' ``api`` modules, named ``rigidsym.*`` wherever they lie): the user's call."""
    level, frame = 1, sys._getframe(1)
    while frame is not None and frame.f_globals.get("__name__", "").startswith("rigidsym"):
        level, frame = level + 1, frame.f_back
    return level
