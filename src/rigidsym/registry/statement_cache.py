"""The built statements of the book, kept on disk (``<cache>/statements/``, see
:mod:`rigidsym.core.cache` for where and how): a process that needs a book declaration's
:class:`~rigidsym.registry.declarations.Statement` loads it rather than running the
declaration again (building the chapter's statements is about 5 s of CPU, repeated by every
command, every ``verify --jobs N`` worker and every test worker).

**One entry per book module**: the statements of every declaration of one module of the
book, in one pickle (the declarations of a module share their models, which a pickle keeps
shared). A process stores a module's entry when it has built every declaration of it (a
``verify`` worker checks a section at a time, :mod:`rigidsym.checking.runner`), and loads
it the first time it needs one of them (:func:`load`, by
:func:`rigidsym.registry.declarations.Equation.build`).

**The key** of a module's entry is a SHA-256 over what can change its statements: every
file of the ``rigidsym`` package and of the book's folder, by content
(:func:`rigidsym.core.sources.package_digest`, which the generated kernels are left out
of: they are made from those sources), the versions of Python, sympy, mpmath and
python-flint, the module's name, the pickle protocol and :data:`FORMAT`. Any edit of the
package misses every entry, however far it seems from a declaration: a statement read back
is never one an edit would have changed. User declarations (``namespace:name``) are never
stored: their sources lie outside the package and a notebook replaces them.

**Exactly the built statement.** sympy evaluates an expression again when a pickle is read
(``Mul(-1, a + b)`` becomes ``-a - b``), so an entry is read with evaluation off
(:func:`sympy.core.parameters.evaluate`): every node is made of the arguments it was
stored with, and the statement read is equal (``==``, node by node) to the one built.
Turning evaluation off and on again empties sympy's cache (sympy's own guard: nothing made
unevaluated stays cached), once per entry read.

**Never trusted when damaged**: an entry whose checksum, format, key or module does not
match, or that does not unpickle into statements, is a miss; the declarations are built
and the entry is written again. Writing is best effort: a cache folder that cannot be
written (read-only, full) leaves the statements built, without error. Writers hold the
cache's lock and write through :func:`rigidsym.core.cache.put` (a temporary file and a
rename), so that processes filling the cache at once never leave half an entry. The
entries are pickles: the cache folder is trusted as the package's own folder is (whoever
can write either can run code as its owner).
"""

from __future__ import annotations

import hashlib
import pickle
from collections.abc import Mapping
from pathlib import Path

from rigidsym.core import cache as _cache
from rigidsym.core import sources as _sources

__all__ = ["FORMAT", "PROTOCOL", "key_of", "path_of", "load", "store"]

#: version of the entry format (an entry of another format is a miss)
FORMAT = 1
#: the pickle protocol of the entries (part of the key)
PROTOCOL = pickle.HIGHEST_PROTOCOL


def key_of(module: str) -> str | None:
    """The key (hex SHA-256) of the book module ``module``'s entry, or ``None`` when the
    package's files cannot be read.

    Args:
        module: the dotted name of a book module (``"rigidsym.derivations.sec3_5"``).
    """
    try:
        parts = [f"statements {FORMAT}", f"pickle {PROTOCOL}", _sources.package_digest(),
                 _sources.environment(), module]
    except OSError:  # a file gone while the package is digested
        return None
    h = hashlib.sha256()
    for part in parts:
        h.update(part.encode() + b"\0")
    return h.hexdigest()


def path_of(key: str) -> Path:
    """Where the entry of ``key`` lies: ``<cache>/statements/<key[:2]>/<key>.pickle`` (its
    checksum beside it, ``.pickle.sha256``)."""
    return _cache.folder("statements") / key[:2] / f"{key}.pickle"


def load(module: str, key: str) -> dict[str, object] | None:
    """The statements stored for ``module`` under ``key``: ``{id: statement}``, or ``None``
    for a miss (no entry, or one that is damaged or written for another key).

    Reading empties sympy's cache (evaluation is off while the entry is read). Never raises
    for the entry's sake: any failure to read or unpickle it is a miss.
    """
    data = _cache.get(path_of(key))
    if data is None:
        return None
    from sympy.core.parameters import evaluate

    try:
        with evaluate(False):  # each node made of its stored arguments, as built
            entry = pickle.loads(data)  # noqa: S301  (the user's own cache: see above)
    except Exception:  # noqa: BLE001  (a damaged entry is a miss, whatever it raises)
        return None
    if not isinstance(entry, dict) or entry.get("format") != FORMAT \
            or entry.get("key") != key or entry.get("module") != module \
            or not isinstance(entry.get("statements"), dict):
        return None
    return entry["statements"]


def store(module: str, key: str, statements: Mapping[str, object]) -> bool:
    """Write the entry of ``module`` under ``key`` (``{id: statement}``, every declaration of
    the module), replacing what is there; returns whether it was written.

    Best effort: a statement that does not pickle, a folder that cannot be written or a
    lock held too long leave the cache as it was and return ``False``; nothing is raised.
    """
    try:
        data = pickle.dumps({"format": FORMAT, "key": key, "module": module,
                             "statements": dict(statements)}, protocol=PROTOCOL)
    except Exception:  # noqa: BLE001  (a value that does not pickle: not stored)
        return False
    path = path_of(key)
    try:
        from filelock import Timeout

        with _cache.lock("statements", timeout=60.0):  # one writer at a time: the data and
            _cache.put(path, data)                      # its checksum go together
    except (OSError, Timeout):
        return False
    return True
