"""``rigidsym generate --target c --out DIR [--module M] [--kernel NAME] [--check]``."""

from __future__ import annotations

import importlib
import time
from pathlib import Path

from rigidsym.core.config import KERNEL_SPEC
from rigidsym.registry.declarations import BadInput

__all__ = ["cmd_generate_c", "select_kernels", "MARKER"]

#: the file that marks a folder as the C-only target's (its orphans may be removed)
MARKER = "rigidsym_c_common.h"


def select_kernels(modules, names) -> tuple[list, dict[str, str]]:
    """The kernels to generate and ``{kernel name: where it is declared}``: the user
    modules' (``--module``) and the book's named ones (``--kernel``); every book kernel
    when neither is given.

    Raises:
        BadInput: a ``--kernel`` name the book does not declare (the known names listed).
    """
    kernels, origins = [], []
    where: dict[str, str] = {}
    if modules:
        from rigidsym.codegen.usergen import load_user_kernels
        ks, title = load_user_kernels(modules)
        kernels += ks
        origins.append(title)
        where.update(dict.fromkeys((k.name for k in ks), title))
    if names or not modules:
        book = {k.name: k for k in importlib.import_module(KERNEL_SPEC).KERNELS}
        if names:
            unknown = [n for n in names if n not in book]
            if unknown:
                raise BadInput(f"--kernel: the book declares no kernel {unknown[0]!r} "
                               f"(known: {', '.join(sorted(book))})")
            picked = [book[n] for n in dict.fromkeys(names)]
        else:
            picked = list(book.values())
        kernels += picked
        origins.append(KERNEL_SPEC)
        where.update(dict.fromkeys((k.name for k in picked), KERNEL_SPEC))
    seen = [k.name for k in kernels]
    dup = sorted({n for n in seen if seen.count(n) > 1})
    if dup:
        raise BadInput(f"kernel {dup[0]} is declared twice in {', '.join(origins)}")
    return kernels, where


def cmd_generate_c(args) -> int:
    """Write (or with ``--check`` compare) the C-only target into ``--out``."""
    from rigidsym.codegen.backends.c.target import float_bounds, generate_c
    from rigidsym.codegen.files import check_or_write
    from rigidsym.codegen.generator import compile_many

    t0 = time.perf_counter()
    if not args.out:
        raise BadInput("--out: a folder is required with --target c")
    out = Path(args.out)
    ours = (out / MARKER).is_file()
    if args.check and not ours:
        raise BadInput(f"--out: {out} holds no C target to compare with")
    if not args.check and out.exists() and any(out.iterdir()) and not ours:
        # write() removes the files it does not own: never in a folder of someone else's
        raise BadInput(f"--out: {out} is not empty and holds no C target "
                       f"({MARKER}); give a new or empty folder")
    from rigidsym.codegen.validate import one_line_warnings

    with one_line_warnings():
        kernels, origin = select_kernels(args.module, getattr(args, "kernel", None))
    files = generate_c(compile_many(kernels, plan32=False), origin,
                       single_header=getattr(args, "single_header", False),
                       bounds=float_bounds(args.module))

    class _Result:  # what codegen.files reads of a generation
        pass
    res = _Result()
    res.files = files  # type: ignore[attr-defined]
    rc = check_or_write(res, out, check_only=args.check, kernels=len(kernels),
                        rerun=f"rigidsym generate --target c ... --out {out}", t0=t0)
    return rc or 0
