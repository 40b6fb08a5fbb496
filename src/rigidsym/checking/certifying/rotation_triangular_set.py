"""The triangular set of a rotation (and of a transform's rotation block) for cofactor
certificates (:mod:`rigidsym.checking.certifying.cofactors`).

The checker's hypotheses of a rotation ``Q`` with columns ``c1, c2, c3`` are
``H_ij = c_i . c_j - [i = j]`` (``i <= j``) and ``det Q - 1``; they are not triangular in
the entries. The identity ``Q - C(Q) = -(det Q - 1) Q + C(Q) (Q^T Q - 1)`` (``C`` the
cofactor matrix, whose third column is ``c1 x c2``; it follows from ``C(Q) Q^T = det Q``)
gives the first three members of a triangular set, each with its cofactors over the
hypotheses; the other three are hypotheses or their combination:

- ``q_r3 - (c1 x c2)_r`` (r = 1, 2, 3), linear and monic in ``q_r3``;
- ``H_12 = c1 . c2``, linear in ``q_32`` with initial ``q_31``;
- ``H_11``, monic quadratic in ``q_31``;
- ``(1 - q_11^2 - q_21^2)(q_12^2 + q_22^2 - 1) + (q_11 q_12 + q_21 q_22)^2
  = q_31^2 H_22 + H_12 (H_12 - 2 q_31 q_32) - H_11 (q_12^2 + q_22^2 - 1)``, quadratic in
  ``q_22`` with initial ``1 - q_11^2``.

Its quasi-variety is the part of SO(3) where ``q_31 (1 - q_11^2) != 0``, irreducible, so
every polynomial that vanishes on SO(3) pseudo-reduces to zero (Ritt-Wu). Along a motion the
k-th time derivative of each member is linear in the k-th jet of its main variable, with the
member's separant as coefficient; the highest jets are reduced first. Only python-flint.
"""

from __future__ import annotations

from math import comb

__all__ = ["ChainRemainder", "rotation_chain", "transform_chain", "pseudo_reduce",
           "hypotheses"]


class ChainRemainder(ArithmeticError):
    """A pseudo-division by a member of the chain was not exact (a bug guard), or the
    reduction went past its size or time budget (the message says which)."""



#: the index of the orthogonality hypothesis (Q^T Q - 1)_{jk}, j <= k, in the checker's order
_HIX = {(0, 0): 0, (0, 1): 1, (0, 2): 2, (1, 1): 3, (1, 2): 4, (2, 2): 5}


def _cofactor_columns(q):
    """The columns of the cofactor matrix C(Q) of the 3 x 3 ``q`` (rows of ring elements):
    column k is the cross product of the other two columns of Q, in cyclic order."""
    col = [[q[r][c] for r in range(3)] for c in range(3)]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0]]
    return [cross(col[1], col[2]), cross(col[2], col[0]), cross(col[0], col[1])]

def _by_powers(p, i: int) -> dict:
    """``p`` as ``{k: coefficient of x_i^k}`` (the nonzero ones): the k-th derivative in
    ``x_i`` at ``x_i = 0`` over k!, in python-flint's own loops (the terms' Python dict of
    a polynomial of thousands of terms was the chain's costliest step)."""
    out: dict = {}
    fact = 1
    for k in range(_degree(p, i) + 1):
        a = p.subs({i: 0})
        if not a.is_zero():
            out[k] = a / fact if fact > 1 else a
        p = p.derivative(i)
        fact *= k + 1
    return out


def _member(R, T, main: str, cof: dict) -> dict:
    """A member of the chain: ``T`` (a ring polynomial) with main variable ``main`` and
    ``T = sum cof[h] * h`` over hypothesis keys ``(hypothesis index, 0)``."""
    return {"T": T, "main": R.index[main], "cof": cof}


def _rotation_members(R, names: list[str], H: list) -> list:
    """The level-0 chain of a rotation whose entries (row-major) are ``names``; ``H`` the
    ring polynomials of its 7 hypotheses (checker's order), elimination order first."""
    q = [[R.var(names[3 * r + c]) for c in range(3)] for r in range(3)]
    C, hix = _cofactor_columns(q), _HIX
    out = []
    for r in range(3):  # q_r3 - C_r3 = -(det - 1) q_r3 + sum_k C_rk H_k3
        cof: dict = {6: -q[r][2]}
        for k in range(3):
            cof[hix[(k, 2)]] = cof.get(hix[(k, 2)], R.zero) + C[k][r]
        out.append(_member(R, q[r][2] - C[2][r], names[3 * r + 2], cof))
    q11, q21, q31, q12, q22, q32 = q[0][0], q[1][0], q[2][0], q[0][1], q[1][1], q[2][1]
    out.append(_member(R, H[1], names[7], {1: R.one}))
    out.append(_member(R, H[0], names[6], {0: R.one}))
    b = q12**2 + q22**2 - R.one
    T = (R.one - q11**2 - q21**2) * b + (q11 * q12 + q21 * q22) ** 2
    out.append(_member(R, T, names[4], {3: q31**2, 1: H[1] - 2 * q31 * q32, 0: -b}))
    for m in out:  # the stated cofactors are the member (a cheap guard on this table)
        if m["T"] != sum((c * H[h] for h, c in m["cof"].items()), R.zero):
            raise AssertionError("rotation chain: a member's cofactors do not give it")
    return out


