"""What the PyTorch and JAX targets share: a kernel's optimised program, printed
into ``array_kernel.py.j2`` (this package's ``templates/``) by the target's printer.

Each target's file holds the kernel's straight-line program(s) exactly as the NumPy and C
kernels print them (the same :class:`~rigidsym.codegen.optimise.Program` objects of the
compiled kernel, rewrites included), printed by the target's visitor printer
(:mod:`rigidsym.codegen.backends.torch.printer`,
:mod:`rigidsym.codegen.backends.jax.printer`): one function per variant taking one array per
scalar input component and returning ``(outputs, denominators)``, and one condition function per
branch. Validation, broadcasting, branch selection (with the safe-``where`` idiom) and the
derivatives live in the runtime (:mod:`rigidsym.kernels.torch`, :mod:`rigidsym.kernels.jax`),
so that the generated files stay small and cheap to print.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import sympy as sp

from rigidsym.codegen.backends import kernel_files, shared_environment
from rigidsym.codegen.backends.printing import ARRAY_SOURCE, is_compensated, uses_diffprod
from rigidsym.codegen.derivatives.jacobians import has_jacobian
from rigidsym.codegen.derivatives.vjp import (
    cotangent_names,
    jvp_program,
    tangent_names,
    vjp_program,
)

__all__ = ["TEMPLATES", "render_array_kernel", "array_kernel_files", "render_array_target",
           "hoist_compensated", "JAX_TRIG_SOURCE", "JAX_KEEP_SOURCE"]

#: the template both targets print into
TEMPLATES = Path(__file__).parent / "templates"

#: the JAX programs' sine and cosine (KernelJaxPrinter prints ``_sin``, ``_cos``): XLA on the
#: CPU fuses an elementwise sine into every consumer, so each output of a program and each
#: gradient computed it again (jit value + gradient of rotation_from_natural_invariants 2x
#: a hand-written Rodrigues formula at N = 1e3, a pattern 3x slower at 1e5), but no
#: producer into a dot: the pair is multiplied by the identity there (exact: x 1 + y 0),
#: and the consumers read it once computed
JAX_TRIG_SOURCE = '''

def _sincos(x):
    sc = jax.numpy.stack([jax.numpy.sin(x), jax.numpy.cos(x)], -1)
    if jax.default_backend() == "cpu":
        sc = sc @ jax.numpy.eye(2, dtype=sc.dtype)
    return sc


def _sin(x):
    return _sincos(x)[..., 0]


def _cos(x):
    return _sincos(x)[..., 1]
'''


#: the JAX programs' named compensated sums (``xc0 = _keep(_sumprod(...))``,
#: :func:`hoist_compensated`): XLA on the CPU fused the ~65 operations of the compensated
#: pitch of instant_screw_axis into each of the 6 fusions reading it (jit value + gradient
#: 2.2-2.6x a hand-written formula at N = 1e3 on one core); through a dot, as the
#: ``_sincos`` pair, it is computed once (exact: x 1 + (-0) 0 = x; XLA's CPU code flushes
#: subnormals wherever it computes). ``jax.lax.optimization_barrier`` does not stop it: XLA
#: removes it before fusion
JAX_KEEP_SOURCE = '''

def _keep(x):
    if jax.default_backend() == "cpu":
        pair = jax.numpy.stack([x, jax.numpy.full_like(x, -0.0)], -1)
        x = (pair @ jax.numpy.eye(2, dtype=x.dtype))[..., 0]
    return x
'''


def _variant(v: Any, printer) -> dict:
    p = v.program
    return {"name": v.name,
            "cond": None if v.cond is None else printer.doprint(v.cond),
            "temps": _lines(printer, p.temps, [*p.outputs, *p.dens]),
            "outputs": [printer.doprint(e) for e in p.outputs],
            "dens": [printer.doprint(e) for e in p.dens]}


def _calls_trig(variants: list, back: dict | None) -> bool:
    texts = [e for v in variants for e in [*(e for _, e in v["temps"]), *v["outputs"],
                                             *v["dens"], v["cond"] or ""]]
    if back is not None:
        texts += [e for _, e in back["temps"] + back["ttemps"]]
        texts += back["outputs"] + back["toutputs"]
    return any("_sin(" in t or "_cos(" in t for t in texts)


def _saved(program, vjp, hoisted: dict) -> list[str]:
    """The forward temps the reverse-mode program reads (it recomputes them from the
    inputs), then the compensated sums it reads (``hoisted``: named by
    :func:`hoist_compensated`): the PyTorch forward returns them for autograd to save, and
    ``_vjp_saved`` takes them instead of recomputing them (the backward reuses the
    forward's common subexpressions)."""
    fwd = {str(s) for s, _ in program.temps}
    nodes = _compensated([e for _, e in vjp.temps] + list(vjp.outputs))
    saved = [str(s) for s, _ in vjp.temps if str(s) in fwd]
    return saved + [hoisted[n] for n in nodes if n in hoisted and hoisted[n] not in saved]


def _compensated(exprs: list) -> list:
    """The compensated nodes (``DiffProd``, ``SumProd``) of ``exprs``, in order of first
    appearance."""
    seen: dict = {}
    for e in exprs:
        for n in sp.preorder_traversal(sp.sympify(e)):
            if is_compensated(n):
                seen.setdefault(n, None)
    return list(seen)


def hoist_compensated(program) -> dict:
    """``{node: name}``: each compensated sum of the forward ``program`` named ``xc<i>``.
    The printers print a named node as its name (``KernelPrinterMixin.named``) and
    :func:`_lines` computes it once, just before its first reader; the expressions stay
    as they are, so every other term prints in the same order, and values and gradients
    stay bit for bit. Why (the first compile of ``instant_screw_axis``): the VJP
    reads the compensated pitch (``_sumprod``, ~65 operations) that the forward computes;
    named, the forward saves it and the VJP takes it instead of computing it again. Empty
    where a node holds another (not printed by one name then). A node that is a temp's whole
    expression keeps that temp's name."""
    nodes = _compensated([e for _, e in program.temps] + list(program.outputs))
    if any(m is not n and m.has(n) for m in nodes for n in nodes):
        return {}
    whole = {e: str(s) for s, e in program.temps}
    return {n: whole.get(n, f"xc{i}") for i, n in enumerate(nodes)}


def _lines(pr, temps: list, outputs: list) -> list[tuple[str, str]]:
    """The printed assignments of ``temps``, each named compensated node of ``pr.named``
    that they or ``outputs`` read assigned once just before its first reader."""
    out: list = []
    todo = dict(pr.named)

    def place(expr) -> None:
        for n in [n for n in todo if sp.sympify(expr).has(n)]:
            out.append((todo.pop(n), pr.named_call(n)))

    for s, e in temps:
        if todo.get(e) == str(s):  # the temp is the node: computed there
            del todo[e]
            out.append((str(s), pr.named_call(e)))
            continue
        place(e)
        out.append((str(s), pr.doprint(e)))
    for o in outputs:
        place(o)
    return out


def _kept_tangents(program, lines: list, backend: str) -> list:
    """JAX: the printed JVP with the tangent of each denominator that is a temp (``_d<k>``
    of temp ``k``: a norm every output reads through a quotient) through ``_keep``. Its
    transpose then sums the denominator's cotangent once: XLA had fused that sum of every
    output's contribution into each input's cotangent column (instant_screw_axis, one
    core, N = 1e3: jit value + gradient 1.12-1.21x -> 0.89x a hand-written formula in
    float32, 0.96-1.00x -> 0.76x in float64; keeping every tangent: 1.22x). Only
    a denominator of two input columns or more."""
    if backend != "jax":
        return lines
    dens, defs = {sp.sympify(d) for d in program.dens}, dict(program.temps)
    seen: dict = {}

    def inputs(x) -> set:  # the input columns temp x reads, through other temps (memoised:
        # shared temps would otherwise be walked once per path)
        if x not in seen:
            seen[x] = set().union(*(inputs(s) if s in defs else {s}
                                    for s in defs[x].free_symbols))
        return seen[x]

    # a denominator of one input column has one cotangent column to feed: nothing to share
    # (L_tilde, N_matrix: 2-10 % slower with the dot)
    keep = {f"_d{k}" for k, (x, _) in enumerate(program.temps)
            if x in dens and len(inputs(x)) >= 2}
    return [(s, f"_keep({e})" if s in keep else e) for s, e in lines]


def _derivatives(kc: Any, memo: dict) -> tuple:
    """The reverse- and forward-mode programs of ``kc`` and its hoisted compensated sums
    (``(None, None, {})`` without a generated Jacobian), computed once per kernel for both
    targets (``memo``: the generation's shared cache)."""
    key = ("array derivatives", kc.kernel.name)
    if key not in memo:
        vjp = jvp = None
        hoisted: dict = {}
        # the backward of a kernel with a generated Jacobian (one formula, no branches):
        # reverse mode over its optimised program
        if has_jacobian(kc.kernel) and len(kc.variants) == 1:
            ins = [s for _, syms in kc.inputs for s in syms]
            vjp = vjp_program(kc.variants[0].program, ins)
            jvp = jvp_program(kc.variants[0].program, ins)
            hoisted = hoist_compensated(kc.variants[0].program)
        memo[key] = (vjp, jvp, hoisted)
    return memo[key]


def render_array_kernel(env, kc: Any, header, backend: str, module: str, printer,
                        memo: dict) -> dict[str, str]:
    """``{"<backend>/<name>.py": text}``: the compiled kernel ``kc`` for one array target.

    Args:
        env: a Jinja2 environment over :data:`TEMPLATES`.
        kc: a :class:`rigidsym.codegen.generator.KernelCode`.
        header: ``header(kc, template) -> [lines]``, the generator's file header.
        backend: the target's name and folder (``"torch"``, ``"jax"``).
        module: the array module the printed code names (``"torch"``, ``"jax.numpy"``).
        printer: the target's printer of kernel programs (a new one).
        memo: the generation's cache shared by the targets (the derivatives' programs).
    """
    t = "array_kernel.py.j2"
    columns = [str(s) for _, syms in kc.inputs for s in syms]
    vjp, jvp, hoisted = _derivatives(kc, memo)
    pr = printer
    pr.named = hoisted
    # branches first, in order, then main (the order of the NumPy kernel's selection)
    variants = [_variant(v, pr) for v in kc.variants]
    back = None if vjp is None else {
        "args": columns + cotangent_names(len(kc.variants[0].program.outputs)),
        "temps": _lines(pr, vjp.temps, vjp.outputs),
        "saved": _saved(kc.variants[0].program, vjp, hoisted),
        "outputs": [pr.doprint(e) for e in vjp.outputs], "ops": vjp.ops,
        "targs": columns + tangent_names(len(columns)),
        "ttemps": _kept_tangents(kc.variants[0].program, _lines(pr, jvp.temps,
                                                                jvp.outputs), backend),
        "toutputs": [pr.doprint(e) for e in jvp.outputs], "tops": jvp.ops}
    helpers = [ARRAY_SOURCE.strip("\n").replace("{module}", module)] if \
        uses_diffprod(kc) else []
    if backend == "jax" and _calls_trig(variants, back):
        helpers.append(JAX_TRIG_SOURCE.strip("\n"))
    kept = back is not None and any(e.startswith("_keep(") for _, e in back["ttemps"])
    if backend == "jax" and (hoisted or kept):
        helpers.append(JAX_KEEP_SOURCE.strip("\n"))
    return {f"{backend}/{kc.kernel.name}.py": env.get_template(t).render(
        header=header(kc, t), backend=backend, module=module, k=kc.kernel, ops=kc.ops,
        hash=kc.hash, columns=columns, variants=variants, vjp=back,
        divides=bool(kc.variants[0].program.dens), helpers="\n\n\n".join(helpers))}


def array_kernel_files(ctx, kc: Any, backend: str, module: str, printer) -> dict[str, str]:
    """:func:`render_array_kernel` of ``kc`` in the generation ``ctx`` (a
    :class:`rigidsym.codegen.backends.RenderContext`: its shared environment, header and
    memo), printed by a new ``printer()``: an array target's ``render_kernel``."""
    return render_array_kernel(shared_environment(TEMPLATES), kc, ctx.header, backend,
                               module, printer(), ctx.memo)


def render_array_target(ctx, target) -> dict[str, str]:
    """An array target's files of a generation (``{"<backend>/<kernel>.py": text}``): every
    compiled kernel of ``ctx`` (a :class:`rigidsym.codegen.backends.RenderContext`) through
    :func:`rigidsym.codegen.backends.kernel_files` (``target.render_kernel``, or what a
    worker of the generator rendered with it)."""
    files: dict[str, str] = {}
    for kc in ctx.kernels:
        files.update(kernel_files(ctx, target, kc))
    return files
