"""Compile the generated C kernels through cffi into a user cache directory.

The shared object is keyed by a hash of the generated sources, the compiler flags, the
Python ABI and the machine, and lives in ``$RIGIDSYM_CACHE`` or the platform's user cache
(``~/.cache/rigidsym``), never in site-packages. Flags: ``-O3 -march=native -std=c99
-ffp-contract=fast`` (FMA contraction, as gcc does by default in GNU C mode; never
``-ffast-math``); ``RIGIDSYM_CFLAGS`` overrides them.

On Linux with glibc the batch loops are first compiled against libmvec (vectorised ``sin`` and
``cos``, within 4 ulp: ``MVEC_FLAGS`` and ``-lmvec``, macro ``RIGIDSYM_LIBMVEC``); if that does
not compile or link, or ``RIGIDSYM_LIBMVEC=0``, the plain build is used.

Threads: every variant is first tried with OpenMP (``OMP_FLAGS``; the batch loops take their
thread count as an argument, never from ``OMP_NUM_THREADS``); when no OpenMP build works
the kernels run on one thread and :func:`build` warns once. ``RIGIDSYM_OPENMP=0`` skips it.
:func:`load` is safe to call from several threads at once (one lock around build and import).
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import platform
import sys
import tempfile
import threading
import warnings
from pathlib import Path

__all__ = ["build", "load", "cache_dir", "generated_dir", "cdef", "build_variants", "CFLAGS",
           "MVEC_FLAGS", "OMP_FLAGS", "openmp"]

CFLAGS = ["-O3", "-march=native", "-std=c99", "-ffp-contract=fast"]
#: extra flags of the libmvec build (sin/cos not fused into a scalar sincos call)
MVEC_FLAGS = ["-fopenmp-simd", "-fno-builtin-sin", "-fno-builtin-cos", "-DRIGIDSYM_LIBMVEC"]
#: flags of the OpenMP build (compile and link): threads in the batch loops
OMP_FLAGS = ["-fopenmp"]

#: the extension's own C (not generated): whether it was built with OpenMP
_PREAMBLE = """#include "rigidsym_kernels.h"
#ifdef _OPENMP
int rigidsym_openmp(void) { return 1; }
#else
int rigidsym_openmp(void) { return 0; }
#endif
"""
_LOCK = threading.RLock()
_WARNED = {"omp": False}


def generated_dir() -> Path:
    """The folder of generated kernels: inside the installed package, else the checkout's."""
    here = Path(__file__).resolve()
    for cand in (here.parents[1] / "generated", here.parents[3] / "generated"):
        if (cand / "kernels.json").exists():
            return cand
    raise FileNotFoundError("generated kernels not found; run `rigidsym generate`")


def cache_dir() -> Path:
    """User cache folder for compiled kernels."""
    env = os.environ.get("RIGIDSYM_CACHE")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or (Path.home() / ".cache")
    return Path(base) / "rigidsym"


def _flags() -> list[str]:
    env = os.environ.get("RIGIDSYM_CFLAGS")
    flags = env.split() if env else list(CFLAGS)
    if "-ffast-math" in flags:
        raise ValueError("RIGIDSYM_CFLAGS: -ffast-math breaks the kernels' NaN/singular logic")
    return flags


def cdef(meta: dict) -> str:
    """cffi declarations of the batch functions listed in ``kernels.json``."""
    lines = []
    for k in meta["kernels"]:
        params = ["int64_t n"] + [f"const double *{a['name']}" for a in k["args"]] \
            + [f"double *{o['name']}" for o in k["outputs"]]
        lines.append(f"int64_t rigidsym_{k['name']}({', '.join(params)});")
        lines.append(f"int64_t rigidsym_{k['name']}_threads({', '.join(params[:1])}, "
                     f"int threads, {', '.join(params[1:])});")
        p32 = [p.replace("double", "float") for p in params[1:]]
        lines.append(f"int64_t rigidsym_{k['name']}_f32_threads(int64_t n, int threads, "
                     f"{', '.join(p32)});")
    lines.append("int rigidsym_openmp(void);")
    return "\n".join(lines)


