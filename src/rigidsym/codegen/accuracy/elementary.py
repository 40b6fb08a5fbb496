"""The elementary functions of the generator's measurements, the same bits on every machine.

The generator measures candidate forms and float32 precision plans by evaluating them in
NumPy (:mod:`rigidsym.codegen.accuracy.float32`, :class:`rigidsym.codegen.accuracy.error.Meter`,
:func:`rigidsym.codegen.accuracy.rule.textbook`), and what it measures is written into
``generated/`` (a plan's float and double nodes, the ratios quoted in the headers). NumPy
picks its ``sin``, ``cos``, ``arctan2``, ``arcsin`` and ``arccos`` loops per CPU (its own SIMD
and SVML loops on AVX-512, glibc's on AVX2, others on Arm), and those differ in the last bit
on some arguments: a plan at the margin of its budget then flipped a node, and ``rigidsym
generate`` on an AVX2 machine rewrote 36 files that an AVX-512 machine had generated.

Here each such value is the exact value rounded to nearest (correctly rounded): computed
in Arb's ball arithmetic (python-flint, already the exact engine's library: integer
arithmetic, the same bits on every CPU, operating system and Python), the precision raised
until both ends of the ball round to the same double (Ziv's strategy); an integer power
exactly, in rationals. A float32 argument gives that float64 value rounded to float32 (C's
``sinf`` and NumPy's float32 loops are faithful to within an ulp, as this is; the
measurements need a fixed one, not a particular one). Special values follow C99 Annex F
(signed zeros, infinities, NaN; an argument outside the domain gives NaN). Values are
memoised per process by the argument's bits (the planner evaluates the same program at
the same points many times), up to :data:`MEMO_SIZE` per function.

:data:`NUMPY` stands in for the ``numpy`` module in the generator's evaluations: these five
functions replaced, every other name NumPy's own (arithmetic and ``sqrt`` are correctly
rounded by IEEE 754, the same everywhere).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction

import numpy as np
from flint import arb, ctx
from sympy.printing.numpy import NumPyPrinter

from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter

__all__ = ["sin", "cos", "tan", "arctan2", "arcsin", "arccos", "power", "NUMPY",
           "measuring_printer", "TEXTBOOK_PRINTER", "KERNEL_PRINTER"]

#: the most values remembered per function (then forgotten, all at once)
MEMO_SIZE = 1 << 18
_MEMO: dict[str, dict] = {}
# Ziv's strategy: the first working precision, and the last before giving up on a ball that
# keeps a rounding boundary (an exact value halfway between two doubles: none of these
# functions has one at a float argument past the exact cases handled before)
_START, _LAST = 96, 1 << 14


def _rounded(f: Callable, *xs: float) -> float:
    """``f`` of the arbs of ``xs`` rounded to the nearest double (``float()`` of an arb
    rounds its midpoint to nearest, ties to even; overflow gives inf)."""
    prec = _START
    while True:
        ctx.prec = prec
        b = f(*[arb(x) for x in xs])
        lo, hi = float(b.lower()), float(b.upper())
        if lo == hi:
            return lo
        if prec >= _LAST:
            raise ArithmeticError(f"{f.__name__}{xs}: no correctly rounded value found")
        prec *= 2


def _sin(x: float) -> float:
    if x == 0 or not math.isfinite(x):
        return x if x == 0 else math.nan      # sin(+-0) = +-0
    return _rounded(arb.sin, x)


def _cos(x: float) -> float:
    if not math.isfinite(x):
        return math.nan
    return _rounded(arb.cos, x)


def _tan(x: float) -> float:
    if x == 0 or not math.isfinite(x):
        return x if x == 0 else math.nan
    return _rounded(arb.tan, x)


def _pow(x: float, y: float) -> float:
    if y == 0 or x == 1:
        return 1.0
    if math.isnan(x) or math.isnan(y):
        return math.nan
    if math.isfinite(x) and y == int(y) and abs(y) <= 64:
        # exactly, in rationals, then rounded once (a ratio of integers to float is
        # correctly rounded); a pole at zero is +-inf, the sign of an odd power of -0
        if x == 0 and y < 0:
            return math.copysign(math.inf, x) if int(y) % 2 else math.inf
        try:
            return float(Fraction(x) ** int(y))
        except OverflowError:
            return math.copysign(math.inf, x) if int(y) % 2 else math.inf
    # the rest of C99's table (a zero, an infinity, a negative base) by Python's math.pow,
    # which follows it; exact cases only
    if x <= 0 or not (math.isfinite(x) and math.isfinite(y)):
        if x == 0 and y < 0:
            odd = math.isfinite(y) and y == int(y) and int(y) % 2
            return math.copysign(math.inf, x) if odd else math.inf
        try:
            return math.pow(x, y)
        except ValueError:      # a negative base to a non-integer power
            return math.nan
    return _rounded(arb.__pow__, x, y)


def _asin(x: float) -> float:
    if x == 0 or math.isnan(x):
        return x
    if abs(x) > 1:
        return math.nan
    return _rounded(arb.asin, x)


def _acos(x: float) -> float:
    if math.isnan(x) or abs(x) > 1:
        return math.nan
    if x == 1:
        return 0.0
    return _rounded(arb.acos, x)


def _atan2(y: float, x: float) -> float:
    # zeros, infinities and NaN: exact results (+-0, +-pi, +-pi/2, +-pi/4, +-3pi/4 rounded
    # once) by C99's table, which Python's math.atan2 follows
    if y == 0 or x == 0 or not (math.isfinite(x) and math.isfinite(y)):
        return math.atan2(y, x)
    return _rounded(arb.atan2, y, x)


def _result_type(args: tuple):
    """NumPy's: float32 where its loop would be float32 (float32 arrays, Python scalars
    beside them), else float64."""
    return np.float32 if np.result_type(*args) == np.float32 else np.float64


def _vectorised(name: str, scalar: Callable, nargs: int) -> Callable:
    memo = _MEMO.setdefault(name, {})

    def f(*args):
        if len(args) != nargs:
            raise TypeError(f"{name}: expected {nargs} argument(s), got {len(args)}")
        arrays = [np.asarray(a) for a in args]
        for a in arrays:
            if a.dtype.kind not in "fiub":
                raise TypeError(f"{name}: expected real numbers, got dtype {a.dtype}")
        out_type = _result_type(args)
        wide = np.broadcast_arrays(*[a.astype(np.float64) for a in arrays])
        shape = wide[0].shape
        if nargs == 1:
            keys = np.ascontiguousarray(wide[0]).reshape(-1).view(np.int64)
        else:
            keys = np.stack([np.ascontiguousarray(w).reshape(-1).view(np.int64)
                             for w in wide], axis=1).view([("y", np.int64), ("x", np.int64)])
            keys = keys.reshape(-1)
        # by bits, not values: -0.0 and 0.0 are different arguments
        uniq, inv = np.unique(keys, return_inverse=True)
        vals = np.empty(len(uniq), dtype=np.float64)
        if len(memo) > MEMO_SIZE:
            memo.clear()
        floats = uniq.view(np.float64).reshape(len(uniq), nargs).tolist()
        prec = ctx.prec
        try:
            for i, k in enumerate(uniq.tolist()):
                v = memo.get(k)
                if v is None:
                    v = memo[k] = scalar(*floats[i])
                vals[i] = v
        finally:
            ctx.prec = prec     # flint's precision is the process's: the exact engine's too
        out = vals[inv.reshape(-1)].reshape(shape).astype(out_type)
        return out[()] if out.ndim == 0 else out

    f.__name__ = f.__qualname__ = name
    f.__doc__ = (f"NumPy's ``{name}`` (broadcasting, float32 in float32 out), each value "
                 "mpmath's at 53 bits rounded to nearest, the same on every machine.")
    return f


#: ``numpy.sin`` with mpmath's values (see the module's docstring)
sin = _vectorised("sin", _sin, 1)
#: ``numpy.cos``, likewise
cos = _vectorised("cos", _cos, 1)
#: ``numpy.tan``, likewise
tan = _vectorised("tan", _tan, 1)
#: ``numpy.power(x, y)``, likewise
power = _vectorised("power", _pow, 2)
#: ``numpy.arcsin``, likewise
arcsin = _vectorised("arcsin", _asin, 1)
#: ``numpy.arccos``, likewise
arccos = _vectorised("arccos", _acos, 1)
#: ``numpy.arctan2(y, x)``, likewise
arctan2 = _vectorised("arctan2", _atan2, 2)

_OWN = {"sin": sin, "cos": cos, "tan": tan, "arcsin": arcsin, "arccos": arccos,
        "arctan2": arctan2, "power": power}
#: NumPy's elementary functions whose loops NumPy picks per CPU and this module does not
#: replace: a measurement that meets one refuses rather than depend on the machine
_DISPATCHED = frozenset({"arctan", "exp", "exp2", "expm1", "log", "log2", "log10", "log1p",
                         "sinh", "cosh", "tanh", "arcsinh", "arccosh", "arctanh",
                         "float_power", "cbrt", "hypot", "logaddexp"})


# NumPy computes these powers exactly rounded without pow (square, reciprocal, sqrt)
_EXACT_EXPONENTS = frozenset({2.0, 1.0, 0.0, -1.0, 0.5, -0.5})


def measuring_printer(cls: type) -> type:
    """``cls`` (a sympy NumPy printer class) printing a power as ``numpy.power(b, e)``
    wherever NumPy would call ``pow`` (an ndarray's ``**`` takes NumPy's per-CPU loop
    without looking up a name: :data:`NUMPY` could not replace it); the exact cases stay as
    ``cls`` prints them (``**2``, ``**-1``: one rounding; square roots)."""

    def _hprint_Pow(self, expr, rational=False, sqrt="numpy.sqrt"):
        e = expr.exp
        exact = e.is_number and e.is_real and float(e) in _EXACT_EXPONENTS
        if rational or exact:
            return cls._hprint_Pow(self, expr, rational=rational, sqrt=sqrt)
        return (f"{self._module_format('numpy.power')}({self._print(expr.base)}, "
                f"{self._print(e)})")

    return type(f"Measuring{cls.__name__}", (cls,), {"_hprint_Pow": _hprint_Pow})


class _Namespace:
    """The ``numpy`` module for printed expressions: :data:`_OWN` replaced, the dispatched
    functions without a replacement refused, every other name NumPy's."""

    def __getattr__(self, name: str):
        if name in _OWN:
            return _OWN[name]
        if name in _DISPATCHED:
            raise NotImplementedError(
                f"numpy.{name} in a generator measurement: its values depend on the CPU; "
                "add it to rigidsym.codegen.accuracy.elementary")
        return getattr(np, name)


#: the stand-in for the ``numpy`` module in the generator's evaluations
NUMPY = _Namespace()
#: sympy's NumPy printer (a declaration evaluated as the harness evaluates it), measuring
TEXTBOOK_PRINTER = measuring_printer(NumPyPrinter)
#: the kernels' NumPy printer, measuring
KERNEL_PRINTER = measuring_printer(KernelNumPyPrinter)
