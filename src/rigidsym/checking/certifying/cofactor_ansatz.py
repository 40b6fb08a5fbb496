"""Cofactors by a linear ansatz, as Lean's ``linear_combination`` is used: find
polynomials ``mu_i`` with ``f = sum mu_i h_i`` whose monomials are those that bring a term of
``h_i`` onto a term of ``f`` (and, ``rounds`` times, onto a term of what they produce), by
exact linear algebra over Q (sparse, sympy's ``DomainMatrix``). No multiplier: the cofactors
stay as small as the identity's own proof, where pseudo-division's initials blow them up (a
rotation along a motion). ``None`` when the ansatz has no solution or is past its size.
"""

from __future__ import annotations

import flint
import numpy as np
from sympy import QQ
from sympy.polys.matrices import DomainMatrix

__all__ = ["linear_combination", "hypothesis_polys"]


def _qq(c):
    q = flint.fmpq(c)
    return QQ(int(q.p), int(q.q))


def _rows(terms) -> np.ndarray:
    """Exponent tuples as the rows of an integer array (sorted: a fixed order)."""
    return np.array(sorted(terms), dtype=np.int64)


def _candidates(f_terms: set, hyps: list, rounds: int, limit: int) -> list[set] | None:
    """Per hypothesis, the monomials its cofactor may use: each quotient ``t / s`` of a
    target term ``t`` by a term ``s`` of the hypothesis that divides it, and the terms such a
    quotient brings, within ``f``'s degree in each variable, the next round's targets (the
    divisibility of every pair tested at once, in NumPy). ``None`` past ``limit``."""
    cand: list[set] = [set() for _ in hyps]
    hs = [_rows(h) for h in hyps]
    targets, seen = set(f_terms), set()
    box = _rows(f_terms).max(axis=0)  # f's degree in each variable
    total = 0
    for _ in range(rounds):
        new: set = set()
        todo = targets - seen
        t = _rows(todo) if todo else None
        for i, h in enumerate(hs):
            if t is None or not len(h):
                continue
            ti, si = np.nonzero((h[None, :, :] <= t[:, None, :]).all(axis=2))
            fresh = set(map(tuple, (t[ti] - h[si]).tolist())) - cand[i]
            total += len(fresh)
            if total > limit:
                return None
            if fresh:
                cand[i] |= fresh
                v = (_rows(fresh)[:, None, :] + h[None, :, :]).reshape(-1, h.shape[1])
                new |= set(map(tuple, v[(v <= box).all(axis=1)].tolist()))
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
