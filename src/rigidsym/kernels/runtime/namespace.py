"""The namespace of a generated directory's kernels, and the package's own.

:func:`load` binds a generated ``api`` module (``rigidsym generate --out DIR``) to the
checked evaluation of its directory (a :class:`~rigidsym.kernels.runtime.space.KernelSpace`)
and returns its kernels with the helpers as one module object. The package's own kernels are
``load()`` of its generated directory, bound when this module is imported, and published as
:mod:`rigidsym.kernels`' (:func:`public`): they are documented there, pickled by reference
through it, and their examples run there, as are those of the helpers the package re-exports.
"""

from __future__ import annotations

import types
from collections.abc import Callable
from pathlib import Path

import rigidsym.generated.api as package_api
from rigidsym.core.config import generated_dir
from rigidsym.core.files import load_module
from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.screw_at_infinity import document
from rigidsym.kernels.runtime.space import KernelSpace

__all__ = ["PUBLIC_MODULE", "KERNEL_NAMES", "public", "load", "space_of"]

#: the module the package's kernels and helpers are public in (``rigidsym.kernels``)
PUBLIC_MODULE = "rigidsym.kernels"
#: names of the public generated kernels
KERNEL_NAMES = tuple(sorted(package_api.__all__))


def public(fn: Callable) -> Callable:
    """Publish ``fn`` as :data:`PUBLIC_MODULE`'s own (its ``__module__``), which re-exports it:
    pickled by reference, documented and its examples run there, as when it was defined there.

    Returns:
        ``fn`` itself (a decorator).
    """
    fn.__module__ = PUBLIC_MODULE
    return fn


for _name in package_api.__all__:  # pickled by reference through rigidsym.kernels
    public(getattr(package_api, _name))


def _bind_module(mod: types.ModuleType) -> KernelSpace:
    """Bind a generated ``api`` module to the kernel space of its directory."""
    here = Path(mod.__file__).resolve().parent
    if mod.__name__ == _state.PACKAGE_API:
        if _state.STATE["builtin"] is None:
            # the NumPy module names of the package's kernels are stable (tests look them up)
            _state.register_builtin(KernelSpace.from_directory(
                generated_dir(), prefix="rigidsym._generated_numpy"))
        space = _state.builtin()
    else:
        space = KernelSpace.from_directory(here)
    space.bind_api(mod)
    document(mod)
    return space


_LOADED: dict[Path, types.ModuleType] = {}
#: names a loaded namespace exposes besides its kernels
_NAMESPACE_HELPERS = ("KERNEL_NAMES", "batch_function")


def _namespace(mod: types.ModuleType, space: KernelSpace, gdir: Path) -> types.ModuleType:
    """The namespace :func:`load` returns: the kernels of ``mod`` and the public helpers,
    nothing of the generated module's own imports (``np``, ``Any``, ...)."""
    ns = types.ModuleType(f"rigidsym.kernels.load({str(gdir)!r})",
                          f"The checked kernels generated into {gdir}.")
    for name in mod.__all__:
        setattr(ns, name, getattr(mod, name))
    ns.KERNEL_NAMES = tuple(mod.__all__)
    ns.batch_function = space.batch_function
    ns.__all__ = [*mod.__all__, *_NAMESPACE_HELPERS]
    ns._SPACE = space  # private: space_of(DIR) and tests reach the directory's space
    return ns


@public
def load(directory: str | Path | None = None) -> types.ModuleType:
    """The checked kernel namespace of a generated directory.

    Args:
        directory: a folder as ``rigidsym generate --out DIR`` writes it (``kernels.json``,
            ``api.py``, ``numpy/``, ``c/``); default the package's own kernels.

    Returns:
        A namespace (a module object) holding only the directory's kernels, with the same
        validation, ``on_singular`` handling and C (compiled into the user cache once, with
        a notice on stderr, when no build matches; NumPy fallback without a compiler) as
        :mod:`rigidsym.kernels`, and the helpers ``KERNEL_NAMES`` (their names) and
        ``batch_function(name, backend)``. Loading the same directory twice returns the
        same namespace.

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        FileNotFoundError: ``directory`` has no ``kernels.json`` or ``api.py``.

    Example:
        >>> load().twist_transfer is twist_transfer
        True
    """
    directory = _names.directory(directory)
    gdir = generated_dir() if directory is None else directory.resolve()
    for f in ("kernels.json", "api.py"):
        if not (gdir / f).is_file():
            raise FileNotFoundError(f"directory: no {f} in {gdir} (run `rigidsym generate "
                                    f"--out {gdir}`)")
    if gdir in _LOADED:
        return _LOADED[gdir]
    if gdir == generated_dir().resolve():
        mod = package_api
    else:
        space = KernelSpace.from_directory(gdir)
        mod = load_module(f"{space.prefix}.api", gdir / "api.py")
    _LOADED[gdir] = ns = _namespace(mod, _bind_module(mod), gdir)
    return ns


def space_of(directory: str | Path | None = None) -> KernelSpace:
    """The kernel space of a generated directory (:func:`load`'s), default the package's.

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        FileNotFoundError: ``directory`` has no ``kernels.json`` or ``api.py``.
    """
    return _state.builtin() if _names.directory(directory) is None else \
        load(directory)._SPACE


# the package's kernels are load() of its generated directory (binds generated.api here)
load()
