"""Entries with square roots (a norm ``‖x‖ = √(xᵀx)``) decided exactly without evaluating
a root (``‖R x‖ = ‖x‖``, the slip ``‖R x‖ = ‖x‖²``).

At a random rational point a norm is irrational, so the exact probes of
:func:`rigidsym.zero.decide.decide_zero` cannot evaluate it. Here the roots of an entry are
``Y_j = √A_j`` (roots of radicands that agree identically, ``A ≡ B`` decided by the zero
test under the constraints, are one root; ``A^(k/2) = A^((k-1)/2) Y``), and the entry, a
polynomial in the ``Y_j`` with root-free coefficients, reduces by ``Y_j² = A_j`` to
``Σ_S c_S ∏_{j∈S} Y_j``. Then, exactly and with no sign guessed:

- every ``c_S ≡ 0``: the entry vanishes identically;
- the product of the entry over every choice of signs of its roots (its norm, root-free:
  ``c₀² − c₁² A`` for one root) non-zero at an exact rational point: the entry is non-zero
  there, since it is one factor of that product (for ``A < 0`` too), so that point is an
  exact counterexample;
- the norm identically zero while some ``c_S`` is not: only a sign is left, which this does
  not decide (undecided, saying so).

More than :data:`MAX_RADICANDS` different radicands, nested roots, a root in a denominator
or inside a function stay undecided, with the reason.
"""

from __future__ import annotations

from itertools import product

import sympy as sp

#: the most different radicands in one entry (the norm multiplies 2^k conjugates)
MAX_RADICANDS = 3

__all__ = ["has_roots", "decide_roots"]


def _is_root(x) -> bool:
    return isinstance(x, sp.Pow) and x.exp.is_Rational and x.exp.q == 2


def has_roots(e) -> bool:
    """Whether ``e`` holds a square root (a power with a half-odd exponent)."""
    return any(_is_root(x) for x in sp.preorder_traversal(e))


def _joined(e):
    """``e`` with each product of square roots of radicands sympy knows non-negative (sums
    of squares of real symbols: norms) written as one root, ``√B √C = √(B C)`` (exact for
    ``B, C ≥ 0``): Kok-Hol-Schön's ``‖p ⊙ q‖ = ‖p‖ ‖q‖`` is then ``√A = √(B C)``, two roots
    whose radicands agree, instead of a relation whose sign is left undecided."""
    def one(m):
        roots = [f for f in m.args if isinstance(f, sp.Pow) and f.exp == sp.S.Half
                 and f.base.is_nonnegative]
        if len(roots) < 2:
            return m
        rest = [f for f in m.args if f not in roots]
        return sp.Mul(*rest) * sp.Pow(sp.expand(sp.Mul(*[r.base for r in roots])), sp.S.Half)
    return e.replace(lambda y: isinstance(y, sp.Mul), one)


def _split(e, decide, merged: list) -> tuple | str:
    """``(coeffs, radicands)``: ``e = Σ_S c_S ∏_{j∈S} √A_j`` (``coeffs``: subset S of
    radicand indices -> root-free c_S), or the reason it cannot be split; the decisions
    that radicands agree go to ``merged`` (a verdict rests on them too)."""
    e = _joined(e)
    roots = sorted({x for x in sp.preorder_traversal(e) if _is_root(x)}, key=sp.default_sort_key)
    bases: list = []
    for r in roots:
        if has_roots(r.base):
            return "a nested square root"
        if r.base not in bases:
            bases.append(r.base)
    reps: list = []  # radicands that agree identically are one root
    of: dict = {}
    for a in bases:
        for j, rep in enumerate(reps):
            same = decide([a - rep])
            if same.zero is True:
                merged.append(same)
                of[a] = j
                break
        else:
            of[a] = len(reps)
            reps.append(a)
    if len(reps) > MAX_RADICANDS:
        return f"square roots of more than {MAX_RADICANDS} different expressions"
    ys = [sp.Dummy(f"Y{j}") for j in range(len(reps))]
    e = e.xreplace({r: r.base ** ((r.exp.p - 1) // 2) * ys[of[r.base]] for r in roots})
    coeffs: dict = {}
    for t in sp.Add.make_args(e):
        coeff, dep = t.as_independent(*ys, as_Add=False)
        if coeff == 0:
            continue
        subset, extra = set(), sp.S.One
        for f in sp.Mul.make_args(dep) if dep != 1 else ():
            b, n = f.as_base_exp()
            if b not in ys or not n.is_Integer or n <= 0:
                return "a square root inside a denominator or a function"
            j = ys.index(b)
            extra *= reps[j] ** (int(n) // 2)
            if n % 2:
                subset.add(j)
        key = frozenset(subset)
        coeffs[key] = coeffs.get(key, sp.S.Zero) + coeff * extra
    return coeffs, reps


def _norm(coeffs: dict, reps: list):
    """The product of ``e`` over every choice of signs of its roots: root-free, and zero
    wherever ``e`` is (the identity factor among them)."""
    acc = {frozenset(): sp.S.One}
    for signs in product((1, -1), repeat=len(reps)):
        conj = {S: c * sp.Mul(*[signs[j] for j in S]) for S, c in coeffs.items()}
        out: dict = {}
        for s1, a in acc.items():
            for s2, b in conj.items():
                k = s1 ^ s2
                out[k] = out.get(k, sp.S.Zero) + a * b * sp.Mul(*[reps[j] for j in s1 & s2])
        acc = out
    return acc.get(frozenset(), sp.S.Zero)  # the others cancel: the product is even in each root


def decide_roots(entries: list, decide, result):
    """Decide ``entries`` (some with square roots) through their squares.

    Args:
        entries: the non-zero sympy expressions of :func:`~rigidsym.zero.decide.decide_zero`.
        decide: ``exprs -> ZeroResult``, the zero test on root-free expressions under the
            entries' own plan (so a witness gives every parameter a value).
        result: ``ZeroResult``'s constructor.

    Returns:
        A ``ZeroResult``: zero, a counterexample (its point exact, its entry the index in
        ``entries``), or undecided with the reason.
    """
    plain = [i for i, e in enumerate(entries) if not has_roots(e)]
    parts, outs = [], []
    for i, e in enumerate(entries):
        if i in plain:
            continue
        s = _split(e, decide, outs)
        if isinstance(s, str):
            return result(None, "undecided", f"irrational root at the sample point ({s})")
        parts.append((i, s))
    if plain:
        r = decide([entries[i] for i in plain])
        if r.zero is False:
            return result(False, r.method, r.detail, r.witness, plain[r.entry], r.plan)
        outs.append(r)
    for i, (coeffs, reps) in parts:
        r = decide(list(coeffs.values()))
        if r.zero is False:
            sq = decide([_norm(coeffs, reps)])
            if sq.zero is False:
                return result(False, "counterexample", "its product over the signs of its "
                              "square roots (root-free) is non-zero at an exact rational point",
                              sq.witness, i, sq.plan)
            why = "its product over the signs of its roots vanishes; the sign is not decided" \
                if sq.zero else sq.detail
            return result(None, "undecided", f"a square root: {why}")
        outs.append(r)
    bad = [r for r in outs if r.zero is None]
    if bad:
        return bad[0]
    method = "random-exact" if any(r.method == "random-exact" for r in outs) \
        else "exact-cancel"
    details = "; ".join(sorted({r.detail for r in outs if r.method == method
                                and "structurally" not in r.detail})) or outs[0].detail
    return result(True, method, f"{details} (each square root √A of one radicand, "
                  f"radicands that agree identically one root)", plan=outs[0].plan)
