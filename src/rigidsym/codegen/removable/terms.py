"""The terms of a kernel output in a norm ``s = sqrt(T)``, grouped by their factor free of
``s`` (used by :mod:`rigidsym.codegen.removable.singularities`).

An output is read as a sparse Laurent polynomial: monomials in *atoms* with exact rational
coefficients (a dict ``{monomial: Fraction}``, a monomial a sorted tuple of ``(atom id,
exponent)``). An atom is a symbol or a function free of ``s`` (a *free* atom), or an
expression in ``s`` alone (``s`` itself, ``sin s``, ``1 - cos s``: an *s-atom*); a function
of both has its arguments rewritten first and is then a free atom. Products and integer
powers are distributed in this form, not by ``sympy.expand`` on the expression tree (which
took minutes for the 6 x 6 Jacobians of SE(3), and more for a branch holding ``acos``).
For ``T = x0^2 + x1^2 + ...`` (a norm of symbols) ``x0^2`` is reduced to ``s^2 - x1^2 - ...``
so that the monomials are independent; then every monomial's free part keys a group whose
s-parts are summed, each group's sum a function of ``s`` alone.

Every step is an identity of rational functions (distributing, ``a^i a^j = a^(i+j)``,
``x0^2 = s^2 - x1^2 - ...``); nothing is decided numerically.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from rigidsym.codegen.removable.series import S

__all__ = ["TooLarge", "Terms"]

_LIMIT = 200_000      # monomials in one product before the output is left as it was


class TooLarge(ValueError):
    """The distributed form would hold more than ``_LIMIT`` monomials."""


def _merge(m1, m2):
    if not m1:
        return m2
    if not m2:
        return m1
    d = dict(m1)
    for a, k in m2:
        k2 = d.get(a, 0) + k
        if k2:
            d[a] = k2
        else:
            del d[a]
    return tuple(sorted(d.items()))


def _accumulate(out: dict, m, c) -> None:
    """``out[m] += c``, a zero coefficient dropped (the sparse form keeps no zeros)."""
    c2 = out.get(m, 0) + c
    if c2:
        out[m] = c2
    else:
        out.pop(m, None)


def _add(p, q, sign=1):
    out = dict(p)
    for m, c in q.items():
        _accumulate(out, m, sign * c)
    return out


def _mul(p, q):
    if len(p) * len(q) > _LIMIT:
        raise TooLarge
    out: dict = {}
    for m1, c1 in p.items():
        for m2, c2 in q.items():
            _accumulate(out, _merge(m1, m2), c1 * c2)
    return out


class Terms:
    """The grouping of outputs in the norm ``sqrt(T)`` (one instance per root ``T``).

    ``inner(e)`` rewrites an expression in ``s`` and other symbols whole; ``fold(h)`` is
    the quotient of ``T`` of an s-only factor as written, or ``None`` (both given by the
    caller, the removable pass): a formula's ``(1 - cos s)/s^2`` stays one quotient, a free
    atom, and is not distributed into terms that would need a new quotient of their own
    (if ``A`` and ``A + B`` are removable, so is ``B``: nothing is lost).
    :meth:`groups` returns ``[(free factor, s-part)]``.
    """

    def __init__(self, T, inner, fold, qtype):
        self.T, self.inner, self.fold, self.qtype = T, inner, fold, qtype
        self.atoms: list = []          # id -> expression
        self.is_s: list = []           # id -> an s-atom
        self.has_q: list = []          # id -> holds a quotient (a folded factor)
        self.ids: dict = {}
        self.memo: dict = {}
        self.found = False             # a quotient in the output being rewritten
        self.x0 = None
        sq = sp.Add.make_args(T)
        if len(sq) > 1 and all(t.is_Pow and t.exp == 2 and t.base.is_Symbol for t in sq):
            xs = sorted((t.base for t in sq), key=sp.default_sort_key)
            self.x0 = self._id(xs[0])
            self.rep = {((self._id(S), 2),): Fraction(1)}
            for x in xs[1:]:
                self.rep[((self._id(x), 2),)] = Fraction(-1)

    def _id(self, a):
        i = self.ids.get(a)
        if i is None:
            i = self.ids[a] = len(self.atoms)
            self.atoms.append(a)
            self.is_s.append(a.has(S))
            self.has_q.append(a.has(self.qtype))
        return i

    def _atom(self, a, k=1):
        return {((self._id(a), k),): Fraction(1)}

    def _opaque(self, e):
        if not e.has(S) or e.free_symbols <= {S}:
            return self._atom(e)
        return self._atom(self.inner(e))   # both: its inside rewritten, then free

    def poly(self, e):
        """``e`` (holding ``s`` for the norm) in the distributed form."""
        got = self.memo.get(e)
        if got is not None:
            return got
        if e.has(S) and e.free_symbols <= {S} and (q := self.fold(e)) is not None:
            out = self._atom(q)
        elif e.is_Mul and (q := self._fold_factors(e)) is not None:
            out = self.poly(q)
        elif e.is_Rational:
            out = {(): Fraction(int(e.p), int(e.q))} if e != 0 else {}
        elif e.is_Symbol:
            out = self._atom(e)
        elif e.is_Add:
            out = {}
            for a in e.args:
                out = _add(out, self.poly(a))
        elif e.is_Mul:
            out = {(): Fraction(1)}
            for a in e.args:
                out = _mul(out, self.poly(a))
        elif e.is_Pow and e.exp.is_Integer and abs(int(e.exp)) <= 64:
            out = self._pow(e.base, int(e.exp))
        else:
            out = self._opaque(e)
        self.memo[e] = out
        return out

    def _fold_factors(self, e):
        dep = [a for a in e.args if a.has(S) and a.free_symbols <= {S}]
        if len(dep) < 2 or len(dep) == len(e.args):
            return None
        q = self.fold(sp.Mul(*dep))
        if q is None:
            return None
        return sp.Mul(*(a for a in e.args if a not in dep)) * q

    def _pow(self, b, k):
        pb = self.poly(b)
        if k < 0:
            if len(pb) == 1:        # a monomial: its inverse is one
                (m, c), = pb.items()
                return {tuple((a, j * k) for a, j in m): Fraction(1) / c ** -k}
            if not b.has(S) or b.free_symbols <= {S}:
                return self._atom(b, k)
            return self._atom(self.inner(b), k)
        out, base = {(): Fraction(1)}, pb
        while k:
            if k & 1:
                out = _mul(out, base)
            k >>= 1
            if k:
                base = _mul(base, base)
        return out

    def reduced(self, p):
        """``p`` with ``x0^2 = s^2 - x1^2 - ...`` (``x0`` of degree at most 1)."""
        if self.x0 is None:
            return p
        out: dict = {}
        todo = p
        while todo:
            nxt: dict = {}
            for m, c in todo.items():
                d = dict(m)
                a = d.get(self.x0, 0)
                if a < 2:
                    out = _add(out, {m: c})
                    continue
                d[self.x0] = a - 2
                if not d[self.x0]:
                    del d[self.x0]
                nxt = _add(nxt, _mul({tuple(sorted(d.items())): c}, self.rep))
            todo = nxt
        return out

    def expr(self, m):
        return sp.Mul(*(self.atoms[a] ** k for a, k in m))

    def groups(self, e) -> list:
        """``[(free factor, s-part)]`` of ``e``, each s-part an expression in ``s`` alone."""
        p = self.reduced(self.poly(e))
        by: dict = {}
        self.found = self.found or any(self.has_q[a] for m in p for a, _ in m)
        for m, c in p.items():
            free = tuple((a, k) for a, k in m if not self.is_s[a])
            dep = tuple((a, k) for a, k in m if self.is_s[a])
            g = by.setdefault(free, {})
            g[dep] = g.get(dep, 0) + c
        out = []
        for free, g in sorted(by.items()):
            part = sp.Add(*(sp.Rational(c.numerator, c.denominator) * self.expr(m)
                            for m, c in sorted(g.items()) if c))
            if part != 0:
                out.append((self.expr(free), part))
        return out
