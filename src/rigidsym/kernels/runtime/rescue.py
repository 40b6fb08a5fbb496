"""Finite in, finite out: the samples a kernel cannot compute in its own type.

A sample whose intermediates overflow or underflow (an input of extreme magnitude, a
square that overflows, a norm whose square underflows to a zero denominator) is flagged by
the kernel (the C kernels test their inputs' exponent bits, ``rigidsym_any_extreme``; the
NumPy backend :func:`extreme_rows`); :func:`rescue` re-runs those samples in a type of wider
exponent range and rounds the result to the call's dtype, as ``hypot`` avoids the spurious
overflow of ``sqrt(x*x + y*y)``. A non-finite input (``check=False``) goes the same way, so
every back-end gives its IEEE result (NaN in the outputs that depend on it).
"""

from __future__ import annotations

import numpy as np

__all__ = ["WIDE", "extreme_rows", "rescue", "RANGE32"]

#: the type of the rescue: NumPy's long double, the x87 extended double on x86-64 (exponent
#: to 16383, 64-bit significand) and quad precision on aarch64 Linux; where long double is
#: double (Windows, macOS on arm64) only float32 samples gain (float64 arithmetic), float64
#: ones keep the plain result and its flags
WIDE = np.longdouble if np.finfo(np.longdouble).maxexp > 1024 else np.float64
#: the range of float64 input magnitudes the kernels evaluate without the rescue (the C
#: kernels' own test: c_common.h, rigidsym_any_extreme)
TINY, BIG = 2.0**-100, 2.0**101
#: float32 inputs, computed in float64 (NumPy as C): the float32 C kernels' range
#: (c_common.h), inside which products of up to ten inputs stay normal in float64
RANGE32 = (2.0**-30, 2.0**31)
_RANGE_BLOCK = 16384
#: sample flags of the generated batch functions (numpy_kernel.py.j2)
_NONFINITE = 2


def rescue(kernel, flat: list, bufs: list, idx: np.ndarray) -> np.ndarray:
    """The rows ``idx`` (flagged, or with an input of extreme magnitude) re-run by the NumPy
    batch function ``kernel`` in :data:`WIDE`, whose exponent range no intermediate of an
    input in range leaves, and rounded into ``bufs`` (the call's dtype). Their flags:
    singular where the wide run divides by an exact zero, non-finite where it overflows or
    the result does not fit the dtype (or an input is NaN or inf: the IEEE values are
    written, NaN in the outputs that depend on it, inf taken as NaN), else 0 and the rows
    hold the result."""
    # an inf input is a NaN here: IEEE arithmetic would give finite limits (x / inf = 0, a
    # unit vector [0, 0, 1] from an inf component) that are no value of the kernel
    ins = [np.ascontiguousarray(a[idx], dtype=WIDE) for a in flat]
    for a in ins:
        a[np.isinf(a)] = np.nan
    tmp = [np.empty((idx.size,) + b.shape[1:], dtype=WIDE) for b in bufs]
    with np.errstate(all="ignore"):
        sub = np.asarray(kernel(*ins, *tmp)).astype(np.uint8)
        for b, t in zip(bufs, tmp, strict=True):
            v = t.astype(b.dtype)
            b[idx] = v
            sub[(sub == 0) & ~np.isfinite(v.reshape(idx.size, -1)).all(axis=1)] = _NONFINITE
    return sub


def extreme_rows(flat: list, n: int, limits: tuple[float, float] | None = None) -> np.ndarray:
    """``(n,)`` bool: rows with an input that is non-finite or nonzero of magnitude outside
    ``[2**-100, 2**101)``, where a float64 kernel's intermediates (products of up to ten
    inputs) could overflow or underflow: the NumPy backend re-runs them in :data:`WIDE` (the
    C kernels flag them themselves, ``rigidsym_any_extreme``). A block at a time through one
    buffer (in cache: 5 % of a cheap kernel's time at N = 1e6), rows only where a block has
    an extreme value or a zero. ``limits``: another range than float64's (float32
    inputs: :data:`RANGE32`)."""
    tiny, big = (TINY, BIG) if limits is None else limits
    bad = np.zeros(n, dtype=bool)
    step = _RANGE_BLOCK
    for a in flat:
        a2 = a.reshape(n, -1)
        buf = np.empty((min(n, step), a2.shape[1]))
        for s in range(0, n, step):
            m = np.abs(a2[s:s + step], out=buf[:min(step, n - s)])
            if m.max() < big and m.min() >= tiny:
                continue
            bad[s:s + step] |= ((m >= big) | ((m < tiny) & (m != 0)) | np.isnan(m)).any(1)
    return bad
