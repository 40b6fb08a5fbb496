"""The PyTorch target: each kernel's programs as a PyTorch module (``torch/<kernel>.py``),
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
from rigidsym.codegen.backends.torch.printer import torch_printer

__all__ = ["TARGET", "render", "render_kernel"]


def render_kernel(ctx: RenderContext, kc) -> dict[str, str]:
    """``{"torch/<kernel>.py": text}``: the compiled kernel ``kc``'s module."""
    return array_kernel_files(ctx, kc, "torch", "torch", torch_printer)


def render(ctx: RenderContext) -> dict[str, str]:
    """The PyTorch target's files of a generation (``{relative path: text}``)."""
    return render_array_target(ctx, TARGET)


TARGET = Target("torch", TEMPLATES, torch_printer, render, render_kernel=render_kernel)