def rotation_chain(R, names: list[str], H: list) -> list:
    """The level-0 members of a rotation's triangular set (see the module's text)."""
    return _rotation_members(R, names, H)


def transform_chain(R, names: list[str], H: list) -> list:
    """A transform's (16 entries, row-major; 11 hypotheses: 7 of its rotation block, then
    ``X_41, X_42, X_43, X_44 - 1``): the last row, then the rotation block's chain."""
    last = [_member(R, H[7 + i], names[12 + i], {7 + i: R.one}) for i in range(4)]
    block = [names[i] for i in (0, 1, 2, 4, 5, 6, 8, 9, 10)]
    return last + _rotation_members(R, block, H)


def _jet(R, name: str, k: int) -> int:
    return R.index[name + "'" * k]


def _derivatives(p, K: int, d) -> list:
    out = [p]
    for _ in range(K):
        out.append(d(out[-1]))
    return out


def pseudo_reduce(N, R, members: list, names: list[str], K: int, d, mus: dict, mult,
                  group: str, budget: tuple[int, float] = (20_000, float("inf"))):
    """Pseudo-reduce ``N`` by the chain ``members`` and its time derivatives up to ``K``
    (``d`` the total time derivative on the ring).

    The monic members' jets first, highest first (pure substitutions: no multiplier), then
    the others' jets, highest first, each followed by the monic quadratic member at level 0
    (keeping the degrees low), then level 0. Keeps ``mult * N0 = sum mus[key] *
    hypothesis(key) + N`` with keys ``(group, h, j)`` (the j-th time derivative of
    hypothesis ``h``); returns ``(N, mult)``. ``budget``: (the most terms of ``N`` or of a
    cofactor, a ``time.process_time()`` deadline), past which :class:`ChainRemainder` is
    raised.
    """
    for m in members:
        m["Ts"] = _derivatives(m["T"], K, d)
        m["cofs"] = {h: _derivatives(c, K, d) for h, c in m["cof"].items()}
        m["monic"] = m["Ts"][0].derivative(m["main"]).is_one()
    square = [m for m in members if _degree(m["T"], m["main"]) == 2 and
              _by_powers(m["T"], m["main"])[2].is_one()]
    steps = [(m, k) for k in range(K, -1, -1) for m in members if m["monic"]]
    for k in range(K, 0, -1):
        for m in members:
            if not m["monic"]:
                steps += [(m, k)] + [(s, 0) for s in square]
    steps += [(m, 0) for m in members if not m["monic"]]
    state = {"N": N, "mult": mult}
    for m, k in steps:
        _step(state, R, m, k, mus, group, budget)
    return state["N"], state["mult"]


def _step(state: dict, R, m: dict, k: int, mus: dict, group: str, budget: tuple) -> None:
    """One pseudo-division of ``state["N"]`` by the k-th derivative of member ``m``."""
    import time

    N, Tk = state["N"], m["Ts"][k]
    x = _jet(R, R.names[m["main"]], k)
    if len(N) > budget[0] or time.process_time() > budget[1]:
        raise ChainRemainder(f"past the budget ({budget[0]} terms, CPU time)")
    if k or _degree(m["T"], m["main"]) == 1:
        c = Tk.derivative(x)
        e, r = prem_linear(N, x, c, Tk - c * R.gens[x])
    else:
        c, e, r = _prem(N, Tk, x, budget)
    if e == 0:
        return
    f = c**e
    q, rest = divmod(f * N - r, Tk)
    if not rest.is_zero():
        raise ChainRemainder("a pseudo-division by a rotation's member left a remainder")
    if not f.is_one():
        for key in mus:
            mus[key] = mus[key] * f
        state["mult"] = state["mult"] * f
    for h, cs in m["cofs"].items():  # T^(k) = sum_h sum_j C(k, j) c_h^(k-j) h^(j)
        for j in range(k + 1):
            key = (group, h, j)
            mus[key] = mus.get(key, R.zero) + q * comb(k, j) * cs[k - j]
            if len(mus[key]) > budget[0]:
                raise ChainRemainder(f"a cofactor of more than {budget[0]} terms")
    state["N"] = r


def prem_linear(N, i: int, c, d):
    """``(m, r)`` with ``c^m N = q (c x_i + d) + r``, ``r`` free of ``x_i``."""
    parts = _by_powers(N, i)
    m = max(parts, default=0)
    out = N.context().from_dict({})
    for k, a in parts.items():
        out = out + a * (-d) ** k * c ** (m - k)
    return m, out


