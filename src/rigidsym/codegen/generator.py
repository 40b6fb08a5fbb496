"""Render the kernels of ``derivations/kernels_spec.py`` into ``generated/``.

Pipeline: per kernel, build the explicit sympy outputs from the formula functions (main
build and per-sample branches), hash them (before any rewrite or printing), rewrite and CSE
them (:mod:`.optimise`): :func:`compile_kernel`; then every registered package target
(:mod:`rigidsym.codegen.backends`: NumPy, the extension's C, PyTorch, JAX) prints the
compiled kernels into its templates, and the generator merges their files with
``kernels.json``. :func:`generate` returns ``{relative path: text}``; :func:`write` writes
it atomically and removes orphans; :func:`check` compares it with the disk and returns a
unified diff (both in :mod:`rigidsym.codegen.files`, re-exported here). With ``stored``, a
kernel whose inputs are unchanged comes from the store of derived kernels
(:mod:`rigidsym.codegen.inputs`) and each one derived is stored as it finishes; every kernel
derived counts one ``derive`` (:mod:`rigidsym.core.work`).
"""

from __future__ import annotations

import importlib
import json
import os
import pickle
import textwrap
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

import sympy as sp

import rigidsym
from rigidsym.codegen import inputs
from rigidsym.codegen.accuracy.cos_form import choose as choose_cos
from rigidsym.codegen.accuracy.float32 import plan_kernel
from rigidsym.codegen.accuracy.rewrites import Chosen, improve
from rigidsym.codegen.backends import RenderContext, targets
from rigidsym.codegen.derivatives.vjp import jacobian_program
from rigidsym.codegen.files import check, write
from rigidsym.codegen.optimise import Program, compile_program, math_hash, trig_split
from rigidsym.codegen.removable.singularities import rewrite as removable
from rigidsym.codegen.spec import Kernel, flat_symbols, input_symbols
from rigidsym.codegen.spec import flatten_outputs as _flatten
from rigidsym.core import kinds as _kinds
from rigidsym.core.config import KERNEL_SPEC as BOOK_ORIGIN
from rigidsym.core.config import generated_dir
from rigidsym.core.errors import BadInput
from rigidsym.core.work import count

__all__ = ["generate", "render", "write", "check", "GenerationResult", "default_out_dir",
           "TEMPLATES"]

#: the template folders of the built-in package targets (file names unique across them)
TEMPLATES = tuple(dict.fromkeys(t.template_dir for t in targets(package=True)))


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
    """One kernel compiled for printing, what every code-generation target renders from.

    Attributes:
        kernel: its declaration (:class:`rigidsym.codegen.spec.Kernel`).
        variants: its straight-line programs, the branches first, then the main one.
        hash: the digest of its mathematics, written in its files.
        ops: the operation count of its programs, summed over the variants.
        inputs: ``[(argument, [the argument's scalar symbols])]`` in argument order.
        rewrites: the accuracy rewrites kept (:mod:`rigidsym.codegen.accuracy.rewrites`).
        plan32: the float32 precision plans (:mod:`rigidsym.codegen.accuracy.float32`).
    """

    kernel: Kernel
    variants: list[Variant]
    hash: str
    ops: int
    inputs: list = field(default_factory=list)   # [(arg, [symbols])]
    rewrites: list = field(default_factory=list)  # accuracy rewrites kept (accuracy.rewrites)
    plan32: dict = field(default_factory=dict)   # float32 precision plans (accuracy.float32)


class PackedKernelCode(KernelCode):
    """A :class:`KernelCode` whose files a pool worker rendered: its ``variants`` and
    ``plan32`` came back pickled and are unpickled on first use (rebuilding the sympy
    programs was 7 % of a cold generation's CPU, for programs the parent no longer prints).
    """

    def __init__(self, kernel: Kernel, packed: bytes, hash: str, ops: int, inputs: list,
                 rewrites: list):
        self.kernel, self.hash, self.ops = kernel, hash, ops
        self.inputs, self.rewrites = inputs, rewrites
        self._packed = packed
        self._unpacked: tuple | None = None

    def _unpack(self) -> tuple:
        if self._unpacked is None:
            self._unpacked = pickle.loads(self._packed)
        return self._unpacked

    @property
    def variants(self) -> list[Variant]:  # type: ignore[override]
        """The kernel's programs (:attr:`KernelCode.variants`)."""
        return self._unpack()[0]

    @property
    def plan32(self) -> dict:  # type: ignore[override]
        """The float32 precision plans (:attr:`KernelCode.plan32`)."""
        return self._unpack()[1]


