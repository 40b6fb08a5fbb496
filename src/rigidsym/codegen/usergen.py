"""The commands of ``rigidsym generate`` that write a folder of the user's (``--out DIR``):
``--module M``, a user module's kernels in the package's layout (same generator), and
``--target c``, the C-only target (:mod:`rigidsym.codegen.backends.c`) of the book's or a
user module's kernels. (The C target's command sits here, above the generator, because it
compiles the kernels as the generator does; the targets themselves import no generator.)

A user module lists :class:`~rigidsym.codegen.spec.Kernel` specs in ``KERNELS``; their
``sources`` may be the formula callables themselves (named here as ``<module>.<function>``
in the headers and ``kernels.json``). The output folder has the layout of ``generated/``
(``numpy/``, ``c/``, ``kernels.json``) and is loaded by ``rigidsym.kernels.load(DIR)``.
"""

from __future__ import annotations

import dataclasses
import importlib
import sys
import time
from pathlib import Path

from rigidsym.codegen.backends.c import prefix as _pfx
from rigidsym.codegen.spec import Kernel
from rigidsym.core.config import KERNEL_SPEC
from rigidsym.registry.declarations import BadInput

__all__ = ["user_kernels", "load_user_kernels", "generate_user", "cmd_generate_user",
           "select_kernels", "cmd_generate_c", "measured_bounds", "MARKER"]


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


def generate_user(modules, stored: bool = False):
    """Generate the kernels of user modules (paths or dotted names) in memory (``stored``:
    each kernel whose inputs are unchanged from the store of derived kernels, each one
    derived stored as it finishes: :func:`rigidsym.codegen.generator.generate`).

    Returns:
        The generator's result (relative path -> text), headers naming the modules.

    Raises:
        BadInput: for a module that cannot be loaded, one without ``KERNELS``, or two
            kernels of one name.
    """
    from rigidsym.codegen.generator import generate

    kernels, origin = load_user_kernels(modules)
    return generate(kernels, origin=origin, stored=stored)


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
        res = generate_user(args.module, stored=not getattr(args, "no_store", False))
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


#: the file that marks a folder as the C-only target's of the default prefix (its orphans
#: may be removed; another prefix's: :func:`rigidsym.codegen.backends.c.prefix.
#: generated_marker`)
MARKER = f"{_pfx.DEFAULT_PREFIX}{_pfx.MARKER_SUFFIX}"


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


def measured_bounds(kernels, codes, origin: dict, known: dict) -> dict:
    """The float bounds of the user kernels among ``kernels`` (and their twins) that
    ``known`` lacks for their declaration hash, measured now
    (:mod:`rigidsym.codegen.accuracy.float_measure`; a few seconds each): ``{name: entry}``
    as :func:`~rigidsym.codegen.backends.c.target.float_bounds` gives. ``codes``: the compiled
    ``kernels`` and twins; ``origin``: ``{kernel: module}``. No C compiler: a note, ``{}``."""
    from rigidsym.codegen.accuracy import float_measure as FM
    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels

    user = [k for k in kernels if origin.get(k.name) != KERNEL_SPEC]
    names = {k.name for k in user} | {j.name for j in jacobian_kernels(user)}
    todo = {kc.kernel.name for kc in codes if kc.kernel.name in names
            and known.get(kc.kernel.name, {}).get("hash") != kc.hash}
    if not todo:
        return {}
    if FM.compiler() is None:
        print("note: float bounds not measured: no C compiler (gcc, cc or $CC)",
              file=sys.stderr)
        return {}
    t0 = time.perf_counter()
    FM.register(user)
    got = FM.measure_codes(codes, origin, only=todo,
                           say=lambda m: print(f"  {m}", file=sys.stderr, flush=True))
    print(f"measured the float bounds of {len(got)} functions "
          f"({time.perf_counter() - t0:.1f} s; --no-measure skips)", file=sys.stderr)
    return got


def cmd_generate_c(args) -> int:
    """Write (or with ``--check`` compare) the C-only target into ``--out`` (with ``--target
    cpp`` also its C++ layer, :mod:`rigidsym.codegen.backends.cpp`, in ``--namespace``),
    every name carrying ``--prefix`` (:mod:`rigidsym.codegen.backends.c.prefix`)."""
    from rigidsym.codegen.backends.c.target import float_bounds, generate_c
    from rigidsym.codegen.files import check_or_write
    from rigidsym.codegen.generator import compile_many

    t0 = time.perf_counter()
    if not args.out:
        raise BadInput(f"--out: a folder is required with --target "
                       f"{getattr(args, 'target', 'c')}")
    prefix = _prefix(args)
    out = Path(args.out)
    ours = _pfx.generated_marker(out, prefix) is not None
    if args.check and not ours:
        raise BadInput(f"--out: {out} holds no C target to compare with")
    if not args.check and out.exists() and any(out.iterdir()) and not ours:
        # write() removes the files it does not own: never in a folder of someone else's
        raise BadInput(f"--out: {out} is not empty and holds no C target "
                       f"(<prefix>{_pfx.MARKER_SUFFIX}); give a new or empty folder")
    from rigidsym.codegen.validate import one_line_warnings

    with one_line_warnings():
        kernels, origin = select_kernels(args.module, getattr(args, "kernel", None))
    ns = getattr(args, "namespace", None)
    notice = getattr(args, "notice", None)
    from rigidsym.codegen.backends.c.target import CTargetError, notice_lines
    try:
        notice_lines(notice)
    except CTargetError as exc:
        raise BadInput(str(exc)) from None
    if ns is not None:
        from rigidsym.codegen.backends.cpp.target import CppTargetError, check_namespace
        try:
            check_namespace(ns)
        except CppTargetError as exc:
            raise BadInput(str(exc)) from None
    codes = compile_many(kernels, plan32=False)
    bounds = float_bounds(args.module)
    try:   # a name the C cannot take: one line, exit 2, nothing written
        if args.module and not getattr(args, "no_measure", False):
            bounds.update(measured_bounds(kernels, codes, origin, bounds))
        files = generate_c(codes, origin, single_header=getattr(args, "single_header", False),
                           bounds=bounds, notice=notice, prefix=prefix)
    except CTargetError as exc:
        raise BadInput(str(exc)) from None
    target = getattr(args, "target", "c")
    if target == "cpp":   # the C++ layer beside the C it calls
        from rigidsym.codegen.backends.cpp.target import generate_cpp
        files.update(generate_cpp(codes, ", ".join(dict.fromkeys(origin.values())),
                                  namespace=ns, notice=notice, prefix=prefix))

    class _Result:  # what codegen.files reads of a generation
        pass
    res = _Result()
    res.files = files  # type: ignore[attr-defined]
    again = "" if prefix == _pfx.DEFAULT_PREFIX else f" --prefix {prefix}"
    rc = check_or_write(res, out, check_only=args.check, kernels=len(kernels),
                        rerun=f"rigidsym generate --target {target}{again} ... --out {out}",
                        t0=t0)
    return rc or 0


def _prefix(args) -> str:
    """``--prefix`` (default ``rigidsym_c``), checked before any kernel is compiled."""
    prefix = getattr(args, "prefix", None) or _pfx.DEFAULT_PREFIX
    try:
        return _pfx.check_prefix(prefix)
    except _pfx.PrefixError as exc:
        raise BadInput(str(exc)) from None
