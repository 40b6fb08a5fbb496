"""Coq proofs by normal forms: for a relation whose hypotheses are those of unit
vectors and angles only (no rotation, nothing along a motion), the certificate's ``let``
abbreviations become Coq ``Definition``s (the statement stays as small as the certificate,
where inlining them made 3.14's file 1.8 MB), each polynomial abbreviation is rewritten to
its normal form modulo the hypotheses (``ring`` checks ``let_k - NF_k = sum mu_i h_i`` with
cofactors computed here), and the entry, cleared of its divisors, is checked by ``field``
on those small normal forms.

The Gröbner basis is the hypotheses themselves: a unit vector's ``x_1^2 + ... - 1`` (leading
term ``x_1^2`` in graded reverse lexicographic order) and an angle's ``sin^2 + cos^2 - 1``
(leading term ``sin^2``) have pairwise coprime leading terms, so division by them is the
normal form. Coq trusts none of it: every step is a ``ring``/``field`` goal.
"""

from __future__ import annotations

import re
from fractions import Fraction
from math import gcd

import sympy as sp

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_.]*'*")


class NotReducible(ValueError):
    """This relation is not for the normal-form proof (the message says why)."""


def _ident(name: str) -> str:
    return "v_" + name.replace(".", "_")


_CALL = re.compile(r"\b(cos|sin)\(\s*(?:\((-?\d+)/(\d+)\)\*|(-?\d+)\*)?"
                   r"([A-Za-z][A-Za-z0-9_.]*)(?:/(\d+))?\s*\)")


def _psi(name: str, M: int) -> str:
    """Coq text of the angle ``name / M`` the cos/sin of an angle are polynomials in."""
    return _ident(name) if M == 1 else f"({_ident(name)} / {M})"


def _angles(cert: dict) -> tuple[dict, dict, dict]:
    """The certificate with each cos/sin call replaced by a name ``trg__N``, the angles'
    ``M`` (cos(k phi/M) for integer k), and ``{name: (fn, k, angle, M)}``."""
    calls: dict = {}

    def key(m):
        num, den = (int(m[2]), int(m[3])) if m[2] else (int(m[4] or 1), 1)
        return (m[1], Fraction(num, den * int(m[6] or 1)), m[5])

    texts = [t for _, t in cert["let"]] + [x for r in cert["relations"]
                                           for side in (r["lhs"], r["rhs"])
                                           for row in side for x in row]
    for t in texts:
        for m in _CALL.finditer(t):
            calls.setdefault(key(m), f"trg__{len(calls)}")
    M: dict = {}
    for _, r, a in calls:
        M[a] = M.get(a, 1) * r.denominator // gcd(M.get(a, 1), r.denominator)
    info = {n: (fn, int(r * M[a]), a, M[a]) for (fn, r, a), n in calls.items()}

    def sub(t):
        return _CALL.sub(lambda m: calls[key(m)], t)

    c = dict(cert, let=[[n, sub(t)] for n, t in cert["let"]])
    c["relations"] = [dict(r, lhs=[[sub(x) for x in row] for row in r["lhs"]],
                           rhs=[[sub(x) for x in row] for row in r["rhs"]])
                      for r in cert["relations"]]
    return c, M, info


def _trig_values(info: dict) -> dict:
    """``{trg name: cos/sin(k psi) as a polynomial in cos psi, sin psi}``."""
    out = {}
    for n, (fn, k, a, M) in info.items():
        c, s = sp.Symbol(f"(cos {_psi(a, M)})"), sp.Symbol(f"(sin {_psi(a, M)})")
        ck, sk = c, s  # cos_plus, sin_plus as Coq rewrites them: no sin^2 + cos^2 = 1
        for _ in range(k - 1):
            ck, sk = sp.expand(ck * c - sk * s), sp.expand(sk * c + ck * s)
        out[n] = ck if fn == "cos" else sk
    return out


def _trig_text(fn: str, k: int, a: str, M: int) -> str:
    """Coq text of cos/sin(k a / M), in lowest terms (cos(phi) stays ``cos v_phi``)."""
    r = Fraction(k, M)
    arg = _ident(a) if r.numerator == 1 else f"{r.numerator} * {_ident(a)}"
    return f"({fn} {arg})" if r == 1 else \
        f"({fn} ({arg}{f' / {r.denominator}' if r.denominator > 1 else ''}))"


