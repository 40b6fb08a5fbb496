"""Render the kernels of ``derivations/kernels_spec.py`` into ``generated/`` (NumPy and C).

Pipeline per kernel: build the explicit sympy outputs from the formula functions (main
build and per-sample branches), hash them (before any rewrite or printing), rewrite and CSE
them (:mod:`.optimise`), print them (:mod:`.printers`) into role-named Jinja2 templates.
:func:`generate` returns ``{relative path: text}``; :func:`write` writes it atomically and
removes orphans; :func:`check` compares it with the disk and returns a unified diff (both in
:mod:`rigidsym.codegen.files`, re-exported here).
"""

from __future__ import annotations

import importlib
import json
import math
import os
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

import jinja2
import sympy as sp

import rigidsym
from rigidsym.codegen import inputs
from rigidsym.codegen.accuracy.compensated import NUMPY_SOURCE, uses_diffprod
from rigidsym.codegen.accuracy.cos_form import choose as choose_cos
from rigidsym.codegen.accuracy.float32 import plan_kernel
from rigidsym.codegen.accuracy.rewrites import Chosen, improve
from rigidsym.codegen.api_spec import render_api
from rigidsym.codegen.arrays import render_array_kernels
from rigidsym.codegen.cprogram import TRIG_BLOCK as TRIG_BLOCK
from rigidsym.codegen.cprogram import (
    f32_code,
    finite_check,
    program_lines,
    risky_names,
    trig_plan,
    trig_split,
)
from rigidsym.codegen.files import check, write
from rigidsym.codegen.optimise import Program, compile_program, math_hash
from rigidsym.codegen.printers import KernelCPrinter, KernelNumPyPrinter
from rigidsym.codegen.removable.singularities import rewrite as removable
from rigidsym.codegen.spec import Kernel, flat_symbols, input_symbols
from rigidsym.codegen.spec import flatten_outputs as _flatten
from rigidsym.codegen.vjp import jacobian_program
from rigidsym.core import kinds as _kinds
from rigidsym.core.config import KERNEL_SPEC as BOOK_ORIGIN
from rigidsym.core.config import generated_dir

__all__ = ["generate", "write", "check", "GenerationResult", "default_out_dir", "TEMPLATES"]

#: where the package's own templates are, one folder per language (issue 53): the C of the
#: extension module (``c_*.j2``, beside the C target's) and the Python package's files
#: (NumPy, PyTorch and JAX kernels, ``api.py``, ``__init__.py``); names are unique across them
TEMPLATES = tuple(Path(__file__).parent / "backends" / lang / "templates"
                  for lang in ("c", "python"))
#: the ``kind`` of an entry point's argument whose constraint only the Python path checks
#: (``RIGIDSYM_PYTHON`` in ``c_fast.h.j2``)
_C_PYTHON_CHECK = 3


def default_out_dir() -> Path:
    """``generated/`` of the checkout (:func:`rigidsym.core.config.generated_dir`)."""
    return generated_dir()


@dataclass
class Variant:
    """One build of a kernel (the main one, or a branch) compiled to a program."""

    name: str
    program: Program
    cond: sp.Basic | None = None


@dataclass
class KernelCode:
    kernel: Kernel
    variants: list[Variant]
    hash: str
    ops: int
    inputs: list = field(default_factory=list)   # [(arg, [symbols])]
    rewrites: list = field(default_factory=list)  # accuracy rewrites kept (codegen.accurate)
    plan32: dict = field(default_factory=dict)   # float32 precision plans (codegen.float32)


@dataclass
class GenerationResult:
    files: dict[str, str]
    kernels: list[KernelCode]


