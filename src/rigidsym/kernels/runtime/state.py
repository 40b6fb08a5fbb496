"""The kernels' global state, in one module the facade and its helpers all import.

- the backend choice (``"c"`` or ``"numpy"``) and its one-time fallback warning;
- the package's own kernel space (registered by :mod:`.namespace` when it loads the
  generated ``api`` module), through which :mod:`.jacobians` and :mod:`.dask_arrays` call
  kernels;
- the lock around the lazy C load and the backend switch (kernels may first be called from
  several threads at once: a thread pool, a Dask worker).

It imports no other module of rigidsym, so every module of :mod:`rigidsym.kernels` can
import it without a cycle.
"""

from __future__ import annotations

import sys
import threading
import types
import warnings
from typing import Any

__all__ = ["STATE", "LISTENERS", "LOCK", "PACKAGE_API", "euler_sequences", "warn_once",
           "register_builtin", "builtin", "select", "backend", "meta", "call", "euler_name",
           "bind_module"]

STATE: dict = {"backend": None, "warned": False, "builtin": None}
#: called with the backend's name after every selection (the C entry points turn off for
#: "numpy": rigidsym.kernels.runtime.entries)
LISTENERS: list = []
LOCK = threading.RLock()
#: the module name of the package's generated API
PACKAGE_API = "rigidsym.generated.api"
#: prefix of the generated Euler-angle rate-matrix kernels, ``<prefix><seq>_<frame>``
_EULER_PREFIX = "euler_rate_matrix_"


def warn_once(exc: Exception) -> None:
    """Warn (once per process) that the C backend is unavailable and NumPy runs instead."""
    if not STATE["warned"]:
        warnings.warn(f"rigidsym.kernels: C backend unavailable ({exc}); using NumPy",
                      RuntimeWarning, stacklevel=3)
        STATE["warned"] = True


def register_builtin(space: Any) -> None:
    """Record the package's kernel space (called once by :mod:`.namespace`)."""
    STATE["builtin"] = space


def builtin() -> Any:
    """The package's kernel space (a :class:`~rigidsym.kernels.runtime.space.KernelSpace`)."""
    space = STATE["builtin"]
    if space is None:  # only while rigidsym.kernels itself is being imported
        raise RuntimeError("rigidsym.kernels is not loaded yet")
    return space


def select(name: str) -> str:
    """Select the global backend (``"c"`` falls back to NumPy when the package's C cannot be
    loaded); returns it.

    Raises:
        TypeError: ``name`` is not a ``str``.
        ValueError: ``name`` is neither ``"c"`` nor ``"numpy"``.
    """
    if not isinstance(name, str):
        raise TypeError(f"name: expected 'c' or 'numpy' (a str), got {type(name).__name__} "
                        f"{name!r:.60}")
    if name not in ("c", "numpy"):
        raise ValueError(f"backend: expected 'c' or 'numpy', got {name!r}")
    with LOCK:
        if name == "c":
            space = builtin()
            space._c_failed = False
            try:
                space.c_lib()
            except Exception as exc:  # noqa: BLE001 - any build failure means: no C backend
                space._c_failed = True
                warn_once(exc)
                name = "numpy"
        STATE["backend"] = name
        for listener in LISTENERS:
            listener(name)
        return name


def backend() -> str:
    """The backend in use (selects ``"c"`` with NumPy fallback on first call)."""
    return STATE["backend"] or select("c")


def meta() -> dict:
    """``kernels.json`` entries of the package's kernels, by name."""
    return builtin().meta


def call(name: str, args: tuple, out: Any = None, check: bool = True,
         on_singular: str | None = None, threads: int | None = None) -> Any:
    """The checked call of package kernel ``name`` (see :meth:`KernelSpace.call`), through
    its entry point (the compiled one when the C loads: :mod:`rigidsym.kernels.runtime.entries`)."""
    return builtin().entry(name)(*args, out, check, on_singular, threads)


def euler_sequences() -> tuple[str, ...]:
    """The intrinsic Euler-angle sequences the package's kernels were generated for
    (Exercise 3.10: the twelve), read from their metadata: the book's kernel list
    (``derivations/kernels_spec_internal.py``) is the one place that names them."""
    return tuple(sorted({n[len(_EULER_PREFIX):-len("_fixed")].upper() for n in meta()
                         if n.startswith(_EULER_PREFIX) and n.endswith("_fixed")}))


def euler_name(kind: str, sequence: str, frame: str) -> str:
    """The generated kernel of an Euler-angle ``kind`` for ``sequence`` and ``frame``.

    Raises:
        ValueError: ``sequence`` is not one of :func:`euler_sequences`, or ``frame`` is
            neither ``"fixed"`` nor ``"body"``.
    """
    seq = sequence.upper() if isinstance(sequence, str) else sequence
    if not isinstance(seq, str) or f"{_EULER_PREFIX}{seq.lower()}_fixed" not in meta():
        raise ValueError(f"sequence: expected one of {', '.join(euler_sequences())}, "
                         f"got {sequence!r}")
    if frame not in ("fixed", "body"):
        raise ValueError(f"frame: expected 'fixed' or 'body', got {frame!r}")
    return f"{kind}_{seq.lower()}_{frame}"


def bind_module(mod: types.ModuleType | str) -> Any:
    """Bind the package's generated ``api`` module to the package's kernel space.

    The generated module calls this when it was imported on its own (unpickling a kernel in
    a fresh process): importing this module has then loaded :mod:`rigidsym.kernels`, which
    registered the space.

    Raises:
        RuntimeError: ``mod`` is a user directory's ``api`` module not loaded through
            ``rigidsym.kernels.load(DIR)``.
    """
    mod = sys.modules[mod] if isinstance(mod, str) else mod
    if getattr(mod, "_SPACE", None) is not None:
        return mod._SPACE
    if mod.__name__ != PACKAGE_API:
        raise RuntimeError(f"{mod.__name__}: load its directory with rigidsym.kernels.load(DIR)")
    builtin().bind_api(mod)
    return mod._SPACE
