"""The per-call entry points of a kernel space: what the generated ``api.py``
functions call.

Each public kernel is a thin Python function of ``api.py`` (true signature, docstring, type
hints, pickled by reference) whose body is one call ``_F.<name>(*inputs, out, check,
on_singular, threads)``. ``_F`` is bound here, lazily at the first call (loading the C may
compile it, which an import must not do):

* the compiled module's entries (``rigidsym_fast.h``) when the directory's C loads: inputs of
  the core shape, Python numbers and lists, float64/float32 arrays (any strides, broadcast
  batch axes) are validated and computed in C; every other case, every error and every
  flagged sample go to the Python path, :meth:`KernelSpace.call
  <rigidsym.kernels.runtime.space.KernelSpace.call>`, unchanged;
* else (no compiler, or the NumPy backend chosen before the first call) the Python path
  itself, through :class:`Lazy`, which binds the C entries once the C backend is selected.

Selecting the NumPy backend turns the C entries off (``_enable``): they then take the Python
path, which runs the NumPy kernels.

With the output pool on (:mod:`rigidsym.kernels.runtime.outpool`) the functions run their
Python body instead, and ``_F`` is :func:`pooled`'s namespace: each entry first takes its
outputs from the pool when the call's are large and plain (``out=None``), then calls the C
entry with them as ``out``.
"""

from __future__ import annotations

import math
import os
import types
from typing import Any

import numpy as np

from rigidsym.core import kinds as _kinds
from rigidsym.kernels.runtime import outpool as _outpool
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.inputs import UNIT_AS_IS_EPS
from rigidsym.kernels.runtime.scale import MIN_PARALLEL, get_num_threads
from rigidsym.kernels.runtime.screw_at_infinity import COMPLETED, wrap_entry

__all__ = ["Lazy", "bind_api", "entries", "unbind", "pooled", "rebind"]

#: the (space, api module) pairs bound to their C entries, rebound when the pool turns on/off
_BOUND: list = []


class Lazy:
    """The ``_F`` of an ``api`` module before its first call: binds the entries then."""

    def __init__(self, space: Any, mod: types.ModuleType | None):
        self._space, self._mod = space, mod

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        ns = self._space.entries()
        if ns is self._space._entries and self._mod is not None:
            with _state.LOCK:
                if (self._space, self._mod) not in _BOUND:
                    _BOUND.append((self._space, self._mod))
                ns = _bind_c(self._space, self._mod)   # the C entries: bound for good
        return getattr(ns, name)


def _bind_c(space: Any, mod: types.ModuleType) -> types.SimpleNamespace:
    """Bind ``mod`` to its C entries: directly (the functions' vectorcall), the output pool
    asked by the compiled entries themselves while it is on (a module with ``_pool``: no
    Python frame in any call), or through the pool's Python wrappers (a module built before
    ``_pool`` existed); returns the namespace bound."""
    cmod = space.c_lib().module
    on, hook = _outpool.enabled(), hasattr(cmod, "_pool")
    if hook:
        cmod._pool(_outpool.take if on else None, _outpool.LIMITS["min_bytes"])
    if on and not hook:
        if hasattr(cmod, "_install"):
            cmod._install(None, None)          # the functions run their body: _F below
        mod._F = ns = pooled(space)
    else:
        mod._F = ns = space._entries
        _install(space, mod)
    return ns


def rebind() -> None:
    """Rebind every api module bound to its C entries after the pool turned on or off."""
    with _state.LOCK:
        for space, mod in _BOUND:
            if space._entries is not None and type(mod._F) is not Lazy:
                _bind_c(space, mod)


_outpool.on_change(rebind)


def pooled(space: Any) -> types.SimpleNamespace:
    """The C entries of ``space`` behind the output pool: ``out=None`` with large, plain
    outputs (:func:`~rigidsym.kernels.runtime.outpool.take_for_inputs`) becomes ``out=`` the
    pool's arrays; every other call goes to the entry unchanged."""
    if space._pooled is None or space._pooled[0] is not space._entries:
        def make(name: str, entry: Any):
            meta = space.meta[name]
            ins = tuple(tuple(a["shape"]) for a in meta["args"])
            outs = tuple(tuple(o["shape"]) for o in meta["outputs"])
            nin, take, limits = len(ins), _outpool.take_for_inputs, _outpool.LIMITS
            # the outputs' bytes over the first input's: a call whose first input is too
            # small for outputs of min_bytes goes to the entry at once
            per_in = math.prod(ins[0])
            per_out = sum(math.prod(s) for s in outs)

            def f(*a):
                x = a[0]
                if a[nin] is None and type(x) is np.ndarray \
                        and x.nbytes * per_out >= limits["min_bytes"] * per_in:
                    y = take(a, ins, outs)
                    if y is not None:
                        a = (*a[:nin], y[0] if len(y) == 1 else y, *a[nin + 1:])
                return entry(*a)
            f.__name__ = f.__qualname__ = name
            return f
        space._pooled = (space._entries, types.SimpleNamespace(
            **{n: make(n, e) for n, e in vars(space._entries).items()}))
    return space._pooled[1]


