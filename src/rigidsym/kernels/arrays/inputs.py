"""The input rules of the array back-ends: the keyword modes of eager and traced
calls, the conversion of the arguments, the eager validation of constrained inputs, the
broadcast batch shape, and the regular point substituted in singular samples. No import of
PyTorch or JAX.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from rigidsym.core import kinds as _kinds

__all__ = ["modes", "validate", "broadcast_batch", "tolerance", "safe_point", "convert"]

_MODES = ("raise", "nan")


def raise_error(exc_type: type, message: str):
    """Raise ``exc_type(message)``: how :func:`modes` refuses by default."""
    raise exc_type(message)


def modes(check: bool | None, on_singular: str | None, traced: bool, where: str,
          refuse: Callable = raise_error):
    """The effective ``(check, on_singular)`` of a call: defaults ``True`` / ``"raise"`` in
    eager mode, ``False`` / ``"nan"`` while traced (no host synchronisation there).
    ``refuse(exc_type, message)`` raises the errors (PyTorch: outside Dynamo's trace).

    Raises:
        ValueError: ``check=True`` or ``on_singular="raise"`` while traced (``where`` names
            the tracer), or a bad value.
    """
    if check is not None and not isinstance(check, bool):
        refuse(TypeError, f"check: expected True, False or None, got {check!r}")
    if on_singular is not None and on_singular not in _MODES:
        refuse(ValueError, f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    if traced:
        if check:
            refuse(ValueError, f"check=True needs eager mode (it reads values on the host); "
                               f"under {where} pass check=False or leave it unset")
        if on_singular == "raise":
            refuse(ValueError, f"on_singular='raise' needs eager mode; under {where} use "
                               "'nan' (the default there)")
        return False, "nan"
    return (True if check is None else check), (on_singular or "raise")


def tolerance(kind: _kinds.Kind, eps: float) -> float:
    """The validation tolerance of ``kind`` for inputs of machine epsilon ``eps`` (that of the
    lowest precision among a call's inputs): the kind table's (``kind.tol``, at least
    ``kind.tol_eps`` eps: float32 1.19e-5) up to float32; 8 eps for float16 and bfloat16
    (7.8e-3, 6.3e-2: a unit vector rounded to the type, its norm formed there, errs by up to
    ~3 u = 1.5 eps, and 100 eps would pass vectors off by 10-80 %)."""
    narrow = eps > float(np.finfo(np.float32).eps)
    return max(kind.tol, (8.0 if narrow else kind.tol_eps) * eps)


def validate(xp, arrays: list, args: list[dict], eps: float | None = None) -> None:
    """Eager validation: finite values, unit vectors, proper rotations (the kind table's
    tolerances, :func:`tolerance`, for ``eps``: default the arrays' own dtype's); one
    reduction per argument read on the host.

    Raises:
        ValueError: naming the argument.
    """
    for x, a in zip(arrays, args, strict=True):
        if not bool(xp.isfinite(x).all()):
            raise ValueError(f"{a['name']}: non-finite value (NaN or inf)")
        kind = _kinds.for_spec(a["kind"], tuple(a["shape"]))
        if kind is None or kind.check is None or not _numel(x):
            continue
        tol = tolerance(kind, float(xp.finfo(x.dtype).eps) if eps is None else eps)
        if kind.shape == (4, 4):   # a homogeneous transform: last row, then R = T[:3, :3]
            last = x[..., 3, :] - _like(xp, x, [0.0, 0.0, 0.0, 1.0])
            err = float(xp.abs(last).max())
            if not err <= tol:
                raise ValueError(f"{a['name']}: not a homogeneous transform (last row not "
                                 f"[0, 0, 0, 1]: max deviation {err:.3g} > {tol:.3g})")
            try:
                _rotation(xp, x[..., :3, :3], a["name"] + "[:3, :3]", tol)
            except ValueError as exc:
                raise ValueError(f"{a['name']}: not a homogeneous transform: {exc}") from None
        elif kind.shape == (3, 3):
            _rotation(xp, x, a["name"], tol)
        elif len(kind.shape) == 1:
            err = float(xp.abs(xp.sqrt((x * x).sum(-1)) - 1.0).max())
            if err > tol:
                raise ValueError(f"{a['name']}: not a unit vector (| ||{a['name']}|| - 1 | = "
                                 f"{err:.3g} > {tol:.3g})")


def _like(xp, x, values):
    v = xp.asarray(values, dtype=x.dtype)
    return v.to(x.device) if hasattr(v, "to") else v  # torch: on the input's device (GPU)


def _rotation(xp, x, name: str, tol: float) -> None:
    g = xp.einsum("...ki,...kj->...ij", x, x) - _like(xp, x, np.eye(3))
    err = float(xp.abs(g).max())
    if not err <= tol:
        raise ValueError(f"{name}: not orthogonal (max |{name}^T {name} - 1| = {err:.3g} > "
                         f"{tol:.3g})")
    if bool((xp.linalg.det(x) <= 0).any()):
        raise ValueError(f"{name}: not a proper rotation (det <= 0)")


def broadcast_batch(broadcast_shapes: Callable, xs: list, args: list[dict],
                    traced: bool = True) -> tuple:
    """The broadcast batch shape of ``xs`` (each less its argument's own trailing shape);
    not ``traced`` (no symbolic shapes), equal batch shapes are taken as they are, without
    ``broadcast_shapes`` (torch's goes through ``torch._refs``: a fixed cost).

    Raises:
        ValueError: the batch shapes do not broadcast (each argument's shape named).
    """
    shapes = [tuple(x.shape[:x.ndim - len(a["shape"])]) for x, a in zip(xs, args, strict=True)]
    if not traced and all(s == shapes[0] for s in shapes):
        return shapes[0]
    try:
        return tuple(broadcast_shapes(*shapes))
    except (RuntimeError, ValueError):  # torch raises RuntimeError, JAX ValueError
        # the message starts with the arguments' names, as rigidsym.kernels' does:
        # which one is wrong is the caller's
        pairs = [(a["name"], tuple(x.shape)) for x, a in zip(xs, args, strict=True)
                 if x.ndim > len(a["shape"])] or [(a["name"], tuple(x.shape))
                                                  for x, a in zip(xs, args, strict=True)]
        raise ValueError(", ".join(n for n, _ in pairs) + ": batch shapes do not broadcast ("
                         + ", ".join(f"{n} {s}" for n, s in pairs) + ")") from None


def _numel(x) -> int:
    return int(math.prod(x.shape))


def safe_point(args: list[dict]) -> list[float]:
    """A fixed generic point of the inputs' sets, one float per column: constrained kinds
    through their rational parametrisation (an exact unit vector or rotation), angles in
    (0.4, 1.2), free entries in (-1.5, 1.5); regular for every kernel of the package (tested:
    tests/test_arrays_masked.py), as a random point is with probability one."""
    rng = np.random.default_rng(38)
    out: list[float] = []
    for a in args:
        kind = _kinds.for_spec(a["kind"], tuple(a["shape"]))
        n = int(math.prod(a["shape"]))
        if kind is not None and kind.parametrise is not None:
            vals = kind.parametrise(list(rng.uniform(-0.9, 0.9, len(kind.params))))
        elif kind is not None and kind.half_angle:
            vals = rng.uniform(0.4, 1.2, n)
        else:
            vals = rng.uniform(-1.5, 1.5, n)
        out.extend(float(v) for v in vals)
    return out


def shape_text(s) -> str:
    """A trailing shape as the docs write it: ``(..., 3)``, ``(...)`` for a scalar."""
    return "(...)" if not s else f"(..., {', '.join(map(str, s))})"


_BAD_KINDS = "bcOUSMmV"  # NumPy kinds that are no real numbers


def convert(lib, values: tuple, args: list[dict]) -> tuple[list, Any, float]:
    """The library arrays of ``values`` on one device, in the dtype the kernel computes in
    (``lib``: the back-end's :class:`rigidsym.kernels.arrays.evaluation.Library`).

    Returns:
        ``(arrays, dtype, eps)``: ``dtype`` is the inputs' promoted dtype (the library's
        rule, ``lib.dtype``), that of the results; the arrays are in it, or in float32
        for float16 and bfloat16 (computed in float32, rounded once at the end);
        ``eps`` is the machine epsilon of the lowest precision among the inputs and the
        result, for the validation tolerance (a float32 unit vector with a float64 angle
        is checked at float32's).

    Raises:
        TypeError: an argument holds no real numbers, or a float type other than float16,
            bfloat16, float32 and float64 (named).
        ValueError: ragged, on another device, or the wrong trailing shape (named).
    """
    lib.note(values)
    arrays, eps = [], []
    for v, a in zip(values, args, strict=True):
        given = lib.is_array(v) or isinstance(v, (np.ndarray, np.generic))
        if lib.is_array(v):
            if not lib.real(v):
                raise TypeError(f"{a['name']}: expected real numbers, got {v.dtype}")
        else:
            try:
                v = np.asarray(v)
            except ValueError as exc:
                raise ValueError(f"{a['name']}: not a rectangular array ({exc})") from None
            if v.dtype.kind in _BAD_KINDS:
                raise TypeError(f"{a['name']}: expected real numbers, got {v.dtype}")
        fd = lib.float_dtype(v)
        if fd is not None and fd not in lib.floats:
            raise TypeError(f"{a['name']}: {v.dtype} is not supported; expected float16, "
                            "bfloat16, float32 or float64 (or integers)")
        if fd is not None and given:  # an array input, not a list or a Python number
            eps.append(float(lib.finfo(fd).eps))
        arrays.append(v)
    dtype, device = lib.dtype(values, arrays), lib.device(arrays)
    eps.append(float(lib.finfo(dtype).eps))
    work = lib.float32 if lib.finfo(dtype).bits < 32 else dtype
    out = []
    for v, a in zip(arrays, args, strict=True):
        t = lib.as_array(v, work, device, a["name"])
        shape = tuple(a["shape"])
        if t.ndim < len(shape) or tuple(t.shape[t.ndim - len(shape):]) != shape:
            raise ValueError(f"{a['name']}: expected shape {shape_text(shape)}, got "
                             f"{tuple(t.shape)}")
        out.append(t)
    return out, dtype, max(eps)