@dataclass
class GenerationResult:
    """A generation: ``files`` (relative path -> text), the compiled ``kernels`` (sorted by
    name) and ``kernel_files``, each kernel's files of the package targets rendered apart
    (``{(target name, kernel name): {path: text}}``; :func:`render` takes them again)."""

    files: dict[str, str]
    kernels: list[KernelCode]
    kernel_files: dict = field(default_factory=dict)


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
#: the origin whose package files the workers render (``[None]``: compile only)
_RENDER: list = [None]


def _compile_group(group: tuple[int, ...]) -> list:
    """One job of the pool: the kernels ``group`` of ``_TODO`` compiled and, when
    ``_RENDER[0]`` names an origin, each one's files of the package targets rendered here
    too (:func:`_kernel_files`), so that the parent only merges them."""
    out = []
    for i in group:
        kc = compile_kernel(_TODO[i], _PLAN32[0])
        if _RENDER[0] is None:
            out.append((i, (kc.variants, kc.hash, kc.ops, kc.inputs, kc.rewrites,
                            kc.plan32), None))
        else:   # the programs packed: the parent reads the files, not the programs
            packed = pickle.dumps((kc.variants, kc.plan32), pickle.HIGHEST_PROTOCOL)
            out.append((i, (packed, kc.hash, kc.ops, kc.inputs, kc.rewrites),
                        _kernel_files(kc, _RENDER[0])))
    return out


def _context(done: list, metas: list, origin: str, memo: dict | None = None) -> RenderContext:
    ver = {"sympy": sp.__version__, "rigidsym": rigidsym.__version__}
    return RenderContext(done, metas, ver, origin,
                         header=lambda kc, t: _header(kc, t, origin), meta=_meta,
                         memo={} if memo is None else memo)


def _kernel_files(kc: KernelCode, origin: str) -> dict:
    """``{(target name, kernel name): {path: text}}``: the files of ``kc`` for every package
    target that renders a kernel apart (``Target.render_kernel``), rendered in a worker
    (the targets share one memo per kernel, as in one generation)."""
    ctx = _context([], [], origin)
    return {(t.name, kc.kernel.name): t.render_kernel(ctx, kc)
            for t in targets(package=True) if t.render_kernel is not None}


def _groups(todo: list[Kernel]) -> list[tuple[int, ...]]:
    """The indices of ``todo`` in the pool's jobs: a kernel with its ``_with_jacobians``
    twin in one job, the kernel first (so that the twin reads the float32 plan's regime
    points the kernel drew, as one process does:
    :func:`rigidsym.codegen.accuracy.points.regime_inputs`), the jobs with a twin first,
    the kernels of more input and output scalars first among them (the long jobs first:
    the two workers finish together)."""
    at: dict[str, list[int]] = {}
    for i, k in enumerate(todo):
        at.setdefault(k.name.removesuffix("_with_jacobians"), []).append(i)
    groups = [tuple(sorted(ix, key=lambda i: todo[i].name)) for ix in at.values()]

    def size(g) -> tuple:
        k = todo[g[-1]]
        return (-len(g), -sum(a.size for a in k.args) * sum(o.size for o in k.outputs), g)
    return sorted(groups, key=size)


