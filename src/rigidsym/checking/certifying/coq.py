"""Coq proofs of identity certificates: each entry of a relation with cofactor
evidence becomes a lemma ``forall atoms, hypotheses -> divisors <> 0 -> lhs = rhs`` proved,
as Lean's ``linear_combination`` would, by ``ring`` (or ``field`` where the statement
divides) checking ``D (lhs - rhs) = sum mu_i h_i`` with the certificate's cofactors, then
the hypotheses set to zero.

A certificate whose atoms are unit vectors, angles and free atoms only is written instead
by :mod:`rigidsym.checking.certifying.coq_normal_form`: its abbreviations as ``Definition``s, each
rewritten to its normal form modulo the hypotheses, the entry cleared of its divisors and closed by
``field`` (3.14 and 3.15: past 240 s inlined, 3-6 s so); where that export does not apply
(a rotation, a motion) or refuses (a numerator that does not reduce to 0), the cofactor
proof above.

Written from the certificate alone (its statement and cofactors; the hypotheses generated
here from the kinds, as certcheck does). ``cos``/``sin`` are Coq's (``Reals``), of an angle
itself (M = 1); a statement with other arguments, a bare angle or ``pi`` gets no proof
(:class:`NoProof`). ``coqc`` checks the file; :func:`prove` runs it.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import sympy as sp

from rigidsym.checking.certifying import coq_normal_form

__all__ = ["NoProof", "coq_file", "prove", "coq_expr"]

_TOKEN = re.compile(r"(\d+)|([A-Za-z][A-Za-z0-9_.]*'*)|(\^-?\d+|\*|/|\+|-|\(|\))|\s+")


class NoProof(ValueError):
    """No Coq proof of this certificate (the message says why)."""


def _ident(name: str) -> str:
    return "v_" + name.replace(".", "_")


def _coq_expr(text: str, lets: dict) -> str:
    """A grammar expression in Coq's syntax over ``R`` (lets inlined)."""
    out = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise NoProof(f"unexpected text {text[pos:pos + 10]!r}")
        pos = m.end()
        num, name, op = m.groups()
        if num is not None:
            out.append(f"{num}%R")
        elif name is not None:
            if name in ("cos", "sin"):
                out.append(name)
            elif name == "sqrt":
                raise NoProof("a square root")
            elif name == "pi":
                raise NoProof("pi outside a supported cos/sin argument")
            elif name in lets:
                out.append(f"({lets[name]})")
            else:
                out.append(_ident(name))
        elif op is not None:
            if op.startswith("^"):
                k = int(op[1:])
                out.append(f"^{k}" if k >= 0 else f"^{-k}")
                if k < 0:  # x^-k: / x^k, wrap the base that precedes
                    base = _pop_operand(out[:-1])
                    out[:] = base[0] + [f"(/ ({''.join(base[1])})^{-k})"]
            else:
                out.append(op)
    s = re.sub(r"\s+", " ", "".join(t if t in "()" else f" {t} " for t in out))
    # cos(phi/1), cos(phi): Coq's cos of the angle itself
    s = re.sub(r"(cos|sin) ?\( ?(v_\w+) / 1%R ?\)", r"(\1 \2)", s)
    s = re.sub(r"(cos|sin) ?\( ?(v_\w+) ?\)", r"(\1 \2)", s)
    if re.search(r"\b(cos|sin) ?\(", s):
        raise NoProof("cos/sin of something other than an angle itself")
    return re.sub(r"\s+", " ", s).strip()


def coq_expr(text: str, lets: dict) -> str:
    """A certificate's grammar expression ``text`` in Coq's syntax over ``R``, the lets of
    ``lets`` (name -> Coq text) inlined.

    Raises:
        NoProof: a square root, a bare ``pi``, or cos/sin of anything but an angle itself.
    """
    return _coq_expr(text, lets)


def _pop_operand(tokens: list) -> tuple[list, list]:
    """Split ``tokens`` into (rest, last operand) (a name, number or parenthesised group;
    a function application included)."""
    if tokens[-1] == ")":
        depth = 0
        for i in range(len(tokens) - 1, -1, -1):
            depth += tokens[i] == ")"
            depth -= tokens[i] == "("
            if depth == 0:
                j = i - 1 if i and tokens[i - 1] in ("cos", "sin") else i
                return tokens[:j], tokens[j:]
    return tokens[:-1], tokens[-1:]


