"""The rule "a polynomial in tan(phi/2)" of :mod:`.rewrites`: a kernel's fractions
over ``1 + cos phi`` as the polynomial in ``t = tan(phi/2)`` they are, each coefficient
homogenised in the unit vector (``L_tilde_dot``: its worst ratio to the accuracy
rule 1.39 -> 0.856). Limited to a
shape cheap to recognise: sympy's ``cancel`` runs only where it may give a polynomial."""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.optimise import rewrite as _half_angle_rewrite

#: the rule's name and reason, for :data:`rigidsym.codegen.accuracy.rewrites.RULES`
TAN_HALF_TEXT = ("a polynomial in tan(phi/2)",
                 "a fraction over 1 + cos phi in the half-angle program reads sin(phi/2) apart "
                 "from cos phi (each rounded); as the polynomial in t = tan(phi/2) it is, each "
                 "coefficient homogenised in the unit vector, it reads t alone")

#: the largest output (operations) :func:`tan_half_polynomial` hands to sympy's cancel: a
#: generic cancel over every kernel with an angle and a unit vector (outputs up to 120
#: operations, the Jacobian kernels' derivatives) ran ``rigidsym generate`` past 10 minutes
TAN_HALF_OPS = 80


def _tan_half_shape(flat, ctx):
    """``(phi, e)`` where the kernel is this rule's shape (cheap to recognise, before any
    cancel): one angle, one unit 3-vector, no rotation, not a Jacobian kernel (but its
    values, ``values_only``:
    :func:`rigidsym.codegen.accuracy.rewrites._rewritten_then_differentiated`
    differentiates them, the rule being exact off the unit sphere too); every output
    with phi at most :data:`TAN_HALF_OPS` operations, phi in ``sin phi`` and ``cos phi``
    only, and its only divisor with phi ``1 + cos phi`` (so that in ``t = tan(phi/2)``,
    ``1 + cos phi = 2 / (1 + t^2)``, it may be a polynomial); else None."""
    k = ctx["kernel"]
    units = [a for a in k.args if a.kind == "unit" and a.shape == (3,)]
    if (k.name.endswith("_with_jacobians") and not ctx.get("values_only")) or \
            len(ctx["angles"]) != 1 or len(units) != 1 or ctx["rotations"]:
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


def tan_half_polynomial(flat, ctx):
    """A rational function of ``sin phi``, ``cos phi`` over powers of ``1 + cos phi`` that is
    a polynomial in ``t = tan(phi/2)`` -> that polynomial, each coefficient homogenised in
    the unit vector (:func:`_homogenised`), ``t`` from ``sin(phi/2) / cos(phi/2)``:
    ``L_tilde_dot = [CPM(v) | -v]``, ``v = (w + t (w x e) + t^2 (e (e . w) + w (e . e -
    1)))/2`` (the half-angle program reads ``sin(phi/2)`` apart from ``cos
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
