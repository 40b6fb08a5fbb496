"""rigidsym's generated C kernels as an extra column of ../shared/peers-bench (``--extra``).

    python run_all.py --extra /path/to/rigidsym/benchmarks/peers_adapter.py \
                      --extra /path/to/rigidsym/benchmarks/peers_adapter_native.py

``setup(ctx)`` builds ``generated/c`` into the extension module the package ships (``pip
install .``: x86-64-v2 and x86-64-v3 objects, the module's dispatcher picks one at import),
with :mod:`rigidsym.kernels.cbuild.driver` (the same driver, flags, OpenMP and libmvec probes),
into ``ctx["build_dir"]``, cached by the sources' hash: the default build is what a user of
the wheel runs. ``peers_adapter_native.py`` is the second column: the ``-march=native``
build (``rigidsym build-c --native``). The harness's ``cflags`` are not used: the point is
the build users get.

Each K is one call of the public kernel, ``rigidsym.kernels.<name>(*inputs, check=False)``,
as a user calls it: the compiled entry of the package's own module (built by ``pip install``
from the same ``generated/c``), outputs allocated by the library inside every call; with
``RIGIDSYM_OUTPUT_POOL=1`` in the environment they come from its output pool
(``rigidsym.kernels.set_output_pool``). rigidsym is imported from the harness's environment,
else from this checkout's ``.venv``; where neither imports, for the native column, and for
K4 and K6 (no public kernel of that name), each K is one call of the built module's
``batch`` (no validation, the equivalent of ``check=False``) on ``np.empty`` outputs, as
before, or on the output pool's arrays when it is on. ``VARIANT`` says which.

K1 rotation_from_euler_rodrigues, K2 rotation_from_natural_invariants, K3 screw_axis_point,
K4 instant_screw_point_pitch (ISA point and pitch), K5 N_matrix, K6 newton_euler_residual
(``newton_euler_wrench(...) - [n; f]``: the harness's K6 is the residual).
"""

from __future__ import annotations

import importlib.util
import json
import os
import site
import sys
import sysconfig
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
NAME = "rigidsym-c"
PER_SAMPLE_LOOP = False
NATIVE = False
GEN = ROOT / "generated"
BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_residual"}
_META = {k["name"]: k for k in json.loads((GEN / "kernels.json").read_text())["kernels"]}
OPS = {kid: _META[name]["ops"] for kid, name in BENCH.items() if name in _META}
KERNELS: dict = {}
VARIANT = ""


def _driver():
    """rigidsym.kernels.cbuild.driver, loaded by path (standard library only: the harness's
    environment need not have rigidsym's dependencies)."""
    path = ROOT / "src" / "rigidsym" / "kernels" / "cbuild" / "driver.py"
    spec = importlib.util.spec_from_file_location("_rigidsym_build", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def _build(build_dir: Path, native: bool):
    """Build (cached by sources, paths and flags) and import the module; returns it."""
    global VARIANT
    drv = _driver()
    cfg = drv.configure(native=native)
    key = drv.sources_hash(GEN / "c")[:12] + "-" + "+".join(p.suffix for p in cfg.paths)
    so = Path(build_dir) / key / ("_ckernels" + sysconfig.get_config_var("EXT_SUFFIX"))
    if not so.exists():
        so.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryDirectory(dir=so.parent) as tmp:
            drv.build(GEN, Path(tmp) / so.name, cfg, Path(tmp))
            (Path(tmp) / so.name).replace(so)
    spec = importlib.util.spec_from_file_location(f"_peers_{key.replace('+', '_')}._ckernels",
                                                  so)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    VARIANT = f"{mod.path}, libmvec {bool(mod.libmvec)}"
    return mod


def _wrap(mod, name: str, take=None):
    """``name``'s call through the built module's ``batch``; ``take(shapes, dtype)``: where
    the outputs come from (the library's output pool when it is on), else ``np.empty``."""
    meta = _META[name]
    k = mod.kernels.index(name)
    batch = mod.batch
    shapes = [tuple(o["shape"]) for o in meta["outputs"]]
    f64 = np.dtype(np.float64)

    def call(*xs):
        n = xs[0].shape[0]
        outs = take and take([(n,) + s for s in shapes], f64)
        outs = outs or [np.empty((n,) + s) for s in shapes]
        batch(k, False, n, 1, *xs, *outs)
        return outs[0] if len(outs) == 1 else tuple(outs)
    call.__name__ = name
    return call


def _package_module():
    """The compiled module of the imported package (``RIGIDSYM_PEERS_MODULE=package``)."""
    global VARIANT
    from rigidsym.kernels.cbuild.driver import MODULE
    mod = importlib.import_module(f"rigidsym.kernels.{MODULE}")
    VARIANT += "; K4/K6 through the package's own module"
    return mod


def _public():
    """rigidsym.kernels, from the harness's environment or this checkout's ``.venv`` (its
    site-packages appended: the harness's own NumPy stays first); None if neither imports."""
    try:
        import rigidsym.kernels as rk
        return rk
    except ImportError:
        pass
    venv = ROOT / ".venv" / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}"
    if not (venv / "site-packages").is_dir():
        return None
    site.addsitedir(str(venv / "site-packages"))
    try:
        import rigidsym.kernels as rk
        return rk
    except ImportError:
        return None


def _call(f):
    def call(*xs):
        return f(*xs, check=False)
    call.__name__ = f.__name__
    return call


def setup(ctx=None) -> None:
    """Bind K1..K6 (the public kernels, else the module built here, cached); ``ctx`` as
    passed by the peers-bench harness."""
    global VARIANT
    ctx = ctx or {}
    rk = None if NATIVE else _public()
    build_dir = Path(ctx.get("build_dir") or (ROOT / "benchmarks" / ".build"))
    mod = None
    if rk is not None:
        info = rk.build_info()
        pool = rk.set_output_pool()
        VARIANT = (f"public API, check=False, {info.get('path', '?')}, output pool "
                   + (f"on ({pool['max_bytes'] >> 20} MiB)" if pool["enabled"] else "off")
                   + f" (RIGIDSYM_OUTPUT_POOL={os.environ.get('RIGIDSYM_OUTPUT_POOL', '')!r});"
                   " the batch of the module built here for a K with no public kernel"
                   " (its outputs from the same pool when on)")
        print(f"  rigidsym-c: {VARIANT}", file=sys.stderr)
    for kid, name in BENCH.items():
        if name not in _META:
            continue
        if rk is not None and name in rk.KERNEL_NAMES:
            KERNELS[kid] = _call(getattr(rk, name))
            continue
        mod = mod or (_package_module() if rk is not None and not NATIVE
                      and os.environ.get("RIGIDSYM_PEERS_MODULE") == "package"
                      else _build(build_dir, NATIVE))
        take = None
        if rk is not None and rk.set_output_pool()["enabled"]:
            from rigidsym.kernels.runtime.outpool import take
        KERNELS[kid] = _wrap(mod, name, take)