def hypotheses(R, names: list[str], transform: bool) -> list:
    """The checker's hypotheses (``certcheck.kinds.constraints``) of a rotation or transform
    whose entries (row-major) are ``names``, as ring polynomials."""
    X = [R.var(n) for n in names]
    M = [X[i] for i in (0, 1, 2, 4, 5, 6, 8, 9, 10)] if transform else X
    out = []
    for i in range(3):
        for j in range(i, 3):
            s = sum((M[3 * k + i] * M[3 * k + j] for k in range(3)), R.zero)
            out.append(s - R.one if i == j else s)
    det = R.zero
    for j in range(3):
        det = det + M[j] * (M[3 + (j + 1) % 3] * M[6 + (j + 2) % 3]
                            - M[3 + (j + 2) % 3] * M[6 + (j + 1) % 3])
    out.append(det - R.one)
    if transform:
        out += [X[12], X[13], X[14], X[15] - R.one]
    return out


def _degree(p, x: int) -> int:
    return p.degrees()[x] if not p.is_zero() else 0


def _prem(N, T, x: int, budget: tuple[int, float]):
    """``(lc, e, r)``: ``lc^e N = q T + r`` with ``deg_x r < deg_x T`` (``lc`` the leading
    coefficient of ``T`` in ``x``); :class:`ChainRemainder` past ``budget``."""
    import time

    dT = _degree(T, x)
    lc = _by_powers(T, x)[dT]
    xv = T.context().gens()[x]
    e, r = 0, N
    while not r.is_zero() and _degree(r, x) >= dT:
        dr = _degree(r, x)
        lr = _by_powers(r, x)[dr]
        r = lc * r - lr * xv ** (dr - dT) * T
        e += 1
        if len(r) > budget[0] or time.process_time() > budget[1]:
            raise ChainRemainder(f"past the budget ({budget[0]} terms, CPU time)")
    return lc, e, r


def cpow(z, n: int, R):
    """``z ** n`` for ``z = (C, S)`` (a negative ``n``: the conjugate's power)."""
    if n < 0:
        re_, im = cpow(z, -n, R)
        return (re_, -im)
    out = (R.one, R.zero)
    for _ in range(n):
        out = (out[0] * z[0] - out[1] * z[1], out[0] * z[1] + out[1] * z[0])
    return out


def dpoly(p, R, nxt: dict):
    out = R.zero
    for i, j in nxt.items():
        d = p.derivative(i)
        if not d.is_zero():
            out = out + d * R.gens[j]
    return out


def rem_square(N, i: int, s):
    """``N`` modulo ``x_i^2 - s`` (``s`` free of ``x_i``): a remainder of degree < 2 in ``x_i``."""
    parts = _by_powers(N, i)
    x = N.context().gens()[i]
    out = N.context().from_dict({})
    for k, a in parts.items():
        out = out + a * s ** (k // 2) * (x if k % 2 else 1)
    return out


def derived(R, names: list[str], transform: bool, K: int, d) -> list:
    """More members of a rotation's ideal with their cofactors written out, for the linear
    ansatz (:mod:`rigidsym.checking.certifying.cofactor_ansatz`): ``F = Q - C(Q) = -(det Q - 1) Q +
    C(Q) H`` and ``E = Q Q^T - 1 = F Q^T + (det Q - 1) 1`` (``H = Q^T Q - 1``; from ``C(Q) Q^T =
    det Q``), entry by entry, and their time derivatives up to ``K``: a list of ``(G,
    {(hypothesis index, j): coefficient})`` with ``G = sum coefficient * h^(j)``."""
    H = hypotheses(R, names, transform)
    X = [R.var(n) for n in names]
    M = [X[i] for i in (0, 1, 2, 4, 5, 6, 8, 9, 10)] if transform else X
    q = [[M[3 * r + c] for c in range(3)] for r in range(3)]
    C, hix = _cofactor_columns(q), _HIX
    F = [[{6: -q[r][c]} for c in range(3)] for r in range(3)]
    for r in range(3):
        for c in range(3):
            for k in range(3):
                key = hix[(min(k, c), max(k, c))]
                F[r][c][key] = F[r][c].get(key, R.zero) + C[k][r]
    out = []
    for r in range(3):
        out.append((q[r][0] - C[0][r], F[r][0]))
        out.append((q[r][1] - C[1][r], F[r][1]))
        out.append((q[r][2] - C[2][r], F[r][2]))
    for i in range(3):
        for j in range(i, 3):
            cof: dict = {6: R.one if i == j else R.zero}
            for c in range(3):
                for key, v in F[i][c].items():
                    cof[key] = cof.get(key, R.zero) + v * q[j][c]
            G = sum((q[i][c] * q[j][c] for c in range(3)), R.zero) - (R.one if i == j else R.zero)
            out.append((G, cof))
    for G, cof in out:
        if G != sum((v * H[h] for h, v in cof.items()), R.zero):
            raise AssertionError("derived rotation member: its cofactors do not give it")
    jets = []
    for G, cof in out:
        Gs = _derivatives(G, K, d)
        cs = {h: _derivatives(v, K, d) for h, v in cof.items()}
        for k in range(K + 1):
            jets.append((Gs[k], {(h, j): comb(k, j) * cs[h][k - j]
                                 for h in cs for j in range(k + 1)}))
    return jets
