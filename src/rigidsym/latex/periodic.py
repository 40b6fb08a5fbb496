"""Free scalars that are angles by what the LaTeX does with them: a symbol no ``--let``
declares that occurs only in the arguments of sin, cos, tan, cot, sec and csc, each time
with an integer coefficient (``\\sin 2\\theta``, ``\\cos(\\theta + \\phi)``).

Every such expression has period 2π in the symbol, so a relation holds for every real
value exactly when it holds on (-π, π), where the zero test's angle (``θ = 2 atan τ``,
:func:`rigidsym.algebra.symbols.angle`) ranges (a relation of continuous members that holds
on a dense set holds wherever both are defined). Without this the zero test leaves such a
relation undecided ("trig of non-angle argument θ") unless the reader writes
``--let '\\theta: angle'``; with it nothing is assumed that the LaTeX does not imply. A
bare occurrence (``\\theta\\sin\\theta``), a derivative in it, an inverse trigonometric
function or a fractional coefficient (``\\cos\\frac{\\theta}{2}``, period 4π) keeps the
symbol free: there (-π, π) would be an assumption.
"""

from __future__ import annotations

import sympy as sp
from sympy.functions.elementary.trigonometric import TrigonometricFunction

__all__: list[str] = []


def _only_periodic(x, s: sp.Symbol, seen: set) -> bool:
    """``s`` occurs in ``x`` only as ``k s + rest`` (integer k, ``rest`` free of s) inside
    trigonometric functions; records the functions' names in ``seen``."""
    if x == s:
        return False
    if not isinstance(x, sp.Basic) or s not in x.free_symbols:
        return True
    if isinstance(x, TrigonometricFunction) and len(x.args) == 1:
        arg = sp.expand(x.args[0])
        k = arg.coeff(s)
        if isinstance(k, sp.Integer) and k != 0 and s not in (arg - k * s).free_symbols:
            seen.add(type(x).__name__)
            return True
        return False
    return all(_only_periodic(a, s, seen) for a in x.args)


def periodic_angles(exprs, symbols) -> dict[sp.Symbol, list[str]]:
    """The symbols of ``symbols`` that occur in ``exprs`` and only in trigonometric
    arguments with integer coefficients, each with the functions it occurs in (sorted).

    Args:
        exprs: sympy expressions (scalars, matrices, matrix expressions); anything else is
            ignored.
        symbols: the candidate scalar symbols (the free scalars of a reading).
    """
    exprs = [e for e in exprs if isinstance(e, sp.Basic)]
    out: dict[sp.Symbol, list[str]] = {}
    for s in symbols:
        seen: set[str] = set()
        if any(s in e.free_symbols for e in exprs) \
                and all(_only_periodic(e, s, seen) for e in exprs):
            out[s] = sorted(seen)
    return out
