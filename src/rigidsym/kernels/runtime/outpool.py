"""A bounded cache of the kernels' large output blocks (opt-in): repeated calls reuse the
memory of outputs the program no longer holds instead of mapping fresh pages.

Why: glibc serves an allocation above its mmap threshold (at most 32 MiB) with fresh pages
and unmaps it when freed, so a kernel called again and again on 1e6 samples pays the page
faults (and the kernel's zeroing) of its whole output in every call: 7-10 ns a sample on
the benchmark's machines, as much as the arithmetic. The pool keeps such blocks, as
PyTorch's caching allocator keeps its tensors' memory.

How it stays sound: a block is a NumPy array owning its memory; the outputs handed out are
views of it (``out.base`` is the block), and every view of a view, memoryview, buffer
export or ``__array_interface__`` consumer that keeps the data alive holds a reference that
leads to the block (NumPy collapses view chains onto the array owning the data). The pool
hands a block out again only when its reference count shows that nothing but the pool's
list refers to it, and never one with a weak reference (which could bring it back), under
one lock. CPython with the GIL only: elsewhere (no ``sys.getrefcount``, free-threaded
builds) the pool stays off.

The compiled entries ask it themselves (``_pool`` of ``c_fast.h.j2``): below ``min_bytes``
a call pays one compare, above it one call of :func:`take`; a module built before that hook
goes through Python wrappers (:mod:`rigidsym.kernels.runtime.entries`, about 0.7 us a call).
Off by default: it keeps up to ``max_bytes`` after a large computation. Turn it on with
``RIGIDSYM_OUTPUT_POOL=1`` (or a byte count, ``512M``, as the bound) or
:func:`set_output_pool`; :func:`release_output_pool` frees what it keeps.
"""

from __future__ import annotations

import math
import os
import sys
import sysconfig
import threading
import warnings
import weakref
from collections.abc import Callable, Sequence

import numpy as np

__all__ = ["DEFAULT_MAX_BYTES", "MIN_BYTES", "LIMITS", "supported", "set_output_pool",
           "release_output_pool", "enabled", "take", "take_for_inputs", "on_change",
           "parse_setting"]

#: default bound of the bytes the pool holds (blocks in use and free together)
DEFAULT_MAX_BYTES = 256 << 20
#: calls whose outputs are smaller than this allocate as before (glibc's heap recycles
#: blocks below its mmap threshold already, and the call is short)
MIN_BYTES = 1 << 20
#: a free block serves a request up to this fraction larger than the request
_SLACK = 8

_F64, _F32 = np.dtype(np.float64), np.dtype(np.float32)


def _refs(blocks: list, i: int) -> int:
    """The reference count of ``blocks[i]`` as seen from here (the list's, this call's)."""
    return sys.getrefcount(blocks[i])


def supported() -> bool:
    """Whether reference counts can tell a free block here: CPython with the GIL."""
    return (sys.implementation.name == "cpython" and hasattr(sys, "getrefcount")
            and not sysconfig.get_config_var("Py_GIL_DISABLED"))


#: the count :func:`_refs` sees for a block no one but the pool's list refers to
_FREE = _refs([object()], 0) if supported() else -1


class _Pool:
    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.blocks: list[np.ndarray] = []
        self.on = False
        self.max_bytes = DEFAULT_MAX_BYTES

    def free(self, i: int) -> bool:
        return _refs(self.blocks, i) == _FREE

    def drop_weak(self) -> None:
        """Forget blocks someone holds a weak reference to: never handed out again."""
        self.blocks[:] = [b for b in self.blocks if weakref.getweakrefcount(b) == 0]

    def block(self, nbytes: int) -> int | None:
        """Index of a free block for ``nbytes`` (the smallest that fits), else a new one
        within the bound (free blocks evicted first), else None."""
        best = None
        for i in range(len(self.blocks)):
            size = self.blocks[i].nbytes
            if nbytes <= size <= nbytes + nbytes // _SLACK and self.free(i) \
                    and (best is None or size < self.blocks[best].nbytes):
                best = i
        if best is not None:
            return best
        total = sum(b.nbytes for b in self.blocks)
        for i in reversed(range(len(self.blocks))):
            if total + nbytes <= self.max_bytes:
                break
            if self.free(i):
                total -= self.blocks[i].nbytes
                del self.blocks[i]
        if total + nbytes > self.max_bytes:
            return None
        self.blocks.append(np.empty(nbytes, dtype=np.uint8))
        return len(self.blocks) - 1


