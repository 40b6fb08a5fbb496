"""``rigidsym generate [--check]`` and ``rigidsym build-c``."""

from __future__ import annotations

import sys
import time
from pathlib import Path
from types import SimpleNamespace

__all__ = ["cmd_generate", "cmd_build_c", "GENERATE", "BUILD_C"]


def _generate_args(p) -> None:
    p.add_argument("--check", action="store_true",
                   help="regenerate in memory; print a diff and exit 1 on any difference "
                        "(2 when there is no generated/ folder to compare with; default: "
                        "off, write the files)")
    p.add_argument("--out", default=None, metavar="DIR",
                   help="output folder (default: generated/ of the source tree)")
    p.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help="a user module whose KERNELS to generate into --out (repeatable; "
                        "default: none, the package's kernels)")
    p.add_argument("--no-build", action="store_true",
                   help="with --module: write the C only; do not compile it into the cache")
    p.add_argument("--target", choices=("package", "c", "cpp"), default="package",
                   help="package: the Python package's kernels (NumPy, C extension, PyTorch, "
                        "JAX); c: C99 sources, headers and build files for C and C++ "
                        "projects, no Python (docs/c-api.md); cpp: the same and a "
                        "header-only C++ layer (Eigen, std::array) over it; default: package")
    p.add_argument("--notice", default=None, metavar="TEXT",
                   help="with --target c or cpp: the licence or copyright notice of every "
                        "generated file, your code's (its lines; \"\" for none; no LICENSE "
                        "file is written); default: the rigidsym project's MIT notice")
    p.add_argument("--no-measure", action="store_true",
                   help="with --target c or cpp and --module: do not measure the module's "
                        "float bounds (a few seconds per kernel; its headers then say \"not "
                        "measured\"); default: measure them (needs a C compiler)")
    p.add_argument("--no-accuracy", action="store_true",
                   help="with the package target: do not build and measure the accuracy of "
                        "the kernels that have no measurement or whose code changed "
                        "(default: measure them into derivations/kernels_accuracy.json, "
                        "seconds a kernel)")
    p.add_argument("--namespace", default=None, metavar="NAME",
                   help="with --target cpp: the C++ namespace of the layer (default: "
                        "rigidsym)")
    p.add_argument("--prefix", default=None, metavar="NAME",
                   help="with --target c or cpp: the name every C symbol, macro (upper "
                        "case), file, the CMake target and the pkg-config module carry, and "
                        "the default C++ namespace, so that folders of different prefixes "
                        "link into one program (a lower-case C identifier; default: "
                        "rigidsym_c, namespace rigidsym)")
    p.add_argument("--kernel", action="append", metavar="NAME",
                   help="with --target c: a book kernel to include (repeatable; default: "
                        "every book kernel when no --module is given, none otherwise); with "
                        "the package target: derive this kernel (and its _with_jacobians) "
                        "even when stored, every other one from the store (repeatable)")
    p.add_argument("--no-store", action="store_true",
                   help="with the package target or --module: derive every kernel, "
                        "neither reading nor writing the store of derived kernels (default: "
                        "derive only the kernels whose inputs changed, keep each one as it "
                        "finishes)")
    p.add_argument("--single-header", action="store_true",
                   help="with --target c: also write rigidsym_c_single.h, every kernel in "
                        "one self-contained header (default: off)")


