"""Removable singularities of a kernel's program, derived and certified.

A formula written in a norm ``theta = sqrt(T)`` (``T = w^T w`` for a rotation vector, any
expression under a square root) divides by powers of ``theta``: ``sin theta / theta``,
``(1 - cos theta) / theta^2``, ``(theta - sin theta) / theta^3``, the quotients of their
derivatives. Where such a quotient ``h(theta)`` is even with a finite limit at 0 it is a
function of ``T`` analytic at ``T = 0``, and :func:`rewrite` replaces it by a call of a
:class:`QuotientBase` of ``T``: printed as a branch, ``T < t*`` the truncated Taylor series **in
T** (Horner, exact coefficients rounded once), else the closed form at a safe argument
(``safe-where``: the closed form is fed ``max(T, t*)``, so neither branch makes a NaN or
a NaN gradient). Coefficients, order and threshold and their error bounds come from
:mod:`rigidsym.codegen.removable.series`. No epsilon anywhere; a quotient without a finite
limit is left as printed (the kernel stays singular there, as before).

How the quotients are found, in any declaration's program (the book's, the Lie-group maps,
a reader's through ``rigidsym generate --module``): each root ``sqrt(T)`` of a polynomial
``T`` in the inputs (and its powers ``T^(k/2)``) becomes a symbol ``s``, ``T`` itself
``s^2``; the output is distributed into monomials and, for a norm of symbols ``T = x0^2 +
x1^2 + ...``, ``x0^2`` becomes ``s^2 - x1^2 - ...`` (:mod:`.terms`, in a sparse
polynomial form, not by ``sympy.expand``); the terms are grouped by their factor free of
``s`` and the ``s``-parts summed (so ``w cos s / s^2 - w sin s / s^3`` of a derivative is one
quotient ``(s cos s - sin s) / s^3``); each group's ``s``-part is then a quotient when it is
one, a polynomial in ``s^2`` when it is one, and otherwise ``s`` goes back to ``sqrt(T)``
unchanged. An output whose distributed form would be too large is left as it was.
"""

from __future__ import annotations

import hashlib
from functools import cache

import mpmath
import sympy as sp

from rigidsym.codegen.removable.series import NotRemovable, S, certify, series_of
from rigidsym.codegen.removable.terms import Terms, TooLarge
from rigidsym.codegen.spec import Grouped

__all__ = ["QuotientBase", "quotient", "rewrite", "half_angle", "Grouped", "NAMES"]


def _ungrouped(e):
    return e.replace(lambda x: isinstance(x, Grouped), lambda x: x.args[0]) \
        if e.has(Grouped) else e

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
        closed = half_angle(self.h).subs(S, sp.sqrt(safe))
        return sp.Piecewise((poly, t < thr), (closed, True))

    def _sympystr(self, printer):
        return f"{self.label}({printer._print(self.args[0])})"

    def __reduce_ex__(self, protocol):
        # the class is made at run time (quotient()): a worker of the generator's pool
        # sends the call back as (h, T), rebuilt by quotient() in the parent
        return (_rebuild, (self.h, self.args[0]))


_HA, _HB = sp.symbols("rq_ha rq_hb")


