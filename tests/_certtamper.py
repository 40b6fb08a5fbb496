"""Tamperings of certificates for tests/test_certcheck.py: each returns a
changed copy, or ``None`` where it does not apply. None touches a checksum or a signature
(the format has none): each changes the mathematics, which the checker must reject."""

from __future__ import annotations

import copy
import json
from fractions import Fraction


def _rels(cert, etype):
    kinds = ("identity", "cofactors") if etype == "identity" else (etype,)
    return [r for r in cert["relations"] if r["evidence"]["type"] in kinds]


def changed_coefficient(cert):
    """An identity's lhs entry gets 1/7 added (its value changes by a non-zero constant)."""
    c = copy.deepcopy(cert)
    rels = _rels(c, "identity")
    if not rels:
        return None
    rels[0]["lhs"][0][0] = f"({rels[0]['lhs'][0][0]}) + 1/7"
    return c


def scaled_let(cert):
    """A shared subexpression's integer coefficient changed: its first integer literal
    k becomes k + 1 (not always a change of value; the test keeps those the checker says
    are no longer identities)."""
    import re
    c = copy.deepcopy(cert)
    for let in c["let"]:
        m = re.search(r"(?<![\^\w'])(\d+)(?![\w'])", let[1])
        if m:
            let[1] = let[1][:m.start()] + str(int(m.group(1)) + 1) + let[1][m.end():]
            return c
    return None


def fake_hypothesis(cert):
    """A wrong rhs, with the relation itself offered as a 'hypothesis' field: the checker
    takes its hypotheses from the kinds only."""
    c = changed_coefficient(cert)
    if c is None:
        return None
    c["hypotheses"] = [f"{r['lhs'][0][0]} - ({r['rhs'][0][0]})" for r in c["relations"]]
    c["relations"][0]["evidence"]["hypotheses"] = c["hypotheses"]
    return c


def unknown_kind(cert):
    """A group declared of a kind the checker does not know (a hypothesis it does not
    give)."""
    c = copy.deepcopy(cert)
    if not c["atoms"]:
        return None
    c["atoms"][0]["kind"] = "identity"
    return c


def swapped_side(cert):
    """Two different entries of a matrix side exchanged, or a does-not-hold's failing side
    moved into its corrected form."""
    c = copy.deepcopy(cert)
    fails = _rels(c, "counterexample") + _rels(c, "shape")
    corr = [r for r in c["relations"] if r["role"] == "corrected"]
    if fails and corr and _shape(fails[0]["rhs"]) == _shape(corr[0]["rhs"]) and \
            fails[0]["rhs"] != corr[0]["rhs"] and fails[0]["lhs"] == corr[0]["lhs"]:
        corr[0]["rhs"] = fails[0]["rhs"]
        return c
    for r in _rels(c, "identity"):
        flat = [(i, j) for i, row in enumerate(r["rhs"]) for j in range(len(row))]
        for a in flat:
            for b in flat:
                ra, rb = r["rhs"][a[0]][a[1]], r["rhs"][b[0]][b[1]]
                la, lb = r["lhs"][a[0]][a[1]], r["lhs"][b[0]][b[1]]
                if ra != rb and la != lb and not (la == rb and lb == ra):
                    r["rhs"][a[0]][a[1]], r["rhs"][b[0]][b[1]] = rb, ra
                    return c
    return None


def _shape(m):
    return (len(m), len(m[0]) if m else 0)


def weakened_kinds(cert):
    """Every constrained group (unit vector, rotation, transform) declared as free atoms."""
    c = copy.deepcopy(cert)
    out, changed = [], False
    for g in c["atoms"]:
        if g["kind"] in ("unit", "unit4", "rotation", "transform"):
            changed = True
            out += [{"group": n, "kind": "free", "names": [n], "timed": g["timed"]}
                    for n in g["names"]]
        else:
            out.append(g)
    c["atoms"] = out
    return c if changed else None


