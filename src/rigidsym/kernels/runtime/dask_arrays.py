"""Dask arrays in, lazy Dask arrays out, for every kernel of :mod:`rigidsym.kernels`.

A kernel called with at least one ``dask.array.Array`` argument builds a graph and computes
nothing: every block of the batch axes is evaluated by the in-memory kernel (same generated
NumPy or C code, so the same bits), on whatever scheduler computes the result (threads,
processes, ``distributed``). Built on :func:`dask.array.map_blocks` with ``block_info``, so
that a singular sample is reported with its *global* batch index.

How the arguments line up: ``map_blocks`` aligns arrays on their trailing axes, but the
arguments have different core shapes (``(3, 3)``, ``(3,)``, ``()``). Each argument ``j`` of
``m`` is therefore given ``m`` trailing axes, its flattened core on axis ``j`` and size 1 on
the others, so that the core axes never meet and broadcasting (one block of size 1) does the
rest. The output is one packed ``batch + (sum of output sizes,)`` array, sliced lazily into
the kernel's outputs.
"""

from __future__ import annotations

import math
import re
import sys
from functools import cache

import numpy as np

from rigidsym.kernels.runtime import state as _state

__all__ = ["is_dask", "apply"]


def is_dask(args) -> bool:
    """Whether any of ``args`` is a ``dask.array.Array`` (never imports Dask itself)."""
    da = sys.modules.get("dask.array")
    return da is not None and any(isinstance(a, da.Array) for a in args)


def _to_dask(da, x, spec: dict):
    """``x`` as a Dask array of a real floating or integer dtype, core shape checked."""
    name, core = spec["name"], tuple(spec["shape"])
    if not isinstance(x, da.Array):
        try:
            x = np.asarray(x)
        except (TypeError, ValueError) as exc:
            raise ValueError(f"{name}: expected a real array-like, got {type(x).__name__} "
                             f"({exc})") from None
    if x.dtype.kind not in "fiu":
        raise TypeError(f"{name}: expected real floating-point values, got dtype {x.dtype}")
    if any(math.isnan(s) for s in x.shape):
        raise ValueError(f"{name}: unknown chunk sizes; call compute_chunk_sizes() first")
    k = len(core)
    if x.ndim < k or tuple(x.shape[x.ndim - k:]) != core:
        raise ValueError(f"{name}: expected shape (..., {', '.join(map(str, core))})"
                         f"{'' if k else ' (a scalar per sample)'}, got {tuple(x.shape)}")
    if not isinstance(x, da.Array):
        x = da.from_array(x, chunks=-1)
    # core axes in one chunk: the kernel needs whole vectors and matrices
    if k and any(len(c) > 1 for c in x.chunks[x.ndim - k:]):
        x = x.rechunk({ax: -1 for ax in range(x.ndim - k, x.ndim)})
    return x


def _batch_chunks(arrs: list, specs: list, batch: tuple) -> tuple:
    """Chunks of the output's batch axes: per axis, those of the first full-size argument."""
    nb = len(batch)
    chunks = []
    for d in range(nb):
        found = None
        for a, s in zip(arrs, specs, strict=True):
            bd = a.ndim - len(s["shape"])
            ax = d - (nb - bd)
            if ax >= 0 and a.shape[ax] == batch[d] and (found is None or len(a.chunks[ax])
                                                         > len(found)):
                found = a.chunks[ax]
        chunks.append(found if found is not None else (batch[d],))
    return tuple(chunks)


def _expand(a, spec: dict, j: int, m: int, batch: tuple, chunks: tuple):
    """Argument ``j``: batch axes rechunked to ``chunks`` (or kept at size 1), left-padded to
    the output's batch rank; then the flattened core on trailing axis ``j`` of ``m``."""
    core = tuple(spec["shape"])
    nb = len(batch)
    bshape = a.shape[:a.ndim - len(core)]
    a = a.reshape((1,) * (nb - len(bshape)) + tuple(a.shape)) if len(bshape) < nb else a
    want = {d: chunks[d] for d in range(nb) if a.shape[d] == batch[d] and batch[d] != 1}
    if any(a.chunks[d] != c for d, c in want.items()):
        a = a.rechunk(want)
    size = math.prod(core)
    tail = (1,) * j + (size,) + (1,) * (m - 1 - j)
    return a.reshape(a.shape[:nb] + tail)


@cache
def _space(directory: str, space_type: type):
    """The kernel space of a generated directory, once per process (a worker's too).

    ``space_type`` is the caller's ``KernelSpace`` class (pickled by reference), so that this
    module needs no import of ``_core``, which imports it."""
    builtin = _state.builtin()
    if str(builtin.directory) == directory:
        return builtin
    return space_type.from_directory(directory)


