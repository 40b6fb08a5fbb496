"""Cofactor certificates of identities: ``D (lhs - rhs) = sum_i mu_i h_i`` with
``h_i`` the hypotheses the checker generates from the kinds, ``mu_i`` polynomials in the atoms
and ``D`` a polynomial that is not zero at a stated point of the constraint set.

Computed over python-flint's ``fmpq_mpoly`` by pseudo-division along a triangular set, one
constrained group after another (their variables are disjoint):

- a unit vector ``x`` (static or along a motion, jets up to order K): for k = K ... 1, the
  k-th time derivative of ``|x|^2 - 1`` is linear in ``x_last^(k)`` with coefficient
  ``2 x_last``, so ``x_last^(k)`` is eliminated by a pseudo-remainder (``D`` gains a power of
  ``x_last``); then ``x_last^2 = 1 - sum of the other squares`` (a monic remainder);
- an angle: ``sin^2 = 1 - cos^2`` of ``angle / M`` (monic);
- a rotation or a transform: the triangular set of
:mod:`rigidsym.checking.certifying.rotation_triangular_set`.

A bare angle or ``pi`` is left to the re-computation certificate (a point where ``D`` is not
zero would need a transcendental coordinate). The hypotheses' order is the
checker's (``certcheck.check``: groups in the certificate's order, each constraint of the
kind with its time derivatives 0 ... K, then the angles' ``cos^2 + sin^2 - 1``).
"""

from __future__ import annotations

import re
import time
from fractions import Fraction

import flint
import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.checking.certifying import cofactor_ansatz as ansatz
from rigidsym.checking.certifying import rotation_triangular_set as triangular
from rigidsym.checking.deciding.explicit import entries_of

__all__ = ["NoCofactors", "cofactor_evidence", "TERMS_LIMIT", "CHARS_LIMIT"]

#: past this many terms in a numerator or cofactor the certificate stays a re-computation
#: one (a file a referee can still open)
TERMS_LIMIT = 20_000
#: past this many characters of a relation's cofactors, too (a rotation along a motion
#: reaches megabytes, which certcheck's re-check would take minutes and gigabytes over)
CHARS_LIMIT = 200_000
#: CPU seconds per relation; past it, a re-computation certificate (the method recorded does
#: not depend on the machine's load, as CPU time is counted)
SECONDS = 5.0


_UNITS = ("unit", "unit4")
#: kinds reduced by a triangular set of
# :mod:`rigidsym.checking.certifying.rotation_triangular_set`: their hypotheses
_CHAINS = {"rotation": 7, "transform": 11}


class NoCofactors(Exception):
    """No cofactor certificate for this relation (the message says why)."""


class _Ring:
    """The atoms' ring: one variable per atom jet, and per angle ``C``/``S`` for the cosine
    and sine of ``angle / M``."""

    def __init__(self, names: list[str]):
        self.names = names
        self.index = {n: i for i, n in enumerate(names)}
        self.ctx = flint.fmpq_mpoly_ctx.get([f"x{i}" for i in range(len(names))], "lex")
        self.gens = self.ctx.gens()
        self.one = self.ctx.from_dict({(0,) * len(names): 1})
        self.zero = self.one - self.one

    def var(self, name: str):
        return self.gens[self.index[name]]

    def text(self, p) -> str:
        """``p`` in the certificate grammar."""
        s = str(p)
        return re.sub(r"\bx(\d+)\b", lambda m: self.names[int(m.group(1))], s)


def _frac_add(a, b):
    """``a + b`` of fractions ``(num, den)`` over the denominators' least common multiple
    (a sum of terms over powers of one norm stays over its highest power, instead of their
    product, which the reduction after it then divided out again)."""
    if a[1] == b[1]:
        return (a[0] + b[0], a[1])
    g = a[1].gcd(b[1])
    if g.is_one():
        return (a[0] * b[1] + b[0] * a[1], a[1] * b[1])
    ag, bg = a[1] / g, b[1] / g
    return (a[0] * bg + b[0] * ag, ag * b[1])


def _reduce(p):
    num, den = p
    if num.is_zero():
        return (num, den.context().from_dict({(0,) * den.context().nvars(): 1}))
    g = num.gcd(den)
    if not g.is_one():
        num, den = num / g, den / g
    return (num, den)


