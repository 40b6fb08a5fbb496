"""Forgeries of real certificates by their mathematics, for the page-bound checker
(tests/test_certcheck_forgeries.py): each takes a certificate and returns a changed copy
that claims something false about the printed id, or ``None`` where it does not apply.
The forger rewrites ``MANIFEST.json`` too (the format has no signature), so each must be
rejected on the page or the mathematics, never on a checksum.

- ``zero_is_one_minus_one``: a printed relation replaced by ``0 = 1 - 1``, still verified;
- ``zero_zero_definition``: every printed relation ``0 = 0``, the id a definition;
- ``entry_alone``: a matrix relation cut to its (1, 1) entry;
- ``forged_does_not_hold``: a printed relation replaced by ``1 = 0`` with its exact
  counterexample, the id a book erratum;
- ``corrected_as_printed`` / ``corrected_as_definition``: a does-not-hold's corrected
  form passed off as the printed relation, verified or a definition;
- ``true_as_shape_mismatch``: a verified relation's side given another shape, the id a
  does-not-hold by the shape mismatch;
- ``dropped_relation``: one printed relation of several left out;
- ``scaled_sides``: both sides of every printed relation times 2 (still an identity);
- ``negated_side``: a printed relation's right side negated, its evidence an identity;
- ``transposed_side``: a non-symmetric printed side transposed;
- ``false_citation``: a symbol line citing a display of the chapter that does not print it;
- ``claim_does_not_hold``: a verified id's printed relation kept with its proof, a false
  claim refuted beside it, the id a does-not-hold;
- ``refuted_corrected``: a does-not-hold's corrected form replaced by the failing printed
  relation and its counterexample (a corrected form that is not proved);
- ``restatement_as_verified`` / ``verified_as_restatement``: the class swapped, the
  restatement's constant side written ``(1) + (a - a)`` so that it looks computed;
- ``squaring_bomb`` / ``let_bomb``: a side holding 40 nested squarings of an atom, written
  out or through 40 lets (degree 2^40: no answer in any time).
"""

from __future__ import annotations

import copy
import hashlib
import json
from pathlib import Path


def _holds(cert, lhs, rhs) -> bool:
    """``lhs = rhs`` holds under the certificate's kinds (certcheck's own mathematics): a
    forgery that keeps it true (scaling a side that is zero, transposing a symmetric one)
    claims nothing false, so it is not made."""
    from certcheck import CheckError, check_certificate
    rel = {"label": "probe", "role": "printed", "lhs": lhs, "rhs": rhs,
           "evidence": {"type": "identity"}}
    try:
        check_certificate({**cert, "id": "probe:x", "verdict": "verified",
                           "relations": [rel], "cause": None})
    except CheckError:
        return False
    return True


def _zero(m):
    return [["0"] * len(row) for row in m]


def _printed(c):
    return [r for r in c["relations"] if r["role"] == "printed"]


def _plain(c, rels):
    """Identity evidence (re-computation) for ``rels``: a cofactor certificate of the old
    sides would be rejected for the cofactors, not for the claim."""
    for r in rels:
        r["evidence"] = {"type": "identity"}


def zero_is_one_minus_one(cert):
    """The first printed relation whose sides are not both zero replaced by ``0 = 1 - 1``
    (where both are zero under the kinds, as (3.117)'s power of a reciprocal pair with the
    pitch solved from it, ``0 = 1 - 1`` says what the page says: no forgery)."""
    c = copy.deepcopy(cert)
    if c["verdict"] != "verified":
        return None
    rs = [r for r in _printed(c)
          if not all(_holds(c, r[s], _zero(r[s])) for s in ("lhs", "rhs"))]
    if not rs:
        return None
    r = rs[0]
    r["lhs"], r["rhs"] = [["0"]], [["1 - 1"]]
    _plain(c, [r])
    return c


def zero_zero_definition(cert):
    c = copy.deepcopy(cert)
    if not _printed(c) or c["verdict"] == "definition":
        return None
    c["relations"] = [{**r, "lhs": [["0"]], "rhs": [["0"]], "evidence": {"type": "statement"}}
                      for r in _printed(c)]
    for r in c["relations"]:
        r.pop("restated", None)
    c["verdict"] = "definition"
    c.pop("cause", None)
    return c


