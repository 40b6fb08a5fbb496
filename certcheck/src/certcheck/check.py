"""Check one certificate: parse its statement, build the hypotheses from the declared
kinds, and check the evidence of every relation by the mathematics.

Evidence (``relations[i]["evidence"]["type"]``):

- ``identity``: lhs - rhs is the zero rational function after the checker's own
  parametrisations of the kinds (which are first shown to satisfy the hypotheses
  identically, with their time derivatives).
- ``counterexample``: an exact point; every hypothesis holds there exactly, no divisor
  vanishes, and an entry of lhs - rhs is not zero. A bare angle (or ``pi``) is kept as
  a transcendental number: the entry is then a non-zero polynomial in it.
- ``shape``: the two sides have different shapes.
- ``statement``: nothing to check but the grammar (a definition's printed form).
"""

from __future__ import annotations

import json
from fractions import Fraction
from math import lcm
from types import SimpleNamespace

from certcheck import kinds as K
from certcheck.field import Field, Root, Vanishing, evaluate
from certcheck.limits import MAX_DIGITS, LimitError, check_tree
from certcheck.parse import ParseError, names_in, parse
from certcheck.poly import make_ring

__all__ = ["CheckError", "check_certificate", "is_vacuous", "load"]

FORMAT = "rigidsym-certificate"
VERSIONS = (1,)
_LETS: list = [[], {}]  # the last statement's lets, as (name, text), and their trees


class CheckError(Exception):
    """The certificate does not prove what it claims (the message says why)."""


def load(path) -> dict:
    """The certificate in the file ``path`` (JSON)."""
    with open(path, encoding="utf-8") as f:
        return json.load(f)


# ----------------------------------------------------------------------------- statement
def _split(name: str) -> tuple[str, int]:
    base = name.rstrip("'")
    return base, len(name) - len(base)


