"""Free scalars that are angles by what the LaTeX does with them: a symbol no ``--let``
declares that occurs only in the arguments of sin, cos, tan, cot, sec and csc, each time
with a rational coefficient (``\\sin 2\\theta``, ``\\cos(\\theta + \\phi)``,
``\\tan\\frac{\\theta}{2}``).

With d the least common multiple of the coefficients' denominators, every such expression
has period 2πd in the symbol, and writing the symbol as d ψ makes every coefficient an
integer. So a relation holds for every real value exactly when it holds for ψ on (-π, π),
where the zero test's angle (``ψ = 2 atan τ``, :func:`rigidsym.algebra.symbols.angle`)
ranges: a relation of continuous members that holds on a dense set holds wherever both are
defined. For d = 1 the symbol is the angle itself; ``\\cos\\frac{\\theta}{2}`` (period 4π)
is decided over θ = 2ψ, a whole period, so that ``\\cos\\frac{\\theta}{2} =
\\sqrt{(1 + \\cos\\theta)/2}``, true on (-π, π) only, does not hold, with θ beyond π as the
counterexample. Without this the zero test leaves such a relation undecided ("trig of
non-angle argument θ") unless the reader writes ``--let '\\theta: angle'``; with it nothing
is assumed that the LaTeX does not imply. A bare occurrence (``\\theta\\sin\\theta``), a
derivative in it or an inverse trigonometric function keeps the symbol free.
"""

from __future__ import annotations

import math

import sympy as sp
from sympy.functions.elementary.trigonometric import TrigonometricFunction

__all__: list[str] = []


def _only_periodic(x, s: sp.Symbol, seen: set, dens: set) -> bool:
    """``s`` occurs in ``x`` only as ``k s + rest`` (rational k, ``rest`` free of s) inside
    trigonometric functions; records the functions' names in ``seen`` and the
    coefficients' denominators in ``dens``."""
    if x == s:
        return False
    if not isinstance(x, sp.Basic) or s not in x.free_symbols:
        return True
    if isinstance(x, TrigonometricFunction) and len(x.args) == 1:
        arg = sp.expand(x.args[0])
        k = arg.coeff(s)
        if isinstance(k, sp.Rational) and k != 0 and s not in (arg - k * s).free_symbols:
            seen.add(type(x).__name__)
            dens.add(int(k.q))
            return True
        return False
    return all(_only_periodic(a, s, seen, dens) for a in x.args)


def periodic_angles(exprs, symbols) -> dict[sp.Symbol, tuple[list[str], int]]:
    """The symbols of ``symbols`` that occur in ``exprs`` and only in trigonometric
    arguments with rational coefficients, each with the functions it occurs in (sorted)
    and d, the least common multiple of the coefficients' denominators: the symbol is
    d times an angle of (-π, π).

    Args:
        exprs: sympy expressions (scalars, matrices, matrix expressions); anything else is
            ignored.
        symbols: the candidate scalar symbols (the free scalars of a reading).
    """
    exprs = [e for e in exprs if isinstance(e, sp.Basic)]
    out: dict[sp.Symbol, tuple[list[str], int]] = {}
    for s in symbols:
        seen: set[str] = set()
        dens: set[int] = set()
        if any(s in e.free_symbols for e in exprs) \
                and all(_only_periodic(e, s, seen, dens) for e in exprs):
            out[s] = (sorted(seen), math.lcm(*dens))
    return out
