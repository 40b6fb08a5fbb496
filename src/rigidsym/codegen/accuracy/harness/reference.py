"""The reference of the accuracy harness: the declared formula in ball arithmetic (the truth
that ``benchmarks/accuracy.py``, the project's accuracy tests and ``rigidsym audit`` judge by).

A kernel's declared outputs (its ``build``, before any rewrite of the code generator, as
``tests/test_kernels.py`` composes them) are printed to Python over python-flint ``arb``
balls: exact rationals stay exact (``arb(p)/q``), ``sqrt`` of a half power, ``atan2``,
``Piecewise`` as a conditional (an undecided ball comparison is False, as a zero exact
input compares). :func:`reference` evaluates at an exact point (rationals, ``fmpq``) with
the precision raised until every output component is narrower than 1e-3 ulp of float64 at
its value (capped at 2000 bits). :func:`condition` gives the problem's condition number per
output, from the same function: central differences in ``arb`` along an orthonormal basis of
each argument's tangent space (unit vectors: the complement of the vector; rotations:
``Q CPM(b_k)/sqrt 2``; the rest: the coordinates), so it does not depend on the formula the
kernel chose.
"""

from __future__ import annotations

from functools import cache
from types import SimpleNamespace

import numpy as np
import sympy as sp
from flint import arb, ctx, fmpq
from sympy.printing.lambdarepr import LambdaPrinter

EPS64 = 2.0**-53
MAX_PREC = 2000


class ArbPrinter(LambdaPrinter):
    """Python source over ``arb``: numbers exact, powers through ``sqrt`` where half."""

    def _print_Integer(self, e):
        return f"arb({int(e)})"

    def _print_Rational(self, e):
        return f"(arb({int(e.p)})/{int(e.q)})"

    def _print_Float(self, e):
        return f"arb({float(e)!r})"

    def _print_Pi(self, e):
        return "arb.pi()"

    def _print_Half(self, e):
        return "(arb(1)/2)"

    def _print_NegativeOne(self, e):
        return "arb(-1)"

    def _print_One(self, e):
        return "arb(1)"

    def _print_Zero(self, e):
        return "arb(0)"

    def _print_Pow(self, e, rational=False):
        b, x = e.args
        base = self._print(b)
        if x.is_Integer:
            return f"(({base})**({int(x)}))"
        if x.is_Rational and x.q == 2:
            return f"((sqrt({base}))**({int(x.p)}))"
        return f"(({base})**({self._print(x)}))"

    def _print_UnevaluatedExpr(self, e):
        return f"({self._print(e.args[0])})"

    def _print_Relational(self, e):
        return f"(({self._print(e.lhs)}) {e.rel_op} ({self._print(e.rhs)}))"


def atan2_branch(y, x):
    """atan2 on the kernels' branch phi in [0, pi] where y is a ball around 0 and x < 0
    (arb's ball there holds both -pi and pi): y is a norm (>= 0) in every declaration that
    uses atan2, so the limit from y >= 0, pi - atan(y/|x|), continuous there."""
    if x < 0 and y.contains(0):
        return arb.pi() - (y / (-x)).atan()
    return arb.atan2(y, x)


NAMESPACE = {
    "arb": arb, "sqrt": lambda x: x.sqrt(), "sin": lambda x: x.sin(), "cos": lambda x: x.cos(),
    "tan": lambda x: x.tan(), "atan2": lambda y, x: atan2_branch(y, x), "atan": lambda x: x.atan(),
    "acos": lambda x: x.acos(), "asin": lambda x: x.asin(), "Abs": abs, "abs": abs,
    "exp": lambda x: x.exp(), "log": lambda x: x.log(),
}
NAMESPACE["math"] = SimpleNamespace(**NAMESPACE)    # the printer writes math.sin(x)


#: kernels the harness judges besides the book's (a user module's and their twins), by name:
#: :func:`register_kernels` fills it
EXTRA_KERNELS: dict = {}


def register_kernels(kernels) -> None:
    """Let the harness judge ``kernels`` (user :class:`~rigidsym.codegen.spec.Kernel` s, not
    the book's) and their Jacobian twins by name: :func:`kernel_of` finds them first."""
    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels

    EXTRA_KERNELS.update({k.name: k for k in kernels})
    EXTRA_KERNELS.update({j.name: j for j in jacobian_kernels(list(kernels))})
    kernel_of.cache_clear()
    functions.cache_clear()


