"""The NumPy target: the Python package's NumPy kernels (``numpy/<kernel>.py`` and their
index ``numpy/__init__.py``), and the package's own Python files: ``__init__.py`` and
``api.py`` (:mod:`.api_spec`).
"""

from __future__ import annotations

from pathlib import Path

from rigidsym.codegen.backends import RenderContext, Target, kernel_files, shared_environment
from rigidsym.codegen.backends.numpy.api_spec import render_api
from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter
from rigidsym.codegen.backends.printing import (
    NUMPY_SOURCE,
    program_lines,
    risky_names,
    uses_diffprod,
)

__all__ = ["TARGET", "TEMPLATES", "NUMPY_CHUNK", "render", "render_kernel"]

#: samples per block of the generated NumPy kernels: the temporaries of one block (tens of
#: arrays of 8 bytes a sample) stay in L2, so large batches are not memory-bound; measured in
#: benchmarks/RESULTS.md
NUMPY_CHUNK = 16384

#: the target's templates
TEMPLATES = Path(__file__).parent / "templates"


def render_kernel(ctx: RenderContext, kc) -> dict[str, str]:
    """``{"numpy/<kernel>.py": text}``: the compiled kernel ``kc``'s NumPy module."""
    env = shared_environment(TEMPLATES)
    k = kc.kernel
    npp = KernelNumPyPrinter()
    # kernels without a division (or sqrt, atan2 of possibly zero arguments) give finite
    # outputs for finite inputs: no finiteness check in the generated code
    divides = any(v.program.dens for v in kc.variants)
    t = "numpy_kernel.py.j2"
    return {f"numpy/{k.name}.py": env.get_template(t).render(
        header=ctx.header(kc, t), ops=kc.ops, hash=kc.hash, chunk=NUMPY_CHUNK,
        helpers=NUMPY_SOURCE.strip("\n") if uses_diffprod(kc) else "",
        variants=[{"name": v.name, "cond": None if v.cond is None else npp.doprint(v.cond),
                   "risky": risky_names(v.program, npp), **program_lines(v.program, npp)}
                  for v in kc.variants],
        k=k, meta=ctx.meta(kc), inputs=kc.inputs, divides=divides)}


def render(ctx: RenderContext) -> dict[str, str]:
    """The NumPy target's files of a generation (``{relative path: text}``)."""
    env = shared_environment(TEMPLATES)
    files: dict[str, str] = {}
    for kc in ctx.kernels:
        files.update(kernel_files(ctx, TARGET, kc))
    files["api.py"] = render_api(env, ctx.metas, ctx.versions)
    for t, path in (("package_init.py.j2", "__init__.py"),
                    ("numpy_index.py.j2", "numpy/__init__.py")):
        files[path] = env.get_template(t).render(kernels=ctx.metas, template=t,
                                                 **ctx.versions)
    return files


TARGET = Target("numpy", TEMPLATES, KernelNumPyPrinter, render, render_kernel=render_kernel)
