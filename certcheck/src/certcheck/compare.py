"""certcheck's comparison: each printed side read (:func:`certcheck.reader.read_relations`)
is held to the certificate's as a rational function under the kinds' hypotheses
(:func:`certcheck.check.check_identity`): one read firmly that differs is a rejection, one
matched through an equation of the page or one of several models is NOT READ when it
differs. ``X^{-1} = Y`` marked ``restated`` (proved as ``X Y = 1``) is read as X and Y;
``\\underbrace{X}_{Y}`` as ``X = Y`` where the page prints a relation under it
(:mod:`certcheck.braces`)."""

from __future__ import annotations

import itertools
import json
import re
from itertools import accumulate

from certcheck.alternatives import read_alternatives
from certcheck.arrays import M, mul
from certcheck.braces import brace_relations
from certcheck.reader import NotRead, read_relations, tokens

__all__ = ["compare"]


def compare(cert: dict, page: str, fast: bool = True, defs: dict | None = None,
            counts: list | None = None, later: str = "",
            read_sides: list | None = None) -> list[str]:
    """Read ``page`` under the certificate's symbol table and check that each printed
    relation of the certificate is the printed one: each side the reader reads is the
    certificate's side as a rational function under the kinds' hypotheses. ``defs``
    (:func:`certcheck.book.definitions_before`): glyphs outside the table are read through
    their printed definitions above the id, each cited. ``counts``: ``(sides read,
    printed sides, the relations read firmly on both sides)`` appended to it. ``later``:
    the book's displays after the id (:func:`certcheck.braces.displays_after`).
    ``read_sides``: for each relation read firmly on both sides, ``(relation, the page's
    lhs rows, the page's rhs rows, the lets the reader named)`` appended to it, so that
    what the page's relation is (a restatement, say) is decided from the page.

    Returns:
        Lines for the referee: what was read, and what was not (a finding, never a pass).

    Raises:
        certcheck.check.CheckError: a side read differs from the certificate's.
    """
    from certcheck.check import CheckError, Statement, check_identity

    symbols, counts = cert.get("symbols") or [], [] if counts is None else counts
    kinds = {g.get("group"): g.get("kind") for g in cert.get("atoms", [])}
    for e in symbols:  # the table's kinds are the certificate's groups' kinds
        for a in e.get("atoms", []) if isinstance(e, dict) else []:
            group = next((g for g in cert.get("atoms", [])
                          if a.rstrip("'") in g.get("names", [])), None)
            if group is None or e.get("kind") != group.get("kind"):
                raise CheckError(f"({cert.get('id')}) symbol {e.get('glyph')}: declared "
                                 f"{e.get('kind')!r}, its atom {a} is of kind "
                                 f"{kinds.get((group or {}).get('group'))!r}")
    printed = [r for r in cert.get("relations", []) if r.get("role") == "printed"]
    for r in sorted((r for r in cert.get("relations", []) if r.get("role") == "claim"
                     and isinstance(r.get("page"), int)), key=lambda r: r["page"]):
        printed.insert(r["page"] - 1, r)  # a chain's member the page prints, proved as a claim
    if not printed:  # a theorem in words, proved by its claims: nothing read on the page
        counts.append((0, 2 * max(1, len(cert["relations"])), []))
        return [f"NOT READ: stated in words only (no relation printed, no entry for them in "
                f"the reading's theorems in words): the {len(cert['relations'])} claim(s), each"
                " proved, are the certificate's reading of the words, a referee's to judge"]
    here = {part.partition("\\equiv")[0].replace(" ", "").strip("&")  # G defined here
            for part in re.split(r",\s*\\quad", page) if "\\equiv" in part}
    defs = {k: v for k, v in (defs or {}).items() if k not in here}  # not an earlier G's
    try:
        sides = read_relations(page, symbols, defs, lets := [])
        sides = read_alternatives(page, printed, symbols, defs, lets, read_relations) or sides
        if len(sides) == 1 and printed and all(r.get("symbols") for r in printed):  # F = N,
            sides = [read_relations(page, [*symbols, *r["symbols"]], defs, lets)[0]  # L or H:
                     for r in printed]  # each member read under its own lines (its F)
    except (NotRead, ValueError) as exc:  # ValueError: an alternative's lines (units)
        raise CheckError(f"({cert.get('id')}) the symbol table: {exc}") from None
    held = cert.get("verdict") != "does-not-hold"  # a = b = c: a is b, where a = b holds
    pairs = [(c[0] if k == 1 or not held or not isinstance(c[0][0], NotRead) else
              (c[1][0], c[1][1], [*c[1][2], "the chain's second member"]), c[k])
             for c in sides for k in range(1, len(c))]
    pairs += [(c[0], c[1]) for x in brace_relations(page, symbols, defs, later)  # the page's
              for c in read_relations(x, symbols, defs, lets)]  # braces (one may fail)
    # one printed relation under several models (a restatement is not another model)
    soft = len(pairs) == 1 and len([r for r in printed if "restated" not in r]) > 1
    pairs = pairs * len(printed) if len(pairs) == 1 and len(printed) > 1 else pairs
    if len(pairs) > len(printed) and cert.get("verdict") != "does-not-hold":  # one fails
        raise CheckError(f"({cert.get('id')}) the page prints {len(pairs)} relation(s), the "
                         f"certificate proves {len(printed)}: a printed relation is missing "
                         "or one not printed is added")
    if len(pairs) > len(printed) == 1 and not held:  # the chain's member that fails:
        agree = [p for q in pairs for p in (q, q[::-1]) if _agrees(cert, printed[0], p, lets,
                                                                  fast)][:1]  # a = b, b = a
        if not agree and not any(isinstance(m, NotRead) for p in pairs for m, _, _ in p):
            raise CheckError(f"({cert.get('id')}) no member of the page's chain, each read, "
                             "is the certificate's printed relation")
        pairs = agree or pairs
    if len(pairs) != len(printed):
        counts.append((0, 2 * len(printed), []))
        return [f"NOT READ: {len(pairs)} printed relation(s) on the page, the certificate "
                f"has {len(printed)} (a family the reader does not match); each relation is "
                "the certificate's word"]
    for k, rel in enumerate(printed):  # X^{-1} = Y proved as X Y = 1: X, Y read
        if "restated" in rel:
            pairs[k] = _restated(cert, rel, page, symbols, defs, lets)
    out = [f"relation {k + 1} restated: the printed X^{{-1}} = Y proved as X Y = 1, X and Y"
           " read from the page" for k, r in enumerate(printed) if "restated" in r]
    for k, rel in enumerate(printed if not held else []):  # a side that is no array
        for j, s in enumerate(("lhs", "rhs")):
            if (v := _no_array(cert, rel, s, pairs[k][j][0], pairs[k][1 - j][0])) is not None:
                pairs[k] = (v, pairs[k][1]) if j == 0 else (pairs[k][0], v)

    def probe(rels: list) -> Statement:  # the sides read, as relations of the certificate's
        return Statement({**cert, "verdict": "verified", "relations": rels,
                          "let": [*cert.get("let", []), *lets]})
    batch = [{"label": f"page {s}", "role": "printed", "lhs": m.rows, "rhs": rel[s],
              "evidence": {"type": "identity"}} for rel, pair in zip(printed, pairs, strict=True)
             for s, (m, _, _) in (("lhs", pair[0]), ("rhs", pair[1]))
             if not isinstance(m, NotRead) and m.shape == (len(rel[s]), len(rel[s][0]))]
    try:  # every side at once (the lets evaluated once); one that differs: side by side
        whole = bool(check_identity(st := probe(batch), st.rels, fast))
    except CheckError:
        whole = False
    n_read, firm = 0, []  # firm: the relations whose two sides are read firmly
    for k, rel in enumerate(printed):
        read, matched = [], []
        for side, (mine, assumed, cited) in (("lhs", pairs[k][0]), ("rhs", pairs[k][1])):
            if isinstance(mine, NotRead):
                out.append(f"NOT READ: relation {k + 1}'s {side} ({mine}); the certificate's "
                           "word")
                continue
            theirs = rel[side]
            if soft and mine.shape != (len(theirs), len(theirs[0])):
                out.append(f"NOT READ: relation {k + 1}'s {side} (the printed relation's "
                           f"shape is not this model's); the certificate's word")
                continue
            o = pairs[k][side == "lhs"]  # a bare 0 or 1: the size of the page's other side
            if assumed and rel.get("evidence", {}).get("type") == "shape":
                raise CheckError(f"({cert.get('id')}) printed {side} of relation {k + 1}: a "
                                 "shape mismatch claimed, but the page's side is a bare 1, O "
                                 "or 0 (or sized by one), which takes its other side's size")
            if assumed and None is not _unit_of(mine.rows) == _unit_of(theirs) and not o[1] \
                    and getattr(o[0], "shape", 0) == (len(theirs), len(theirs[0])):
                mine = M(theirs)
            if assumed and _unit_of(mine.rows) and (len(theirs), len(theirs[0])) == (1, 1):
                raise CheckError(f"({cert.get('id')}) printed {side} of relation {k + 1}: a "
                                 "bold 1, O or 0 (an array), the certificate's a scalar")
            if assumed and isinstance(o[0], NotRead) and mine.shape != (len(theirs), len(
                    theirs[0])):  # a bare 0 or 1 whose size the other side would give
                out.append(f"NOT READ: relation {k + 1}'s {side} (a bare 0 or 1 of a size "
                           "the page's other side, not read, would give); the certificate's")
                continue
            if mine.shape != (len(theirs), len(theirs[0])):  # a 1, O or 0 sized so too
                raise CheckError(f"({cert.get('id')}) printed {side} {rel.get('label', '')}: "
                                 f"the page's reads {mine.shape[0]}x{mine.shape[1]}, the "
                                 f"certificate's {len(theirs)}x{len(theirs[0])}")
            try:
                if not whole:
                    check_identity(st := probe([{"label": f"page {side}", "role": "printed",
                                                 "lhs": mine.rows, "rhs": theirs,
                                                 "evidence": {"type": "identity"}}]),
                                   st.rels, fast)
            except CheckError as exc:
                if soft or any(c.endswith("an equation") for c in cited):
                    out.append(f"NOT READ: relation {k + 1}'s {side} (read "
                               + (f"through {', '.join(dict.fromkeys(cited))}" if cited
                                  else "as one of the certificate's models")
                               + ", it differs: the model's glyph or relation may be another"
                               "); the certificate's word")
                    continue
                raise CheckError(f"({cert.get('id')}) the printed {side} of relation {k + 1} is "
                                 f"not the certificate's: {exc}") from None
            tentative = soft or any(c.endswith("an equation") for c in cited)
            (matched if tentative else read).append(
                side + (f" (through {', '.join(dict.fromkeys(cited))})" if cited else ""))
        n_read, firm = n_read + len(read) + len(matched), firm + [rel] * (len(read) == 2)
        if len(read) == 2 and read_sides is not None:
            read_sides.append((rel, pairs[k][0][0].rows, pairs[k][1][0].rows, list(lets)))
        if read:
            out.append(f"read from the page: relation {k + 1}'s {' and '.join(read)}, the "
                       "certificate's under the symbol table")
        if matched:  # a difference here would be NOT READ, not a rejection
            out.append(f"matched on the page: relation {k + 1}'s {' and '.join(matched)}, "
                       "the certificate's" + (" under one of its models" if soft else ""))
    counts.append((n_read, 2 * len(printed), firm))
    return out