def _trig_lemmas(info: dict, values: dict) -> tuple[list, list]:
    """(Coq lemmas ``T_n : cos (k phi / M) = P(cos psi, sin psi)``, their names), for the
    calls that are not cos/sin of psi itself; by ``cos_plus``/``sin_plus``."""
    out, names = [], []
    for n, (fn, k, a, M) in info.items():
        if k < 1:
            raise NotReducible("cos/sin of a negative multiple of an angle")
        text, psi = _trig_text(fn, k, a, M), _psi(a, M)
        if text == f"({fn} {psi})":
            continue
        arg = text[len(fn) + 2:-1]
        out.append(f"Lemma T_{n} : {text} = {_poly(values[n])}.\nProof.\n"
                   f"  assert (E : {fn} {arg} = {fn} ({' + '.join([psi] * k)})) by "
                   f"(f_equal; field).\n  rewrite E; repeat rewrite ?cos_plus, ?sin_plus; "
                   "ring.\nQed.")
        names.append(f"T_{n}")
    return out, names


def _gens(cert: dict, M: dict) -> tuple[list, list]:
    """(generators in order, hypothesis polynomials) of the unit and angle groups; free
    atoms after them."""
    gens, hyps = [], []
    for g in cert["atoms"]:
        if g["kind"] in ("unit", "unit4"):
            if g["timed"]:
                raise NotReducible("a unit vector along a motion")
            xs = [sp.Symbol(_ident(n)) for n in g["names"]]
            gens += xs
            hyps.append(sum(x**2 for x in xs) - 1)
        elif g["kind"] in ("angle", "angle_pi"):
            a = _psi(g["names"][0], M.get(g["names"][0], 1))
            s, c = sp.Symbol(f"(sin {a})"), sp.Symbol(f"(cos {a})")
            gens += [s, c]
            hyps.append(s**2 + c**2 - 1)
        elif g["kind"] in ("rotation", "transform"):
            raise NotReducible(f"a {g['kind']}")
    return gens, hyps


def _sympy(text: str, env: dict):
    """A grammar expression as sympy, names from ``env`` (lets, cos/sin calls already
    named by :func:`_angles`), other names as symbols ``v_name``."""
    local: dict = {}
    s = text
    if re.search(r"\b(cos|sin|sqrt|pi)\b", s):
        raise NotReducible("cos/sin of something other than a rational multiple of an angle")

    def name(m):
        n = m[0]
        if n in local:
            return n
        key = "n_" + re.sub(r"\W", lambda c: f"_{ord(c[0])}_", n)
        local[key] = env[n] if n in env else sp.Symbol(_ident(n))
        return key

    s = re.sub(r"[A-Za-z][A-Za-z0-9_.]*'*", name, s).replace("^", "**")
    return sp.sympify(s, locals=local)


def _reduce(p, gens, hyps) -> tuple[list, object]:
    """(cofactors, normal form) of the polynomial ``p`` modulo ``hyps``."""
    p = sp.expand(p)
    if not hyps:
        return [], p
    gens = list(gens) + sorted(p.free_symbols - set(gens), key=str)
    if p == 0:
        return [0] * len(hyps), p
    q, r = sp.reduced(p, hyps, *gens, order="grevlex")
    return list(q), r


def _poly(p) -> str:
    """A polynomial in Coq's syntax (symbols named by their Coq text)."""
    p = sp.expand(p)
    if p == 0:
        return "0"
    xs = sorted(p.free_symbols, key=str)
    if not xs:
        return f"({p})%R"
    terms = []
    for mono, c in sp.Poly(p, *xs).terms():
        terms.append(" * ".join([f"({c})%R"] + [f"{x}^{e}" if e > 1 else str(x)
                                             for x, e in zip(xs, mono, strict=True) if e]))
    return " + ".join(terms)


def _comb(mus, hyp_texts) -> str:
    return " + ".join(f"({_poly(m)}) * ({h})" for m, h in zip(mus, hyp_texts, strict=True)
                      if m != 0) or "0"