@cache
def kernel_of(name: str):
    """The declared :class:`~rigidsym.codegen.spec.Kernel` ``name`` (Jacobian kernels too;
    registered ones, :func:`register_kernels`, first)."""
    import importlib

    if name in EXTRA_KERNELS:
        return EXTRA_KERNELS[name]

    from rigidsym.codegen.derivatives.jacobians import jacobian_kernels
    from rigidsym.core.config import KERNEL_SPEC

    by = {k.name: k for k in importlib.import_module(KERNEL_SPEC).KERNELS}
    if name not in by:
        if not name.endswith("_with_jacobians") or name.removesuffix("_with_jacobians") not in by:
            raise KeyError(name)
        base = name.removesuffix("_with_jacobians")
        by.update({k.name: k for k in jacobian_kernels([by[base]])})
    return by[name]


@cache
def functions(name: str):
    """``[(cond or None, arb function)]`` per variant (branches first) of the declaration;
    ``cond`` is a float function of the flat inputs (the branch the kernel takes)."""
    from rigidsym.codegen.spec import flat_symbols, input_symbols
    from rigidsym.codegen.spec import flatten_outputs as _flatten

    k = kernel_of(name)
    syms = input_symbols(k)
    flat = [s for _, ss in flat_symbols(k) for s in ss]
    out = []
    for br in k.branches:
        cond = sp.lambdify(flat, br.when(**syms), modules="math")
        f = sp.lambdify(flat, _flatten(k, br.build(**syms)), modules=[NAMESPACE],
                        printer=ArbPrinter, cse=True)
        out.append((cond, f))
    out.append((None, sp.lambdify(flat, _flatten(k, k.build(**syms)), modules=[NAMESPACE],
                                  printer=ArbPrinter, cse=True)))
    return out


def pick(name: str, rounded: list[float]):
    """The variant the kernel evaluates at its (rounded) inputs."""
    import numpy as np

    # NumPy scalars: a Python float's ** raises OverflowError near 1e160, NumPy's is inf
    wide = [np.float64(x) for x in rounded]
    for cond, f in functions(name):
        with np.errstate(all="ignore"):
            if cond is None or bool(cond(*wide)):
                return f
    raise AssertionError("no variant")


def is_narrow(vals) -> bool:
    mids = [abs(float(v.mid())) for v in vals]
    big = max(mids) if mids else 0.0
    for v, m in zip(vals, mids, strict=True):
        if not v.is_finite():
            return False
        if float(v.rad()) > 1e-3 * EPS64 * max(m, 2.0**-60 * big):
            return False
    return True


def evaluate(f, exact: list[fmpq], prec: int):
    old = ctx.prec
    ctx.prec = prec
    try:
        return list(f(*[arb(q) for q in exact]))
    except (ZeroDivisionError, ValueError):
        return None
    finally:
        ctx.prec = old


def max_prec(exact: list[fmpq]) -> int:
    """The precision cap at ``exact``: :data:`MAX_PREC`, raised where an input's magnitude is
    extreme. A removable singularity in a norm ``theta`` (``1/theta^2 - sin theta / (2 theta
    (1 - cos theta))``, the ``theta^-4`` of SE(3)'s Q block, twice in ``J^-1 Q J^-1``) cancels
    up to ``8 |log2 theta|`` bits: at ``theta = 1e-300`` 2000 bits left a ball 1e-3 wide
    whose midpoint the harness took for the truth (the Lie kernels' "finite wrong values" at
    the ends of the range were the reference's)."""
    e = max((abs(int(x.p).bit_length() - int(x.q).bit_length()) for x in exact if x != 0),
            default=0)
    return max(MAX_PREC, 8 * e + 256)


def reference(f, exact: list[fmpq]):
    """(float64 values, bits used) of ``f`` at ``exact``; values None where undefined
    (the ball of a division by an exact zero, or not narrow at :func:`max_prec` bits and not
    finite)."""
    prec, cap = 128, max_prec(exact)
    while True:
        vals = evaluate(f, exact, prec)
        if vals is not None and is_narrow(vals):
            return np.array([float(v.mid()) for v in vals]), prec
        if prec >= cap:
            if vals is None or not all(v.is_finite() for v in vals):
                return None, prec
            return np.array([float(v.mid()) for v in vals]), prec
        prec = min(2 * prec, cap)


