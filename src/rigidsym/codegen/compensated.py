"""The compensated difference of products ``a b - c d`` (issue 37).

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
(:mod:`rigidsym.codegen.accurate`); :func:`diffprod` its NumPy evaluation, which the
generated NumPy modules carry as ``_diffprod`` (:data:`NUMPY_SOURCE`).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

__all__ = ["DiffProd", "SumProd", "diffprod", "sumprod", "expand_diffprod", "NUMPY_SOURCE",
           "ARRAY_SOURCE"]


class DiffProd(sp.Function):
    """``DiffProd(a, b, c, d) = a b - c d``, evaluated compensated by every printer."""

    nargs = 4

    def fdiff(self, argindex=1):
        a, b, c, d = self.args
        return (b, a, -d, -c)[argindex - 1]

    def _eval_rewrite_as_Add(self, a, b, c, d, **kwargs):
        return a * b - c * d


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


def expand_diffprod(expr):
    """``expr`` with every :class:`DiffProd` written out as ``a b - c d`` and every
    :class:`SumProd` as its sum of products."""
    expr = sp.sympify(expr).replace(lambda x: isinstance(x, SumProd),
                                    lambda x: sp.Add(*[x.args[i] * x.args[i + 1] for i in
                                                       range(0, len(x.args), 2)]))
    return expr.replace(lambda x: isinstance(x, DiffProd),
                        lambda x: x.args[0] * x.args[1] - x.args[2] * x.args[3])


#: the helper of the generated NumPy kernels (``module`` is ``numpy``); the same text for
#: PyTorch and JAX (:data:`ARRAY_SOURCE`) with their array module
_SOURCE = '''

def _split(x, k):
    # Veltkamp: x = hi + lo exactly, hi of at most p - ceil(p/2) bits
    t = k * x
    hi = t - (t - x)
    return hi, x - hi


def _two_prod(a, b, k):
    # Dekker: a b = p + e exactly (barring underflow)
    p = a * b
    ah, al = _split(a, k)
    bh, bl = _split(b, k)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _diffprod(a, b, c, d):
    """a b - c d compensated (Kahan's algorithm, its fma emulated; rigidsym.codegen.compensated)."""
    k = {splitter}
    p, q = _two_prod(a, b, k)
    w, r = _two_prod(c, d, k)
    s = p - w
    bb = s - p
    t = (p - (s - bb)) + (-w - bb)     # p - w = s + t exactly (Knuth's TwoSum)
    return (s + (t + q)) - r


def _sumprod(*args):
    """a1 b1 + ... + an bn compensated (Dot2 of Ogita, Rump and Oishi)."""
    a = args[0]
    k = {splitter}
    p, s = _two_prod(args[0], args[1], k)
    for i in range(2, len(args), 2):
        h, r = _two_prod(args[i], args[i + 1], k)
        t = p + h
        z = t - p
        s = s + (((p - (t - z)) + (h - z)) + r)     # Knuth's TwoSum error, then the product's
        p = t
    return p + s
'''

#: NumPy: the splitter from the dtype (float32, float64, long double)
NUMPY_SOURCE = _SOURCE.replace(
    "{splitter}", "2.0 ** ((numpy.finfo(a.dtype).nmant + 2) // 2) + 1.0 "
    "if isinstance(a, numpy.ndarray) and a.dtype.kind == 'f' else 134217729.0")
#: PyTorch and JAX (``{module}`` replaced by the array module's name)
ARRAY_SOURCE = _SOURCE.replace(
    "{splitter}", "4097.0 if a.dtype == {module}.float32 else 134217729.0")


def _load(name: str):
    ns: dict = {"numpy": np}
    exec(compile(NUMPY_SOURCE, "<rigidsym.codegen.compensated>", "exec"), ns)  # noqa: S102
    return ns[name]


#: :func:`_diffprod` of the generated NumPy modules, for the generator's own measurements
diffprod = _load("_diffprod")
#: and :func:`_sumprod`
sumprod = _load("_sumprod")


def uses_diffprod(kc) -> bool:
    """Whether a program of ``kc`` has a compensated difference of products (its printed
    module then carries the helper of this module); ``kc`` a
    :class:`rigidsym.codegen.generator.KernelCode`."""
    return any(sp.sympify(e).has(DiffProd, SumProd) for v in kc.variants
               for e in [*(x for _, x in v.program.temps), *v.program.outputs])
