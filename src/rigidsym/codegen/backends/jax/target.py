"""The JAX target: each kernel's programs as a JAX module (``jax/<kernel>.py``),
printed into the template the array targets share
(:mod:`rigidsym.codegen.backends.arrays.programs`).
"""

from __future__ import annotations

from rigidsym.codegen.backends import RenderContext, Target
from rigidsym.codegen.backends.arrays.programs import (
    TEMPLATES,
    array_kernel_files,
    render_array_target,
)
from rigidsym.codegen.backends.jax.printer import KernelJaxPrinter

__all__ = ["TARGET", "render", "render_kernel"]


def render_kernel(ctx: RenderContext, kc) -> dict[str, str]:
    """``{"jax/<kernel>.py": text}``: the compiled kernel ``kc``'s module."""
    return array_kernel_files(ctx, kc, "jax", "jax.numpy", KernelJaxPrinter)


def render(ctx: RenderContext) -> dict[str, str]:
    """The JAX target's files of a generation (``{relative path: text}``)."""
    return render_array_target(ctx, TARGET)


TARGET = Target("jax", TEMPLATES, KernelJaxPrinter, render, render_kernel=render_kernel)