def cmd_generate(args) -> int:
    """Generate the NumPy and C kernels into generated/ (--check: compare only)."""
    from rigidsym.codegen.generator import check, default_out_dir, generate, render, write
    from rigidsym.core.work import since, snapshot

    if getattr(args, "target", "package") in ("c", "cpp"):
        if args.target == "c" and getattr(args, "namespace", None):
            print("error: --namespace: only with --target cpp", file=sys.stderr)
            return 2
        from rigidsym.codegen.usergen import cmd_generate_c
        return cmd_generate_c(args)
    for opt, given in (("--single-header", getattr(args, "single_header", False)),
                       ("--namespace", getattr(args, "namespace", None)),
                       ("--prefix", getattr(args, "prefix", None)),
                       ("--notice", getattr(args, "notice", None)),
                       ("--no-measure", getattr(args, "no_measure", False))):
        if given is not None and given is not False:    # --notice "" is given
            print(f"error: {opt}: only with --target c or cpp", file=sys.stderr)
            return 2
    if args.module:
        if getattr(args, "kernel", None):
            print("error: --kernel: with --target c, or without --module", file=sys.stderr)
            return 2
        from rigidsym.codegen.usergen import cmd_generate_user
        return cmd_generate_user(args)
    t0 = time.perf_counter()
    out = Path(args.out) if args.out else default_out_dir()
    if args.check and not out.is_dir():
        # e.g. an installed wheel: there is no checkout to compare with
        print(f"error: no generated/ folder here ({out}): run from the repository root",
              file=sys.stderr)
        return 2
    from rigidsym.core.progress import Reporter
    with Reporter("rigidsym generate") as rep, \
            rep.phase("deriving, optimising and printing the kernels") as ph:
        before = snapshot()
        res = generate(stored=not getattr(args, "no_store", False),
                       only=getattr(args, "kernel", None), progress=ph.counted)
        derived = len(since(before, "derive"))
        ph.finish(f"{len(res.kernels)} kernels ({derived} derived, "
                  f"{len(res.kernels) - derived} stored), {len(res.files)} files")
    books = _notebooks()
    if args.check:
        diff = check(res, out)
        stale = _check_notebooks(books, out)
        if diff or stale:
            sys.stdout.write(diff)
            print(f"generated/ is stale: run `rigidsym generate` "
                  f"({time.perf_counter() - t0:.1f} s)", file=sys.stderr)
            return 1
        print(f"generated/ is up to date: {len(res.kernels)} kernels, {len(res.files)} files, "
              f"{len(books)} notebook files ({time.perf_counter() - t0:.1f} s)")
        return 0
    touched = write(res, out)
    if not getattr(args, "no_accuracy", False):
        names = _unmeasured(res, touched, set(since(before, "derive")))
        if names and _measure(names, out):
            res = render(res.kernels, res.kernel_files)
            touched += [t for t in write(res, out) if t not in touched]
    if books:
        from rigidsym.course import NOTEBOOK_DIR, write_files
        touched += [f"{NOTEBOOK_DIR}/{n}" for n in write_files(books, out / NOTEBOOK_DIR)]
    for t in touched:
        print(f"wrote {t}")
    print(f"{len(res.kernels)} kernels, {len(res.files)} files, {len(touched)} changed "
          f"({time.perf_counter() - t0:.1f} s)")
    return 0


def _unmeasured(res, touched: list[str], derived: set[str]) -> list[str]:
    """The kernels of the generation ``res`` whose accuracy is to be measured: those with
    no measurement in ``kernels.json``, and those derived now (``derived``) whose NumPy
    code changed on disk (``touched``)."""
    import json

    metas = json.loads(res.files["kernels.json"])["kernels"]
    return sorted(m["name"] for m in metas if m.get("accuracy") is None or (
        m["name"] in derived and f"numpy/{m['name']}.py" in touched))


def _measure(names: list[str], out: Path) -> bool:
    """Build the package's C of ``out`` (only the objects whose sources changed compile)
    and measure the accuracy of ``names`` into ``derivations/kernels_accuracy.json``
    (``benchmarks/accuracy.py --kernels``, the harness of every recorded row); True when
    the data file was written. Outside a checkout (no ``benchmarks/``) a note says how."""
    import subprocess

    from rigidsym.codegen.generator import ACCURACY_DATA
    from rigidsym.kernels.cbuild import driver as _build
    from rigidsym.kernels.cbuild import extension as _ext

    root = out.resolve().parent
    script, data = root / "benchmarks" / "accuracy.py", root / "derivations" / ACCURACY_DATA
    if not script.is_file() or not data.parent.is_dir():
        print(f"note: the accuracy of {', '.join(names)} is not measured: no "
              f"benchmarks/accuracy.py beside {out}", file=sys.stderr)
        return False
    try:
        _ext.ensure(out.resolve(), why="rigidsym generate (to measure new kernels)")
    except _build.CompilerNotFound as exc:
        print(f"note: not compiled ({exc}): measuring on NumPy only", file=sys.stderr)
    except _build.BuildError as exc:
        print(f"error: compiling {out} failed: {exc}", file=sys.stderr)
        return False
    print(f"measuring the accuracy of {len(names)} kernels: {', '.join(names)}", flush=True)
    rc = subprocess.run([sys.executable, str(script), "--kernels", ",".join(names),
                         "--data", str(data)], cwd=root).returncode
    if rc != 0:
        print(f"note: a row of {', '.join(names)} is past the accuracy rule (exit {rc}; "
              f"docs/accuracy.md); recorded as measured", file=sys.stderr)
    return True


