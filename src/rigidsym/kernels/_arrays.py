"""What the PyTorch and JAX kernels share (issue 31): no import of either library.

Both back-ends evaluate the same generated programs (``generated/torch``, ``generated/jax``:
:mod:`rigidsym.codegen.arrays`) on array modules with the same names for what is needed
here (``where``, ``stack``, ``isfinite``, ``broadcast_to``, ``einsum``, ``linalg.det``):
``xp`` below is ``torch`` or ``jax.numpy``. This module holds the directory of programs,
the keyword rules of traced and eager calls, validation of constrained inputs, the
selection of a branch kernel's variant with the safe-``where`` idiom, and the contraction of
the generated Jacobians with a cotangent or tangent.
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
from rigidsym.kernels._errors import NonFiniteResultError, SingularConfigurationError

__all__ = ["ArraySpace", "modes", "validate", "evaluate", "contract", "raise_flagged",
           "SUFFIX", "make_kernel", "namespace", "euler_name", "docstring"]

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


def modes(check: bool | None, on_singular: str | None, traced: bool, where: str):
    """The effective ``(check, on_singular)`` of a call: defaults ``True`` / ``"raise"`` in
    eager mode, ``False`` / ``"nan"`` while traced (no host synchronisation there).

    Raises:
        ValueError: ``check=True`` or ``on_singular="raise"`` while traced (``where`` names
            the tracer), or a bad value.
    """
    if check is not None and not isinstance(check, bool):
        raise TypeError(f"check: expected True, False or None, got {check!r}")
    if on_singular is not None and on_singular not in _MODES:
        raise ValueError(f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    if traced:
        if check:
            raise ValueError(f"check=True needs eager mode (it reads values on the host); "
                             f"under {where} pass check=False or leave it unset")
        if on_singular == "raise":
            raise ValueError(f"on_singular='raise' needs eager mode; under {where} use "
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


def _full(xp, v, like):
    """An output entry as an array of the batch shape (a constant entry prints as a float)."""
    return v if hasattr(v, "shape") and tuple(v.shape) == tuple(like.shape) else \
        xp.zeros_like(like) + v


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


def contract(xp, grads: list, jac: list, outs: list[dict], args: list[dict],
             forward: bool, singular=None) -> list:
    """Chain rule through the generated Jacobian entries ``jac`` (flat, output-major then
    input, each entry row-major ``output shape + input shape``).

    ``forward=False``: ``grads`` are the cotangents of the outputs; returns those of the
    inputs, ``sum_i g_i J_ij``. ``forward=True``: ``grads`` are the tangents of the inputs;
    returns those of the outputs, ``sum_j J_ij t_j``. A zero cotangent contributes zero
    even where ``J`` is not finite (a masked singular sample), a non-zero one NaN.
    Forward mode cannot test the tangent (its transpose must stay linear): there the
    ``singular`` samples (a boolean mask of the batch shape) get a zero derivative, their
    values being NaN or an error already.
    """
    sizes_o = [int(math.prod(o["shape"])) for o in outs]
    sizes_a = [int(math.prod(a["shape"])) for a in args]
    k = 0
    blocks = {}
    for io, no in enumerate(sizes_o):
        for ia, na in enumerate(sizes_a):
            blocks[io, ia] = jac[k:k + no * na]
            k += no * na
    if forward:
        res = []
        for io, no in enumerate(sizes_o):
            acc = 0
            for ia, na in enumerate(sizes_a):
                t = grads[ia].reshape(tuple(grads[ia].shape[:grads[ia].ndim - len(
                    args[ia]["shape"])]) + (na, 1))
                J = xp.stack([_full(xp, v, t[..., 0, 0]) for v in blocks[io, ia]], -1)
                J = J.reshape(tuple(t.shape[:-2]) + (no, na))
                if singular is not None:
                    J = xp.where(singular[..., None, None], 0.0, J)
                acc = acc + (J @ t)[..., 0]
            res.append(acc.reshape(tuple(acc.shape[:-1]) + tuple(outs[io]["shape"])))
        return res
    res = []
    for ia, na in enumerate(sizes_a):
        acc = 0
        for io, no in enumerate(sizes_o):
            g = grads[io]
            if g is None:
                continue
            batch = tuple(g.shape[:g.ndim - len(outs[io]["shape"])])
            g = g.reshape(batch + (no, 1))
            J = xp.stack([_full(xp, v, g[..., 0, 0]) for v in blocks[io, ia]], -1)
            J = J.reshape(batch + (no, na))
            acc = acc + xp.where(g == 0, 0.0, g * J).sum(-2)
        res.append(acc if not isinstance(acc, int) else None)
    return [None if r is None else r.reshape(tuple(r.shape[:-1]) + tuple(a["shape"]))
            for r, a in zip(res, args, strict=True)]


def raise_flagged(name: str, meta: dict, sing, nonfinite, arrays: list) -> None:
    """Eager ``on_singular="raise"``: the kernels' errors, with the batch indices.

    ``sing`` and ``nonfinite`` are boolean NumPy arrays of the batch shape; the caller
    copies them to the host only once a reduction on the device found a flagged sample
    (the error path), as it does ``arrays`` (the inputs, for the largest magnitude).
    """
    s = np.asarray(sing)
    if s.any():
        w = [tuple(int(i) for i in t) for t in np.argwhere(s)[:20]]
        arg = meta["singular_arg"] or meta["args"][0]["name"]
        raise SingularConfigurationError(
            f"{name}: singular configuration ({meta['singular'] or 'division by zero'}) "
            f"in argument {arg!r} at batch indices {w}{' ...' if s.sum() > 20 else ''}",
            arg, w)
    f = np.asarray(nonfinite)
    if f.any():
        w = [tuple(int(i) for i in t) for t in np.argwhere(f)[:20]]
        mags = [float(np.abs(np.asarray(x)).max()) if x.size else 0.0 for x in arrays]
        k = int(np.argmax(mags))
        arg = meta["args"][k]["name"]
        raise NonFiniteResultError(
            f"{name}: non-finite output (overflow) from finite inputs at batch indices {w}"
            f"{' ...' if f.sum() > 20 else ''}; largest input there: {arg!r} "
            f"(max |{arg}| = {mags[k]:.3g})", arg, w)


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


def euler_name(progs: ArraySpace, kind: str, sequence: str, frame: str) -> str:
    """The generated kernel of an Euler-angle ``kind`` for ``sequence`` and ``frame``.

    Raises:
        ValueError: an unknown sequence, or a frame neither "fixed" nor "body".
    """
    seq = sequence.lower() if isinstance(sequence, str) else None
    if seq is None or f"{kind}_{seq}_fixed" not in progs.meta:
        known = sorted(n[len(kind) + 1:-6].upper() for n in progs.meta
                       if n.startswith(kind + "_") and n.endswith("_fixed"))
        raise ValueError(f"sequence: expected one of {', '.join(known)}, got {sequence!r}")
    if frame not in ("fixed", "body"):
        raise ValueError(f"frame: expected 'fixed' or 'body', got {frame!r}")
    return f"{kind}_{seq}_{frame}"
