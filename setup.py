"""Build the package's C kernels into the extension module ``rigidsym.kernels._ckernels``.

Everything else is in pyproject.toml. The compiling is :mod:`rigidsym.kernels._build`'s (the
same driver and flags as a run-time build), loaded by path: rigidsym is not importable while
it is being built. Its objects are compiled in parallel, one per source and build path (the
x86-64-v2 baseline and x86-64-v3 on x86-64, chosen at import by the module's dispatcher).
"""

import importlib.util
import sys
import tempfile
import time
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
GENERATED = HERE / "generated"


def _driver():
    spec = importlib.util.spec_from_file_location(
        "_rigidsym_build", HERE / "src" / "rigidsym" / "kernels" / "_build.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod          # dataclasses look their module up by name
    spec.loader.exec_module(mod)
    return mod


class BuildKernels(build_ext):
    """build_ext for the kernels: the driver compiles and links; setuptools only places the
    module (in the wheel, or beside the sources for an editable install)."""

    def build_extension(self, ext):
        drv = _driver()
        cfg = drv.configure()
        out = Path(self.get_ext_fullpath(ext.name))
        n = len(drv.kernel_sources(GENERATED / "c")) * len(cfg.paths) + 1
        print(f"rigidsym: compiling {n} objects ({', '.join(p.name for p in cfg.paths)}; "
              f"OpenMP {cfg.openmp}, libmvec {cfg.libmvec}) on {drv.jobs()} cores, about "
              f"{drv.estimate_seconds(GENERATED / 'c', cfg):.0f} s", flush=True)
        t0 = time.perf_counter()
        Path(self.build_temp).mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryDirectory(dir=self.build_temp) as tmp:
            drv.build(GENERATED, out, cfg, Path(tmp))
        print(f"rigidsym: built {out.name} in {time.perf_counter() - t0:.1f} s", flush=True)


setup(
    ext_modules=[Extension("rigidsym.kernels._ckernels",
                           sources=sorted(str(p.relative_to(HERE))
                                          for p in (GENERATED / "c").glob("*.c")),
                           depends=sorted(str(p.relative_to(HERE))
                                          for p in (GENERATED / "c").glob("*.h")))],
    cmdclass={"build_ext": BuildKernels},
)
