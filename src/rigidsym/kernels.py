"""Batched NumPy/C kernels generated from the verified chapter-3 declarations.

Every kernel accepts array-likes with leading batch axes that broadcast (vectors
``(..., 3)``, matrices ``(..., 3, 3)`` row-major, twists ``[omega; v]``, wrenches ``[n; f]``,
float64), validates them, calls the generated code and returns new arrays (or fills
``out=``). The generated code lives in ``generated/`` (``rigidsym generate``); the C is
compiled through cffi on first use into the user cache (``rigidsym build-c``).

Common keyword arguments of every kernel:

* ``out``: preallocated output array (a tuple for several outputs), shape batch + output.
* ``check``: validate shapes, finiteness, unit vectors and rotations (default True).
* ``on_singular``: ``"raise"`` (default) raises :class:`SingularConfigurationError` naming
  the argument and the batch indices; ``"nan"`` returns NaN in exactly those rows.

Example:
    >>> import numpy as np
    >>> from rigidsym import kernels
    >>> Q = kernels.rotation_from_natural_invariants([0.0, 0.0, 1.0], np.pi / 2)
    >>> np.round(Q, 12).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
"""

from __future__ import annotations

import importlib.util
import inspect
import json
import math
import sys
import warnings
from collections.abc import Callable
from functools import cache

import numpy as np

__all__ = ["SingularConfigurationError", "use_backend", "backend", "swap_blocks",
           "batch_function", "euler_rate_matrix", "euler_angle_rates", "KERNEL_NAMES",
           "UNIT_TOL", "ORTHO_TOL"]

#: tolerance on | ||e|| - 1 | for unit-vector arguments (e, eta).
UNIT_TOL = 1e-8
#: tolerance on max |Q^T Q - 1| for rotation arguments (and det Q > 0).
ORTHO_TOL = 1e-8

_EULER_SEQUENCES = ("ZXZ", "XYX", "YZY", "ZYZ", "XZX", "YXY",
                    "XYZ", "YZX", "ZXY", "XZY", "ZYX", "YXZ")


class SingularConfigurationError(ValueError):
    """The kernel is evaluated on its singular set (division by an exact zero).

    Attributes:
        argument: the argument that makes the configuration singular.
        indices: the batch indices (tuples over the batch shape) of the singular samples.
    """

    def __init__(self, message: str, argument: str, indices: list):
        super().__init__(message)
        self.argument = argument
        self.indices = indices


@cache
def _meta() -> dict:
    from rigidsym.codegen.cbuild import generated_dir
    data = json.loads((generated_dir() / "kernels.json").read_text(encoding="utf-8"))
    return {k["name"]: k for k in data["kernels"]}


