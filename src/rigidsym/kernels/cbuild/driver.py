"""The C compiler driver: a generated directory's ``c/`` into the extension module ``_ckernels``.

Used with the same flags in two places: by ``setup.py`` when the package is built (``pip
install``, ``pip wheel``: the package's kernels go into the wheel), and at run time by
:mod:`rigidsym.kernels.cbuild.extension` for what no wheel holds (a user's kernels, a stale editable
build, ``rigidsym build-c --native``), into the user cache. Standard library (and
:mod:`rigidsym.kernels.cbuild.objects`, the object cache) only: ``setup.py`` loads it by path.

CPU dispatch as in NumPy: every kernel source (and the table ``rigidsym_table.c``) is
compiled once per build path, with that path's ``-march`` and ``-DRIGIDSYM_ISA_SUFFIX``;
``rigidsym_module.c`` once, with the baseline path's flags; all objects link into one module
whose dispatcher (``rigidsym_dispatch.h``) picks a path at import. Paths: ``x86-64-v2``
(baseline), ``x86-64-v3`` (AVX2 + FMA) and ``x86-64-v4`` (AVX-512) on x86-64, no ``-march``
elsewhere, ``native`` (``-march=native``, one path) on request, never by default.

Flags of the kernels: ``-O3 -std=c99 -ffp-contract=off -fno-math-errno
-fno-tree-slp-vectorize`` (never ``-ffast-math``; ``RIGIDSYM_CFLAGS`` replaces them; the last
because GCC's SLP vectorizer fuses products into vfmaddsub despite -ffp-contract=off, see
:data:`rigidsym.kernels.cbuild.flags.KERNEL_FLAGS`). No FMA contraction: the
generator chooses its forms by their error measured with every product rounded (NumPy), and a
contracted ``a b + c`` rounds differently, not always better: contracted, C was 3.76 times the
textbook's error in ``rotation_from_rotation_vector`` (theta = |w| 0.79 ulp off, the
textbook 0.21), 2.1-2.9 times in ``newton_euler_residual`` and three Euler-angle rates, where
the uncontracted code gives NumPy's (the textbook's) result; measured at 0-12 % more time.
The explicit ``fma`` calls (the compensated forms, the sine's and cosine's error term) stay.
OpenMP (threads of
the batch loops) is used when a probe compiles and links with it (``RIGIDSYM_OPENMP=0``
skips it). The SIMD ``sin``/``cos`` are the generated header's own (within 1 ulp,
c_common.h.j2); glibc's libmvec (within 4 ulp, which takes trig kernels past the accuracy
rule) only on request, ``RIGIDSYM_LIBMVEC=1``, and when its probe links. Objects compile in parallel
(``RIGIDSYM_BUILD_JOBS``, default the usable cores), or come from the object cache.

GCC compiles ``rigidsym_common.h`` once per path into a precompiled header (GCC's own
``.gch``, used by ``-include``; the kernel's ``#include`` of it is then a guarded no-op): the
header (its intrinsics headers) was 0.7 of the about 1.1 CPU seconds of each kernel object,
and the objects are the same bytes with it and without it (tests/test_build.py). It is made
only for a path of :data:`PCH_MIN_OBJECTS` objects or more, when one of them is compiled
(not all from the object cache); another compiler, ``RIGIDSYM_PCH=0``, or a
precompiled header that GCC cannot use reads the header as text, to the same objects.
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
import shlex
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cache
from pathlib import Path

if __package__:
    from rigidsym.kernels.cbuild import flags as _flags
    from rigidsym.kernels.cbuild import objects as _objects
    from rigidsym.kernels.cbuild import paths as _paths
else:   # loaded by path from setup.py: the siblings by path too (rigidsym is not importable)
    import importlib.util as _ilu

    def _sibling(name: str):
        spec = _ilu.spec_from_file_location(f"_rigidsym{name}",
                                            Path(__file__).parent / f"{name}.py")
        mod = sys.modules[spec.name] = _ilu.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return mod

    _flags, _objects, _paths = _sibling("flags"), _sibling("objects"), _sibling("paths")

# the build paths, from rigidsym.kernels.cbuild.paths (read here by the runtime and the benchmarks)
IsaPath, X86_V4, X86_PATHS, NATIVE, BASELINE = (_paths.IsaPath, _paths.X86_V4, _paths.X86_PATHS,
                                                _paths.NATIVE, _paths.BASELINE)
default_paths, cpu_features, _x86 = _paths.default_paths, _paths.cpu_features, _paths.is_x86
# the kernels' flags and the refusal of unsafe ones, from rigidsym.kernels.cbuild.flags
KERNEL_FLAGS, COMMON_FLAGS, MVEC_FLAGS, OMP_FLAGS = (_flags.KERNEL_FLAGS, _flags.COMMON_FLAGS,
                                                     _flags.MVEC_FLAGS, _flags.OMP_FLAGS)
UNSAFE_FLAGS, unsafe_flag, kernel_flags = (_flags.UNSAFE_FLAGS, _flags.unsafe_flag,
                                           _flags.kernel_flags)

__all__ = ["MODULE", "IsaPath", "Config", "BuildError", "CompilerNotFound",
           "default_paths", "compiler", "configure", "kernel_sources", "sources_hash",
           "embedded_hash", "build", "object_count", "estimate_seconds", "jobs", "cpu_features",
           "Progress", "SILENCE", "TICK", "text_progress", "running_text",
           "X86_PATHS", "NATIVE", "BASELINE", "KERNEL_FLAGS", "MVEC_FLAGS", "OMP_FLAGS"]

#: the extension module's name (every generated directory builds one of this name)
MODULE = "_ckernels"
#: the module's own C (compiled once); every other ``c/*.c`` is compiled once per path
MODULE_SOURCE = "rigidsym_module.c"
#: the header every kernel and the table include first, precompiled per path under GCC
COMMON_HEADER = "rigidsym_common.h"
#: the objects a path must have for its header to be precompiled: making it costs about one
#: object's time, while the pool's other compiles of that path wait for it, and saves about
#: half of each object's (a user's few kernels read the header as text)
PCH_MIN_OBJECTS = 8
#: the table of one path's functions (compiled by every path, partial ones included)
TABLE_SOURCE = "rigidsym_table.c"
#: CPU seconds to compile one kernel object at -O3 (measured: 50 s for the 134 kernels of
#: the package at x86-64-v3 with gcc 12), for the "about N s" of the notice
SECONDS_PER_OBJECT = 0.4
_TAG = b"rigidsym-sources:"


class BuildError(RuntimeError):
    """Compiling or linking the kernels failed (the message ends with the compiler's)."""


class CompilerNotFound(BuildError):
    """No C compiler on ``PATH`` (``CC``, else the compiler Python was built with)."""


def compiler() -> list[str] | None:
    """The C compiler command (``CC``, else the one Python was built with, else ``cc``), or
    ``None`` when it is not on ``PATH``."""
    import shutil
    import sysconfig

    cmd = shlex.split(os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc")
    return cmd if cmd and shutil.which(cmd[0]) else None


def jobs() -> int:
    """Parallel compiles: ``RIGIDSYM_BUILD_JOBS``, else the cores this process may use."""
    env = os.environ.get("RIGIDSYM_BUILD_JOBS")
    if env and env.isdigit() and int(env) > 0:
        return int(env)
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not Linux
        return os.cpu_count() or 1


@dataclass(frozen=True)
class Config:
    """What to build with: the compiler, the paths (best first), the kernels' flags, and
    whether OpenMP and libmvec are used."""

    cc: tuple[str, ...]
    paths: tuple[IsaPath, ...]
    flags: tuple[str, ...]
    openmp: bool
    libmvec: bool

    def object_flags(self, path: IsaPath) -> list[str]:
        """Flags of one path's kernel objects."""
        return [*COMMON_FLAGS, *self.flags, *path.flags, *(MVEC_FLAGS if self.libmvec else ()),
                *(OMP_FLAGS if self.openmp else ()), f"-DRIGIDSYM_ISA_SUFFIX=_{path.suffix}"]

    def libraries(self) -> list[str]:
        return (["-lmvec"] if self.libmvec else []) + ["-lm"]

    def describe(self) -> str:
        """One line per path: its name and flags (the module's ``build`` attribute); a
        ``trig_only`` path says so."""
        some = " (kernels calling sin/cos, and V4_KERNELS)"
        return "; ".join(f"{p.name}{some if p.trig_only else ''}: "
                         f"{' '.join(self.object_flags(p)[len(COMMON_FLAGS):-1])}"
                         for p in self.paths)


_PROBE = """#include <math.h>
%s
double x[64], y[64];
int main(void)
{
    %s
    for (int i = 0; i < 64; ++i)
        y[i] = sin(x[i]) + cos(x[i]);
    return (int)y[0];
}
"""
_MVEC_DECL = ("#pragma omp declare simd notinbranch\ndouble sin(double);\n"
              "#pragma omp declare simd notinbranch\ndouble cos(double);")


@cache
def _probe(cc: tuple[str, ...], flags: tuple[str, ...], libs: tuple[str, ...], simd: bool) -> bool:
    """Whether a small program compiles and links (an executable: a shared object would
    accept an unresolved libmvec symbol) with ``flags`` and ``libs``."""
    import subprocess
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "probe.c"
        src.write_text(_PROBE % (_MVEC_DECL if simd else "",
                                 "#pragma omp simd" if simd else ""))
        r = subprocess.run([*cc, *flags, str(src), "-o", str(Path(tmp) / "probe"), *libs],
                           capture_output=True)
        return r.returncode == 0


def configure(native: bool = False, cc: list[str] | None = None) -> Config:
    """The build of this machine: compiler, paths, flags, OpenMP when it links, libmvec when
    asked for (``RIGIDSYM_LIBMVEC=1``) and it links.

    Raises:
        CompilerNotFound: no C compiler on ``PATH``.
        ValueError: bad ``RIGIDSYM_CFLAGS`` or ``RIGIDSYM_PATHS``.
    """
    cc = cc or compiler()
    if cc is None:
        import sysconfig

        name = os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"
        raise CompilerNotFound(f"no C compiler found ({name!r} is not on PATH)")
    cmd, flags, paths = tuple(cc), kernel_flags(), default_paths(native)
    base = (*flags, *paths[-1].flags)
    mvec = (sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc"
            and os.environ.get("RIGIDSYM_LIBMVEC", "0") == "1"
            and _probe(cmd, (*base, *MVEC_FLAGS), ("-lmvec", "-lm"), True))
    omp = (os.environ.get("RIGIDSYM_OPENMP", "1") != "0"
           and _probe(cmd, (*base, *OMP_FLAGS), ("-lm",), False))
    return Config(cmd, paths, flags, omp, mvec)


def kernel_sources(cdir: Path) -> list[Path]:
    """The sources compiled once per path: every ``c/*.c`` but the module's."""
    return sorted(p for p in Path(cdir).glob("*.c") if p.name != MODULE_SOURCE)


def sources_hash(cdir: Path) -> str:
    """SHA-256 over the names and bytes of every file in ``cdir`` (the C of one generated
    directory); built into the module, compared with the folder before it is loaded."""
    h = hashlib.sha256()
    for p in sorted(Path(cdir).iterdir()):
        if p.is_file() and p.suffix in (".c", ".h"):
            h.update(p.name.encode() + b"\0" + p.read_bytes() + b"\0")
    return h.hexdigest()


def embedded_hash(data: bytes | Path) -> str | None:
    """The sources hash built into a module (its bytes or its file), read without loading
    it; ``None`` when there is none."""
    if isinstance(data, Path):
        try:
            data = data.read_bytes()
        except OSError:
            return None
    i = data.find(_TAG)
    if i < 0:
        return None
    value = data[i + len(_TAG):i + len(_TAG) + 64]
    return value.decode("ascii", "replace") if len(value) == 64 else None


def object_count(cdir: Path, cfg: Config) -> int:
    """How many objects :func:`build` compiles (or takes from the object cache)."""
    plan, _ = _paths.partial_plan(cfg.paths, kernel_sources(cdir), TABLE_SOURCE)
    return sum(len(v) for v in plan.values()) + 1


def estimate_seconds(cdir: Path, cfg: Config) -> float:
    """A rough wall time of :func:`build` (for the notice before it starts): the measured
    CPU time per object over the parallel compiles, slowed by the machine's other work
    (the 1-minute load average)."""
    n = object_count(cdir, cfg)
    par = min(jobs(), n)
    cores = os.cpu_count() or 1
    try:
        busy = os.getloadavg()[0]
    except (AttributeError, OSError):   # not Unix
        busy = 0.0
    share = min(1.0, cores / max(cores, busy + par))
    return n * SECONDS_PER_OBJECT / (par * share)


#: ``progress(done, total, running)``: ``done`` of ``total`` steps (every object, then the
#: link) finished, and what runs now, ``(name, seconds running)`` pairs, oldest first. Called
#: by :func:`build` when a step finishes and every :data:`TICK` seconds while none does.
Progress = Callable[[int, int, tuple[tuple[str, float], ...]], None]
#: the longest :func:`text_progress` stays silent between two lines, in seconds (a reader
#: takes a longer silence for a hang)
SILENCE = 2.5
#: how often :func:`build` calls its progress callback while no step finishes, in seconds
TICK = 0.25


def text_progress(t0: float, stream=None) -> Progress:
    """A :data:`Progress` printing a line at each tenth of the build and, between tenths,
    whenever :data:`SILENCE` seconds passed without one; a line after a silence names what
    runs (the compiles, or the link) and for how long. ``t0`` is the build's start
    (``time.perf_counter()``); lines go to ``stream`` (default ``sys.stdout``, read at each
    line). ``setup.py`` prints the build's lines with it (pip shows them with ``-v``), and
    so does a run-time build off a terminal."""
    import time

    shown = [0, t0]

    def progress(done: int, total: int, running: tuple[tuple[str, float], ...] = ()) -> None:
        tenth, now = 10 * done // max(total, 1), time.perf_counter()
        if not (tenth > shown[0] or now - shown[1] >= SILENCE or done == total):
            return
        quiet = tenth == shown[0] and done < total
        shown[:] = [tenth, now]
        line = (f"rigidsym: {min(done, total - 1)}/{total - 1} objects"
                f"{' and the link' if done == total else ''} "
                f"({100 * done // max(total, 1)} %), {now - t0:.0f} s")
        if quiet and running:
            line += "; running: " + running_text(running)
        print(line, file=stream or sys.stdout, flush=True)
    return progress


def running_text(running: tuple[tuple[str, float], ...], most: int = 3) -> str:
    """What runs, in words: ``"rigidsym_module.c (x86-64-v2) 7 s, ... and 2 more"``."""
    shown = ", ".join(f"{name} {sec:.0f} s" for name, sec in running[:most])
    return shown + (f" and {len(running) - most} more" if len(running) > most else "")


def _tasks(cdir: Path, cfg: Config, tmp: Path) -> list[tuple[list[str], Path]]:
    """``(argv, object)`` of every compile, largest sources first (balances the workers); the
    source is the word after ``-c``."""
    import sysconfig

    inc = ["-I", str(cdir)]
    tasks = []
    plan, _ = _paths.partial_plan(cfg.paths, kernel_sources(cdir), TABLE_SOURCE)
    pch = _precompiles(cfg) and (cdir / COMMON_HEADER).is_file()
    for path in cfg.paths:
        (tmp / path.suffix).mkdir(parents=True, exist_ok=True)
        pre = ["-include", str(tmp / "pch" / path.suffix / COMMON_HEADER)] \
            if pch and len(plan[path.suffix]) >= PCH_MIN_OBJECTS else []
        for src in plan[path.suffix]:
            obj = tmp / path.suffix / (src.stem + ".o")
            tasks.append(([*cfg.cc, *cfg.object_flags(path), *inc, *pre, "-c", str(src), "-o",
                           str(obj)], src.stat().st_size))
    base = cfg.paths[-1]
    mod = [*cfg.cc, *COMMON_FLAGS, "-O2", *base.flags, *(OMP_FLAGS if cfg.openmp else ()),
           *(f"-DRIGIDSYM_PATH_{p.suffix}" for p in cfg.paths),
           f"-DRIGIDSYM_SOURCES={json.dumps(sources_hash(cdir))}",
           f"-DRIGIDSYM_BUILD={json.dumps(cfg.describe())}",
           *inc, "-I", sysconfig.get_paths()["include"], "-I", _numpy_include(),
           "-c", str(cdir / MODULE_SOURCE),
           "-o", str(tmp / "module.o")]
    tasks.append((mod, 1 << 30))      # first: its errors (Python headers) show early
    tasks.sort(key=lambda t: -t[1])
    return [(argv, Path(argv[argv.index("-o") + 1])) for argv, _ in tasks]


def _numpy_include() -> str:
    """NumPy's C headers: the module's entry points (rigidsym_fast.h) allocate and read
    ndarrays through NumPy's C API (NumPy is a build requirement, pyproject.toml)."""
    import numpy

    return numpy.get_include()


def _precompiles(cfg: Config) -> bool:
    """Whether the kernels' common header is precompiled: GCC (whose ``-include`` of a header
    reads its ``.gch`` beside it), unless ``RIGIDSYM_PCH=0``."""
    if os.environ.get("RIGIDSYM_PCH", "1") == "0":
        return False
    said = _objects.compiler_id(tuple(cfg.cc))
    return "Free Software Foundation" in said and "clang" not in said


def _precompile(argv: list[str], cdir: Path) -> None:
    """Make the precompiled header that the kernel compile ``argv`` includes (``-include
    DIR/rigidsym_common.h``), with the compile's own flags: the header copied into DIR and
    compiled beside it (``.gch``). A failure leaves the copy alone, which GCC reads as text."""
    import shutil

    at = Path(argv[argv.index("-include") + 1])
    at.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(cdir / COMMON_HEADER, at)
    flags = argv[len(_objects.cc_words(argv)):argv.index("-include")]
    try:
        _run([*_objects.cc_words(argv), *flags, "-x", "c-header", str(at), "-o",
              str(at) + ".gch"])
    except BuildError:
        Path(str(at) + ".gch").unlink(missing_ok=True)


def _run(argv: list[str]) -> None:
    import subprocess

    r = subprocess.run(argv, capture_output=True, text=True)
    if r.returncode != 0:
        tail = "\n".join((r.stderr or r.stdout).strip().splitlines()[-20:])
        raise BuildError(f"{shlex.join(argv)}\nfailed with exit code {r.returncode}:\n{tail}")


class _Running:
    """The steps running now in :func:`build`'s pool, and since when (thread-safe)."""

    def __init__(self) -> None:
        import threading

        self._lock, self._since = threading.Lock(), {}

    @contextmanager
    def step(self, name: str) -> Iterator[None]:
        import time

        with self._lock:
            self._since[name] = time.perf_counter()
        try:
            yield
        finally:
            with self._lock:
                self._since.pop(name, None)

    def now(self) -> tuple[tuple[str, float], ...]:
        """``(name, seconds running)`` of each running step, the oldest first."""
        import time

        t = time.perf_counter()
        with self._lock:
            since = sorted(self._since.items(), key=lambda kv: kv[1])
        return tuple((name, t - t0) for name, t0 in since)


def _watched(futures: list, done: int, total: int, progress: Progress | None,
             running: _Running) -> list:
    """The results of ``futures`` (steps ``done + 1`` ... of ``total``), calling
    ``progress`` as each finishes and every :data:`TICK` seconds while none does; the
    first failure cancels the steps not started and is raised."""
    from concurrent.futures import FIRST_COMPLETED, wait

    pending, results = set(futures), []
    try:
        while pending:
            finished, pending = wait(pending, timeout=TICK, return_when=FIRST_COMPLETED)
            for f in finished:
                results.append(f.result())
            done += len(finished)
            if progress is not None:
                progress(done, total, running.now())
    except BaseException:
        for f in futures:       # the first failure: do not start the rest
            f.cancel()
        raise
    return results


def build(gdir: Path, out: Path, cfg: Config, tmp: Path,
          progress: Progress | None = None, stats: dict | None = None) -> Path:
    """Compile ``gdir/c`` into the module file ``out`` (objects in ``tmp``, each reused from
    the object cache :mod:`rigidsym.kernels.cbuild.objects` when it holds it); returns ``out``.
    ``stats``, when given, receives ``objects``, ``compiled``, ``reused``, ``seconds``
    (wall) and ``cpu_seconds`` (the compiler processes' user + system time). ``progress``
    (:data:`Progress`, e.g. :func:`text_progress`) is called from the pool's watch: as each
    compile or the link finishes, and every :data:`TICK` seconds while none does, with what
    runs.

    Raises:
        BuildError: a compile or the link failed (the compiler's last lines in the message).
    """
    import resource
    import threading
    import time
    from concurrent.futures import ThreadPoolExecutor

    import numpy

    cdir = Path(gdir) / "c"
    if not (cdir / MODULE_SOURCE).is_file():
        raise BuildError(f"{cdir}: no {MODULE_SOURCE}; regenerate this folder with this "
                         f"version of rigidsym (`rigidsym generate`)")
    t0, r0 = time.perf_counter(), resource.getrusage(resource.RUSAGE_CHILDREN)
    tasks = _tasks(cdir, cfg, Path(tmp))
    where = _objects.root()
    neutral = {str(cdir): "<generated>", _numpy_include(): f"<numpy {numpy.__version__}>",
               str(Path(tmp) / "pch"): "<precompiled>"}
    total = len(tasks) + 1
    names = {suffix: name for suffix, name in ((p.suffix, p.name) for p in cfg.paths)}
    running, made = _Running(), {}

    def run(argv: list[str]) -> None:    # a compile the cache lacks: its header first
        if "-include" in argv:
            at = argv[argv.index("-include") + 1]
            with made.setdefault(at, threading.Lock()):   # setdefault: atomic under the GIL
                if not Path(at).is_file():
                    with running.step(f"{COMMON_HEADER} ({names[Path(at).parent.name]})"):
                        _precompile(argv, cdir)
        _run(argv)

    def compile_one(argv: list[str]) -> bool:
        src, obj = Path(argv[argv.index("-c") + 1]), Path(argv[argv.index("-o") + 1])
        where_ = f" ({names[obj.parent.name]})" if obj.parent.name in names else ""
        with running.step(src.name + where_):
            return _objects.compile_cached(run, argv, where,
                                           _objects.headers_digest(cdir, src), neutral)

    with ThreadPoolExecutor(max_workers=min(jobs(), len(tasks))) as pool:
        futures = [pool.submit(compile_one, argv) for argv, _ in tasks]
        compiled = sum(_watched(futures, 0, total, progress, running))
    link = [*cfg.cc, "-shared", *(("-bundle", "-undefined", "dynamic_lookup")
                                  if sys.platform == "darwin" else ()),
            *(str(o) for _, o in tasks), *cfg.libraries(),
            *_paths.partial_plan(cfg.paths, kernel_sources(cdir), TABLE_SOURCE)[1],
            *(OMP_FLAGS if cfg.openmp else ()), "-o", str(out)]
    Path(out).parent.mkdir(parents=True, exist_ok=True)

    def link_it() -> bool:
        with running.step("the link"):
            _run(link)
        return False

    with ThreadPoolExecutor(max_workers=1) as pool:
        _watched([pool.submit(link_it)], len(tasks), total, progress, running)
    if stats is not None:
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime
        stats.update(objects=len(tasks), compiled=compiled, reused=len(tasks) - compiled,
                     seconds=round(time.perf_counter() - t0, 2), cpu_seconds=round(cpu, 2),
                     object_cache=str(where) if where else None)
    return Path(out)