def _notebooks() -> dict[str, str]:
    """The exercise notebooks (``{}`` with a note when nbformat is not installed)."""
    try:
        from rigidsym.course import notebook_files
        return notebook_files()
    except ModuleNotFoundError as exc:
        if exc.name != "nbformat":
            raise
        print("note: notebooks skipped: nbformat is not installed "
              "(pip install \"rigidsym[notebooks]\")", file=sys.stderr)
        return {}


def _check_notebooks(books: dict[str, str], out: Path) -> bool:
    """Print the stale notebook files; True when any differs."""
    if not books:
        return False
    from rigidsym.course import NOTEBOOK_DIR, check_files
    stale = check_files(books, out / NOTEBOOK_DIR)
    for name in stale:
        print(f"stale notebook file: generated/{NOTEBOOK_DIR}/{name}")
    return bool(stale)


def _build_args(p) -> None:
    p.add_argument("directory", nargs="?", default=None, metavar="DIR",
                   help="a generated folder (rigidsym generate --out DIR); default the "
                        "package's kernels")
    p.add_argument("--module", action="append", metavar="PATH_OR_DOTTED",
                   help="generate this user module's kernels into --out, then compile them "
                        "(default: none)")
    p.add_argument("--out", default=None, metavar="DIR",
                   help="output folder of --module (default: none)")
    p.add_argument("--native", action="store_true",
                   help="build for this CPU only (-march=native) into the cache; used "
                        "whenever present")
    p.add_argument("--force", action="store_true",
                   help="rebuild even if a build is cached (default: off)")
    p.add_argument("--info", action="store_true",
                   help="print the build information of the kernels in use (JSON) and exit")


def _pip_note(info: dict) -> None:
    """On stderr (stdout is the JSON): where the package's C was compiled, and how to watch
    it next time; pip prints nothing while its build runs (minutes on a small machine)."""
    build = info.get("build") if isinstance(info, dict) else None
    if info.get("origin") not in ("editable build", "wheel") or not isinstance(build, dict):
        return
    print(f"rigidsym build-c: the package's C kernels were compiled by `pip install` "
          f"({build.get('compiled', '?')} objects compiled, {build.get('reused', '?')} reused "
          f"from the object cache, {build.get('seconds', '?')} s); pip is silent while it "
          f"compiles: `pip install -v .` shows its progress (a line per tenth of the objects)",
          file=sys.stderr)


def cmd_build_c(args) -> int:
    """Compile generated C kernels into the user cache (the package's own kernels only when
    their module is stale, or with --native), with a notice and a progress bar."""
    from rigidsym.kernels.cbuild import driver as _build
    from rigidsym.kernels.cbuild import extension as _ext

    if args.info:
        import json

        from rigidsym import kernels
        info = kernels.build_info(args.directory)
        print(json.dumps(info, indent=1))
        _pip_note(info)
        return 0
    if args.module:
        if args.directory:
            print("error: give either DIR or --module (with --out), not both", file=sys.stderr)
            return 2
        from rigidsym.codegen.usergen import cmd_generate_user
        args.check = False
        args.no_build = False
        return cmd_generate_user(args)
    gdir = Path(args.directory).resolve() if args.directory else _ext.generated_dir()
    if not (gdir / "c").is_dir():
        print(f"error: {gdir} holds no generated C (run `rigidsym generate --out {gdir}`)",
              file=sys.stderr)
        return 2
    package = args.directory is None
    sources = _build.sources_hash(gdir / "c")
    built = _ext.package_module() if package else None
    if package and not (args.native or args.force) and built is not None \
            and _build.embedded_hash(built) == sources:
        print(f"up to date: {built} (built with the package)")
        return 0
    try:
        path = _ext.ensure(gdir, native=args.native, force=args.force,
                           why="rigidsym build-c" + (" --native" if args.native else ""))
    except _build.BuildError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    print(f"built {path}")
    return 0


GENERATE = SimpleNamespace(
    HELP="generate the NumPy and C kernels (into generated/, or --out)",
    EXAMPLES="  rigidsym generate --check             is generated/ up to date?\n"
             "  rigidsym generate --module my_eqs.py --out mykernels/   your own kernels\n"
             "  rigidsym generate --target c --module my_eqs.py --out fw/   C for firmware",
    add_arguments=_generate_args, run=cmd_generate)
BUILD_C = SimpleNamespace(HELP="compile the generated C kernels into the user cache",
                          add_arguments=_build_args, run=cmd_build_c)
