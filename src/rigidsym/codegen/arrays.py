"""The PyTorch and JAX programs of a kernel (issue 31): the optimised program, printed.

Each back-end file holds the kernel's straight-line program(s) exactly as the NumPy and C
kernels print them (the same :class:`~rigidsym.codegen.optimise.Program` objects of the
compiled kernel, rewrites included), printed by the visitor printers of
:mod:`rigidsym.codegen.printers`: one function per variant taking one array per scalar
input component and returning ``(outputs, denominators)``, and one condition function per
branch. Validation, broadcasting, branch selection (with the safe-``where`` idiom) and the
derivatives live in the runtime (:mod:`rigidsym.kernels.torch`, :mod:`rigidsym.kernels.jax`),
so that the generated files stay small and cheap to print.
"""

from __future__ import annotations

from typing import Any

from rigidsym.codegen.compensated import ARRAY_SOURCE
from rigidsym.codegen.jacobians import has_jacobian
from rigidsym.codegen.printers import KernelJaxPrinter, torch_printer
from rigidsym.codegen.vjp import cotangent_names, jvp_program, tangent_names, vjp_program

__all__ = ["BACKENDS", "render_array_kernels"]

#: back-end -> (folder, module the printed code names)
BACKENDS = {"torch": "torch", "jax": "jax.numpy"}

#: the JAX programs' sine and cosine (KernelJaxPrinter prints ``_sin``, ``_cos``): XLA on the
#: CPU fuses an elementwise sine into every consumer, so each output of a program and each
#: gradient computed it again (jit value + gradient of rotation_from_natural_invariants 2x
#: a hand-written Rodrigues formula at N = 1e3, a pattern 3x slower at 1e5), but no
#: producer into a dot: the pair is multiplied by the identity there (exact: x 1 + y 0),
#: and the consumers read it once computed (issue 38)
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


def _printer(backend: str):
    return torch_printer() if backend == "torch" else KernelJaxPrinter()


def _variant(v: Any, printer) -> dict:
    p = v.program
    return {"name": v.name,
            "cond": None if v.cond is None else printer.doprint(v.cond),
            "temps": [(str(s), printer.doprint(e)) for s, e in p.temps],
            "outputs": [printer.doprint(e) for e in p.outputs],
            "dens": [printer.doprint(e) for e in p.dens]}


def _calls_trig(variants: list, back: dict | None) -> bool:
    texts = [e for v in variants for e in [*(e for _, e in v["temps"]), *v["outputs"],
                                             *v["dens"], v["cond"] or ""]]
    if back is not None:
        texts += [e for _, e in back["temps"] + back["ttemps"]]
        texts += back["outputs"] + back["toutputs"]
    return any("_sin(" in t or "_cos(" in t for t in texts)


def _saved(program, vjp) -> list[str]:
    """The forward temps the reverse-mode program reads (it recomputes them from the
    inputs): the PyTorch forward returns them for autograd to save, and ``_vjp_saved``
    takes them instead of recomputing them (issue 38: the backward reuses the forward's
    common subexpressions)."""
    fwd = {str(s) for s, _ in program.temps}
    return [str(s) for s, _ in vjp.temps if str(s) in fwd]


def render_array_kernels(env, kc: Any, header) -> dict[str, str]:
    """``{"torch/<name>.py": text, "jax/<name>.py": text}`` for the compiled kernel ``kc``.

    Args:
        env: the generator's Jinja2 environment.
        kc: a :class:`rigidsym.codegen.generator.KernelCode`.
        header: ``header(template) -> [lines]``, the generator's file header.
    """
    from rigidsym.codegen.compensated import uses_diffprod

    t = "array_kernel.py.j2"
    columns = [str(s) for _, syms in kc.inputs for s in syms]
    # the backward of a kernel with a generated Jacobian (one formula, no branches): reverse
    # mode over its optimised program (issue 38)
    vjp = jvp = None
    if has_jacobian(kc.kernel) and len(kc.variants) == 1:
        ins = [s for _, syms in kc.inputs for s in syms]
        vjp = vjp_program(kc.variants[0].program, ins)
        jvp = jvp_program(kc.variants[0].program, ins)
    files = {}
    for backend, module in BACKENDS.items():
        pr = _printer(backend)
        # branches first, in order, then main (the order of the NumPy kernel's selection)
        variants = [_variant(v, pr) for v in kc.variants]
        back = None if vjp is None else {
            "args": columns + cotangent_names(len(kc.variants[0].program.outputs)),
            "temps": [(str(s), pr.doprint(e)) for s, e in vjp.temps],
            "saved": _saved(kc.variants[0].program, vjp),
            "outputs": [pr.doprint(e) for e in vjp.outputs], "ops": vjp.ops,
            "targs": columns + tangent_names(len(columns)),
            "ttemps": [(str(s), pr.doprint(e)) for s, e in jvp.temps],
            "toutputs": [pr.doprint(e) for e in jvp.outputs], "tops": jvp.ops}
        helpers = [ARRAY_SOURCE.strip("\n").replace("{module}", module)] if \
            uses_diffprod(kc) else []
        if backend == "jax" and _calls_trig(variants, back):
            helpers.append(JAX_TRIG_SOURCE.strip("\n"))
        files[f"{backend}/{kc.kernel.name}.py"] = env.get_template(t).render(
            header=header(t), backend=backend, module=module, k=kc.kernel, ops=kc.ops,
            hash=kc.hash, columns=columns, variants=variants, vjp=back,
            divides=bool(kc.variants[0].program.dens), helpers="\n\n\n".join(helpers))
    return files
