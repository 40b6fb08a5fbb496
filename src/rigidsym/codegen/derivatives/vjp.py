"""The vector-Jacobian product of a kernel's program, by reverse mode.

For a straight-line :class:`~rigidsym.codegen.optimise.Program` (``x_k = e_k(inputs,
x_<k)``, then ``y_i = o_i(...)``) and one cotangent symbol ``_g{i}`` per output, the adjoint
of every temp is accumulated in reverse order from the local derivatives of its uses (sympy
differentiates each small ``e_k`` and ``o_i`` alone, never the whole formula), and the
program returns the cotangent of every input component: ``sum_i g_i d y_i / d u``. The
forward's temps are reused (a local derivative that recomputes a temp's own expression,
``1/(2 sqrt x3)`` where ``x4 = sqrt(x3)``, names the temp instead), and temps no adjoint
needs are dropped, so the backward costs a small multiple of the forward, whatever the
number of outputs and inputs: not the whole Jacobian then a product.

The result is plain arithmetic in the inputs and cotangents (a second derivative is autograd
through it), and it equals the contraction of the kernel's generated Jacobian (derived from
the declared formula; the programs differ by the half-angle rewrite, an identity): tested
against ``rigidsym.kernels.jacobian`` (tests/test_torch_kernels.py).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.optimise import Program, denominators

__all__ = ["vjp_program", "jvp_program", "jacobian_program", "cotangent_names", "tangent_names"]


def cotangent_names(n: int) -> list[str]:
    """The names of the cotangent arguments of a program with ``n`` outputs."""
    return [f"_g{i}" for i in range(n)]


def tangent_names(n: int) -> list[str]:
    """The names of the tangent arguments of a program with ``n`` input components."""
    return [f"_t{i}" for i in range(n)]


def jvp_program(program: Program, inputs: list[sp.Symbol]) -> Program:
    """The forward-mode program of ``program``: arguments ``inputs`` then the tangents
    ``tangent_names(len(inputs))``; outputs the tangent of each output, linear in the
    tangents (JAX transposes it for reverse mode). A temp's tangent is the sum of its local
    derivatives times its arguments' tangents; temps nothing reads are dropped."""
    tan = dict(zip(inputs, (sp.Symbol(n) for n in tangent_names(len(inputs))), strict=True))
    known: dict = {}  # only the temps defined so far: a tangent is computed in between
    body = []

    def d(expr) -> sp.Expr:
        terms = [_local(expr, s).xreplace(known) * tan[s]
                 for s in sorted(expr.free_symbols, key=sp.default_sort_key) if s in tan]
        return sp.Add(*terms)

    for k, (x, e) in enumerate(program.temps):
        body.append((x, e))
        known.update(_named([(x, e)]))
        dx = d(e)
        if dx != 0:
            tan[x] = sp.Symbol(f"_d{k}")
            body.append((tan[x], dx))
    outputs = [d(sp.sympify(o)) for o in program.outputs]
    body, outputs = _shared(body, outputs, "_d", "_e")
    kept = _live(body, outputs)
    ops = sum(int(sp.count_ops(v)) for _, v in kept) + sum(int(sp.count_ops(v))
                                                           for v in outputs)
    return Program(temps=kept, outputs=outputs, dens=[], ops=ops)


def _live(body: list, roots: list) -> list:
    """The assignments of ``body`` that ``roots`` read, directly or through others (dead
    code dropped), in their order."""
    need = set().union(*(sp.sympify(v).free_symbols for v in roots))
    kept = []
    for x, e in reversed(body):
        if x in need:
            kept.append((x, e))
            need |= e.free_symbols
    return kept[::-1]


def _shared(body: list, outputs: list, mine: str, prefix: str) -> tuple[list, list]:
    """``sympy.cse`` over the temps of ``body`` named ``mine...`` (the adjoints or
    tangents, each formed alone from its local derivatives: the same products recur across
    them, e.g. a cotangent times a forward temp in several adjoints) and the ``outputs``;
    each common subexpression (``prefix0``, ...) is placed just before its first reader, so
    every temp is still defined before it is read. Fewer operations: a fixed cost of a call
    in eager PyTorch, where each is one dispatch."""
    idx = [i for i, (x, _) in enumerate(body) if str(x).startswith(mine)]
    exprs = [body[i][1] for i in idx] + [sp.sympify(o) for o in outputs]
    reps, red = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
    if not reps:
        return body, outputs
    defs, order = dict(reps), {x: k for k, (x, _) in enumerate(reps)}
    placed: set = set()
    out: list = []

    def place(expr) -> None:
        for x in sorted(expr.free_symbols & defs.keys() - placed, key=order.__getitem__):
            if x not in placed:
                place(defs[x])
                placed.add(x)
                out.append((x, defs[x]))

    new = dict(zip(idx, red[:len(idx)], strict=True))
    for i, (x, e) in enumerate(body):
        e = new.get(i, e)
        place(e)
        out.append((x, e))
    outputs = list(red[len(idx):])
    for o in outputs:
        place(o)
    return out, outputs


def _named(temps: list) -> dict:
    """``{expression: temp}`` for the temps whose expression a derivative may recompute (a
    function call or a non-integer power)."""
    return {e: s for s, e in temps
            if isinstance(e, sp.Function) or (isinstance(e, sp.Pow) and not e.exp.is_Integer)}


