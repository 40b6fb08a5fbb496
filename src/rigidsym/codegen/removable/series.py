"""The series of a removable quotient and its certificate: for an even
``h(s)`` with a finite limit at ``s = 0`` (``sin s / s``, ``(1 - cos s) / s^2``, ...), the
Taylor coefficients of ``g(t) = h(sqrt t)`` in exact rationals, and the order ``n`` and switch
threshold ``t*`` of the branch ``t < t* -> sum_k c_k t^k`` with its error bounded, remainder
and rounding included, over the whole interval ``[0, t*]``.

- Coefficients: the series of numerator and denominator from the Taylor series of ``sin``,
  ``cos``, ``asin`` and of a root of a polynomial ``1 + ...`` (``sqrt(1 - s^2)``, by Miller's
  recurrence; its radius half its base's nearest zero), summed and multiplied truncated in
  :class:`fractions.Fraction`, divided as power series, and checked against
  ``sympy.series`` of numerator and denominator (``N = c D`` to twelve orders past the
  leading one); the odd ones must vanish (``h`` even) and so must the numerator's below the
  denominator's order (a finite limit). Nothing in floating point.
- Remainder: the exact ``|c_k|`` for ten more terms, then Cauchy's estimate ``|c_k| <= M /
  rho^k`` with ``M`` an upper bound of ``|h|`` on ``|s|^2 = rho`` by complex balls
  (python-flint's ``acb``, the ball arithmetic of :mod:`rigidsym.checking.deciding.balls`)
  over arcs covering the half circle; ``rho`` half the distance to the nearest singularity
  of the denominator's factors (``sin``, ``1 - cos``, ``cos``, a polynomial) or of
  ``asin``'s branch point.
- Rounding: a running error bound of Horner's scheme (each IEEE operation ``<= u |x|``, the
  coefficients rounded too) at ``t = t*``, where every term's magnitude is largest.
- The closed form just above ``t*``: a first-order running error bound of its evaluation
  (``sqrt``, ``+ - * /`` correctly rounded, ``u``; ``sin``/``cos``/``asin`` within one ulp,
  ``2u``), on balls covering ``[t*, 4 t*]``.

``t*`` is the smallest power of two at or above which the closed form's bound is within 10 %
of its best (or ``<= 2u``), or, where no series of order ``<= 18`` is within ``2u`` that
far, the largest smaller one where one is; ``n`` the smallest order whose Taylor bound is
``<= 2u`` on ``[0, t*]`` in float64 (where the closed form there is past 32 u, ``t*`` moves
up while a series within 2.5 u reaches it: :func:`_wider`); the float32 bound of the same
series is recorded (``<= 2u`` but where a float32 ``c_0`` rounds by nearly ``u`` itself). The
closed form's bound just above ``t*`` is recorded: its rounding (one ulp per ``sin``/``cos``, the
cancellation in ``s - sin s``) is
what it is; the series branch keeps the singular neighbourhood within ``2u``.

Long: one certificate (the series, its ball bounds, the switch point and its widening) read
in one place; 405 lines, to be split along the series/bounds seam.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from math import factorial

import flint
import numpy as np
import sympy as sp

__all__ = ["S", "Series", "series_of", "certify", "Certificate", "NotRemovable"]

S = sp.Symbol("s", positive=True)  #: the norm, in the canonical form of a quotient
U64, U32 = 2.0**-53, 2.0**-24
_EXTRA = 10           # exact coefficients beyond the order, before Cauchy's estimate
_KMAX = 18            # the largest order tried


class NotRemovable(ValueError):
    """The quotient is not even, has no finite limit, or holds a function not known here."""


@dataclass(frozen=True)
class Series:
    coeffs: tuple        # c_0 ... c_K of g(t) = h(sqrt t), exact Fractions
    rho: float           # the radius (in t) of the Cauchy circle
    M: float             # upper bound of |h| on that circle


def _fn_series(f, k, n):
    """The coefficients of s^0 ... s^(n-1) of sin(k s), cos(k s) or asin(s) (exact)."""
    out = [Fraction(0)] * n
    for j in range(n):
        if f is sp.sin and j % 2 == 1:
            out[j] = (-1) ** (j // 2) * k**j / factorial(j)
        elif f is sp.cos and j % 2 == 0:
            out[j] = (-1) ** (j // 2) * k**j / factorial(j)
        elif f is sp.asin and j % 2 == 1:
            m = j // 2
            out[j] = Fraction(factorial(2 * m), 4**m * factorial(m) ** 2 * (2 * m + 1))
    return out


def _mul_series(a, b, n):
    out = [Fraction(0)] * n
    for i, x in enumerate(a):
        if x:
            for j in range(n - i):
                if b[j]:
                    out[i + j] += x * b[j]
    return out


def _poly_series(e, n):
    """The coefficients of s^0 ... s^(n-1) of ``e``, a polynomial in s and sin, cos of
    rational multiples of s (or asin s): each function by its Taylor series, sums and
    products truncated, in exact rationals (:class:`fractions.Fraction`)."""
    if e == S:
        return [Fraction(int(j == 1)) for j in range(n)]
    if e.is_Rational:
        return [Fraction(int(e.p), int(e.q))] + [Fraction(0)] * (n - 1)
    if isinstance(e, sp.Add):
        out = [Fraction(0)] * n
        for a in e.args:
            out = [x + y for x, y in zip(out, _poly_series(a, n), strict=True)]
        return out
    if isinstance(e, sp.Mul):
        out = _poly_series(e.args[0], n)
        for a in e.args[1:]:
            out = _mul_series(out, _poly_series(a, n), n)
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Integer and e.exp >= 0:
        out, b = _poly_series(sp.S.One, n), _poly_series(e.base, n)
        for _ in range(int(e.exp)):
            out = _mul_series(out, b, n)
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Rational:   # a root (1 - s^2)^(1/2): b(0) = 1
        b, a = _poly_series(e.base, n), Fraction(int(e.exp.p), int(e.exp.q))
        if b[0] != 1:
            raise NotRemovable(f"{e}: a root of a series not 1 at s = 0")
        y = [Fraction(1)] + [Fraction(0)] * (n - 1)
        for m in range(1, n):      # J. C. P. Miller's recurrence for b^a (y' b = a b' y)
            y[m] = sum((a * k - (m - k)) * b[k] * y[m - k] for k in range(1, m + 1)) / m
        return y
    if type(e) in (sp.sin, sp.cos, sp.asin) and e.args[0].free_symbols == {S}:
        k = e.args[0] / S
        if k.is_Rational and (type(e) is not sp.asin or k == 1):
            return _fn_series(type(e), Fraction(int(k.p), int(k.q)), n)
    raise NotRemovable(f"{e}: no series here")


def _sympy_series(e, n):
    ser = sp.expand(sp.series(e, S, 0, n).removeO()) if e.has(S) else e
    out = [Fraction(0)] * n
    for (k,), c in sp.Poly(ser, S).terms():
        out[k] = Fraction(int(c.p), int(c.q))
    return out


def _singular_radius(D) -> float:
    """Half the smallest |t| of a zero of ``D(sqrt t)`` other than ``t = 0``."""
    best = float("inf")
    for f, _ in sp.factor_list(D)[1]:
        if f.free_symbols - {S}:
            raise NotRemovable(f"a factor {f} of other variables")
        if f == S:
            continue
        if f.is_polynomial(S):
            roots = [abs(complex(r)) ** 2 for r in sp.Poly(f, S).nroots() if abs(complex(r)) > 0]
            best = min([best, *roots])
            continue
        known = {sp.sin(S): sp.pi**2, 1 - sp.cos(S): 4 * sp.pi**2, sp.cos(S) - 1: 4 * sp.pi**2,
                 sp.cos(S): sp.pi**2 / 4, 1 + sp.cos(S): sp.pi**2}
        if f in known:
            best = min(best, float(known[f]))
        elif (-f) in known:
            best = min(best, float(known[-f]))
        else:
            raise NotRemovable(f"a denominator factor {f} whose zeros are not known here")
    return best / 2


def _numerator_radius(N) -> float:
    best = float("inf")
    for fn in N.atoms(sp.Function):
        if isinstance(fn, sp.asin) and fn.args[0] == S:
            best = min(best, 0.5)   # asin's branch points at s = +-1 (t = 1)
        elif not isinstance(fn, sp.sin | sp.cos) or not (fn.args[0] / S).is_Rational:
            raise NotRemovable(f"a function {fn} not known to be entire in s")
    for p in N.atoms(sp.Pow):
        if not p.exp.is_Integer and p.has(S):   # a root: half its base's nearest zero
            if not p.base.is_polynomial(S) or p.base.subs(S, 0) == 0:
                raise NotRemovable(f"a root {p} not analytic at s = 0")
            zs = [abs(complex(r)) ** 2 for r in sp.Poly(p.base, S).nroots()]
            best = min([best, *(z / 2 for z in zs)])
    return best


def _acb(e, s):
    if e == S:
        return s
    if e.is_Rational:
        return flint.acb(flint.arb(e.p) / e.q)
    if isinstance(e, sp.Add):
        out = flint.acb(0)
        for a in e.args:
            out += _acb(a, s)
        return out
    if isinstance(e, sp.Mul):
        out = flint.acb(1)
        for a in e.args:
            out *= _acb(a, s)
        return out
    if isinstance(e, sp.Pow) and e.exp.is_Integer:
        b = _acb(e.base, s)
        return b ** int(e.exp) if e.exp > 0 else 1 / b ** int(-e.exp)
    if isinstance(e, sp.Pow) and e.exp.is_Rational:  # principal branch: Re base > 0 here
        return _acb(e.base, s) ** flint.acb(flint.arb(int(e.exp.p)) / int(e.exp.q))
    f = {sp.sin: "sin", sp.cos: "cos", sp.asin: "asin"}.get(type(e))
    if f is None:
        raise NotRemovable(f"cannot bound {e}")
    return getattr(_acb(e.args[0], s), f)()


def _cauchy_bound(h, rho: float, arcs: int = 512) -> float:
    """An upper bound of |h(s)| on |s|^2 = rho (the half circle Re s >= 0 covers t)."""
    r = flint.arb(rho).sqrt()
    M = flint.arb(0)
    pi = flint.arb.pi()
    for j in range(arcs):
        a = -pi / 2 + pi * (flint.arb(j) + flint.arb(0.5, 0.5)) / arcs
        s = flint.acb(r * a.cos(), r * a.sin())
        v = abs(_acb(h, s))
        M = max(M, v.upper(), key=lambda x: float(x.upper()))
    out = float(M.upper()) * (1 + 1e-12)
    if not out < float("inf"):
        raise NotRemovable("no bound on the Cauchy circle")
    return out


@cache
def series_of(h: sp.Expr, K: int = 2 * (_KMAX + _EXTRA + 12)) -> Series:
    """The exact coefficients of ``g(t) = h(sqrt t)`` (``h`` in :data:`S`), checked.

    Raises:
        NotRemovable: ``h`` is not even, has no finite limit at 0, or a function or a
            denominator factor whose singularities are not known here.
    """
    N, D = sp.fraction(sp.together(h))
    if sp.expand(N.subs(S, -S) * D - N * D.subs(S, -S)) != 0:
        raise NotRemovable("not even in s")
    rho = min(_singular_radius(D), _numerator_radius(N), 16.0)  # entire: any circle
    n_, d_ = _poly_series(N, K), _poly_series(D, K)
    d0 = next((k for k, c in enumerate(d_) if c != 0), None)
    if d0 is None or any(c != 0 for c in n_[:d0]):
        raise NotRemovable("no finite limit at s = 0")
    a, b = n_[d0:], d_[d0:]
    c: list[Fraction] = []
    for k in range(len(a)):
        c.append((a[k] - sum(c[j] * b[k - j] for j in range(k))) / b[0])
    if any(x != 0 for x in c[1::2]):
        raise NotRemovable("odd coefficients")
    # sympy's own series of numerator and denominator (an independent expansion; of the
    # quotient itself it took seconds per derivative quotient) agree with c: N = c D
    sn, sd = _sympy_series(N, d0 + 12), _sympy_series(D, d0 + 12)
    if sn[:d0] != n_[:d0] or sd[:d0] != d_[:d0] or any(
            sn[k] != sum(c[j] * sd[k - j] for j in range(k - d0 + 1))
            for k in range(d0, d0 + 12)):
        raise NotRemovable("sympy's series disagrees")  # pragma: no cover
    M = _cauchy_bound(h, rho)
    return Series(tuple(c[0::2]), rho, M)


@dataclass(frozen=True)
class Certificate:
    order: int             # the highest power of t kept
    threshold: float       # t* (a power of two)
    taylor64: float        # the bound on [0, t*], in units of u (float64)
    taylor32: float
    closed64: float        # the closed form's bound on [t*, 4 t*], in units of u


def _taylor_bound(ser: Series, n: int, t: float, u: float) -> float:
    """(truncation + Horner rounding) / min |g| on [0, t], in units of ``u``."""
    c = [abs(float(x)) for x in ser.coeffs]
    # a coefficient is rounded once to the format: its exact rounding error
    rnd = float if u == U64 else (lambda x: float(np.float32(x)))
    rc = [abs(float(Fraction(rnd(x)) - x)) for x in ser.coeffs]
    tail = sum(c[k] * t**k for k in range(n + 1, n + 1 + _EXTRA))
    q = t / ser.rho
    if q >= 1:
        return float("inf")
    tail += ser.M * q ** (n + 1 + _EXTRA) / (1 - q)
    low = c[0] - sum(c[k] * t**k for k in range(1, n + 1)) - tail
    if low <= 0:
        return float("inf")
    # Horner, q_n = c_n, q_k = c_k + t q_{k+1}: running bound of the error e_k
    mag, err = c[n], rc[n]
    for k in range(n - 1, -1, -1):
        prod = t * mag
        err = rc[k] + t * err + u * prod + u * (c[k] + prod)
        mag = c[k] + prod
    return (tail + err * (1 + 4 * n * u)) / low / u


def _run(e, s, u):
    """(value ball, error bound) of the floating-point evaluation of ``e`` at the ball s."""
    if e == S:
        return s, 0.0      # the rounding of s = sqrt(t) is propagated by h' (_closed_bound)
    if e.is_Rational:
        v = flint.arb(e.p) / e.q
        return v, (0.0 if e.is_Integer else u * abs(v).upper())
    if isinstance(e, sp.Add | sp.Mul):
        parts = [_run(a, s, u) for a in e.args]
        v, err = parts[0]
        for w, ew in parts[1:]:
            if isinstance(e, sp.Add):
                v, err = v + w, err + ew
            else:
                err = abs(w).upper() * err + abs(v).upper() * ew
                v = v * w
            err += u * abs(v).upper()
        return v, err
    if isinstance(e, sp.Pow) and e.exp.is_Rational:
        b, eb = _run(e.base, s, u)
        k = e.exp
        lo = abs(b).lower()
        if not lo > 0:
            return b, float("inf")
        if k.is_Integer:
            v = b ** int(k) if k > 0 else 1 / b ** int(-k)
            ops = abs(int(k)) - 1 + (1 if int(k) < 0 else 0)
        else:   # a root: pow, or sqrt then a power; one rounding more than the power's
            v = b ** (flint.arb(int(k.p)) / int(k.q))
            ops = abs(int(k.p)) + 1
        rel = abs(float(k)) * eb / float(lo) + ops * u
        return v, rel * float(abs(v).upper())
    f = {sp.sin: (lambda x: x.sin(), lambda x: x.cos()),
         sp.cos: (lambda x: x.cos(), lambda x: -x.sin()),
         sp.asin: (lambda x: x.asin(), lambda x: 1 / (1 - x * x).sqrt())}.get(type(e))
    if f is None:
        raise NotRemovable(f"cannot bound {e}")
    x, ex = _run(e.args[0], s, u)
    v = f[0](x)
    return v, abs(f[1](x)).upper() * ex + 2 * u * abs(v).upper()


def _series_lower(ser: Series, tb) -> float:
    """A lower bound of |g| on the ball ``tb`` from the series (its tail by Cauchy)."""
    q = float(abs(tb).upper()) / ser.rho
    if q >= 1:
        return 0.0
    n = len(ser.coeffs)
    v = flint.arb(0)
    for c in reversed(ser.coeffs):
        v = v * tb + flint.arb(c.numerator) / c.denominator
    return max(0.0, float(abs(v).lower()) - ser.M * q**n / (1 - q))


def _closed_bound(h, t0: float, u: float, pieces: int = 16) -> float:
    """The closed form's relative error bound on [t0, 4 t0], in units of ``u``."""
    ser = series_of(h)
    worst, dh = 0.0, sp.diff(h, S)
    for j in range(pieces):
        a, b = t0 * 4 ** (j / pieces), t0 * 4 ** ((j + 1) / pieces)
        tb = flint.arb((a + b) / 2, (b - a) / 2 * (1 + 1e-9))
        sb = tb.sqrt()
        v, err = _run(h, sb, u)
        dv, _ = _run(dh, sb, u)
        lo = max(float(abs(v).lower()), _series_lower(ser, tb))
        if not lo > 0:
            return float("inf")
        err = float(err) + float(abs(dv * sb).upper()) * u * (1 + 1e-6)  # s rounded once
        worst = max(worst, err / lo / u)
    return worst


