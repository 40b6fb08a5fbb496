"""The back-ends of the NumPy/C kernels: which one runs every call (:func:`use_backend`,
:func:`backend`: the compiled extension, with the NumPy fallback), how the C in use was built
and which CPU path runs (:func:`build_info`), and a kernel's raw batch function on either
(:func:`batch_function`). Re-exported by :mod:`rigidsym.kernels`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.namespace import public, space_of
from rigidsym.kernels.runtime.scale import check_threads

__all__ = ["use_backend", "backend", "build_info", "batch_function"]


@public
def use_backend(name: str) -> str:
    """Select the backend of every kernel call: ``"c"`` (the compiled extension) or
    ``"numpy"``.

    ``"c"`` falls back to ``"numpy"`` with a one-time warning when no compiled module
    matches the kernels and none can be built (no compiler): the warning says how to get one.

    Args:
        name: ``"c"`` or ``"numpy"``.

    Returns:
        The backend in use after the call (``"numpy"`` when ``"c"`` fell back).

    Raises:
        TypeError: ``name`` is not a ``str``.
        ValueError: ``name`` is neither.
    """
    return _state.select(name)


@public
def build_info(directory: str | Path | None = None) -> dict:
    """How the C kernels in use were built and which CPU path runs, in the spirit of
    ``numpy.show_runtime()``.

    Args:
        directory: a generated directory (``rigidsym generate --out DIR``); default the
            package's kernels.

    Returns:
        dict with ``path`` (the path in use, e.g. ``"x86-64-v3"``), ``paths`` (compiled, best
        first), ``forced`` (``RIGIDSYM_DISPATCH``, or None), ``openmp``, ``libmvec`` (the
        vector sin/cos variant the path calls, or None), ``file`` (the extension),
        ``origin`` (``"wheel"``, ``"editable build"``, ``"cache"`` or ``"cache (native)"``),
        ``sources`` (SHA-256 of the C it was built from), ``compiler``, ``flags``, ``cpu``
        (this machine's model) and ``build``: what the build did, or None where it left no
        record (``objects``, ``compiled``, ``reused`` from the object cache, ``seconds`` of
        wall time, ``cpu_seconds`` of the compilers, ``paths``, ``built`` (UTC),
        ``object_cache`` (its folder, or None)).

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        rigidsym.kernels.cbuild.extension.NoCompiledKernels: nothing compiled matches and
            no compiler can build it (the NumPy backend runs then).

    Example:
        >>> build_info()["path"] in build_info()["paths"]
        True
    """
    from rigidsym.kernels.cbuild import extension as _ext

    return _ext.info(space_of(directory).c_lib())


@public
def backend() -> str:
    """The backend in use.

    Returns:
        ``"c"`` or ``"numpy"``; the first call selects ``"c"``, with the NumPy fallback.
    """
    return _state.backend()


@public
def batch_function(name: str, backend_name: str | None = None,
                   threads: int | None = None, dtype=np.float64) -> Callable:
    """Low-level ``f(*inputs, *outputs) -> flags`` of a package kernel (for benchmarks).

    The call takes every input *and then every output*, in the kernel's order (its
    signature, ``help(kernels.NAME)``), all preallocated by the caller: C-contiguous
    ``(n, ...)`` arrays of ``dtype`` with the same leading ``n``, no validation, no
    broadcasting, no allocation. ``kernels.load(DIR).batch_function`` is the same for a
    generated directory. Passing the inputs only fails (``expected 5 arguments, got 4``
    for ``N_matrix``: ``n``, the thread count, ``e``, ``phi`` and the missing output).

    Args:
        name: a kernel's name (``"N_matrix"``).
        backend_name: ``"c"`` or ``"numpy"`` (default: the current backend).
        threads: worker threads of the C loop (default: :func:`get_num_threads`).
        dtype: ``np.float64`` or ``np.float32`` (arrays in and out of that type).

    Returns:
        ``f(*inputs, *outputs)``: for the C backend the number of flagged samples
        (singular or non-finite, written as NaN); for NumPy the ``(n,)`` uint8 flags (1
        singular, 2 non-finite output).

    Raises:
        TypeError: ``name`` not a ``str``, ``dtype`` not a dtype, ``threads`` not an int.
        KeyError: no kernel ``name`` (the message lists the close names).
        ValueError: ``backend_name`` neither ``"c"`` nor ``"numpy"``, ``dtype`` neither
            float64 nor float32, ``threads`` < 1.

    Example:
        >>> import numpy as np
        >>> f = batch_function("N_matrix", "numpy")
        >>> e, phi = np.tile([0.0, 0.6, 0.8], (4, 1)), np.linspace(0.5, 2.0, 4)
        >>> N = np.empty((4, 4, 3))           # the output, (n, 4, 3), preallocated
        >>> int(np.sum(f(e, phi, N)))         # no flagged sample
        0
        >>> bool(np.allclose(N, N_matrix(e, phi)))
        True
    """
    space = _state.builtin()
    _names.kernel_name(name, space.meta)
    if backend_name is not None and backend_name not in ("c", "numpy"):
        raise ValueError(f"backend_name: expected 'c', 'numpy' or None, got {backend_name!r}")
    if threads is not None:
        check_threads(threads, "threads")
    return space.batch_function(name, backend_name, threads, _names.dtype(dtype))
