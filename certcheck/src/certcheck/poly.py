"""Sparse multivariate polynomials over the integers, standard library only.

A polynomial is a dict ``{monomial: coefficient}`` with non-zero ``int`` coefficients. A
monomial is one ``int`` that packs the exponents, :data:`WIDTH` bits per variable
(variable ``i`` at bit ``i * WIDTH``), so multiplying monomials is adding integers. A
total-degree bound travels with each polynomial and is checked before it could overflow a
field, so two different monomials never share a packed value.

:class:`Ring` is the interface the rest of the checker uses; :class:`FlintRing` gives the
same operations on python-flint's ``fmpz_mpoly`` when it is installed (an optional fast
path: the answers are the same, a test compares them).
"""

from __future__ import annotations

import heapq

WIDTH = 16
MASK = (1 << WIDTH) - 1
MAX_DEGREE = MASK


class Poly:
    """A polynomial of a :class:`Ring`: ``terms`` (packed monomial -> int) and ``deg``, an
    upper bound on the total degree."""

    __slots__ = ("terms", "deg")

    def __init__(self, terms: dict, deg: int):
        if deg > MAX_DEGREE:
            raise OverflowError("total degree above 65535: the packed monomials would overlap")
        self.terms = terms
        self.deg = deg

    def __add__(self, other: Poly) -> Poly:
        if len(self.terms) < len(other.terms):
            self, other = other, self
        t = dict(self.terms)
        get = t.get
        for m, c in other.terms.items():
            v = get(m, 0) + c
            if v:
                t[m] = v
            else:
                del t[m]
        return Poly(t, max(self.deg, other.deg))

    def __neg__(self) -> Poly:
        return Poly({m: -c for m, c in self.terms.items()}, self.deg)

    def __sub__(self, other: Poly) -> Poly:
        return self + (-other)

    def __mul__(self, other: Poly) -> Poly:
        a, b = self.terms, other.terms
        if len(a) < len(b):
            a, b = b, a
        if len(b) == 1:
            ((mb, cb),) = b.items()
            return Poly({m + mb: c * cb for m, c in a.items()}, self.deg + other.deg)
        t: dict = {}
        get = t.get
        for mb, cb in b.items():
            for ma, ca in a.items():
                k = ma + mb
                t[k] = get(k, 0) + ca * cb
        return Poly({m: c for m, c in t.items() if c}, self.deg + other.deg)

    def __pow__(self, n: int) -> Poly:
        out = Poly({0: 1}, 0)
        base = self
        while n:
            if n & 1:
                out = out * base
            n >>= 1
            if n:
                base = base * base
        return out

    def __eq__(self, other) -> bool:
        return isinstance(other, Poly) and self.terms == other.terms

    def __hash__(self) -> int:
        return hash(frozenset(self.terms.items()))


