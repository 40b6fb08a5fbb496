"""The singular and cancellation sets of a kernel's program, derived from its formula
, not listed by hand.

A list of regimes someone wrote (0, pi, close points, the ends of the range) never
approaches a singular set it does not name: the inverse Jacobians' ``1 - cos theta`` vanishes
at ``theta = 2 pi k``, where the harness never looked and the kernels were 2.5e-2 off. Here
each norm ``theta = sqrt(T)`` of a sub-vector of one argument (``T = w0^2 + w1^2 + w2^2``) is
a symbol; in each declared output (every branch and the main build)

- every **denominator factor** in ``theta`` alone (the base of a negative power:
  ``1 - cos theta``, ``theta sin theta``, ``sin(theta/2)``) and
- every **difference** in ``theta`` alone (an ``Add`` of trigonometric terms, the
  cancellation of nearly equal terms: ``1 - cos theta``, ``theta - sin theta``)

is solved for its zeros ``theta0`` in ``(0, (2 K + 1) pi]`` (``sympy.solveset``; a set it
cannot decide, a transcendental equation, is left out and says so). ``theta = 0`` is every
norm's own (the removable pass's and the harness's ``scale`` regime). The harness then
approaches each zero (:func:`rigidsym.codegen.accuracy.regimes.regimes`, ``derived=True``): the
argument's sub-vector along random axes at norm ``theta0 -+ delta``, ``delta = 10^-1 ..
10^-15``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import sympy as sp

__all__ = ["Zero", "norm_zeros", "K_MULTIPLES"]

#: the multiples approached: theta0 up to (2 K + 1) pi
K_MULTIPLES = 3
_TH = sp.Symbol("theta_norm", positive=True)


@dataclass(frozen=True)
class Zero:
    """A zero ``theta0`` of a denominator factor or a difference in the norm of
    ``args[arg].flat[comps]``."""

    arg: int
    comps: tuple[int, ...]
    theta0: sp.Expr
    what: str          # "denominator" or "difference"
    factor: str        # the factor or difference, as printed

    @property
    def label(self) -> str:
        return f"derived: |norm|->{sp.sstr(self.theta0)} ({self.what})"


def _norms(kernel, syms) -> dict:
    """``{T: (arg index, component indices)}`` for each sum of squares of components of
    one argument (the norms whose roots the kernel's formulas take)."""
    out = {}
    for i, a in enumerate(kernel.args):
        flat = list(sp.Matrix(syms[a.name])) if a.size > 1 else [syms[a.name]]
        if a.kind != "any" or len(flat) < 2:
            continue
        for lo in range(0, len(flat) - 2, 3):    # each 3-vector block (w of xi = [w; v])
            comps = tuple(range(lo, lo + 3))
            out[sum(flat[j] ** 2 for j in comps)] = (i, comps)
    return out


def _solve(f) -> list:
    top = (2 * K_MULTIPLES + 1) * sp.pi
    try:
        s = sp.solveset(f, _TH, sp.Interval.Lopen(0, top))
    except (NotImplementedError, ValueError, TypeError):
        return []
    return sorted(s, key=float) if isinstance(s, sp.FiniteSet) else []


def _parts(e):
    """Denominator factors and differences of ``e`` that hold theta alone."""
    dens, diffs = set(), set()
    for p in sp.preorder_traversal(e):
        if isinstance(p, sp.Pow) and p.exp.is_negative and p.base.free_symbols == {_TH}:
            for f in sp.Mul.make_args(sp.factor_terms(p.base)):
                if f.has(sp.sin, sp.cos, sp.tan):
                    dens.add(f)
        elif isinstance(p, sp.Add) and p.free_symbols == {_TH} and p.has(sp.sin, sp.cos):
            diffs.add(p)
    return dens, diffs


@cache
def norm_zeros(kernel) -> tuple[Zero, ...]:
    """The derived zeros of ``kernel`` (a :class:`rigidsym.codegen.spec.Kernel`; a Jacobian
    kernel's are its values'), nonzero, up to :data:`K_MULTIPLES` multiples."""
    from rigidsym.codegen.spec import flatten_outputs, input_symbols

    spec = getattr(kernel, "jacobian_of", None) or kernel
    syms = input_symbols(spec)
    norms = _norms(spec, syms)
    if not norms:
        return ()
    builds = [b.build for b in spec.branches] + [spec.build]
    found: dict = {}
    for build in builds:
        outs = [sp.sympify(e) for e in flatten_outputs(spec, build(**syms))]
        for T, where in norms.items():
            def sub(x, T=T):
                return (isinstance(x, sp.Pow) and x.base == T and x.exp.is_Rational
                        and x.exp.q == 2)
            for e in outs:
                e1 = e.replace(sub, lambda x: _TH ** int(2 * x.exp))
                if not e1.has(_TH):
                    continue
                dens, diffs = _parts(e1)
                for what, fs in (("denominator", dens), ("difference", diffs)):
                    for f in fs:
                        for t0 in _solve(f):
                            key = (where, t0, what)
                            if key not in found:
                                found[key] = Zero(where[0], where[1], t0, what, sp.sstr(f))
    return tuple(sorted(found.values(), key=lambda z: (z.arg, float(z.theta0), z.what)))
