"""What the PyTorch and JAX kernels share (issue 31): no import of either library.

Both back-ends evaluate the same generated programs (``generated/torch``, ``generated/jax``:
:mod:`rigidsym.codegen.arrays`) on array modules with the same names for what is needed
here (``where``, ``stack``, ``isfinite``, ``broadcast_to``, ``einsum``, ``linalg.det``):
``xp`` below is ``torch`` or ``jax.numpy``. This module holds the directory of programs,
the keyword rules of traced and eager calls, validation of constrained inputs, the
selection of a branch kernel's variant with the safe-``where`` idiom, and a back-end module's
functions (:func:`module_api`); it re-exports ``contract`` (``_jacobian``) and ``raise_flagged``.
"""

from __future__ import annotations

import json
import math
import types
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from rigidsym import _kinds
from rigidsym._config import generated_dir
from rigidsym._io import load_module
from rigidsym.kernels import _state
from rigidsym.kernels._errors import raise_flagged
from rigidsym.kernels._jacobian import contract
from rigidsym.kernels._jacobian import full_batch as _full

__all__ = ["ArraySpace", "modes", "validate", "evaluate", "contract", "raise_flagged",
           "SUFFIX", "make_kernel", "namespace", "docstring", "module_api",
           "make_all", "broadcast_batch"]

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


def docstring(meta: dict, backend: str, derivative: str) -> str:
    """The docstring of a back-end kernel, from its ``kernels.json`` entry."""
    lib = {"torch": "torch.Tensor", "jax": "jax.Array"}[backend]
    lines = [meta["summary"], "", f"    {meta['formula']}", "",
             f"Book: Eq. {', '.join('(' + i + ')' for i in meta['ids'])}.", "", "Args:"]
    for a in meta["args"]:
        lines.append(f"    {a['name']}: {lib} or array-like {_shp(a['shape'])}; {a['doc']}")
    lines += [f"    check, on_singular: see :mod:`rigidsym.kernels.{backend}`.", "",
              "Returns:"]
    lines += [f"    {lib} {_shp(o['shape'])}: {o['name']}" for o in meta["outputs"]]
    lines += ["", "Raises:", "    TypeError, ValueError: bad argument (naming it), or check=True"
              " / on_singular='raise' while traced."]
    if meta["singular"]:
        lines.append(f"    SingularConfigurationError: on the singular set "
                     f"({meta['singular']}), eager and on_singular='raise'.")
    lines += ["", "Notes:", f"    Derivative: {derivative}",
              f"    Generated; {meta['ops']} operations; math hash {meta['hash']}."]
    return "\n".join(lines)


def make_kernel(progs: ArraySpace, call: Callable, name: str, module: str) -> Callable:
    """The public function of kernel ``name``: the kernel's arguments (positional or
    keyword), then ``check`` and ``on_singular`` (keyword-only); ``call(name, values,
    check, on_singular)`` evaluates it."""
    meta = progs.meta[name]
    names = [a["name"] for a in meta["args"]]
    params = ", ".join(names)
    # a def of its own per kernel (not one closure for all): its real signature, and a code
    # object of its own, so torch.compile's per-code-object recompile limit (8) is not
    # shared by every kernel a program compiles
    scope: dict = {"_call": call}
    exec(f"def {name}({params}, *, check=None, on_singular=None):\n"  # noqa: S102
         f"    return _call({name!r}, ({params},), check, on_singular)\n", scope)
    fn = scope[name]
    fn.__name__ = fn.__qualname__ = name
    fn.__module__ = module
    lib = {"torch": "torch.autograd.Function", "jax": "jax.custom_jvp"}[progs.backend]
    deriv = (f"the generated Jacobian kernel {name}{SUFFIX} ({lib})"
             if progs.has_jacobian(name) else
             "autograd through the generated expression (safe where at branches)")
    fn.__doc__ = docstring(meta, progs.backend, deriv)
    return fn


def namespace(progs: ArraySpace, call: Callable, title: str) -> types.ModuleType:
    """A namespace (module object) with the public kernels of ``progs`` and
    ``KERNEL_NAMES``."""
    ns = types.ModuleType(title)
    names = progs.kernel_names()
    for n in names:
        setattr(ns, n, make_kernel(progs, call, n, title))
    ns.KERNEL_NAMES = tuple(names)  # type: ignore[attr-defined]
    ns.__all__ = [*names, "KERNEL_NAMES"]  # type: ignore[attr-defined]
    return ns