@cache
def certify(h: sp.Expr) -> Certificate:
    """The order and threshold of ``h``'s series branch, with their bounds (see above).

    Raises:
        NotRemovable: no series (:func:`series_of`), or no order up to 18 is within 2u.
    """
    ser = series_of(h)
    tops = [2.0**k for k in range(-40, 5) if 2.0**k <= ser.rho / 2]
    bounds = {t: _closed_bound(h, t, U64) for t in tops}
    best = min(bounds.values())
    ok = [t for t in tops if bounds[t] <= max(2.0, 1.1 * best)]
    # the closed form at its best; where no series is within 2u that far, smaller t*
    for t in ok + sorted((t for t in tops if t < min(ok)), reverse=True):
        n = _order(ser, t, 2.0)
        if n is not None:
            return _wider(ser, Certificate(n, t, _taylor_bound(ser, n, t, U64),
                                           _taylor_bound(ser, n, t, U32), bounds[t]), bounds)
    raise NotRemovable(f"no order up to {_KMAX} is within 2u")  # pragma: no cover


def _order(ser: Series, t: float, within: float) -> int | None:
    """The smallest order whose float64 Taylor bound on [0, t] is ``<= within`` u."""
    return next((n for n in range(_KMAX + 1) if _taylor_bound(ser, n, t, U64) <= within),
                None)


#: a closed form's bound past which the switch may move up (see :func:`_wider`)
WIDE_CLOSED = 32.0
#: the series' bound it may then take (u)
WIDE_SERIES = 2.5


def _wider(ser: Series, cert: Certificate, bounds: dict) -> Certificate:
    """Where the closed form just above ``t*`` is past WIDE_CLOSED u (a derivative's
    quotient, ``(s cos s + 2 s - 3 sin s) / s^5``: 181 u at ``t* = 2``, 5979 u for a third
    derivative's), ``t*`` doubles (twice at most) while a series within WIDE_SERIES u
    reaches it and the closed form's bound falls by a third at least: the worse of the two
    branches is what a kernel sees (the SE(3) left Jacobian's Jacobian 9 u at
    ``|w|^2`` just above 2, where the textbook is 3 u)."""
    for _ in range(2):
        t = cert.threshold * 2
        if cert.closed64 <= WIDE_CLOSED or t not in bounds or \
                bounds[t] * 1.5 > cert.closed64:
            break
        n = _order(ser, t, WIDE_SERIES)
        if n is None:
            break
        cert = Certificate(n, t, _taylor_bound(ser, n, t, U64), _taylor_bound(ser, n, t, U32),
                           bounds[t])
    return cert