class Statement:
    """The parsed statement: atoms by group, lets, relations as trees."""

    def __init__(self, cert: dict):
        if cert.get("format") != FORMAT or cert.get("version") not in VERSIONS:
            raise CheckError(f"not a {FORMAT} of version {VERSIONS}: "
                             f"{cert.get('format')!r} {cert.get('version')!r}")
        self.id = str(cert.get("id", "?"))
        self.groups = []
        self.atom_group: dict[str, tuple[int, int]] = {}
        for gi, g in enumerate(cert.get("atoms", [])):
            kind, names = g.get("kind"), list(g.get("names", []))
            if kind not in K.SIZES:
                raise CheckError(f"group {g.get('group')!r}: unknown kind {kind!r}")
            if len(names) != K.SIZES[kind]:
                raise CheckError(f"group {g.get('group')!r}: a {kind} has {K.SIZES[kind]} "
                                 f"atoms, {len(names)} given")
            for j, n in enumerate(names):
                if n in self.atom_group or n in ("pi", "cos", "sin") or _split(n)[1]:
                    raise CheckError(f"atom name {n!r} declared twice or reserved")
                self.atom_group[n] = (gi, j)
            self.groups.append({"group": str(g.get("group")), "kind": kind, "names": names,
                                "timed": bool(g.get("timed", False))})
        self.lets: dict = {}
        pairs, same, (last, trees) = [], True, _LETS  # a probe's lets extend its certificate's
        try:
            for k, (name, text) in enumerate(cert.get("let", [])):
                if name in self.atom_group or name in self.lets or _split(name)[1]:
                    raise CheckError(f"let {name!r} shadows an atom or another let")
                pairs.append((name, text))
                same = same and k < len(last) and last[k] == pairs[k]  # parsed once
                self.lets[name] = trees[name] if same else parse(text, self.lets)
            _LETS[:] = pairs, self.lets
            self.rels, memo = [], {}
            for r in cert.get("relations", []):
                lhs = [[parse(x, self.lets) for x in row] for row in r["lhs"]]
                rhs = [[parse(x, self.lets) for x in row] for row in r["rhs"]]
                for t in (t for row in lhs + rhs for t in row):
                    check_tree(t, _who(r), memo)
                self.rels.append((r, lhs, rhs))
        except LimitError as exc:
            raise CheckError(f"beyond certcheck's limits: {exc}") from None
        except (ParseError, KeyError, TypeError, ValueError) as exc:
            raise CheckError(f"statement outside the grammar: {exc}") from None
        # every name an atom of a declared group, jets only of timed ones; usage per relation
        self.trig: dict = {}
        self.usage = [self._usage(lhs + rhs) for _, lhs, rhs in self.rels]
        self.orders, self.used, self.bare_pi = self._merge(self.usage)
        self.M = self.lcm_M(self.trig.values())

    def lcm_M(self, forms) -> dict:
        """For each angle group, the lcm of the denominators of its coefficients."""
        forms = list(forms)
        return {gi: lcm(1, *[c.denominator for form in forms for a, c in form.items()
                             if a == g["names"][0]])
                for gi, g in enumerate(self.groups) if g["kind"] in ("angle", "angle_pi")}

    def _usage(self, rows) -> tuple:
        """``(orders, used, bare_pi, angles)``: the highest derivative per group, the
        ``(atom, order)`` pairs, whether ``pi`` stands outside cos/sin, and the angles of
        the cos/sin arguments."""
        orders, used, angles, trees = {}, set(), set(), [t for row in rows for t in row]
        self._scan(trees, orders, used, angles)  # a let shared by the entries: once
        return orders, used, _uses(trees, "pi"), angles

    @staticmethod
    def _merge(usages) -> tuple:
        orders: dict = {}
        for o, _, _, _ in usages:
            for gi, k in o.items():
                orders[gi] = max(orders.get(gi, 0), k)
        return orders, set().union(*(u[1] for u in usages)), any(u[2] for u in usages)

    def _scan(self, trees: list, orders, used, angles):
        names, seen = set(), set()
        for tree in trees:
            names_in(tree, names, seen)
        for name in names:
            base, k = _split(name)
            if base not in self.atom_group:
                raise CheckError(f"{name!r} is neither a declared atom nor a let")
            gi, _ = self.atom_group[base]
            if k and not self.groups[gi]["timed"]:
                raise CheckError(f"{name!r}: a derivative of an atom not declared timed")
            orders[gi] = max(orders.get(gi, 0), k)
            used.add((base, k))
        stack, seen = list(trees), set()
        while stack:
            n = stack.pop()
            if id(n) in seen:
                continue
            seen.add(id(n))
            if n[0] in ("cos", "sin"):
                self.trig[id(n[1])] = self._linear(n[1])
                angles |= {a for a in self.trig[id(n[1])] if a not in ("", "pi")}
            stack.extend(k for k in n[1:] if isinstance(k, tuple))

    def _linear(self, n) -> dict:
        """A trig argument as ``{angle atom or "pi": rational coefficient}``."""
        tag = n[0]
        if tag == "num":
            return {"": Fraction(n[1])}
        if tag == "pi":
            return {"pi": Fraction(1)}
        if tag == "name":
            gi = self.atom_group.get(n[1], (None,))[0]
            if gi is None or self.groups[gi]["kind"] not in ("angle", "angle_pi"):
                raise CheckError(f"cos/sin of {n[1]!r}, which is not a declared angle")
            return {n[1]: Fraction(1)}
        if tag == "neg":
            return {a: -c for a, c in self._linear(n[1]).items()}
        if tag in ("add", "sub"):
            out, s = dict(self._linear(n[1])), 1 if tag == "add" else -1
            for x, c in self._linear(n[2]).items():
                out[x] = out.get(x, 0) + s * c
            return out
        if tag in ("mul", "div"):
            a, b = self._linear(n[1]), self._linear(n[2])
            if set(b) == {""} and b[""] != 0:
                k = b[""] if tag == "mul" else 1 / b[""]
                return {x: c * k for x, c in a.items()}
            if tag == "mul" and set(a) == {""}:
                return {x: c * a[""] for x, c in b.items()}
        raise CheckError("a cos/sin argument that is not a rational combination of angles "
                         "and pi")

    def angle_form(self, arg) -> dict:
        form = self._linear(arg)  # never looked up by id: a later tree may reuse one
        if form.get("", 0):
            raise CheckError("a cos/sin argument with a rational constant term")
        if (2 * form.get("pi", 0)).denominator != 1:
            raise CheckError("a cos/sin argument with a multiple of pi other than k pi / 2")
        return {a: c for a, c in form.items() if a != "" and c}


def _cmul(F, a, b):
    return (F.sub(F.mul(a[0], b[0]), F.mul(a[1], b[1])),
            F.add(F.mul(a[0], b[1]), F.mul(a[1], b[0])))