def _block(*blocks, kernel_name, directory, space_type, specs, outs, nb, check, on_singular,
           threads, backend_name, out_dtype, block_info=None):
    """Evaluate one block with the in-memory kernel; singular indices made global."""
    from rigidsym.kernels.runtime.errors import SingularConfigurationError

    if _state.backend() != backend_name:
        _state.select(backend_name)
    space = _space(directory, space_type)
    args = []
    for b, s in zip(blocks, specs, strict=True):
        args.append(b.reshape(b.shape[:nb] + tuple(s["shape"])))
    kw = {"check": check, "on_singular": on_singular}
    if threads is not None:
        kw["threads"] = threads
    try:
        res = space.call(kernel_name, tuple(args), **kw)
    except SingularConfigurationError as exc:
        start = [lo for lo, _ in block_info[None]["array-location"][:nb]]
        where = [tuple(int(i) + s for i, s in zip(idx, start, strict=True))
                 for idx in exc.indices]
        msg = re.sub(r"batch indices \[.*?\]( \.\.\.)?",
                     lambda m: f"batch indices {where}{m.group(1) or ''}", str(exc), count=1)
        raise type(exc)(msg, exc.argument, where) from None
    res = res if isinstance(res, tuple) else (res,)
    shape = res[0].shape[:nb] if res else ()
    flat = [np.reshape(r, shape + (-1,)) for r in res]
    return flat[0].astype(out_dtype, copy=False) if len(flat) == 1 else \
        np.concatenate(flat, axis=-1).astype(out_dtype, copy=False)


def apply(space, name: str, args: tuple, *, out=None, check: bool = True,
          on_singular: str | None = None, threads: int | None = None):
    """Lazy evaluation of kernel ``name`` on Dask (and NumPy) arguments.

    Args:
        space: the :class:`~rigidsym.kernels.runtime.space.KernelSpace` the kernel belongs to.
        name: the kernel's name in ``kernels.json``.
        args: the kernel's array arguments, at least one a ``dask.array.Array``; NumPy
            arrays and array-likes are wrapped.
        out: must be None (a lazy result cannot fill a caller's array).
        check: validate the inputs block by block at compute time.
        on_singular: ``"nan"`` (default with Dask inputs) or ``"raise"``: a
            :class:`~rigidsym.kernels.SingularConfigurationError` at compute time naming the
            global batch indices (within the first offending block).
        threads: passed to the in-memory kernel of each block.

    Returns:
        Dask array(s) of shape batch + output shape, chunked like the batch axes of the
        inputs, core axes in one chunk (a tuple when the kernel has several outputs).

    Raises:
        TypeError: ``out`` given, or an argument of non-real dtype.
        ValueError: a core shape that does not match, or batch shapes that do not broadcast
            (before any graph is built).
    """
    import dask.array as da

    from rigidsym.kernels.runtime import scale as _scale

    meta = space.meta[name]
    specs = meta["args"]
    if out is not None:
        raise TypeError("out: not supported with Dask inputs (the result is lazy); "
                        "store the returned arrays instead, e.g. with dask.array.store")
    if on_singular is None:
        on_singular = "nan"
    if on_singular not in ("raise", "nan"):
        raise ValueError(f"on_singular: expected 'raise' or 'nan', got {on_singular!r}")
    if len(args) != len(specs):
        raise TypeError(f"{name}() takes {len(specs)} arguments, got {len(args)}")
    arrs = [_to_dask(da, x, s) for x, s in zip(args, specs, strict=True)]
    try:
        batch = np.broadcast_shapes(*[tuple(a.shape[:a.ndim - len(s["shape"])])
                                      for a, s in zip(arrs, specs, strict=True)])
    except ValueError:
        raise ValueError("batch shapes do not broadcast: " + ", ".join(
            f"{s['name']} {tuple(a.shape)}" for a, s in zip(arrs, specs, strict=True))) from None
    # NEP 50 as in memory: float32 Dask arrays with Python floats stay float32
    dtype = _scale.result_dtype(tuple(np.empty(0, a.dtype) if isinstance(a, da.Array) else a
                                 for a in args))
    nb, m = len(batch), len(specs)
    chunks = _batch_chunks(arrs, specs, batch)
    expanded = [_expand(a, s, j, m, batch, chunks)
                for j, (a, s) in enumerate(zip(arrs, specs, strict=True))]
    outs = meta["outputs"]
    sizes = [math.prod(o["shape"]) for o in outs]
    total = sum(sizes)
    packed = da.map_blocks(
        _block, *expanded, token=f"rigidsym-{name}", dtype=dtype,
        meta=np.empty((0,) * (nb + 1), dtype=dtype),
        chunks=chunks + ((total,),), drop_axis=list(range(nb, nb + m - 1)),
        kernel_name=name, directory=str(space.directory), space_type=type(space), specs=specs,
        outs=outs, nb=nb, check=check,
        on_singular=on_singular, threads=threads, backend_name=_state.backend(), out_dtype=dtype)
    results = []
    off = 0
    for o, size in zip(outs, sizes, strict=True):
        part = packed[..., off:off + size]
        results.append(part.reshape(batch + tuple(o["shape"])) if o["shape"] != [size]
                       else part)
        off += size
    return results[0] if len(results) == 1 else tuple(results)