def _convert(e, R: _Ring, atom_name, unit, memo):
    """``e`` as a fraction ``(num, den)`` of the ring's polynomials."""
    if e in memo:
        return memo[e]
    if e.is_Rational:
        out = (R.one * flint.fmpq(int(e.p), int(e.q)), R.one)
    elif isinstance(e, sp.Symbol | AppliedUndef) or e is sp.pi:
        out = (R.var(atom_name(e)), R.one)
    elif isinstance(e, sp.Derivative):
        k = sum(int(n) for _, n in e.variable_count)
        out = (R.var(atom_name(e.expr) + "'" * k), R.one)
    elif isinstance(e, sp.Add):
        out = (R.zero, R.one)
        for a in e.args:
            out = _frac_add(out, _convert(a, R, atom_name, unit, memo))
        out = _reduce(out)
    elif isinstance(e, sp.Mul):
        num, den = R.one, R.one
        for a in e.args:
            n, d = _convert(a, R, atom_name, unit, memo)
            num, den = num * n, den * d
        out = _reduce((num, den))
    elif isinstance(e, sp.Pow) and e.exp.is_Integer:
        n, d = _convert(e.base, R, atom_name, unit, memo)
        k = int(e.exp)
        if k < 0:
            memo.setdefault(None, []).append(n)  # a divisor: not zero at the point
        out = (n**k, d**k) if k >= 0 else (d ** (-k), n ** (-k))
        if out[1].is_zero():
            raise NoCofactors("a division by zero")
    elif isinstance(e, sp.cos | sp.sin):
        re_, im = unit(e.args[0])
        out = (re_ if isinstance(e, sp.cos) else im, R.one)
    else:
        raise NoCofactors(f"{type(e).__name__} in an entry")
    if len(out[0]) > TERMS_LIMIT:
        raise NoCofactors(f"a numerator of more than {TERMS_LIMIT} terms")
    memo[e] = out
    return out


def _reduce_group(N, R: _Ring, g: dict, order: int, nxt: dict, mus: dict, mult):
    """Eliminate a unit group's last coordinate and its jets from ``N``; ``(N, mult)``."""
    x = g["names"]
    h = sum((R.var(n) ** 2 for n in x), -R.one)
    gs = [h]
    for _ in range(order):
        gs.append(triangular.dpoly(gs[-1], R, nxt))
    last = x[-1]
    for k in range(order, 0, -1):
        i = R.index[last + "'" * k]
        gk = gs[k]
        c = gk.derivative(i)
        d = gk - c * R.gens[i]
        m, r = triangular.prem_linear(N, i, c, d)
        q, rest = divmod(c**m * N - r, gk)
        if not rest.is_zero():
            raise NoCofactors("a pseudo-division left a remainder")
        for key in mus:
            mus[key] = mus[key] * c**m
        mult = mult * c**m
        mus[(g["group"], k)] = q
        N = r
    s = R.one - sum((R.var(n) ** 2 for n in x[:-1]), R.zero)
    r = triangular.rem_square(N, R.index[last], s)
    q, rest = divmod(N - r, h)
    if not rest.is_zero():
        raise NoCofactors("a division by the unit constraint left a remainder")
    mus[(g["group"], 0)] = q
    return r, mult


def _scan(e, atom_name, used: dict, trig_angles: set) -> None:
    stack = [e]
    while stack:
        x = stack.pop()
        if isinstance(x, sp.cos | sp.sin):
            trig_angles |= {atom_name(a) for a in x.args[0].atoms(sp.Symbol, AppliedUndef)}
            continue
        if x is sp.pi:
            raise NoCofactors("pi outside cos/sin")
        if isinstance(x, sp.Derivative):
            n = atom_name(x.expr)
            used.setdefault(n, set()).add(sum(int(k) for _, k in x.variable_count))
            continue
        if isinstance(x, sp.Symbol | AppliedUndef):
            used.setdefault(atom_name(x), set()).add(0)
            continue
        stack.extend(x.args)


