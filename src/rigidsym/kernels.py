"""Batched NumPy/C kernels generated from the verified chapter-3 declarations.

Every kernel accepts array-likes with leading batch axes that broadcast (vectors
``(..., 3)``, matrices ``(..., 3, 3)`` row-major, twists ``[omega; v]``, wrenches ``[n; f]``,
float64), validates them, calls the generated code and returns new arrays (or fills
``out=``). The generated code lives in ``generated/`` (``rigidsym generate``); the C is
compiled through cffi on first use into the user cache (``rigidsym build-c``).

Common keyword arguments of every kernel:

* ``out``: preallocated output array (a tuple for several outputs), shape batch + output.
* ``threads``: threads of the C batch loop (OpenMP); None: :func:`get_num_threads`
  (:func:`set_num_threads`, else ``RIGIDSYM_NUM_THREADS``, else 1). Outputs do not depend on
  it (bit for bit). The NumPy backend runs one thread (one warning when more are asked).
* ``check``: validate shapes, finiteness, unit vectors and rotations (default True).
* ``on_singular``: ``"raise"`` (the default for NumPy inputs) raises
  :class:`SingularConfigurationError` naming the argument and the batch indices; ``"nan"``
  (the default for Dask inputs) returns NaN in exactly those rows.

float32: the dtype is ``np.result_type`` of the array inputs (NEP 50: Python floats are weak,
so float32 arrays with a Python float stay float32; lists and integers are float64). float32
inputs run float32 C (or NumPy) batch functions that widen each block to float64, evaluate
the same generated code and round the outputs once: error against the 50-digit reference at
the same float32 inputs measured at most 0.49 ulp of float32 (max-norm relative), at random
points and near phi -> 0, pi, ||omega|| -> 0, gimbal lock and Q near 1 and pi alike
(``tests/test_float32.py``); an output that overflows float32 is flagged like any overflow.
``out=`` must have the inputs' dtype (``TypeError`` naming ``out``); the unit and
orthogonality tolerances are ``max(UNIT_TOL, 100 eps)`` of the argument's dtype.

Dask arrays in (NumPy arrays mixed in are wrapped): the result is lazy Dask arrays chunked
along the batch axes; nothing is computed until the caller computes (:mod:`rigidsym._dask`).

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
import threading
import warnings
from collections.abc import Callable
from functools import cache

import numpy as np

from rigidsym import _dask, _scale
from rigidsym._scale import get_num_threads, set_num_threads

__all__ = ["SingularConfigurationError", "NonFiniteResultError", "use_backend", "backend",
           "set_num_threads", "get_num_threads",
           "swap_blocks", "batch_function", "euler_rate_matrix", "euler_angle_rates",
           "KERNEL_NAMES", "UNIT_TOL", "ORTHO_TOL"]

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

    def __reduce__(self):
        # pickled with its fields (distributed re-raises a worker's error on the client)
        return (type(self), (str(self), self.argument, self.indices))


class NonFiniteResultError(SingularConfigurationError):
    """Finite inputs gave a non-finite output (overflow): reported with ``check=True``.

    Attributes:
        argument: the input of largest magnitude in the offending samples.
        indices: the batch indices (tuples over the batch shape) of those samples.
    """


#: sample flags of the generated batch functions (see numpy_kernel.py.j2)
_SINGULAR, _NONFINITE = 1, 2


def _classify_c_rows(name: str, flat: list, bufs: list, n: int) -> np.ndarray:
    """Flags of the C batch: it writes NaN rows without saying why; the NumPy kernel,
    re-run on just those rows, tells a singular sample from an overflow."""
    idx = np.flatnonzero(np.isnan(bufs[0].reshape(n, -1)[:, 0]))
    flags = np.zeros(n, dtype=np.uint8)
    if idx.size:
        tmp = [np.empty((idx.size,) + b.shape[1:]) for b in bufs]
        sub = _numpy_kernel(name)(*[np.ascontiguousarray(a[idx], dtype=np.float64)
                                    for a in flat], *tmp)
        # a row C flagged and NumPy did not (rounding at the edge of the range): overflow
        flags[idx] = np.where(sub == 0, _NONFINITE, sub)
    return flags


def _report_flags(name, meta, flags, flat, bufs, batch, check, on_singular) -> None:
    """Raise for flagged samples, or write NaN in their rows (``on_singular="nan"``)."""
    specs = meta["args"]
    sing = np.flatnonzero(flags == _SINGULAR)
    over = np.flatnonzero(flags == _NONFINITE) if check else np.empty(0, dtype=np.intp)

    def where(idx):
        return [tuple(int(j) for j in np.unravel_index(i, batch)) for i in idx[:20]]
    more = " ..."
    if on_singular == "raise" and sing.size:
        arg = meta["singular_arg"] or specs[0]["name"]
        w = where(sing)
        raise SingularConfigurationError(
            f"{name}: singular configuration ({meta['singular'] or 'non-finite result'}"
            f") in argument {arg!r} at batch indices {w}{more if sing.size > 20 else ''}",
            arg, w)
    if on_singular == "raise" and over.size:
        # name the input of largest magnitude there: the likely cause of the overflow
        mags = [np.abs(a[over]).max() for a in flat]
        k = int(np.argmax(mags))
        arg, w = specs[k]["name"], where(over)
        raise NonFiniteResultError(
            f"{name}: non-finite output (overflow) from finite inputs at batch indices {w}"
            f"{more if over.size > 20 else ''}; largest input there: {arg!r} "
            f"(max |{arg}| = {mags[k]:.3g})", arg, w)
    for buf in bufs:
        buf[sing] = np.nan
        buf[over] = np.nan


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
# one lock for the lazy build and the backend switch: kernels may first be called from
# several threads at once (a thread pool, a Dask worker)
_LOCK = threading.RLock()


def _c_lib():
    lib = _STATE["lib"]
    if lib is None:
        with _LOCK:
            if _STATE["lib"] is None:
                from rigidsym.codegen.cbuild import load
                _STATE["lib"] = load()
            lib = _STATE["lib"]
    return lib


def use_backend(name: str) -> str:
    """Select ``"c"`` (compiled through cffi) or ``"numpy"``; returns the backend in use.

    ``"c"`` falls back to ``"numpy"`` with a one-time warning when compiling fails (no
    compiler, no cffi).
    """
    if name not in ("c", "numpy"):
        raise ValueError(f"backend: expected 'c' or 'numpy', got {name!r}")
    with _LOCK:
        if name == "c":
            try:
                _c_lib()
            except Exception as exc:  # noqa: BLE001 - any build failure means: no C backend
                if not _STATE["warned"]:
                    warnings.warn(f"rigidsym.kernels: C backend unavailable ({exc}); "
                                  "using NumPy", RuntimeWarning, stacklevel=2)
                    _STATE["warned"] = True
                name = "numpy"
        _STATE["backend"] = name
    return name


def backend() -> str:
    """The backend in use (selects ``"c"`` with NumPy fallback on first call)."""
    b = _STATE["backend"]
    if b is None:
        with _LOCK:
            b = _STATE["backend"] or use_backend("c")
    return b


def batch_function(name: str, backend_name: str | None = None,
                   threads: int | None = None, dtype=np.float64) -> Callable:
    """Low-level ``f(*inputs, *outputs) -> singular mask or count`` on C-contiguous
    ``(n, ...)`` float64 arrays, without validation or broadcasting (for benchmarks).

    For the C backend the return value is the number of singular samples (written as NaN);
    for NumPy it is the boolean mask of singular samples. ``threads`` as for the kernels
    (None: :func:`get_num_threads`); the outputs are the same for every thread count.
    ``dtype`` float32: float32 arrays in and out, float64 arithmetic inside.
    """
    b = backend_name or backend()
    t = _scale.resolve_threads(threads, b)
    f32 = np.dtype(dtype) == np.float32
    if b == "numpy":
        return _scale.numpy_f32(_numpy_kernel(name), len(_meta()[name]["args"])) if f32 \
            else _numpy_kernel(name)
    ffi, lib = _c_lib()
    cfun = getattr(lib, f"rigidsym_{name}_f32_threads" if f32 else f"rigidsym_{name}_threads")
    fb = ffi.from_buffer
    ctype = "float[]" if f32 else "double[]"

    def f(*arrays):
        n = arrays[0].shape[0]
        return cfun(n, t if n >= _scale.MIN_PARALLEL else 1, *[fb(ctype, a) for a in arrays])
    return f


def _as_array(x, arg: dict, check: bool, dtype=np.float64) -> np.ndarray:
    a = np.asarray(x, dtype=dtype)
    shape = tuple(arg["shape"])
    k = len(shape)
    if a.ndim < k or a.shape[a.ndim - k:] != shape:
        raise ValueError(f"{arg['name']}: expected shape (..., {', '.join(map(str, shape))})"
                         f"{'' if k else ' (a scalar per sample)'}, got {a.shape}")
    return a


def _validate(a: np.ndarray, arg: dict, given=None) -> None:
    """Finiteness, unit vectors, rotations; tolerances of the dtype ``given`` (the argument's
    own, e.g. float32 values in a float64 call keep the float32 tolerance)."""
    name, kind = arg["name"], arg["kind"]
    prec = given if given is not None and given.kind == "f" and given.itemsize < 8 else a.dtype
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: non-finite values")
    if kind == "unit":
        err = np.abs(np.sqrt(np.einsum("...i,...i->...", a, a)) - 1.0)
        tol = _scale.tolerance(UNIT_TOL, prec)
        if (err > tol).any():
            raise ValueError(f"{name}: not a unit vector (| ||{name}|| - 1 | = "
                             f"{err.max():.3g} > {tol:.3g})")
    elif kind == "rotation":
        g = np.einsum("...ki,...kj->...ij", a, a) - np.eye(3)
        err = np.abs(g).max() if g.size else 0.0
        tol = _scale.tolerance(ORTHO_TOL, prec)
        if err > tol:
            raise ValueError(f"{name}: not orthogonal (max |{name}^T {name} - 1| = "
                             f"{err:.3g} > {tol:.3g})")
        if (np.linalg.det(a) <= 0).any():
            raise ValueError(f"{name}: not a proper rotation (det <= 0)")


def _call(name: str, args: tuple, out=None, check: bool = True,
          on_singular: str | None = None, threads: int | None = None):
    if _dask.is_dask(args):
        return _dask.apply(name, args, out=out, check=check, on_singular=on_singular,
                           threads=threads)
    on_singular = "raise" if on_singular is None else on_singular
    meta = _meta()[name]
    if on_singular not in ("raise", "nan"):
        raise ValueError(f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    specs = meta["args"]
    if len(args) != len(specs):
        raise TypeError(f"{name}() takes {len(specs)} arguments, got {len(args)}")
    dtype = _scale.result_dtype(args)
    arrs = [_as_array(x, s, check, dtype) for x, s in zip(args, specs, strict=True)]
    if check:
        for x, a, s in zip(args, arrs, specs, strict=True):
            _validate(a, s, getattr(x, "dtype", None))
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
            if isinstance(u, np.ndarray) and u.dtype != dtype:
                raise TypeError(f"out ({o['name']}): expected dtype {dtype} (the inputs' "
                                f"dtype), got {u.dtype}")
            if not isinstance(u, np.ndarray) or u.shape != want:
                raise ValueError(f"out ({o['name']}): expected a {dtype} array of shape {want}")
    else:
        user = None
    bufs = []
    for i, o in enumerate(outs_meta):
        shp = (n,) + tuple(o["shape"])
        u = None if user is None else user[i]
        if u is not None and u.flags.c_contiguous:
            bufs.append(u.reshape(shp))
        else:
            bufs.append(np.empty(shp, dtype=dtype))
    if n:
        b = backend()
        res = batch_function(name, b, threads, dtype)(*flat, *bufs)
        if b == "numpy":
            flags = res
        elif res:
            flags = _classify_c_rows(name, flat, bufs, n)
        else:
            flags = None
        if flags is not None and flags.any():
            _report_flags(name, meta, flags, flat, bufs, batch, check, on_singular)
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
    lines += ["    out, check, on_singular, threads: see :mod:`rigidsym.kernels`.", "", "Returns:"]
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

    def kernel(*args, out=None, check=True, on_singular=None, threads=None):
        return _call(name, args, out=out, check=check, on_singular=on_singular,
                     threads=threads)
    kernel.__name__ = kernel.__qualname__ = name
    kernel.__doc__ = _doc(meta)
    P = inspect.Parameter
    kernel.__signature__ = inspect.Signature(
        [P(a["name"], P.POSITIONAL_OR_KEYWORD) for a in meta["args"]]
        + [P("out", P.KEYWORD_ONLY, default=None), P("check", P.KEYWORD_ONLY, default=True),
           P("on_singular", P.KEYWORD_ONLY, default=None),
           P("threads", P.KEYWORD_ONLY, default=None)])
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
                      check: bool = True, threads: int | None = None):
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
                 check=check, threads=threads)


def euler_angle_rates(angles, omega, sequence: str, frame: str = "fixed", *, out=None,
                      check: bool = True, on_singular: str | None = None,
                      threads: int | None = None):
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
                 check=check, on_singular=on_singular, threads=threads)


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
