"""Straight-line programs: a sympy expression tree translated once, then run many times.

The zero test (:mod:`rigidsym.zero`) and its numeric backing walk the same trees again and
again: at a dozen rational points, once more as a rational function, at ten ball-arithmetic
points. Walking a sympy tree costs a dictionary look-up and an ``isinstance`` cascade per
node per run; a program pays that once. It is a list of operations on numbered slots, each
shared subexpression computed once (hash-consed on the sympy node and on the operation).

Two translations:

- :func:`parametrised` (exact): atoms are replaced by the plan's rational parametrisation
  (:mod:`rigidsym.zero.plan`) and trigonometric functions of angles by rational functions of
  ``tau = tan(angle / 2M)``, so the program computes a rational function over Q of
  ``plan.params``. Runs over ``fmpq`` (:func:`run_exact`, a rational point) or over
  ``fmpq_mpoly`` fractions (:func:`run_rational`, the rational function itself, python-flint).
- :func:`unparametrised` (numeric): atoms stay leaves, functions are applied as such; runs
  over ``arb`` balls (:mod:`rigidsym.checking.deciding.balls`).

Operations (tuples, the first item the code): ``(CONST, q)``, ``(LEAF, k)``,
``(ADD, i, j, ...)``, ``(MUL, i, j, ...)``, ``(POW, i, n)`` (integer n), ``(ROOT, i, p, q)``
(``x^(p/q)``, evaluation only), ``(ABS, i)``, ``(FUNC, name, i, ...)`` (unparametrised
only), ``(PI,)`` (unparametrised only).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import flint
import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.zero.plan import TRIG, Plan, Unsupported, linear_angles
from rigidsym.zero.signs import definite_abs, definite_sqrt

__all__ = ["Program", "TooLarge", "parametrised", "unparametrised", "run_exact", "run_rational",
           "CONST", "LEAF", "ADD", "MUL", "POW", "ROOT", "ABS", "FUNC", "PI"]

CONST, LEAF, ADD, MUL, POW, ROOT, ABS, FUNC, PI = range(9)

#: functions the unparametrised translation applies as such (their ``arb`` names)
_FUNCS = {sp.cos: "cos", sp.sin: "sin", sp.tan: "tan", sp.cot: "cot", sp.sec: "sec",
          sp.csc: "csc", sp.exp: "exp", sp.log: "log", sp.atan: "atan", sp.asin: "asin",
          sp.acos: "acos", sp.atan2: "atan2", sp.sinh: "sinh", sp.cosh: "cosh",
          sp.tanh: "tanh"}


class TooLarge(Exception):
    """A rational-function run went past its work budget (terms of a polynomial, or pairs of
    terms of a product)."""


@dataclass
class Program:
    """A translated family of expressions.

    Attributes:
        ops: the operations, in an order where every operand precedes its use.
        outputs: the slot of each translated expression, in the order given.
        leaves: what each ``LEAF`` stands for: the plan's parameter symbols (parametrised)
            or the atoms (unparametrised: ``Symbol``, ``f(t)``, ``Derivative``).
    """

    ops: list
    outputs: list
    leaves: list


class _Builder:
    """Emits operations, hash-consed on the sympy node and on the operation itself."""

    def __init__(self):
        self.ops: list = []
        self.by_op: dict = {}
        self.by_node: dict = {}
        self.leaves: list = []
        self.leaf_slot: dict = {}

    def emit(self, op: tuple) -> int:
        slot = self.by_op.get(op)
        if slot is None:
            slot = self.by_op[op] = len(self.ops)
            self.ops.append(op)
        return slot

    def memo(self, x, make) -> int:
        """The slot of sympy node ``x``, emitted by ``make(x)`` the first time only."""
        slot = self.by_node.get(x)
        if slot is None:
            slot = self.by_node[x] = make(x)
        return slot

    def const(self, q) -> int:
        return self.emit((CONST, Fraction(q)))

    def leaf(self, x) -> int:
        slot = self.leaf_slot.get(x)
        if slot is None:
            self.leaf_slot[x] = slot = self.emit((LEAF, len(self.leaves)))
            self.leaves.append(x)
        return slot

    def add(self, *slots) -> int:
        return self.emit((ADD, *slots)) if len(slots) > 1 else slots[0]

    def mul(self, *slots) -> int:
        return self.emit((MUL, *slots)) if len(slots) > 1 else slots[0]

    def neg(self, a: int) -> int:
        return self.mul(self.const(-1), a)

    def div(self, a: int, b: int) -> int:
        return self.mul(a, self.emit((POW, b, -1)))


# --------------------------------------------------------------------------- exact
def _cis(b: _Builder, tau: int, k: int) -> tuple[int, int]:
    """Slots of (cos(2k atan tau), sin(2k atan tau)): ((1 + i tau)^2 / (1 + tau^2))^k, as
    :mod:`rigidsym.zero.exact` computes them."""
    one = b.const(1)
    t2 = b.mul(tau, tau)
    d = b.add(one, t2)
    c = b.div(b.add(one, b.neg(t2)), d)
    s = b.div(b.mul(b.const(2), tau), d)
    base_re, base_im = (c, s) if k >= 0 else (c, b.neg(s))
    re, im = one, b.const(0)
    for _ in range(abs(k)):
        re, im = (b.add(b.mul(re, base_re), b.neg(b.mul(im, base_im))),
                  b.add(b.mul(re, base_im), b.mul(im, base_re)))
    return re, im


def _trig(b: _Builder, x, plan: Plan, param) -> int:
    coeffs, cpi = linear_angles(x.args[0])
    re, im = b.const(1), b.const(0)
    for a, c in coeffs.items():
        tau, M = plan.angles[a]
        cr, ci = _cis(b, param(tau), int(c * M))
        re, im = (b.add(b.mul(re, cr), b.neg(b.mul(im, ci))),
                  b.add(b.mul(re, ci), b.mul(im, cr)))
    for _ in range(int(2 * cpi) % 4):  # rotation by cpi * pi, cpi a multiple of 1/2
        re, im = b.neg(im), re
    f = x.func
    if f is sp.cos:
        return re
    if f is sp.sin:
        return im
    num, den = {sp.tan: (im, re), sp.cot: (re, im), sp.sec: (b.const(1), re),
                sp.csc: (b.const(1), im)}[f]
    return b.div(num, den)


_ARITH = (sp.Add, sp.Mul, sp.Pow, sp.Abs)


def _arith(b, x, node) -> int:
    """The step of a sum, product, power or absolute value, the nodes both translations
    share (``node`` translates an argument).

    Raises:
        Unsupported: a power whose exponent is not rational.
    """
    if isinstance(x, sp.Add):
        return b.add(*[node(a) for a in x.args])
    if isinstance(x, sp.Mul):
        return b.mul(*[node(a) for a in x.args])
    if isinstance(x, sp.Abs):
        return b.emit((ABS, node(x.args[0])))
    base, n = x.args
    if n.is_Integer:
        return b.emit((POW, node(base), int(n)))
    if n.is_Rational:
        return b.emit((ROOT, node(base), int(n.p), int(n.q)))
    raise Unsupported(f"power {x}")


def parametrised(exprs, plan: Plan) -> Program:
    """Translate ``exprs`` under ``plan`` (atoms by their rational parametrisation).

    Leaves are ``plan.params`` (in that order), so a point is a list of values in the
    order of ``plan.params``.

    Raises:
        Unsupported: for an atom without a rule or a node the exact evaluator cannot treat
            (the same cases as :func:`rigidsym.zero.exact.evaluate`).
    """
    b = _Builder()
    for p in plan.params:
        b.leaf(p)
    params = set(plan.params)

    def param(s) -> int:
        return b.leaf_slot[s]

    def node(x) -> int:
        return b.memo(x, _node)

    def _node(x) -> int:
        if x.is_Rational:
            return b.const(Fraction(int(x.p), int(x.q)))
        if x in params:
            return param(x)
        if x == sp.pi or isinstance(x, sp.Symbol | AppliedUndef | sp.Derivative):
            rule = plan.rules.get(x)
            if rule is None or rule == x:
                raise Unsupported(f"no value for atom {x}")
            return node(rule)
        if isinstance(x, _ARITH):
            return _arith(b, x, node)
        if isinstance(x, TRIG):
            return _trig(b, x, plan, param)
        raise Unsupported(f"an operator the exact evaluator does not take "
                          f"({type(x).__name__.lower()})")

    outputs = [node(sp.sympify(e)) for e in exprs]
    return Program(b.ops, outputs, b.leaves)


def unparametrised(exprs) -> Program:
    """Translate ``exprs`` as they stand: atoms (``Symbol``, ``f(t)``, ``Derivative``) are
    leaves, in order of first appearance, and functions are applied as such.

    Raises:
        Unsupported: for a node with no numeric meaning here (an unknown function, a float
            exponent, ...).
    """
    b = _Builder()

    def node(x) -> int:
        return b.memo(x, _node)

    def _node(x) -> int:
        if x.is_Rational:
            return b.const(Fraction(int(x.p), int(x.q)))
        if x == sp.pi:
            return b.emit((PI,))
        if isinstance(x, sp.Symbol | AppliedUndef | sp.Derivative):
            return b.leaf(x)
        if isinstance(x, _ARITH):
            return _arith(b, x, node)
        name = _FUNCS.get(x.func)
        if name is not None:
            return b.emit((FUNC, name, *[node(a) for a in x.args]))
        raise Unsupported(f"an operator the exact evaluator does not take "
                          f"({type(x).__name__.lower()})")

    outputs = [node(sp.sympify(e)) for e in exprs]
    return Program(b.ops, outputs, b.leaves)


# --------------------------------------------------------------------------- runs
def run_exact(prog: Program, point: list) -> list:
    """Values of the outputs at a rational point (``fmpq`` values of the leaves).

    Raises:
        ZeroDivisionError: where a denominator vanishes at the point.
        Unsupported: an irrational root at the point.
    """
    vals: list = [None] * len(prog.ops)
    for i, op in enumerate(prog.ops):
        code = op[0]
        if code == MUL:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = acc * vals[j]
        elif code == ADD:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = acc + vals[j]
        elif code == POW:
            acc = vals[op[1]] ** op[2]  # fmpq raises ZeroDivisionError on 0 ** -n
        elif code == CONST:
            acc = flint.fmpq(op[1].numerator, op[1].denominator)
        elif code == LEAF:
            acc = point[op[1]]
        elif code == ABS:
            acc = abs(vals[op[1]])
        elif code == ROOT:
            acc = _root(vals[op[1]], op[2], op[3])
        else:  # pragma: no cover  (FUNC, PI: unparametrised programs only)
            raise Unsupported(f"operation {op[0]} in an exact run")
        vals[i] = acc
    return [vals[k] for k in prog.outputs]


def _root(v, p: int, q: int):
    """``v^(p/q)`` when it is rational (as :func:`rigidsym.zero.exact.rational_root`)."""
    from rigidsym.zero.exact import rational_root

    r = rational_root(Fraction(int(v.p), int(v.q)), p, q)
    return flint.fmpq(r.numerator, r.denominator)


def run_rational(prog: Program, ctx, terms_limit: int = 10**9,
                 product_limit: int = 10**18) -> list:
    """The outputs as fractions ``(numerator, denominator)`` of ``fmpq_mpoly`` in ``ctx``
    (whose generators are the leaves), each kept free of the common factors that a gcd of
    the denominators finds (FLINT's multivariate gcd).

    A numerator is the zero polynomial exactly when its expression vanishes identically
    (the denominator is never the zero polynomial: that raises ``Unsupported``).

    Args:
        prog: a :func:`parametrised` program.
        ctx: a ``fmpq_mpoly_ctx`` with one generator per leaf.
        terms_limit: the most terms an intermediate numerator or denominator may have.
        product_limit: the most pairs of terms a product may multiply.

    Raises:
        Unsupported: ``ABS``/``ROOT`` of what is no rational function of constant sign
            (:mod:`rigidsym.zero.signs`) or the inverse of an identically zero subexpression.
        TooLarge: past ``terms_limit`` or ``product_limit``.
    """
    gens = ctx.gens()
    one = ctx.from_dict({(0,) * len(gens): 1})
    budget = (terms_limit, product_limit)
    vals: list = [None] * len(prog.ops)
    for i, op in enumerate(prog.ops):
        code = op[0]
        if code == MUL:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = _mul(acc, vals[j], budget)
        elif code == ADD:
            acc = vals[op[1]]
            for j in op[2:]:
                acc = _add(acc, vals[j], budget)
        elif code == POW:
            acc = _pow(vals[op[1]], op[2], budget)
        elif code == CONST:
            acc = (one * flint.fmpq(op[1].numerator, op[1].denominator), one)
        elif code == LEAF:
            acc = (gens[op[1]], one)
        elif code == ABS:  # where the signs are known everywhere (rigidsym.zero.signs)
            acc = definite_abs(vals[op[1]])
        elif code == ROOT:
            acc = _pow(definite_sqrt(vals[op[1]], op[3]), op[2], budget)
        else:  # pragma: no cover  (FUNC, PI: unparametrised programs only)
            raise Unsupported(f"operation {op[0]} in a rational run")
        vals[i] = acc
    return [vals[k] for k in prog.outputs]


def _check(budget, *sizes: int) -> None:
    if max(sizes) > budget[0]:
        raise TooLarge(f"a polynomial of {max(sizes)} terms")


def _product(budget, a, b):
    if len(a) * len(b) > budget[1]:
        raise TooLarge(f"a product of {len(a)} by {len(b)} terms")
    return a * b


def _pow(x, k: int, budget):
    n, d = x
    if k < 0:
        if n.is_zero():
            raise Unsupported("inverse of an identically zero subexpression")
        n, d, k = d, n, -k
        lc = d.leading_coefficient()  # denominators monic: equal ones compare equal
        if lc != 1:
            n, d = n / lc, d / lc
    # (len)^k bounds the terms of the power: checked before FLINT expands it
    if max(len(n), len(d)) > 1 and max(len(n), len(d)) ** min(k, 64) > budget[1]:
        raise TooLarge(f"a power {k} of {max(len(n), len(d))} terms")
    out = (n**k, d**k)
    _check(budget, len(out[0]), len(out[1]))
    return out


def _add(a, b, budget):
    (n1, d1), (n2, d2) = a, b
    if d1 == d2:
        out = (n1 + n2, d1)
    elif d1.is_one():
        out = (_product(budget, n1, d2) + n2, d2)
    elif d2.is_one():
        out = (n1 + _product(budget, n2, d1), d1)
    else:
        g = d1.gcd(d2)
        e1, e2 = (d1, d2) if g.is_one() else (d1 / g, d2 / g)
        out = (_product(budget, n1, e2) + _product(budget, n2, e1), _product(budget, d1, e2))
    _check(budget, len(out[0]), len(out[1]))
    return out


def _mul(a, b, budget):
    (n1, d1), (n2, d2) = a, b
    if not d2.is_one() and not n1.is_constant():
        g = n1.gcd(d2)
        if not g.is_one():
            n1, d2 = n1 / g, d2 / g
    if not d1.is_one() and not n2.is_constant():
        g = n2.gcd(d1)
        if not g.is_one():
            n2, d1 = n2 / g, d1 / g
    out = (_product(budget, n1, n2), _product(budget, d1, d2))
    _check(budget, len(out[0]), len(out[1]))
    return out