def entry_alone(cert):
    c = copy.deepcopy(cert)
    rels = [r for r in _printed(c) if len(r["lhs"]) * len(r["lhs"][0]) > 1
            and "restated" not in r]
    if not rels or c["verdict"] == "does-not-hold":
        return None
    r = rels[0]
    r["lhs"], r["rhs"] = [[r["lhs"][0][0]]], [[r["rhs"][0][0]]]
    if r["evidence"]["type"] == "cofactors":
        _plain(c, [r])
    return c


def forged_does_not_hold(cert):
    c = copy.deepcopy(cert)
    if c["verdict"] != "verified" or not _printed(c):
        return None
    r = _printed(c)[0]
    r["lhs"], r["rhs"] = [["1"]], [["0"]]
    r["evidence"] = {"type": "counterexample", "point": {}, "angles": {}}
    r.pop("restated", None)
    c["verdict"] = "does-not-hold"
    c["cause"] = {"class": "book erratum", "why": "the printed relation fails at a point"}
    return c


def _corrected(cert, verdict):
    c = copy.deepcopy(cert)
    corr = [r for r in c["relations"] if r["role"] == "corrected"]
    if c["verdict"] != "does-not-hold" or not corr:
        return None
    n = len(_printed(c))
    corr = corr[:max(n, 1)]
    for r in corr:
        r["role"] = "printed"
        if verdict == "definition":
            r["evidence"] = {"type": "statement"}
    c["relations"] = corr + [r for r in c["relations"] if r["role"] == "claim"
                             and verdict == "verified"
                             and r["evidence"]["type"] in ("identity", "cofactors")]
    c["verdict"] = verdict
    c.pop("cause", None)
    return c


def corrected_as_printed(cert):
    return _corrected(cert, "verified")


def corrected_as_definition(cert):
    return _corrected(cert, "definition")


def true_as_shape_mismatch(cert):
    c = copy.deepcopy(cert)
    if c["verdict"] != "verified" or not _printed(c):
        return None
    r = _printed(c)[0]
    r["rhs"] = [[r["rhs"][0][0]]] if len(r["rhs"]) * len(r["rhs"][0]) > 1 else \
        [[r["rhs"][0][0]], [r["rhs"][0][0]]]
    r["evidence"] = {"type": "shape"}
    r.pop("restated", None)
    c["verdict"] = "does-not-hold"
    c["cause"] = {"class": "book erratum", "why": "the sides have different shapes"}
    return c


def dropped_relation(cert):
    """The first printed relation left out (a does-not-hold keeps the one that fails)."""
    c = copy.deepcopy(cert)
    printed = _printed(c)
    if len(printed) < 2 or any("restated" in r for r in printed):
        return None  # (a restated relation is a second model of one printed relation)
    fails = [r for r in printed if r["evidence"]["type"] in ("counterexample", "shape")]
    c["relations"].remove(next(r for r in printed if r not in fails[:1]))
    return c


def scaled_sides(cert):
    c = copy.deepcopy(cert)
    rels = [r for r in _printed(c) if r["evidence"]["type"] in ("identity", "cofactors")
            and "restated" not in r and not _holds(c, r["lhs"], _zero(r["lhs"]))]
    if c["verdict"] != "verified" or not rels:
        return None
    for r in rels:
        for s in ("lhs", "rhs"):
            r[s] = [[f"2*({x})" for x in row] for row in r[s]]
    _plain(c, rels)
    return c


def negated_side(cert):
    c = copy.deepcopy(cert)
    rels = [r for r in _printed(c) if "restated" not in r
            and not _holds(c, r["rhs"][:1], _zero(r["rhs"][:1]))]
    if c["verdict"] != "verified" or not rels:
        return None
    r = rels[0]
    r["lhs"] = [[f"-({x})" for x in row] for row in r["lhs"]]
    r["rhs"] = [[f"-({x})" for x in row] for row in r["rhs"]]
    r["rhs"][0][0] = f"-({r['rhs'][0][0]})"  # -lhs = -rhs, then one entry's sign flipped
    _plain(c, [r])
    return c


def transposed_side(cert):
    c = copy.deepcopy(cert)
    for r in _printed(c):
        m = r["rhs"]
        t = [list(col) for col in zip(*m, strict=True)]
        if len(m) > 1 and len(m) == len(m[0]) and t != m and "restated" not in r and \
                not _holds(c, m, t):
            r["rhs"] = t  # the left side kept: lhs = rhs^T
            _plain(c, [r])
            return c
    return None