def compile_kernel(kernel: Kernel, plan32: bool = True) -> KernelCode:
    """Build, hash and optimise every variant of ``kernel`` (of a Jacobian kernel
    ``jacobian_from="program"``: its values' variants, each then differentiated).
    ``plan32=False`` skips the float32 precision plans (the C-only target has no use for
    them: its float functions compute in float throughout)."""
    of = kernel.jacobian_of if kernel.jacobian_from == "program" else None
    spec = of or kernel
    syms = input_symbols(spec)
    angles = [syms[a.name] for a in spec.args
              if (k := _kinds.for_spec(a.kind, a.shape)) is not None and k.half_angle]
    parts: list = []
    variants = []
    chosen: list[Chosen] = []
    sflat = [s for _, ss in flat_symbols(spec) for s in ss]
    before: list = []     # float predicates of the branches tried before (accuracy points)
    for br in spec.branches:
        cond = br.when(**syms)
        declared = _flatten(spec, br.build(**syms))
        parts += [cond, *declared]
        fcond = sp.lambdify(sflat, cond, modules="math")
        flat, got = improve(spec, br.name, declared, syms, sflat, list(before), fcond)
        flat = removable(flat)
        form, got2 = choose_cos(spec, br.name, declared, flat, angles, sflat, list(before),
                                fcond)
        before.append(fcond)
        chosen += got + got2
        variants.append(Variant(br.name, compile_program(flat, angles, form), cond))
    declared = _flatten(spec, spec.build(**syms))
    parts += declared
    flat, got = improve(spec, "main", declared, syms, sflat, before)
    flat = removable(flat)
    form, got2 = choose_cos(spec, "main", declared, flat, angles, sflat, before)
    chosen += got + got2
    variants.append(Variant("main", compile_program(flat, angles, form), None))
    if of is not None:
        args = [ss for _, ss in flat_symbols(of)]
        sizes = [o.size for o in of.outputs]
        for v in variants:
            v.program = jacobian_program(v.program, args, sizes)
        parts.append(sp.Symbol("forward_mode_over_the_program"))
    ops = sum(v.program.ops for v in variants)
    kc = KernelCode(kernel, variants, math_hash(parts), ops, flat_symbols(kernel), chosen)
    if not plan32:
        return kc
    kc.plan32 = plan_kernel(kernel, variants, trig_split(kc)) if of is None else \
        _double_plan(kc)
    return kc


def _double_plan(kc: KernelCode) -> dict:
    """The float32 plan of a Jacobian kernel differentiated over its program: every node in
    double, the outputs rounded to float once (error <= u/2 per entry: 1/8 of the rule's 4 u
    floor). The plan search (:func:`rigidsym.codegen.accuracy.float32.plan_kernel`) runs the program
    twice per node, so its time grows as the square of the nodes: 180 s for the 1760 of
    ``exponential_coordinates_left_jacobian_inverse_with_jacobians``."""
    def plan(prog, trig=()) -> dict:
        nodes = [*trig, *(str(s) for s, _ in prog.temps),
                 *(f"out:{j}" for j in range(len(prog.outputs)))]
        return {"plan": dict.fromkeys(nodes, "d"), "error": 0.125}
    split = trig_split(kc)
    if split is not None:
        return {"trig": plan(split["program"], list(split["calls"])), "variants": None}
    return {"trig": None, "variants": [plan(v.program) for v in kc.variants]}


_TODO: list = []
_PLAN32: list = [True]


def _compile_index(i: int):
    kc = compile_kernel(_TODO[i], _PLAN32[0])
    return kc.variants, kc.hash, kc.ops, kc.inputs, kc.rewrites, kc.plan32


def _compile_all(todo: list, plan32: bool = True) -> list[KernelCode]:
    """Compile kernels, over two forked workers when there are many (same result, in order)."""
    jobs = min(2, os.cpu_count() or 1)
    if len(todo) < 8 or jobs < 2 or os.environ.get("RIGIDSYM_GENERATE_JOBS") == "1":
        return [compile_kernel(k, plan32) for k in todo]
    import multiprocessing as mp

    _TODO[:] = todo
    _PLAN32[0] = plan32
    try:
        with mp.get_context("fork").Pool(jobs) as pool:
            parts = pool.map(_compile_index, range(len(todo)), chunksize=1)
    finally:
        _TODO.clear()
        _PLAN32[0] = True
    return [KernelCode(k, *p) for k, p in zip(todo, parts, strict=True)]


def compile_many(kernels: list[Kernel], plan32: bool = True) -> list[KernelCode]:
    """``kernels`` and their Jacobian twins (sorted by name), compiled to programs
    (``plan32=False``: without the float32 precision plans of the package's kernels)."""
    return _compile_all(_with_jacobian_kernels(sorted(kernels, key=lambda k: k.name)),
                        plan32)


def _env() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader([str(t) for t in TEMPLATES]), keep_trailing_newline=True,
        trim_blocks=True, lstrip_blocks=True, undefined=jinja2.StrictUndefined,
        autoescape=False)


#: where the book's kernels are composed (a user module's kernels name that module)


