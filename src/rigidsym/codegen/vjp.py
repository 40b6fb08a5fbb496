"""The vector-Jacobian product of a kernel's program, by reverse mode (issue 38, item 4).

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

from rigidsym.codegen.optimise import Program

__all__ = ["vjp_program", "cotangent_names"]


def cotangent_names(n: int) -> list[str]:
    """The names of the cotangent arguments of a program with ``n`` outputs."""
    return [f"_g{i}" for i in range(n)]


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
            d = sp.diff(expr, s).xreplace(known)
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
