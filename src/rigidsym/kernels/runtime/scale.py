"""Threads and dtypes of the kernels: the thread-count setting, the dtype of a
call (NEP 50), and float32 over the float64 NumPy kernels (the validation tolerances per
dtype are the kind table's, :mod:`rigidsym.core.kinds`).

Used by :mod:`rigidsym.kernels` (which re-exports :func:`set_num_threads` and
:func:`get_num_threads`) and :mod:`rigidsym.kernels.runtime.dask_arrays`.
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable

import numpy as np

__all__ = ["MIN_PARALLEL", "set_num_threads", "get_num_threads", "check_threads", "resolve_threads",
           "result_dtype", "numpy_f32", "NONFINITE"]

#: batch size below which the C kernels run on one thread whatever is asked: waking the
#: (sleeping, OMP_WAIT_POLICY=PASSIVE) second thread costs tens of microseconds, more than
#: half the work of a smaller batch saves. Measured on the quiet 2-core machine
#: (benchmarks/RESULTS.md, "Threads below and above MIN_PARALLEL"): through the C entry
#: point 2 threads give 0.67-0.90x at 16384 samples and 1.22-1.47x at 65536; break-even
#: lies between, so this errs on the side of using the second core
MIN_PARALLEL = 16384
#: sample flag of a non-finite output (as the generated NumPy kernels return it)
NONFINITE = 2
_STATE = {"threads": None, "warned": False}


def set_num_threads(n: int | None) -> None:
    """Process-wide thread count of the C kernels called with ``threads=None``.

    Args:
        n: threads (>= 1), or None to go back to ``RIGIDSYM_NUM_THREADS`` (else 1).

    Raises:
        TypeError: ``n`` is not an int (a bool, a float, a str).
        ValueError: ``n`` < 1.
    """
    _STATE["threads"] = None if n is None else check_threads(n, "n")


def get_num_threads() -> int:
    """Thread count used with ``threads=None``.

    Returns:
        :func:`set_num_threads`'s count, else the environment variable
        ``RIGIDSYM_NUM_THREADS``, else 1 (never oversubscribes unasked).

    Raises:
        ValueError: ``RIGIDSYM_NUM_THREADS`` is not a positive integer.
    """
    if _STATE["threads"] is not None:
        return _STATE["threads"]
    env = os.environ.get("RIGIDSYM_NUM_THREADS")
    if not env:
        return 1
    try:
        return check_threads(int(env), "RIGIDSYM_NUM_THREADS")
    except ValueError:  # a text from the environment is a bad value, whatever it says
        raise ValueError(f"RIGIDSYM_NUM_THREADS: expected a positive integer number of "
                         f"threads, got {env!r}") from None


def check_threads(n, what: str) -> int:
    """``n`` as a positive int: the one validation of a thread count (the ``threads=``
    keyword, :func:`set_num_threads`, ``RIGIDSYM_NUM_THREADS``).

    Raises:
        TypeError: ``n`` is not an int (a bool, 1.5, "4"), naming ``what``.
        ValueError: ``n`` < 1, naming ``what``.
    """
    if isinstance(n, bool) or not isinstance(n, int | np.integer):
        raise TypeError(f"{what}: expected a positive int or None, got {n!r}")
    if n < 1:
        raise ValueError(f"{what}: expected a positive int or None, got {n}")
    return int(n)


def resolve_threads(threads, b: str) -> int:
    """Resolve ``threads`` for backend ``b``; NumPy runs one thread (one warning)."""
    t = get_num_threads() if threads is None else check_threads(threads, "threads")
    if t > 1 and b == "numpy":
        if not _STATE["warned"]:
            _STATE["warned"] = True
            warnings.warn("rigidsym.kernels: the NumPy backend runs on one thread "
                          f"(threads={t} asked)", RuntimeWarning, stacklevel=3)
        t = 1
    return t


def result_dtype(args: tuple) -> np.dtype:
    """float32 when the array inputs are float32 (NEP 50: Python floats and ints are weak,
    lists become float64 arrays), else float64."""
    kinds = []
    for x in args:
        if isinstance(x, (np.ndarray, np.generic)):
            kinds.append(x.dtype if x.dtype.kind == "f" else np.float64)
        elif not isinstance(x, (int, float)):
            kinds.append(np.float64)
    dt = np.result_type(*kinds) if kinds else np.dtype(np.float64)
    return np.dtype(np.float32) if dt.itemsize <= 4 else np.dtype(np.float64)


def numpy_f32(kernel: Callable, n_in: int) -> Callable:
    """A generated NumPy kernel on float32 arrays: float64 arithmetic (as the C kernels),
    outputs rounded to float32; a row whose output overflows float32 is flagged (2)."""
    def f(*arrays):
        ins = [np.asarray(a, dtype=np.float64) for a in arrays[:n_in]]
        tmp = [np.empty(o.shape) for o in arrays[n_in:]]
        flags = np.asarray(kernel(*ins, *tmp)).astype(np.uint8)
        n = ins[0].shape[0]
        with np.errstate(over="ignore"):
            for o, t in zip(arrays[n_in:], tmp, strict=True):
                o[...] = t
                bad = ~np.isfinite(o.reshape(n, -1)).all(axis=1) & (flags == 0)
                flags[bad] = NONFINITE
        return flags
    return f
