"""Removable singularities of a kernel's program, derived and certified (issue 38 item 1).

A formula written in a norm ``theta = sqrt(T)`` (``T = w^T w`` for a rotation vector, any
expression under a square root) divides by powers of ``theta``: ``sin theta / theta``,
``(1 - cos theta) / theta^2``, ``(theta - sin theta) / theta^3``, the quotients of their
derivatives. Where such a quotient ``h(theta)`` is even with a finite limit at 0 it is a
function of ``T`` analytic at ``T = 0``, and :func:`rewrite` replaces it by a call of a
:class:`QuotientBase` of ``T``: printed as a branch, ``T < t*`` the truncated Taylor series **in
T** (Horner, exact coefficients rounded once), else the closed form at a safe argument
(``safe-where``: the closed form is fed ``max(T, t*)``, so neither branch makes a NaN or
a NaN gradient). Coefficients, order and threshold and their error bounds come from
:mod:`rigidsym.codegen.removable_cert`. No epsilon anywhere; a quotient without a finite
limit is left as printed (the kernel stays singular there, as before).

How the quotients are found, in any declaration's program (the book's, the Lie-group maps,
a reader's through ``rigidsym generate --module``): each root ``sqrt(T)`` (and its powers
``T^(k/2)``) becomes a symbol ``s``, ``T`` itself ``s^2`` (and, for a norm of symbols,
``x0^2`` becomes ``s^2 - x1^2 - ...``: :func:`_normal`), products are distributed over
sums; in every sum the terms are
grouped by their factor free of ``s`` and the ``s``-parts summed (so ``w cos s / s^2 - w
sin s / s^3`` of a derivative is one quotient ``(s cos s - sin s) / s^3``); each group's
``s``-part is then a quotient when it is one, a polynomial in ``s^2`` when it is one, and
otherwise ``s`` goes back to ``sqrt(T)`` unchanged.
"""

from __future__ import annotations

import hashlib
from functools import cache

import mpmath
import sympy as sp

from rigidsym.codegen.removable_cert import NotRemovable, S, certify, series_of

__all__ = ["QuotientBase", "quotient", "rewrite", "NAMES"]

#: names of the usual quotients (the rest are named by a hash of their form)
NAMES = {sp.sin(S) / S: "rq_sinc", (1 - sp.cos(S)) / S**2: "rq_cosc",
         (S - sp.sin(S)) / S**3: "rq_sincc", (S * sp.cos(S) - sp.sin(S)) / S**3: "rq_dsinc"}


class QuotientBase(sp.Function):
    """``h(sqrt(T))`` for an even ``h`` with a finite limit at 0, as a function of ``T``.

    Subclasses (one per ``h``, :func:`quotient`) carry ``h``, its certificate and series.
    """

    nargs = 1
    h: sp.Expr = sp.S.Zero
    label = ""

    @classmethod
    def eval(cls, t):
        if t == 0:
            return sp.Rational(*_frac(series_of(cls.h).coeffs[0]))
        return None

    def fdiff(self, argindex=1):
        # d/dT h(sqrt T) = h'(s) / (2 s): even with a finite limit again
        return quotient(sp.diff(self.h, S) / (2 * S))(self.args[0])

    def _eval_evalf(self, prec):
        t = self.args[0].evalf(prec)
        if not t.is_Number:
            return None
        return self.h.subs(S, sp.sqrt(t)).evalf(prec) if t != 0 else self.eval(0).evalf(prec)

    def expansion(self):
        """The printed branch: the Horner series below ``t*``, the closed form above it at a
        safe argument (``safe-where``)."""
        t = self.args[0]
        cert = certify(self.h)
        cs = series_of(self.h).coeffs[:cert.order + 1]
        thr = sp.Float(cert.threshold, 17)
        poly = sp.Float(float(cs[-1]), 17)
        for c in reversed(cs[:-1]):
            poly = sp.Float(float(c), 17) + t * poly
        safe = sp.Piecewise((thr, t < thr), (t, True))
        closed = self.h.subs(S, sp.sqrt(safe))
        return sp.Piecewise((poly, t < thr), (closed, True))

    def _sympystr(self, printer):
        return f"{self.label}({printer._print(self.args[0])})"

    def __reduce_ex__(self, protocol):
        # the class is made at run time (quotient()): a worker of the generator's pool
        # sends the call back as (h, T), rebuilt by quotient() in the parent
        return (_rebuild, (self.h, self.args[0]))


def _rebuild(h, t):
    return quotient(h)(t)


def _frac(f):
    return int(f.numerator), int(f.denominator)


def _imp(h):
    f = sp.lambdify(S, h, "mpmath")
    c0 = series_of(h).coeffs[0]

    def value(t):
        if t == 0:
            return mpmath.mpf(c0.numerator) / c0.denominator
        return f(mpmath.sqrt(t))
    return value


