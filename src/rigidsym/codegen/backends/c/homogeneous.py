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

__all__ = ["degree", "scaling_plans", "SCALABLE"]

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


def _mdeg(e, ks: dict, memo: dict, reach: dict, cons: list):
    """The degree of ``e`` under ``x_a -> 2^(k_a) x_a`` for the arguments' symbols ``ks``
    (symbol -> its argument's exponent symbol ``k_a``): a linear form in the ``k_a``, valid
    on the scalings that satisfy every linear form appended to ``cons`` (each must be 0);
    None for an expression that is exactly zero. A node whose homogeneity is not shown (a
    ``Piecewise``, a power of zero, ...) pins the exponents of every argument it reaches to 0
    (it is then unchanged): sound, at the cost of a rescue."""
    if e in memo:
        return memo[e]
    if hasattr(e, "_eval_rewrite_as_Add"):      # the compensated a b - c d, sum of products
        d = _mdeg(e.rewrite(sp.Add), ks, memo, reach, cons)
    elif e.is_Symbol:
        d = ks.get(e, sp.Integer(0))
    elif e.is_Number or e.is_NumberSymbol:
        d = None if e == 0 else sp.Integer(0)
    elif e.is_Add:
        ds = [x for x in (_mdeg(a, ks, memo, reach, cons) for a in e.args) if x is not None]
        cons.extend(x - ds[0] for x in ds[1:])
        d = ds[0] if ds else None
    elif e.is_Mul:
        ds = [_mdeg(a, ks, memo, reach, cons) for a in e.args]
        d = None if None in ds else sp.Add(*ds)
    elif e.is_Pow and e.exp.is_Rational and not (e.exp <= 0 and e.base.is_zero is not False
                                                  and _mdeg(e.base, ks, memo, reach,
                                                            cons) is None):
        b = _mdeg(e.base, ks, memo, reach, cons)
        d = None if b is None else b * e.exp
    elif isinstance(e, sp.atan2):
        y, x = (_mdeg(a, ks, memo, reach, cons) for a in e.args)
        if y is not None and x is not None:
            cons.append(y - x)
        d = sp.Integer(0)
    elif isinstance(e, sp.Abs):
        d = _mdeg(e.args[0], ks, memo, reach, cons)
    elif isinstance(e, sp.Function) and not isinstance(e, sp.Piecewise):
        for a in e.args:        # sin, cos, exp ...: an argument of degree 0
            x = _mdeg(a, ks, memo, reach, cons)
            if x is not None:
                cons.append(x)
        d = sp.Integer(0)
    else:
        for v in e.free_symbols:
            cons.extend(ks[s] for s in reach.get(v, {v}) if s in ks)
        d = sp.Integer(0)
    memo[e] = d
    return d


def scaling_plans(kernel, program) -> list[dict]:
    """The exact power-of-two rescalings of ``kernel`` (a
    :class:`~rigidsym.codegen.spec.Kernel` without branches) whose ``program`` (temporaries
    ``[(symbol, expr)]`` in order and flat ``outputs``, row-major) the C target prints,
    argument by argument.

    Every output ``o`` satisfies ``o(2^(k_1) x_1, ..., 2^(k_n) x_n) = 2^(d_o . k) o(x)`` for
    every integer exponent vector ``k`` of a lattice: the solutions of linear equations
    ("constraints", from the sums whose terms must share a degree, the arguments of ``sin``,
    ``atan2`` ...) in the exponents of the scalable arguments (kind "any"). A plan solves
    them for some arguments (pivots) in terms of the others (free): each free argument gets
    the scale of its own exponent (its largest component into [2^-D, 1)), each pivot the
    combination the constraints give, so that no argument's scale is chosen by another's
    magnitude unless the formula ties them. Several plans (one per choice of pivots, the
    argument order rotated) let the C code take the first under which every scaled argument
    is of ordinary magnitude (e.g. a zero argument as the pivot).

    Returns ``[{"free": [names], "D": int, "scale": {name: [int per free]}, "out": [[int per
    free] per output slot], "constraints": [str], "degrees": [str per slot]}]``: the
    exponent of argument ``a`` is ``sum(scale[a][i] t_i)`` and output slot ``s`` is scaled
    back by ``2^-(sum(out[s][i] t_i))``, where ``t_i = -(e_i / D)`` (C division) and
    ``e_i`` is the binary exponent of free argument ``i``'s largest component. ``[]`` where
    the only scaling is the identity."""
    from rigidsym.codegen.spec import flat_symbols

    if kernel.branches:
        return []
    kinds = {a.name: a.kind for a in kernel.args}
    names = [n for n, _ in flat_symbols(kernel) if kinds[n] in SCALABLE]
    kvar = {n: sp.Symbol(f"k_{n}") for n in names}
    ks = {s: kvar[n] for n, syms in flat_symbols(kernel) if n in kvar for s in syms}
    temps = [(t, sp.sympify(x)) for t, x in program.temps]
    reach: dict = {}      # temporary -> the input symbols it depends on
    for t, x in temps:
        reach[t] = set().union(*(reach.get(v, {v}) for v in x.free_symbols))
    memo: dict = {}
    cons: list = []
    for t, x in temps:
        memo[t] = _mdeg(x, ks, memo, reach, cons)
    outs = [_mdeg(sp.sympify(x), ks, memo, reach, cons) for x in program.outputs]
    cons = list(dict.fromkeys(c for c in (sp.expand(x) for x in cons) if c != 0))
    kv = [kvar[n] for n in names]
    A = sp.Matrix([[c.coeff(k) for k in kv] for c in cons]) if cons else \
        sp.zeros(0, len(kv))
    plans, seen = [], set()
    for shift in range(len(names)):
        order = list(range(shift, len(names))) + list(range(shift))
        if A.rows:
            R, piv = A.extract(list(range(A.rows)), order).rref()
        else:
            R, piv = A, ()
        free = [order[c] for c in range(len(order)) if c not in piv]
        if not free or frozenset(free) in seen:
            continue
        seen.add(frozenset(free))
        basis = []                          # per free argument: the exponent vector
        for f in free:
            v = [sp.Integer(0)] * len(names)
            v[f] = sp.Integer(1)
            for r, pc in enumerate(piv):
                v[order[pc]] = -R[r, order.index(f)]
            basis.append(v)
        odeg = [[sp.Integer(0) if d is None else
                 sp.expand(d).subs(dict(zip(kv, v, strict=True))) for v in basis]
                for d in outs]
        D = sp.ilcm(1, *[sp.Rational(x).q for v in basis for x in v],
                    *[sp.Rational(x).q for row in odeg for x in row])
        plans.append({
            "free": [names[f] for f in free], "D": int(D),
            "scale": {n: [int(v[i] * D) for v in basis] for i, n in enumerate(names)
                      if any(v[i] != 0 for v in basis)},
            "out": [[int(x * D) for x in row] for row in odeg],
            "constraints": [f"{sp.sstr(c)} = 0" for c in cons],
            "degrees": ["0" if d is None else sp.sstr(sp.expand(d)) for d in outs]})
    return plans
