"""Rational functions over Q without gcds, and the evaluation of a statement's tree.

An element is ``(num, c, F)``: the value ``num * prod(f_i ^ F[i]) / c`` with ``num`` a
polynomial of the ring (:mod:`certcheck.poly`), ``c`` a positive integer and ``F`` a dict
from the index of a *factor* (a non-zero polynomial in :attr:`Field.factors`) to a signed
exponent. Adding brings both to the lowest exponent of each factor; no gcd is ever taken,
so the representation is not unique, but it is always a correct one: a factor is stored
only after it is checked to be a non-zero polynomial, so the element is the zero rational
function exactly when ``num`` is the zero polynomial. A factor of the denominator that
divides ``num`` is cancelled at once (:meth:`certcheck.poly.Ring.divexact`, no gcd): ``q_O /
m`` with ``q_O = m o`` is ``o``, so a moving body's expressions stay the size of their values.

The time derivative :meth:`Field.d` acts on the polynomials by the chain rule over jet
variables: ``d(x_k) = x_(k+1)`` for the variables :attr:`Field.next` maps.
"""

from __future__ import annotations

from fractions import Fraction
from math import gcd

__all__ = ["Field", "Root", "Vanishing", "evaluate"]


class Vanishing(ZeroDivisionError):
    """A divisor is the zero rational function (or zero at the point)."""


