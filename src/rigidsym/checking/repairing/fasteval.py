"""The repair search's fast filter: a book-symbol tree evaluated at fixed exact points,
modulo a 61-bit prime, reusing the values of unchanged subtrees.

Why modulo a prime, and why it is exact: every book symbol's model value, parametrised as
the zero test does (:mod:`rigidsym.zero.plan`), is a rational function over Q of free
parameters. At a rational point its value ``a/b`` reduces modulo ``p`` to ``a b⁻¹`` whenever
``p`` does not divide ``b``, and reduction is a ring homomorphism: sums, products,
transposes, traces, determinants and inverses of the reduced values are the reductions of
the exact ones. So a candidate whose two sides differ modulo ``p`` differs at that rational
point, and does not hold: rejecting it is exact, never a guess. A candidate equal modulo
``p`` at every point is only a *survivor*: the full sound zero test
(:func:`rigidsym.zero.decide.decide_zero`) decides it. A zero denominator modulo ``p``, or
a node this evaluator does not know (an irrational root at the point), makes the point
inconclusive, and the candidate survives.

Values are memoised on the (hash-consed) sympy node: a candidate that differs from the
printed form in one subterm costs the nodes on the path from that subterm to the root.
Scalars are ``flint.nmod``, matrices ``flint.nmod_mat`` (python-flint: FLINT's word-size
modular arithmetic).
"""

from __future__ import annotations

import hashlib
import random
from fractions import Fraction

import flint
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.matrices.expressions.slice import MatrixSlice

from rigidsym.algebra.operators import Cpm, Cross, Det, Vect
from rigidsym.checking.deciding.explicit import entries_of, explicit, explicit_scalar
from rigidsym.checking.repairing.treeops import RawBlocks
from rigidsym.zero.decide import Unsupported, evaluate

__all__ = ["PRIME", "Inconclusive", "Undecidable", "PointValues", "GenericValues", "points_for",
           "differs", "difference"]

#: the modulus: the Mersenne prime 2^61 - 1 (fits FLINT's word-size ``nmod``)
PRIME = 2**61 - 1
_FAIL = object()
_NEVER = object()


class Inconclusive(Exception):
    """The point cannot tell: a zero denominator modulo the prime."""


class Undecidable(Inconclusive):
    """No point can tell, and neither can the zero test: a node the exact evaluator does not
    treat (an irrational root such as an odd power of ``‖ω‖``, a trigonometric function of
    a non-angle)."""


def _lift(r) -> flint.nmod:
    q = int(r.q) % PRIME
    if q == 0:
        raise ZeroDivisionError("denominator divisible by the prime")
    return flint.nmod(int(r.p), PRIME) / flint.nmod(q, PRIME)


def _zero_mat(rows: int, cols: int) -> flint.nmod_mat:
    return flint.nmod_mat(rows, cols, PRIME)