def _agrees(cert: dict, rel: dict, pair: tuple, lets: list, fast: bool) -> bool:
    """Both sides of ``pair`` (a member of the page's chain) read firmly and are ``rel``'s."""
    from certcheck.check import CheckError, Statement, check_identity
    if any(isinstance(m, NotRead) or m.shape != (len(rel[s]), len(rel[s][0])) or
           any(c.endswith("an equation") for c in cited)
           for s, (m, _, cited) in zip(("lhs", "rhs"), pair, strict=True)):
        return False
    st = Statement({**cert, "verdict": "verified", "let": [*cert.get("let", []), *lets],
                    "relations": [{"label": "member", "role": "printed", "lhs": m.rows,
                                   "rhs": rel[s], "evidence": {"type": "identity"}}
                                  for s, (m, _, _) in zip(("lhs", "rhs"), pair, strict=True)]})
    try:
        return bool(check_identity(st, st.rels, fast))
    except CheckError:
        return False


def _unit_of(rows: list) -> str | None:
    """``"0"`` for a zero matrix, ``"1"`` for an identity (entries as written), else None."""
    t = [[str(x).replace(" ", "") for x in row] for row in rows]
    if all(x == "0" for row in t for x in row):
        return "0"
    eye = all(x == ("1" if i == j else "0") for i, row in enumerate(t) for j, x in enumerate(row))
    return "1" if eye and len(t) == len(t[0]) else None