def _cpow(F, z, n: int, cache: dict, key):
    """``z ** n`` for a unit complex ``z`` (negative ``n``: the conjugate's power)."""
    if (key, n) in cache:
        return cache[(key, n)]
    if n < 0:
        w = _cpow(F, z, -n, cache, key)
        out = (w[0], F.neg(w[1]))
    else:  # z^n = (z^(n // 2))^2 z^(n % 2)
        out = _cmul(F, *[_cpow(F, z, n // 2, cache, key)] * 2) if n else (F.one, F.zero)
        out = _cmul(F, out, z) if n % 2 else out
    cache[(key, n)] = out
    return out


def _trig(st: Statement, F: Field, unit_of, cache: dict, M: dict):
    """``trig(kind, arg)``: cos/sin of an argument from ``unit_of(angle) = (cos, sin)`` of
    ``angle / M``, by de Moivre and the quarter turns of ``pi / 2``."""
    quarter = [(F.one, F.zero), (F.zero, F.one), (F.const(-1), F.zero), (F.zero, F.const(-1))]

    def trig(kind, arg):
        form = st.angle_form(arg)
        z = quarter[int(2 * form.pop("pi", 0)) % 4]
        for a, c in sorted(form.items()):
            n = c * M[gi := st.atom_group[a][0]]
            if n.denominator != 1:
                raise CheckError(f"coefficient {c} of {a} is not a multiple of 1/{M[gi]}")
            z = _cmul(F, z, _cpow(F, unit_of(a), int(n), cache, a))
        return z[0] if kind == "cos" else z[1]
    return trig


# ----------------------------------------------------------------------------- identity
def _identity_context(st: Statement, fast: bool):
    """The field of the checker's parametrisation, the leaf and trig functions, and the
    hypotheses it proves."""
    names, nxt, index = [], {}, {}

    def var(name):
        if name not in index:
            index[name] = len(names)
            names.append(name)
        return index[name]

    params = {}
    for gi, g in enumerate(st.groups):
        if g["kind"] in K.PARAMS and gi in st.orders:
            order = st.orders[gi] if g["timed"] else 0
            params[gi] = [[var(f"{g['group']}.{p}" + "'" * k) for k in range(order + 1)]
                          for p in K.PARAMS[g["kind"]]]
            for jets in params[gi]:
                for a, b in zip(jets, jets[1:], strict=False):
                    nxt[a] = b
    for base, k in sorted(st.used):
        if st.groups[st.atom_group[base][0]]["kind"] not in K.PARAMS:
            var(base + "'" * k)
    taus = {}
    for gi, M in st.M.items():
        taus[gi] = var(f"tan({st.groups[gi]['names'][0]}/{2 * M})")
    if st.bare_pi:
        var("pi")  # pi outside cos/sin: transcendental, an independent variable
    ring = make_ring(names, fast)
    F = Field(ring, nxt)
    atoms = {}
    for gi, P in params.items():
        g = st.groups[gi]
        X = K.parametrise(g["kind"], F, [F.var(jets[0]) for jets in P])
        for k in range(st.orders[gi] + 1 if g["timed"] else 1):
            if k:
                X = [F.d(x) for x in X]
            for j, n in enumerate(g["names"]):
                atoms[n + "'" * k] = X[j]
    units = {}
    for gi, t in taus.items():
        tau = F.var(t)
        den = F.inv(F.add(F.one, F.mul(tau, tau)))
        units[st.groups[gi]["names"][0]] = (
            F.mul(F.sub(F.one, F.mul(tau, tau)), den), F.mul(F.mul(F.const(2), tau), den))

    def leaf(name):
        if name in atoms:
            return atoms[name]
        return F.var(index[name])  # free atoms, bare angles, pi: independent variables
    return F, atoms, params, leaf, _trig(st, F, units.__getitem__, {}, st.M), var, index


def _prove_parametrisation(st: Statement, F: Field, params: dict) -> None:
    """The parametrised atoms satisfy their kind's constraints identically, and so do the
    time derivatives of the constraints up to the order the statement uses."""
    for gi, P in params.items():
        g = st.groups[gi]
        X0 = K.parametrise(g["kind"], F, [F.var(jets[0]) for jets in P])
        for h in K.constraints(g["kind"], F, X0):
            for k in range(st.orders[gi] + 1 if g["timed"] else 1):
                if not F.is_zero(h):
                    raise CheckError(f"the checker's parametrisation of {g['group']} fails "
                                     f"its constraint (derivative {k})")
                if k < st.orders[gi]:
                    h = F.d(h)


def check_identity(st: Statement, rels: list, fast: bool) -> list[str]:
    """Every relation of ``rels`` is an identity under the hypotheses."""
    F, atoms, params, leaf, trig, var, index = _identity_context(st, fast)
    _prove_parametrisation(st, F, params)
    memo, R, m, out = {}, None, {}, []
    for r, lhs, rhs in rels:
        _same_shape(lhs, rhs, r)
        roots = _uses([x for s in (lhs, rhs) for row in s for x in row], "sqrt")
        if not roots:
            _zero(r, lhs, rhs, F, memo, leaf, trig)
        for fresh in () if not roots else (True,) if R is None else (False, True):
            R, m = (Root(F), {}) if fresh else (R, m)  # K(s): one while the radicand is
            try:
                _zero(r, lhs, rhs, R, m, lambda n, R=R: R.lift(leaf(n)),
                      lambda k, a, R=R: R.lift(trig(k, a)))
                break
            except CheckError:  # another radicand: K(s) of its own
                if fresh:
                    raise
        out.append(f"{_who(r)}: identity, lhs - rhs = 0 as a rational function of "
                   f"{len(F.ring.names)} parameters")
    return out


def _zero(r: dict, lhs, rhs, E, m: dict, lf, tr) -> None:
    """Every entry of lhs - rhs is zero in ``E`` (evaluated with the memo ``m``)."""
    for i, (lr, rr) in enumerate(zip(lhs, rhs, strict=True)):
        for j, (a, b) in enumerate(zip(lr, rr, strict=True)):
            try:
                diff = evaluate(("sub", a, b), E, lf, tr, m)  # the same difference: once
            except (Vanishing, ValueError) as exc:
                raise CheckError(f"{_who(r)} entry ({i + 1}, {j + 1}): {exc}") from None
            if not E.is_zero(diff):
                raise CheckError(f"{_who(r)} entry ({i + 1}, {j + 1}): lhs - rhs is not "
                                 "zero after the parametrisation")


def _uses(trees: list, tag: str) -> bool:
    stack, seen = list(trees), set()
    while stack:
        n = stack.pop()
        if id(n) in seen:
            continue
        seen.add(id(n))
        if n[0] == tag:
            return True
        if n[0] not in ("cos", "sin") or tag != "pi":
            stack.extend(k for k in n[1:] if isinstance(k, tuple))
    return False


def _same_shape(lhs, rhs, r) -> None:
    if [len(x) for x in lhs] != [len(x) for x in rhs]:
        raise CheckError(f"{_who(r)}: the sides have different shapes")


def _who(r: dict) -> str:
    return f"{r.get('role', 'relation')} {r.get('label') or ''}".strip()


# ----------------------------------------------------------------------------- counterexample
def _rational(text, what: str) -> Fraction:
    if len(str(text)) > 2 * MAX_DIGITS + 2:
        raise CheckError(f"{what}: a number of {len(str(text))} characters (certcheck's "
                         f"limit: {MAX_DIGITS} digits a part)")
    try:
        return Fraction(str(text))
    except (ValueError, ZeroDivisionError):
        raise CheckError(f"{what}: {text!r} is not a rational number") from None


def _check_point(st: Statement, usage, point: dict, angles: dict) -> tuple[list, dict, dict]:
    """Every hypothesis holds at the point exactly (constraints and, for a motion, their
    time derivatives up to the order used); returns the facts in words, each angle's M and
    tan(angle / 2M)."""
    orders, used, _, trig_angles = usage
    facts = []
    for gi, g in enumerate(st.groups):
        if g["kind"] not in K.PARAMS or gi not in orders:
            continue
        order = orders[gi] if g["timed"] else 0
        names = [n + "'" * k for k in range(order + 1) for n in g["names"]]
        missing = [n for n in names if n not in point]
        if missing:
            raise CheckError(f"the point gives no value to {', '.join(missing)}")
        nn = len(g["names"])
        F = Field(make_ring(names, fast=False), {i: i + nn for i in range(len(names) - nn)})
        values = [point[n] for n in names]
        for h in K.constraints(g["kind"], F, [F.var(i) for i in range(nn)]):
            for k in range(order + 1):
                if F.value(h, values) != 0:
                    raise CheckError(f"the point is off the constraint set of {g['group']} "
                                     f"({g['kind']}, time derivative {k})")
                h = F.d(h)
        facts.append(f"{g['group']}: its {g['kind']} constraints hold exactly"
                     + (f" with {order} time derivative(s)" if order else ""))
    Ms, taus = {}, {}
    for gi, g in enumerate(st.groups):
        a = g["names"][0]
        if g["kind"] not in ("angle", "angle_pi") or (a not in trig_angles and (a, 0) not in used):
            continue
        if a not in angles:
            raise CheckError(f"the point gives no tan({a}/2M) for the angle {a}")
        M = angles[a].get("M")
        if not isinstance(M, int) or M < 1:
            raise CheckError(f"angle {a}: M must be a positive integer, got {M!r}")
        t = _rational(angles[a].get("tan"), f"tan({a}/{2 * M})")
        if g["kind"] == "angle_pi" and (M != 1 or t < 0):
            raise CheckError(f"angle {a} in [0, pi]: needs M = 1 and tan({a}/2) >= 0")
        Ms[gi], taus[a] = M, t
        facts.append(f"{a} = {2 * M} atan({t})")
    return facts, Ms, taus


def check_counterexample(st: Statement, index: int, ev: dict) -> str:
    """Relation ``index`` fails at the certificate's point: an entry of lhs - rhs is not
    zero there, and every hypothesis holds there. With ``for_every`` (free atoms left out of
    the point: 3.148's P, never given) it fails there for every real value of them:
    ``x^T (lhs - rhs) x = c + sum w_k L_k^2`` (x the rational ``form``, ``squares`` the
    pairs ``[w_k, L_k]``), ``c`` a non-zero constant and every ``w_k`` of its sign."""
    (r, lhs, rhs), usage = st.rels[index], st.usage[index]
    _same_shape(lhs, rhs, r)
    point = {n: _rational(v, n) for n, v in dict(ev.get("point", {})).items()}
    facts, Ms, taus = _check_point(st, usage, point, dict(ev.get("angles", {})))
    every = [str(a) for a in ev.get("for_every", [])]
    if any((st.groups[st.atom_group[n][0]] if n in st.atom_group else {}).get("kind") != "free"
           or st.groups[st.atom_group[n][0]]["timed"] or n in point for n in every):
        raise CheckError(f"{_who(r)}: for_every names atoms not free, timed, or on the point")
    # bare angles (with tan != 0) and pi are transcendental: at most one of them stays a
    # variable (two such numbers are not known to be algebraically independent)
    bare = sorted({b for b, k in usage[1] if k == 0 and b in taus and taus[b] != 0})
    if usage[2]:
        bare.append("pi")
    if len(bare) > 1 or bare and every:
        raise CheckError(f"the entries hold {', '.join(bare)} outside cos/sin: more than one "
                         "transcendental number (or one beside for_every), not decided")
    F, slot = Field(make_ring(bare + every, fast=False)), {n: i for i, n in enumerate(bare + every)}
    units = {a: (F.const((1 - t * t) / (1 + t * t)), F.const(2 * t / (1 + t * t)))
             for a, t in taus.items()}

    def leaf(name):
        if name in slot:
            return F.var(slot[name])
        if name in taus:  # a bare angle at tan = 0 is 0
            return F.zero
        if name not in point:
            raise CheckError(f"the point gives no value to {name}")
        return F.const(point[name])
    trig = _trig(st, F, units.__getitem__, {}, Ms)
    memo, diffs = {}, {}
    try:
        for i, (lr, rr) in enumerate(zip(lhs, rhs, strict=True)):
            for j, (a, b) in enumerate(zip(lr, rr, strict=True)):
                diffs[i, j] = F.sub(*(evaluate(x, F, leaf, trig, memo) for x in (a, b)))
        if every:
            squares = [(w, evaluate(parse(str(t), st.lets), F, leaf, trig, memo))
                       for w, t in ev.get("squares", [])]
            return _for_every(r, F, diffs, ev.get("form", []), squares, facts, every)
    except (Vanishing, ValueError, ParseError) as exc:
        raise CheckError(f"{_who(r)}: {exc} (a divisor vanishing at the point, or a text "
                         "outside the grammar)") from None
    hit = next(((i, j, d) for (i, j), d in diffs.items() if not F.is_zero(d)), None)
    if hit is None:
        raise CheckError(f"{_who(r)}: every entry of lhs - rhs is zero at the point")
    i, j, d = hit
    what = f"is a non-zero rational function of {bare[0]}, a transcendental number " \
        "(Lindemann), so not zero" if bare else f"= {F.value(d, [])}"
    return (f"{_who(r)}: does not hold; at the point ({'; '.join(facts) or 'no constraints'})"
            f" entry ({i + 1}, {j + 1}) of lhs - rhs {what}")


def _for_every(r, F, diffs, form, squares, facts, every) -> str:
    """``x^T (lhs - rhs) x - sum w_k L_k^2`` is a non-zero constant c, each w_k c >= 0, and no
    divisor holds an atom of ``every``: x^T (lhs - rhs) x is never 0, so nor is lhs - rhs."""
    x, ws = [_rational(v, "form") for v in form], [_rational(w, "weight") for w, _ in squares]
    q = F.zero if {(i, j) for i in range(len(x)) for j in range(len(x))} == set(diffs) else None
    for (i, j), d in diffs.items() if q else ():
        q = F.add(q, F.mul(F.const(x[i] * x[j]), d))
    for w, (_, L) in zip(ws, squares if q else (), strict=False):
        q = F.sub(q, F.mul(F.const(w), F.mul(L, L)))
    c = F.value(q, [0] * len(every)) if q else 0
    if F.factors or c == 0 or not F.is_zero(F.sub(q, F.const(c))) or any(w * c < 0 for w in ws):
        raise CheckError(f"{_who(r)}: x^T (lhs - rhs) x (x the form, of the square relation's "
                         "size) is not a non-zero constant plus squares weighted of its sign")
    return (f"{_who(r)}: does not hold for any real {', '.join(every[:2])}, ...; at the point "
            f"({'; '.join(facts) or 'no constraints'}) x^T (lhs - rhs) x = {c} + squares each"
            " weighted of its sign, never 0")


# ----------------------------------------------------------------------------- cofactors
def check_cofactors(st: Statement, index: int, ev: dict, fast: bool = True) -> str:
    """Relation ``index`` is an identity by cofactors: for each entry, ``D (lhs - rhs) -
    sum_i mu_i h_i`` is the zero rational function of the atoms (``cos``/``sin`` of each
    angle over its M as two more variables), the ``h_i`` the hypotheses of the kinds
    (generated here), and ``D`` and every divisor are non-zero at an exact point of the
    constraint set."""
    r, lhs, rhs = st.rels[index]
    orders, used, bare_pi, trig_angles = usage = st.usage[index]
    _same_shape(lhs, rhs, r)
    if bare_pi or any(st.groups[st.atom_group[b][0]]["kind"] in ("angle", "angle_pi")
                      for b, k in used if k == 0):
        raise CheckError(f"{_who(r)}: cofactors with a bare angle or pi are not decided here")
    point = {n: _rational(v, n) for n, v in dict(ev.get("point", {})).items()}
    facts, Ms, taus = _check_point(st, usage, point, dict(ev.get("angles", {})))
    names, nxt, hyps_of = [], {}, []
    for gi, g in enumerate(st.groups):
        if gi not in orders:
            continue
        top = orders[gi] if g["timed"] else 0
        if g["kind"] in K.PARAMS:
            names += [n + "'" * k for k in range(top + 1) for n in g["names"]]
            hyps_of.append((gi, top))
        else:
            names += sorted({b + "'" * k for b, k in used if st.atom_group[b][0] == gi})
    angles = [g["names"][0] for gi, g in enumerate(st.groups) if g["names"][0] in trig_angles]
    for a in angles:
        if Ms.get(st.atom_group[a][0]) != st.M[st.atom_group[a][0]]:
            raise CheckError(f"angle {a}: the point's M must be {st.M[st.atom_group[a][0]]}")
        names += [f"cos({a}/{st.M[st.atom_group[a][0]]})", f"sin({a}/{st.M[st.atom_group[a][0]]})"]
    index_of = {n: i for i, n in enumerate(names)}
    for gi, top in hyps_of:
        for k in range(top):
            for n in st.groups[gi]["names"]:
                nxt[index_of[n + "'" * k]] = index_of[n + "'" * (k + 1)]
    F = Field(make_ring(names, fast), nxt)
    hyps = []
    for gi, top in hyps_of:
        g = st.groups[gi]
        for h in K.constraints(g["kind"], F, [F.var(index_of[n]) for n in g["names"]]):
            for k in range(top + 1):
                hyps.append(h)
                h = F.d(h) if k < top else h
    units = {}
    for a in angles:
        M = st.M[st.atom_group[a][0]]
        C, S = F.var(index_of[f"cos({a}/{M})"]), F.var(index_of[f"sin({a}/{M})"])
        hyps.append(F.sub(F.add(F.mul(C, C), F.mul(S, S)), F.one))
        units[a] = (C, S)
    trig = _trig(st, F, units.__getitem__, {}, st.M)

    def leaf(name):
        if name not in index_of:
            raise CheckError(f"{name!r} is not an atom of this relation")
        return F.var(index_of[name])
    entries = list(ev.get("entries", []))
    flat = [(i, j, a, b) for i, (lr, rr) in enumerate(zip(lhs, rhs, strict=True))
            for j, (a, b) in enumerate(zip(lr, rr, strict=True))]
    if len(entries) != len(flat):
        raise CheckError(f"{_who(r)}: {len(entries)} cofactor entries for {len(flat)} entries")
    memo: dict = {}
    dens = []
    for (i, j, a, b), e in zip(flat, entries, strict=True):
        where = f"{_who(r)} entry ({i + 1}, {j + 1})"
        mus = list(e.get("cofactors", []))
        if len(mus) != len(hyps):
            raise CheckError(f"{where}: {len(mus)} cofactors for {len(hyps)} hypotheses")
        try:
            check_tree(D := parse(e["denominator"], st.lets), f"{where}'s denominator")
            D = evaluate(D, F, leaf, trig, memo)
            total = F.mul(D, F.sub(evaluate(a, F, leaf, trig, memo),
                                   evaluate(b, F, leaf, trig, memo)))
            for mu, h in zip(mus, hyps, strict=True):
                check_tree(m := parse(mu), f"{where}'s cofactor")
                total = F.sub(total, F.mul(evaluate(m, F, leaf, trig, memo), h))
        except (Vanishing, ValueError, KeyError) as exc:
            raise CheckError(f"{where}: {exc}") from None
        if not F.is_zero(total):
            raise CheckError(f"{where}: D (lhs - rhs) - sum mu_i h_i is not zero")
        dens.append(D)
    values = []
    for n in names:
        if n.startswith(("cos(", "sin(")):
            t = taus[n[4:n.index("/")]]
            values.append((1 - t * t) / (1 + t * t) if n[0] == "c" else 2 * t / (1 + t * t))
        elif n in point:
            values.append(point[n])
        else:
            raise CheckError(f"the point gives no value to {n}")
    for f in F.factors:  # every divisor met on the way, the denominators' included
        if F.ring.evaluate(f, values) == 0:
            raise CheckError(f"{_who(r)}: a divisor vanishes at the point")
    for D in dens:
        if F.value(D, values) == 0:
            raise CheckError(f"{_who(r)}: a denominator D vanishes at the point")
    return (f"{_who(r)}: identity by cofactors over {len(hyps)} hypotheses, D != 0 at a "
            f"point of the constraint set ({'; '.join(facts) or 'no constraints'})")


# ----------------------------------------------------------------------------- the verdict
def hypotheses(st: Statement) -> list[str]:
    """The hypotheses of the statement in words (from the kinds, never the certificate)."""
    return [K.words(g["kind"], g["group"], g["timed"], st.orders.get(gi, 0))
            for gi, g in enumerate(st.groups) if g["kind"] != "free" or g["timed"]]


def check_certificate(cert: dict, fast: bool = True) -> tuple[str, list[str]]:
    """Check ``cert``; returns ``(verdict, lines)``.

    Raises:
        CheckError: the evidence does not prove the verdict (the message names the id).
    """
    try:
        return _check(cert, fast)
    except CheckError as exc:
        raise CheckError(f"({cert.get('id', '?')}) {exc}") from None


#: :func:`evaluate`'s field of (literally zero, atom-free once every product with a literal
#: 0 factor is dropped): ``1*(1*1 - 0*e_1) = 1`` is constants only, ``(a - b) + (b - a)`` not
_FREE = SimpleNamespace(
    const=lambda q: (Fraction(q) == 0, True), neg=lambda a: a,
    pow=lambda a, n: (a[0] and n > 0, a[1]), add=lambda a, b: (a[0] and b[0], a[1] and b[1]),
    sub=lambda a, b: (a[0] and b[0], a[1] and b[1]), sqrt=lambda a: a,
    div=lambda a, b: (a[0], a[0] or a[1] and b[1]),
    mul=lambda a, b: (a[0] or b[0], a[0] or b[0] or a[1] and b[1]))


def is_vacuous(rel, st: Statement, same: bool = True) -> bool:
    """Vacuous: the two sides are one expression once the lets are read in (unless
    ``same`` is false), or both are constants only, an atom standing only in a product with
    a literal 0 (``1·1·1 = 1``; 3.30's determinant of a unit triangular block matrix,
    expanded)."""
    memo: dict = {}
    try:
        return same and rel[1] == rel[2] or all(
            evaluate(x, _FREE, lambda n: (False, False), lambda k, a: (False, False), memo)[1]
            for side in rel[1:] for row in side for x in row)
    except ValueError:  # a square root: not a constant of this kind
        return False


def _check(cert: dict, fast: bool) -> tuple[str, list[str]]:
    st = Statement(cert)
    verdict = cert.get("verdict")
    lines = [f"hypothesis: {h}" for h in hypotheses(st)]
    by = {"identity": [], "cofactors": [], "counterexample": [], "shape": [],
          "statement": []}
    for rel in st.rels:
        t = dict(rel[0].get("evidence") or {}).get("type")
        if t not in by:
            raise CheckError(f"{_who(rel[0])}: unknown evidence {t!r}")
        by[t].append(rel)
    if not st.rels:
        raise CheckError("no relation")
    roles = {rel[0].get("role") for rel in st.rels}
    printed = [rel for rel in st.rels if rel[0].get("role") == "printed"]
    unproved = [rel for rel in st.rels if rel[0].get("role") == "corrected"
                and rel not in by["identity"] + by["cofactors"]]
    if unproved:  # a corrected form is a theorem of the certificate: proved, or no form
        raise CheckError(f"{_who(unproved[0][0])}: a corrected form needs identity or "
                         "cofactor evidence (it is proved, never stated or refuted)")
    if verdict == "restatement" and not all(is_vacuous(rel, st) for rel in printed or st.rels):
        raise CheckError("a restatement, but a printed relation derives something (its sides "
                         "are neither one expression nor constants only): verified or not, "
                         "never a restatement")
    if verdict in ("verified", "restatement"):  # a restatement: identities deriving nothing
        if by["counterexample"] or by["shape"] or by["statement"] or \
                not roles <= {"printed", "claim"}:
            raise CheckError(f"a {verdict} statement needs identity evidence for every "
                             "printed member and claim")
        vacuous = [rel for rel in printed or st.rels if is_vacuous(rel, st)]
        if len(vacuous) == len(printed or st.rels) and verdict == "verified":
            if ":" not in st.id:  # the book's ids; a reader's own (ns:name) get a note
                raise CheckError("verified, but every printed relation (or claim) is vacuous:"
                                 " two identical sides, or constants only (nothing derived: "
                                 "a definition, a restatement or an identity by definition)")
            lines.append("NOTE: every printed relation has two identical sides: nothing "
                         "derived here (an identity by definition)")
        lines += [f"{_who(rel[0])}: VACUOUS, not evidence (two identical sides, or constants"
                  " only); the id is verified by its other printed relations"
                  for rel in printed if rel in vacuous and verdict == "verified"]
    elif verdict == "does-not-hold":
        failing = [rel for rel in by["counterexample"] + by["shape"]
                   if rel[0].get("role") == "printed" or rel[0].get("role") == "claim"
                   and isinstance(rel[0].get("page"), int)]  # a chain's member, printed
        if not failing or by["statement"]:
            raise CheckError("a does-not-hold needs a printed relation with a counterexample "
                             "or a shape mismatch (a failing claim is not the page's)")
        refuted = [rel for rel in by["counterexample"] + by["shape"] if rel not in failing]
        if refuted:
            raise CheckError(f"{_who(refuted[0][0])}: refuted, but not a printed relation "
                             "(a does-not-hold fails on what the page prints)")
    elif verdict == "definition":
        if all(str(x).strip() == "0" for rel in printed for s in ("lhs", "rhs")
               for row in rel[0][s] for x in row):
            raise CheckError("a definition whose printed relations are zeros only (0 = 0) "
                             "defines nothing")
        if by["counterexample"] or by["shape"] or not printed or \
                any(rel[0].get("role") != "printed" for rel in by["statement"]) or \
                any(rel not in by["statement"] for rel in printed):
            raise CheckError("a definition holds its printed form as a statement and its "
                             "claims as identities")
    else:
        raise CheckError(f"unknown verdict {verdict!r}")
    for rel in by["statement"]:
        _same_shape(rel[1], rel[2], rel[0])
        lines.append(f"{_who(rel[0])}: a definition (the statement only)")
    for rel in by["shape"]:
        shapes = [(len(s), len(s[0]) if s else 0) for s in rel[1:]]
        if shapes[0] == shapes[1] and [len(x) for x in rel[1]] == [len(x) for x in rel[2]]:
            raise CheckError(f"{_who(rel[0])}: the sides have the same shape")
        lines.append(f"{_who(rel[0])}: does not hold, shapes {shapes[0][0]}x{shapes[0][1]} "
                     f"and {shapes[1][0]}x{shapes[1][1]}")
    for rel in by["counterexample"]:
        lines.append(check_counterexample(st, st.rels.index(rel), rel[0]["evidence"]))
    for rel in by["cofactors"]:
        lines.append(check_cofactors(st, st.rels.index(rel), rel[0]["evidence"], fast))
    return verdict, lines + (check_identity(st, by["identity"], fast) if by["identity"] else [])
