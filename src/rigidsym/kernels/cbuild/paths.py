"""The build paths of the C driver (:mod:`rigidsym.kernels.cbuild.driver`): which CPU levels the
kernels are compiled for, and which kernels each level compiles.

As in NumPy's dispatcher, every kernel is compiled once per path; the module picks the best
path the CPU runs at import. The x86-64-v4 path compiles only the kernels that call ``sin``
or ``cos``: what it buys is 8-wide AVX-512 sin/cos in their SIMD loops (libmvec's then,
measured 0.83-0.92x the x86-64-v3 time on the trigonometric K3 and K5; the generated
header's own since ``benchmarks/RESULTS.md``), and those 34 of 134 kernels cost
29 % of its compile time for nothing; and the few of :data:`V4_KERNELS`, which
call neither but measured faster there (outputs allocated, N = 1e6:
their range test and lanes loop run 8 doubles wide). The others' x86-64-v4 entries are the
x86-64-v3 functions, aliased at link time (``--defsym``, GNU ld). Standard library only
(``setup.py`` loads it by path).
"""

from __future__ import annotations

import json
import os
import platform
import re
import sys
from dataclasses import dataclass
from pathlib import Path

__all__ = ["IsaPath", "X86_V4", "V4_KERNELS", "X86_PATHS", "NATIVE", "BASELINE", "default_paths",
           "host_paths", "cpu_features", "calls_trig", "partial_plan"]

@dataclass(frozen=True)
class IsaPath:
    """One build path: a suffix for the exported names, the name build_info() reports,
    and its flags."""

    suffix: str
    name: str
    flags: tuple[str, ...]
    #: compiles only the kernels that call sin or cos; the next path serves the others
    trig_only: bool = False


#: the AVX-512 path: measured 0.83-0.92x the x86-64-v3 time on the trigonometric K2, K3,
#: K5 (libmvec's 8-wide _ZGVeN8v_sin/cos), level on K1, K4, K6 (benchmarks/RESULTS.md), and
#: what keeps the default build within 1.10x of -march=native on K3 on an AVX-512 CPU
X86_V4 = IsaPath("v4", "x86-64-v4", ("-march=x86-64-v4",), trig_only=True)
#: kernels without sin/cos that the x86-64-v4 path compiles too, where it measured faster
#: (the peer benchmark's K1, K4, K6 at N = 1e6, outputs allocated: 0.97 -> 0.93,
#: 1.11-1.14 -> 1.03-1.05 and 1.14-1.16 -> 1.07-1.08 of the fastest peer; their range test
#: and lanes loop run 8 doubles wide; benchmarks/RESULTS.md)
V4_KERNELS = frozenset({"rotation_from_euler_rodrigues", "instant_screw_point_pitch",
                        "newton_euler_residual"})
X86_PATHS = (X86_V4, IsaPath("v3", "x86-64-v3", ("-march=x86-64-v3",)),
             IsaPath("v2", "x86-64-v2", ("-march=x86-64-v2",)))
NATIVE = IsaPath("native", "native", ("-march=native",))
BASELINE = IsaPath("base", "baseline", ())



def is_x86() -> bool:
    return platform.machine().lower() in ("x86_64", "amd64")


def default_paths(native: bool = False) -> tuple[IsaPath, ...]:
    """The build paths, best first (the last is the baseline).

    ``native``: ``-march=native`` only. Else ``RIGIDSYM_PATHS`` (suffixes, e.g. ``v3,v2`` for
    a quicker build) if set, else x86-64-v4, x86-64-v3 and x86-64-v2 on x86-64 and one path
    without ``-march`` elsewhere.

    Raises:
        ValueError: ``RIGIDSYM_PATHS`` names an unknown path.
    """
    if native:
        return (NATIVE,)
    if not is_x86():
        return (BASELINE,)
    env = os.environ.get("RIGIDSYM_PATHS")
    if not env:
        return X86_PATHS
    known = {p.suffix: p for p in X86_PATHS}
    wanted = [s.strip() for s in env.split(",") if s.strip()]
    bad = [s for s in wanted if s not in known]
    if bad or not wanted:
        raise ValueError(f"RIGIDSYM_PATHS: expected suffixes among {', '.join(known)}, got "
                         f"{env!r}")
    return tuple(sorted((known[s] for s in set(wanted)), key=lambda p: -int(p.suffix[1])))


#: the CPU flags (``/proc/cpuinfo``, Linux's names) each x86-64 level needs (psABI)
_LEVEL_FLAGS = {
    "v2": {"sse4_2", "ssse3", "popcnt", "cx16"},
    "v3": {"avx", "avx2", "fma", "bmi1", "bmi2", "f16c", "movbe", "abm"},
    "v4": {"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"},
}