def _hypotheses(cert: dict, rel: dict) -> list[tuple[str, str]]:
    """``(text, why)`` of the hypotheses in certcheck's order for a relation."""
    text = " ".join(rel["lhs"][0] + rel["rhs"][0] + [x for _, x in cert["let"]]
                    + [c for e in rel["evidence"]["entries"] for c in e["cofactors"]]
                    + [e["denominator"] for e in rel["evidence"]["entries"]])
    names = set(re.findall(r"[A-Za-z][A-Za-z0-9_.]*'*", text))
    out = []
    for g in cert["atoms"]:
        if g["kind"] not in ("unit", "unit4", "rotation", "transform"):
            continue
        used = [n for n in names if n.rstrip("'") in g["names"]]
        if not used:
            continue
        order = max(len(n) - len(n.rstrip("'")) for n in used) if g["timed"] else 0
        jets = {(n, k): sp.Symbol(_ident(n + "'" * k)) for n in g["names"]
                for k in range(order + 2)}
        for i, h in enumerate(_constraints(g["kind"], [jets[(n, 0)] for n in g["names"]])):
            for k in range(order + 1):
                out.append((_poly(sp.expand(h)), f"{g['group']} {g['kind']} constraint "
                                                 f"{i + 1}, derivative {k}"))
                h = sum(sp.diff(h, jets[(n, j)]) * jets[(n, j + 1)]
                        for n in g["names"] for j in range(order + 1))
    for g in cert["atoms"]:
        if g["kind"] in ("angle", "angle_pi") and re.search(
                rf"(cos|sin)\({re.escape(g['names'][0])}(/1)?\)", text):
            a = _ident(g["names"][0])
            out.append((f"(cos {a})^2 + (sin {a})^2 - 1", f"{g['group']} angle"))
    return out


def _constraints(kind: str, X: list) -> list:
    """certcheck's constraint polynomials of a kind (``certcheck.kinds.constraints``)."""
    if kind in ("unit", "unit4"):
        return [sum(x**2 for x in X) - 1]
    M = [X[i] for i in (0, 1, 2, 4, 5, 6, 8, 9, 10)] if kind == "transform" else X
    out = [sum(M[3 * k + i] * M[3 * k + j] for k in range(3)) - int(i == j)
           for i in range(3) for j in range(i, 3)]
    out.append(sp.Matrix(3, 3, M).det() - 1)
    return out + ([X[12], X[13], X[14], X[15] - 1] if kind == "transform" else [])


def _poly(p) -> str:
    terms = []
    for mono, c in sp.Poly(p, *sorted(p.free_symbols, key=str)).terms():
        factors = [f"{x}^{e}" for x, e in zip(sorted(p.free_symbols, key=str), mono,
                                               strict=True) if e]
        terms.append(" * ".join([f"({c})%R", *factors]))
    return " + ".join(terms) or "0"


def coq_file(cert: dict, normal_forms: bool = True) -> str:
    """The Coq file proving every cofactor-certified relation of ``cert``: by normal forms
    where :mod:`rigidsym.checking.certifying.coq_normal_form` applies (unless ``normal_forms`` is
    false), else by the certificate's cofactors.

    Raises:
        NoProof: no relation of ``cert`` has cofactor evidence Coq can take.
    """
    head = ("(* Generated by rigidsym from the certificate of "
            f"({cert['id']}) {cert.get('title', '')}; checked by coqc. *)\n"
            "Require Import Reals Lra Field.\nOpen Scope R_scope.\n")
    if normal_forms and any(r["evidence"]["type"] == "cofactors" for r in cert["relations"]):
        try:  # unit vectors and angles: normal forms, the statement as small as the JSON
            return head + coq_normal_form.reduced_file(cert, _coq_expr, _divisors)
        except (ValueError, KeyError, TypeError, SyntaxError, ZeroDivisionError):
            pass  # the certificate's cofactors below (a NoProof is a ValueError)
    lets: dict = {}
    for name, text in cert["let"]:
        lets[name] = _coq_expr(text, lets)
    lemmas = []
    for ri, rel in enumerate(cert["relations"]):
        ev = rel["evidence"]
        if ev["type"] != "cofactors":
            continue
        hyps = _hypotheses(cert, rel)
        flat = [(i, j, a, b) for i, (lr, rr) in enumerate(zip(rel["lhs"], rel["rhs"],
                                                              strict=True))
                for j, (a, b) in enumerate(zip(lr, rr, strict=True))]
        for (i, j, a, b), e in zip(flat, ev["entries"], strict=True):
            if len(e["cofactors"]) != len(hyps):
                raise NoProof("cofactors and hypotheses differ in number")
            lhs, rhs = _coq_expr(a, lets), _coq_expr(b, lets)
            D = _coq_expr(e["denominator"], lets)
            mus = [_coq_expr(m, lets) for m in e["cofactors"]]
            lemmas.append(_lemma(f"r{ri}_e{i + 1}{j + 1}", lhs, rhs, D, mus, hyps))
    if not lemmas:
        raise NoProof("no relation with cofactor evidence")
    return head + "\n".join(lemmas) + "\n"


