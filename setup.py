"""Build the package's C kernels into the extension module ``rigidsym.kernels._ckernels``.

Everything else is in pyproject.toml. The compiling is :mod:`rigidsym.kernels.cbuild.driver`'s (the
same driver and flags as a run-time build), loaded by path: rigidsym is not importable while
it is being built. Its objects are compiled in parallel, one per source and build path (the
x86-64-v2 baseline and x86-64-v3 on x86-64, chosen at import by the module's dispatcher).
"""

import dataclasses
import importlib.util
import json
import sys
import tempfile
import time
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
GENERATED = HERE / "generated"
#: the build's record beside the module (kernels.build_info()["build"])
STATS = "_ckernels.build.json"


def _driver():
    spec = importlib.util.spec_from_file_location(
        "_rigidsym_build", HERE / "src" / "rigidsym" / "kernels" / "cbuild" / "driver.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod          # dataclasses look their module up by name
    spec.loader.exec_module(mod)
    return mod


class BuildKernels(build_ext):
    """build_ext for the kernels: the driver compiles and links; setuptools only places the
    module (in the wheel, or beside the sources for an editable install)."""

    def _stats_pairs(self):
        """(built, in-place) paths of the build record (``_ckernels.build.json``)."""
        build_py = self.get_finalized_command("build_py")
        for ext in self.extensions:
            inplace, regular = self._get_inplace_equivalent(build_py, ext)
            yield (str(Path(regular).with_name(STATS)), str(Path(inplace).with_name(STATS)))

    def get_outputs(self):
        outs = super().get_outputs()
        return outs + [str(Path(o).with_name(STATS)) for o in outs if "_ckernels" in o]

    def copy_extensions_to_source(self):
        # an editable install: the record goes beside the module in the source tree too
        super().copy_extensions_to_source()
        for regular, inplace in self._stats_pairs():
            if Path(regular).exists():
                self.copy_file(regular, inplace, level=self.verbose)

    def _get_output_mapping(self):
        yield from super()._get_output_mapping()
        if self.inplace:
            yield from self._stats_pairs()

    def build_extension(self, ext):
        drv = _driver()
        cfg = drv.configure()
        if self.editable_mode or self.inplace:
            # an editable install runs on this machine only: the best path its CPU runs,
            # every kernel compiled there (172 objects instead of 276 on an AVX-512 host,
            # the same values bit for bit: benchmarks/results/editable_paths.json); the
            # wheel keeps every path
            cfg = dataclasses.replace(cfg, paths=drv._paths.host_paths(cfg.paths))
        out = Path(self.get_ext_fullpath(ext.name))
        n = drv.object_count(GENERATED / "c", cfg)
        print(f"rigidsym: compiling {n} objects ({', '.join(p.name for p in cfg.paths)}; "
              f"OpenMP {cfg.openmp}, libmvec {cfg.libmvec}) on {drv.jobs()} cores, about "
              f"{drv.estimate_seconds(GENERATED / 'c', cfg):.0f} s", flush=True)
        # a line at each tenth of the objects and whenever 2.5 s passed without one, naming
        # what runs (pip shows them with -v; without it pip is silent for the whole compile)
        t0 = time.perf_counter()
        Path(self.build_temp).mkdir(parents=True, exist_ok=True)
        stats: dict = {}
        with tempfile.TemporaryDirectory(dir=self.build_temp) as tmp:
            drv.build(GENERATED, out, cfg, Path(tmp), stats=stats, progress=drv.text_progress(t0))
        # what was built, in what time: kernels.build_info()["build"] reads it back
        stats.update(paths=[p.name for p in cfg.paths],
                     built=time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()))
        out.with_name(STATS).write_text(json.dumps(stats, indent=1) + "\n")
        print(f"rigidsym: built {out.name} in {time.perf_counter() - t0:.1f} s "
              f"({stats['compiled']} objects compiled, {stats['reused']} from the object cache "
              f"{stats['object_cache']})", flush=True)


setup(
    ext_modules=[Extension("rigidsym.kernels._ckernels",
                           sources=sorted(str(p.relative_to(HERE))
                                          for p in (GENERATED / "c").glob("*.c")),
                           depends=sorted(str(p.relative_to(HERE))
                                          for p in (GENERATED / "c").glob("*.h")))],
    cmdclass={"build_ext": BuildKernels},
)
