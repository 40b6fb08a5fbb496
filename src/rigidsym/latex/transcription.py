"""The transcription check: is a declaration's hand-written ``printed`` form what its LaTeX says?

For one declaration, :func:`check_transcription` parses its ``latex`` (the glyph table of its
section, and its per-id note in ``notes.json``) and decides, member by member, that each
printed relation (``Statement.printed``, then ``Statement.claims``) is a relation the LaTeX
states: ``l - r`` equals ``±(E_i - E_j)`` for two expressions ``E_i``, ``E_j`` of one of the
text's ``=`` chains (``x = y = z`` states ``x = y``, ``x = z`` and ``y = z``), or of the
equivalent product form of an inverse (``X^{-1} = Y`` states ``X Y = 1`` and ``Y X = 1``).
The difference is decided by the zero test (:func:`rigidsym.zero.decide_zero`) with the book
symbols left as free atoms: every book matrix is a matrix of free entries, so nothing the
model knows (orthogonality, skew symmetry) can make a moved sign or a dropped factor agree.
Only notational atoms (a row of the glyph table with a definition: ``E = CPM(e)``, the norm
``‖ω‖``) are replaced by their definitions.

The record (:data:`STATUSES`): ``machine-checked``, ``differs`` (the member and an exact
counterexample) or ``not parsed`` (the construct and why).
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

import sympy as sp

from rigidsym.algebra.symbols import angle
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.shapes import LatexError
from rigidsym.latex.table import Glyph, glyph_table
from rigidsym.zero import decide_zero

__all__ = ["STATUSES", "check_transcription", "notes", "transcription_words",
           "transcription_for"]

#: the values of a transcription record's ``status``
STATUSES = ("machine-checked", "differs", "not parsed")
_ANGLES = ("phi", "theta")


@cache
def notes() -> dict:
    """The per-id notes of the transcription check.

    Returns:
        ``notes.json`` as ``{id: note}``: how to read one id's LaTeX (instances of a letter
        that stands for several quantities, aliases of the printed names, a lost column
        separator, relations a definition is stated through, a construct the reader does
        not take).
    """
    text = resources.files("rigidsym.latex").joinpath("notes.json").read_text("utf-8")
    return {k: v for k, v in json.loads(text).items() if not k.startswith("_")}


def _override(spec: dict, section: str) -> dict:
    out = {}
    for key, value in spec.items():
        name, _, shape = value.partition(":")
        from rigidsym.latex.table import _shape

        kind = "row" if shape.endswith("row") else "instance"
        shape = shape.removesuffix("row").strip()
        out[key] = Glyph(key, section, name, _shape(shape or "scalar"), kind,
                         "per-id note")
    return out


# --------------------------------------------------------------------------- canonical form
def _definitions(section: str) -> dict:
    """Notational atoms of a section: name -> parsed definition."""
    out = {}
    rows = [g for g in glyph_table() if g.definition]
    best: dict = {}
    for g in rows:
        if g.section == "*" or section == g.section or section.startswith(g.section + "."):
            prev = best.get(g.name)
            if prev is None or len(g.section) > len(prev.section):
                best[g.name] = g
    for name, g in best.items():
        p = parse_latex(f"{g.latex} = {g.definition}", section)
        out[name] = p.chains[0][1]
    return out


@cache
def _definitions_cached(section: str) -> dict:
    return _definitions(section)


def _free(x, defs: dict, aliases: dict):
    """The explicit value of ``x`` with book symbols as free atoms (see the module doc)."""
    if not isinstance(x, sp.Basic):
        x = sp.sympify(x)
    for _ in range(3):  # notational atoms may refer to one another
        swap = {}
        for s in x.atoms(sp.MatrixSymbol, sp.Symbol):
            name = aliases.get(s.name, s.name)
            if name in defs and defs[name] is not s:
                swap[s] = defs[name]
            elif name.startswith("norm_"):
                swap[s] = _norm(name[5:], defs)
            elif name != s.name:
                swap[s] = (sp.MatrixSymbol(name, *s.shape) if isinstance(s, sp.MatrixSymbol)
                           else sp.Symbol(name, real=True))
        if not swap:
            break
        x = x.xreplace(swap)
    # an inverse stays an atom of its own, keyed by what it inverts (never expanded)
    for inv in sorted(x.atoms(sp.Inverse), key=lambda v: len(str(v))):
        key = "inv(" + sp.srepr(inv.arg) + ")"
        x = x.xreplace({inv: sp.MatrixSymbol(f"inv{abs(hash(key)) % 10**8}", *inv.shape)})
    for p in sorted(x.atoms(sp.MatPow), key=lambda v: len(str(v))):
        if p.exp == -1:
            key = "inv(" + sp.srepr(p.base) + ")"
            x = x.xreplace({p: sp.MatrixSymbol(f"inv{abs(hash(key)) % 10**8}", *p.shape)})
    # the determinant of a larger matrix stays an atom too (a 6 x 6 of free entries expands
    # to 720 terms); keyed by its argument, so det(U) in both forms is one atom
    from rigidsym.algebra.operators import Det

    for d in sorted(x.atoms(Det, sp.Determinant), key=lambda v: len(str(v))):
        if d.args[0].shape[0] > 3:
            key = "det(" + sp.srepr(d.args[0]) + ")"
            x = x.xreplace({d: sp.Symbol(f"det{abs(hash(key)) % 10**8}", real=True)})
    atoms = {}
    for s in x.atoms(sp.MatrixSymbol):
        atoms[s] = sp.ImmutableMatrix(*s.shape, lambda i, j, n=s.name:
                                      sp.Symbol(f"{n}[{i},{j}]", real=True))
    for s in x.atoms(sp.Symbol):
        if isinstance(s, sp.Dummy) or s in atoms:
            continue
        atoms[s] = angle(s.name) if s.name in _ANGLES else sp.Symbol(s.name, real=True)
    x = x.xreplace(atoms)
    x = x.doit() if hasattr(x, "doit") else x
    while x.atoms(sp.Trace):  # a trace over a mixed product stays lazy after doit
        tr = min(x.atoms(sp.Trace), key=lambda v: len(str(v)))
        x = x.xreplace({tr: sp.Matrix(tr.arg.doit().as_explicit()).trace()})
    if isinstance(x, sp.MatrixExpr | sp.MatrixBase):
        x = sp.Matrix(x.as_explicit() if isinstance(x, sp.MatrixExpr) else x)
        x = x.applyfunc(lambda e: e.doit())
    return x


def _norm(name: str, defs: dict):
    v = sp.MatrixSymbol({"p21": "p_2"}.get(name, name), 3, 1)
    if name == "p21":
        v = sp.MatrixSymbol("p_2", 3, 1) - sp.MatrixSymbol("p_1", 3, 1)
    return sp.sqrt((v.T * v)[0, 0])


def _roots(entries: list) -> list:
    """Odd powers of square roots -> powers of a free positive atom per radicand (exact for
    deciding zero: an identity in a free atom holds at its value)."""
    atoms: dict = {}

    def rep(e):
        for p in sorted(e.atoms(sp.Pow), key=sp.count_ops, reverse=True):
            if p.exp.is_Rational and p.exp.q == 2 and p in e.atoms(sp.Pow):
                r = atoms.setdefault(p.base, sp.Symbol(f"root{len(atoms)}", positive=True))
                e = e.xreplace({p: r ** int(p.exp * 2)})
        return e

    return [rep(e) for e in entries]


def _difference(l, r):
    """``l - r`` as a list of entries, or ``None`` when the shapes differ."""
    def shape(v):
        return (v.rows, v.cols) if isinstance(v, sp.MatrixBase) else (1, 1)

    if not isinstance(l, sp.MatrixBase) and l == 0 and isinstance(r, sp.MatrixBase):
        l = sp.zeros(*r.shape)
    if not isinstance(r, sp.MatrixBase) and r == 0 and isinstance(l, sp.MatrixBase):
        r = sp.zeros(*l.shape)
    if shape(l) != shape(r):
        return None
    lv = list(l) if isinstance(l, sp.MatrixBase) else [l]
    rv = list(r) if isinstance(r, sp.MatrixBase) else [r]
    return [a - b for a, b in zip(lv, rv, strict=True)]


def _same(dm: list, dp: list) -> tuple[bool | None, object]:
    """Whether ``dm = dp`` or ``dm = -dp`` identically (zero test), with the result."""
    if len(dm) != len(dp):
        return False, None
    best = None
    for sign in (1, -1):
        res = decide_zero(_roots([a - sign * b for a, b in zip(dm, dp, strict=True)]))
        if res.zero:
            return True, res
        best = best or res
    return False, best


# --------------------------------------------------------------------------- the check
def _parsed_relations(eq, note: dict):
    """Every relation the text states: ``(label, E_i, E_j)``."""
    instances = note.get("instances") or [{}]
    out = []
    readings: list[str] = []
    for _k, inst in enumerate(instances):
        p = parse_latex(eq.latex, eq.section, overrides=_override(inst, eq.section),
                        block_rows=bool(note.get("block_rows")))
        readings += [r for r in p.readings if r not in readings]
        names = ", ".join(a + "=" + b.split(":")[0] for a, b in inst.items())
        tag = f" ({names})" if inst else ""
        for c, i, j, a, b in p.pairs():
            out.append((f"chain {c + 1}: {i + 1} = {j + 1}{tag}", a, b))
            for x, y in ((a, b), (b, a)):  # X^{-1} = Y states X Y = 1 and Y X = 1
                if isinstance(x, sp.Inverse):
                    m = x.arg
                    out.append((f"chain {c + 1}: {i + 1} = {j + 1}{tag} as a product",
                                m * y, sp.Identity(m.shape[0])))
                    out.append((f"chain {c + 1}: {i + 1} = {j + 1}{tag} as a product",
                                y * m, sp.Identity(m.shape[0])))
        for via in note.get("via", []):
            q = parse_latex(via, eq.section, overrides=_override(inst, eq.section))
            defs = {}
            for exprs in p.chains:  # X := its definiens, in the via relation
                head = exprs[0]
                if isinstance(head, sp.MatrixSymbol | sp.Symbol):
                    defs[head] = exprs[-1]
            for _c, _i, _j, a, b in q.pairs():
                out.append((f"via {via}", a.xreplace(defs) if isinstance(a, sp.Basic) else a,
                            b.xreplace(defs) if isinstance(b, sp.Basic) else b))
    return out, readings


def _match(fl, fr, dm, order, sides):
    """The parsed relation a printed member (free sides ``fl``, ``fr``, difference ``dm``)
    equals, and the last zero-test result tried; ``order`` tries the member's own position
    first (members pair in order)."""
    if dm is not None and all(x == 0 for x in dm):
        # a restatement of a notational atom's definition (R = CPM(r)): it says nothing
        # beyond the glyph table
        return "a definition of the glyph table", None
    if dm is None:  # a relation whose sides' shapes differ, as printed: side by side
        for plabel, fa, fb in sides:
            for x, y in ((fa, fb), (fb, fa)):
                dl, dr = _difference(fl, x), _difference(fr, y)
                if dl is not None and dr is not None and \
                        decide_zero(_roots(dl)).zero and decide_zero(_roots(dr)).zero:
                    return plabel + " (side by side: the shapes differ as printed)", None
        return None, None
    last = None
    for plabel, dp in order:
        ok, res = _same(dm, dp)
        if ok:
            return plabel, None
        last = last or res
    return None, last


def check_transcription(eq, statement) -> dict:
    """Check one declaration's printed form against its LaTeX.

    Args:
        eq: a registered declaration (:class:`rigidsym.checking.deciding.registry.Equation`).
        statement: its built :class:`~rigidsym.checking.deciding.registry.Statement`.

    Returns:
        The ``transcription`` record: ``{"status": "machine-checked" | "differs" | "not
        parsed", "members": [{"member", "matches"}...], "readings": [...], "note": ...}``
        with, for ``differs``, ``member`` and ``counterexample``; for ``not parsed``,
        ``construct`` and ``why``.
    """
    note = notes().get(eq.id, {})
    if not eq.latex:
        return {"status": "not parsed", "construct": "no LaTeX",
                "why": "the declaration gives no latex="}
    if note.get("not_parsed"):
        return {"status": "not parsed", "construct": note["not_parsed"],
                "why": note.get("why", "")}
    try:
        rels, readings = _parsed_relations(eq, note)
    except LatexError as exc:
        construct = exc.construct
        if eq.kind == "claim" and construct == "syntax":
            construct = "prose (a theorem or claim stated in words)"
        elif "\\int" in construct:
            construct = "an integral over the body (∫ over B; declared as a point-mass sum)"
        return {"status": "not parsed", "construct": construct,
                "why": str(exc).splitlines()[0]}
    aliases = note.get("aliases", {})
    defs = dict(_definitions_cached(eq.section))
    for name, tex in note.get("defs", {}).items():  # a declaration's own notational atom
        defs[name] = parse_latex(tex, eq.section).chains[0][0]  # "X = ..." gives X
    free_rels, sides = [], []
    for label, a, b in rels:
        fa, fb = _free(a, defs, {}), _free(b, defs, {})
        d = _difference(fa, fb)
        if d is not None:
            free_rels.append((label, d))
        sides.append((label, fa, fb))
    members = [(r.label or f"member {k + 1}", r) for k, r in enumerate(statement.printed)]
    out_members = []
    for k, (label, rel) in enumerate(members):
        fl, fr = _free(rel.lhs, defs, aliases), _free(rel.rhs, defs, aliases)
        dm = _difference(fl, fr)
        found, last = _match(fl, fr, dm, free_rels[k:] + free_rels[:k], sides)
        if found is None:
            rec = {"status": "differs", "member": label, "members": out_members,
                   "readings": readings,
                   "why": ("shapes differ from every relation of the LaTeX" if dm is None
                           else "no relation of the LaTeX equals this member")}
            if last is not None and last.witness:
                rec["counterexample"] = {str(k2): str(v) for k2, v in last.witness.items()}
            return rec
        out_members.append({"member": label, "matches": found})
    rec = {"status": "machine-checked", "members": out_members, "readings": readings}
    if note.get("why"):
        rec["note"] = note["why"]
    return rec


def transcription_words(t: dict | None) -> str:
    """The transcription record in words, for the reports.

    Args:
        t: a transcription record, or ``None``.

    Returns:
        ``"transcription machine-checked"``, ``"transcription differs: MEMBER (why)"``,
        ``"transcription not parsed: CONSTRUCT"``, or ``""`` for ``None``.
    """
    if not t:
        return ""
    if t["status"] == "machine-checked":
        return "transcription machine-checked"
    if t["status"] == "differs":
        return f"transcription differs: {t.get('member', '')} ({t.get('why', '')})"
    return f"transcription not parsed: {t.get('construct', '')}"


_DONE: dict[str, dict] = {}


def transcription_for(eq_id: str) -> dict | None:
    """The transcription record of a registered id, through the user cache.

    Args:
        eq_id: a registered id (book or ``namespace:name``).

    Returns:
        The record of :func:`check_transcription` (computed once per process and stored in
        the user cache, keyed by the declaration), or ``None`` for an id that is not
        registered or gives no LaTeX. LaTeX that cannot be read gives a ``not parsed``
        record, not an exception.
    """
    from rigidsym.checking.deciding.registry import REGISTRY

    eq = REGISTRY.get(eq_id)
    if eq is None or not eq.latex or eq_id.startswith("latex:"):  # check --latex: the
        return None  # LaTeX is the printed form itself, nothing was transcribed by hand
    hit = _DONE.get(eq_id)
    if hit is None:
        st = eq.build()
        if st.from_latex:  # the printed form is the reader's: nothing hand-written to check
            return {"status": "machine-checked", "readings": [],
                    "members": [{"member": r.label or f"member {k + 1}",
                                 "matches": "read from the LaTeX"}
                                for k, r in enumerate(st.printed)],
                    "note": "the printed form is read from the LaTeX by the reader"}
        hit = _DONE[eq_id] = _cached(eq, eq.build())
    return hit


@cache
def _sources() -> str:
    """What a transcription record depends on besides the declaration: the reader's data
    and code, and sympy's version."""
    pkg = resources.files("rigidsym.latex")
    names = ("grammar.lark", "glyphs.csv", "notes.json", "lexing.py", "parser.py", "reader.py",
             "shapes.py", "table.py", "transcription.py")
    return sp.__version__ + "".join(pkg.joinpath(n).read_text("utf-8") for n in names)


def _cached(eq, statement) -> dict:
    """:func:`check_transcription` through the user cache (``verdicts/``), keyed by the
    declaration's LaTeX, section and printed members (``srepr``) and :func:`_sources`: a
    changed declaration, table, note or reader is checked again."""
    from rigidsym import _cache

    key = json.dumps([eq.id, eq.latex, eq.section, _sources(),
                      [[sp.srepr(r.lhs), sp.srepr(r.rhs), r.label] for r in statement.printed]])
    path = _cache.folder("verdicts") / f"transcription-{_cache.digest(key.encode())}.json"
    data = _cache.get(path)
    if data is not None:
        return json.loads(data)
    rec = check_transcription(eq, statement)
    _cache.put(path, json.dumps(rec).encode())
    return rec