_POOL = _Pool()
#: the settings the callers' gates read (min_bytes: the smallest outputs pooled, in all)
LIMITS: dict[str, int] = {"min_bytes": MIN_BYTES}
_LISTENERS: list[Callable[[], None]] = []


def _after_fork() -> None:
    # a lock held by another thread at fork would never be released in the child
    _POOL.lock = threading.Lock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_after_fork)


def enabled() -> bool:
    """Whether the kernels' allocated outputs come from the pool."""
    return _POOL.on


def on_change(fn: Callable[[], None]) -> None:
    """Call ``fn()`` after every :func:`set_output_pool` that turns the pool on or off."""
    _LISTENERS.append(fn)


def take(shapes: Sequence[tuple[int, ...]], dtype: np.dtype) -> tuple[np.ndarray, ...] | None:
    """C-contiguous arrays of these shapes and dtype (float64 or float32) on pooled blocks,
    one block each; None when the pool is off, the outputs are below ``min_bytes`` in all,
    or the bound leaves no room (the caller then allocates as usual)."""
    if not _POOL.on:
        return None
    dtype = np.dtype(dtype)
    sizes = [math.prod(s) * dtype.itemsize for s in shapes]
    if sum(sizes) < LIMITS["min_bytes"] or 0 in sizes:
        return None
    outs = []
    with _POOL.lock:
        _POOL.drop_weak()
        for shape, nbytes in zip(shapes, sizes, strict=True):
            i = _POOL.block(nbytes)
            if i is None:
                return None
            # the view holds the block from here: no later search in this call sees it free
            outs.append(_POOL.blocks[i][:nbytes].view(dtype).reshape(shape))
    return tuple(outs)


def take_for_inputs(args: Sequence, in_shapes: Sequence[tuple[int, ...]],
                    out_shapes: Sequence[tuple[int, ...]]) -> tuple[np.ndarray, ...] | None:
    """Pooled outputs for a kernel call on ``args`` (its inputs first), or None (then the entry
    allocates them): only for the case whose outputs' dtype and shape are plain to see,
    every input an ndarray of one dtype (float64 or float32, native order) with the same
    batch shape (at least one axis) before its core shape ``in_shapes[i]``."""
    x0 = args[0]
    if not _POOL.on or type(x0) is not np.ndarray:
        return None
    dt = x0.dtype
    if dt is not _F64 and dt is not _F32:
        return None
    bnd = x0.ndim - len(in_shapes[0])
    if bnd < 1 or x0.shape[bnd:] != in_shapes[0]:
        return None
    batch = x0.shape[:bnd]
    for i in range(1, len(in_shapes)):
        x, s = args[i], in_shapes[i]
        if type(x) is not np.ndarray or x.dtype is not dt or x.shape != batch + s:
            return None
    return take([batch + s for s in out_shapes], dt)


def parse_setting(text: str | None) -> int | None:
    """``RIGIDSYM_OUTPUT_POOL``'s value: the bound in bytes (``1``/``on``/``yes``/``true``:
    the default bound; ``512M``, ``2G``, ``100000000``: that bound), or None for off (unset,
    empty, ``0``, ``off``, ``no``, ``false``).

    Raises:
        ValueError: any other text (naming the variable).
    """
    t = (text or "").strip().lower()
    if t in ("", "0", "off", "no", "false"):
        return None
    if t in ("1", "on", "yes", "true"):
        return DEFAULT_MAX_BYTES
    scale = {"k": 1 << 10, "m": 1 << 20, "g": 1 << 30}.get(t[-1:], 1)
    digits = t[:-1] if scale > 1 else t
    if not digits.isdigit():
        raise ValueError(f"RIGIDSYM_OUTPUT_POOL={text!r}: expected 0/1, on/off or a byte "
                         f"count such as 512M")
    return int(digits) * scale