class Ring:
    """Polynomials in ``n`` named variables over the integers (standard library)."""

    name = "stdlib"

    def __init__(self, names: list[str]):
        self.names = list(names)

    def const(self, c: int) -> Poly:
        return Poly({0: c} if c else {}, 0)

    def var(self, i: int) -> Poly:
        return Poly({1 << (WIDTH * i): 1}, 1)

    def is_zero(self, p: Poly) -> bool:
        return not p.terms

    def constant(self, p: Poly):
        """The constant ``int`` when ``p`` is one, else ``None``."""
        if not p.terms:
            return 0
        if len(p.terms) == 1 and 0 in p.terms:
            return p.terms[0]
        return None

    def content(self, p: Poly) -> int:
        from math import gcd
        g = 0
        for c in p.terms.values():
            g = gcd(g, c)
        return g

    def scale_div(self, p: Poly, d: int) -> Poly:
        return Poly({m: c // d for m, c in p.terms.items()}, p.deg)

    def scale(self, p: Poly, d: int) -> Poly:
        return Poly({m: c * d for m, c in p.terms.items()} if d else {}, p.deg)

    def deriv(self, p: Poly, i: int) -> Poly:
        sh = WIDTH * i
        one = 1 << sh
        t = {}
        for m, c in p.terms.items():
            e = (m >> sh) & MASK
            if e:
                t[m - one] = c * e
        return Poly(t, max(p.deg - 1, 0))

    def evaluate(self, p: Poly, values: list):
        """The value at ``values`` (one per variable; ``Fraction`` or ``int``)."""
        total = 0
        for m, c in p.terms.items():
            v = c
            i = 0
            while m:
                e = m & MASK
                if e:
                    v *= values[i] ** e
                m >>= WIDTH
                i += 1
            total += v
        return total

    def nterms(self, p: Poly) -> int:
        return len(p.terms)

    def divexact(self, p: Poly, f: Poly) -> Poly | None:
        """``p / f`` when ``f`` (primitive, not zero) divides ``p`` exactly, else ``None``:
        the division algorithm in the packed order (an integer's order on the packed
        monomials is a monomial order), the remainder's terms taken from the highest by a
        heap; by Gauss's lemma a primitive ``f`` dividing ``p`` over Q gives an integer
        quotient, so a coefficient that does not divide stops it."""
        if not p.terms:
            return p
        if max(p.deg, f.deg) >= 1 << (WIDTH - 1):
            return None  # the guard bits below need exponents under 2^15 (never cancelled)
        lead = max(f.terms)
        lc = f.terms[lead]
        rest = [(m - lead, c) for m, c in f.terms.items() if m != lead]
        guard = sum(1 << (WIDTH * i + WIDTH - 1) for i in range(len(self.names) + 1))
        pending = dict(p.terms)
        heap = [-m for m in pending]
        heapq.heapify(heap)
        q = {}
        while heap:
            m = -heapq.heappop(heap)
            c = pending.pop(m)
            if not c:
                continue
            if ((m | guard) - lead) & guard != guard:
                return None  # the remainder's leading monomial is not a multiple of f's
            qc, r = divmod(c, lc)
            if r:
                return None
            q[m - lead] = qc
            for d, fc in rest:  # m + d < m: a monomial once popped never comes back
                k = m + d
                v = pending.get(k)
                if v is None:
                    pending[k] = -qc * fc
                    heapq.heappush(heap, -k)
                else:
                    pending[k] = v - qc * fc
        return Poly(q, p.deg)


class FlintRing(Ring):
    """The same operations on python-flint's ``fmpz_mpoly`` (optional fast path)."""

    name = "python-flint"

    def __init__(self, names: list[str]):
        import flint
        super().__init__(names)
        self._flint = flint
        self.ctx = flint.fmpz_mpoly_ctx.get([f"x{i}" for i in range(max(len(names), 1))],
                                            "degrevlex")
        self._gens = self.ctx.gens()

    def const(self, c: int):
        return self.ctx.from_dict({(0,) * self.ctx.nvars(): c}) if c else self.ctx.from_dict({})

    def var(self, i: int):
        return self._gens[i]

    def is_zero(self, p) -> bool:
        return p.is_zero()

    def constant(self, p):
        if p.is_zero():
            return 0
        return int(p.leading_coefficient()) if p.total_degree() == 0 else None

    def content(self, p) -> int:
        return int(p.content())

    def scale_div(self, p, d: int):
        return p / d if d != 1 else p

    def scale(self, p, d: int):
        return p * d

    def deriv(self, p, i: int):
        return p.derivative(i)

    def evaluate(self, p, values: list):
        from fractions import Fraction
        total = Fraction(0)
        for exps, c in p.to_dict().items():
            v = Fraction(int(c))
            for x, e in zip(values, exps, strict=False):
                if e:
                    v *= x ** int(e)
            total += v
        return total

    def nterms(self, p) -> int:
        return len(p)

    def divexact(self, p, f):
        """``p / f`` when ``f`` divides ``p`` exactly (remainder zero), else ``None``."""
        q, r = divmod(p, f)
        return q if r.is_zero() else None


def make_ring(names: list[str], fast: bool = True) -> Ring:
    """A :class:`FlintRing` when ``fast`` and python-flint imports, else a :class:`Ring`."""
    if fast:
        try:
            return FlintRing(names)
        except ImportError:
            pass
    return Ring(names)
