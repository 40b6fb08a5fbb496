"""Step 1 of the zero test (:mod:`rigidsym.zero.decide`): the *plan* that parametrises constrained
atoms by rational functions of free parameters (stereographic unit vectors, rational
quaternions, ``tan(phi / 2M)`` for the trigonometric functions of an angle) and turns
derivatives along a motion into jets of those parameters.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache
from math import gcd

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import TIME, constrained_atom, constraint_of
from rigidsym.core import kinds as _kinds

TRIG = (sp.cos, sp.sin, sp.tan, sp.cot, sp.sec, sp.csc)


class Unsupported(Exception):
    """The expression holds something the exact evaluator cannot treat."""


def _atom_name(a) -> str:
    if isinstance(a, sp.Symbol):
        return a.name
    if isinstance(a, AppliedUndef):
        return a.func.__name__
    raise TypeError(a)


def _constraint(a):
    return constraint_of(a)  # carried by the atom itself, never looked up by name


def _is_angle_atom(a) -> bool:
    if isinstance(a, sp.Symbol | AppliedUndef):
        c = _constraint(a)
        return c is not None and _kinds.get(c.kind).half_angle
    return False


def _deriv_order(d: sp.Derivative) -> int:
    n = 0
    for v, k in d.variable_count:
        if v != TIME:
            raise Unsupported(f"derivative with respect to {v}, not time")
        n += int(k)
    return n


# --------------------------------------------------------------------------- jets
def _jet_symbol(name: str, k: int, timed: bool = True) -> sp.Symbol:
    """Symbol for the k-th time derivative of atom ``name`` (``name(t)``, ``name__d1`` …).

    Static atoms keep their own symbol; time-dependent ones get names that cannot clash
    with a static atom of the same book name.
    """
    if not timed:
        return sp.Symbol(name, real=True)
    return sp.Symbol(f"{name}(t)" if k == 0 else f"{name}__d{k}", real=True)


def _replace_jets(expr, funcs: dict[str, sp.Expr]):
    """Replace f(t) and its derivatives, for f named in ``funcs``, by jet symbols."""
    reps = {}
    for d in expr.atoms(sp.Derivative):
        reps[d] = _jet_symbol(_atom_name(d.expr), _deriv_order(d))
    expr = expr.xreplace(reps)
    return expr.xreplace({f: _jet_symbol(n, 0) for n, f in funcs.items()})


#: the group name the generic rules are derived under, renamed to each group's own
_GENERIC = "rigidsym_generic_group"


@cache
def _group_rules(kind: str, name: str, names: tuple[str, ...], timed: bool, order: int):
    """Rational rules ``(atom name, derivative order) -> expr`` for a constrained group.

    The derivatives are taken once per kind and order (a rotation's second derivative takes
    a second), under a generic name whose parameters are then renamed to this group's.
    """
    generic = _generic_rules(kind, timed, order)
    syms = set().union(*(ex.free_symbols for rules in generic for ex in rules.values()))
    rename = {x: sp.Symbol(name + x.name[len(_GENERIC):], real=True) for x in syms
              if x.name.startswith(_GENERIC)}
    return {(n, k): ex.xreplace(rename)
            for n, rules in zip(names, generic, strict=True) for k, ex in rules.items()}


@cache
def _generic_rules(kind: str, timed: bool, order: int) -> list[dict]:
    """Per entry of the group, ``{derivative order: expr}`` under the name :data:`_GENERIC`
    (the parametrisation of the kind's row in :mod:`rigidsym.core.kinds`)."""
    name = _GENERIC
    t = TIME
    k = _kinds.get(kind)
    if k.parametrise is None:
        raise ValueError(f"kind: {kind!r} has no rational parametrisation")
    pn = [f"{name}__{p}" for p in k.params]
    P = [sp.Function(p, real=True)(t) for p in pn] if timed else \
        [_jet_symbol(p, 0, timed=False) for p in pn]
    vals = list(k.parametrise(P))  # the kind table's rational parametrisation
    out = []
    funcs = dict(zip(pn, P, strict=True)) if timed else {}
    for val in vals:
        rules = {}
        for k in range(order + 1 if timed else 1):
            ex = sp.diff(val, t, k) if k else val
            rules[k] = _replace_jets(ex, funcs) if timed else ex
        out.append(rules)
    return out


# --------------------------------------------------------------------------- plan
@dataclass
class Plan:
    """How to evaluate a family of expressions exactly.

    Attributes:
        rules: atom (Symbol, f(t) or Derivative) -> rational expression in parameters.
        angles: angle atom -> (tau symbol, M) with ``tau = tan(angle / (2 M))``.
        bare: angle atom -> symbol standing for the bare angle (independent variable).
        params: the free parameters, sorted by name.
    """

    rules: dict = field(default_factory=dict)
    angles: dict = field(default_factory=dict)
    bare: dict = field(default_factory=dict)
    params: list = field(default_factory=list)


def linear_angles(arg) -> tuple[dict, Fraction]:
    """Write a trig argument as sum c_j * angle_j + c * pi with rational c_j, c."""
    arg = sp.expand(arg)
    coeffs: dict = {}
    cpi = Fraction(0)
    for term in sp.Add.make_args(arg):
        c, rest = term.as_coeff_Mul()
        if not c.is_Rational:
            raise Unsupported(f"trig argument {arg}")
        if rest == sp.pi:
            cpi += Fraction(int(c.p), int(c.q))
        elif _is_angle_atom(rest):
            coeffs[rest] = coeffs.get(rest, Fraction(0)) + Fraction(int(c.p), int(c.q))
        else:
            raise Unsupported(f"trig of non-angle argument {arg} (an angle is a symbol "
                              f"declared so: --let 'NAME: angle', angle() in a module)")
    if (2 * cpi).denominator != 1:
        raise Unsupported(f"trig argument with pi multiple {cpi}")
    return coeffs, cpi


def walk_tree(expr, visit):
    """Visit each distinct node of ``expr`` once, depth first; a node's arguments are visited
    only where ``visit(node)`` returns true."""
    seen = set()
    stack = [expr]
    while stack:
        x = stack.pop()
        if x in seen:
            continue
        seen.add(x)
        if visit(x):
            stack.extend(x.args)


def make_plan(exprs) -> Plan:
    """Collect atoms of ``exprs`` and build the parametrisation that imposes constraints."""
    plan = Plan()
    params: set = set()
    denoms: dict = {}
    groups: dict = {}
    free: set = set()

    def visit(x):
        if isinstance(x, sp.Derivative):
            base = x.expr
            if not isinstance(base, AppliedUndef):
                raise Unsupported(f"derivative of a non-atom {x}")
            _note(base, _deriv_order(x))
            return False
        if isinstance(x, AppliedUndef):
            _note(x, 0)
            return False
        if isinstance(x, sp.Symbol):
            if x != TIME:
                _note(x, 0)
            return False
        if x == sp.pi:
            # pi outside a trig argument: transcendental, so an independent variable is exact
            plan.rules[sp.pi] = sp.Symbol("pi__var", real=True)
            params.add(plan.rules[sp.pi])
            return False
        if isinstance(x, TRIG):
            try:
                coeffs, _ = linear_angles(x.args[0])
            except Unsupported:  # sin(acos(c)): the balls evaluate it; the exact
                return True      # translation refuses it (rigidsym.zero.program)
            for a, c in coeffs.items():
                denoms[a] = denoms.get(a, 1) * c.denominator // gcd(denoms.get(a, 1),
                                                                    c.denominator)
            return False
        return True

    def _note(atom, k):
        c = _constraint(atom)
        if c is None or _kinds.get(c.kind).half_angle:
            free.add((atom, k))
            if c is not None and k == 0:
                denoms.setdefault(atom, 1)
        else:
            groups[c] = max(groups.get(c, 0), k)

    for e in exprs:
        walk_tree(sp.sympify(e), visit)
    _assemble(plan, params, denoms, groups, free)
    return plan