def tangent_basis(kind: str, shape: tuple, exact: list[fmpq], prec: int) -> list[list]:
    """Orthonormal directions of the argument's tangent space, as ``arb`` lists."""
    x = [arb(q) for q in exact]
    n = len(x)
    if kind == "unit":
        nn = sum(v * v for v in x)
        basis = []
        for j in range(n):     # project the coordinate axes, Gram-Schmidt, keep n - 1
            d = [(-x[i] * x[j] / nn) + (1 if i == j else 0) for i in range(n)]
            for b in basis:
                dot = sum(p * q for p, q in zip(d, b, strict=True))
                d = [p - dot * q for p, q in zip(d, b, strict=True)]
            norm = sum(v * v for v in d).sqrt()
            if float(norm.mid()) > 0.3:
                basis.append([v / norm for v in d])
            if len(basis) == n - 1:
                break
        return basis
    if kind == "rotation":
        Q = [[x[3 * i + j] for j in range(3)] for i in range(3)]
        out = []
        for k in range(3):
            W = [[arb(0)] * 3 for _ in range(3)]
            a, b = (k + 1) % 3, (k + 2) % 3
            W[b][a], W[a][b] = arb(1), arb(-1)          # CPM of the k-th axis
            QW = [[sum(Q[i][m] * W[m][j] for m in range(3)) for j in range(3)]
                  for i in range(3)]
            out.append([QW[i][j] / arb(2).sqrt() for i in range(3) for j in range(3)])
        return out
    return [[arb(1) if i == j else arb(0) for i in range(n)] for j in range(n)]


def condition(name: str, f, exact_args: list[list[fmpq]], out_sizes: list[int],
              ref: np.ndarray, prec: int):
    """Per output: (sum over arguments of ||J_oi|| ||x_i||, ||f_o||); kappa_o = first/second.

    ``J_oi`` is the derivative of output ``o`` along an orthonormal basis of argument ``i``'s
    tangent space (central differences of the ball function, step 2^-100 of the argument's
    size, and at most 2^-100 (absolute) where the size exceeds 1, at ``prec + 300`` bits and
    the bits of the largest size: truncation 2^-200 relative). The absolute cap: a function
    of the norm's trigonometry (the Lie kernels' ``cot(theta/2)``) varies on a scale of 1
    whatever the size; a step 2^-100 of ``theta = 1e300`` spans 1e270 periods and measured
    a condition number of 1e-74 where it is 1e300."""
    k = kernel_of(name)
    big = max((float(sum(arb(q) ** 2 for q in ex).sqrt().mid()) for ex in exact_args),
              default=1.0)
    p = prec + 300 + max(0, int(np.log2(big)) if np.isfinite(big) and big > 1 else 0)
    old = ctx.prec
    ctx.prec = p
    try:
        flat = [arb(q) for a in exact_args for q in a]
        offs = np.cumsum([0] + out_sizes)
        scale = np.zeros(len(out_sizes))
        start = 0
        for arg, ex in zip(k.args, exact_args, strict=True):
            xs = [arb(q) for q in ex]
            size = float(sum(v * v for v in xs).sqrt().mid())
            n = len(ex)
            if size == 0.0:
                start += n
                continue
            h = arb(min(size, 1.0)) * arb(2) ** -100
            cols = []
            for d in tangent_basis(arg.kind, arg.shape, ex, p):
                plus = list(flat)
                minus = list(flat)
                for i in range(n):
                    plus[start + i] = flat[start + i] + h * d[i]
                    minus[start + i] = flat[start + i] - h * d[i]
                fp, fm = f(*plus), f(*minus)
                cols.append([float(((a - b) / (2 * h)).mid()) for a, b in zip(fp, fm,
                                                                              strict=True)])
            J = np.array(cols).T              # outputs x directions
            for o in range(len(out_sizes)):
                Jo = J[offs[o]:offs[o + 1]]
                if np.isfinite(Jo).all():
                    scale[o] += np.linalg.norm(Jo, 2) * size
                else:
                    scale[o] = np.inf
            start += n
        norms = np.array([np.linalg.norm(ref[offs[o]:offs[o + 1]])
                          for o in range(len(out_sizes))])
        return scale, norms
    except (ZeroDivisionError, ValueError):
        return np.full(len(out_sizes), np.inf), np.zeros(len(out_sizes))
    finally:
        ctx.prec = old
