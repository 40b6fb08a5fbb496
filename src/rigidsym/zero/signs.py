"""``|x|`` and ``x^(p/2)`` of a rational function, where they are rational functions again.

The rational run of a program (:func:`rigidsym.zero.program.run_rational`) computes with
fractions of polynomials; ``|n/d|`` and ``sqrt(n/d)`` are fractions of polynomials only where
the signs are known everywhere. Known here by a sufficient test, exact and cheap: a
polynomial whose every term has even exponents and a coefficient of one sign (``1 + u² +
v²``, the stereographic denominator) never changes sign. ``sqrt(s²/t²)`` is ``|s|/|t|`` for
such ``s`` and ``t`` (``‖ω̂‖`` of a unit vector is ``sqrt((1 + u² + v²)²/(1 + u² + v²)²)``).
Anything else stays :class:`~rigidsym.zero.plan.Unsupported`: never a guessed
sign.
"""

from __future__ import annotations

from rigidsym.zero.plan import Unsupported

__all__ = ["definite_abs", "definite_sqrt"]


def _sign(poly) -> int | None:
    """``+1`` (``-1``) where ``poly`` is ``>= 0`` (``<= 0``) everywhere by the test above,
    else ``None``."""
    signs = set()
    for exps, coeff in poly.to_dict().items():
        if any(e % 2 for e in exps):
            return None
        signs.add(1 if coeff > 0 else -1)
    return signs.pop() if len(signs) == 1 else None


def definite_abs(x):
    """``|n/d|`` as a fraction ``(n', d)``.

    Raises:
        Unsupported: the sign of ``n`` or ``d`` is not known everywhere.
    """
    n, d = x
    if n.is_zero():
        return x
    sn, sd = _sign(n), _sign(d)
    if sn is None or sd is None:
        raise Unsupported("the rational function of |x| with x of no constant sign")
    return (n if sn * sd > 0 else -n, d)


def definite_sqrt(x, q: int):
    """``(n/d)^(1/q)`` as a fraction, for ``q == 2`` and ``n``, ``d`` squares of
    polynomials of constant sign (the principal root: ``|s|/|t|``).

    Raises:
        Unsupported: another root, or a radicand that is not such a square.
    """
    n, d = x
    if q != 2:
        raise Unsupported("the rational function of a root other than a square root")
    if n.is_zero():
        return x
    try:
        s, t = n.sqrt(), d.sqrt()
    except Exception:  # flint's DomainError: not a perfect square over Q
        raise Unsupported("the rational function of the square root of a non-square") \
            from None
    ss, st = _sign(s), _sign(t)
    if ss is None or st is None:
        raise Unsupported("the rational function of sqrt(x²) with x of no constant sign")
    return (s if ss > 0 else -s, t if st > 0 else -t)
