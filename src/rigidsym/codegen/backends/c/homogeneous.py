"""Power-of-two rescaling of the C target's extreme inputs, where the formula allows it.

A kernel whose every output ``o`` is homogeneous in a set ``S`` of its arguments,
``o(2^k x_S, x_rest) = 2^(k d_o) o(x)``, can be evaluated at inputs whose magnitude would
make its intermediates overflow or underflow: scale the arguments of ``S`` by ``2^-e`` (``e``
the binary exponent of their largest component, so that it lands in [1/2, 1)), evaluate, and
scale each output back by ``2^(e d_o)``. Multiplying by a power of two is exact (unless a
component falls below the smallest normal number, a normwise relative change below the
type's smallest normal, far under its rounding unit), so the result is the kernel's
ordinary-range result, rounded once more only where it over- or underflows. This is the
rescue of the float functions (no wider type on a float-only FPU) and of the double
functions where ``long double`` is ``double`` (Cortex-M, Windows, macOS arm64).

The degrees are decided on the declaration's expressions (:func:`degree`), structurally and
exactly: a sum is homogeneous when its terms are, of one degree; a product adds degrees; a
rational power multiplies it; ``sin``, ``cos``, ``exp`` ... need an argument of degree 0;
``atan2(y, x)`` is of degree 0 when ``y`` and ``x`` share one (``2^k > 0``); anything else
(a ``Piecewise``, a branch) is not decided, and then the kernel is not rescaled (it keeps
``RIGIDSYM_C_EXTREME_INPUT``). Sound: a "homogeneous" answer is a proof of the identity for
every positive scale; "no" only costs a rescue.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

__all__ = ["degree", "rescale_steps", "SCALABLE"]

#: the argument kinds whose values may be scaled (a unit vector, a rotation or an angle may
#: not: its formula is not homogeneous in it)
SCALABLE = frozenset({"any"})


class _NotHomogeneous(Exception):
    pass


def degree(expr, scaled: set, env: dict | None = None) -> Fraction | None:
    """The degree of ``expr`` under ``x -> 2^k x`` of the symbols of ``scaled`` (the others
    fixed; a symbol of ``env``, a temporary of a program, has the degree given there);
    None for an expression that is exactly zero; raises ``ValueError`` where homogeneity is
    not shown."""
    memo: dict = {s: d for s, d in (env or {}).items()}
    try:
        return _deg(sp.sympify(expr), frozenset(scaled), memo)
    except _NotHomogeneous as exc:
        raise ValueError(str(exc)) from None


def _deg(e, S, memo) -> Fraction | None:
    """The degree, or None for an expression that is exactly zero (of every degree)."""
    if e in memo:
        return memo[e]
    if hasattr(e, "_eval_rewrite_as_Add"):      # the compensated a b - c d, sum of products
        d = _deg(e.rewrite(sp.Add), S, memo)
    elif e.is_Symbol:
        d = Fraction(1) if e in S else Fraction(0)
    elif e.is_Number or e.is_NumberSymbol:
        d = None if e == 0 else Fraction(0)
    elif e.is_Add:
        ds = {x for x in (_deg(a, S, memo) for a in e.args) if x is not None}
        if len(ds) > 1:
            raise _NotHomogeneous(f"a sum of degrees {sorted(ds)}")
        d = ds.pop() if ds else None
    elif e.is_Mul:
        ds = [_deg(a, S, memo) for a in e.args]
        d = None if None in ds else sum(ds, Fraction(0))
    elif e.is_Pow and e.exp.is_Rational:     # (c x)^r = c^r x^r for c > 0
        b = _deg(e.base, S, memo)
        if b is None and e.exp <= 0:
            raise _NotHomogeneous("a power of zero")
        d = None if b is None else b * Fraction(int(e.exp.p), int(e.exp.q))
    elif isinstance(e, sp.atan2):
        y, x = (_deg(a, S, memo) for a in e.args)
        if y is not None and x is not None and y != x:
            raise _NotHomogeneous("atan2 of two degrees")
        d = Fraction(0)
    elif isinstance(e, sp.Abs):
        d = _deg(e.args[0], S, memo)
    elif isinstance(e, sp.Function) and not isinstance(e, sp.Piecewise) and \
            all(_deg(a, S, memo) in (None, 0) for a in e.args):
        d = Fraction(0)     # a function of unscaled arguments only
    else:
        raise _NotHomogeneous(type(e).__name__)
    memo[e] = d
    return d


def rescale_steps(kernel, program) -> list[dict]:
    """The rescaling of ``kernel`` (a :class:`~rigidsym.codegen.spec.Kernel` without
    branches) whose ``program`` (temporaries ``[(symbol, expr)]`` in order and flat
    ``outputs``, row-major) the C target prints: ``[{"args": [names], "degrees": [int per
    output slot]}]``, one step per independent scale: each scalable argument alone where
    every output is homogeneous in it (it is then normalised on its own), then the others
    together where every output is homogeneous in them jointly (an argument that reaches
    ``sin``, ``cos``, ... is never scaled). ``[]`` where neither holds; an argument in no
    step keeps its extreme flag."""
    from rigidsym.codegen.spec import flat_symbols

    if kernel.branches:
        return []
    kinds = {a.name: a.kind for a in kernel.args}
    temps = [(t, sp.sympify(x)) for t, x in program.temps]
    outs = [sp.sympify(x) for x in program.outputs]
    reach: dict = {}      # temporary -> the input symbols it depends on
    for t, x in temps:
        reach[t] = set().union(*(reach.get(v, {v}) for v in x.free_symbols))
    inside: set = set()
    for x in [x for _, x in temps] + outs:
        for f in x.atoms(sp.Function):
            if not isinstance(f, sp.Abs | sp.atan2) and not hasattr(f, "_eval_rewrite_as_Add"):
                inside |= set().union(*(reach.get(v, {v}) for v in f.free_symbols))
    groups = [(name, set(syms)) for name, syms in flat_symbols(kernel)
              if kinds[name] in SCALABLE and not set(syms) & inside]

    def step(names, syms):
        env: dict = {}
        try:
            for t, x in temps:
                env[t] = degree(x, syms, env)
            ds = [degree(x, syms, env) for x in outs]
        except ValueError:
            return None
        if any(d is not None and d.denominator != 1 for d in ds):
            return None
        return {"args": names, "degrees": [int(d or 0) for d in ds]}

    steps = [st for st in (step([n], syms) for n, syms in groups) if st]
    done = {n for st in steps for n in st["args"]}
    rest = [(n, syms) for n, syms in groups if n not in done]
    joint = step([n for n, _ in rest], set().union(*(syms for _, syms in rest))) \
        if rest else None
    return steps + ([joint] if joint else [])
