"""Find, check and load the compiled extension of a generated directory; compile it into
the user cache only when nothing built matches, and never silently.

Which module runs, first match:

1. a native build in the cache (``rigidsym build-c --native``), when one is there;
2. the package's own module (``rigidsym/kernels/_ckernels*.so``, built by ``pip install``),
   for the package's kernels, when the sources hash built into it matches ``generated/c``;
3. the dispatched default build in the cache, compiled now if missing (a user's kernels; an
   editable install whose module is stale because ``rigidsym generate`` ran since).

A module is loaded only when the hash built into it equals the hash of the folder's C (read
from its bytes, before loading), so a stale module never runs. Cache entries are written
under a cross-process lock (:func:`rigidsym.core.cache.lock`, the well-kept ``filelock``) and
with a checksum (:func:`rigidsym.core.cache.put`); one that fails it is rebuilt with a warning.
Before a compile starts one line on stderr says what, where and about how long; on a
terminal ``rich`` shows a progress bar. Keys name the sources, flags, Python, machine and,
for a native build, the CPU's features: never the host name, so a shared
``RIGIDSYM_CACHE`` hits across identical machines.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import json
import os
import platform
import sys
import threading
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

from rigidsym.core import cache as _cache
from rigidsym.core.config import generated_dir  # re-exported: the one place that finds it
from rigidsym.core.files import load_module
from rigidsym.kernels.cbuild import driver as _build

__all__ = ["Loaded", "load", "generated_dir", "info", "ensure", "entry", "package_module",
           "NoCompiledKernels"]

_LOCK = threading.RLock()
_MODULES: dict[Path, Loaded] = {}
_WARNED = {"omp": False}


class NoCompiledKernels(RuntimeError):
    """No compiled module matches the sources and none can be built (no compiler); the
    message says how to get one."""


@dataclass(frozen=True)
class Loaded:
    """A loaded extension: the module, its file, where it came from (``"wheel"``,
    ``"editable build"``, ``"cache"``, ``"cache (native)"``) and its sources hash."""

    module: ModuleType
    file: Path
    origin: str
    sources: str


def package_module() -> Path | None:
    """The module file built with the package (``pip install``), if any."""
    here = Path(__file__).resolve().parents[1]   # the module sits in rigidsym/kernels/
    for suffix in importlib.machinery.EXTENSION_SUFFIXES:
        p = here / f"{_build.MODULE}{suffix}"
        if p.is_file():
            return p
    return None


def _key(sources: str, native: bool) -> str:
    """The cache key of a build: sources, paths and flags, Python, machine (and the CPU's
    features for a native build); no host name."""
    paths = _build.default_paths(native)
    parts = [sources, " ".join(_build.kernel_flags()),
             ";".join(f"{p.name}={' '.join(p.flags)}" for p in paths),
             sys.implementation.cache_tag, platform.machine(), platform.system(),
             os.environ.get("RIGIDSYM_OPENMP", "1"), os.environ.get("RIGIDSYM_LIBMVEC", "0")]
    if native:
        parts.append(_build.cpu_features())
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()[:20]


def entry(gdir: Path, native: bool = False, sources: str | None = None) -> Path:
    """The cache file of the module of ``gdir`` (default build, or native)."""
    sources = sources or _build.sources_hash(Path(gdir) / "c")
    label = "native" if native else "+".join(p.name for p in _build.default_paths())
    name = f"{label}-{sys.implementation.cache_tag}-{_key(sources, native)}"
    suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
    return _cache.folder("kernels") / name / f"{_build.MODULE}{suffix}"


def _valid(path: Path, sources: str) -> bool | None:
    """True: the entry is whole (checksum) and built from ``sources``; None: missing;
    False: present but corrupt or foreign."""
    if not path.exists():
        return None
    data = _cache.get(path)
    return data is not None and _build.embedded_hash(data) == sources


def _notice(gdir: Path, cfg: _build.Config, where: Path, why: str) -> None:
    from rigidsym.core.progress import begun

    begun()     # the build's own lines follow: the program's start lines end
    cdir = Path(gdir) / "c"
    n = len(_build.kernel_sources(cdir)) - 1     # the table is not a kernel
    print(f"rigidsym: compiling the C of {n} kernels in {gdir} ({why}) for "
          f"{' + '.join(p.name for p in cfg.paths)} into {where.parent}: about "
          f"{_build.estimate_seconds(cdir, cfg):.0f} s on {_build.jobs()} cores",
          file=sys.stderr, flush=True)


def _compile(gdir: Path, cfg: _build.Config, path: Path) -> None:
    """Build into a temporary folder beside ``path``, then :func:`_cache.put` (atomic,
    checksummed). A progress bar on a terminal, else a line per tenth of the objects and one
    whenever :data:`rigidsym.kernels.cbuild.driver.SILENCE` seconds passed without one."""
    import tempfile
    import time

    from rigidsym.core.files import write_atomic_bytes

    path.parent.mkdir(parents=True, exist_ok=True)
    stats: dict = {}
    with tempfile.TemporaryDirectory(dir=path.parent, prefix=".build-") as tmp:
        out = Path(tmp) / path.name
        if sys.stderr.isatty():
            from rich.console import Console
            from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

            with Progress(TextColumn("rigidsym: compiling"), BarColumn(),
                          TextColumn("{task.completed}/{task.total} objects"),
                          TimeElapsedColumn(), console=Console(stderr=True),
                          transient=True) as bar:
                total = _build.object_count(Path(gdir) / "c", cfg) + 1
                task = bar.add_task("compile", total=total)
                _build.build(gdir, out, cfg, Path(tmp),
                             lambda done, total, running=(): bar.update(task, completed=done,
                                                                        total=total),
                             stats=stats)
        else:   # a line per tenth, and one whenever 2.5 s passed without (what runs)
            _build.build(gdir, out, cfg, Path(tmp), stats=stats,
                         progress=_build.text_progress(time.perf_counter(), sys.stderr))
        stats.update(paths=[p.name for p in cfg.paths],
                     built=time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()))
        _cache.put(path, out.read_bytes())
        write_atomic_bytes(_stats_file(path), (json.dumps(stats, indent=1) + "\n").encode())


@contextmanager
def _lock(path: Path) -> Iterator[None]:
    """The cross-process lock of one cache entry; a process that has to wait for another's
    compile says so first (waiting is not silent either)."""
    from filelock import Timeout

    try:
        with _cache.lock("kernels", path.parent.name, timeout=0):
            yield
            return
    except Timeout:
        pass
    print(f"rigidsym: another process is compiling these kernels into {path.parent}; "
          f"waiting for it", file=sys.stderr, flush=True)
    with _cache.lock("kernels", path.parent.name):
        yield


def ensure(gdir: Path, native: bool = False, why: str = "not compiled yet",
           force: bool = False) -> Path:
    """The cache entry of ``gdir``'s module, compiled first when missing, corrupt (with a
    warning) or ``force``; one process compiles, the others wait for it (file lock).

    Raises:
        rigidsym.kernels.cbuild.driver.CompilerNotFound: no C compiler (and nothing cached).
        rigidsym.kernels.cbuild.driver.BuildError: compiling failed.
    """
    gdir = Path(gdir).resolve()
    sources = _build.sources_hash(gdir / "c")
    path = entry(gdir, native, sources)
    if not force and _valid(path, sources):
        return path
    cfg = _build.configure(native)
    with _lock(path):
        state = _valid(path, sources)
        if state and not force:
            return path                     # another process built it meanwhile
        if state is False:
            warnings.warn(f"rigidsym: the cached kernels {path} fail their checksum "
                          f"(corrupt or truncated); rebuilding them", RuntimeWarning,
                          stacklevel=3)
        _notice(gdir, cfg, path, "forced rebuild" if force and state else why)
        _compile(gdir, cfg, path)
    return path


def _import(path: Path, origin: str, sources: str, name: str) -> Loaded:
    # idle OpenMP threads sleep instead of spinning (read by libgomp when it loads; a
    # user's setting wins): a spinning worker takes the caller's core between two kernel
    # calls, measured 11 ms per 2-thread call on a busy 2-core machine instead of 0.1 ms
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    mod = load_module(name, path)
    if mod.sources != sources:     # read from the bytes already; a race with a rebuild
        sys.modules.pop(name, None)
        raise ImportError(f"{path}: built from other sources than it was checked against")
    if not mod.openmp and os.environ.get("RIGIDSYM_OPENMP", "1") != "0" \
            and not _WARNED["omp"]:
        _WARNED["omp"] = True
        warnings.warn(f"rigidsym: the C kernels of {path} were built without OpenMP (the "
                      f"compiler had none); they run on one thread", RuntimeWarning,
                      stacklevel=4)
    return Loaded(mod, path, origin, sources)


def _origin(path: Path) -> str:
    """``"editable build"`` for a module built in place in a checkout (``src/rigidsym/...``
    beside ``pyproject.toml``), else ``"wheel"`` (installed from one, whatever the folder)."""
    root = path.resolve().parents[3]
    in_checkout = path.resolve().parents[2].name == "src" and (root / "pyproject.toml").is_file()
    return "editable build" if in_checkout else "wheel"


def load(gdir: Path, package: bool = False) -> Loaded:
    """The extension of generated directory ``gdir`` (see the module docstring); the same
    object for the same folder. ``package``: ``gdir`` is the package's own ``generated/``.

    Raises:
        NoCompiledKernels: nothing compiled matches and no compiler builds it.
        rigidsym.kernels.cbuild.driver.BuildError: compiling failed.
    """
    gdir = Path(gdir).resolve()
    with _LOCK:
        if gdir in _MODULES:
            return _MODULES[gdir]
        sources = _build.sources_hash(gdir / "c")
        tag = "rigidsym.kernels" if package else \
            f"rigidsym._loaded_{hashlib.sha256(str(gdir).encode()).hexdigest()[:12]}"
        name = f"{tag}.{_build.MODULE}"
        native = entry(gdir, True, sources)
        state = _valid(native, sources)
        if state is False:
            warnings.warn(f"rigidsym: the native build {native} fails its checksum (corrupt "
                          f"or truncated); not loaded (rebuild: rigidsym build-c --native)",
                          RuntimeWarning, stacklevel=3)
        if state:
            loaded = _import(native, "cache (native)", sources, name)
        else:
            loaded = _load_default(gdir, package, sources, name)
        _MODULES[gdir] = loaded
        return loaded


def _load_default(gdir: Path, package: bool, sources: str, name: str) -> Loaded:
    why = "not compiled yet"
    if package:
        built = package_module()
        if built is not None and _build.embedded_hash(built) == sources:
            return _import(built, _origin(built), sources, name)
        why = ("the module built at install time is stale: generated/ changed since "
               "(rigidsym generate)" if built is not None else
               "the package was installed without its compiled module")
    try:
        path = ensure(gdir, why=why)
    except _build.CompilerNotFound as exc:
        what = "the package's kernels" if package else f"the kernels of {gdir}"
        fix = ("install a prebuilt wheel of rigidsym, or a C compiler (e.g. `apt-get install "
               "gcc`) and reinstall" if package else
               f"install a C compiler (e.g. `apt-get install gcc`) and run `rigidsym build-c "
               f"{gdir}`, or compile them where one is (`rigidsym generate --module M --out "
               f"DIR` compiles them) and share RIGIDSYM_CACHE")
        raise NoCompiledKernels(f"{what} are not compiled ({why}) and {exc}: to get the C "
                                f"backend, {fix}") from None
    return _import(path, "cache", sources, name)


#: the libmvec variants each x86-64 path calls (nm -u of its objects, gcc 12, glibc 2.36)
_MVEC_VARIANTS = {"x86-64-v2": "SSE (_ZGVbN2v_sin, _ZGVbN2v_cos)",
                  "x86-64-v3": "AVX2 (_ZGVdN4v_sin, _ZGVdN4v_cos)",
                  "x86-64-v4": "AVX-512 (_ZGVeN8v_sin, _ZGVeN8v_cos)"}


def _mvec_variant(loaded: Loaded) -> str | None:
    m = loaded.module
    if not m.libmvec:
        return None
    if len(m.paths) > 1 and m.path in _MVEC_VARIANTS:
        return _MVEC_VARIANTS[m.path]
    # one path (native, baseline): the module's own undefined symbols say it
    import re

    names = sorted(set(re.findall(rb"_ZGV[a-z]N[0-9]+v_(?:sin|cos)", loaded.file.read_bytes())))
    return ", ".join(n.decode() for n in names) or "none called"


def _stats_file(module: Path) -> Path:
    """The record of a module's build (objects compiled and reused, seconds), beside it."""
    return module.with_name(f"{_build.MODULE}.build.json")


def _stats(module: Path) -> dict | None:
    try:
        return json.loads(_stats_file(module).read_text())
    except (OSError, ValueError):
        return None


def info(loaded: Loaded) -> dict:
    """The build information of a loaded extension (:func:`rigidsym.kernels.build_info`)."""
    m = loaded.module
    cpu = json.loads(_build.cpu_features()) if sys.platform.startswith("linux") else {}
    return {"path": m.path, "paths": list(m.paths),
            "forced": os.environ.get("RIGIDSYM_DISPATCH") or None,
            "openmp": bool(m.openmp), "libmvec": _mvec_variant(loaded),
            "file": str(loaded.file), "origin": loaded.origin, "sources": m.sources,
            "compiler": getattr(m, "compiler", None), "flags": m.build,
            "cpu": cpu.get("model name") or platform.processor() or platform.machine(),
            "build": _stats(loaded.file)}