# --------------------------------------------------------------- a back-end module's API
_LOAD_DOC = """The {lib} kernels of a generated directory (``rigidsym generate --out DIR``).

    Args:
        directory: a folder with ``kernels.json`` and ``{backend}/``; default the package's.

    Returns:
        A namespace with one function per public kernel and ``KERNEL_NAMES``.

    Raises:
        FileNotFoundError: no ``kernels.json`` or ``{backend}/`` there.
    """
_RATE_MATRIX_DOC = """Euler-angle rate matrix ``W`` with ``omega = W eta_dot`` (Exercise 3.10).

    Args:
        angles: {noun} (..., 3), the intrinsic Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".
        check, on_singular: see the module.

    Returns:
        {noun} (..., 3, 3); derivative: the generated Jacobian kernel.

    Raises:
        TypeError, ValueError: bad input, naming the argument.
    """
_ANGLE_RATES_DOC = """Euler-angle rates ``eta_dot = W^-1 omega`` (Exercise 3.10).

    Args:
        angles: {noun} (..., 3) [rad].
        omega: {noun} (..., 3) [rad/s], in the frame given by ``frame``.
        sequence: one of the twelve intrinsic sequences.
        frame: "fixed" or "body".
        check, on_singular: see the module.

    Returns:
        {noun} (..., 3); derivative: {autodiff} through the generated expression.

    Raises:
        TypeError, ValueError: bad input, naming the argument.
        SingularConfigurationError: at gimbal lock, eager with on_singular="raise".
    """


def module_api(scope: dict, make_space: Callable, lib: str, noun: str,
               autodiff: str) -> tuple:
    """The module-level functions of a back-end module (``rigidsym.kernels.torch``, ``.jax``).

    Args:
        scope: the back-end module's ``globals()`` (its name; where ``__getattr__`` caches a
            kernel made on first access).
        make_space: ``make_space(directory)``, the back-end's space: ``.progs`` (an
            :class:`ArraySpace`) and ``.call(name, values, check, on_singular)``.
        lib, noun, autodiff: the words of its docstrings ("PyTorch", "tensor", "autograd").

    Returns:
        ``(load, euler_rate_matrix, euler_angle_rates, __getattr__, __dir__, space)``: the
        first five made as the module's own (``__module__``, ``__qualname__``, ``__doc__``:
        Sphinx documents them there); ``space(directory=None)`` caches one space a folder.
    """
    module, spaces = scope["__name__"], {}

    def space(directory=None):
        key = None if directory is None else Path(directory).resolve()
        if key not in spaces:
            spaces[key] = make_space(directory)
        return spaces[key]

    def load(directory: str | Path | None = None) -> types.ModuleType:
        s = space(directory)
        return namespace(s.progs, s.call, f"{module}.load({str(directory)!r})")

    def euler_rate_matrix(angles, sequence: str, frame: str = "fixed", *, check=None,
                          on_singular=None):
        name = _state.euler_name("euler_rate_matrix", sequence, frame)
        return space().call(name, (angles,), check, on_singular)

    def euler_angle_rates(angles, omega, sequence: str, frame: str = "fixed", *, check=None,
                          on_singular=None):
        name = _state.euler_name("euler_angle_rates", sequence, frame)
        return space().call(name, (angles, omega), check, on_singular)

    def __getattr__(attr: str):
        # the package's kernels, made on first access (importing the module stays cheap)
        s = space()
        if attr in s.progs.kernel_names():
            fn = scope[attr] = make_kernel(s.progs, s.call, attr, module)
            return fn
        raise AttributeError(f"module {module!r} has no attribute {attr!r}")

    def __dir__():
        return sorted([*scope, *space().progs.kernel_names()])

    words = {"lib": lib, "noun": noun, "autodiff": autodiff, "backend": space().progs.backend}
    docs = {load: _LOAD_DOC, euler_rate_matrix: _RATE_MATRIX_DOC,
            euler_angle_rates: _ANGLE_RATES_DOC, __getattr__: None, __dir__: None}
    for fn, doc in docs.items():
        fn.__module__, fn.__qualname__ = module, fn.__name__
        fn.__doc__ = None if doc is None else doc.format(**words)
    return load, euler_rate_matrix, euler_angle_rates, __getattr__, __dir__, space