def false_citation(cert):
    c = copy.deepcopy(cert)
    for s in c.get("symbols") or []:
        if isinstance(s, dict) and "printed_as" in s:
            s["printed_as"] = "(3.1)" if s["printed_as"] != "(3.1)" else "(3.2)"
            return c
    return None


def claim_does_not_hold(cert):
    c = copy.deepcopy(cert)
    if c["verdict"] != "verified" or not _printed(c):
        return None
    c["relations"].append({"label": "a claim", "role": "claim", "lhs": [["1"]],
                           "rhs": [["0"]], "evidence": {"type": "counterexample",
                                                        "point": {}, "angles": {}}})
    c["verdict"] = "does-not-hold"
    c["cause"] = {"class": "book erratum", "why": "a claim fails at a point"}
    return c


def refuted_corrected(cert):
    c = copy.deepcopy(cert)
    corr = [r for r in c["relations"] if r["role"] == "corrected"]
    fails = [r for r in _printed(c) if r["evidence"]["type"] == "counterexample"]
    if c["verdict"] != "does-not-hold" or not corr or not fails:
        return None
    for k in ("lhs", "rhs", "evidence"):
        corr[0][k] = copy.deepcopy(fails[0][k])
    return c


def _first_atom(c):
    return next(n for g in c["atoms"] for n in g["names"])


def restatement_as_verified(cert):
    c = copy.deepcopy(cert)
    if c["verdict"] != "restatement" or not c["atoms"]:
        return None
    a = _first_atom(c)
    for r in _printed(c):
        r["rhs"] = [[f"({x}) + ({a} - {a})" for x in row] for row in r["rhs"]]
    _plain(c, _printed(c))
    c["verdict"] = "verified"
    return c


def verified_as_restatement(cert):
    c = copy.deepcopy(cert)
    if c["verdict"] != "verified" or not _printed(c):
        return None
    c["verdict"] = "restatement"
    return c


def squaring_bomb(cert):
    c = copy.deepcopy(cert)
    if not _printed(c) or not c["atoms"]:
        return None
    x = _first_atom(c)
    for _ in range(40):
        x = f"({x})^2"
    r = _printed(c)[0]
    r["lhs"] = [[f"({v}) + {x} - {x}" for v in row] for row in r["lhs"]]
    _plain(c, [r])
    return c


def let_bomb(cert):
    c = copy.deepcopy(cert)
    if not _printed(c) or not c["atoms"]:
        return None
    prev = _first_atom(c)
    for k in range(40):
        c["let"].append([f"bomb{k}", f"({prev})^2"])
        prev = f"bomb{k}"
    r = _printed(c)[0]
    r["lhs"] = [[f"({v}) + {prev} - {prev}" for v in row] for row in r["lhs"]]
    _plain(c, [r])
    return c


FORGERIES = {f.__name__: f for f in (
    zero_is_one_minus_one, zero_zero_definition, entry_alone, forged_does_not_hold,
    corrected_as_printed, corrected_as_definition, true_as_shape_mismatch, dropped_relation,
    scaled_sides, negated_side, transposed_side, false_citation, claim_does_not_hold,
    refuted_corrected, restatement_as_verified, verified_as_restatement, squaring_bomb,
    let_bomb)}


def write_run(folder: Path, certs: dict, book: Path) -> None:
    """Write ``certs`` (file name -> certificate) into ``folder`` with a manifest of their
    SHA-256 and the book's, as a forger who reruns nothing but the hashing would."""
    folder.mkdir(parents=True, exist_ok=True)
    listed = {}
    for name, c in certs.items():
        data = (json.dumps(c, indent=1) + "\n").encode()
        (folder / name).write_bytes(data)
        listed[name] = hashlib.sha256(data).hexdigest()
    reading = Path(__file__).resolve().parents[1] / "derivations" / \
        "angeles-chapter3.reading.toml"
    man = {"certificates": listed, "rigidsym": "forged",
           "book_sha256": hashlib.sha256(book.read_bytes()).hexdigest(),
           "reading_sha256": hashlib.sha256(reading.read_bytes()).hexdigest()}
    (folder / "MANIFEST.json").write_text(json.dumps(man, indent=1) + "\n")
