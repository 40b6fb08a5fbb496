"""The compensated difference of products ``a b - c d``.

``a b - c d`` with ``a b`` close to ``c d`` loses ``u |a b| / |a b - c d|`` relative in
floating point: a cross product ``p1 x p2`` of two nearly parallel vectors (the moment of a
line through two nearly coincident points far from the origin). Kahan's algorithm with a
fused multiply-add (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed.,
sol. to problem 2.26; error at most 2 u, Jeannerod, Louvet and Muller, Math. Comp. 82, 2013)::

    w = c d;  e = fma(-c, d, w);  f = fma(a, b, -w);  return f + e

In C it is ``rigidsym_diffprod`` (``c_common.h``: C99 ``fma``, a hardware instruction on
x86-64-v3 and -v4). NumPy, PyTorch and JAX have no fused multiply-add: there ``a b`` and
``c d`` are split exactly into a rounded product and its error (Dekker's product, Veltkamp's
splitting with ``2**ceil(p/2) + 1``, ``p`` the precision of the dtype: float32, float64 and
the long double of the rescue alike), and ``f`` is the exactly rounded ``a b - w`` wherever
``a b`` and ``w`` are within a factor 2 (Sterbenz: the cancelling case), so the result is
Kahan's bit for bit there and within 2 u of the truth everywhere.

:class:`DiffProd` is the sympy node the code generator writes
(:mod:`rigidsym.codegen.accuracy.rewrites`); :func:`diffprod` its NumPy evaluation, which the
generated NumPy modules carry as ``_diffprod`` (:data:`NUMPY_SOURCE`).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from rigidsym.codegen.backends.printing import ARRAY_SOURCE as ARRAY_SOURCE
from rigidsym.codegen.backends.printing import NUMPY_SOURCE as NUMPY_SOURCE

__all__ = ["DiffProd", "SumProd", "diffprod", "sumprod", "expand_diffprod", "compensated_sums",
           "expand_numerators", "expand_plain", "NUMPY_SOURCE", "ARRAY_SOURCE"]


class DiffProd(sp.Function):
    """``DiffProd(a, b, c, d) = a b - c d``, evaluated compensated by every printer."""

    nargs = 4

    def fdiff(self, argindex=1):
        a, b, c, d = self.args
        return (b, a, -d, -c)[argindex - 1]

    def _eval_rewrite_as_Add(self, a, b, c, d, **kwargs):
        return a * b - c * d

    def _eval_evalf(self, prec):
        # of numbers (a program run by substitution): the exact value's; of symbols: kept
        if all(a.is_number for a in self.args):
            return self._eval_rewrite_as_Add(*self.args)._eval_evalf(prec)
        return None


class SumProd(sp.Function):
    """``SumProd(a1, b1, ..., an, bn) = a1 b1 + ... + an bn`` (n = 2, 3 or 4), evaluated
    compensated by every printer: Ogita, Rump and Oishi's Dot2 (SIAM J. Sci. Comput. 26, 2005,
    Algorithm 5.3), as if computed in twice the working precision and then rounded: the
    error is at most ``u |s| + gamma_n^2 sum |a_i b_i|``, so a dot product that cancels (the
    pitch ``a_dot . omega / ||omega||^2`` of a twist nearly perpendicular to its axis) keeps
    about 1 u where the plain sum loses ``u sum |a_i b_i| / |s|``."""

    def fdiff(self, argindex=1):
        i = argindex - 1
        return self.args[i ^ 1]

    def _eval_rewrite_as_Add(self, *args, **kwargs):
        return sp.Add(*[args[i] * args[i + 1] for i in range(0, len(args), 2)])

    def _eval_evalf(self, prec):
        if all(a.is_number for a in self.args):
            return self._eval_rewrite_as_Add(*self.args)._eval_evalf(prec)
        return None


def expand_diffprod(expr):
    """``expr`` with every :class:`DiffProd` written out as ``a b - c d`` and every
    :class:`SumProd` as its sum of products."""
    expr = sp.sympify(expr).replace(lambda x: isinstance(x, SumProd),
                                    lambda x: sp.Add(*[x.args[i] * x.args[i + 1] for i in
                                                       range(0, len(x.args), 2)]))
    return expr.replace(lambda x: isinstance(x, DiffProd),
                        lambda x: x.args[0] * x.args[1] - x.args[2] * x.args[3])


def _load(name: str):
    ns: dict = {"numpy": np}
    exec(compile(NUMPY_SOURCE, "<rigidsym.codegen.accuracy.compensated>", "exec"), ns)  # noqa: S102
    return ns[name]


#: :func:`_diffprod` of the generated NumPy modules, for the generator's own measurements
diffprod = _load("_diffprod")
#: and :func:`_sumprod`
sumprod = _load("_sumprod")


#: expressions larger than this (operations) are not expanded
EXPAND_LIMIT = 60


def _compensated(n):
    """``n`` (expanded) as a :class:`DiffProd` when it is ``+-a b +- c d`` (every sign: a
    sum of products of opposite signs cancels as a difference does); else None."""
    if not n.is_Add or len(n.args) != 2:
        return None
    pairs = []
    for t in n.args:
        c, fs = t.as_coeff_mul()
        if c not in (1, -1):
            return None
        fs = [f for x in fs for f in ([x.base] * int(x.exp) if x.is_Pow and x.exp.is_Integer
                                      and 1 <= x.exp <= 2 else [x])]
        if len(fs) != 2:
            return None
        pairs.append((c * fs[0], fs[1]))
    (a, b), (c, d) = sorted(pairs, key=lambda ab: sp.default_sort_key(ab[0] * ab[1]))
    return DiffProd(a, b, -c, d)


def expand_plain(flat, ctx):
    """The expanded numerator without compensation (the form ``p1 x p2``): offered
    so that the accuracy rule chooses between it and the compensated one; it loses the
    exactness of ``p2 - p1`` at nearly coincident points and fails the rule there."""
    return expand_numerators(flat, ctx, compensate=False)


def expand_numerators(flat, ctx, compensate: bool = True):
    """Each small output ``n / d`` with its numerator expanded: cancelling terms of the
    declared grouping (``p1 x (p2 - p1)``) cancel symbolically, not in floating point; a
    numerator then of two products (a cross product ``p1 x p2``) is a compensated
    difference of products (:mod:`rigidsym.codegen.accuracy.compensated`): ``p1 x p2`` of nearly
    parallel points cancels in floating point as ``p1 x (p2 - p1)`` did not."""
    out, parts = [], []
    for e in flat:
        if e.has(sp.Piecewise) or sp.count_ops(e) > EXPAND_LIMIT or ctx["angles"] and \
                e.has(*ctx["angles"]):
            out.append(e)
            continue
        n, d, ne, longer = _expanded(e)
        if longer or ne == n:
            out.append(e)
            continue
        ne = (_compensated(ne) if compensate else None) or ne
        out.append(ne / d)
        parts.append((n, ne))
    return (out, parts) if parts else None


@lru_cache(maxsize=4096)
def _expanded(e) -> tuple:
    """``(n, d, expanded n, whether it is 4 or more operations longer)`` of ``e = n / d``:
    the plain and the compensated proposal (and a kernel's Jacobian twin, of the same
    values) expand the same outputs."""
    n, d = sp.fraction(sp.together(e))
    ne = sp.expand(n)
    return n, d, ne, sp.count_ops(ne) >= sp.count_ops(n) + 4


def _pairs(add):
    """``add`` as ``[(a1, b1), ...]`` with ``add = sum a_i b_i`` (a term of one factor: ``(a,
    1)``; a coefficient +-2^k folded into the first factor, exactly), or None."""
    pairs = []
    for t in add.args:
        c, fs = t.as_coeff_mul()
        fs = [f for x in fs for f in ([x.base] * int(x.exp) if x.is_Pow and x.exp.is_Integer
                                      and 2 <= x.exp <= 2 else [x])]
        m = abs(c)
        if not (c.is_Rational and m.p & (m.p - 1) == 0 and m.q & (m.q - 1) == 0) or \
                not 1 <= len(fs) <= 2:
            return None
        pairs.append((c * fs[0], fs[1]) if len(fs) == 2 else (c * fs[0], sp.S.One))
    return pairs


def _common_factor(add):
    """``(g, rest)`` with ``add = g rest``, ``g`` the product of the factors every term of
    ``add`` shares (``e . d`` with ``e = v / ||v||``: ``(1/||v||, v . d)``)."""
    terms = [sp.Mul.make_args(t) for t in add.args]
    common = [f for f in terms[0] if not f.is_Number and all(f in t for t in terms[1:])]
    if not common:
        return sp.S.One, add
    g = sp.Mul(*common)
    return g, sp.Add(*[sp.Mul(*[f for f in t if f not in common]) for t in terms])


def _trig(f) -> bool:
    """Whether the factor ``f`` is a trigonometric function (or a power of one)."""
    b = f.base if f.is_Pow else f
    return isinstance(b, (sp.functions.elementary.trigonometric.TrigonometricFunction,
                          sp.functions.elementary.trigonometric.InverseTrigonometricFunction,
                          sp.atan2))


def _sum_of_products(e):
    """``e`` as a :class:`SumProd` where it is a sum of 2 to 4 products of at most two
    factors (after a common factor), not all squares, no term a multiple of a trigonometric
    function (``k cos(phi) - k``: the half-angle rewrite's); else None."""
    if not e.is_Add or not 2 <= len(e.args) <= 4 or \
            any(_trig(f) for t in e.args for f in sp.Mul.make_args(t)):
        return None
    g, rest = _common_factor(e)
    if not rest.is_Add or len(rest.args) != len(e.args):
        return None
    pairs = _pairs(rest)
    if pairs is None or all(b == 1 for _, b in pairs) or all(a == b for a, b in pairs):
        return None
    pairs.sort(key=lambda ab: ab[1] == 1)       # a symbol first: the helpers read its type
    return g * SumProd(*[x for ab in pairs for x in ab])


def compensated_sums(flat, ctx):
    """Each sum of two to four products in an output (a dot product, a component of a cross
    product plus a term) as a compensated :class:`SumProd`: a sum that cancels (the pitch
    ``a_dot . omega / ||omega||^2`` of a twist nearly perpendicular to its axis, ``e .
    (a' - a)``) loses ``u sum |a_i b_i| / |s|`` plainly and about 1 u compensated. Not in
    the branches' conditions, nor in a sum with a term that is a multiple of a
    trigonometric function (``k cos(phi) - k``: the half-angle rewrite reads those). A rule of
    :mod:`rigidsym.codegen.accuracy.rewrites`: ``(outputs, [(old, new) parts])`` or None."""
    parts = []

    def walk(e):
        if e.is_Relational or e.is_Atom:
            return e
        args = [walk(a) for a in e.args]
        e2 = e.func(*args) if any(a is not b for a, b in zip(args, e.args, strict=True)) \
            else e
        got = _sum_of_products(e2)
        if got is None:
            return e2
        parts.append((e, got))
        return got

    out = [walk(e) for e in flat]
    return (out, parts) if parts else None
