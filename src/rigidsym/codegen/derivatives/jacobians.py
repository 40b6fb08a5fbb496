"""The Jacobian transform of a kernel spec: a kernel with the derivatives as extra outputs.

As SymForce's ``Codegen.with_jacobians``, :func:`with_jacobians` turns one spec into a second
spec, named ``<name>_with_jacobians``, that returns the values and, for each output ``o`` and
array input ``a``, the output ``o_D_a`` of per-sample shape ``o.shape + a.shape`` (the entry
``[i..., j...]`` is ``d o[i...] / d a[j...]``, the JAX convention). The derivatives are taken
by sympy on the **declared formula**, i.e. on what ``kernel.build`` returns, before the
generator's half-angle rewrite; the generator then rewrites and CSEs values and derivatives
as one program, so they share sub-expressions and the same rewrite.

Derivatives are in the ambient coordinates of each input (every component of a unit ``e``
or of a rotation ``Q`` is an independent variable); the tangent-space maps of the rotation
invariants are the book's N, L, H (3.76)-(3.77).

Kernels with per-sample branches are transformed only where they ask for it
(``Kernel.branch_jacobian``: the Lie logs and ``euler_rodrigues_from_rotation``).
Their branches agree on the constraint manifold only, so each branch is differentiated with
its value, under the same condition: the Jacobian kernel takes one branch per sample for
values and derivatives together, and returns the derivative of the very function the value
kernel computes there (finite differences of the kernel, ambient, agree with it). Along the
manifold (a rotation ``Q`` moved by ``Q Omega``, ``Omega`` skew) every branch gives the
derivative of the declared formula; normal to it (``Q S``, ``S`` symmetric), where no
rotation goes, each branch keeps its own extension's derivative.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.spec import Branch, Kernel, Out, flat_symbols

__all__ = ["with_jacobians", "jacobian_kernels", "has_jacobian", "jacobian_name",
           "derivative_name", "SUFFIX"]

#: name suffix of a kernel with Jacobians (as SymForce's generated names)
SUFFIX = "_with_jacobians"


def jacobian_name(kernel_name: str) -> str:
    """Name of the generated kernel that returns the values and Jacobians of ``kernel_name``."""
    return kernel_name + SUFFIX


def derivative_name(output: str, arg: str) -> str:
    """Name of the output ``d output / d arg`` (SymForce's ``<result>_D_<arg>``)."""
    return f"{output}_D_{arg}"


def has_jacobian(kernel: Kernel) -> bool:
    """Whether ``kernel`` asks for a Jacobian and is one smooth formula (no per-sample branch)
    or asks for its branches to be differentiated too (``branch_jacobian``)."""
    return kernel.jacobian and (not kernel.branches or kernel.branch_jacobian) and \
        not kernel.name.endswith(SUFFIX)


def _flat(value, out: Out) -> list[sp.Expr]:
    if out.shape == ():
        if isinstance(value, sp.MatrixBase):
            return [value[0, 0]]
        return [sp.sympify(value)]
    return list(sp.Matrix(value))          # row-major


def _shaped(entries: list[sp.Expr], shape: tuple[int, ...]):
    if shape == ():
        return entries[0]
    if len(shape) == 2:
        return sp.Matrix(shape[0], shape[1], entries)
    return sp.Matrix(entries)               # flat, row-major over ``shape``


def with_jacobians(kernel: Kernel) -> Kernel:
    """The spec returning ``kernel``'s outputs and their derivatives w.r.t. every input.

    Args:
        kernel: a kernel without branches, or one with ``branch_jacobian`` (see
            :func:`has_jacobian`): its branches are differentiated each with its value.

    Returns:
        A non-public :class:`~rigidsym.codegen.spec.Kernel` named
        ``jacobian_name(kernel.name)``: outputs ``kernel.outputs`` followed by
        ``derivative_name(o, a)`` of shape ``o.shape + a.shape`` for each output ``o`` and
        input ``a`` (output-major).

    Raises:
        ValueError: ``kernel`` has per-sample branches and no ``branch_jacobian`` (or is
            already a Jacobian kernel).
    """
    if not has_jacobian(kernel):
        raise ValueError(f"kernel: {kernel.name} has per-sample branches and no "
                         "branch_jacobian (or is already a Jacobian kernel); its ambient "
                         "derivative is not one formula")
    outs = list(kernel.outputs)
    for o in kernel.outputs:
        for a in kernel.args:
            outs.append(Out(derivative_name(o.name, a.name), o.shape + a.shape,
                            f"d {o.name} / d {a.name}, shape {o.shape} + {a.shape}"))

    singular = kernel.singular
    how = _by_program if kernel.jacobian_from == "program" else _differentiated
    branches = tuple(Branch(br.name, br.when, how(kernel, br.build), br.doc)
                     for br in kernel.branches)
    return Kernel(
        name=jacobian_name(kernel.name),
        summary=f"{kernel.summary.rstrip('.')}, with the Jacobians of its outputs.",
        formula=f"{kernel.formula}; and d(output)/d(input) by sympy on the declared formula",
        ids=kernel.ids, sources=kernel.sources, args=kernel.args, outputs=tuple(outs),
        build=how(kernel, kernel.build), singular=singular,
        singular_arg=kernel.singular_arg, branches=branches, notes=kernel.notes,
        public=False, jacobian=False, jacobian_from=kernel.jacobian_from, jacobian_of=kernel)


def _differentiated(kernel: Kernel, value_build):
    """A build returning ``value_build``'s outputs and their derivatives by every input."""
    def build(**syms):
        values = value_build(**syms)
        res = dict(values)
        # same names and assumptions as ``syms``: the same sympy symbols
        flat_in = dict(flat_symbols(kernel))
        for o in kernel.outputs:
            f = _flat(values[o.name], o)
            for a in kernel.args:
                xs = flat_in[a.name]
                # the declared formula, differentiated before any rewrite (row-major: output
                # index first, then input index)
                d = [sp.diff(fi, x) for fi in f for x in xs]
                res[derivative_name(o.name, a.name)] = _shaped(d, o.shape + a.shape)
        return res
    return build


def _by_program(kernel: Kernel, value_build):
    """As :func:`_differentiated`, the chain rule over the declared formula's common
    subexpressions (``sympy.cse``, each small temp differentiated by sympy alone:
    :func:`rigidsym.codegen.derivatives.vjp.jacobian_program`) instead of ``sympy.diff`` of
    the expanded tree; the same derivative, a graph of shared subexpressions (for the
    references: the generator differentiates its own optimised program,
    ``Kernel.jacobian_from``)."""
    from rigidsym.codegen.derivatives.vjp import jacobian_program
    from rigidsym.codegen.optimise import Program
    from rigidsym.codegen.spec import flatten_outputs

    def build(**syms):
        values = value_build(**syms)
        flat = flatten_outputs(kernel, values)
        temps, red = sp.cse(flat, symbols=sp.numbered_symbols("_v"), order="canonical")
        args = [xs for _, xs in flat_symbols(kernel)]
        p = jacobian_program(Program(list(temps), list(red), [], 0), args,
                             [o.size for o in kernel.outputs])
        env: dict = {}
        for x, e in p.temps:
            env[x] = e.xreplace(env)
        d = [sp.sympify(o).xreplace(env) for o in p.outputs[len(flat):]]
        res = dict(values)
        for o in kernel.outputs:
            for a in kernel.args:
                n = o.size * a.size
                res[derivative_name(o.name, a.name)] = _shaped(d[:n], o.shape + a.shape)
                d = d[n:]
        return res
    return build


def jacobian_kernels(kernels) -> list[Kernel]:
    """``with_jacobians(k)`` for every kernel of ``kernels`` that has a Jacobian."""
    return [with_jacobians(k) for k in kernels if has_jacobian(k)]