def _compile_all(todo: list, plan32: bool = True, render: str | None = None,
                 finished=None) -> tuple:
    """Compile kernels, over two forked workers when there are many (same result, in
    order); ``render``: the origin whose package files the workers also render (see
    :func:`_kernel_files`). Returns ``(kernels, files)``, ``files`` the workers' rendered
    files (``{}`` when compiled here). ``finished(group, parts, files)``, when given, is
    called in this process as each group of :func:`_groups` is done (``parts``: ``{index:
    (packed programs, hash, ops, inputs, rewrites)}``; ``render`` is then required): the
    store keeps it before the next one ends."""
    jobs = min(2, os.cpu_count() or 1)
    serial = len(todo) < 8 or jobs < 2 or os.environ.get("RIGIDSYM_GENERATE_JOBS") == "1"
    if serial and finished is None:
        done = [compile_kernel(k, plan32) for k in todo]
        for k in todo:
            count("derive", k.name)
        return done, {}
    import multiprocessing as mp

    _TODO[:] = todo
    _PLAN32[0] = plan32
    _RENDER[0] = render
    parts: dict = {}
    files: dict = {}

    def take(got: list) -> None:
        group_parts, group_files = {}, {}
        for i, part, rendered in got:
            count("derive", todo[i].name)
            group_parts[i] = part
            group_files.update(rendered or {})
        if finished is not None:
            finished(tuple(sorted(group_parts)), group_parts, group_files)
        parts.update(group_parts)
        files.update(group_files)
    try:
        if serial:
            for group in _groups(todo):
                take(_compile_group(group))
        else:
            from rigidsym.core.interrupts import for_worker

            with mp.get_context("fork").Pool(jobs, initializer=for_worker) as pool:
                for got in pool.imap_unordered(_compile_group, _groups(todo), chunksize=1):
                    take(got)
    finally:
        _TODO.clear()
        _PLAN32[0] = True
        _RENDER[0] = None
    return [(KernelCode if render is None else PackedKernelCode)(k, *parts[i])
            for i, k in enumerate(todo)], files


def compile_many(kernels: list[Kernel], plan32: bool = True) -> list[KernelCode]:
    """``kernels`` and their Jacobian twins (sorted by name), compiled to programs
    (``plan32=False``: without the float32 precision plans of the package's kernels)."""
    return _compile_all(_with_jacobian_kernels(sorted(kernels, key=lambda k: k.name)),
                        plan32)[0]


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


def _with_jacobian_kernels(todo: list[Kernel]) -> list[Kernel]:
    """``todo`` and, for each smooth kernel, its ``<name>_with_jacobians`` (sorted by name).

    The Jacobian kernels are ordinary (non-public) kernels with extra outputs, so they go
    through the same rewrite, CSE, templates and checks as the values.
    """
    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels

    return sorted(todo + jacobian_kernels(todo), key=lambda k: k.name)


def generate(kernels=None, origin: str = BOOK_ORIGIN, *, stored: bool = False,
             only: list[str] | None = None,
             progress: Callable[[int, int], None] | None = None) -> GenerationResult:
    """Render every kernel; returns the files (relative path -> text) and the compiled kernels.

    ``kernels`` defaults to the book's; a user module's kernels come with ``origin`` (the
    module's name, written in the headers) and sources already named, not imported here.
    ``stored``: take each kernel whose inputs are unchanged from the store
    (:mod:`rigidsym.codegen.inputs`) and keep each kernel derived there as it finishes (the
    same files as without). ``only`` (kernel names, with ``stored``): derive these kernels
    (and their ``_with_jacobians``) even when stored, and every other one from the store.
    ``progress(done, total)``, when given, is called in this process as each group of
    kernels to derive is done (``total``: the kernels derived, not those read back).

    Raises:
        BadInput: ``only`` names no kernel, or another kernel is not in the store.
    """
    kernels_are_book = kernels is None
    if kernels is None:  # by name: the generator imports no book
        kernels = importlib.import_module(BOOK_ORIGIN).KERNELS
    todo = _with_jacobian_kernels(sorted(kernels, key=lambda k: k.name))
    if stored:
        done, rendered = _derive_stored(todo, origin, only, progress)
    else:
        said = [0]

        def finished(group: tuple, parts: dict, files: dict) -> None:
            said[0] += len(group)
            progress(said[0], len(todo))
        done, rendered = _compile_all(todo, render=origin,
                                      finished=None if progress is None else finished)
    return render(done, rendered, origin, kernels_are_book)