def _restated(cert: dict, rel: dict, page: str, symbols: list, defs: dict, lets: list):
    """The sides (X Y, 1) of a printed ``X^{-1} = Y`` proved as ``X Y = 1`` (``restated``:
    X, Y as printed), X and Y read from the page, square. Raises CheckError: the marking is
    not the printed relation's restatement."""
    from certcheck.check import CheckError
    r, who = rel["restated"], f"({cert.get('id')}) relation {rel.get('label') or ''}"
    x, y = str(r.get("X", "")), str(r.get("Y", ""))
    t, depth = tokens(x), list(accumulate((c == "(") - (c == ")") for c in tokens(x)))
    whole = len(t) == 4 and t[0] in ("\\mathbf", "\\boldsymbol") or t[:1] == ["("] and \
        0 not in depth[:-1] and depth[-1] == 0  # a glyph, or one bracket: X^{-1} is X's
    if (r.get("printed"), r.get("proved")) != ("X^{-1} = Y", "X Y = 1") or not whole or \
            tokens(page.rstrip(",. ")) != tokens(f"{x}^{{-1}} = {y}"):
        raise CheckError(f"{who}: restated as {r.get('proved')!r} of X = {x!r}, Y = {y!r}, "
                         f"which is not the printed relation's restatement")
    (a, b), = read_relations(f"{x} = {y}", symbols, defs, lets)
    if (why := next((v[0] for v in (a, b) if isinstance(v[0], NotRead)), None)) is not None:
        return (why, False, []), (why, False, [])  # X or Y not read: nor is X Y
    n = a[0].shape[0]
    if a[0].shape != (n, n) or b[0].shape != (n, n):
        raise CheckError(f"{who}: X Y = 1 of shapes {a[0].shape}, {b[0].shape} does not make "
                         "Y the inverse of X")
    one = M([[str(int(i == j)) for j in range(n)] for i in range(n)])
    return (mul(a[0], b[0]), a[1] or b[1], a[2] + b[2]), (one, False, [])