def set_output_pool(enabled: bool | None = None, *, max_bytes: int | None = None,
                    min_bytes: int | None = None) -> dict[str, int | bool]:
    """Turn on or off the reuse of the kernels' large output blocks, or bound it; returns
    the pool's state.

    When on, a kernel of the C back-end called with ``out=None`` on a batch (at least one
    batch axis) whose outputs take at least 1 MiB gets them on blocks that earlier
    outputs held and the program has let go of (no array, view, memoryview or buffer export of
    them left, and no weak reference): the page faults of fresh memory are not paid again.
    The results are the same values, writeable, C-contiguous; they are views (``out.base`` is
    the block, so ``out.flags.owndata`` is False and ``out.resize()`` refuses). Other calls
    allocate as before. Off by default (``RIGIDSYM_OUTPUT_POOL`` sets the default: ``1`` or a
    bound such as ``512M``): it keeps up to ``max_bytes`` until :func:`release_output_pool`.
    The compiled entries ask it only for calls of at least ``min_bytes`` (a call of
    :func:`take` from C); a module generated before that hook runs a Python wrapper in every
    call while on (about 0.7 us).

    Args:
        enabled: True or False, or None to leave it as it is.
        max_bytes: the most bytes the pool holds, blocks in use and free together (default
            256 MiB); a call that would exceed it allocates as before. None: unchanged.
        min_bytes: calls whose outputs take fewer bytes in all allocate as before (default
            1 MiB). None: unchanged.

    Returns:
        ``{"enabled", "max_bytes", "min_bytes", "blocks", "bytes", "free_bytes"}``.

    Raises:
        TypeError: ``enabled`` not a bool or None, a bound not an int or None.
        ValueError: a bound < 0.
        RuntimeError: turning it on where reference counts cannot tell a free block (not
            CPython, or a free-threaded build).

    Example:
        >>> state = set_output_pool()          # the current state, nothing changed
        >>> sorted(state)
        ['blocks', 'bytes', 'enabled', 'free_bytes', 'max_bytes', 'min_bytes']
    """
    if enabled is not None and type(enabled) is not bool:
        raise TypeError(f"enabled: expected True, False or None, got {enabled!r}")
    for name, v in (("max_bytes", max_bytes), ("min_bytes", min_bytes)):
        if v is not None and type(v) is not int:
            raise TypeError(f"{name}: expected an int or None, got {v!r}")
        if v is not None and v < 0:
            raise ValueError(f"{name}: expected >= 0, got {v}")
    if enabled and not supported():
        raise RuntimeError("set_output_pool: needs CPython with the GIL (reference counts "
                           "tell a free block)")
    # the compiled entries read min_bytes when bound: a new one rebinds them too
    changed = (enabled is not None and enabled != _POOL.on) or (
        min_bytes is not None and min_bytes != LIMITS["min_bytes"])
    with _POOL.lock:
        if max_bytes is not None:
            _POOL.max_bytes = max_bytes
        if min_bytes is not None:
            LIMITS["min_bytes"] = min_bytes
        if enabled is not None:
            _POOL.on = enabled
    if enabled is False or max_bytes is not None:
        _trim()
    if changed:
        for fn in _LISTENERS:
            fn()
    return _state()


def _trim() -> None:
    with _POOL.lock:
        if not _POOL.on:
            _POOL.blocks.clear()
            return
        total = sum(b.nbytes for b in _POOL.blocks)
        for i in reversed(range(len(_POOL.blocks))):
            if total <= _POOL.max_bytes:
                break
            if _POOL.free(i):
                total -= _POOL.blocks[i].nbytes
                del _POOL.blocks[i]


def release_output_pool() -> int:
    """Free the blocks the output pool keeps (the pool stays on or off as it is).

    Blocks still held by outputs are forgotten too: they are freed with their last view, as
    any array.

    Returns:
        The bytes of the free blocks released now.

    Example:
        >>> release_output_pool() >= 0
        True
    """
    with _POOL.lock:
        freed = sum(_POOL.blocks[i].nbytes for i in range(len(_POOL.blocks)) if _POOL.free(i))
        _POOL.blocks.clear()
    return freed


def _state() -> dict[str, int | bool]:
    with _POOL.lock:
        free = sum(_POOL.blocks[i].nbytes for i in range(len(_POOL.blocks)) if _POOL.free(i))
        return {"enabled": _POOL.on, "max_bytes": _POOL.max_bytes,
                "min_bytes": LIMITS["min_bytes"],
                "blocks": len(_POOL.blocks), "bytes": sum(b.nbytes for b in _POOL.blocks),
                "free_bytes": free}


def _from_environment() -> None:
    try:
        bound = parse_setting(os.environ.get("RIGIDSYM_OUTPUT_POOL"))
    except ValueError as exc:          # an import does not fail on it: said, and left off
        warnings.warn(f"{exc}; the output pool stays off", stacklevel=2)
        return
    if bound is not None and supported():
        _POOL.on, _POOL.max_bytes = True, bound


_from_environment()
