"""The peers of the kernels: per kernel, the functions a user would call
instead, in pytransform3d, Pinocchio, PyPose, jaxlie, spatialmath-python and Modern
Robotics' library, each with the adapter that puts it in the kernel's conventions.

This is the table the accuracy rule's reference half reads (:mod:`.rule`: ``err <= max(2
e_ref, 4 u)``, ``e_ref`` the smallest error of the textbook formula and of each peer; the
textbook formula, :func:`.rule.textbook`, judges every kernel and is not listed here), and
the one docs/accuracy.md's peer column is written from (:func:`markdown`). Plain data: an
entry names its library, the call as the docs print it, the kernel outputs it computes and
an adapter ``adapt(lib, *args) -> one array per output``, ``lib`` the library's module,
imported on first use (these libraries are the test-only ``[oracles]`` extra, never a
dependency: :func:`available` leaves out a peer whose library is missing and says why).

Conventions (each adapter is checked against the kernel at random points by
``tests/test_peers.py``, and the conventions below by numeric properties there, not by
belief): rigidsym's ``xi = [w; v]`` (angular first) and ``eta = [r; r0]`` (scalar last);
Pinocchio's and PyPose's, jaxlie's and spatialmath's SE(3) tangent vectors are ``[v; w]``
(linear first; Modern Robotics' ``[w; v]``); quaternions are ``w`` first in pytransform3d,
spatialmath and ``pin.Quaternion(w, x, y, z)``, ``xyzw`` in PyPose and jaxlie's
``from_quaternion_xyzw``. Pinocchio's ``Jexp3``/``Jexp6`` and PyPose's ``Jr`` are right
Jacobians (``Exp(w + dw) = Exp(w) Exp(J_r dw)``), ``J_l(w) = J_r(-w)``; ``Jlog3(R)``,
``Jlog6(M)`` and jaxlie's ``jlog()`` are ``J_r^-1`` at the logarithm, so they stand for
the kernel only where the logarithm gives ``w`` back (``|w| < pi``; elsewhere the adapter
raises, which the harness counts as the peer failing there).

A ``<name>_with_jacobians`` kernel has the peers of ``<name>`` for its values (its
derivatives then from the textbook formula alone), and the derivative peers listed for it
(the exponential maps' derivatives from Pinocchio's and PyPose's right Jacobians:
``dExp(w)/dw_k = Exp(w) hat(J_r(w) e_k)``).
"""

from __future__ import annotations

import importlib
import importlib.metadata
import importlib.util
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from rigidsym.codegen.accuracy import peer_adapters as A
from rigidsym.codegen.accuracy.peer_adapters import x64

__all__ = ["LIBRARIES", "PEERS", "Peer", "available", "for_kernel", "markdown", "x64"]

#: library (as the table names it) -> (module imported on first use, distribution, version
#: the adapters were checked with)
LIBRARIES = {
    "pytransform3d": ("pytransform3d", "pytransform3d", "3.17"),
    "Pinocchio": ("pinocchio", "pin", "4.1"),
    "PyPose": ("pypose", "pypose", "0.9"),
    "jaxlie": ("jaxlie", "jaxlie", "1.5"),
    "spatialmath": ("spatialmath.base", "spatialmath-python", "1.1.18"),
    "Modern Robotics": ("modern_robotics", "modern_robotics", "1.1.1"),
}


@dataclass(frozen=True)
class Peer:
    """One peer function of one kernel.

    Attributes:
        kernel: the kernel's name (a ``_with_jacobians`` kernel also has its base's).
        library: a key of :data:`LIBRARIES`.
        call: what is called, in the kernel's arguments, as docs/accuracy.md prints it.
        outputs: the kernel outputs the adapter returns, in that order.
        adapt: ``adapt(lib, *args)``: ``lib`` the library's module, ``args`` the kernel's
            arguments at one point (float64 arrays of the declared shapes); returns one
            array-like per name of ``outputs``, in the kernel's conventions. Raises where
            the peer does not compute the kernel's function (outside its domain).
    """

    kernel: str
    library: str
    call: str
    outputs: tuple[str, ...]
    adapt: Callable[..., Sequence]

    @property
    def label(self) -> str:
        """``library call``: the yardstick's name in the harness's tables."""
        return f"{self.library} {self.call}"