#: the keyword-only parameters of every generated kernel function, in the entries' order
_KEYWORDS = ("out", "check", "on_singular", "threads")


def _install(space: Any, mod: types.ModuleType) -> None:
    """Let the functions of ``mod`` call their C entries without running their Python body
    (the compiled module's ``_install``: their vectorcall), for the calls the entries take
    (inputs positionally, keywords among :data:`_KEYWORDS`). Only functions with exactly the
    generated signature (the kernel's inputs, then the four keywords with the same defaults);
    a module built without it has no ``_install``: nothing changes."""
    cmod = space.c_lib().module
    install = getattr(cmod, "_install", None)
    if install is None:
        return
    funcs, defaults = [], None
    for name in cmod.kernels:
        f = getattr(mod, name, None)
        code = getattr(f, "__code__", None)
        meta = space.meta.get(name)
        kwd = getattr(f, "__kwdefaults__", None) or {}
        ok = (type(f) is types.FunctionType and meta is not None and code is not None
              and code.co_argcount == len(meta["args"]) and code.co_posonlyargcount == 0
              and code.co_varnames[code.co_argcount:code.co_argcount + code.co_kwonlyargcount]
              == _KEYWORDS and not code.co_flags & 0x0C      # no *args, **kwargs
              and tuple(kwd) == _KEYWORDS and name not in COMPLETED)
        if ok and defaults not in (None, tuple(kwd.values())):
            ok = False                          # one set of defaults for every kernel
        if ok:
            defaults = tuple(kwd.values())
        funcs.append(f if ok else None)
    if defaults is not None:
        install(tuple(funcs), defaults)


def unbind(space: Any, mod: types.ModuleType) -> None:
    """Undo the binding of ``mod``'s entries (the state before its first call): its
    functions run their Python body again, which binds them at the next call."""
    with _state.LOCK:
        if space._clib is not None and hasattr(space._clib.module, "_install"):
            space._clib.module._install(None, None)
        space._entries = None
        mod._F = Lazy(space, mod)


def bind_api(space: Any, mod: types.ModuleType) -> None:
    """Bind the generated ``api`` module ``mod`` to ``space`` (``_SPACE`` and ``_F``)."""
    mod._SPACE = space
    mod._F = Lazy(space, mod)


def _python_entries(space: Any) -> types.SimpleNamespace:
    """The Python path with the entries' calling convention (inputs, then the keywords
    positionally)."""
    if space._py_entries is None:
        def make(name: str):
            def f(*a):
                return space.call(name, a[:-4], out=a[-4], check=a[-3], on_singular=a[-2],
                                  threads=a[-1])
            f.__name__ = f.__qualname__ = name
            return f
        space._py_entries = types.SimpleNamespace(**{n: make(n) for n in space.meta})
    return space._py_entries


def _general(space: Any):
    def general(name, args, out, check, on_singular, threads):
        return space.call(name, args, out=out, check=check, on_singular=on_singular,
                          threads=threads)
    return general


def entries(space: Any) -> types.SimpleNamespace:
    """The entries of ``space`` by kernel name: the compiled module's when its C loads (and
    the C backend is selected), else the Python path's. The C validation gets its
    tolerances, per dtype, from the kind table (:mod:`rigidsym.core.kinds`), as Python's does."""
    with _state.LOCK:
        if space._entries is not None:
            return space._entries
        if space.backend() != "c":
            return _python_entries(space)      # the api module stays Lazy: C when selected
        mod = space.c_lib().module
        rot = _kinds.get("rotation")
        # unit vectors: the C entry takes those of norm 1 to rounding; the others within
        # the tolerance go to the Python path, which normalises them (inputs.normalise)
        mod._bind(_general(space), get_num_threads, MIN_PARALLEL,
                  UNIT_AS_IS_EPS * float(np.finfo(np.float64).eps), rot.tolerance(np.float64),
                  UNIT_AS_IS_EPS * float(np.finfo(np.float32).eps), rot.tolerance(np.float32))
        mod._enable(_state.STATE["backend"] != "numpy")
        data = getattr(os.environ, "_data", None)     # what get_num_threads reads
        if hasattr(mod, "_environ") and type(data) is dict:
            mod._environ(data, os.environ.encodekey("RIGIDSYM_NUM_THREADS"))
        ns = dict(zip(mod.kernels, mod.entries, strict=True))
        # the kernels whose rows of a pure translation the runtime answers after the entry
        # (rigidsym.kernels.runtime.screw_at_infinity); their functions run their Python body
        ns.update({k: wrap_entry(k, ns[k], tuple(tuple(a["shape"])
                                                 for a in space.meta[k]["args"]))
                   for k in COMPLETED if k in ns})
        space._entries = types.SimpleNamespace(**ns)
        _state.LISTENERS.append(lambda name, m=mod: m._enable(name == "c"))
        return space._entries
