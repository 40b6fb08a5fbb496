"""Files in and out without half states: atomic writes (nothing half-written on disk; the
moment before a file's rename is the ``write`` checkpoint of :mod:`rigidsym.core.interrupts`)
and loading a module from a file (nothing half-registered in ``sys.modules``).
"""

from __future__ import annotations

import importlib.util
import os
import sys
import tempfile
import types
from pathlib import Path

from rigidsym.core.interrupts import checkpoint

__all__ = ["write_atomic", "write_atomic_bytes", "load_module", "NotAModule"]


class NotAModule(ImportError):
    """A file that is neither a Python source file nor an extension module."""


def write_atomic(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` (UTF-8, ``\\n`` line ends) to ``path`` atomically.

    Args:
        path: the file to (re)write; its folder is created if missing.
        text: the whole content.

    Returns:
        ``path`` as a :class:`~pathlib.Path`.

    Raises:
        OSError: if the folder cannot be created or written.
    """
    return write_atomic_bytes(path, text.encode("utf-8"))


def write_atomic_bytes(path: str | os.PathLike, data: bytes) -> Path:
    """Write ``data`` to ``path`` through a temporary file in the same folder and a rename,
    so a reader sees the old file or the new one, never a half-written one.

    Args:
        path: the file to (re)write; its folder is created if missing.
        data: the whole content.

    Returns:
        ``path`` as a :class:`~pathlib.Path`.

    Raises:
        OSError: if the folder cannot be created or written.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        # mkstemp creates 0600; give the file the mode a plain open() would have
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        checkpoint("write")  # an interrupt here leaves the old file and no temporary one
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def load_module(name: str, path: str | os.PathLike) -> types.ModuleType:
    """Execute the Python source or extension module at ``path`` as the module ``name``.

    The module is in ``sys.modules`` while it executes (dataclasses and pickling look it
    up there) and is removed again if executing it fails.

    Args:
        name: the module's name (dotted names need no parent package).
        path: a ``.py`` file or a compiled extension module.

    Returns:
        The executed module.

    Raises:
        NotAModule: ``path`` is neither a Python source file nor an extension module.
        Exception: whatever executing the module raises.
    """
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise NotAModule(f"{path}: not a Python source file or extension module")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    try:
        spec.loader.exec_module(mod)
    except BaseException:
        sys.modules.pop(name, None)
        raise
    return mod
