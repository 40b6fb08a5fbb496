"""Principal branches the zero test honours exactly: ``acos``, ``asin`` and ``atan2``.

The zero test decides rational functions of its parameters; ``acos`` and ``atan2`` are
not. Before it runs, each is rewritten where its value is known exactly on the whole
declared domain, and left alone otherwise (the zero test then says ``undecided``):

- ``acos(E)`` with ``E - cos(b) = 0`` (decided exactly) for an angle ``b`` on ``[0, pi]``
  (``angle(..., range="[0, pi]")``) is ``b``; with ``E + cos(b) = 0``, ``pi - b``;
- an angle ``a`` on the default range ``(-pi, pi)`` whose cosine an ``acos`` reads is
  split into the two cases ``a = b`` and ``a = -b`` with ``b`` on ``[0, pi]``: the
  relation holds when it holds in both, and a counterexample lies in one of them
  (``acos(cos a) = |a|``: MR's ``theta = acos((tr R - 1) / 2)`` is false for ``a < 0``);
- ``atan2(y, x)`` with ``y cos a - x sin a = 0`` and ``x cos a + y sin a`` a positive
  number (decided exactly) for an angle ``a`` is ``a`` (both ranges lie in ``(-pi, pi]``);
- ``asin(E)`` with ``E - sin(b/2) = 0`` (decided exactly) for an angle ``b`` on ``[0, pi]``
  is ``b/2`` (``b/2`` lies in ``[0, pi/2]``, asin's principal range): the angle of a rotation
  of at most a quarter turn read from ``|vect Q| = sin(theta)``, ``theta = b/2`` (the Lie
  logs' small-angle branches);
- a half-integer power ``E^(k/2)`` (the norm ``theta = sqrt(w^T w)`` of a rotation vector
  and its powers) with ``E - (c f(b))^2 = 0`` (decided exactly) for an angle ``b``
  on ``[0, pi]``, ``f`` one of ``b``, ``sin b``, ``cos(b/2)``, ``sin(b/2)`` (each non-
  negative there) and ``c`` in ``{1, 2, 1/2}``, is ``(c f(b))^k``: the polar parametrisation
  ``w = theta e`` (``theta >= 0``, ``e`` a unit vector) makes the trigonometric functions of
  a norm those of an angle; an angle ``a`` of the default range whose square a root reads is
  split into ``a = b``, ``a = -b`` as for ``acos`` (``sqrt(a^2) = |a|``).

The balls evaluate the unrewritten ``acos``/``atan2`` (python-flint), so a verdict is
still backed by arithmetic independent of these rules.
"""

from __future__ import annotations

from itertools import product

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import constrained_group, constraint_of
from rigidsym.zero.decide import decide_zero

__all__ = ["cases"]


def _angles(expr, kind: str | None = None) -> list:
    out = []
    for a in expr.free_symbols | expr.atoms(AppliedUndef):
        c = constraint_of(a)
        if c is not None and c.kind in ("angle", "angle_pi") and (kind is None or
                                                                  c.kind == kind):
            out.append(a)
    return sorted(out, key=sp.default_sort_key)


def _zero(e) -> bool:
    return decide_zero([e]).zero is True


def _acos_value(E):
    for b in _angles(E, "angle_pi"):
        if _zero(E - sp.cos(b)):
            return b
        if _zero(E + sp.cos(b)):
            return sp.pi - b
    return None


def _asin_value(E):
    for b in _angles(E, "angle_pi"):
        if _zero(E - sp.sin(b / 2)):
            return b / 2
    return None


def _atan2_value(y, x):
    for a in _angles(y + x):
        if _zero(y * sp.cos(a) - x * sp.sin(a)):
            k = x * sp.cos(a) + y * sp.sin(a)  # the radius: a positive constant, exactly
            c = k.xreplace({a: sp.Integer(0)})
            if c.is_Rational and c > 0 and _zero(k - c):
                return a
    return None


def _is_root(z) -> bool:
    """``E^(k/2)`` for an odd ``k``: a norm, or a power of one."""
    return isinstance(z, sp.Pow) and z.exp.is_Rational and z.exp.q == 2