@cache
def _numpy_kernel(name: str) -> Callable:
    from rigidsym.codegen.cbuild import generated_dir
    path = generated_dir() / "numpy" / f"{name}.py"
    modname = f"rigidsym._generated_numpy.{name}"
    spec = importlib.util.spec_from_file_location(modname, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    sys.modules[modname] = mod
    return getattr(mod, name)


_STATE = {"backend": None, "warned": False, "lib": None}


def _c_lib():
    if _STATE["lib"] is None:
        from rigidsym.codegen.cbuild import load
        _STATE["lib"] = load()
    return _STATE["lib"]


def use_backend(name: str) -> str:
    """Select ``"c"`` (compiled through cffi) or ``"numpy"``; returns the backend in use.

    ``"c"`` falls back to ``"numpy"`` with a one-time warning when compiling fails (no
    compiler, no cffi).
    """
    if name not in ("c", "numpy"):
        raise ValueError(f"backend: expected 'c' or 'numpy', got {name!r}")
    if name == "c":
        try:
            _c_lib()
        except Exception as exc:  # noqa: BLE001 - any build failure means: no C backend
            if not _STATE["warned"]:
                warnings.warn(f"rigidsym.kernels: C backend unavailable ({exc}); using NumPy",
                              RuntimeWarning, stacklevel=2)
                _STATE["warned"] = True
            name = "numpy"
    _STATE["backend"] = name
    return name


def backend() -> str:
    """The backend in use (selects ``"c"`` with NumPy fallback on first call)."""
    if _STATE["backend"] is None:
        use_backend("c")
    return _STATE["backend"]


def batch_function(name: str, backend_name: str | None = None) -> Callable:
    """Low-level ``f(*inputs, *outputs) -> singular mask or count`` on C-contiguous
    ``(n, ...)`` float64 arrays, without validation or broadcasting (for benchmarks).

    For the C backend the return value is the number of singular samples (written as NaN);
    for NumPy it is the boolean mask of singular samples.
    """
    b = backend_name or backend()
    if b == "numpy":
        return _numpy_kernel(name)
    ffi, lib = _c_lib()
    cfun = getattr(lib, f"rigidsym_{name}")
    fb = ffi.from_buffer

    def f(*arrays):
        return cfun(arrays[0].shape[0], *[fb("double[]", a) for a in arrays])
    return f


def _as_array(x, arg: dict, check: bool) -> np.ndarray:
    a = np.asarray(x, dtype=np.float64)
    shape = tuple(arg["shape"])
    k = len(shape)
    if a.ndim < k or a.shape[a.ndim - k:] != shape:
        raise ValueError(f"{arg['name']}: expected shape (..., {', '.join(map(str, shape))})"
                         f"{'' if k else ' (a scalar per sample)'}, got {a.shape}")
    return a


def _validate(a: np.ndarray, arg: dict) -> None:
    name, kind = arg["name"], arg["kind"]
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: non-finite values")
    if kind == "unit":
        err = np.abs(np.sqrt(np.einsum("...i,...i->...", a, a)) - 1.0)
        if (err > UNIT_TOL).any():
            raise ValueError(f"{name}: not a unit vector (| ||{name}|| - 1 | = "
                             f"{err.max():.3g} > {UNIT_TOL})")
    elif kind == "rotation":
        g = np.einsum("...ki,...kj->...ij", a, a) - np.eye(3)
        err = np.abs(g).max() if g.size else 0.0
        if err > ORTHO_TOL:
            raise ValueError(f"{name}: not orthogonal (max |{name}^T {name} - 1| = "
                             f"{err:.3g} > {ORTHO_TOL})")
        if (np.linalg.det(a) <= 0).any():
            raise ValueError(f"{name}: not a proper rotation (det <= 0)")


def _call(name: str, args: tuple, out=None, check: bool = True,
          on_singular: str = "raise"):
    meta = _meta()[name]
    if on_singular not in ("raise", "nan"):
        raise ValueError(f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    specs = meta["args"]
    if len(args) != len(specs):
        raise TypeError(f"{name}() takes {len(specs)} arguments, got {len(args)}")
    arrs = [_as_array(x, s, check) for x, s in zip(args, specs, strict=True)]
    if check:
        for a, s in zip(arrs, specs, strict=True):
            _validate(a, s)
    batch = np.broadcast_shapes(*[a.shape[:a.ndim - len(s["shape"])]
                                  for a, s in zip(arrs, specs, strict=True)])
    n = math.prod(batch)
    flat = [np.ascontiguousarray(np.broadcast_to(a, batch + tuple(s["shape"])))
            .reshape((n,) + tuple(s["shape"])) for a, s in zip(arrs, specs, strict=True)]
    outs_meta = meta["outputs"]
    if out is not None:
        user = (out,) if len(outs_meta) == 1 and not isinstance(out, tuple) else tuple(out)
        if len(user) != len(outs_meta):
            raise ValueError(f"out: expected {len(outs_meta)} arrays")
        for u, o in zip(user, outs_meta, strict=True):
            want = batch + tuple(o["shape"])
            if not isinstance(u, np.ndarray) or u.shape != want or u.dtype != np.float64:
                raise ValueError(f"out ({o['name']}): expected a float64 array of shape {want}")
    else:
        user = None
    bufs = []
    for i, o in enumerate(outs_meta):
        shp = (n,) + tuple(o["shape"])
        u = None if user is None else user[i]
        if u is not None and u.flags.c_contiguous:
            bufs.append(u.reshape(shp))
        else:
            bufs.append(np.empty(shp))
    if n:
        b = backend()
        res = batch_function(name, b)(*flat, *bufs)
        if b == "numpy":
            mask = res
        else:
            mask = np.isnan(bufs[0].reshape(n, -1)[:, 0]) if res else None
        if mask is not None and mask.any():
            idx = np.flatnonzero(mask)
            if on_singular == "raise":
                where = [tuple(int(j) for j in np.unravel_index(i, batch)) for i in idx[:20]]
                arg = meta["singular_arg"] or specs[0]["name"]
                raise SingularConfigurationError(
                    f"{name}: singular configuration ({meta['singular'] or 'non-finite result'}"
                    f") in argument {arg!r} at batch indices {where}"
                    f"{' ...' if len(idx) > 20 else ''}", arg, where)
            for buf in bufs:
                buf[idx] = np.nan
    results = []
    for i, o in enumerate(outs_meta):
        shp = batch + tuple(o["shape"])
        r = bufs[i].reshape(shp)
        if user is not None:
            if user[i].flags.c_contiguous:
                r = user[i]
            else:
                user[i][...] = r
                r = user[i]
        results.append(r)
    return results[0] if len(results) == 1 else tuple(results)


def _doc(meta: dict) -> str:
    def shp(s):
        return "(...)" if not s else f"(..., {', '.join(map(str, s))})"
    lines = [meta["summary"], "", f"    {meta['formula']}", "",
             f"Book: Eq. {', '.join('(' + i + ')' for i in meta['ids'])}; composed of "
             f"{', '.join(meta['sources'])}.", "", "Args:"]
    for a in meta["args"]:
        kind = {"unit": ", unit", "rotation": ", proper orthogonal"}.get(a["kind"], "")
        lines.append(f"    {a['name']}: array-like {shp(a['shape'])}{kind}; {a['doc']}")
    lines += ["    out, check, on_singular: see :mod:`rigidsym.kernels`.", "", "Returns:"]
    for o in meta["outputs"]:
        lines.append(f"    {o['name']}: ndarray {shp(o['shape'])}; {o['doc']}")
    lines += ["", "Raises:", "    ValueError: bad shape, non-finite input, non-unit or "
              "non-orthogonal argument."]
    if meta["singular"]:
        lines += ["    SingularConfigurationError: on the singular set "
                  f"({meta['singular']}), unless on_singular='nan'.",
                  "", "Notes:", f"    Singular set: {meta['singular']}."]
    if meta["notes"]:
        lines += ["", f"    {meta['notes']}"]
    lines += ["", f"    Generated; {meta['ops']} operations; math hash {meta['hash']}."]
    return "\n".join(lines)


def _make(name: str) -> Callable:
    meta = _meta()[name]

    def kernel(*args, out=None, check=True, on_singular="raise"):
        return _call(name, args, out=out, check=check, on_singular=on_singular)
    kernel.__name__ = kernel.__qualname__ = name
    kernel.__doc__ = _doc(meta)
    P = inspect.Parameter
    kernel.__signature__ = inspect.Signature(
        [P(a["name"], P.POSITIONAL_OR_KEYWORD) for a in meta["args"]]
        + [P("out", P.KEYWORD_ONLY, default=None), P("check", P.KEYWORD_ONLY, default=True),
           P("on_singular", P.KEYWORD_ONLY, default="raise")])
    kernel.__module__ = __name__
    return kernel


KERNEL_NAMES = tuple(sorted(k for k, m in _meta().items() if m["public"]))
for _name in KERNEL_NAMES:
    globals()[_name] = _make(_name)
__all__ += list(KERNEL_NAMES)


def _euler_name(kind: str, sequence: str, frame: str) -> str:
    seq = str(sequence).upper()
    if seq not in _EULER_SEQUENCES:
        raise ValueError(f"sequence: expected one of {', '.join(_EULER_SEQUENCES)}, "
                         f"got {sequence!r}")
    if frame not in ("fixed", "body"):
        raise ValueError(f"frame: expected 'fixed' or 'body', got {frame!r}")
    return f"{kind}_{seq.lower()}_{frame}"


def euler_rate_matrix(angles, sequence: str, frame: str = "fixed", *, out=None,
                      check: bool = True):
    """Euler-angle rate matrix ``W`` with ``omega = W eta_dot`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3), the intrinsic Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".

    Returns:
        ndarray (..., 3, 3).

    Example:
        >>> euler_rate_matrix([0.1, 0.2, 0.3], "ZYX").shape
        (3, 3)
    """
    return _call(_euler_name("euler_rate_matrix", sequence, frame), (angles,), out=out,
                 check=check)


def euler_angle_rates(angles, omega, sequence: str, frame: str = "fixed", *, out=None,
                      check: bool = True, on_singular: str = "raise"):
    """Euler-angle rates ``eta_dot = W^-1 omega`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3) [rad]; omega: array-like (..., 3) [rad/s].
        sequence: one of the twelve intrinsic sequences; frame: "fixed" or "body".

    Returns:
        ndarray (..., 3) [rad/s].

    Raises:
        SingularConfigurationError: at gimbal lock (det W = 0), unless on_singular="nan".
    """
    return _call(_euler_name("euler_angle_rates", sequence, frame), (angles, omega), out=out,
                 check=check, on_singular=on_singular)


def swap_blocks(x, matrix: bool = False) -> np.ndarray:
    """Swap the 3-blocks of 6-arrays: ``[omega; v] <-> [v; omega]``, ``[n; f] <-> [f; n]``.

    Converts to and from the order of Pinocchio and ROS. With ``matrix=True`` a
    ``(..., 6, 6)`` operator is converted (rows and columns).

    Example:
        >>> swap_blocks([1, 2, 3, 4, 5, 6]).tolist()
        [4.0, 5.0, 6.0, 1.0, 2.0, 3.0]
    """
    a = np.asarray(x, dtype=np.float64)
    perm = [3, 4, 5, 0, 1, 2]
    if matrix:
        if a.shape[-2:] != (6, 6):
            raise ValueError(f"x: expected shape (..., 6, 6), got {a.shape}")
        return a[..., perm, :][..., perm]
    if a.shape[-1:] != (6,):
        raise ValueError(f"x: expected shape (..., 6), got {a.shape}")
    return a[..., perm]

from ._jacobian import jacobian  # noqa: E402,F401 - re-exported; imports kernels lazily
