"""The Coq export of a folder of certificates (``rigidsym verify --coq DIR``): one file per
id that coqc accepts (``eq3_16.v``: a Coq file name is a module name, a letter first), and
``NO-PROOF.txt`` naming each id without one and why.

An identity gets the lemmas of :func:`rigidsym.checking.certifying.coq.coq_file`. A
does-not-hold gets, beside its corrected form's lemmas where Coq takes them, a
**counterexample lemma** per failing relation: the entry of ``lhs - rhs`` that certcheck
finds non-zero, written with every atom at the point's exact rational value and every
``cos``/``sin`` of a multiple of an angle at its exact value there (``phi = 2M atan(t)``:
``cos(k phi / M) + i sin(k phi / M) = ((1 - t^2 + 2 i t) / (1 + t^2))^k``, computed here
in exact rationals), is shown equal to a non-zero rational by ``field`` and so not zero;
and a lemma that the point satisfies every unit-vector constraint and that ``(cos, sin)``
of ``phi / M`` lies on the unit circle. What Coq does not see: that these rationals are the
cosines and sines of the angle (that is de Moivre, above) — certcheck checks the same point
by its own arithmetic.
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

from rigidsym.checking.certifying.coq import NoProof, coq_expr, coq_file
from rigidsym.core.files import write_atomic

__all__ = ["coq_file_name", "counterexample_lemmas", "coq_text", "write_coq_folder"]

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_.]*'*")


def coq_file_name(eq_id: str) -> str:
    """The Coq file of an id: ``eq`` and the id with every character outside
    ``[A-Za-z0-9_]`` as ``_`` (``3.96e`` -> ``eq3_96e.v``; coqc refuses ``3_96e.v``)."""
    return "eq" + re.sub(r"[^A-Za-z0-9_]", "_", eq_id) + ".v"


def _inline(text: str, lets: dict) -> str:
    return _NAME.sub(lambda m: f"({lets[m.group()]})" if m.group() in lets else m.group(),
                     text)


def _unit_power(t: Fraction, n: int) -> tuple[Fraction, Fraction]:
    """``(cos, sin)`` of ``n psi`` where ``tan(psi / 2) = t``."""
    c, s = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    z = (Fraction(1), Fraction(0))
    w = (c, s if n >= 0 else -s)
    for _ in range(abs(n)):
        z = (z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0])
    return z


def _trig_value(kind: str, arg: str, angles: dict) -> Fraction:
    """cos/sin of a rational combination of angles and pi at the point."""
    import sympy as sp

    syms = {a: sp.Symbol(f"A{k}") for k, a in enumerate(angles)}
    expr = sp.sympify(_NAME.sub(lambda m: "pi" if m.group() == "pi" else
                                syms[m.group()].name if m.group() in syms else "BAD", arg)
                      .replace("^", "**"))
    if expr.has(sp.Symbol("BAD")):
        raise NoProof(f"cos/sin of {arg!r}: not an angle of the point")
    z = (Fraction(1), Fraction(0))
    for a, s in syms.items():
        c = Fraction(str(expr.coeff(s)))
        n = c * angles[a]["M"]
        if n.denominator != 1:
            raise NoProof(f"cos/sin of {arg!r}: not a multiple of {a}/M")
        w = _unit_power(Fraction(angles[a]["tan"]), int(n))
        z = (z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0])
    rest = sp.expand(expr - sum(expr.coeff(s) * s for s in syms.values()))
    q = Fraction(str(rest / sp.pi)) if rest != 0 else Fraction(0)
    if (2 * q).denominator != 1 or rest.free_symbols:
        raise NoProof(f"cos/sin of {arg!r}: a multiple of pi other than k pi / 2")
    quarter = [(1, 0), (0, 1), (-1, 0), (0, -1)][int(2 * q) % 4]
    z = (z[0] * quarter[0] - z[1] * quarter[1], z[0] * quarter[1] + z[1] * quarter[0])
    return z[0] if kind == "cos" else z[1]


def _at_point(text: str, point: dict, angles: dict) -> str:
    """The grammar text with cos/sin and atoms at the point (rational literals)."""
    out, pos = [], 0
    for m in re.finditer(r"\b(cos|sin)\(", text):
        if m.start() < pos:
            continue
        depth, end = 0, m.end() - 1
        for end in range(m.end() - 1, len(text)):
            depth += text[end] == "("
            depth -= text[end] == ")"
            if depth == 0:
                break
        v = _trig_value(m.group(1), text[m.end():end], angles)
        out += [text[pos:m.start()], f"({v.numerator}/{v.denominator})"]
        pos = end + 1
    text = "".join(out) + text[pos:]

    def value(m):
        name = m.group()
        if name not in point:
            raise NoProof(f"{name!r} has no value at the point (a bare angle or pi: "
                          "a transcendental point, which Coq is not given)")
        v = Fraction(point[name])
        return f"({v.numerator}/{v.denominator})"
    return _NAME.sub(value, text)


def counterexample_lemmas(cert: dict) -> list[str]:
    """Coq lemmas that each counterexample relation's residual is not zero at its exact
    point, and that the point lies on the unit-vector constraints and the angles' circle.

    Raises:
        NoProof: a bare angle or ``pi`` (a transcendental point) or no counterexample.
    """
    import sympy as sp

    lets: dict = {}
    for name, text in cert["let"]:
        lets[name] = _inline(text, lets)
    lemmas = []
    for ri, rel in enumerate(cert["relations"]):
        ev = rel["evidence"]
        if ev["type"] != "counterexample":
            continue
        point, angles = ev.get("point", {}), ev.get("angles", {})
        point = {**dict.fromkeys(ev.get("for_every", []), "0"), **point}  # one of every value
        hit = None
        for i, (lr, rr) in enumerate(zip(rel["lhs"], rel["rhs"], strict=True)):
            for j, (a, b) in enumerate(zip(lr, rr, strict=True)):
                lt, rt = (_at_point(_inline(x, lets), point, angles) for x in (a, b))
                q = sp.Rational(sp.sympify(f"({lt}) - ({rt})".replace("^", "**")))
                if q != 0:
                    hit = (i, j, lt, rt, q)
                    break
            if hit:
                break
        if hit is None:
            raise NoProof(f"relation {ri}: no entry of lhs - rhs is non-zero at the point")
        i, j, lt, rt, q = hit
        L, R = coq_expr(lt, {}), coq_expr(rt, {})
        name = f"residual_r{ri}_e{i + 1}{j + 1}"
        lemmas.append(f"(* ({cert['id']}) {rel['role']} {rel.get('label', '')}: entry "
                      f"({i + 1}, {j + 1}) of lhs - rhs at the certificate's point *)\n"
                      f"Lemma {name} : ({L}) - ({R}) = ({q.p})%R / ({q.q})%R.\n"
                      f"Proof. field. Qed.\n"
                      f"Lemma {name}_not_zero : ({L}) - ({R}) <> 0.\n"
                      f"Proof. rewrite {name}. lra. Qed.\n")
        lemmas.append(_on_constraints(cert, ri, point, angles))
    if not lemmas:
        raise NoProof("no counterexample relation")
    return lemmas


def _on_constraints(cert: dict, ri: int, point: dict, angles: dict) -> str:
    """The point's unit vectors have norm 1 and each angle's (cos, sin) of phi / M lies on
    the unit circle (rotations: certcheck's check only)."""
    facts = []
    for g in cert["atoms"]:
        if g["kind"] in ("unit", "unit4") and all(n in point for n in g["names"]):
            facts.append(" + ".join(f"({_at_point(n, point, {})})^2" for n in g["names"])
                         + " = 1")
        if g["kind"] in ("angle", "angle_pi") and g["names"][0] in angles:
            c, s = _unit_power(Fraction(angles[g["names"][0]]["tan"]), 1)
            facts.append(f"({c.numerator}/{c.denominator})^2 + ({s.numerator}/"
                         f"{s.denominator})^2 = 1")
    if not facts:
        return ""
    body = " /\\ ".join(f"({coq_expr(f.split(' = ')[0], {})}) = 1" for f in facts)
    return (f"Lemma point_r{ri}_on_constraints : {body}.\n"
            f"Proof. repeat split; field. Qed.\n")


def coq_text(cert: dict) -> str:
    """The Coq file of a certificate: its identities' lemmas and, for a does-not-hold, its
    counterexample lemmas.

    Raises:
        NoProof: nothing Coq can be given (the message says why).
    """
    parts, why = [], []
    try:
        parts.append(coq_file(cert))
    except NoProof as exc:
        why.append(str(exc))
    if cert.get("verdict") == "does-not-hold":
        try:
            lemmas = counterexample_lemmas(cert)
        except NoProof as exc:
            why.append(f"counterexample: {exc}")
        else:
            head = "" if parts else ("(* Generated by rigidsym from the certificate of "
                                     f"({cert['id']}); checked by coqc. *)\n"
                                     "Require Import Reals Lra Field.\nOpen Scope R_scope.\n")
            parts.append(head + "\n".join(x for x in lemmas if x))
    if not parts:
        raise NoProof("; ".join(why))
    return "\n".join(parts)


def write_coq_folder(certs: dict, directory, extra_none: dict | None = None) -> dict:
    """Write ``directory/eq<id>.v`` for each certificate Coq can be given and
    ``directory/NO-PROOF.txt`` with each other id and why.

    Args:
        certs: id -> certificate (dicts, as :func:`rigidsym.checking.certifying.
            certificates.certificate` returns them).
        directory: the folder (created).
        extra_none: id -> why, for ids without a certificate (listed in NO-PROOF.txt).

    Returns:
        ``{"written": {id: file name}, "none": {id: why}}``.
    """
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    written, none = {}, dict(extra_none or {})
    for eq_id, cert in certs.items():
        try:
            text = coq_text(cert)
        except (NoProof, KeyError, TypeError, ValueError) as exc:
            none[eq_id] = str(exc) or type(exc).__name__
            continue
        write_atomic(out / coq_file_name(eq_id), text)
        written[eq_id] = coq_file_name(eq_id)
    write_atomic(out / "NO-PROOF.txt",
                 "".join(f"{i}: {why}\n" for i, why in none.items()) or "none\n")
    return {"written": written, "none": none}
