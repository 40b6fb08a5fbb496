"""The candidate rewrites' proposals of :mod:`.accurate` (issue 30, 37): each
``propose(flat, ctx) -> (new flat, [(old, new) parts]) | None``; the parts are what the zero
test decides equal. Kept apart from the measuring and choosing, which is
:mod:`.accurate`'s."""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.optimise import rewrite as _half_angle_rewrite


def _skew_one_minus_cos(flat, ctx):
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


def _axis_point_from_skew(flat, ctx):
    """(3.18)'s ``p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))`` -> ``(1 + tr Q) / (4 v.v)
    v x c + (c - v (v.c) / v.v) / 2``, ``v = vect(Q)``, ``c = a' - Q a`` (= ``cot(phi/2)/2 e
    x c + (c - e (e.c))/2``, with ``Q - 1 = sin phi E + (1 - cos phi) E^2``). The declared
    form reads the diagonal of Q, whose rounding (absolute u) is relative ``u / phi`` of
    ``(Q - 1)^T c`` as phi -> 0; this one reads the axis from the skew part only, as
    pytransform3d's screw parameters do (issue 37: 3e7 u where they are 4 u at phi = 1e-8)."""
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


def _exact_powers(flat, ctx):
    """``x^(k/2)`` (``|k| >= 3``) and ``x^-n`` (``n >= 2``) -> ``pow(x, k/2)``: the kernels
    print a rational power as a product of roots and a quotient (``1/(x sqrt x)``: three
    roundings, four for ``x^(-5/2)``), where ``pow`` rounds once; the exponent is written
    as its float (exact in binary), which every printer prints as ``pow``."""
    if ctx.get("angles"):
        # the half-angle rewrite, after this measurement, rewrites those powers' bases
        return None
    # a norm under a function (sin sqrt(T) / sqrt(T)^3, 1 / (1 - cos sqrt(T))^2) makes
    # removable quotients (rigidsym.codegen.removable), which read its powers as rational
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


def _angle_fractions(flat, ctx):
    """Sums of fractions in ``cos phi`` over one phi-free factor as one reduced fraction:
    ``sympy.diff`` of ``sin phi / (2 - 2 cos phi)`` gives ``cos phi / (2 - 2 cos phi) - 2
    sin^2 phi / (2 - 2 cos phi)^2``, which is ``-1 / (2 - 2 cos phi)`` (issue 37:
    ``N_tilde_dot_with_jacobians``' derivative by phi 4.7 u where the textbook is 2.3 u)."""
    out = list(flat)
    for phi in ctx["angles"]:
        memo: dict = {}
        out = [_merge_angle_terms(sp.sympify(e), phi, memo) for e in out]
    parts = [(o, n) for o, n in zip(flat, out, strict=True) if o != n]
    return (out, parts) if parts else None


#: the largest output (operations) :func:`_tan_half_polynomial` hands to sympy's cancel: a
#: generic cancel over every kernel with an angle and a unit vector (outputs up to 120
#: operations, the Jacobian kernels' derivatives) ran ``rigidsym generate`` past 10 minutes
TAN_HALF_OPS = 80


def _tan_half_shape(flat, ctx):
    """``(phi, e)`` where the kernel is this rule's shape (cheap to recognise, before any
    cancel): one angle, one unit 3-vector, no rotation, not a Jacobian kernel; every output
    with phi at most :data:`TAN_HALF_OPS` operations, phi in ``sin phi`` and ``cos phi``
    only, and its only divisor with phi ``1 + cos phi`` (so that in ``t = tan(phi/2)``,
    ``1 + cos phi = 2 / (1 + t^2)``, it may be a polynomial); else None."""
    k = ctx["kernel"]
    units = [a for a in k.args if a.kind == "unit" and a.shape == (3,)]
    if k.name.endswith("_with_jacobians") or len(ctx["angles"]) != 1 or len(units) != 1 \
            or ctx["rotations"]:
        return None
    phi = ctx["angles"][0]
    trig, plus, divides = (sp.sin(phi), sp.cos(phi)), sp.cos(phi) + 1, False
    for f in flat:
        f = sp.sympify(f)
        if not f.has(phi):
            continue
        if sp.count_ops(f) > TAN_HALF_OPS:
            return None
        for p in sp.preorder_traversal(f):
            if isinstance(p, sp.Function) and p.has(phi) and p not in trig:
                return None
            if isinstance(p, sp.Pow) and p.exp.is_negative and p.base.has(phi):
                if p.base != plus:
                    return None
                divides = True
    return (phi, ctx["flat"][units[0].name]) if divides else None