def _key(gdir: Path, flags: list[str]) -> str:
    h = hashlib.sha256()
    for p in sorted((gdir / "c").glob("*")):
        h.update(p.name.encode())
        h.update(p.read_bytes())
    h.update(" ".join(flags).encode())
    h.update(f"{sys.implementation.cache_tag}{platform.machine()}{platform.node()}".encode())
    return h.hexdigest()[:16]


def build(force: bool = False, gdir: Path | None = None) -> Path:
    """Compile (if needed) and return the path of the extension module.

    Args:
        force: rebuild even if a build of the same sources is cached.
        gdir: a generated directory (``kernels.json`` + ``c/``); default the package's.

    Raises:
        Exception: whatever the compiler / cffi raises when no C compiler works.
    """
    gdir = generated_dir() if gdir is None else Path(gdir)
    meta = json.loads((gdir / "kernels.json").read_text())
    base = _flags()
    last = None
    with _LOCK:
        for flags, libs in build_variants(base):
            try:
                path = _build(gdir, meta, flags, libs, force)
            except Exception as exc:  # noqa: BLE001 - the next variant is the fallback
                last = exc
                continue
            if "-fopenmp" not in flags and not _WARNED["omp"]:
                _WARNED["omp"] = True
                warnings.warn("rigidsym: the C kernels built without OpenMP "
                              f"({last or 'RIGIDSYM_OPENMP=0'}); they run on one thread",
                              RuntimeWarning, stacklevel=2)
            return path
    raise last


def build_variants(base: list[str]) -> list[tuple[list[str], list[str]]]:
    """Build variants ``(flags, libraries)``, best first: with OpenMP (unless
    ``RIGIDSYM_OPENMP=0``), then without; each with libmvec (glibc only), then plain."""
    plain = []
    if sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc" \
            and os.environ.get("RIGIDSYM_LIBMVEC", "1") != "0":
        plain.append((base + MVEC_FLAGS, ["mvec", "m"]))
    plain.append((base, ["m"]))
    if os.environ.get("RIGIDSYM_OPENMP", "1") == "0":
        return plain
    return [(f + OMP_FLAGS, libs) for f, libs in plain] + plain


def openmp() -> bool:
    """Whether the loaded C kernels were built with OpenMP (builds them if needed)."""
    return bool(load()[1].rigidsym_openmp())


_variants = build_variants


def _build(gdir: Path, meta: dict, flags: list[str], libs: list[str], force: bool) -> Path:
    import cffi

    name = f"_rigidsym_kernels_{_key(gdir, flags + libs)}"
    out = cache_dir() / name
    found = sorted(out.glob(f"{name}*.so")) + sorted(out.glob(f"{name}*.pyd"))
    if found and not force:
        return found[0]
    out.mkdir(parents=True, exist_ok=True)
    ffi = cffi.FFI()
    ffi.cdef(cdef(meta))
    cdir = gdir / "c"
    sources = [str(cdir / f"{k['name']}.c") for k in meta["kernels"]]
    ffi.set_source(name, _PREAMBLE, sources=sources, include_dirs=[str(cdir)],
                   extra_compile_args=flags, libraries=libs,
                   extra_link_args=[f for f in flags if f in OMP_FLAGS])
    with tempfile.TemporaryDirectory(dir=out) as tmp:
        so = Path(ffi.compile(tmpdir=tmp, verbose=False))
        final = out / so.name
        os.replace(so, final)
    return final


def load(force: bool = False, gdir: Path | None = None):
    """Build if needed and import the extension of ``gdir`` (default the package's
    generated directory); returns ``(ffi, lib)``. Thread-safe."""
    with _LOCK:
        path = build(force=force, gdir=gdir)
        name = path.name.split(".")[0]
        if name in sys.modules:
            mod = sys.modules[name]
        else:
            # idle OpenMP threads sleep instead of spinning (read by libgomp when it loads;
            # a user's setting wins): between two kernel calls a spinning worker takes the
            # caller's core, measured 11 ms per 2-thread call on a busy 2-core machine
            # instead of 0.1 ms (benchmarks/scale.py)
            os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
            spec = importlib.util.spec_from_file_location(name, path)
            mod = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(mod)
            sys.modules[name] = mod
    return mod.ffi, mod.lib
