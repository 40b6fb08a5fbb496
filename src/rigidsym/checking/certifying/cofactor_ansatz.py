"""Cofactors by a linear ansatz, as Lean's ``linear_combination`` is used: find
polynomials ``mu_i`` with ``f = sum mu_i h_i`` whose monomials are those that bring a term of
``h_i`` onto a term of ``f`` (and, ``rounds`` times, onto a term of what they produce), by
exact linear algebra over Q (sparse, sympy's ``DomainMatrix``). No multiplier: the cofactors
stay as small as the identity's own proof, where pseudo-division's initials blow them up (a
rotation along a motion). ``None`` when the ansatz has no solution or is past its size.
"""

from __future__ import annotations

import flint
from sympy import QQ
from sympy.polys.matrices import DomainMatrix

__all__ = ["linear_combination", "hypothesis_polys"]


def _qq(c):
    q = flint.fmpq(c)
    return QQ(int(q.p), int(q.q))


def _divides(s: tuple, t: tuple) -> bool:
    return all(a <= b for a, b in zip(s, t, strict=True))


def _candidates(f_terms: set, hyps: list, rounds: int, limit: int) -> list[set] | None:
    """Per hypothesis, the monomials its cofactor may use."""
    cand = [set() for _ in hyps]
    targets, seen = set(f_terms), set()
    box = tuple(max(e) for e in zip(*f_terms, strict=True))  # f's degree in each variable
    total = 0
    for _ in range(rounds):
        new = set()
        for t in targets - seen:
            for i, h in enumerate(hyps):
                for s in h:
                    if _divides(s, t):
                        m = tuple(b - a for a, b in zip(s, t, strict=True))
                        if m not in cand[i]:
                            cand[i].add(m)
                            total += 1
                            if total > limit:
                                return None
                            for u in h:
                                v = tuple(x + y for x, y in zip(m, u, strict=True))
                                if all(a <= b for a, b in zip(v, box, strict=True)):
                                    new.add(v)
        seen |= targets
        targets = new | targets
    return cand


def linear_combination(f, hyps: list, rounds: int = 2, limit: int = 1500):
    """``[mu_i]`` (``fmpq_mpoly``) with ``f = sum mu_i hyps[i]``, or ``None``.

    Args:
        f: the polynomial to write (an ``fmpq_mpoly``).
        hyps: the hypotheses (same context).
        rounds: how many times the candidate monomials are closed under the terms they
            produce.
        limit: the most unknowns (candidate monomials over all cofactors).
    """
    ctx = f.context()
    if f.is_zero():
        return [ctx.from_dict({}) for _ in hyps]
    fd = f.to_dict()
    hd = [h.to_dict() for h in hyps]
    cand = _candidates(set(fd), hd, rounds, limit)
    if cand is None:
        return None
    unknowns = [(i, m) for i, c in enumerate(cand) for m in sorted(c)]
    if not unknowns:
        return None
    rows: dict = {}
    for col, (i, m) in enumerate(unknowns):
        for s, c in hd[i].items():
            key = tuple(a + b for a, b in zip(m, s, strict=True))
            rows.setdefault(key, {})[col] = c
    if any(t not in rows for t in fd):
        return None
    keys = sorted(rows)
    n = len(unknowns)
    # the system is sparse (thousands of equations, a few unknowns each): sympy's sparse
    # reduced row echelon form over Q, the same unique form a dense elimination gives (one of
    # 4806 x 2611 in 0.04 s instead of 10 s), free unknowns 0
    A = DomainMatrix({r: {**{col: _qq(c) for col, c in rows[key].items()},
                          **({n: _qq(fd[key])} if key in fd else {})}
                      for r, key in enumerate(keys)}, (len(keys), n + 1), QQ)
    R, pivots = A.rref()
    if pivots and pivots[-1] == n:
        return None  # inconsistent: no such combination
    R = R.to_sdm()
    sol = [flint.fmpq(0)] * n
    for r, col in enumerate(pivots):
        v = R.get(r, {}).get(n, QQ.zero)
        sol[col] = flint.fmpq(int(QQ.numer(v)), int(QQ.denom(v)))
    mus = [ctx.from_dict({}) for _ in hyps]
    for (i, m), v in zip(unknowns, sol, strict=True):
        if v != 0:
            mus[i] = mus[i] + ctx.from_dict({m: v})
    return mus


def hypothesis_polys(R, atoms: list, keys: list, M: dict, d, rotation_hyps) -> list:
    """The checker's hypotheses named by ``keys`` (``(group, k)`` of a unit vector,
    ``(group, h, k)`` of a rotation or transform, ``("angle", a)``) as polynomials of the
    ring ``R`` (``d`` its time derivative, ``rotation_hyps``
    :func:`.rotation_triangular_set.hypotheses`)."""
    groups = {g["group"]: g for g in atoms}
    out = []
    for key in keys:
        if key[0] == "angle" and len(key) == 2 and key[0] not in groups:
            C, S = (R.var(f"{f}({key[1]}/{M[key[1]]})") for f in ("cos", "sin"))
            out.append(C**2 + S**2 - R.one)
            continue
        g = groups[key[0]]
        if len(key) == 2:
            h = sum((R.var(n) ** 2 for n in g["names"]), -R.one)
        else:
            h = rotation_hyps(R, g["names"], g["kind"] == "transform")[key[1]]
        for _ in range(key[-1]):
            h = d(h)
        out.append(h)
    return out