class PointValues:
    """Values of book-symbol trees at one exact point, modulo :data:`PRIME`.

    Args:
        model: the statement's model (book symbol -> first-principles value).
        plan: the zero test's plan covering every atom of the model and of the members.
        point: a value (``Fraction``) for each parameter of the plan.
    """

    def __init__(self, model: dict, plan, point: dict):
        self.model, self.plan = model, plan
        self.point = {k: _lift(sp.Rational(v.numerator, v.denominator))
                      for k, v in point.items()}
        self.memo: dict = {}

    # ------------------------------------------------------------------ public
    def value(self, x):
        """The value of ``x`` (``nmod`` or ``nmod_mat``).

        Raises:
            Inconclusive: when this point cannot evaluate ``x``.
        """
        hit = self.memo.get(x)
        if hit is not None:
            if hit is _FAIL:
                raise Inconclusive(str(x)[:80])
            if hit is _NEVER:
                raise Undecidable(str(x)[:80])
            return hit
        try:
            v = self._value(x)
        except (Undecidable, Unsupported) as exc:
            self.memo[x] = _NEVER
            raise Undecidable(str(exc)[:80]) from exc
        except (Inconclusive, ZeroDivisionError, TypeError, KeyError, ValueError,
                AttributeError, IndexError) as exc:
            self.memo[x] = _FAIL
            raise Inconclusive(str(exc)[:80]) from exc
        self.memo[x] = v
        return v

    # ------------------------------------------------------------------ exact leaves
    def _exact(self, e) -> flint.nmod:
        return evaluate(e, self.plan, self.point, lift=_lift)

    def _explicit(self, x):
        """A node through the model and the exact evaluator (the slow path)."""
        if isinstance(x, sp.MatrixExpr | sp.MatrixBase):
            m = explicit(x, self.model)
            return flint.nmod_mat(m.rows, m.cols, [self._exact(e) for e in entries_of(m)],
                                  PRIME)
        return self._exact(explicit_scalar(x, self.model))

    # ------------------------------------------------------------------ structure
    def _value(self, x):  # noqa: C901  one case per node class, as sympy's printers
        if isinstance(x, sp.Basic) and x.is_Rational:
            return _lift(x)
        if isinstance(x, sp.MatrixSymbol | sp.Symbol | AppliedUndef | sp.Derivative):
            return self._explicit(x)
        if isinstance(x, sp.Identity):
            n = int(x.rows)
            m = _zero_mat(n, n)
            for i in range(n):
                m[i, i] = 1
            return m
        if isinstance(x, sp.ZeroMatrix):
            return _zero_mat(int(x.rows), int(x.cols))
        if isinstance(x, sp.MatrixBase):
            return flint.nmod_mat(x.rows, x.cols, [self._scalar(e) for e in x], PRIME)
        if isinstance(x, sp.MatAdd | sp.Add):
            vals = [self.value(a) for a in x.args]
            acc = vals[0]
            for v in vals[1:]:
                acc = acc + v
            return acc
        if isinstance(x, sp.MatMul | sp.Mul):
            return self._product(x)
        if isinstance(x, sp.Pow | sp.MatPow) and x.exp.is_Integer:
            return self._power(x)
        if isinstance(x, sp.Transpose):
            v = self.value(x.arg)
            return v.transpose() if isinstance(v, flint.nmod_mat) else v
        if isinstance(x, sp.Inverse):
            return self.value(x.arg).inv()
        if isinstance(x, sp.Trace):
            v = self.value(x.arg)
            return sum((v[i, i] for i in range(1, v.nrows())), v[0, 0])
        if isinstance(x, sp.Determinant | Det):
            return self.value(x.args[0]).det()
        if isinstance(x, MatrixElement):
            return self._matrix(x.parent)[int(x.i), int(x.j)]
        if isinstance(x, MatrixSlice):
            return self._slice(x)
        if isinstance(x, sp.BlockMatrix):
            b = x.blocks
            return self._blocks([[b[i, j] for j in range(b.cols)] for i in range(b.rows)])
        if isinstance(x, RawBlocks):
            return self._blocks(x.grid)
        if isinstance(x, Cross):
            u, v = (self._matrix(a) for a in x.args)
            k = [u[(i + 1) % 3, 0] * v[(i + 2) % 3, 0] - u[(i + 2) % 3, 0] * v[(i + 1) % 3, 0]
                 for i in range(3)]
            return flint.nmod_mat(3, 1, k, PRIME)
        if isinstance(x, Cpm):  # the lazy CPM(v) of a book symbol (Eq. (2.38))
            v = self._matrix(x.args[0])
            z = flint.nmod(0, PRIME)
            return flint.nmod_mat(3, 3, [z, -v[2, 0], v[1, 0], v[2, 0], z, -v[0, 0],
                                         -v[1, 0], v[0, 0], z], PRIME)
        if isinstance(x, Vect):  # the lazy vect(A): half the skew part's axial vector
            a = self._matrix(x.args[0])
            half = flint.nmod(1, PRIME) / 2
            return flint.nmod_mat(3, 1, [half * (a[2, 1] - a[1, 2]), half * (a[0, 2] - a[2, 0]),
                                         half * (a[1, 0] - a[0, 1])], PRIME)
        return self._explicit(x)  # trig of angles, roots, custom operators

    def _scalar(self, e):
        v = self.value(e)
        if isinstance(v, flint.nmod_mat):
            if (v.nrows(), v.ncols()) != (1, 1):
                raise Inconclusive("a matrix where a scalar belongs")
            return v[0, 0]
        return v

    def _matrix(self, e) -> flint.nmod_mat:
        v = self.value(e)
        return v if isinstance(v, flint.nmod_mat) else flint.nmod_mat(1, 1, [v], PRIME)

    def _product(self, x):
        scal = flint.nmod(1, PRIME)
        mat = None
        for a in x.args:
            v = self.value(a)
            if isinstance(v, flint.nmod_mat):
                mat = v if mat is None else mat * v
            else:
                scal = scal * v
        if mat is None:
            return scal
        return mat * scal if scal != 1 else mat

    def _power(self, x):
        try:
            b = self.value(x.base)
        except Undecidable:
            if isinstance(x, sp.Pow):  # sqrt(X)^-2 in the model: sympy simplifies it
                return self._explicit(x)
            raise
        n = int(x.exp)
        if isinstance(b, flint.nmod_mat):
            if n < 0:
                b, n = b.inv(), -n
            acc = flint.nmod_mat(b.nrows(), b.ncols(), PRIME)
            for i in range(b.nrows()):
                acc[i, i] = 1
            for _ in range(n):
                acc = acc * b
            return acc
        return b**n

    def _slice(self, x):
        v = self._matrix(x.parent)
        rows = range(*[int(s) for s in x.rowslice])
        cols = range(*[int(s) for s in x.colslice])
        return flint.nmod_mat(len(rows), len(cols), [v[i, j] for i in rows for j in cols],
                              PRIME)

    def _blocks(self, grid: list[list]):
        vals = [[self._matrix(x) for x in row] for row in grid]
        rows = sum(row[0].nrows() for row in vals)
        cols = sum(v.ncols() for v in vals[0])
        out = _zero_mat(rows, cols)
        r0 = 0
        for i in range(len(vals)):
            c0 = 0
            for j in range(len(vals[0])):
                v = vals[i][j]
                for r in range(v.nrows()):
                    for c in range(v.ncols()):
                        out[r0 + r, c0 + c] = v[r, c]
                c0 += v.ncols()
            r0 += vals[i][0].nrows()
        return out