def _runs(path: IsaPath, flags: set[str]) -> bool:
    level = int(path.suffix[1])
    return all(_LEVEL_FLAGS[f"v{k}"] <= flags for k in range(2, level + 1))


def host_paths(paths: tuple[IsaPath, ...], cpuinfo: str | None = None) -> tuple[IsaPath, ...]:
    """The path of ``paths`` an editable install needs on this machine: the best one its CPU
    runs, alone (an editable install is this checkout on this machine: the x86-64-v2 objects
    it never runs were 159 of its 419 objects on an AVX-512 host). A ``trig_only`` path alone
    compiles every kernel (:func:`partial_plan`): on an AVX-512 host the x86-64-v4 objects
    of the kernels without sin/cos replace the x86-64-v3 objects a full build aliases them
    to (the same values, bit for bit: ``benchmarks/results/editable_paths.json``), and the
    x86-64-v3 objects of the kernels with sin/cos, which it never runs, are not compiled
    (172 objects instead of 276). ``paths`` unchanged off x86-64 Linux, with
    ``RIGIDSYM_PATHS`` set, or when the CPU's flags cannot be read; the module's dispatcher
    still refuses, naming the path, a CPU that lacks the remaining baseline (a checkout
    shared with an older machine: reinstall there, or set ``RIGIDSYM_PATHS``).

    ``cpuinfo``: the text of ``/proc/cpuinfo`` (tests pass their own)."""
    if os.environ.get("RIGIDSYM_PATHS") or not all(p.suffix in ("v2", "v3", "v4")
                                                  for p in paths):
        return paths
    if cpuinfo is None:
        try:
            cpuinfo = Path("/proc/cpuinfo").read_text(errors="replace")
        except OSError:
            return paths
    line = next((ln for ln in cpuinfo.splitlines() if ln.split(":")[0].strip() == "flags"),
                None)
    if line is None:
        return paths
    flags = set(line.partition(":")[2].split())
    for p in paths:
        if _runs(p, flags):
            return (p,)
    return paths        # the CPU runs none of them: the dispatcher says so at import


def cpu_features() -> str:
    """The CPU's model and feature flags (``/proc/cpuinfo``), for the key of a native build:
    identical machines share it, whatever their host names."""
    try:
        text = Path("/proc/cpuinfo").read_text(errors="replace")
    except OSError:
        return f"{platform.machine()} {platform.processor()}"
    fields = {}
    for line in text.splitlines():
        key, _, value = line.partition(":")
        key = key.strip()
        if key in ("flags", "Features", "model name", "vendor_id", "CPU part") \
                and key not in fields:
            fields[key] = " ".join(sorted(value.split())) if key in ("flags", "Features") \
                else value.strip()
    return json.dumps(fields, sort_keys=True)


#: a call of sin or cos (double or float) in generated C
_TRIG = re.compile(rb"\b(?:sin|cos)f?\s*\(")
#: what a kernel source exports, per path suffix (rigidsym_<stem>..._<suffix>)
_EXPORTS = ("", "_threads", "_f32_threads")


def calls_trig(src: Path) -> bool:
    """Whether the generated C source ``src`` calls ``sin`` or ``cos``."""
    return bool(_TRIG.search(Path(src).read_bytes()))


def partial_plan(paths: tuple[IsaPath, ...], sources: list[Path],
                 table: str) -> tuple[dict[str, list[Path]], list[str]]:
    """The sources each path compiles, by suffix, and the linker's aliases (``--defsym``
    flags) that give a ``trig_only`` path the next path's functions for the others (the
    sources calling sin or cos and those of :data:`V4_KERNELS` are its own). A
    ``trig_only`` path compiles everything when no path follows it or the linker is not GNU
    ld's kind (not Linux)."""
    plan, aliases = {}, []
    for i, path in enumerate(paths):
        plan[path.suffix] = list(sources)
        if not (path.trig_only and i + 1 < len(paths) and sys.platform.startswith("linux")):
            continue
        nxt = paths[i + 1].suffix
        plan[path.suffix] = [s for s in sources
                             if s.name == table or s.stem in V4_KERNELS or calls_trig(s)]
        for s in sources:
            if s not in plan[path.suffix]:
                aliases += [f"-Wl,--defsym,rigidsym_{s.stem}{e}_{path.suffix}="
                            f"rigidsym_{s.stem}{e}_{nxt}" for e in _EXPORTS]
    return plan, aliases
