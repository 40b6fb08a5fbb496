"""The checked evaluation of one generated directory (``kernels.json`` + ``numpy/`` + ``c/``).

A :class:`KernelSpace` reads the metadata, loads the NumPy kernels and (lazily) the C
extension module of the directory (:mod:`rigidsym.kernels.cbuild.extension`);
:meth:`KernelSpace.call` validates the inputs (:mod:`rigidsym.kernels.runtime.inputs`: errors
name the argument), broadcasts the batch, runs the selected backend, and reports singular
and non-finite samples. The generated ``api.py`` functions end in that call.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from rigidsym.core import kinds as _kinds
from rigidsym.core.files import load_module
from rigidsym.kernels.runtime import dask_arrays as _dask
from rigidsym.kernels.runtime import entries as _entries
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.errors import (
    NonFiniteResultError,
    SingularConfigurationError,
    at_batch_indices,
)
from rigidsym.kernels.runtime.inputs import (
    BODY_KERNELS,
    as_array,
    batch_shape,
    check_inertia,
    check_keywords,
    normalise,
    validate,
)
from rigidsym.kernels.runtime.rescue import RANGE32, extreme_rows, rescue
from rigidsym.kernels.runtime.scale import (
    MIN_PARALLEL,
    numpy_f32,
    resolve_threads,
    result_dtype,
)
from rigidsym.kernels.runtime.screw_at_infinity import COMPLETED, complete

#: sample flags of the generated batch functions (numpy_kernel.py.j2)
_SINGULAR, _NONFINITE = 1, 2


@dataclass
class KernelSpace:
    """The kernels of one generated directory and their checked evaluation.

    Attributes:
        directory: the generated directory.
        prefix: module-name prefix of its NumPy kernels.
        meta: ``kernels.json`` entries by kernel name.
    """

    directory: Path
    prefix: str
    meta: dict
    _numpy: dict = field(default_factory=dict)
    _clib: Any = None
    _cindex: dict = field(default_factory=dict)
    _c_failed: bool = False
    _entries: Any = None        # the C entry points by name (rigidsym.kernels.runtime.entries)
    _py_entries: Any = None
    _pooled: Any = None         # (C entries, their output-pool wrappers): entries.pooled
    _apis: list = field(default_factory=list)

    @classmethod
    def from_directory(cls, directory: Path, prefix: str | None = None) -> KernelSpace:
        """Read ``directory/kernels.json``.

        Raises:
            FileNotFoundError: no ``kernels.json`` there.
        """
        directory = Path(directory).resolve()
        data = json.loads((directory / "kernels.json").read_text(encoding="utf-8"))
        meta = {}
        for k in data["kernels"]:
            for a in k["args"]:
                a["tshape"] = tuple(a["shape"])
                _kinds.for_spec(a["kind"], a["tshape"])  # an unknown kind fails here, not later
            for o in k["outputs"]:
                o["tshape"] = tuple(o["shape"])
            meta[k["name"]] = k
        if prefix is None:
            key = hashlib.sha256(str(directory).encode()).hexdigest()[:12]
            prefix = f"rigidsym._loaded_{key}"
        return cls(directory, prefix, meta)

    def bind_api(self, mod) -> None:
        """Bind a generated ``api`` module to this space (its ``_SPACE`` and ``_F``)."""
        _entries.bind_api(self, mod)
        self._apis.append(mod)

    def entries(self):
        """The per-call entry points by kernel name (:mod:`rigidsym.kernels.runtime.entries`)."""
        return _entries.entries(self)

    def entry(self, name: str) -> Callable:
        """The entry point of kernel ``name``: ``f(*inputs, out, check, on_singular,
        threads)``."""
        return getattr(self.entries(), name)

    def numpy_kernel(self, name: str) -> Callable:
        f = self._numpy.get(name)
        if f is None:
            mod = load_module(f"{self.prefix}.{name}", self.directory / "numpy" / f"{name}.py")
            f = self._numpy[name] = getattr(mod, name)
        return f

    def c_lib(self):
        """The loaded extension of this directory
        (:class:`rigidsym.kernels.cbuild.extension.Loaded`):
        built with the package, or from the cache, compiled there first if needed."""
        if self._clib is None:
            with _state.LOCK:
                if self._clib is None:
                    from rigidsym.kernels.cbuild import extension as _ext
                    self._clib = _ext.load(self.directory,
                                           package=self.directory == _ext.generated_dir())
                    names = self._clib.module.kernels
                    self._cindex = {n: i for i, n in enumerate(names)}
        return self._clib

    def backend(self) -> str:
        """The backend in effect here: the global choice, NumPy if this C did not build."""
        # a user directory's C never waits for the package's: "c" unless NumPy was chosen
        b = _state.STATE["backend"] or "c"
        if b == "c" and self._clib is None:
            if self._c_failed:
                return "numpy"
            try:
                self.c_lib()
            except Exception as exc:  # noqa: BLE001 - any build failure means: no C backend
                self._c_failed = True
                _state.warn_once(exc)
                return "numpy"
        return b

    def batch_function(self, name: str, backend_name: str | None = None,
                       threads: int | None = None, dtype=np.float64) -> Callable:
        """``f(*inputs, *outputs)`` on C-contiguous ``(n, ...)`` arrays of ``dtype``: every
        input then every output, preallocated by the caller, in the kernel's order
        (:func:`rigidsym.kernels.batch_function` has an example).

        ``threads`` as for the kernels (None:
        :func:`rigidsym.kernels.runtime.scale.get_num_threads`; one
        thread below ``MIN_PARALLEL`` samples); outputs are the same for every count.
        float32: float32 arrays in and out, float64 arithmetic inside. Samples the kernel
        cannot compute in its type (an input of extreme magnitude, an intermediate that
        overflows or underflows) are re-run in a wider one (:mod:`.rescue`).
        """
        b = backend_name or self.backend()
        t = resolve_threads(threads, b)
        f32 = np.dtype(dtype) == np.float32
        nin = len(self.meta[name]["args"])
        wide = self.numpy_kernel(name)
        if b == "numpy":
            k = numpy_f32(wide, nin) if f32 else wide

            def g(*arrays):
                flags = k(*arrays)
                n = len(flags)
                # the rows re-run in the wide type: those with an input of extreme magnitude
                # or a non-finite one, whatever their flags, and no other (one answer per
                # row, a flagged row of ordinary inputs is singular or cancels to
                # a zero denominator, and its wide value was a wrong number, which C gave in
                # raise mode and not in nan mode); float32 samples ran in float64
                # arithmetic: the C kernels' float32 range
                rows = extreme_rows(arrays[:nin], n, RANGE32 if f32 else None)
                if rows.any():
                    idx = np.flatnonzero(rows)
                    flags[idx] = rescue(wide, arrays[:nin], arrays[nin:], idx)
                return flags
            return g
        batch = self.c_lib().module.batch
        k = self._cindex[name]

        def f(*arrays):
            n = arrays[0].shape[0]
            count = batch(k, f32, n, t if n >= MIN_PARALLEL else 1, *arrays)
            if count:      # flagged rows are NaN: re-run those of extreme or non-finite
                # input (the NumPy backend's rule); those still flagged stay NaN
                nan = np.isnan(arrays[nin].reshape(n, -1)[:, 0])
                idx = np.flatnonzero(nan & extreme_rows(arrays[:nin], n,
                                                        RANGE32 if f32 else None))
                bad = idx[rescue(wide, arrays[:nin], arrays[nin:], idx) != 0] \
                    if idx.size else idx
                for o in arrays[nin:]:
                    o.reshape(n, -1)[bad] = np.nan
                count = int(nan.sum()) - idx.size + bad.size
            return count
        return f

    def call(self, name: str, args: tuple, out=None, check: bool = True,
             on_singular: str | None = None, threads: int | None = None):
        """Validate, broadcast, evaluate ``name`` and report singular/non-finite samples.
        Dask inputs: a lazy result (:mod:`rigidsym.kernels.runtime.dask_arrays`)."""
        if _dask.is_dask(args):
            return _dask.apply(self, name, args, out=out, check=check,
                               on_singular=on_singular, threads=threads)
        on_singular = "raise" if on_singular is None else on_singular
        meta = self.meta[name]
        check_keywords(check, on_singular, threads)
        specs = meta["args"]
        dtype = result_dtype(args)
        arrs = [as_array(x, s, dtype) for x, s in zip(args, specs, strict=True)]
        if check:
            for x, a, s in zip(args, arrs, specs, strict=True):
                validate(a, s, getattr(x, "dtype", None))
            arrs = [normalise(a, s) for a, s in zip(arrs, specs, strict=True)]
            if name in BODY_KERNELS:
                by = {s["name"]: a for a, s in zip(arrs, specs, strict=True)}
                check_inertia(by["I_C"], by["m"], _kinds.get("unit").tolerance(dtype))
        batch = batch_shape(arrs, specs, name)
        n = math.prod(batch)
        flat = []
        for a, s in zip(arrs, specs, strict=True):
            full = batch + s["tshape"]
            if a.shape != full:     # broadcast_to is most of the overhead: only when needed
                a = np.broadcast_to(a, full)
            flat.append(np.ascontiguousarray(a).reshape((n,) + s["tshape"]))
        outs_meta = meta["outputs"]
        user = None if out is None else _check_out(out, outs_meta, batch, dtype)
        bufs = []
        for i, o in enumerate(outs_meta):
            u = None if user is None else user[i]
            if u is not None and u.flags.c_contiguous:
                bufs.append(u.reshape((n,) + o["tshape"]))
            else:
                bufs.append(np.empty((n,) + o["tshape"], dtype=dtype))
        if n:
            b = self.backend()
            res = self.batch_function(name, b, threads, dtype)(*flat, *bufs)
            if b == "numpy":
                flags = res
            else:
                flags = self._classify_c_rows(name, flat, bufs, n) if res else None
            if name in COMPLETED:
                flags = complete(name, flat, bufs, flags, batch, on_singular)
            if flags is not None and flags.any():
                _report_flags(name, meta, flags, flat, bufs, batch, check, on_singular)
        results = []
        for i, o in enumerate(outs_meta):
            r = bufs[i].reshape(batch + o["tshape"])
            if user is not None:
                if not user[i].flags.c_contiguous:
                    user[i][...] = r
                r = user[i]
            results.append(r)
        return results[0] if len(results) == 1 else tuple(results)

    def _classify_c_rows(self, name: str, flat: list, bufs: list, n: int) -> np.ndarray:
        """Flags of the C batch: it writes NaN rows without saying why (a singular sample,
        an overflow, an input of extreme magnitude or a non-finite one): those rows are
        re-run by :func:`~rigidsym.kernels.runtime.rescue.rescue`, which computes them and tells
        which is which."""
        nan = np.isnan(bufs[0].reshape(n, -1)[:, 0])
        flags = np.zeros(n, dtype=np.uint8)
        if not nan.any():
            return flags
        f32 = bufs[0].dtype == np.float32
        ext = extreme_rows(flat, n, RANGE32 if f32 else None)
        idx = np.flatnonzero(nan & ext)
        if idx.size:
            flags[idx] = rescue(self.numpy_kernel(name), flat, bufs, idx)
        # rows of ordinary inputs are never re-run (one answer per row): their
        # flag is the NumPy kernel's in the call's own type, the program C ran
        own = np.flatnonzero(nan & ~ext)
        if own.size:
            wide = self.numpy_kernel(name)
            k = numpy_f32(wide, len(flat)) if f32 else wide
            ins = [np.ascontiguousarray(a[own]) for a in flat]
            tmp = [np.empty((own.size,) + b.shape[1:], dtype=b.dtype) for b in bufs]
            with np.errstate(all="ignore"):
                sub = np.asarray(k(*ins, *tmp)).astype(np.uint8)
            flags[own] = np.where(sub == 0, _NONFINITE, sub)
        return flags



def _check_out(out, outs_meta: list, batch: tuple, dtype=np.float64) -> tuple:
    user = (out,) if len(outs_meta) == 1 and not isinstance(out, tuple) else tuple(out)
    if len(user) != len(outs_meta):
        raise ValueError(f"out: expected {len(outs_meta)} arrays, got {len(user)}")
    for u, o in zip(user, outs_meta, strict=True):
        want = batch + o["tshape"]
        if isinstance(u, np.ndarray) and u.dtype != dtype:
            raise TypeError(f"out ({o['name']}): expected dtype {np.dtype(dtype)} (the inputs' "
                            f"dtype), got {u.dtype}")
        if not isinstance(u, np.ndarray) or u.shape != want or not u.flags.writeable:
            raise ValueError(f"out ({o['name']}): expected a writeable {np.dtype(dtype)} array "
                             f"of shape {want}")
    return user


def _report_flags(name, meta, flags, flat, bufs, batch, check, on_singular) -> None:
    """Raise for flagged samples, or write NaN in their rows (``on_singular="nan"``).
    ``check=False`` only skips validation: an overflow is reported as with
    ``check=True``; a sample with a non-finite input (unvalidated) keeps its IEEE values."""
    specs = meta["args"]
    sing = np.flatnonzero(flags == _SINGULAR)
    over = np.flatnonzero(flags == _NONFINITE)
    if not check and over.size:
        over = over[np.logical_and.reduce([np.isfinite(a[over].reshape(over.size, -1)).all(1)
                                           for a in flat])]

    def where(idx):
        return [tuple(int(j) for j in np.unravel_index(i, batch)) for i in idx[:20]]
    if on_singular == "raise" and sing.size:
        arg = meta["singular_arg"] or specs[0]["name"]
        w = where(sing)
        raise SingularConfigurationError(
            f"{name}: singular configuration ({meta['singular'] or 'non-finite result'}"
            f") in argument {arg!r}{at_batch_indices(w, sing.size > 20)}",
            arg, w)
    if on_singular == "raise" and over.size:
        # name the input of largest magnitude there: the likely cause of the overflow
        mags = [float(np.abs(a[over]).max()) if a[over].size else 0.0 for a in flat]
        k = max(range(len(mags)), key=mags.__getitem__)
        arg, w = specs[k]["name"], where(over)
        raise NonFiniteResultError(
            f"{name}: non-finite output (overflow) from finite inputs"
            f"{at_batch_indices(w, over.size > 20)}; largest input there: {arg!r} "
            f"(max |{arg}| = {mags[k]:.3g})", arg, w)
    for buf in bufs:
        buf[sing] = np.nan
        buf[over] = np.nan