def _homogenised(c: sp.Expr, e: list) -> sp.Expr:
    """``c``, a polynomial in the unit vector ``e``, as ``H + q (e . e - 1)``: ``H`` its
    terms of degree ``d - 2 j`` times ``(e . e)^j`` (homogeneous, cancelled symbolically:
    ``e0^2 w2 + e1^2 w2 + 2 e2^2 w2 - w2``, which cancels in floating point, is
    ``e2 (e . w) + w2 (e . e - 1)``), ``q`` the exact quotient; equal to ``c`` everywhere,
    off the unit sphere too. ``c`` itself where it is homogeneous or of mixed parity."""
    parts: dict = {}
    for mon, co in sp.Poly(c, *e).terms():
        parts.setdefault(sum(mon), []).append(co * sp.Mul(*[x**n for x, n in zip(e, mon,
                                                                                  strict=True)]))
    if len(parts) < 2 or len({d % 2 for d in parts}) > 1:
        return c
    d, ee = max(parts), sp.Add(*[x**2 for x in e])
    h = sp.expand(sp.Add(*[sp.Add(*ts) * ee**((d - j) // 2) for j, ts in parts.items()]))
    q = sp.expand(-sp.Add(*[sp.Add(*ts) * sp.Add(*[ee**i for i in range((d - j) // 2)])
                            for j, ts in parts.items()]))
    # written plainly (no UnevaluatedExpr: the JAX printer differentiates the program, and
    # a differentiated UnevaluatedExpr prints as a Derivative)
    return h if q == 0 else sp.Add(h, sp.Mul(q, sp.Add(ee, -1), evaluate=False))


def _tan_half_polynomial(flat, ctx):
    """A rational function of ``sin phi``, ``cos phi`` over powers of ``1 + cos phi`` that is
    a polynomial in ``t = tan(phi/2)`` -> that polynomial, each coefficient homogenised in
    the unit vector (:func:`_homogenised`), ``t`` from ``sin(phi/2) / cos(phi/2)``:
    ``L_tilde_dot = [CPM(v) | -v]``, ``v = (w + t (w x e) + t^2 (e (e . w) + w (e . e -
    1)))/2`` (issue 37: the half-angle program reads ``sin(phi/2)`` apart from ``cos
    phi``; 6.3 u where the textbook is 2.3 u). Equal to the declaration off the unit
    sphere too (the identity is ``sin phi = 2t / (1 + t^2)``, ``cos phi = (1 - t^2) / (1 +
    t^2)``), so the harness's unit vectors a few ulps off read the declared formula."""
    shape = _tan_half_shape(flat, ctx)
    if shape is None:
        return None
    phi, e = shape
    t = sp.Dummy("t")
    half = {t: sp.sin(phi / 2) / sp.cos(phi / 2)}
    to_t = {sp.sin(phi): 2 * t / (1 + t**2), sp.cos(phi): (1 - t**2) / (1 + t**2)}
    out, parts = [], []
    for f in flat:
        f = sp.sympify(f)
        new = None
        if f.has(phi):
            num, den = sp.fraction(sp.cancel(f.xreplace(to_t)))
            if not den.has(t):
                poly = sp.Poly(num, t)
                new = sp.Add(*[t**n * _homogenised(c, e) for (n,), c in poly.terms()])
                new = (new / den).xreplace(half)
        # where the half-angle rewrite gives this form already (L_tilde: 1 + t CPM(e)),
        # nothing is proposed (a rewrite that prints the same program)
        if new is None or _half_angle_rewrite(f, [phi]) == _half_angle_rewrite(new, [phi]):
            out.append(f)
        else:
            out.append(new)
            parts.append((f, new))
    return (out, parts) if parts else None