class Field:
    """The rational functions of ``ring``; ``next`` maps a variable index to the index of
    its time derivative (jets)."""

    def __init__(self, ring, next_jet: dict | None = None):
        self.ring = ring
        self.next = next_jet or {}
        self.factors: list = []
        self._index: dict = {}
        self._dfac: dict = {}
        self.one = (ring.const(1), 1, {})
        self.zero = (ring.const(0), 1, {})

    # ------------------------------------------------------------------ construction
    def const(self, q) -> tuple:
        q = Fraction(q)
        return (self.ring.const(q.numerator), q.denominator, {})

    def var(self, i: int) -> tuple:
        return (self.ring.var(i), 1, {})

    def is_zero(self, a) -> bool:
        return self.ring.is_zero(a[0])

    def _factor(self, p) -> int:
        key = p if self.ring.name == "stdlib" else str(p)
        i = self._index.get(key)
        if i is None:
            i = self._index[key] = len(self.factors)
            self.factors.append(p)
        return i

    def _pow_factors(self, F: dict):
        out = self.ring.const(1)
        for i, e in F.items():
            if e:
                out = out * self.factors[i] ** e
        return out

    def _norm(self, num, c: int, F: dict) -> tuple:
        if self.ring.is_zero(num):
            return self.zero
        for i, e in F.items():  # a factor of the denominator that divides num: cancelled
            while e < 0 and (q := self.ring.divexact(num, self.factors[i])) is not None:
                num, e = q, e + 1
            F[i] = e
        if c > 1 and (g := gcd(self.ring.content(num), c)) > 1:
            num, c = self.ring.scale_div(num, g), c // g
        return (num, c, {i: e for i, e in F.items() if e})

    # ------------------------------------------------------------------ arithmetic
    def add(self, a, b) -> tuple:
        if self.ring.is_zero(a[0]):
            return b
        if self.ring.is_zero(b[0]):
            return a
        (na, ca, Fa), (nb, cb, Fb) = a, b
        low = {i: min(Fa.get(i, 0), Fb.get(i, 0)) for i in set(Fa) | set(Fb)}
        c = ca * cb // gcd(ca, cb)
        na = self.ring.scale(na * self._pow_factors({i: Fa.get(i, 0) - e
                                                     for i, e in low.items()}), c // ca)
        nb = self.ring.scale(nb * self._pow_factors({i: Fb.get(i, 0) - e
                                                     for i, e in low.items()}), c // cb)
        return self._norm(na + nb, c, low)

    def neg(self, a) -> tuple:
        return (-a[0], a[1], a[2])

    def sub(self, a, b) -> tuple:
        return self.add(a, self.neg(b))

    def mul(self, a, b) -> tuple:
        (na, ca, Fa), (nb, cb, Fb) = a, b
        F = dict(Fa)
        for i, e in Fb.items():
            F[i] = F.get(i, 0) + e
        return self._norm(na * nb, ca * cb, F)

    def inv(self, a) -> tuple:
        num, c, F = a
        F = {i: -e for i, e in F.items()}
        k = self.ring.constant(num)
        if k == 0:
            raise Vanishing("division by the zero rational function")
        if k is not None:
            return (self.ring.const(c if k > 0 else -c), abs(k), F)
        g = self.ring.content(num)
        num = self.ring.scale_div(num, g)
        i = self._factor(num)
        F[i] = F.get(i, 0) - 1
        return self._norm(self.ring.const(c), g, F)

    def div(self, a, b) -> tuple:
        return self.mul(a, self.inv(b))

    def pow(self, a, n: int) -> tuple:
        if n < 0:
            a, n = self.inv(a), -n
        num, c, F = a
        return (num ** n, c ** n, {i: e * n for i, e in F.items()})

    def sqrt(self, a) -> tuple:
        raise ValueError("sqrt: a square root outside K(s) (a definition's statement may "
                         "hold one)")

    # ------------------------------------------------------------------ time derivative
    def dpoly(self, p):
        out = self.ring.const(0)
        for i, j in self.next.items():
            dp = self.ring.deriv(p, i)
            if not self.ring.is_zero(dp):
                out = out + dp * self.ring.var(j)
        return out

    def d(self, a) -> tuple:
        """The time derivative of ``a`` (jets: ``x_k -> x_(k+1)``)."""
        num, c, F = a
        live = [i for i, e in F.items() if e]
        prod_all = self.ring.const(1)
        for i in live:
            prod_all = prod_all * self.factors[i]
        top = self.dpoly(num) * prod_all
        for i in live:
            if i not in self._dfac:
                self._dfac[i] = self.dpoly(self.factors[i])
            rest = self.ring.const(F[i])
            for j in live:
                if j != i:
                    rest = rest * self.factors[j]
            top = top + num * self._dfac[i] * rest
        return self._norm(top, c, {i: F[i] - 1 for i in live})

    # ------------------------------------------------------------------ values
    def value(self, a, values: list) -> Fraction:
        """The value at a point (one ``Fraction`` per variable).

        Raises:
            Vanishing: a factor of the denominator is zero there.
        """
        num, c, F = a
        v = Fraction(self.ring.evaluate(num, values), c)
        for i, e in F.items():
            f = self.ring.evaluate(self.factors[i], values)
            if f == 0:
                raise Vanishing("a divisor vanishes at the point")
            v *= Fraction(f) ** e
        return v


class Root:
    """K(s), s^2 = d, over the Field K: ``a + b s`` as ``(a, b)``; d is the radicand of the
    first square root met (another radicand is not decided). Zero is decided as a = b = 0,
    which makes a + b sqrt(d) zero whether or not d is a square in K (so never a false
    identity); a divisor a^2 - b^2 d that is the zero function is a Vanishing."""

    def __init__(self, F: Field):
        self.F, self.d = F, None
        self.one, self.zero = (F.one, F.zero), (F.zero, F.zero)

    def lift(self, a) -> tuple:
        return (a, self.F.zero)

    def const(self, q) -> tuple:
        return self.lift(self.F.const(q))

    def is_zero(self, a) -> bool:
        return self.F.is_zero(a[0]) and self.F.is_zero(a[1])

    def add(self, a, b) -> tuple:
        return (self.F.add(a[0], b[0]), self.F.add(a[1], b[1]))

    def neg(self, a) -> tuple:
        return (self.F.neg(a[0]), self.F.neg(a[1]))

    def sub(self, a, b) -> tuple:
        return self.add(a, self.neg(b))

    def _d(self, y) -> tuple:  # y d (y's part is zero until a square root is met)
        return self.F.mul(y, self.d) if self.d is not None else self.F.zero

    def mul(self, a, b) -> tuple:
        F, (x, y), (u, v) = self.F, a, b
        if F.is_zero(y) and F.is_zero(v):  # both in K
            return (F.mul(x, u), F.zero)
        return (F.add(F.mul(x, u), self._d(F.mul(y, v))), F.add(F.mul(x, v), F.mul(y, u)))

    def inv(self, a) -> tuple:
        F, (x, y) = self.F, a
        n = F.inv(F.sub(F.mul(x, x), self._d(F.mul(y, y))))
        return (F.mul(x, n), F.neg(F.mul(y, n)))

    def div(self, a, b) -> tuple:
        return self.mul(a, self.inv(b))

    def pow(self, a, n: int) -> tuple:
        a, out = (self.inv(a) if n < 0 else a), self.one
        for _ in range(abs(n)):
            out = self.mul(out, a)
        return out

    def sqrt(self, a) -> tuple:
        if not self.F.is_zero(a[1]) or self.d is not None and not self.F.is_zero(
                self.F.sub(a[0], self.d)):
            raise ValueError("sqrt: a second radicand (one square root per relation)")
        self.d = a[0]
        return (self.F.zero, self.F.one)


def evaluate(node, field: Field, leaf, trig, memo: dict):
    """The value of a parsed tree in ``field``: ``leaf(name)`` gives an atom's value,
    ``trig(kind, argument tree)`` a cosine's or sine's; ``memo`` (by node identity) makes a
    shared subtree cost once (the nodes are kept alive in ``memo[None]``, so an identity is
    never reused by a later tree), and so do two subtrees that are one expression: an atom
    is one element, an operation on the same elements is done once. Iterative, so a deep
    tree does not hit the recursion limit."""
    keep = memo.setdefault(None, [])
    stack = [(node, False)]
    while stack:
        n, ready = stack.pop()
        key = id(n)
        if key in memo:
            continue
        if not ready:
            keep.append(n)
        tag = n[0]
        if tag in ("num", "name", "pi", "cos", "sin"):  # by value (a cos/sin by its argument)
            if (tag, n[1:]) not in memo:
                memo[tag, n[1:]] = field.const(n[1]) if tag == "num" else leaf(
                    n[1]) if tag == "name" else leaf("pi") if tag == "pi" else trig(tag, n[1])
            memo[key] = memo[tag, n[1:]]
        elif not ready:
            stack.append((n, True))
            stack.extend((k, False) for k in n[1:] if isinstance(k, tuple))
        else:  # by the identity of its operands' elements (kept alive in memo)
            args = [memo[id(k)] if isinstance(k, tuple) else k for k in n[1:]]
            op = (tag, *(a if isinstance(a, int) else id(a) for a in args))  # pow's n
            if op not in memo:
                memo[op] = getattr(field, tag)(*args)
            memo[key] = memo[op]
    return memo[id(node)]