def _assemble(plan: Plan, params: set, denoms: dict, groups: dict, free: set) -> None:
    """Fill ``plan`` from what :func:`make_plan`'s walk collected: the constrained groups
    (with their highest derivative order), the free atoms, the angles' denominators."""
    # Constrained groups: rational rules for all atoms and derivative orders present.
    for c, order in groups.items():
        rules = _group_rules(c.kind, c.name, c.names, c.timed, order)
        for (n, k), ex in rules.items():
            atom = constrained_atom(n, c)
            key = atom if k == 0 else sp.Derivative(atom, (TIME, k))
            plan.rules[key] = ex
            params |= ex.free_symbols
    # Free atoms (and bare angles, kept independent): each its own variable.
    for atom, k in free:
        sym = _jet_symbol(_atom_name(atom), k)
        key = atom if k == 0 else sp.Derivative(atom, (TIME, k))
        if isinstance(atom, sp.Symbol) and k == 0:
            plan.rules.setdefault(key, atom)
        else:
            plan.rules[key] = sym
        params.add(plan.rules[key] if k == 0 and isinstance(atom, sp.Symbol) else sym)
        if _is_angle_atom(atom) and k == 0:
            plan.bare[atom] = plan.rules[key]
    for a, M in denoms.items():
        tag = "(t)" if isinstance(a, AppliedUndef) else ""
        tau = sp.Symbol(f"tan({_atom_name(a)}{tag}/{2 * M})", real=True)
        plan.angles[a] = (tau, M)
        params.add(tau)
    plan.params = sorted(params, key=lambda s: s.name)