def normal_forms(cert: dict, gens: list, hyps: list, trig: dict) -> dict:
    """``{let name: (sympy value, normal form or None)}``; the normal form (a polynomial in
    the atoms) for a polynomial abbreviation, None for one that divides (``cert`` as
    :func:`_angles` writes it, ``trig`` the values of its cos/sin calls)."""
    env: dict = dict(trig)
    out = {}
    for name, text in cert["let"]:
        v = _sympy(text, env)
        if v.is_polynomial(*v.free_symbols):
            nf = _reduce(v, gens, hyps)[1]
            env[name] = nf
            out[name] = (v, nf)
        else:
            env[name] = v
            out[name] = (v, None)
    return out


def _lets_used(texts, lets: dict) -> list[str]:
    """The abbreviations ``texts`` use, directly or through others, in definition order."""
    seen: set = set()
    todo = [n for t in texts for n in _NAME.findall(t) if n in lets]
    while todo:
        n = todo.pop()
        if n not in seen:
            seen.add(n)
            todo += [m for m in _NAME.findall(lets[n]) if m in lets]
    return [n for n in lets if n in seen]


def reduced_file(cert: dict, coq_expr, divisors) -> str:
    """The Coq file of every cofactor-certified relation of ``cert`` by normal forms
    (``coq_expr(text, {})`` writes a grammar text in Coq; ``divisors(*texts)`` the
    expressions a Coq text divides by).

    Raises:
        NotReducible: a rotation, a motion, a function other than cos/sin of an angle, or an
            entry whose cleared numerator does not reduce to 0.
    """
    cert, M, info = _angles(cert)
    trig = _trig_values(info)
    gens, hyps = _gens(cert, M)
    nfs = normal_forms(cert, gens, hyps, trig)
    lets = dict(cert["let"])
    angle = [i for i, h in enumerate(hyps) if "(sin " in str(h)]
    htext = [_poly(h) for h in hyps]
    psi = {}
    for i in angle:  # as written, so that sin2_cos2 rewrites its one 1
        psi[i] = next(str(x)[5:-1] for x in hyps[i].free_symbols if str(x).startswith("(sin"))
        htext[i] = f"(cos {psi[i]})^2 + (sin {psi[i]})^2 - 1"
    unit = [i for i in range(len(hyps)) if i not in angle]
    prem = "".join(f"  ({htext[i]} = 0) ->\n" for i in unit)
    hnames = " ".join(f"H{i}" for i in unit)
    asserts = "".join(
        f"  assert (H{i} : {htext[i]} = 0) by (rewrite <- (sin2_cos2 "
        f"{psi[i]}); unfold Rsqr; ring).\n"
        for i in angle)
    rw_h = "rewrite " + ", ".join(f"?H{i}" for i in range(len(hyps))) + "; " if hyps else ""
    names = sorted({_ident(n) for g in cert["atoms"] for n in g["names"]})
    out = ["Section Cert."] + ([f"Variables {' '.join(names)} : R."] if names else [])
    out += [f"Definition {_ident(n)} := {coq_expr(t, {})}." for n, t in cert["let"]]
    tl, tnames = _trig_lemmas(info, trig)
    out += tl
    rw_t = "".join(f"  rewrite ?{t}.\n" for t in tnames)
    applied = {n: f"(L_{_ident(n)} {hnames})".replace(" )", ")") for n in lets}
    for n, t in cert["let"]:
        v, nf = nfs[n]
        if nf is None:
            continue
        mus, r = _reduce(v - nf, gens, hyps)
        if r != 0:
            raise NotReducible(f"{n}: no normal form")
        rw = "".join(f"  rewrite {applied[m]}.\n" for m in _lets_used([t], lets)
                     if m != n and nfs[m][1] is not None and m in _NAME.findall(t))
        out.append(f"Lemma L_{_ident(n)} :\n{prem}  {_ident(n)} = {_poly(nf)}.\n"
                   f"Proof.\n  intros {hnames}.\n{asserts}  unfold {_ident(n)}.\n{rw}{rw_t}"
                   f"  apply Rminus_diag_uniq.\n  transitivity ({_comb(mus, htext)}); "
                   f"[field | {rw_h}ring].\nQed.")
    env = dict(trig, **{n: (nf if nf is not None else v) for n, (v, nf) in nfs.items()})
    for ri, rel in enumerate(cert["relations"]):
        if rel["evidence"]["type"] != "cofactors":
            continue
        for i, (lr, rr) in enumerate(zip(rel["lhs"], rel["rhs"], strict=True)):
            for j, (a, b) in enumerate(zip(lr, rr, strict=True)):
                out.append(_entry(f"r{ri}_e{i + 1}{j + 1}", a, b, cert, env, nfs, gens, hyps,
                                  htext, (prem, hnames, asserts, rw_h, applied, tnames),
                                  coq_expr, divisors))
    out.append("End Cert.")
    return re.sub(r"\bv_(trg__\d+)\b", lambda m: _trig_text(*info[m[1]]),
                  "\n".join(out) + "\n")


