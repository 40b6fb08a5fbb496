"""User modules: a reader's own declarations, checked and compiled by the book's engine.

A user module is a Python file (or an importable dotted name) that declares equations with
:func:`rigidsym.equation` under user ids ``namespace:name`` and, optionally, kernels in a
module-level ``KERNELS`` list of :class:`rigidsym.codegen.spec.Kernel`.

- A file is imported under a unique module name (derived from its resolved path) with its
  folder on ``sys.path``; a dotted name is imported with the current directory on
  ``sys.path``.
- Loading a module again (a notebook cell run twice, an edited file) first forgets its
  declarations, so they are replaced, never "declared twice".
- Bad input (a missing file, a module that raises on import, a malformed or reserved id, an
  id declared in two places, a declaration returning the wrong type) raises
  :class:`rigidsym.registry.declarations.BadInput` with one line naming the module and
  the problem.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib
import os
import re
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from rigidsym.core.files import NotAModule, load_module
from rigidsym.registry.declarations import (
    REGISTRY,
    BadInput,
    DeclarationTypeError,
    forget_module,
    is_user_id,
    load_all,
)

__all__ = ["UserModule", "load", "load_many", "adopt", "module_of", "LOADED", "MODULE_HELP",
           "select_with_modules"]


@dataclass(frozen=True)
class UserModule:
    """A loaded user module.

    Attributes:
        name: the name it is imported under (``sys.modules`` key, ``Equation.module``).
        title: the name a reader knows it by: the file's stem or the dotted name (used in
            report titles, file names and generated headers).
        path: the file, or ``None`` for a dotted name without a file.
        ids: the ids it declares, in declaration order.
        kernels: its ``KERNELS`` (kernel specs), possibly empty.
    """

    name: str
    title: str
    path: Path | None
    ids: tuple[str, ...]
    kernels: tuple = ()


#: Loaded user modules by import name (a module loaded again replaces its entry).
LOADED: dict[str, UserModule] = {}

_DOTTED = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*$")


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _is_path(spec: str) -> bool:
    return spec.endswith(".py") or os.sep in spec or "/" in spec or not _DOTTED.match(spec)


@contextlib.contextmanager
def _first_on_path(folder: str):
    """``folder`` first on ``sys.path`` while the user's module executes (its sibling imports
    work), then last: a user file named like an installed package (examples/modern_robotics.py)
    must not shadow the package for the rest of the process. A folder already on the path
    stays where it is."""
    if folder in sys.path:
        yield
        return
    sys.path.insert(0, folder)
    try:
        yield
    finally:
        with contextlib.suppress(ValueError):
            sys.path.remove(folder)
        sys.path.append(folder)  # a later lazy sibling import still finds it


def _import_file(path: Path) -> tuple[str, object]:
    """Execute ``path`` as a fresh module under a name unique to its resolved path."""
    digest = hashlib.sha256(str(path).encode()).hexdigest()[:10]
    stem = re.sub(r"\W", "_", path.stem)
    name = f"_rigidsym_user_{stem}_{digest}"
    forget_module(name)
    try:
        with _first_on_path(str(path.parent)):
            mod = load_module(name, path)
    except NotAModule:
        raise BadInput(f"module {path}: not a Python source file") from None
    except BaseException:
        forget_module(name)
        raise
    return name, mod


def _import_dotted(dotted: str) -> tuple[str, object]:
    forget_module(dotted)
    old = sys.modules.get(dotted)
    try:
        with _first_on_path(os.getcwd()):
            mod = importlib.reload(old) if old is not None else importlib.import_module(dotted)
    except BaseException:
        forget_module(dotted)
        raise
    return dotted, mod


def load(spec: str | os.PathLike) -> UserModule:
    """Import a user module (a ``.py`` file or a dotted name) and register its declarations.

    Args:
        spec: a path to a ``.py`` file, or a dotted module name importable from the
            current directory.

    Returns:
        The :class:`UserModule`, also kept in :data:`LOADED`.

    Raises:
        BadInput: one line naming the module and the problem (missing file, an exception
            on import, a malformed, reserved or twice-declared id, a declaration that
            returns something other than a ``Statement``).
    """
    load_all()  # the book first: a user id colliding with it is then caught on import
    text = os.fspath(spec)
    if _is_path(text):
        path = Path(text).expanduser().resolve()
        label = text
        if not path.is_file():
            raise BadInput(f"module {text}: no such file")
        title = path.stem
    else:
        path, label, title = None, text, text
    try:
        name, mod = _import_file(path) if path is not None else _import_dotted(text)
    except BadInput:
        raise
    except ModuleNotFoundError as exc:
        if path is None and exc.name and text.startswith(exc.name):
            raise BadInput(f"module {label}: not found (a dotted name is imported from the "
                           f"current directory; give a path to a .py file otherwise)") from exc
        raise BadInput(f"module {label}: raised on import: {_one_line(exc)}") from exc
    except Exception as exc:  # the module's own error, reported in one line
        raise BadInput(f"module {label}: raised on import: {_one_line(exc)}") from exc
    except SystemExit as exc:
        raise BadInput(f"module {label}: called sys.exit({exc.code}) on import") from exc
    if path is None and getattr(mod, "__file__", None):
        path = Path(mod.__file__)
    ids = tuple(k for k, eq in REGISTRY.items() if eq.module == name)
    book = [k for k in ids if not is_user_id(k)]
    if book:  # only reachable from inside rigidsym.derivations: not a user module
        raise BadInput(f"module {label}: declares book ids ({', '.join(book)})")
    kernels = tuple(getattr(mod, "KERNELS", ()) or ())
    um = UserModule(name, title, path, ids, kernels)
    LOADED[name] = um
    _prebuild(um, label)
    return um


#: the ids of those given whose declaration, as it is now, is known to build (a verdict of
#: it is stored); set by :mod:`rigidsym.checking.verdict_cache`, a layer above
KNOWN_TO_BUILD: Callable[[tuple[str, ...]], set[str]] | None = None


def _prebuild(um: UserModule, label: str) -> None:
    """Build every declaration once, here, so a wrong return type is bad input (exit 2).

    Any other exception inside a declaration is left for the checker, which reports that id
    ``undecided`` with the error; built statements are cached (and inherited by forked
    workers). A declaration known to build (:data:`KNOWN_TO_BUILD`) is not built: a warm
    command builds nothing.
    """
    known = KNOWN_TO_BUILD(um.ids) if KNOWN_TO_BUILD else set()
    for eq_id in um.ids:
        if eq_id in known:
            continue
        try:
            REGISTRY[eq_id].build()
        except DeclarationTypeError as exc:
            raise BadInput(f"module {label}: {exc}") from exc
        except Exception:  # noqa: BLE001  (reported per id by the checker)
            continue


def adopt(mod) -> UserModule:
    """Register an already imported module (``import mynotes`` in a notebook) as a user
    module, without importing it again; returns its :class:`UserModule`.

    Raises:
        BadInput: if its ``KERNELS`` or a declaration is malformed.
    """
    name = mod.__name__
    if name in LOADED and LOADED[name].title != name:  # a file this module loaded
        old = LOADED[name]
        ids = tuple(k for k, eq in REGISTRY.items() if eq.module == name)
        LOADED[name] = UserModule(name, old.title, old.path, ids, old.kernels)
        return LOADED[name]
    path = Path(mod.__file__) if getattr(mod, "__file__", None) else None
    ids = tuple(k for k, eq in REGISTRY.items() if eq.module == name)
    kernels = tuple(getattr(mod, "KERNELS", ()) or ())
    um = UserModule(name, name, path, ids, kernels)
    LOADED[name] = um
    _prebuild(um, name)
    return um


def load_many(specs) -> list[UserModule]:
    """:func:`load` each of ``specs`` in order (see there); returns the modules."""
    return [load(s) for s in specs or ()]


def module_of(eq_id: str) -> UserModule | None:
    """The loaded user module that declares ``eq_id``, if any."""
    eq = REGISTRY.get(eq_id)
    return LOADED.get(eq.module) if eq is not None else None


#: help text of the ``--module`` options
MODULE_HELP = ("a user module: a .py file or a dotted name importable from the current "
               "directory (repeatable)")


def select_with_modules(ids, sections, modules) -> list[str]:
    """Load ``modules`` (paths or dotted names), then resolve ids and sections as
    :func:`rigidsym.registry.declarations.select` does: with no ids and no sections, the
    modules' ids.

    Raises:
        BadInput: for a module that cannot be loaded, or an unknown id or section.
    """
    from rigidsym.registry.declarations import select

    names = [m.name for m in load_many(modules)]
    return select(ids, sections, names)