def cofactor_evidence(lhs, rhs, atoms: list, atom_name, M: dict, points: list) -> dict:
    """The cofactor evidence of the relation ``lhs = rhs``.

    Args:
        lhs, rhs: its sides (sympy, the model substituted; same shapes).
        atoms: the certificate's atom groups (``cert["atoms"]``), in its order.
        atom_name: sympy atom -> its certificate name.
        M: angle name -> the M of its cosines and sines (``cos(angle / M)``), as the checker
            computes it over the whole certificate.
        points: candidates ``{"point": {...}, "angles": {...}}``, exact points of the
            constraint set (counterexample conventions); the first where no denominator
            vanishes is kept (a free atom it does not value gets 1/2).

    Returns:
        ``{"type": "cofactors", "entries": [{"denominator": text, "cofactors": [text per
        hypothesis]}], "point", "angles"}``, entries row-major, hypotheses in the checker's
        order.

    Raises:
        NoCofactors: a kind without a triangular set here, a bare angle, a size past
            :data:`TERMS_LIMIT`, a remainder that is not zero, or a denominator zero at the
            point.
    """
    L, Rh = entries_of(lhs), entries_of(rhs)
    names, nxt, order, angle_names = _layout(L + Rh, atoms, atom_name, M)
    R = _Ring(names)
    nxt_i = {R.index[a]: R.index[b] for a, b in nxt.items()}
    unit = _unit_of(R, atom_name, M)
    memo: dict = {}
    hyps = []  # the checker's order
    for g in atoms:
        K = order.get(g["group"]) if g["kind"] != "free" else None
        if K is not None:
            hyps += [(g["group"], k) for k in range(K + 1)] if g["kind"] in _UNITS else \
                [(g["group"], h, k) for h in range(_CHAINS[g["kind"]]) for k in range(K + 1)]
    hyps += [("angle", a) for a in angle_names]
    entries = []
    t0 = time.process_time()
    for a, b in zip(L, Rh, strict=True):
        if time.process_time() - t0 > SECONDS:
            raise NoCofactors(f"over {SECONDS} s of CPU")
        ln = _convert(sp.sympify(a), R, atom_name, unit, memo)
        rn = _convert(sp.sympify(b), R, atom_name, unit, memo)
        D, mus = _ansatz(ln, rn, R, atoms, order, nxt_i, hyps, M) or \
            _entry_cofactors(ln, rn, R, atoms, order, nxt_i, angle_names, M, t0 + SECONDS)
        entries.append((D, [mus.get(k) for k in hyps]))
    free = {n for g in atoms if g["kind"] == "free" for n in g["names"]}
    divisors = [D for D, _ in entries] + memo.get(None, [])
    for point in points:
        values = _values(R, point, M, free)
        if values is not None and all(D(*values) != 0 for D in divisors):
            break
    else:
        raise NoCofactors("no candidate point where every denominator is non-zero")
    out = [{"denominator": R.text(D), "cofactors": ["0" if m is None else R.text(m)
                                                   for m in mus]} for D, mus in entries]
    if sum(len(m) for e in out for m in e["cofactors"]) > CHARS_LIMIT:
        raise NoCofactors(f"cofactors of more than {CHARS_LIMIT} characters")
    return {"type": "cofactors", "entries": out, **point}


def _layout(exprs: list, atoms: list, atom_name, M: dict) -> tuple:
    """The ring's variables for the entries ``exprs``: ``(names, next jet of each unit
    entry jet, K of each unit group used, the angles under cos/sin)``; :class:`NoCofactors`
    for a bare angle, or a kind without a triangular set here."""
    used: dict = {}   # certificate name -> its jets used outside cos/sin
    trig_angles: set = set()
    for e in exprs:
        _scan(sp.sympify(e), atom_name, used, trig_angles)
    names, nxt, order = [], {}, {}
    for g in atoms:
        use = [max(used[n]) for n in g["names"] if n in used]
        if g["kind"] in ("angle", "angle_pi"):
            a = g["names"][0]
            if 0 in used.get(a, ()):
                raise NoCofactors(f"the bare angle {a} (a point would need a "
                                  "transcendental coordinate)")
            names += [a + "'" * k for k in sorted(used.get(a, ()))]  # its rates: free
            continue
        if not use:
            continue
        if g["kind"] not in (*_UNITS, *_CHAINS, "free"):
            raise NoCofactors(f"a {g['kind']} (no triangular set in its entries here)")
        K = max(use) if g["timed"] else 0
        order[g["group"]] = K
        for k in range(K + 1):
            for n in g["names"]:
                if g["kind"] == "free" and (n not in used or max(used[n]) < k):
                    continue
                names.append(n + "'" * k)
    for g in atoms:
        if g["kind"] in (*_UNITS, *_CHAINS) and g["group"] in order:
            K = order[g["group"]]
            for k in range(K):
                for n in g["names"]:
                    nxt[n + "'" * k] = n + "'" * (k + 1)
    angle_names = [g["names"][0] for g in atoms
                   if g["kind"] in ("angle", "angle_pi") and g["names"][0] in trig_angles]
    for a in angle_names:
        names += [f"cos({a}/{M[a]})", f"sin({a}/{M[a]})"]
    return names, nxt, order, angle_names


def _unit_of(R: _Ring, atom_name, M: dict):
    """``arg -> exp(i arg)`` as a pair (cos, sin) of ring elements, for a rational
    combination of angles and ``pi`` (the angles' coefficients multiples of ``1/M``)."""

    def unit(arg):
        form = sp.expand(arg)
        z = (R.one, R.zero)
        quarter = [(R.one, R.zero), (R.zero, R.one), (-R.one, R.zero), (R.zero, -R.one)]
        for term in sp.Add.make_args(form):
            c, rest = term.as_coeff_Mul()
            if rest is sp.pi:
                z0 = quarter[int(2 * c) % 4]
                z = (z[0] * z0[0] - z[1] * z0[1], z[0] * z0[1] + z[1] * z0[0])
                continue
            a = atom_name(rest)
            k = Fraction(int(c.p), int(c.q)) * M[a]
            if k.denominator != 1:
                raise NoCofactors("an angle coefficient off its M")
            w = triangular.cpow((R.var(f"cos({a}/{M[a]})"), R.var(f"sin({a}/{M[a]})")), int(k), R)
            z = (z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0])
        return z

    return unit


