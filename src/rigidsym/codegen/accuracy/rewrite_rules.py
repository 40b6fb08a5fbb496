"""The candidate rewrites' proposals of :mod:`.rewrites`: each
``propose(flat, ctx) -> (new flat, [(old, new) parts]) | None``; the parts are what the zero
test decides equal. Kept apart from the measuring and choosing, which is
:mod:`.rewrites`'s."""

from __future__ import annotations

import sympy as sp


def skew_one_minus_cos(flat, ctx):
    """``(1 - Q00) + (1 - Q11) + (1 - Q22)`` (= 3 - tr Q = 2 (1 - cos phi)) ->
    ``||Q - Q^T||_F^2 / (2 (1 + tr Q))`` (= 2 sin^2 phi / (1 + cos phi))."""
    reps = {}
    for Q in ctx["rotations"]:
        d = [Q[i, i] for i in range(3)]
        old_forms = {sp.Add(*[sp.UnevaluatedExpr(1 - x) for x in d]), 3 - sum(d)}
        skew = sum((Q[i, j] - Q[j, i]) ** 2 for i, j in ((2, 1), (0, 2), (1, 0)))
        new = skew / (1 + sum(d))
        for e in flat:
            for sub in sp.preorder_traversal(e):
                if sub in old_forms:
                    reps[sub] = new
    if not reps:
        return None
    return [e.xreplace(reps) for e in flat], list(reps.items())


def axis_point_from_skew(flat, ctx):
    """(3.18)'s ``p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))`` -> ``(1 + tr Q) / (4 v.v)
    v x c + (c - v (v.c) / v.v) / 2``, ``v = vect(Q)``, ``c = a' - Q a`` (= ``cot(phi/2)/2 e
    x c + (c - e (e.c))/2``, with ``Q - 1 = sin phi E + (1 - cos phi) E^2``). The declared
    form reads the diagonal of Q, whose rounding (absolute u) is relative ``u / phi`` of
    ``(Q - 1)^T c`` as phi -> 0; this one reads the axis from the skew part only, as
    pytransform3d's screw parameters do (3e7 u where they are 4 u at phi = 1e-8)."""
    k = ctx["kernel"]
    vecs = [a.name for a in k.args if a.kind == "any" and a.shape == (3,)]
    reps = {}
    for Q in ctx["rotations"]:
        om = sp.Add(*[sp.UnevaluatedExpr(1 - Q[i, i]) for i in range(3)])
        h = sp.Dummy("half")
        for x, y in zip(vecs, vecs[1:], strict=False):
            a, ap = sp.Matrix(ctx["flat"][x]), sp.Matrix(ctx["flat"][y])
            # the declaration's grouping, rebuilt as kernels_spec builds it
            old = ((Q - sp.eye(3)).T * (Q * a - ap) / (2 * (1 - (1 - h)))).xreplace(
                {h: om / 2})
            v = sp.Matrix([Q[2, 1] - Q[1, 2], Q[0, 2] - Q[2, 0], Q[1, 0] - Q[0, 1]]) / 2
            c = ap - Q * a
            vv = v.dot(v)
            new = (1 + Q.trace()) / (4 * vv) * v.cross(c) + (c - v * (v.dot(c) / vv)) / 2
            if any(e.has(old[i]) for e in flat for i in range(3)):
                reps.update(zip(old, new, strict=True))
    if not reps:
        return None
    # subs, not xreplace: in the Plücker moment p0 x e a component of p0 is a factor of a
    # larger product (sympy flattens Mul), which only subs finds
    return [e.subs(reps) if e.has(om) else e for e in flat], list(reps.items())


def axis_point_from_axis(flat, ctx):
    """(3.18)'s ``p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))`` with ``Q`` from ``(e, phi)``
    by (2.49) -> ``cot(phi/2)/2 e x (a' - a) - e x (e x (a + a'))/2 + d ((a - a')/2 + s^2 E^2
    a + s^2 d a)``, ``s = sin(phi/2)``, ``E^2 x = e (e.x) - (e.e) x``, ``d = e.e - 1`` (Dot2).

    With ``Q - 1 = 2 s (c E + s N)``, ``N = e e^T - 1 = E^2 + d 1`` (which commutes with E),
    the declared product is exactly this for every e, unit or not (so its derivatives are
    the declared ones too): the midpoint's part normal to the axis plus the cot term, read
    from the inputs, where the declared form rounds Q's nine entries and two sums of three
    products over them (5.1 u where the textbook is 1.0 u at a random point); the
    ``d`` terms keep it equal to the declared formula at a unit vector a few ulps off (35 u
    there without them), and ``d`` is ``e.e - 1`` compensated (plainly it is itself a few
    ulps, so half wrong)."""
    from rigidsym.algebra.primitives import rotation_from_natural_invariants
    from rigidsym.codegen.accuracy.compensated import SumProd

    k = ctx["kernel"]
    if k.name.endswith("_with_jacobians") and not ctx.get("values_only"):
        # the values alone rewritten lose the declared derivatives' shared terms (365 -> 458
        # operations) and moved the float32 C plan past the rule (0.86 -> 1.6 at phi -> pi):
        # there only with their own derivatives (accurate._rewritten_then_differentiated)
        return None
    units = [a.name for a in k.args if a.kind == "unit" and a.shape == (3,)]
    vecs = [a.name for a in k.args if a.kind == "any" and a.shape == (3,)]
    reps = {}
    for u in units:
        e = sp.Matrix(ctx["flat"][u])
        for phi in ctx["angles"]:
            Q = rotation_from_natural_invariants(e, phi)
            for x, y in zip(vecs, vecs[1:], strict=False):
                a, ap = sp.Matrix(ctx["flat"][x]), sp.Matrix(ctx["flat"][y])
                old = (Q - sp.eye(3)).T * (Q * a - ap) / (2 - 2 * sp.cos(phi))
                if not any(o == f or f.has(o) for o in old for f in flat):
                    continue
                sh, ch = sp.sin(phi / 2), sp.cos(phi / 2)
                d = SumProd(e[0], e[0], e[1], e[1], e[2], e[2], -1, 1)
                ee = e.dot(e)
                e2a = e * e.dot(a) - ee * a
                new = (ch / (2 * sh) * e.cross(ap - a) - e.cross(e.cross(a + ap)) / 2
                       + d * ((a - ap) / 2 + sh**2 * e2a + sh**2 * d * a))
                reps.update(zip(old, new, strict=True))
    if not reps:
        return None
    return [reps.get(e, e.xreplace(reps)) for e in flat], list(reps.items())