def _names(cert, rel):
    """The atom names a relation uses (through the lets it refers to)."""
    import re
    lets = dict(cert["let"])
    todo = [x for row in rel["lhs"] + rel["rhs"] for x in row]
    seen, names = set(), set()
    while todo:
        for n in re.findall(r"[A-Za-z][A-Za-z0-9_.]*'*", todo.pop()):
            if n in lets and n not in seen:
                seen.add(n)
                todo.append(lets[n])
            names.add(n.rstrip("'"))
    return names


def moved_point(cert):
    """A counterexample's (or a cofactor certificate's) values of the constrained atoms the
    relation uses moved by 1/3 (off the constraint set)."""
    c = copy.deepcopy(cert)
    constrained = {n for g in c["atoms"] if g["kind"] in ("unit", "unit4", "rotation",
                                                           "transform") for n in g["names"]}
    for r in _rels(c, "counterexample") + _rels(c, "cofactors"):
        used = constrained & _names(c, r)
        moved = [n for n in sorted(r["evidence"]["point"]) if n.rstrip("'") in used]
        if moved:
            for name in moved:
                v = Fraction(r["evidence"]["point"][name]) + Fraction(1, 3)
                r["evidence"]["point"][name] = str(v)
            return c
    return None


def made_to_agree(cert):
    """A failing member's rhs replaced by its lhs."""
    c = copy.deepcopy(cert)
    rels = _rels(c, "counterexample")
    if not rels:
        return None
    rels[0]["rhs"] = copy.deepcopy(rels[0]["lhs"])
    return c


def zero_denominator(cert):
    """An entry divided by something zero: identically (identity), or at the point
    (counterexample)."""
    c = copy.deepcopy(cert)
    for r in _rels(c, "counterexample"):
        pt = r["evidence"]["point"]
        if pt:
            name = sorted(pt)[0]
            r["lhs"][0][0] = f"({r['lhs'][0][0]}) / ({name} - ({pt[name]}))"
            return c
    rels = _rels(c, "identity")
    if not rels:
        return None
    e = rels[0]["lhs"][0][0]
    rels[0]["lhs"][0][0] = f"({e}) + 1/(({e}) - ({e}))"
    return c


def forged_identity(cert):
    """A does-not-hold's failing member claimed as an identity of a verified statement."""
    c = copy.deepcopy(cert)
    fails = _rels(c, "counterexample") + _rels(c, "shape")
    if not fails:
        return None
    c["verdict"] = "verified"
    c["relations"] = [r for r in c["relations"] if r in fails]
    for r in c["relations"]:
        r["evidence"] = {"type": "identity"}
    return c


def _cofactor_entry(cert):
    """The first cofactor entry with a non-zero cofactor: (entry, index)."""
    for r in _rels(cert, "cofactors"):
        for e in r["evidence"]["entries"]:
            for k, mu in enumerate(e["cofactors"]):
                if mu != "0":
                    return e, k
    return None, None


def dropped_cofactor(cert):
    """A non-zero cofactor set to 0."""
    c = copy.deepcopy(cert)
    e, k = _cofactor_entry(c)
    if e is None:
        return None
    e["cofactors"][k] = "0"
    return c


def altered_cofactor(cert):
    """A non-zero cofactor changed by 1."""
    c = copy.deepcopy(cert)
    e, k = _cofactor_entry(c)
    if e is None:
        return None
    e["cofactors"][k] = f"({e['cofactors'][k]}) + 1"
    return c


def extra_hypothesis(cert):
    """One more cofactor than the kinds give hypotheses (a hypothesis of the certificate's)."""
    c = copy.deepcopy(cert)
    rels = _rels(c, "cofactors")
    if not rels:
        return None
    for e in rels[0]["evidence"]["entries"]:
        e["cofactors"].append("1")
    return c


def zero_D(cert):
    """A cofactor certificate's stated denominator D set to 0."""
    c = copy.deepcopy(cert)
    rels = _rels(c, "cofactors")
    if not rels:
        return None
    for e in rels[0]["evidence"]["entries"]:
        e["denominator"] = "0"
    return c