def _ansatz(ln, rn, R: _Ring, atoms: list, order: dict, nxt_i: dict, hyps: list,
            M: dict):
    """``(D, {hypothesis: cofactor})`` by :func:`cofactor_ansatz.linear_combination` (no
    multiplier: ``D`` is the entry's denominator) for a relation on a rotation or transform;
    ``None`` otherwise or when the ansatz finds none."""
    if not any(g["kind"] in _CHAINS and g["group"] in order for g in atoms):
        return None
    N, Q = _reduce((ln[0] * rn[1] - rn[0] * ln[1], ln[1] * rn[1]))
    d = lambda p: triangular.dpoly(p, R, nxt_i)  # noqa: E731
    polys = ansatz.hypothesis_polys(R, atoms, hyps, M, d, triangular.hypotheses)
    extra = [(g["group"], G, cof) for g in atoms if g["kind"] in _CHAINS and g["group"] in order
             for G, cof in triangular.derived(R, g["names"], g["kind"] == "transform",
                                          order[g["group"]], d)]
    mus = ansatz.linear_combination(N, polys + [G for _, G, _ in extra], 1, 4000)
    if mus is None:
        return None
    out = dict(zip(hyps, mus[:len(hyps)], strict=True))
    for (group, _, cof), nu in zip(extra, mus[len(hyps):], strict=True):
        for (h, j), c in cof.items():  # G = sum c h^(j): nu G in the hypotheses
            out[(group, h, j)] = out[(group, h, j)] + nu * c
    return Q, out


def _entry_cofactors(ln, rn, R: _Ring, atoms: list, order: dict, nxt_i: dict,
                     angle_names: list, M: dict, deadline: float) -> tuple:
    """``(D, {hypothesis: cofactor})`` of one entry ``ln = rn`` (each ``(num, den)`` over
    the ring); :class:`NoCofactors` for a non-zero remainder or a size past the limit."""
    N, Q = _reduce((ln[0] * rn[1] - rn[0] * ln[1], ln[1] * rn[1]))
    mus: dict = {}
    mult = R.one
    for g in atoms:
        if g["kind"] in _UNITS and g["group"] in order:
            N, mult = _reduce_group(N, R, g, order[g["group"]], nxt_i, mus, mult)
        elif g["kind"] in _CHAINS and g["group"] in order:
            H = triangular.hypotheses(R, g["names"], g["kind"] == "transform")
            chain = (triangular.transform_chain if g["kind"] == "transform" else
                     triangular.rotation_chain)(R, g["names"], H)
            try:
                N, mult = triangular.pseudo_reduce(N, R, chain, g["names"], order[g["group"]],
                                               lambda p: triangular.dpoly(p, R, nxt_i), mus, mult,
                                               g["group"], (TERMS_LIMIT, deadline))
            except triangular.ChainRemainder as exc:
                raise NoCofactors(str(exc)) from None
    for a_ in angle_names:
        C, S = R.var(f"cos({a_}/{M[a_]})"), R.var(f"sin({a_}/{M[a_]})")
        h = C**2 + S**2 - R.one
        r = triangular.rem_square(N, R.index[f"sin({a_}/{M[a_]})"], R.one - C**2)
        q, rest = divmod(N - r, h)
        if not rest.is_zero():
            raise NoCofactors("a division by cos^2 + sin^2 - 1 left a remainder")
        mus[("angle", a_)] = q
        N = r
    if not N.is_zero():
        raise NoCofactors("the remainder is not zero")
    D = mult * Q
    if any(len(m) > TERMS_LIMIT for m in mus.values()) or len(D) > TERMS_LIMIT:
        raise NoCofactors(f"a cofactor of more than {TERMS_LIMIT} terms")
    return D, mus


def _values(R: _Ring, point: dict, M: dict, free: set):
    """The ring's variables at the point (``fmpq``), or ``None`` when one is missing; a free
    atom's missing value is set to 1/2 (in ``point``)."""
    vals = []
    for n in R.names:
        if n.startswith(("cos(", "sin(")):
            a = n[4:n.index("/")]
            ang = point["angles"].get(a)
            if ang is None or ang["M"] != M[a]:
                return None
            t = Fraction(ang["tan"])
            v = (1 - t * t) / (1 + t * t) if n.startswith("cos") else 2 * t / (1 + t * t)
        elif n in point["point"]:
            v = Fraction(point["point"][n])
        elif n.rstrip("'") in free or n != n.rstrip("'"):  # a free atom, an angle's rate
            v = Fraction(1, 2)
            point["point"][n] = "1/2"
        else:
            return None
        vals.append(flint.fmpq(v.numerator, v.denominator))
    return vals
