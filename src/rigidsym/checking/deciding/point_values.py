"""Exact values at a counterexample, for describing it
(:mod:`rigidsym.checking.deciding.counterexample`):
the plan's atoms at the point (angles as ``2M atan(t)``, consistent with their cosines),
closed forms where a value is irrational (``√21/4``), decimals for reading.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import TIME, constraint_of
from rigidsym.checking.deciding.explicit import entries_of
from rigidsym.printing.names import strip_private
from rigidsym.zero.decide import Unsupported, evaluate
from rigidsym.zero.plan import TRIG

__all__ = ["PointValues", "decimal_text", "decimal", "atom_base", "point_atoms", "plain_name",
           "group_base"]


class PointValues:
    """Exact values at the point: plan atoms by the plan's rules, angles consistent."""

    def __init__(self, plan, pt: dict):
        self.plan, self.pt = plan, pt
        self.spt = {k: sp.Rational(v.numerator, v.denominator) for k, v in pt.items()}
        self.memo: dict = {}
        #: free atoms the failing member does not depend on (they cancel), set to 1/2
        self.filled: list = []

    def angle(self, a):
        """The bare angle ``2M atan(t)`` of an angle atom."""
        tau, M = self.plan.angles[a]
        return 2 * M * sp.atan(self.spt[tau])

    def atom(self, a):
        hit = self.memo.get(a)
        if hit is None:
            if a in self.plan.angles:  # bare or not: phi = 2M atan(t), consistent
                hit = self.angle(a)
            elif a not in self.plan.rules and constraint_of(atom_base(a)[0]) is None:
                hit = sp.Rational(1, 2)  # any value: the member does not depend on it
                self.filled.append(a)
            else:
                f = evaluate(a, self.plan, self.pt)
                hit = sp.Rational(f.numerator, f.denominator)
            self.memo[a] = hit
        return hit

    def scalar(self, e):
        e = sp.sympify(e)
        if not e.has(sp.pi, *self.plan.bare):
            try:  # the fast exact evaluator, when it applies
                f = evaluate(e, self.plan, self.pt)
                return sp.Rational(f.numerator, f.denominator)
            except (Unsupported, KeyError):
                pass
        if e.has(*TRIG):
            e = e.replace(lambda x: isinstance(x, TRIG), lambda x: self._trig(x))
        atoms = e.atoms(sp.Derivative) | e.atoms(AppliedUndef) | e.free_symbols
        sub = {a: self.atom(a) for a in atoms if a != TIME}
        out = e.xreplace(sub)
        if out.free_symbols:
            raise Unsupported(f"no value for {sorted(map(str, out.free_symbols))}")
        return sp.radsimp(out) if out.has(sp.Pow) else out

    def _trig(self, x):
        f = evaluate(x, self.plan, self.pt)
        return sp.Rational(f.numerator, f.denominator)

    def value(self, v):
        if isinstance(v, sp.MatrixBase):
            return sp.ImmutableMatrix(v.rows, v.cols, [self.scalar(e) for e in v])
        return self.scalar(v)


def decimal(x) -> str:
    """Decimals of an exact number (8 significant digits), "" when it is an integer."""
    if x.is_Integer:
        return str(x)
    v = float(sp.N(x, 17))
    return f"{v:.8g}"


def decimal_text(v) -> str:
    """Decimals of an exact value in book layout (``[0.6; 1; 0.8]``), "" when exact is
    already all integers."""
    entries = entries_of(v)
    if all(sp.sympify(e).is_Integer for e in entries):
        return ""
    if isinstance(v, sp.MatrixBase):
        return "[" + "; ".join(", ".join(decimal(v[i, j]) for j in range(v.cols))
                               for i in range(v.rows)) + "]"
    return decimal(v)


def atom_base(a):
    """``(base atom, derivative order)`` of a plan atom."""
    if isinstance(a, sp.Derivative):
        return a.expr, sum(int(k) for _, k in a.variable_count)
    return a, 0


def point_atoms(plan) -> list:
    """The atoms the point gives a value: the plan's (π aside) and the angles that appear
    only inside cos/sin."""
    atoms = set(plan.rules) | set(plan.angles)
    atoms.discard(sp.pi)
    return sorted(atoms, key=sp.default_sort_key)


def plain_name(a) -> str:
    """The name of plan atom ``a``'s base symbol (a function's name for an applied function)."""
    base, _ = atom_base(a)
    return base.func.__name__ if isinstance(base, AppliedUndef) else base.name


def group_base(name: str) -> str:
    """The ASCII name of the vector an entry atom belongs to (``s38_mu1`` -> ``mu``,
    ``a_2`` -> ``a``), as :func:`rigidsym.printing.notation.book_group` reads it."""
    name = strip_private(name)
    return re.sub(r"_\d+$", "", name) if re.search(r"_\d+$", name) else \
        re.sub(r"(?<=[A-Za-z])\d+$", "", name)
