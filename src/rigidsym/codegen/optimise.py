"""Symbolic optimisation of kernel expressions before printing.

1. Half-angle rewrite of every angle input ``phi`` (own rewrite, through
   :class:`sympy.codegen.rewriting.ReplaceOptim`): a sum ``k (1 - cos phi)`` hidden in an
   ``Add`` becomes ``2 k sin^2(phi/2)``, ``k (1 + cos phi)`` becomes ``2 k cos^2(phi/2)``;
   then ``sin phi -> 2 sin(phi/2) cos(phi/2)`` and ``cos phi`` by one of :data:`COS_FORMS`
   (chosen per kernel by measured error, :mod:`.accuracy.cos_form`). This removes the cancellation
   of ``1 - cos phi`` near 0 (and of ``1 + cos phi`` near pi), turns removable ratios such
   as ``sin phi / (1 - cos phi)`` into ``cot(phi/2)`` by sympy's automatic power
   collection, and leaves two transcendental calls per angle.
2. ``sympy.cse`` over all outputs (and denominators) of a kernel at once, so
   sub-expressions are shared across outputs.
3. Operation count of the result (``sympy.count_ops`` of the CSE'd program).
4. The split of a trig-calling program into its sine and cosine calls, computed by a SIMD
   loop ahead of the rest (:func:`trig_split`; used by the C extension's blocked batch loop
   and by the float32 precision plans).

Everything is deterministic: no sets are iterated without sorting.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.codegen.rewriting import ReplaceOptim, optimize
from sympy.printing.repr import ReprPrinter

__all__ = ["COS_FORMS", "half_angle_optims", "Program", "compile_program", "math_hash",
           "divides_or_roots", "trig_split"]

#: the forms of a bare ``cos phi`` from ``s = sin(phi/2)``, ``c = cos(phi/2)`` (each rounded,
#: relative error about u/2). ``1 - 2 s^2`` is off by about 3 u absolute near pi, where
#: ``cos phi`` itself (libm, the textbook) is off by u/2: the error of ``s^2`` (1.5 u) twice
#: (L_matrix 5.2 u near pi where the textbook is 2-4 u). ``2 c^2 - 1`` is the
#: mirror image (accurate near pi, 3 u near 0); the piecewise form takes the better of the
#: two (at most about 1.5 u); ``(c - s)(c + s)`` has no branch (at most about 2.5 u).
COS_FORMS = {
    "1 - 2 s^2": lambda s, c: 1 - 2 * s**2,
    "1 - 2 s^2 or 2 c^2 - 1": lambda s, c: sp.Piecewise((1 - 2 * s**2, s**2 < sp.S.Half),
                                                        (2 * c**2 - 1, True)),
    "(c - s) (c + s)": lambda s, c: (c - s) * (c + s),
}
DEFAULT_COS = "1 - 2 s^2"


def half_angle_optims(phi: sp.Symbol, cos_form: str = DEFAULT_COS) -> list:
    """The rewrites of :mod:`sympy.codegen.rewriting` that make ``phi`` cancellation-free;
    a bare ``cos phi`` left becomes :data:`COS_FORMS` ``[cos_form]``."""
    C, S = sp.cos(phi), sp.sin(phi)
    s, c = sp.sin(phi / 2), sp.cos(phi / 2)
    cos_phi = COS_FORMS[cos_form](s, c)

    def _fold(add: sp.Add) -> sp.Expr:
        k = sp.S.Zero           # coefficient of cos(phi)
        rest = []               # terms free of phi
        other = []              # terms with phi but not linear in cos(phi)
        for t in add.args:
            if not t.has(phi):
                rest.append(t)
                continue
            q = t / C
            if not q.has(phi):
                k += q
            else:
                other.append(t)
        if k == 0:
            return add
        r = sp.Add(*rest)
        if sp.expand(r + k) == 0:       # k cos - k = -k (1 - cos) = -2 k sin^2(phi/2)
            return sp.Add(-2 * k * s**2, *other)
        if sp.expand(r - k) == 0:       # k cos + k = 2 k cos^2(phi/2)
            return sp.Add(2 * k * c**2, *other)
        return add

    fold = ReplaceOptim(lambda x: x.is_Add and x.has(C), _fold)
    last = ReplaceOptim(lambda x: x in (S, C),
                        lambda x: 2 * s * c if x == S else cos_phi)
    return [fold, last]


def rewrite(expr: sp.Expr, angles: list[sp.Symbol], cos_form: str = DEFAULT_COS) -> sp.Expr:
    """Apply the half-angle rewrites for each angle symbol."""
    for phi in angles:
        expr = optimize(expr, half_angle_optims(phi, cos_form))
    return expr


def denominators(exprs) -> list[sp.Expr]:
    """Bases of negative powers in ``exprs`` (sorted, unique): where a division happens."""
    found = set()
    for e in exprs:
        for p in sp.preorder_traversal(e):
            if isinstance(p, sp.Pow) and p.exp.is_negative:
                found.add(p.base)
    return sorted(found, key=sp.default_sort_key)


@dataclass
class Program:
    """A straight-line program: ``temps`` (symbol, expr) then ``outputs`` and ``dens``."""

    temps: list
    outputs: list
    dens: list
    ops: int


def compile_program(outputs: list[sp.Expr], angles: list[sp.Symbol],
                    cos_form: str = DEFAULT_COS) -> Program:
    """Rewrite (``cos_form``: the form of a bare ``cos phi``, :data:`COS_FORMS`), CSE and
    count a flat list of scalar outputs.

    Returns a :class:`Program` whose ``dens`` are the expressions divided by (a sample is
    singular where one of them is exactly 0).
    """
    rw = [rewrite(sp.sympify(e), angles, cos_form) for e in outputs]
    dens = denominators(rw)
    temps, red = sp.cse(rw + dens, symbols=sp.numbered_symbols("x"), order="canonical")
    n = len(rw)
    ops = sum(int(sp.count_ops(v)) for _, v in temps) + sum(int(sp.count_ops(v)) for v in red)
    return Program(temps=list(temps), outputs=list(red[:n]), dens=list(red[n:]), ops=ops)


class _SharedRepr(ReprPrinter):
    """``sympy.srepr``'s printer, each sub-expression (the same object) printed once: a
    differentiated output shares its sub-expressions, which ``srepr`` prints (and sorts)
    again at every use."""

    def __init__(self):
        super().__init__()
        self._done: dict = {}    # id -> (the expression, its repr)

    def _print(self, expr, **kwargs) -> str:
        if kwargs or not isinstance(expr, sp.Basic):
            return super()._print(expr, **kwargs)
        hit = self._done.get(id(expr))
        if hit is not None and hit[0] is expr:
            return hit[1]
        got = super()._print(expr)
        self._done[id(expr)] = (expr, got)
        return got


def math_hash(parts) -> str:
    """SHA-256 (first 16 hex digits) of the ``srepr`` of the derived mathematics."""
    h = hashlib.sha256()
    printer = _SharedRepr()
    for p in parts:
        h.update(printer.doprint(p).encode())
        h.update(b"\0")
    return h.hexdigest()[:16]


def divides_or_roots(e) -> bool:
    """Whether ``e`` itself divides or takes a root (may be non-finite for finite inputs)."""
    return any(isinstance(p, sp.Pow) and not (p.exp.is_Integer and p.exp > 0)
               for p in sp.preorder_traversal(e))


#: the calls a trig split moves into the SIMD loop
_TRIG = (sp.sin, sp.cos)


def trig_split(kc: Any) -> dict | None:
    """Split a trig-calling kernel into a SIMD trig loop and a per-sample loop.

    For a kernel without branches whose ``sin``/``cos`` arguments do not themselves depend
    on a trig call, returns the prelude (the temporaries the arguments need, in order, and
    the ``sin``/``cos`` calls by parameter name ``trig_<k>``) and the per-sample program with
    each call replaced by its parameter; ``None`` when the kernel is not blocked.
    """
    if len(kc.variants) != 1:
        return None
    p = kc.variants[0].program
    exprs = [v for _, v in p.temps] + list(p.outputs) + list(p.dens)
    calls: list = []
    for e in exprs:
        for node in sp.preorder_traversal(sp.sympify(e)):
            if isinstance(node, _TRIG) and node not in calls:
                calls.append(node)
    if not calls:
        return None
    defs = dict(p.temps)
    need: set = set()
    todo = [s for c in calls for s in c.args[0].free_symbols]
    while todo:
        s = todo.pop()
        if s in defs and s not in need:
            need.add(s)
            todo.extend(defs[s].free_symbols)
    pre = [(s, v) for s, v in p.temps if s in need]
    if any(v.has(*_TRIG) for _, v in pre):
        return None
    names = {c: sp.Symbol(f"trig_{k}") for k, c in enumerate(calls)}
    temps = [(s, v.xreplace(names)) for s, v in p.temps]
    outputs = [sp.sympify(v).xreplace(names) for v in p.outputs]
    dens = [sp.sympify(v).xreplace(names) for v in p.dens]
    # drop the temporaries that only fed the trig arguments (keep divisions and roots: the
    # finiteness check stays the same)
    live = set().union(*(sp.sympify(v).free_symbols for v in outputs + dens))
    kept = []
    for s, v in reversed(temps):
        if s in live or divides_or_roots(v):
            kept.append((s, v))
            live |= v.free_symbols
    kept.reverse()
    return {"calls": {str(names[c]): c for c in calls}, "pre": pre,
            "program": Program(kept, outputs, dens, p.ops)}
