"""Finite in, finite out and one NaN policy on the PyTorch and JAX back-ends.

The C and NumPy kernels re-run the samples they cannot compute in their own type (an input
of extreme magnitude, an intermediate that overflows or underflows to a zero denominator, a
non-finite input) in NumPy's long double (:mod:`rigidsym.kernels.runtime.rescue`). The array
back-ends do the same in eager calls: :func:`flag_rows` finds those samples on the device
(a few reductions, one host read), :func:`rescue` copies only them to the host, re-runs the
generated NumPy kernel of the same directory through the very rescue of C and NumPy, and
writes back the samples whose own result is non-finite, singular or off the wide one by
more than :data:`AGREE` units of the dtype. So a rescued sample gets the value C and NumPy
give it, and a NaN input the same NaN positions. No import of PyTorch or JAX.

Traced calls (``jit``, ``torch.compile``, ``torch.func``) read nothing on the host: there a
denominator that overflowed to inf marks its sample as flagged (as one that is exactly 0
does), so an overflow is NaN there, never a finite wrong value (an inf input is taken as
NaN, the rescue's rule: :func:`finite_columns` inside the kernel's function under ``jit`` and
``torch.compile``, :func:`traced_inputs` on the inputs under ``torch.func``).
"""

from __future__ import annotations

import numpy as np

from rigidsym.core.files import load_module
from rigidsym.kernels.runtime import rescue as _rescue

__all__ = ["input_range", "screen", "flag_rows", "rescue", "traced_inputs", "finite_columns",
           "AGREE"]

#: the input magnitudes a program evaluates in its own type without the rescue: float64
#: as the C and NumPy kernels (products of up to ten inputs stay normal); float32 programs
#: (torch and JAX compute float32 in float32, unlike C) as the float32 C kernels' range test,
#: inside which the package's programs stay within their bounds (measured: the first
#: departures at 2^-44 .. 2^-48 for kinetic_energy, 2^64 for the transfers, 2^-96 for the
#: normalised axes)
_RANGES = {64: (_rescue.TINY, _rescue.BIG), 32: _rescue.RANGE32}
#: a rescued sample keeps its own result (and its derivative) when within this many units
#: of its dtype of the wide one, normwise per output
AGREE = 64
_SINGULAR, _NONFINITE = 1, 2


def input_range(bits: int) -> tuple[float, float]:
    """``(tiny, big)``: nonzero input magnitudes outside ``[tiny, big)`` are rescued."""
    return _RANGES[64 if bits > 32 else 32]


def _rows(xp, x, batch: tuple):
    return x.reshape(batch + (-1,)) if batch else x.reshape((1, -1))


def _magnitudes(xp, x, bits: int):
    """``(|x|'s bits, tiny's and big's bits)``: the inputs are tested on their bits, as the
    C kernels do (XLA on CPU flushes subnormals to zero in every floating operation,
    comparisons included, so a float test would miss them)."""
    fdt, idt = (np.float64, xp.int64) if bits > 32 else (np.float32, xp.int32)
    tiny, big = (int(np.asarray(v, dtype=fdt).view(fdt.__name__.replace("float", "int")))
                 for v in input_range(bits))
    magnitude = (1 << (bits - 1)) - 1 if bits > 32 else 0x7FFFFFFF
    return x.view(idt) & magnitude, tiny, big  # NaN's bits above inf's


def screen(lib, xs: list, res: list, sing, bits: int) -> bool:
    """Whether :func:`flag_rows` may flag a sample: a few operations over every entry at
    once and one host read (at N = 1e3 eager PyTorch, ``flag_rows`` cost 142 us a
    call of ``instant_screw_axis``, this ~40 us; the common case flags nothing)."""
    views = lib.views([*xs, *res, sing])
    if views is not None:  # eager CPU tensors: NumPy's operations cost ~1/3 of PyTorch's
        with np.errstate(all="ignore"):
            return _screen(np, np.asarray, views[:len(xs)], views[len(xs):-1], views[-1],
                           bits)
    return _screen(lib.xp, lib.host, xs, res, sing, bits)


def _screen(xp, host, xs: list, res: list, sing, bits: int) -> bool:
    a, tiny, big = _magnitudes(xp, xp.concatenate([x.reshape(-1) for x in xs]), bits)
    a = xp.where(a == 0, tiny, a)  # a zero is in range
    nonfinite = (xp.concatenate([r.reshape(-1) for r in res]) * 0).sum()  # NaN iff any
    lo, hi, n, bad = host(xp.stack([a.min(), a.max(), sing.sum(), xp.isnan(nonfinite)]))
    return bool(lo < tiny or hi >= big or n > 0 or bad)


def flag_rows(xp, xs: list, res: list, sing, batch: tuple, bits: int):
    """``batch`` bool on the device: samples with an input that is non-finite or of extreme
    magnitude (:func:`input_range`), the only ones re-run, whatever their flags (one answer
    per row, the rule of C and NumPy: a flagged sample of ordinary inputs keeps its
    own flag; its wide value was a wrong number where a difference cancelled to a zero
    denominator). The inputs are tested on their bits, as the C kernels do: XLA on CPU
    flushes subnormals to zero in every floating operation, comparisons included, so a float
    test would miss them. (``res`` and ``sing``: the signature of before.)"""
    del res, sing
    a, tiny, big = _magnitudes(xp, xp.concatenate([_rows(xp, x, batch) for x in xs], -1),
                               bits)
    return ((a >= big) | ((a < tiny) & (a != 0))).any(-1)