def _vars(*texts: str) -> list[str]:
    found = set()
    for t in texts:
        found |= set(re.findall(r"\bv_[A-Za-z0-9_]*'*", t))
    return sorted(found)


def _divisors(*texts: str) -> list[str]:
    """The expressions a text divides by (``/ (x)``), innermost last."""
    out = []
    for t in texts:
        for m in re.finditer(r"/ \(", t):
            depth, k = 0, m.end() - 1
            for k2 in range(m.end() - 1, len(t)):
                depth += t[k2] == "("
                depth -= t[k2] == ")"
                if depth == 0:
                    k = k2
                    break
            out.append(t[m.end() - 1:k + 1])
    return list(dict.fromkeys(out))


def _lemma(name, lhs, rhs, D, mus, hyps) -> str:
    hs = [h for h, _ in hyps]
    vs = _vars(lhs, rhs, D, *mus, *hs)
    divs = _divisors(lhs, rhs, D)
    binders = " ".join(vs) or "_unused"
    premises = [f"H{k} : {h} = 0" for k, h in enumerate(hs) if "cos" not in h]
    premises += [f"N{k} : {d} <> 0" for k, d in enumerate(divs)]
    if D != "1%R":
        premises.append(f"ND : {D} <> 0")
    comb = " + ".join(f"({m}) * ({h})" for m, h in zip(mus, hs, strict=True)) or "0"
    lines = [f"Lemma {name} : forall {binders} : R,"]
    lines += [f"  ({p.split(' : ', 1)[1]}) ->" for p in premises]
    lines.append(f"  {lhs} = {rhs}.")
    names = " ".join(p.split(" : ")[0] for p in premises)
    lines.append(f"Proof.\n  intros {' '.join(vs) if vs else '_unused'} {names}.")
    for k, (h, _why) in enumerate(hyps):
        if "cos" in h:
            a = re.search(r"cos (v_\w+)", h).group(1)
            lines.append(f"  assert (H{k} : {h} = 0) by "
                         f"(rewrite <- (sin2_cos2 {a}); unfold Rsqr; ring).")
    rew = " ".join(f"H{k}" for k in range(len(hs)))
    if D == "1%R" and not divs:
        lines.append("  apply Rminus_diag_uniq.")
        lines.append(f"  replace ({lhs} - ({rhs})) with ({comb}) by field.")
        lines.append(f"  {'rewrite ' + ', '.join(rew.split()) + '. ' if rew else ''}field.")
    else:
        side = " | ".join([f"intro Z0; apply {n}; ring_simplify in Z0; ring_simplify; lra"
                           for n in [p.split(" : ")[0] for p in premises if p.startswith("N")]]
                          + ["lra"])
        lines.append(f"  assert (E : ({D}) * ({lhs} - ({rhs})) = {comb}) by "
                     f"(first [field; repeat split; assumption | "
                     f"field; repeat split; try assumption; solve [{side}]]).")
        if rew:
            lines.append(f"  rewrite {', '.join(rew.split())} in E.")
        lines.append(f"  assert (Z : ({D}) * ({lhs} - ({rhs})) = 0) by (rewrite E; field).")
        lines.append("  apply Rminus_diag_uniq.")
        lines.append("  destruct (Rmult_integral _ _ Z) as [Z1 | Z1]; "
                     "[solve [contradiction | lra] | exact Z1].")
    lines.append("Qed.\n")
    return "\n".join(lines)


def prove(cert: dict, timeout: float = 300) -> tuple[bool, str]:
    """Run ``coqc`` on :func:`coq_file` of ``cert``: ``(proved, message)``; where the
    normal-form file fails (a side condition of ``field`` its tactics do not close: a divisor
    that itself divides, 3.52), the cofactor file in the time left.

    Raises:
        NoProof: no proof to write (see :func:`coq_file`).
        FileNotFoundError: ``coqc`` is not installed (Debian's ``coq`` package).
    """
    coqc = shutil.which("coqc")
    if coqc is None:
        raise FileNotFoundError("coqc not found (apt-get install coq)")
    end = time.monotonic() + timeout
    texts = [coq_file(cert)]
    try:
        other = coq_file(cert, normal_forms=False)
    except NoProof:
        other = texts[0]
    if other != texts[0]:
        texts.append(other)
    for text in texts:
        with tempfile.TemporaryDirectory() as d:
            f = Path(d) / "cert.v"
            f.write_text(text)
            p = subprocess.run([coqc, "-q", str(f)], capture_output=True, text=True, cwd=d,
                               timeout=max(end - time.monotonic(), 1), check=False)
        if p.returncode == 0:
            break
    return p.returncode == 0, (p.stdout + p.stderr).strip()[-2000:]