def _header(kc: KernelCode, template: str, origin: str = BOOK_ORIGIN) -> list[str]:
    k = kc.kernel
    lines = [
        "Generated by rigidsym.codegen -- do not modify by hand; run `rigidsym generate`.",
        f"kernel: {k.name}",
        f"source: {', '.join(k.sources)} (composed in {origin})",
        f"equations: {', '.join('(' + i + ')' for i in k.ids)}",
        f"template: {template}",
        f"math hash: sha256:{kc.hash}",
        f"sympy {sp.__version__}, rigidsym {rigidsym.__version__}",
        f"operations: {kc.ops}",
    ]
    if k.branches:
        lines.append("branches: " + ", ".join(b.name for b in k.branches) + ", main")
    lines += [w for c in kc.rewrites
              for w in textwrap.wrap(c.line(), 92, subsequent_indent="    ")]
    return lines


def _meta(kc: KernelCode) -> dict:
    k = kc.kernel
    return {
        "name": k.name, "summary": k.summary, "formula": k.formula, "ids": list(k.ids),
        "sources": list(k.sources), "public": k.public,
        "args": [{"name": a.name, "shape": list(a.shape), "kind": a.kind, "doc": a.doc}
                 for a in k.args],
        "outputs": [{"name": o.name, "shape": list(o.shape), "doc": o.doc} for o in k.outputs],
        "singular": k.singular, "singular_arg": k.singular_arg, "notes": k.notes,
        "branches": [b.name for b in k.branches], "ops": kc.ops, "hash": kc.hash,
    }


#: samples per block of the generated NumPy kernels: the temporaries of one block (tens of
#: arrays of 8 bytes a sample) stay in L2, so large batches are not memory-bound; measured in
#: benchmarks/RESULTS.md
NUMPY_CHUNK = 16384


def _render_kernel(env, kc: KernelCode, origin: str = BOOK_ORIGIN) -> dict[str, str]:
    k = kc.kernel
    npp, cp = KernelNumPyPrinter(), KernelCPrinter()
    # kernels without a division (or sqrt, atan2 of possibly zero arguments) give finite
    # outputs for finite inputs: no finiteness check in the generated code
    divides = any(v.program.dens for v in kc.variants)
    common = {"k": k, "meta": _meta(kc), "inputs": kc.inputs, "divides": divides}
    files = {}
    t = "numpy_kernel.py.j2"
    files[f"numpy/{k.name}.py"] = env.get_template(t).render(
        header=_header(kc, t, origin), ops=kc.ops, hash=kc.hash, chunk=NUMPY_CHUNK,
        helpers=NUMPY_SOURCE.strip("\n") if uses_diffprod(kc) else "",
        variants=[{"name": v.name, "cond": None if v.cond is None else npp.doprint(v.cond),
                   "risky": risky_names(v.program, npp), **program_lines(v.program, npp)}
                  for v in kc.variants], **common)
    used = set()
    for v in kc.variants:
        for e in [*(x for _, x in v.program.temps), *v.program.outputs, *v.program.dens,
                  *([v.cond] if v.cond is not None else [])]:
            used |= {str(s) for s in sp.sympify(e).free_symbols}
    cvars = [{"name": v.name, "cond": None if v.cond is None else cp.doprint(v.cond),
              "finite": finite_check(v.program, k), **program_lines(v.program, cp)}
             for v in kc.variants]
    # nothing a sample could flag (no division, no finiteness test, no branch): the batch
    # loop needs no count
    never_singular = len(cvars) == 1 and not divides and not cvars[0]["finite"]
    for t, path in (("c_kernel.h.j2", f"c/{k.name}.h"), ("c_kernel.c.j2", f"c/{k.name}.c")):
        files[path] = env.get_template(t).render(header=_header(kc, t, origin), variants=cvars,
                                                 used=used, trig=trig_plan(kc, cp),
                                                 never_singular=never_singular,
                                                 f32=f32_code(kc), **common)
    # PyTorch and JAX: the same programs (issue 31)
    files.update(render_array_kernels(env, kc, lambda t: _header(kc, t, origin)))
    return files


