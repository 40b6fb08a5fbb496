"""``rigidsym generate --module M --out DIR``: a user module's kernels, same generator.

A user module lists :class:`~rigidsym.codegen.spec.Kernel` specs in ``KERNELS``; their
``sources`` may be the formula callables themselves (named here as ``<module>.<function>``
in the headers and ``kernels.json``). The output folder has the layout of ``generated/``
(``numpy/``, ``c/``, ``kernels.json``) and is loaded by ``rigidsym.kernels.load(DIR)``.
"""

from __future__ import annotations

import dataclasses
import sys
import time
from pathlib import Path

from rigidsym.codegen.spec import Kernel
from rigidsym.registry.declarations import BadInput

__all__ = ["user_kernels", "load_user_kernels", "generate_user", "cmd_generate_user"]


def _source_name(src, title: str) -> str:
    if isinstance(src, str):
        return src
    qual = getattr(src, "__qualname__", None)
    if qual is None or not callable(src):
        raise BadInput(f"module {title}: a kernel source must be a formula function or its "
                       f"dotted name, got {type(src).__name__}")
    return f"{title}.{qual}"


def user_kernels(um) -> list[Kernel]:
    """The kernels of a loaded user module, sources named (callables -> dotted names).

    Raises:
        BadInput: for a ``KERNELS`` entry that is not a :class:`Kernel`, a source that is
            neither a string nor a function, or a kernel name that is not an identifier.
    """
    out = []
    for k in um.kernels:
        if not isinstance(k, Kernel):  # checked here: the checking layer knows no codegen
            raise BadInput(f"module {um.title}: KERNELS holds a {type(k).__name__}, expected "
                           f"rigidsym.codegen.spec.Kernel")
        if not k.name.isidentifier():
            raise BadInput(f"module {um.title}: kernel name {k.name!r} is not an identifier")
        srcs = tuple(_source_name(s, um.title) for s in k.sources)
        out.append(dataclasses.replace(k, sources=srcs))
    return out


def load_user_kernels(modules) -> tuple[list[Kernel], str]:
    """The kernels of user modules (paths or dotted names), sources named, and the modules'
    titles joined (the generated files' origin).

    Raises:
        BadInput: for a module that cannot be loaded, one without ``KERNELS``, or two
            kernels of one name.
    """
    from rigidsym.registry.usermodules import load_many

    ums = load_many(modules)
    kernels, titles = [], []
    from rigidsym.codegen.validate import validate_all

    for um in ums:
        ks = validate_all(user_kernels(um), um.title)
        if not ks:
            raise BadInput(f"module {um.title}: declares no KERNELS (a list of "
                           f"rigidsym.codegen.spec.Kernel)")
        kernels += ks
        titles.append(um.title)
    names = [k.name for k in kernels]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise BadInput(f"kernel {dup[0]} is declared twice in {', '.join(titles)}")
    return kernels, ", ".join(titles)


def generate_user(modules):
    """Generate the kernels of user modules (paths or dotted names) in memory.

    Returns:
        The generator's result (relative path -> text), headers naming the modules.

    Raises:
        BadInput: for a module that cannot be loaded, one without ``KERNELS``, or two
            kernels of one name.
    """
    from rigidsym.codegen.generator import generate

    kernels, origin = load_user_kernels(modules)
    return generate(kernels, origin=origin)


def cmd_generate_user(args) -> int:
    """``rigidsym generate --module M --out DIR [--check]``."""
    from rigidsym.codegen.files import check_or_write

    t0 = time.perf_counter()
    if not args.out:
        raise BadInput("--out: a folder is required with --module")
    out = Path(args.out)
    if args.check and not (out / "kernels.json").is_file():
        raise BadInput(f"--out: {out} holds no generated kernels to compare with")
    if not args.check and out.exists() and any(out.iterdir()) and \
            not (out / "kernels.json").is_file():
        # write() removes files it does not own: never in a folder of someone else's files
        raise BadInput(f"--out: {out} is not empty and holds no generated kernels; give a new "
                       f"or empty folder")
    from rigidsym.codegen.validate import one_line_warnings

    with one_line_warnings():
        res = generate_user(args.module)
    rc = check_or_write(res, out, check_only=args.check, kernels=len(res.kernels),
                        rerun=f"rigidsym generate --module ... --out {out}", t0=t0)
    if rc is not None:
        return rc
    if getattr(args, "no_build", False):
        return 0
    return _compile(out)


def _compile(out: Path) -> int:
    """Compile the C of ``out`` into the cache now, so that ``kernels.load(out)`` in another
    process only loads it; without a compiler, say so (the kernels then run on NumPy)."""
    from rigidsym.kernels.cbuild import driver as _build
    from rigidsym.kernels.cbuild import extension as _ext

    try:
        path = _ext.ensure(out, why="rigidsym generate")
    except _build.CompilerNotFound as exc:
        print(f"note: not compiled: {exc}; kernels.load({str(out)!r}) runs them on NumPy "
              f"(install a C compiler and run `rigidsym build-c {out}` for C)", file=sys.stderr)
        return 0
    except _build.BuildError as exc:
        print(f"error: compiling {out} failed: {exc}", file=sys.stderr)
        return 1
    print(f"compiled {path}")
    return 0