def _root_value(E, k):
    # sqrt(E) = c f(b) for f(b) >= 0 on [0, pi]: the norm b of w = b e, sin b of
    # sin(acos(cos b)), 2 cos(b/2) of sqrt(1 + tr Q) (an Euler-Rodrigues parameter)
    for b in _angles(E, "angle_pi"):
        for f in (b, sp.sin(b), sp.cos(b / 2), sp.sin(b / 2)):
            for c in (1, 2, sp.Rational(1, 2)):
                if _zero(E - (c * f)**2):
                    return (c * f)**k
    return None


def _resolve(x):
    def rule(z):
        if isinstance(z, sp.acos):
            v = _acos_value(z.args[0])
        elif isinstance(z, sp.asin):
            v = _asin_value(z.args[0])
        elif isinstance(z, sp.atan2):
            v = _atan2_value(*z.args)
        else:
            v = _root_value(z.base, z.exp.p)
        return z if v is None else v

    return x.replace(lambda z: isinstance(z, sp.acos | sp.asin | sp.atan2) or _is_root(z),
                     rule)


def _apply(x, f):
    return x.applyfunc(f) if isinstance(x, sp.MatrixBase) else f(x)


def _nodes(exprs: list, types: tuple) -> set:
    """The subexpressions of ``exprs`` of one of ``types`` (``Basic.atoms(*types)`` of
    each, united), each distinct node visited once: ``atoms`` walks a subexpression shared
    by many entries (a rotation matrix in every entry of a product) once per occurrence,
    a tenth of a cold ``rigidsym verify``."""
    out, seen = set(), set()
    stack = list(exprs)
    while stack:
        x = stack.pop()
        if id(x) in seen:
            continue
        seen.add(id(x))
        if isinstance(x, types):
            out.add(x)
        stack.extend(x.args)
    return out


def cases(lhs, rhs) -> list[tuple]:
    """The cases to decide: ``(lhs, rhs, lhs', rhs', sub)`` with the split angles
    substituted, then also ``acos``/``atan2`` rewritten, and ``sub`` the substitution of
    the case (split angle ``a`` -> ``s b``, so that a counterexample is described in ``a``);
    one case, ``(lhs, rhs, lhs, rhs, {})``, when the relation holds neither."""
    ents = list(lhs) if isinstance(lhs, sp.MatrixBase) else [lhs]
    ents += list(rhs) if isinstance(rhs, sp.MatrixBase) else [rhs]
    fns = _nodes([sp.sympify(e) for e in ents], (sp.acos, sp.asin, sp.atan2, sp.Pow))
    fns = {f for f in fns if not isinstance(f, sp.Pow) or _is_root(f)}
    if not fns:
        return [(lhs, rhs, lhs, rhs, {})]
    split = []
    for f in sorted(fns, key=sp.default_sort_key):
        if isinstance(f, sp.acos | sp.Pow):
            arg = f.args[0]
            for a in _angles(arg, "angle"):
                if isinstance(a, sp.Symbol) and a not in split and \
                        _zero(arg - (sp.cos(a) if isinstance(f, sp.acos) else a**2)):
                    split.append(a)
    out = []
    for signs in product((1, -1), repeat=len(split)):
        sub, sign = {}, dict(zip(split, signs, strict=True))
        for a, s in sign.items():
            b = constrained_group("angle_pi", a.name if s > 0 else f"{a.name}_neg")
            sub[a] = s * b

        def exact(e, sub=sub, sign=sign):
            # acos(cos a) = s a in the case a = s b, replaced before a is (a rebuilt
            # sin(acos(c)) would turn into sqrt(1 - c^2), which the zero test cannot read)
            e = e.replace(lambda z: isinstance(z, sp.acos),
                          lambda z: _split_acos(z, sign))
            return _resolve(e.xreplace(sub))

        subbed = [_apply(x, lambda e, sub=sub: e.xreplace(sub)) for x in (lhs, rhs)]
        out.append((*subbed, *(_apply(x, exact) for x in (lhs, rhs)), sub))
    return out


def _split_acos(z, sign: dict):
    for a, s in sign.items():
        if _zero(z.args[0] - sp.cos(a)):
            return s * a
    return z
