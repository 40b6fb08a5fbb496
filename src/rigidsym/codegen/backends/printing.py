"""What every target's printer of kernel programs shares (sympy's printers extended as
visitors, ``_print_<Class>`` methods, no string surgery):

* small integer powers print as products (``x*x``, ``1.0/(x*x)``), half powers as roots;
* the compensated products of :mod:`rigidsym.codegen.accuracy.compensated` print as calls of
  the helper each printed module defines, or as the name of the temp that holds one;
* a removable quotient prints as its branch (a ``Piecewise``);
* rationals with a power-of-two denominator print exactly (:func:`dyadic_repr`);
* the compensated products' helpers, as the Python targets define them (:data:`NUMPY_SOURCE`,
  :data:`ARRAY_SOURCE`);
* a program printed line by line (:func:`program_lines`), and the names of its divisions and
  roots, divisors and radicands, which the finiteness checks read (:func:`risky_names`).

Each target's printer (``backends/<target>/printer.py``) mixes :class:`KernelPrinterMixin`
into sympy's printer of its language.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import PRECEDENCE

from rigidsym.codegen.optimise import Program, divides_or_roots

__all__ = ["KernelPrinterMixin", "dyadic_repr", "program_lines", "risky_names",
           "divisors_and_radicands", "NUMPY_SOURCE", "ARRAY_SOURCE", "COMPENSATED",
           "is_compensated", "uses_diffprod"]

_MAX_EXPAND = 4


class KernelPrinterMixin:
    """The visitors every kernel printer shares: ``_print_Pow`` (products for small integer
    exponents, roots for halves), the compensated products' helper calls and named temps,
    removable quotients. A printer sets ``_one`` (its literal 1), ``_diffprod`` and
    ``_sumprod`` (its helpers' names) and defines ``_sqrt``."""

    def _as_ordered_terms(self, expr, order=None):
        # sympy's order of an Add's terms, computed once per sum for every printer (five
        # targets print each program: sorting the terms was a third of the printing time)
        order = order or self.order
        if order in ("old", "none"):
            return super()._as_ordered_terms(expr, order=order)
        return list(_ordered_terms(expr, order))

    def _print_QuotientBase(self, expr):
        # a removable quotient (codegen.removable): its branch, series below t*, closed
        # form above at a safe argument, printed as this printer prints a Piecewise
        return self._print(expr.expansion())

    _one = "1"
    #: the compensated a b - c d of :mod:`rigidsym.codegen.accuracy.compensated`, as the printed
    #: module names it (a helper the templates define)
    _diffprod = "_diffprod"

    #: the compensated sum of products (:class:`rigidsym.codegen.accuracy.compensated.SumProd`)
    _sumprod = "_sumprod"
    #: ``{compensated node: temp name}``: nodes a program computes once as a named temp
    #: (:func:`rigidsym.codegen.backends.arrays.programs.hoist_compensated`), printed as that name
    named: dict = {}

    def compensated_call(self, expr) -> str:
        """The call of the helper that evaluates the compensated node ``expr``."""
        name = self._diffprod if expr.func.__name__ == "DiffProd" else \
            self._sumprod.format(n=len(expr.args) // 2)
        return f"{name}({', '.join(self._print(a) for a in expr.args)})"

    def named_call(self, expr) -> str:
        """The right-hand side of the named temp (``named``) of the compensated node
        ``expr``: its helper's call (the JAX printer wraps it)."""
        return self.compensated_call(expr)

    def _print_DiffProd(self, expr):
        return self.named.get(expr) or self.compensated_call(expr)

    _print_SumProd = _print_DiffProd

    def _sqrt(self, arg: str) -> str:  # pragma: no cover - overridden
        raise NotImplementedError

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and 2 <= int(exp) <= _MAX_EXPAND:
            b = self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            # parenthesised: the Mul printer may place a Pow after "/" without parentheses
            return "(" + "*".join([b] * int(exp)) + ")"
        if exp.is_Integer and -_MAX_EXPAND <= int(exp) <= -1:
            if exp == -1:
                return f"{self._one}/{self.parenthesize(base, PRECEDENCE['Mul'], strict=True)}"
            b = self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            return f"{self._one}/({'*'.join([b] * -int(exp))})"
        if exp == sp.S.Half:
            return self._sqrt(self._print(base))
        if exp == -sp.S.Half:
            return f"{self._one}/{self._sqrt(self._print(base))}"
        if exp.is_Rational and exp.q == 2 and abs(exp.p) <= 2 * _MAX_EXPAND + 1:
            # x**(k/2) = x**((k-1)/2) * sqrt(x): one sqrt, no pow()
            b = self._print(base)
            k = (abs(exp.p) - 1) // 2
            whole = self._print(sp.Pow(base, k, evaluate=False)) if k > 1 else \
                self.parenthesize(base, PRECEDENCE["Mul"], strict=False)
            num = f"({whole}*{self._sqrt(b)})"
            return num if exp > 0 else f"{self._one}/{num}"
        if isinstance(self, NumPyPrinter):
            return super()._print_Pow(expr, rational=rational)
        return super()._print_Pow(expr)


@lru_cache(maxsize=1 << 16)
def _ordered_terms(expr: sp.Expr, order) -> tuple:
    """``expr.as_ordered_terms(order=order)``, remembered (a function of the expression's
    structure only, so the same for every printer)."""
    return tuple(expr.as_ordered_terms(order=order))


def dyadic_repr(expr) -> str | None:
    """``repr`` of a rational with a power-of-two denominator (exact in binary), else None."""
    q = int(expr.q)
    if q & (q - 1) == 0:
        return repr(float(expr))
    return None


def program_lines(p: Program, printer) -> dict:
    """The printed program ``p``: ``{"temps": [(name, text)], "outputs": [text],
    "dens": [text]}`` (what the templates loop over)."""
    return {
        "temps": [(str(s), printer.doprint(v)) for s, v in p.temps],
        "outputs": [printer.doprint(v) for v in p.outputs],
        "dens": [printer.doprint(v) for v in p.dens],
    }


def divisors_and_radicands(p: Program, printer) -> list[str]:
    """The divisors and radicands of ``p``, printed: a finite quotient of an overflowed
    divisor (``x / inf == 0``: the unit vector of ``1/sqrt(|p|^2)`` with ``|p|^2 = inf``) is
    finite but wrong, so they are checked for finiteness too."""
    out: list[str] = []
    for e in [v for _, v in p.temps] + list(p.outputs):
        for node in sp.preorder_traversal(sp.sympify(e)):
            if isinstance(node, sp.Pow) and not (node.exp.is_Integer and node.exp > 0) \
                    and not node.base.is_number:
                s = printer.doprint(node.base)
                s = s if s.isidentifier() else f"({s})"
                if s not in out:
                    out.append(s)
    return out


def risky_names(p: Program, printer) -> list[str]:
    """Temporaries / outputs that divide or take a root, and their divisors and radicands,
    printed (NumPy finiteness check)."""
    names = [str(s) for s, v in p.temps if divides_or_roots(v)]
    names += [printer.doprint(v) for v in p.outputs if divides_or_roots(v)]
    return names + [b for b in divisors_and_radicands(p, printer) if b not in names]


#: the helpers of the compensated products (:mod:`rigidsym.codegen.accuracy.compensated`) as
#: the generated NumPy kernels define them (:data:`NUMPY_SOURCE`, ``module`` is ``numpy``;
#: the accuracy meter evaluates through the same text); the same text for PyTorch and JAX
#: (:data:`ARRAY_SOURCE`) with their array module
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
    """a b - c d compensated (Kahan's algorithm, its fma emulated;
    rigidsym.codegen.accuracy.compensated)."""
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


#: the compensated products' node classes (:mod:`rigidsym.codegen.accuracy.compensated`), by
#: the names the printers dispatch on (``_print_DiffProd``): the printers print the nodes and
#: know no more of them, so that the accuracy meter can evaluate through these printers
COMPENSATED = ("DiffProd", "SumProd")


def is_compensated(node) -> bool:
    """Whether ``node`` (a sympy expression) is a compensated product (one of
    :data:`COMPENSATED`)."""
    return type(node).__name__ in COMPENSATED


def uses_diffprod(kc) -> bool:
    """Whether a program of ``kc`` has a compensated difference of products (its printed
    module then carries the helpers, :data:`NUMPY_SOURCE`); ``kc`` a
    :class:`rigidsym.codegen.generator.KernelCode`."""
    return any(is_compensated(n) for v in kc.variants
               for e in [*(x for _, x in v.program.temps), *v.program.outputs]
               for n in sp.preorder_traversal(sp.sympify(e)))