def _table() -> tuple[Peer, ...]:
    P: list[Peer] = []

    def add(kernel, library, call, outputs, adapt):
        P.append(Peer(kernel, library, call, tuple(outputs.split()), adapt))

    for subject in (A.rotations, A.screws, A.transfers, A.dynamics, A.so3, A.se3,
                    A.quaternions):
        subject(add)
    return tuple(P)


#: every peer, in the table's order
PEERS: tuple[Peer, ...] = _table()

_LOADED: dict[str, object] = {}


def _installed_copy(mod: str, dist: str) -> None:
    """Raise ImportError unless ``mod``'s top-level package would be imported from the
    installed distribution ``dist``: a user's file of that name on ``sys.path`` (a
    ``--module`` folder, which stays last on the path, holds examples/modern_robotics.py)
    is not the library, and importing it would run it. Checked before any import."""
    try:
        where = Path(str(importlib.metadata.distribution(dist).locate_file(""))).resolve()
    except importlib.metadata.PackageNotFoundError:
        raise ImportError(f"the {dist} distribution is not installed") from None
    spec = importlib.util.find_spec(mod.split(".")[0])
    origin = None if spec is None else spec.origin or next(
        iter(spec.submodule_search_locations or ()), None)
    if origin is None or not Path(origin).resolve().is_relative_to(where):
        raise ImportError(f"`{mod.split('.')[0]}` would be imported from {origin}, not from "
                          f"the installed {dist} ({where})")


def _load(library: str):
    """The library's module, imported once; an ImportError (with its reason) if missing or
    if the name finds another file first (:func:`_installed_copy`)."""
    if library not in _LOADED:
        mod = LIBRARIES[library][0]
        try:
            _installed_copy(mod, LIBRARIES[library][1])
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                m = importlib.import_module(mod)
                if library == "pytransform3d":
                    importlib.import_module("pytransform3d.rotations")
                    importlib.import_module("pytransform3d.transformations")
            _LOADED[library] = m
        except ImportError as e:
            _LOADED[library] = e
    got = _LOADED[library]
    if isinstance(got, ImportError):
        raise ImportError(f"{library} ({LIBRARIES[library][1]}): not available, the "
                          f"[oracles] extra installs it ({got})")
    return got


def for_kernel(name: str) -> list[Peer]:
    """The peers of kernel ``name`` from :data:`PEERS` (none: empty): its own, and for a
    ``<base>_with_jacobians`` kernel those of ``<base>`` (its values) too."""
    base = name[: -len("_with_jacobians")] if name.endswith("_with_jacobians") else None
    return [p for p in PEERS if p.kernel == name or (base is not None and p.kernel == base)]


def available(name: str) -> tuple[list[tuple[Peer, Callable]], list[tuple[Peer, str]]]:
    """The peers of kernel ``name`` that can run here, each with ``f(*args) -> tuple of
    arrays`` (its library bound), and those left out, each with the reason.

    Raises nothing: a missing library is a reason (the ``[oracles]`` extra)."""
    ok, missing = [], []
    for p in for_kernel(name):
        try:
            lib = _load(p.library)
        except ImportError as e:
            missing.append((p, str(e)))
            continue
        ok.append((p, lambda *args, p=p, lib=lib: p.adapt(lib, *args)))
    return ok, missing


def markdown() -> str:
    """docs/accuracy.md's peer table: per kernel with a peer, each peer's library and call
    (``tests/test_accuracy_docs.py`` fails when the page and :data:`PEERS` disagree)."""
    rows: dict[str, list[str]] = {}
    for p in PEERS:
        rows.setdefault(p.kernel, []).append(f"{p.library} {p.call}")
    lines = ["| kernel | peer functions compared (besides the textbook formula) |",
             "|---|---|"]
    lines += [f"| `{k}` | {'; '.join(v)} |" for k, v in rows.items()]
    return "\n".join(lines) + "\n"