def _no_array(cert: dict, rel: dict, s: str, e, other) -> tuple | None:
    """A does-not-hold's printed side that is no array (NotRead with the ``blocks`` of the
    side's block matrix), read as ``rel[s]``: one block read has another shape than its slot
    (sized by the other blocks and the page's other side, read), the certificate's entries
    there distinct free atoms found nowhere else (relation, lets, page's glyphs), every other
    block the page's."""
    n, theirs, found = (len(rel[s]), len(rel[s][0])), rel[s], []
    if not getattr(e, "blocks", None) or getattr(other, "shape", 0) != n:
        return None
    cells = {(i, k): b for i, r in enumerate(e.blocks) for k, b in enumerate(r)}
    page = {a for x in cert.get("symbols") or [] for a in x.get("atoms", []) if a != x["glyph"]}
    free = {a for g in cert["atoms"] if g.get("kind") == "free" for a in g["names"]} - page
    text = json.dumps([rel["lhs"], rel["rhs"], cert.get("let")])
    for hole in [c for c, b in cells.items() if isinstance(b, M)]:
        hs, ws = ([next((b.shape[d] for c, b in cells.items() if c[d] == x and c != hole and
                         isinstance(b, M)), None) for x in range(1 + max(c[d] for c in cells))]
                  for d in (0, 1))
        for xs, total in ((hs, n[0]), (ws, n[1])):
            xs[:] = [total - sum(filter(None, xs)) if x is None and xs.count(None) == 1 else x
                     for x in xs]
        if None in hs + ws or min(hs + ws) < 1 or (sum(hs), sum(ws)) != n or \
                len(cells) != len(hs) * len(ws) or any(isinstance(b, M) and (b.shape == (
                    hs[c[0]], ws[c[1]])) == (c == hole) for c, b in cells.items()):
            continue
        v = [list(r) for r in theirs]  # the slot keeps the certificate's entries, if fresh
        fresh = [v[sum(hs[:hole[0]]) + a][sum(ws[:hole[1]]) + b] for a in range(hs[hole[0]])
                 for b in range(ws[hole[1]])]
        if len(set(fresh)) < len(fresh) or any(x not in free or len(re.findall(
                rf"(?<![\w']){re.escape(x)}(?![\w'])", text)) != 1 for x in fresh):
            continue
        for (i, k), b in cells.items():
            for a, c in itertools.product(range(hs[i]), range(ws[k])) if (i, k) != hole else ():
                v[sum(hs[:i]) + a][sum(ws[:k]) + c] = b.rows[a][c] if isinstance(b, M) else \
                    str(int(b == "1" and a == c))
        found.append(M(v))
    return (found[0], False, ["no array as printed (a block of another shape than its slot),"
                              " its slot the certificate's fresh entries"]) if found[1:] == [] \
        and found else None