@cache
def half_angle(h: sp.Expr) -> sp.Expr:
    """The closed form of ``h`` as printed above ``t*``: where a factor of its
    denominator vanishes at ``s = 2 pi`` (``1 - cos s``, ``sin s``: the zero set of the
    formula's own denominator, derived, not listed), ``h`` in ``a = sin(s/2)``, ``b =
    cos(s/2)`` (``1 - cos s = 2 a^2``, ``sin s = 2 a b``), cancelled and reduced by
    ``a^2 + b^2 = 1``: ``1/s^2 - sin s/(2 s (1 - cos s))`` becomes ``(2a - s b)/(2 s^2
    a)``, ``1/s^2 - cot(s/2)/(2 s)``. Near ``s = 2 pi k`` the textbook ``1 - cos s``
    cancels completely (J_l^-1 was 2.5e-2 off at ``2 pi - 1e-9`` and overflowed at ``2 pi
    - 1e-10``); ``a`` is then read from ``s/2`` near ``pi k`` (its rounding, the
    problem's own condition), and nothing cancels at odd multiples of pi either. ``h``
    itself where no denominator factor vanishes there (``sin s / s``, ...)."""
    den = sp.fraction(sp.together(h))[1]
    if not den.has(sp.sin(S), sp.cos(S)) or sp.simplify(den.subs(S, 2 * sp.pi)) != 0:
        return h
    g = sp.cancel(sp.together(h.subs({sp.sin(S): 2 * _HA * _HB,
                                      sp.cos(S): 1 - 2 * _HA**2})))
    n, d = (sp.rem(sp.expand(x), _HA**2 + _HB**2 - 1, _HB) for x in sp.fraction(g))
    out = sp.factor_terms(n) / sp.factor_terms(d)
    return out.subs({_HA: sp.sin(S / 2), _HB: sp.cos(S / 2)})


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
    :data:`rigidsym.codegen.removable.series.S`), certified.

    Raises:
        NotRemovable: ``h`` is not even, has no finite limit at 0, or is not certified.
    """
    h = sp.together(h)
    certify(h)
    name = NAMES.get(h) or "rq_" + hashlib.sha256(sp.srepr(h).encode()).hexdigest()[:8]
    return type(name, (QuotientBase,), {"h": h, "label": name, "_imp_": staticmethod(_imp(h))})


def _as_t(part, T, depth: int = 0, strict: bool = False):
    """An ``s``-only expression as a function of ``T``: a quotient, a polynomial in ``s^2``,
    or unchanged (``s = sqrt(T)``; ``None`` if ``strict``)."""
    if part.is_polynomial(S):
        p = sp.Poly(part, S)
        if all(k % 2 == 0 for (k,) in p.monoms()):
            return sum(c * T ** (k // 2) for (k,), c in p.terms())
        return None if strict else part.subs(S, sp.sqrt(T))
    k, rest = sp.together(part).as_coeff_Mul()  # -h and h/2 share the function of h
    try:
        if not sp.fraction(rest)[1].has(S):   # no division by s: nothing to remove
            raise NotRemovable("no division")
        if series_of(rest).coeffs[0] == 0 and depth < 8:  # h = T h1: T keeps h1's error
            inner = _as_t(sp.together(rest / S**2), T, depth + 1, strict)
            return None if inner is None else k * T * inner
        return k * quotient(rest)(T)
    except NotRemovable:
        return None if strict else part.subs(S, sp.sqrt(T))


@cache
def _part(part, T):
    # many groups share an s-part (every w_i w_j of one coefficient): once each
    return _as_t(sp.together(part), T)


@cache
def _fold(part, T):
    """A removable s-only factor as written (``(1 - cos s)/s^2`` of a formula) as its
    quotient of ``T``, before any distributing; ``None`` where it is not one."""
    den = sp.fraction(sp.together(part))[1]
    # a denominator that does not vanish at s = 0 (1/sqrt(1 - s^2), asin's derivative in
    # the Lie logs' Jacobians) removes nothing: folded alone it would hide its s from the
    # grouping, and 1/(s^2 sqrt(1 - s^2)) - asin(s)/s^3 would stay two singular terms
    if part == S or not den.has(S) or den.subs(S, 0) != 0:
        return None
    return _as_t(part, T, strict=True)


def _grouped(e, terms: Terms):
    """``e`` (holding ``s``) with each group's s-part a function of ``T`` (see above)."""
    out = []
    for f, part in terms.groups(e):
        q = _part(part, terms.T)
        terms.found = terms.found or q.has(QuotientBase)   # small: never the whole output
        out.append(f * q)
    return sp.Add(*out)


def _inner(e, terms: Terms):
    """A sub-expression of ``s`` and other symbols that is not a product of atoms (an
    argument of a function, a base of a root or of a negative power): rewritten whole."""
    if not e.has(S):
        return e
    if e.free_symbols <= {S}:
        # a quotient in s alone (-sin(s)/(2 s), the derivative of cos(sqrt(x3)) by a temp
        # x3 = w^T w): found too, or its output was returned unchanged
        q = _part(e, terms.T)
        terms.found = terms.found or q.has(QuotientBase)
        return q
    if isinstance(e, sp.Add | sp.Mul):
        return _grouped(e, terms)
    return e.func(*(_inner(a, terms) for a in e.args))


def _roots(exprs) -> list:
    found = set()
    for e in exprs:
        for p in sp.sympify(e).atoms(sp.Pow):
            # a norm of a polynomial in the inputs (w^T w, |vect Q|^2): a radicand holding
            # a function (acos, atan2 of a branch near pi) is never 0 where its branch
            # runs and would only be expanded at great cost
            if p.exp.is_Rational and p.exp.q == 2 and p.base.free_symbols and \
                    p.base.is_polynomial(*p.base.free_symbols):
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
            # T^(k/2) and T^k (a 1/T of a derivative) in s
            if isinstance(x, sp.Pow) and x.base == T and x.exp.is_Rational and x.exp.q <= 2:
                return S ** int(2 * x.exp)
            return None
        terms = Terms(T, lambda x: _inner(x, terms),  # noqa: B023 (called in this pass)
                      lambda x, T=T: _fold(x, T), QuotientBase)
        new = []
        for e in out:
            e1 = e.replace(lambda x, T=T: sub(x) is not None, lambda x, T=T: sub(x))
            if e1 == e:
                new.append(e)
                continue
            if terms.x0 is None:
                e1 = e1.subs(T, S**2)     # T as a sub-sum (a norm of expressions)
            terms.found = False
            try:
                e2 = _inner(e1, terms) if e1.has(S) else e1
            except TooLarge:
                new.append(e)
                continue
            # only where a quotient was removed: elsewhere the output as it was (its form,
            # and so the kernel's program, unchanged)
            new.append(e2 if terms.found else e)
        out = new
    return [_ungrouped(e) for e in out]