def vjp_program(program: Program, inputs: list[sp.Symbol]) -> Program:
    """The reverse-mode program of ``program``: arguments ``inputs`` then the cotangents
    ``cotangent_names(len(program.outputs))``; outputs the cotangent of each input (0 where
    an input is unused); no denominators (the runtime masks the singular samples first).
    """
    gs = [sp.Symbol(n) for n in cotangent_names(len(program.outputs))]
    temps = list(program.temps)
    known = _named(temps)
    adj: dict = {}

    def use(expr, weight) -> None:
        for s in sorted(expr.free_symbols, key=sp.default_sort_key):
            d = _local(expr, s).xreplace(known)
            if d != 0:
                adj.setdefault(s, []).append(weight * d)

    for g, o in zip(gs, program.outputs, strict=True):
        use(sp.sympify(o), g)
    back = []
    for k, (x, e) in enumerate(reversed(temps)):
        terms = adj.pop(x, None)
        if not terms:
            continue
        b = sp.Symbol(f"_b{k}")
        back.append((b, sp.Add(*terms)))
        use(e, b)
    outputs = [sp.Add(*adj.get(s, [])) for s in inputs]
    back, outputs = _shared(back, outputs, "_b", "_c")
    # only the forward temps an adjoint or an output reads, in their order
    need = set().union(*(sp.sympify(v).free_symbols for _, v in back),
                       *(sp.sympify(v).free_symbols for v in outputs))
    fwd = []
    for x, e in reversed(temps):
        if x in need:
            fwd.append((x, e))
            need |= e.free_symbols
    body = fwd[::-1] + back
    ops = sum(int(sp.count_ops(v)) for _, v in body) + sum(int(sp.count_ops(v))
                                                           for v in outputs)
    return Program(temps=body, outputs=outputs, dens=[], ops=ops)


def jacobian_program(program: Program, args: list[list[sp.Symbol]],
                     sizes: list[int]) -> Program:
    """The program of the values and the full Jacobian of ``program``, by vector forward mode
    over its straight-line code (the SE(3) log's 6 x 16 Jacobian by sympy on the
    expanded formula took 516 s to generate). ``args``: each argument's flat symbols;
    ``sizes``: each (named) output's number of entries. Outputs ``program.outputs`` then, for
    each output ``o`` and argument ``a``, ``d o[i] / d a[j]`` (``i`` major), as
    :func:`rigidsym.codegen.derivatives.jacobians.with_jacobians` lays them out.

    Each temp carries its gradient, sparse in the inputs (sympy differentiates each small
    temp alone); every entry that is not a number or a symbol is a temp ``dx<k>_<j>``;
    ``dens`` are the values' and the local derivatives' denominators (a derivative singular
    where the value is not flags the sample)."""
    inputs = [s for a in args for s in a]
    body, grads = _forward(program, inputs)
    outputs = list(program.outputs)
    starts = [sum(len(a) for a in args[:k]) for k in range(len(args))]
    lo = 0
    for size in sizes:
        for a, j0 in zip(args, starts, strict=True):
            outputs += [g.get(j0 + j, sp.S.Zero) for g in grads[lo:lo + size]
                        for j in range(len(a))]
        lo += size
    nv = len(program.outputs)
    body, outs = _shared(body, outputs[nv:], "dx", "dc")
    outputs = outputs[:nv] + outs
    kept = _live(body, [*outputs, *program.dens])
    dens = list(program.dens)
    dens += [d for d in denominators([e for x, e in kept if str(x).startswith("d")] + outs)
             if d not in dens]
    ops = sum(int(sp.count_ops(v)) for _, v in kept) + sum(int(sp.count_ops(v))
                                                           for v in outputs)
    return Program(temps=kept, outputs=outputs, dens=dens, ops=ops)


def _forward(program: Program, inputs: list[sp.Symbol]) -> tuple[list, list[dict]]:
    """The temps of ``program`` each followed by its gradient's entries (``{input index:
    entry}``), and the gradient of each output."""
    known: dict = {}
    grad: dict = {s: {j: sp.S.One} for j, s in enumerate(inputs)}
    body = []

    def tangent(expr) -> dict:
        out: dict = {}
        for s in sorted(expr.free_symbols, key=sp.default_sort_key):
            d = _local(expr, s).xreplace(known) if grad.get(s) else 0
            for j, gj in (grad[s].items() if d != 0 else ()):
                out.setdefault(j, []).append(d * gj)
        return {j: sp.Add(*t) for j, t in sorted(out.items())}

    for k, (x, e) in enumerate(program.temps):
        body.append((x, e))
        known.update(_named([(x, e)]))
        grad[x] = {}
        for j, dj in tangent(e).items():
            if dj == 0:
                continue
            if not (dj.is_Atom or (dj.is_Mul and len(dj.args) == 2 and dj.args[0].is_Number
                                   and dj.args[1].is_Atom)):
                body.append((s := sp.Symbol(f"dx{k}_{j}"), dj))
                dj = s
            grad[x][j] = dj
    return body, [tangent(sp.sympify(o)) for o in program.outputs]


def _local(expr, s) -> sp.Expr:
    """``d expr / d s``; a root in it made a removable quotient where it is one (a value's
    ``cos(sqrt(x3))``, even in ``sqrt(x3)``, has the derivative ``-sin(sqrt(x3)) / (2
    sqrt(x3))``: singular at ``x3 = 0`` as printed, ``-rq_sinc(x3) / 2`` after
    :func:`rigidsym.codegen.removable.singularities.rewrite`)."""
    d = sp.diff(expr, s)
    if any(isinstance(p, sp.Pow) and not p.exp.is_Integer for p in sp.preorder_traversal(d)):
        from rigidsym.codegen.removable.singularities import rewrite

        d = rewrite([d])[0]
    return d