def render(done: list[KernelCode], rendered: dict, origin: str = BOOK_ORIGIN,
           book: bool = True) -> GenerationResult:
    """The files of a generation of the compiled kernels ``done`` (sorted by name):
    ``rendered`` holds each kernel's files of the package targets rendered already
    (``{(target name, kernel name): {path: text}}``), the rest are rendered here; ``book``:
    with the measured accuracy (read now) and ``inputs.json``."""
    metas = [_meta(kc) for kc in done]
    if book:
        acc = _accuracy_data()
        for m in metas:
            m["accuracy"] = acc.get(m["name"])
    ver = {"sympy": sp.__version__, "rigidsym": rigidsym.__version__}
    ctx = _context(done, metas, origin,
                   {("kernel files", *key): got for key, got in rendered.items()})
    files: dict[str, str] = {}
    for target in targets(package=True):
        got = target.render(ctx)
        clash = sorted(files.keys() & got.keys())
        if clash:
            raise ValueError(f"target {target.name} writes {clash[0]}, written by another")
        files.update(got)
    files["kernels.json"] = json.dumps({"generator": ver, "kernels": metas},
                                       indent=1, sort_keys=True) + "\n"
    if book:
        # what the default test run compares instead of generating again
        files[inputs.MANIFEST] = inputs.render(files)
    return GenerationResult(dict(sorted(files.items())), done, rendered)


def _derive_stored(todo: list[Kernel], origin: str, only: list[str] | None,
                   progress: Callable[[int, int], None] | None = None) -> tuple:
    """``(kernels, files)`` as :func:`_compile_all` returns them with ``render=origin``: each
    group whose key the store holds loaded, the others derived and stored one by one as
    they finish (an interrupt keeps every stored one; :func:`rigidsym.core.interrupts.line`
    says how many)."""
    from rigidsym.core import interrupts

    groups = [[todo[i] for i in g] for g in _groups(todo)]
    if only is not None:
        unknown = sorted(set(only) - {k.name for k in todo})
        if unknown:
            raise BadInput(f"--kernel {unknown[0]}: no such kernel")
        wanted = {n.removesuffix("_with_jacobians") for n in only}
    keys = [inputs.kernel_key(g, origin) for g in groups]
    interrupts.note_kept(partial(inputs.kept, {d: len(g) for d, g in zip(
        keys, groups, strict=True)}), len(todo), "kernels")
    kept: dict[str, tuple] = {}
    derive: list[Kernel] = []
    where: dict[str, str] = {}
    for g, digest in zip(groups, keys, strict=True):
        forced = only is not None and g[0].name.removesuffix("_with_jacobians") in wanted
        entry = None if forced else inputs.load_entry(digest)
        if entry is None:
            derive += g
            where.update((k.name, digest) for k in g)
        else:
            kept.update((e[0], e[1:]) for e in entry)
    if only is not None:
        missing = sorted(k.name for k in derive
                         if k.name.removesuffix("_with_jacobians") not in wanted)
        if missing:
            raise BadInput(f"{len(missing)} other kernels are not stored ({missing[0]}, ...): "
                           f"run `rigidsym generate` without --kernel first")

    def finished(group: tuple, parts: dict, files: dict) -> None:
        names = [derive[i].name for i in group]
        inputs.save_entry(where[names[0]], [
            (n, *parts[i], {tk: f for tk, f in files.items() if tk[1] == n})
            for i, n in zip(group, names, strict=True)])
        kept.update((n, (*parts[i], {tk: f for tk, f in files.items() if tk[1] == n}))
                    for i, n in zip(group, names, strict=True))
        if progress is not None:
            progress(sum(k.name in kept for k in derive), len(derive))
    if derive:
        _compile_all(derive, render=origin, finished=finished)
    done, rendered = [], {}
    for k in todo:
        *part, files = kept[k.name]
        done.append(PackedKernelCode(k, *part))
        rendered.update(files)
    return done, rendered


#: the measured accuracy of the book's kernels (benchmarks/accuracy.py --data), shipped in
#: kernels.json for ``kernels.accuracy``; beside the kernel declarations, loaded by name
ACCURACY_DATA = "kernels_accuracy.json"


def _accuracy_data() -> dict:
    from importlib.resources import files

    path = files(BOOK_ORIGIN.rsplit(".", 1)[0]).joinpath(ACCURACY_DATA)
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