def _with_jacobian_kernels(todo: list[Kernel]) -> list[Kernel]:
    """``todo`` and, for each smooth kernel, its ``<name>_with_jacobians`` (sorted by name).

    The Jacobian kernels are ordinary (non-public) kernels with extra outputs, so they go
    through the same rewrite, CSE, templates and checks as the values.
    """
    from rigidsym.codegen.jacobians import jacobian_kernels

    return sorted(todo + jacobian_kernels(todo), key=lambda k: k.name)


def generate(kernels=None, origin: str = BOOK_ORIGIN) -> GenerationResult:
    """Render every kernel; returns the files (relative path -> text) and the compiled kernels.

    ``kernels`` defaults to the book's; a user module's kernels come with ``origin`` (the
    module's name, written in the headers) and sources already named, not imported here.
    """
    kernels_are_book = kernels is None
    if kernels is None:  # by name: the generator imports no book
        kernels = importlib.import_module(BOOK_ORIGIN).KERNELS
    env = _env()
    files: dict[str, str] = {}
    done: list[KernelCode] = []
    todo = sorted(kernels, key=lambda k: k.name)
    for kc in _compile_all(_with_jacobian_kernels(todo)):
        done.append(kc)
        files.update(_render_kernel(env, kc, origin))
    metas = [_meta(kc) for kc in done]
    if kernels_are_book:
        acc = _accuracy_data()
        for m in metas:
            m["accuracy"] = acc.get(m["name"])
    ver = {"sympy": sp.__version__, "rigidsym": rigidsym.__version__}
    files["kernels.json"] = json.dumps({"generator": ver, "kernels": metas},
                                       indent=1, sort_keys=True) + "\n"
    files["api.py"] = render_api(env, metas, ver)
    for t, path in (("package_init.py.j2", "__init__.py"),
                    ("numpy_index.py.j2", "numpy/__init__.py"),
                    ("c_common.h.j2", "c/rigidsym_common.h"),
                    ("c_kernels_index.h.j2", "c/rigidsym_kernels.h")):
        files[path] = env.get_template(t).render(kernels=metas, template=t, **ver)
    files.update(_render_extension(env, metas, ver))
    if kernels_are_book:
        # what the default test run compares instead of generating again (issue 54)
        files[inputs.MANIFEST] = inputs.render(files)
    return GenerationResult(dict(sorted(files.items())), done)


#: the measured accuracy of the book's kernels (benchmarks/accuracy.py --data), shipped in
#: kernels.json for ``kernels.accuracy``; beside the kernel declarations, loaded by name
ACCURACY_DATA = "kernels_accuracy.json"


def _accuracy_data() -> dict:
    from importlib.resources import files

    path = files(BOOK_ORIGIN.rsplit(".", 1)[0]).joinpath(ACCURACY_DATA)
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}


def _render_extension(env, metas: list[dict], ver: dict) -> dict[str, str]:
    """The extension module's own C: the module (``c_module.c.j2``), the per-path table of
    batch functions (``c_table.c.j2``), the CPU dispatcher (``c_dispatch.h.j2``) and the
    per-call entry points (``c_fast.h.j2``)."""
    def size(shape) -> int:
        return int(math.prod(shape))
    def c_check(a: dict) -> int:  # the kind table's C validation routine (0 for outputs)
        k = _kinds.for_spec(a["kind"], a["shape"]) if "kind" in a else None
        if k is None:
            return 0
        # a checked kind with no C routine of its own: checked calls take the Python path
        return k.c_check if k.c_check or k.check is None else _C_PYTHON_CHECK

    def slot(a: dict) -> dict:
        return {"nd": len(a["shape"]), "dims": list(a["shape"]), "size": size(a["shape"]),
                "kind": c_check(a)}
    ck = [{"name": m["name"], "ins": [size(a["shape"]) for a in m["args"]],
           "outs": [size(o["shape"]) for o in m["outputs"]],
           "narrays": len(m["args"]) + len(m["outputs"]),
           "nin": len(m["args"]), "nout": len(m["outputs"]),
           "args": [slot(a) for a in m["args"]],
           "outs_meta": [slot(o) for o in m["outputs"]]} for m in metas]
    files = {}
    for t, path in (("c_module.c.j2", "c/rigidsym_module.c"),
                    ("c_table.c.j2", "c/rigidsym_table.c"),
                    ("c_dispatch.h.j2", "c/rigidsym_dispatch.h"),
                    ("c_fast.h.j2", "c/rigidsym_fast.h")):
        files[path] = env.get_template(t).render(kernels=ck, template=t, **ver)
    return files
