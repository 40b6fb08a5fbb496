"""Compile the generated C kernels through cffi into a user cache directory.

The shared object is keyed by a hash of the generated sources, the compiler flags, the
Python ABI and the machine, and lives in ``$RIGIDSYM_CACHE`` or the platform's user cache
(``~/.cache/rigidsym``), never in site-packages. Flags: ``-O3 -march=native -std=c99
-ffp-contract=fast`` (FMA contraction, as gcc does by default in GNU C mode; never
``-ffast-math``); ``RIGIDSYM_CFLAGS`` overrides them.

On Linux with glibc the batch loops are first compiled against libmvec (vectorised ``sin`` and
``cos``, within 4 ulp: ``MVEC_FLAGS`` and ``-lmvec``, macro ``RIGIDSYM_LIBMVEC``); if that does
not compile or link, or ``RIGIDSYM_LIBMVEC=0``, the plain build is used.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import platform
import sys
import tempfile
from pathlib import Path

__all__ = ["build", "load", "cache_dir", "generated_dir", "cdef", "build_variants", "CFLAGS",
           "MVEC_FLAGS"]

CFLAGS = ["-O3", "-march=native", "-std=c99", "-ffp-contract=fast"]
#: extra flags of the libmvec build (sin/cos not fused into a scalar sincos call)
MVEC_FLAGS = ["-fopenmp-simd", "-fno-builtin-sin", "-fno-builtin-cos", "-DRIGIDSYM_LIBMVEC"]


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
    for flags, libs in build_variants(base):
        try:
            return _build(gdir, meta, flags, libs, force)
        except Exception as exc:  # noqa: BLE001 - the next variant is the fallback
            last = exc
    raise last


def build_variants(base: list[str]) -> list[tuple[list[str], list[str]]]:
    """Build variants ``(flags, libraries)``, best first: libmvec (glibc only), then plain."""
    out = []
    if sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc" \
            and os.environ.get("RIGIDSYM_LIBMVEC", "1") != "0":
        out.append((base + MVEC_FLAGS, ["mvec", "m"]))
    out.append((base, ["m"]))
    return out


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
    ffi.set_source(name, '#include "rigidsym_kernels.h"', sources=sources,
                   include_dirs=[str(cdir)], extra_compile_args=flags, libraries=libs)
    with tempfile.TemporaryDirectory(dir=out) as tmp:
        so = Path(ffi.compile(tmpdir=tmp, verbose=False))
        final = out / so.name
        os.replace(so, final)
    return final


def load(force: bool = False, gdir: Path | None = None):
    """Build if needed and import the extension of ``gdir`` (default the package's
    generated directory); returns ``(ffi, lib)``."""
    path = build(force=force, gdir=gdir)
    name = path.name.split(".")[0]
    if name in sys.modules:
        mod = sys.modules[name]
    else:
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        sys.modules[name] = mod
    return mod.ffi, mod.lib
