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
from math import gcd

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
            if mb == 0 and cb == 1:  # times 1: the same terms (a Poly is never mutated)
                return Poly(a, self.deg + other.deg)
            return Poly({m + mb: c * cb for m, c in a.items()}, self.deg + other.deg)
        t: dict = {}
        get = t.get
        for mb, cb in b.items():
            for ma, ca in a.items():
                k = ma + mb
                t[k] = get(k, 0) + ca * cb
        return Poly(t if all(t.values()) else {m: c for m, c in t.items() if c},
                    self.deg + other.deg)

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
        self.guard = sum(1 << (WIDTH * i + WIDTH - 1) for i in range(len(self.names) + 1))

    def const(self, c: int) -> Poly:
        return Poly({0: c} if c else {}, 0)

    def var(self, i: int) -> Poly:
        return Poly({1 << (WIDTH * i): 1}, 1)

    def is_zero(self, p: Poly) -> bool:
        return not p.terms

    def constant(self, p: Poly):
        """The constant ``int`` when ``p`` is one, else ``None``."""
        return None if p.terms.keys() - {0} else p.terms.get(0, 0)

    def content(self, p: Poly) -> int:
        return gcd(*p.terms.values())  # 0 for the zero polynomial

    def scale_div(self, p: Poly, d: int) -> Poly:
        return Poly({m: c // d for m, c in p.terms.items()}, p.deg)

    def scale(self, p: Poly, d: int) -> Poly:
        return p if d == 1 else Poly({m: c * d for m, c in p.terms.items()} if d else {}, p.deg)

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
        """``p / f`` when the primitive ``f`` divides ``p``, else ``None``: division by the
        leading term in the packed order (a monomial order), the remainder's highest term
        first; the quotient is integral (Gauss's lemma), so a coefficient that does not
        divide stops it, as does a leading monomial that is not a multiple of f's."""
        if max(p.deg, f.deg) >= 1 << (WIDTH - 1):  # the guard bits need exponents < 2^15
            return None
        lead, guard = max(f.terms), self.guard  # p's first and last terms: f's times q's
        for m, g in ((max(p.terms), lead), (min(p.terms), min(f.terms))):
            if ((m | guard) - g) & guard != guard or p.terms[m] % f.terms[g]:
                return None
        lc, rest = f.terms[lead], [(m - lead, c) for m, c in f.terms.items() if m != lead]
        pending, q = dict(p.terms), {}
        heap = [-m for m in pending]
        heapq.heapify(heap)
        while heap:
            m = -heapq.heappop(heap)
            if not (c := pending.pop(m)):
                continue
            if ((m | guard) - lead) & guard != guard or c % lc:
                return None
            q[m - lead] = qc = c // lc
            for d, fc in rest:  # m + d < m: a monomial popped never comes back
                if (k := m + d) in pending:
                    pending[k] -= qc * fc
                else:
                    pending[k] = -qc * fc
                    heapq.heappush(heap, -k)
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
        q, r = divmod(p, f)  # p / f when the remainder is zero, else None
        return q if r.is_zero() else None


def make_ring(names: list[str], fast: bool = True) -> Ring:
    """A :class:`FlintRing` when ``fast`` and python-flint imports, else a :class:`Ring`."""
    if fast:
        try:
            return FlintRing(names)
        except ImportError:
            pass
    return Ring(names)