def differs(pv: PointValues, lhs, rhs) -> bool:
    """Whether the two sides differ at the point (a proof that ``lhs = rhs`` fails).

    Raises:
        Inconclusive: when the point cannot evaluate a side.
    """
    a, b = pv.value(lhs), pv.value(rhs)
    if isinstance(a, flint.nmod_mat) or isinstance(b, flint.nmod_mat):
        a, b = pv._matrix(lhs), pv._matrix(rhs)
        if (a.nrows(), a.ncols()) != (b.nrows(), b.ncols()):
            return True
    return a != b


def difference(pv: PointValues, lhs, rhs):
    """``lhs - rhs`` at the point (``nmod`` or ``nmod_mat``; a scalar as 1 x 1).

    Raises:
        Inconclusive: when the point cannot evaluate a side.
    """
    a, b = pv._matrix(lhs), pv._matrix(rhs)
    if (a.nrows(), a.ncols()) != (b.nrows(), b.ncols()):
        raise Inconclusive("the sides have different shapes")
    return a - b


def points_for(model: dict, plan, sides: list, seed: int, count: int = 2) -> list:
    """``count`` points at which every side in ``sides`` evaluates (off the singular set
    and off the prime's zero divisors), drawn from a seeded generator.

    Returns fewer points when no such point is found in 20 draws each (then every candidate
    survives to the full test, which is slower but still exact).
    """
    rng = random.Random(seed)
    out = []
    for _ in range(20 * count):
        if len(out) == count:
            break
        pt = {p: Fraction(rng.randint(-(2**20), 2**20), rng.randint(1, 2**20))
              for p in plan.params}
        pv = PointValues(model, plan, pt)
        try:
            for s in sides:
                pv.value(s)
        except Inconclusive:
            continue
        out.append(pv)
    return out


class GenericValues(PointValues):
    """Values with the book symbols left unsubstituted: every entry of a matrix symbol, every
    scalar symbol and every function application (``sin φ``) gets its own pseudo-random
    residue (from a hash of its name, the same in every run), as if it were an independent
    variable, which is how ``sympy.expand`` treats them.

    Two book-symbol expressions with different values here differ after expansion (the
    reduction is a ring homomorphism again), so the expansion is needed only to confirm an
    equality: :mod:`rigidsym.checking.repairing.repair` uses it to recognise a trivial candidate
    (``Eᵀ = Eᵀ``), the same repair found twice, and a repair equal to the declared one.
    """

    def __init__(self):
        super().__init__({}, None, {})

    @staticmethod
    def _residue(key: str) -> flint.nmod:
        digest = hashlib.blake2b(key.encode(), digest_size=16).digest()
        return flint.nmod(int.from_bytes(digest, "little"), PRIME)

    def _explicit(self, x):
        if isinstance(x, sp.MatrixSymbol):
            r, c = (int(n) for n in x.shape)
            return flint.nmod_mat(r, c, [self._residue(f"{x.name}[{i},{j}]")
                                         for i in range(r) for j in range(c)], PRIME)
        if isinstance(x, sp.MatrixExpr | sp.MatrixBase):
            raise Undecidable(f"no generic value for {type(x).__name__}")
        return self._residue(sp.srepr(x))
