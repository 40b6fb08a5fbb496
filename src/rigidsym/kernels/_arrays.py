"""What the PyTorch and JAX kernels share (issue 31): no import of either library.

Both back-ends evaluate the same generated programs (``generated/torch``, ``generated/jax``:
:mod:`rigidsym.codegen.arrays`) on array modules with the same names for what is needed
here (``where``, ``stack``, ``isfinite``, ``broadcast_to``, ``einsum``, ``linalg.det``):
``xp`` below is ``torch`` or ``jax.numpy``. This module holds the directory of programs,
the keyword rules of traced and eager calls, validation of constrained inputs, the
selection of a branch kernel's variant with the safe-``where`` idiom, and the call path both
back-ends share (:class:`Space`: conversion, modes, validation, broadcasting, the singular
and overflow masks); each back-end supplies only what differs, as a :class:`Library`. It
re-exports ``contract`` (``_jacobian``) and ``raise_flagged``; a back-end module's public
face is :mod:`rigidsym.kernels._arrays_api`.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from rigidsym import _kinds
from rigidsym._config import generated_dir
from rigidsym._io import load_module
from rigidsym.kernels._errors import raise_flagged
from rigidsym.kernels._jacobian import contract
from rigidsym.kernels._jacobian import full_batch as _full

__all__ = ["ArraySpace", "Library", "Space", "modes", "validate", "evaluate", "contract",
           "raise_flagged", "SUFFIX", "make_all", "broadcast_batch", "convert"]

#: suffix of the generated kernels with Jacobians (rigidsym.codegen.jacobians.SUFFIX)
SUFFIX = "_with_jacobians"
_MODES = ("raise", "nan")


@dataclass
class ArraySpace:
    """The generated programs of one directory for one back-end (``"torch"``, ``"jax"``)."""

    directory: Path
    backend: str
    meta: dict
    _programs: dict = field(default_factory=dict)

    @classmethod
    def from_directory(cls, directory: str | Path | None, backend: str) -> ArraySpace:
        """Read ``directory/kernels.json`` (default the package's ``generated/``).

        Raises:
            FileNotFoundError: no ``kernels.json``, or no ``<backend>/`` folder (a directory
                generated before the back-end existed: regenerate it).
        """
        d = (generated_dir() if directory is None else Path(directory)).resolve()
        if not (d / "kernels.json").is_file() or not (d / backend).is_dir():
            raise FileNotFoundError(f"directory: no kernels.json or {backend}/ in {d} (run "
                                    f"`rigidsym generate --out {d}`)")
        data = json.loads((d / "kernels.json").read_text(encoding="utf-8"))
        meta = {k["name"]: k for k in data["kernels"]}
        return cls(d, backend, meta)

    def kernel_names(self) -> list[str]:
        """The public kernels, sorted."""
        return sorted(n for n, m in self.meta.items() if m["public"])

    def has_jacobian(self, name: str) -> bool:
        return name + SUFFIX in self.meta

    def variants(self, name: str) -> tuple:
        """``((name, program, condition or None), ...)`` of kernel ``name``'s module."""
        v = self._programs.get(name)
        if v is None:
            key = abs(hash((str(self.directory), self.backend))) % 10**12
            mod = load_module(f"rigidsym._{self.backend}_{key}.{name}",
                              self.directory / self.backend / f"{name}.py")
            v = self._programs[name] = mod.VARIANTS
        return v


def make_all(progs: ArraySpace, make: Callable) -> dict:
    """``{name: make(name)}`` for every kernel of ``progs`` but the Jacobian kernels, every
    program loaded first (0.15 s for the package's 134 kernels): never inside a traced call,
    so torch.compile(fullgraph=True) and jit see only tensor code."""
    for name in progs.meta:
        progs.variants(name)
    return {name: make(name) for name in progs.meta if not name.endswith(SUFFIX)}


def _raise(exc_type: type, message: str):
    raise exc_type(message)


def modes(check: bool | None, on_singular: str | None, traced: bool, where: str,
          refuse: Callable = _raise):
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


def validate(xp, arrays: list, args: list[dict]) -> None:
    """Eager validation: finite values, unit vectors, proper rotations (the kind table's
    tolerances for the dtype); one reduction per argument read on the host.

    Raises:
        ValueError: naming the argument.
    """
    for x, a in zip(arrays, args, strict=True):
        if not bool(xp.isfinite(x).all()):
            raise ValueError(f"{a['name']}: non-finite value (NaN or inf)")
        kind = _kinds.for_spec(a["kind"], tuple(a["shape"]))
        if kind is None or kind.check is None or not _numel(x):
            continue
        tol = kind.tolerance(np.dtype(str(x.dtype).replace("torch.", "")))
        if kind.shape == (3, 3):
            ident = xp.eye(3, dtype=x.dtype)
            if hasattr(ident, "to"):  # torch: on the input's device (found on a GPU)
                ident = ident.to(x.device)
            g = xp.einsum("...ki,...kj->...ij", x, x) - ident
            err = float(xp.abs(g).max())
            if not err <= tol:
                raise ValueError(f"{a['name']}: not orthogonal (max |{a['name']}^T "
                                 f"{a['name']} - 1| = {err:.3g} > {tol:.3g})")
            if bool((xp.linalg.det(x) <= 0).any()):
                raise ValueError(f"{a['name']}: not a proper rotation (det <= 0)")
        elif len(kind.shape) == 1:
            err = float(xp.abs(xp.sqrt((x * x).sum(-1)) - 1.0).max())
            if err > tol:
                raise ValueError(f"{a['name']}: not a unit vector (| ||{a['name']}|| - 1 | = "
                                 f"{err:.3g} > {tol:.3g})")


def broadcast_batch(broadcast_shapes: Callable, xs: list, args: list[dict]) -> tuple:
    """The broadcast batch shape of ``xs`` (each less its argument's own trailing shape).

    Raises:
        ValueError: the batch shapes do not broadcast (each argument's shape named).
    """
    try:
        return tuple(broadcast_shapes(*[x.shape[:x.ndim - len(a["shape"])]
                                        for x, a in zip(xs, args, strict=True)]))
    except (RuntimeError, ValueError):  # torch raises RuntimeError, JAX ValueError
        shapes = ", ".join(f"{a['name']} {tuple(x.shape)}" for x, a in zip(xs, args,
                                                                             strict=True))
        raise ValueError(f"batch shapes do not broadcast: {shapes}") from None


def _numel(x) -> int:
    return int(math.prod(x.shape))


def columns(arrays: list, args: list[dict]) -> list:
    """One array per scalar component (row-major), each of the batch shape."""
    cols = []
    for x, a in zip(arrays, args, strict=True):
        if not a["shape"]:
            cols.append(x)
            continue
        n = int(math.prod(a["shape"]))
        flat = x.reshape(tuple(x.shape[:len(x.shape) - len(a["shape"])]) + (n,))
        cols.extend(flat[..., i] for i in range(n))
    return cols


def shape_outputs(xp, flat: list, outs: list[dict], like) -> list:
    """The flat outputs of a program as arrays ``batch + output shape``."""
    res, k = [], 0
    batch = tuple(like.shape)
    for o in outs:
        n = int(math.prod(o["shape"]))
        parts = [_full(xp, v, like) for v in flat[k:k + n]]
        k += n
        res.append(parts[0] if not o["shape"] else
                   xp.stack(parts, -1).reshape(batch + tuple(o["shape"])))
    return res


def evaluate(xp, variants: tuple, cols: list, stop_gradient: Callable) -> tuple[list, Any]:
    """Run a kernel's variants on ``cols``: ``(flat outputs, singular mask)``.

    A kernel with branches takes, per sample, the first branch whose condition holds, else
    main (the NumPy kernel's rule). Safe ``where``: each variant sees the real inputs only
    in its own samples and ``stop_gradient`` of them elsewhere, so a NaN or inf derivative
    of a branch not taken never reaches the gradient.
    """
    like = cols[0]
    if len(variants) == 1:
        outs, dens = variants[0][1](*cols)
        sing = _singular(xp, dens, like)
        return list(outs), sing
    taken, rest = [], None
    for _, _, when in variants[:-1]:
        hit = when(*cols)
        hit = hit if rest is None else xp.logical_and(rest, hit)
        rest = xp.logical_not(hit) if rest is None else xp.logical_and(rest, xp.logical_not(hit))
        taken.append(hit)
    taken.append(rest)
    result = sing = None
    for (_, prog, _), hit in zip(reversed(variants), reversed(taken), strict=True):
        safe = [xp.where(hit, c, stop_gradient(c)) for c in cols]
        outs, dens = prog(*safe)
        s = _singular(xp, dens, like)
        outs = [_full(xp, v, like) for v in outs]
        if result is None:
            result, sing = outs, s
        else:
            result = [xp.where(hit, v, r) for v, r in zip(outs, result, strict=True)]
            sing = xp.where(hit, s, sing)
    return result, sing


def _singular(xp, dens, like):
    sing = xp.zeros_like(like, dtype=bool) if hasattr(like, "dtype") else None
    for d in dens:
        sing = xp.logical_or(sing, d == 0)
    return sing


def _shp(s) -> str:
    return "(...)" if not s else f"(..., {', '.join(map(str, s))})"


# ------------------------------------------------ the call path both back-ends share
@dataclass(frozen=True)
class Library:
    """What differs between the array back-ends; :class:`Space` does the rest.

    Fields: ``backend`` (``"torch"``, ``"jax"``), ``xp`` (``torch``, ``jax.numpy``),
    ``tracer`` (the tracers' names in errors), ``traced(xs)`` (an input is traced: no host
    reads), ``stop_gradient``, ``detach`` (a view for host reads), ``is_array(v)`` (the
    library's own array), ``real(v)`` (a library array holds real numbers), ``dtype(values,
    arrays)`` (the working dtype of the raw ``values``, once ``arrays`` are the library
    arrays and NumPy arrays they became), ``as_array(v, dtype, device, name)`` (convert, or
    raise naming ``name``), ``device(arrays)``, ``host(x)`` (a NumPy copy), ``make(space,
    name)`` (``f(*broadcast inputs) -> (*outputs, singular)``, with the derivative rule),
    ``refuse(exc_type, message)`` (raises the refusals of :func:`modes`) and ``note(values)``
    (a warning before conversion, or nothing).
    """

    backend: str
    xp: Any
    tracer: str
    traced: Callable
    stop_gradient: Callable
    detach: Callable
    is_array: Callable
    real: Callable
    dtype: Callable
    as_array: Callable
    device: Callable
    host: Callable
    make: Callable
    refuse: Callable = _raise
    note: Callable = lambda values: None


_BAD_KINDS = "bcOUSMmV"  # NumPy kinds that are no real numbers


def convert(lib: Library, values: tuple, args: list[dict]) -> list:
    """The library arrays of ``values``, of one floating dtype on one device.

    Raises:
        TypeError: an argument holds no real numbers (named).
        ValueError: ragged, on another device, or the wrong trailing shape (named).
    """
    lib.note(values)
    arrays = []
    for v, a in zip(values, args, strict=True):
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
        arrays.append(v)
    dtype, device = lib.dtype(values, arrays), lib.device(arrays)
    out = []
    for v, a in zip(arrays, args, strict=True):
        t = lib.as_array(v, dtype, device, a["name"])
        shape = tuple(a["shape"])
        if t.ndim < len(shape) or tuple(t.shape[t.ndim - len(shape):]) != shape:
            raise ValueError(f"{a['name']}: expected shape {_shp(shape)}, got "
                             f"{tuple(t.shape)}")
        out.append(t)
    return out


class Space:
    """The kernels of one generated directory in one back-end: ``call`` is the public path."""

    def __init__(self, lib: Library, directory):
        self.lib = lib
        self.progs = ArraySpace.from_directory(directory, lib.backend)
        self._fns = make_all(self.progs, lambda name: lib.make(self, name))

    def function(self, name: str) -> Callable:
        """``f(*broadcast inputs) -> (*outputs, singular)`` of kernel ``name``, with its
        back-end's derivative rule."""
        return self._fns[name]

    def values(self, name: str, xs) -> tuple:
        """``(*outputs, singular)`` of kernel ``name`` on broadcast inputs ``xs``."""
        xp, outs = self.lib.xp, self.progs.meta[name]["outputs"]
        cols = columns(xs, self.progs.meta[name]["args"])
        flat, sing = evaluate(xp, self.progs.variants(name), cols, self.lib.stop_gradient)
        return (*shape_outputs(xp, flat, outs, cols[0]), sing)

    def jacobian(self, name: str, xs) -> list:
        """The entries of the generated Jacobian kernel of ``name`` at ``xs``, flat."""
        meta = self.progs.meta[name]
        nval = sum(math.prod(o["shape"]) for o in meta["outputs"])
        flat, _ = evaluate(self.lib.xp, self.progs.variants(name + SUFFIX),
                           columns(xs, meta["args"]), self.lib.stop_gradient)
        return flat[nval:]

    def call(self, name: str, values: tuple, check, on_singular):
        """Kernel ``name`` on ``values`` (the public functions' body): convert, validate
        (``check``), broadcast, evaluate, then flag the singular (and, checked, overflowed)
        samples: an error (``on_singular="raise"``) or NaN there."""
        lib, xp = self.lib, self.lib.xp
        meta = self.progs.meta[name]
        args = meta["args"]
        xs = convert(lib, values, args)
        check, on_singular = modes(check, on_singular, lib.traced(xs), lib.tracer, lib.refuse)
        batch = broadcast_batch(xp.broadcast_shapes, xs, args)
        if check:
            validate(xp, [lib.detach(x) for x in xs], args)
        full = [xp.broadcast_to(x, batch + tuple(a["shape"])) for x, a in zip(xs, args,
                                                                             strict=True)]
        *res, sing = self.function(name)(*full)
        bad = sing
        if check:
            over = xp.zeros_like(sing)
            for r in res:
                over = over | ~xp.isfinite(r.reshape(batch + (-1,))).all(-1)
            bad = sing | (over & ~sing)
        if on_singular == "raise":
            if bool(bad.any()):  # the error path copies the masks to the host
                raise_flagged(name, meta, lib.host(sing), lib.host(bad & ~sing),
                              [lib.host(lib.detach(x)) for x in xs])
        else:
            res = [xp.where(bad.reshape(batch + (1,) * (r.ndim - len(batch))), xp.nan, r)
                   for r in res]
        return res[0] if len(res) == 1 else tuple(res)
