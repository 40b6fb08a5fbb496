"""Validation of the non-array arguments of :mod:`rigidsym.kernels`' helpers: a kernel
name, a backend name, a directory, a flag; errors name the argument and what
was expected, as the kernels' own do."""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from pathlib import Path

import numpy as np

__all__ = ["kernel_name", "flag", "directory", "dtype"]


def kernel_name(name, known: Iterable[str], what: str = "name") -> str:
    """``name`` when it is one of ``known``.

    Raises:
        TypeError: ``name`` is not a ``str`` (a bool, a list, an array).
        KeyError: no such name; the message lists the close ones.
    """
    if not isinstance(name, str):
        raise TypeError(f"{what}: expected a kernel name (str), got {type(name).__name__} "
                        f"{name!r:.60}")
    known = list(known)
    if name not in known:
        close = difflib.get_close_matches(name, known, n=5, cutoff=0.6)
        hint = f"; close names: {', '.join(close)}" if close else \
            " (kernels.KERNEL_NAMES lists the public ones)"
        raise KeyError(f"{what}: no kernel {name!r}{hint}")
    return name


def flag(value, what: str) -> bool:
    """``value`` as a bool; ``TypeError`` naming ``what`` for anything but True/False (and
    NumPy's bools)."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise TypeError(f"{what}: expected True or False, got {value!r:.60}")


def directory(value, what: str = "directory") -> Path | None:
    """``value`` (a str or path-like, or None) as a Path; ``TypeError`` naming ``what``."""
    if value is None:
        return None
    if isinstance(value, str | Path) or hasattr(value, "__fspath__"):
        return Path(value)
    raise TypeError(f"{what}: expected a folder (str or path-like) or None, got "
                    f"{type(value).__name__} {value!r:.60}")


def dtype(value, what: str = "dtype") -> np.dtype:
    """``value`` as ``float64`` or ``float32``; ``TypeError``/``ValueError`` naming ``what``."""
    try:
        dt = np.dtype(value)
    except TypeError:
        raise TypeError(f"{what}: expected np.float64 or np.float32, got {value!r:.60}") \
            from None
    if dt not in (np.dtype(np.float64), np.dtype(np.float32)):
        raise ValueError(f"{what}: expected np.float64 or np.float32, got {dt}")
    return dt