def traced_inputs(xp, xs: list) -> list:
    """An inf input as NaN (the rescue's rule: IEEE limits such as ``x / inf = 0`` are no
    value of the kernel), for calls that are not rescued."""
    return [xp.where(xp.isinf(x), xp.nan, x) for x in xs]


def finite_columns(cols: list) -> list:
    """:func:`traced_inputs`' rule on the columns inside a kernel's function: ``c + 0 * c``
    is ``c`` bit for bit when finite (signed zeros and subnormals included: ``0 * c`` has
    the sign of ``c``) and NaN for ±inf, with derivative 1. Neither XLA nor inductor folds a
    float ``0 * c`` (it is NaN at inf). Measured, ``jax.jit`` value + gradient of
    ``instant_screw_axis`` at N = 1e4, process CPU ms: none 0.77 / 1.10 (float32 / 64),
    ``where(isinf)`` on the inputs before the ``custom_jvp`` 1.12 / 1.50, ``where`` on the
    columns inside it 0.94 / 1.33, this 0.82 / 1.15: XLA fuses it into every reader."""
    return [c + 0.0 * c for c in cols]


def _numpy_kernel(progs, name: str):
    key = ("numpy", name)
    f = progs._programs.get(key)
    if f is None:
        tag = abs(hash(str(progs.directory))) % 10**12
        mod = load_module(f"rigidsym._rescue_{tag}.{name}",
                          progs.directory / "numpy" / f"{name}.py")
        f = progs._programs[key] = getattr(mod, name)
    return f


def rescue(lib, progs, name: str, xs: list, res: list, rows, batch: tuple, bits: int):
    """Re-run the ``rows`` samples (a device mask from :func:`flag_rows`) in long double.

    Args:
        lib: the back-end's :class:`~rigidsym.kernels.arrays.evaluation.Library`.
        progs: the :class:`~rigidsym.kernels.arrays.evaluation.ArraySpace` (its NumPy kernel).
        xs: the broadcast inputs (``batch + shape``), in the working dtype.
        res: the outputs (``batch + shape``), in the working dtype.

    Returns:
        ``(res, singular, written)``: the outputs with the rescued samples written, and
        the host masks (flat, ``batch`` size) of the samples the wide run found singular
        and of those whose values it wrote.
    """
    n = int(np.prod(batch, dtype=np.int64))
    mask = np.asarray(lib.host(rows)).reshape(n)
    idx = np.flatnonzero(mask)
    meta = progs.meta[name]
    dev = lib.device(xs)
    work = xs[0].dtype
    npdt = np.float64 if bits > 32 else np.float32
    where = lib.as_array(idx, None, dev, "idx") if dev is not None else idx
    ins = [np.asarray(lib.host(lib.detach(_rows(lib.xp, x, batch))[where]), dtype=npdt)
           .reshape((idx.size,) + tuple(a["shape"])) for x, a in zip(xs, meta["args"],
                                                                    strict=True)]
    wide = [np.empty((idx.size,) + tuple(o["shape"]), dtype=npdt) for o in meta["outputs"]]
    sub = _rescue.rescue(_numpy_kernel(progs, name), ins, wide, np.arange(idx.size))
    finite_in = np.logical_and.reduce([np.isfinite(a.reshape(idx.size, -1)).all(1)
                                       for a in ins])
    own = [np.asarray(lib.host(lib.detach(_rows(lib.xp, r, batch))[where]), dtype=npdt)
           for r in res]
    eps = float(np.finfo(npdt).eps)
    keep = (sub == 0) & finite_in
    for o, w in zip(own, wide, strict=True):
        w2 = w.reshape(idx.size, -1)
        scale = np.abs(w2).max(1)
        with np.errstate(invalid="ignore"):
            near = np.abs(o - w2).max(1) <= AGREE * eps * scale
        keep &= near & np.isfinite(o).all(1)
    put = np.flatnonzero(~keep & (sub != _SINGULAR))
    if put.size:
        at = idx[put]
        at_dev = lib.as_array(at, None, dev, "idx") if dev is not None else at
        out = []
        for r, w in zip(res, wide, strict=True):
            vals = lib.as_array(w.reshape(idx.size, -1)[put], work, dev, "rescue")
            out.append(_put(_rows(lib.xp, r, batch), at_dev, vals).reshape(r.shape))
        res = out
    singular = np.zeros(n, dtype=bool)
    written = np.zeros(n, dtype=bool)
    singular[idx[sub == _SINGULAR]] = True
    written[idx[put]] = True
    return res, singular, written


def _put(x2, idx, vals):
    """``x2`` with rows ``idx`` set to ``vals``, out of place (differentiable in the other
    rows): JAX's ``.at[].set``, torch's ``index_put``."""
    if hasattr(x2, "at"):
        return x2.at[idx].set(vals)
    return x2.index_put((idx,), vals)