def exact_powers(flat, ctx):
    """``x^(k/2)`` (``|k| >= 3``) and ``x^-n`` (``n >= 2``) -> ``pow(x, k/2)``: the kernels
    print a rational power as a product of roots and a quotient (``1/(x sqrt x)``: three
    roundings, four for ``x^(-5/2)``), where ``pow`` rounds once; the exponent is written
    as its float (exact in binary), which every printer prints as ``pow``."""
    if ctx.get("angles"):
        # the half-angle rewrite, after this measurement, rewrites those powers' bases
        return None
    # a norm under a function (sin sqrt(T) / sqrt(T)^3, 1 / (1 - cos sqrt(T))^2) makes
    # removable quotients (rigidsym.codegen.removable.singularities), which read its powers as
    # rational
    quotients = {a.base for e in flat for f in e.atoms(sp.Function) for a in
                 f.atoms(sp.Pow) if a.exp.is_Rational and a.exp.q == 2}
    reps = {}
    for e in flat:
        for p in sp.preorder_traversal(e):
            if isinstance(p, sp.Pow) and p.exp.is_Rational and p.base.free_symbols and (
                    (p.exp.q == 2 and abs(p.exp.p) >= 3) or (p.exp.is_Integer and p.exp <= -2)) \
                    and p.base not in quotients and not p.base.atoms(sp.Function):
                reps[p] = sp.Pow(p.base, sp.Float(float(p.exp)))
    if not reps:
        return None
    return [e.xreplace(reps) for e in flat], list(reps.items())


def _rational_in_cos(f: sp.Expr, phi: sp.Symbol) -> sp.Expr:
    """``f``, a rational function of ``cos phi`` and ``sin phi``, as one reduced fraction
    (``sin^2 -> 1 - cos^2``, then ``cancel``); ``f`` itself where it holds phi otherwise."""
    C, S = sp.Dummy("C"), sp.Dummy("S")
    g = f.xreplace({sp.sin(phi): S, sp.cos(phi): C})
    if g.has(phi):
        return f
    circle = sp.Poly(S**2 + C**2 - 1, S)
    num, den = (sp.expand(x) for x in sp.fraction(sp.together(g)))
    num, den = (sp.rem(sp.Poly(x, S), circle).as_expr() if x.has(S) else x
                for x in (num, den))
    return sp.factor(sp.cancel(num / den)).xreplace({S: sp.sin(phi), C: sp.cos(phi)})


#: the largest sum `_merge_angle_terms` hands to sympy's factor (terms, operations)
MERGE_TERMS, MERGE_OPS = 4, 40


def _merge_angle_terms(e: sp.Expr, phi: sp.Symbol, memo: dict) -> sp.Expr:
    """In every sum, the terms sharing a phi-free factor: their functions of phi merged
    into one reduced fraction where that has fewer operations."""
    if e in memo:
        return memo[e]
    if e.is_Atom or not e.has(phi):
        return e
    args = [_merge_angle_terms(a, phi, memo) for a in e.args]
    out = e.func(*args) if args != list(e.args) else e
    if out.is_Add:
        groups: dict = {}
        for t in out.args:
            ind, dep = t.as_independent(phi, as_Add=False)
            c, ind = ind.as_coeff_Mul()
            groups.setdefault(ind, []).append(c * dep)
        terms, merged = [], False
        for ind, parts in groups.items():
            s = sp.Add(*parts)
            # bounded: factor/cancel of a large sum ran for tens of minutes (the Jacobian
            # kernels' long sums); the cancelling sums this is for are a few terms
            if 1 < len(parts) <= MERGE_TERMS and any(x.has(phi) for x in parts) and \
                    sp.count_ops(s) <= MERGE_OPS:
                r = _rational_in_cos(s, phi)
                if sp.count_ops(r) < sp.count_ops(s):
                    s, merged = r, True
            terms.append(ind * s)
        if merged:
            out = sp.Add(*terms)
    memo[e] = out
    return out


def angle_fractions(flat, ctx):
    """Sums of fractions in ``cos phi`` over one phi-free factor as one reduced fraction:
    ``sympy.diff`` of ``sin phi / (2 - 2 cos phi)`` gives ``cos phi / (2 - 2 cos phi) - 2
    sin^2 phi / (2 - 2 cos phi)^2``, which is ``-1 / (2 - 2 cos phi)`` (
    ``N_tilde_dot_with_jacobians``' derivative by phi 4.7 u where the textbook is 2.3 u)."""
    out = list(flat)
    for phi in ctx["angles"]:
        memo: dict = {}
        out = [_merge_angle_terms(sp.sympify(e), phi, memo) for e in out]
    parts = [(o, n) for o, n in zip(flat, out, strict=True) if o != n]
    return (out, parts) if parts else None