def claimed_verified(cert):
    """A does-not-hold's verdict changed to verified, its evidence left as it is."""
    if cert["verdict"] != "does-not-hold":
        return None
    c = copy.deepcopy(cert)
    c["verdict"] = "verified"
    return c


#: every tampering, by name
TAMPERINGS = {f.__name__: f for f in (
    changed_coefficient, fake_hypothesis, unknown_kind, swapped_side, weakened_kinds,
    moved_point, made_to_agree, zero_denominator, forged_identity, claimed_verified,
    dropped_cofactor, altered_cofactor, extra_hypothesis, zero_D)}


# ------------------------------------------------------------------ restated relations
# A printed X^{-1} = Y proved as X Y = 1 (the relation's "restated": X, Y as printed):
# certcheck reads X and Y from the page, so each of these must be rejected by its reader
# (tests/test_cert_page.py), never by the mathematics, which none of them changes.
def _restated(cert):
    return [r for r in cert["relations"] if "restated" in r]


def restated_other_y(cert):
    """The restatement's Y doubled: X (2 Y) = 1 is not the printed relation's."""
    c = copy.deepcopy(cert)
    for r in _restated(c):
        r["restated"]["Y"] = f"2({r['restated']['Y']})"
    return c if _restated(c) else None


def restated_swapped(cert):
    """X and Y exchanged: the page prints X^{-1} = Y, not Y^{-1} = X."""
    c = copy.deepcopy(cert)
    for r in _restated(c):
        r["restated"]["X"], r["restated"]["Y"] = r["restated"]["Y"], r["restated"]["X"]
    return c if _restated(c) else None


def restated_scaled(cert):
    """The proved relation 2 X Y = 2 (the same relation, but its sides are not X Y and 1)."""
    c = copy.deepcopy(cert)
    for r in _restated(c):
        for side in ("lhs", "rhs"):
            r[side] = [[f"2*({x})" for x in row] for row in r[side]]
    return c if _restated(c) else None


def restated_elsewhere(cert):
    """The marking moved onto another printed relation of the id (one not proved as X Y =
    1): its sides are then held against X Y and 1."""
    c = copy.deepcopy(cert)
    marked = _restated(c)
    other = [r for r in c["relations"] if r["role"] == "printed" and "restated" not in r]
    if not marked or not other:
        return None
    other[0]["restated"] = marked[0].pop("restated")
    return c


def restated_unmarked(cert):
    """The marking dropped: the page's X^{-1} is then held against the certificate's X Y."""
    c = copy.deepcopy(cert)
    for r in _restated(c):
        del r["restated"]
    return c if c != cert else None


#: the tamperings of a restated relation, by name
RESTATED = {f.__name__: f for f in (restated_other_y, restated_swapped, restated_scaled,
                                    restated_elsewhere, restated_unmarked)}


def roundtrip(cert):
    return json.loads(json.dumps(cert))


def holds_without_constraints(eq_id: str) -> bool:
    """rigidsym's zero test on the id's relations with every constrained atom replaced by a
    free symbol of the same name."""
    import sympy as sp
    from sympy.core.function import AppliedUndef

    from rigidsym.algebra.symbols import constraint_of
    from rigidsym.checking.deciding.explicit import entries_of, explicit
    from rigidsym.registry.declarations import REGISTRY
    from rigidsym.zero.decide import decide_zero

    st = REGISTRY[eq_id].build()
    diffs = []
    for r in st.printed + st.claims:
        for a, b in zip(entries_of(explicit(r.lhs, st.model)), entries_of(explicit(r.rhs,
        st.model)),
                        strict=True):
            d = sp.sympify(a - b)
            free = {x: sp.Symbol(x.name, real=True) for x in d.free_symbols
                    if constraint_of(x) is not None and constraint_of(x).kind != "angle"}
            free.update({f: sp.Function(f.func.__name__, real=True)(*f.args)
                         for f in d.atoms(AppliedUndef) if constraint_of(f) is not None
                         and constraint_of(f).kind != "angle"})
            diffs.append(d.xreplace(free))
    return decide_zero(diffs).zero is True
