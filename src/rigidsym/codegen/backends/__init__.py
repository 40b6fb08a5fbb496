"""The code generator's targets, one folder each (as SymForce's ``codegen/backends/<lang>/``):
its printer, its templates and a ``target.py`` describing it as one :class:`Target`.

* ``numpy/``: the Python package's NumPy kernels (``generated/numpy/``), its ``__init__.py``
  and ``api.py`` (the real signatures of the public kernels);
* ``extension/``: the C of the package's extension module (``generated/c/``);
* ``torch/`` and ``jax/``: the PyTorch and JAX programs (``generated/torch/``, ``jax/``),
  rendered by what they share in ``arrays/`` (a module and the template, no target);
* ``c/``: the C-only target (``rigidsym generate --target c``: C99 for C and C++ projects,
  firmware included, with no Python at build or run time), not part of the package;
* ``cpp/``: the header-only C++ layer over the C target (``rigidsym generate --target
  cpp``: Eigen and ``std::array`` functions in a namespace), not part of the package.

:mod:`.printing` holds what every printer shares. A target registers itself when its package
is imported (this module imports the six built-in ones, in that order);
:func:`rigidsym.codegen.generator.generate` renders every registered package target and
merges their files. README.md beside this file says how to add one.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import jinja2

__all__ = ["Target", "RenderContext", "register", "unregister", "targets", "environment",
           "kernel_files", "shared_environment"]


@dataclass(frozen=True)
class RenderContext:
    """What a target renders from: one generation's compiled kernels and their metadata.

    Attributes:
        kernels: the compiled kernels (:class:`rigidsym.codegen.generator.KernelCode`), the
            Jacobian twins among them, sorted by name.
        metas: their ``kernels.json`` entries, in the same order (with the measured accuracy
            for the book's kernels).
        versions: ``{"sympy": version, "rigidsym": version}``.
        origin: where the kernels are declared (a module's name), for the headers.
        header: ``header(kc, template) -> [lines]``: the provenance header of one kernel's
            file rendered from ``template`` (a file name).
        meta: ``meta(kc) -> dict``: one kernel's ``kernels.json`` entry, without accuracy.
        memo: a cache the targets of one generation share (work two targets would repeat).
        options: a target's own options (the C target's ``single_header`` and ``bounds``).
    """

    kernels: list
    metas: list[dict]
    versions: dict[str, str]
    origin: str
    header: Callable[[Any, str], list[str]]
    meta: Callable[[Any], dict]
    memo: dict = field(default_factory=dict)
    options: dict = field(default_factory=dict)


@dataclass(frozen=True)
class Target:
    """One code-generation target.

    Attributes:
        name: its name (and its folder's).
        template_dir: the folder of its Jinja2 templates (file names are unique across the
            package targets: a generated file names its template by file name alone).
        printer: a new printer of kernel programs in the target's language.
        render: ``render(ctx) -> {relative path: text}``: its files of a generation.
        package: whether :func:`rigidsym.codegen.generator.generate` renders it into the
            Python package (``generated/``); the C-only target writes a folder of its own.
        render_kernel: ``render_kernel(ctx, kc) -> {relative path: text}``: the files of one
            compiled kernel alone (``None``: the target has none apart). With it the
            generator renders each kernel's files in the worker that compiled it, in
            parallel, and ``render`` takes them through :func:`kernel_files`.
    """

    name: str
    template_dir: Path
    printer: Callable[[], Any]
    render: Callable[[RenderContext], dict[str, str]]
    package: bool = True
    render_kernel: Callable[[RenderContext, Any], dict[str, str]] | None = None


_TARGETS: dict[str, Target] = {}


def register(target: Target) -> Target:
    """Add ``target`` after the registered ones; returns it.

    Raises:
        ValueError: a target of that name is registered already.
    """
    if target.name in _TARGETS:
        raise ValueError(f"a code-generation target {target.name!r} is registered already")
    _TARGETS[target.name] = target
    return target


def unregister(name: str) -> None:
    """Remove the target ``name``.

    Raises:
        KeyError: no target of that name is registered.
    """
    del _TARGETS[name]


def targets(package: bool | None = None) -> tuple[Target, ...]:
    """The registered targets in registration order (``package``: only those that are, or
    are not, rendered into the Python package; None: all)."""
    return tuple(t for t in _TARGETS.values() if package is None or t.package == package)


def environment(template_dir: Path) -> jinja2.Environment:
    """The Jinja2 environment of a package target's templates (strict: an undefined name is
    an error; no autoescaping: the output is code)."""
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(template_dir)), keep_trailing_newline=True,
        trim_blocks=True, lstrip_blocks=True, undefined=jinja2.StrictUndefined,
        autoescape=False)


def kernel_files(ctx: RenderContext, target: Target, kc: Any) -> dict[str, str]:
    """The files of the compiled kernel ``kc`` for ``target``: those a worker of the
    generator rendered already (``ctx.memo[("kernel files", target name, kernel name)]``),
    else ``target.render_kernel(ctx, kc)`` now. The same text either way: a worker renders
    with the same ``render_kernel``."""
    got = ctx.memo.get(("kernel files", target.name, kc.kernel.name))
    return dict(got) if got is not None else target.render_kernel(ctx, kc)


@cache
def shared_environment(template_dir: Path) -> jinja2.Environment:
    """The :func:`environment` of ``template_dir`` made once per process (its templates
    compiled once for every kernel a package target renders; not to be changed: a target
    that adds filters makes its own with :func:`environment`)."""
    return environment(template_dir)


# the built-in targets, in the order of their registration (each registers itself)
# isort: off
from rigidsym.codegen.backends import numpy as numpy  # noqa: E402
from rigidsym.codegen.backends import extension as extension  # noqa: E402
from rigidsym.codegen.backends import torch as torch  # noqa: E402
from rigidsym.codegen.backends import jax as jax  # noqa: E402
from rigidsym.codegen.backends import c as c  # noqa: E402
from rigidsym.codegen.backends import cpp as cpp  # noqa: E402
# isort: on