def _entry(name, a, b, cert, env, nfs, gens, hyps, htext, parts, coq_expr, divisors) -> str:
    prem, hnames, asserts, rw_h, applied, tnames = parts
    lets = dict(cert["let"])
    used = _lets_used([a, b], lets)
    rational = [n for n in used if nfs[n][1] is None]
    lhs, rhs = coq_expr(a, {}), coq_expr(b, {})
    divs = divisors(lhs, rhs, *(coq_expr(lets[n], {}) for n in rational))
    f = _sympy(a, env) - _sympy(b, env)
    for k in (1, 2, 3):
        W = sp.Mul(*[_sympy_coq(d, env, cert) ** k for d in divs])
        num = sp.cancel(sp.together(W * f))
        if num.is_polynomial(*num.free_symbols):
            break
    else:
        raise NotReducible(f"{name}: the divisors do not clear the entry")
    mus, r = _reduce(num, gens, hyps)
    if r != 0:
        raise NotReducible(f"{name}: the cleared entry does not reduce to 0")
    wtext = " * ".join(f"({d})^{k}" for d in divs) or "1"
    nprem = "".join(f"  ({d} <> 0) ->\n" for d in divs)
    nnames = " ".join(f"N{i}" for i in range(len(divs)))
    unf = (f"  unfold {', '.join(_ident(n) for n in reversed(rational))} in *.\n"
           if rational else "")
    rw = ", ".join(f"?{applied[n]}" for n in reversed(used) if nfs[n][1] is not None)
    rw = f"  rewrite {rw} in *.\n" if rw else ""
    rw += "".join(f"  rewrite ?{t} in *.\n" for t in tnames)
    return (f"Lemma {name} :\n{prem}{nprem}  {lhs} = {rhs}.\n"
            f"Proof.\n  intros {hnames} {nnames}.\n{asserts}"
            f"  assert (NW : {wtext} <> 0) by (repeat apply Rmult_integral_contrapositive_"
            f"currified; try apply pow_nonzero; try assumption; apply R1_neq_R0).\n"
            f"  apply Rminus_diag_uniq.\n  apply (Rmult_eq_reg_l ({wtext})); [| exact NW].\n"
            f"  rewrite Rmult_0_r.\n  transitivity ({_comb(mus, htext)}); "
            f"[| {rw_h}ring].\n{unf}{rw}"
            f"  field; repeat split; try assumption.\n{_side(len(divs))}Qed.")


def _side(n: int) -> str:
    """Close field's side goals ``X <> 0``: each is a premise up to ``ring``, or the
    numerator of a premise that divides (``field_simplify`` leaves ``X' / Q = 0`` and
    ``Q <> 0``; two passes)."""
    if not n:
        return ""
    eq = "transitivity X; [ring | exact Z]"
    tries = " | ".join(f"apply N{i}; {eq}" for i in range(n))
    tries += "".join(f" | apply N{i}; field_simplify; [first [unfold Rdiv; apply "
                     f"Rmult_eq_0_compat_r; {eq} | {eq}] | idtac ..]" for i in range(n))
    one = (f"try (match goal with |- ?X <> 0 => let Z := fresh \"Z\" in intro Z; "
           f"first [{tries}] end)")
    return f"  all: {one}.\n  all: {one}.\n"


def _sympy_coq(text: str, env: dict, cert: dict):
    """A divisor written in Coq (``v_`` names, ``(cos v_phi)``) back as sympy over
    ``env``."""
    back = {_ident(n): n for g in cert["atoms"] for n in g["names"]}
    back.update({_ident(n): n for n in env})
    s = re.sub(r"\((cos|sin) (v_[A-Za-z0-9_]*)\)", lambda m: f"{m[1]}({back[m[2]]})", text)
    s = re.sub(r"\bv_[A-Za-z0-9_]*'*", lambda m: back[m[0]], s.replace("%R", ""))
    s = re.sub(r"\(/ ", "(1/", s)
    return _sympy(s, env)