@cache
def quotient(h: sp.Expr) -> type[QuotientBase]:
    """The :class:`QuotientBase` class of ``h`` (an expression in
    :data:`rigidsym.codegen.removable_cert.S`), certified.

    Raises:
        NotRemovable: ``h`` is not even, has no finite limit at 0, or is not certified.
    """
    h = sp.together(h)
    certify(h)
    name = NAMES.get(h) or "rq_" + hashlib.sha256(sp.srepr(h).encode()).hexdigest()[:8]
    return type(name, (QuotientBase,), {"h": h, "label": name, "_imp_": staticmethod(_imp(h))})


def _split(term):
    """``(factor free of s, s-part)`` of a product."""
    free, dep = [], []
    for f in sp.Mul.make_args(term):  # a number goes with the s-part: terms group by symbols
        (dep if f.has(S) or f.is_Number else free).append(f)
    return sp.Mul(*free), sp.Mul(*dep)


def _as_t(part, T, depth: int = 0):
    """An ``s``-only expression as a function of ``T``: a quotient, a polynomial in ``s^2``,
    or unchanged (``s = sqrt(T)``)."""
    if part.is_polynomial(S):
        p = sp.Poly(part, S)
        if all(k % 2 == 0 for (k,) in p.monoms()):
            return sum(c * T ** (k // 2) for (k,), c in p.terms())
        return part.subs(S, sp.sqrt(T))
    k, rest = sp.together(part).as_coeff_Mul()  # -h and h/2 share the function of h
    try:
        if series_of(rest).coeffs[0] == 0 and depth < 8:  # h = T h1: T keeps h1's error
            return k * T * _as_t(sp.together(rest / S**2), T, depth + 1)
        return k * quotient(rest)(T)
    except NotRemovable:
        return part.subs(S, sp.sqrt(T))


def _walk(e, T):
    if not e.has(S):
        return e
    if e.free_symbols == {S}:
        return _as_t(e, T)
    if isinstance(e, sp.Add):
        groups: dict = {}
        rest = []
        for term in e.args:
            free, dep = _split(term)
            if dep.free_symbols - {S}:  # an s-part with other symbols: walk it whole
                rest.append(_walk(term, T))
            else:
                groups[free] = groups.get(free, sp.S.Zero) + dep
        return sp.Add(*rest, *(_walk(k, T) * _as_t(sp.together(v), T)
                               for k, v in groups.items()))
    if isinstance(e, sp.Mul):
        free, dep = _split(e)
        if not dep.free_symbols - {S}:
            return _walk(free, T) * _as_t(dep, T)
    return e.func(*(_walk(a, T) for a in e.args))


def _normal(e, T):
    """``e`` with ``T = s^2`` imposed: ``T`` as a sub-sum becomes ``s^2``; for ``T = x0^2 +
    x1^2 + ...`` (a norm of symbols) ``x0^2`` becomes ``s^2 - x1^2 - ...`` (so the terms
    are in a canonical form, ``x0`` of degree at most 1, whose groups are independent);
    products and powers of sums expanded, so that every term's s-part is s alone."""
    e = e.subs(T, S**2)
    sq = sp.Add.make_args(T)
    if len(sq) > 1 and all(t.is_Pow and t.exp == 2 and t.base.is_Symbol for t in sq):
        xs = sorted((t.base for t in sq), key=sp.default_sort_key)
        x0, rep = xs[0], S**2 - sum(x**2 for x in xs[1:])
        high = lambda z: z.is_Pow and z.base == x0 and z.exp.is_Integer and z.exp >= 2  # noqa: E731
        for _ in range(8):  # a product of two x0 terms makes an x0^2 again: until none
            e = _expand(e.replace(high, lambda z: x0 ** (int(z.exp) % 2) *
                                  rep ** (int(z.exp) // 2)))
            if not e.has(x0**2) and not any(high(z) for z in e.atoms(sp.Pow)):
                break
        return e
    return _expand(e)


def _expand(e):
    return sp.expand(e, deep=True, mul=True, multinomial=True, power_base=False,
                     power_exp=False, log=False)


def _roots(exprs) -> list:
    found = set()
    for e in exprs:
        for p in sp.sympify(e).atoms(sp.Pow):
            if p.exp.is_Rational and p.exp.q == 2 and p.base.free_symbols:
                found.add(p.base)
    return sorted(found, key=sp.default_sort_key)


def rewrite(exprs: list) -> list:
    """Replace every removable quotient in a norm ``sqrt(T)`` of ``exprs`` (see above).

    Args:
        exprs: flat scalar sympy outputs of a kernel (one program).

    Returns:
        The outputs, with :class:`QuotientBase` calls where quotients were removable; an
        output without one is returned unchanged (the same object).
    """
    out = [sp.sympify(e) for e in exprs]
    for T in _roots(out):
        def sub(x, T=T):
            if isinstance(x, sp.Pow) and x.base == T and x.exp.is_Rational and x.exp.q == 2:
                return S ** int(2 * x.exp)
            return None
        new = []
        for e in out:
            e1 = e.replace(lambda x, T=T: sub(x) is not None, lambda x, T=T: sub(x))
            if e1 == e:
                new.append(e)
                continue
            e2 = _walk(_normal(e1, T), T)
            # only where a quotient was removed: elsewhere the output as it was (its form,
            # and so the kernel's program, unchanged)
            new.append(e2 if e2.atoms(QuotientBase) else e)
        out = new
    return out
