"""The transcription check: is a declaration's hand-written ``printed`` form what its LaTeX says?

For one declaration, :func:`check_transcription` parses its ``latex`` (the glyph table of its
section, and its per-id note, the book's data: :func:`notes`) and decides, member by member,
that each printed relation (``Statement.printed``, then ``Statement.claims``) is a relation
the LaTeX states: ``l - r`` equals ``±(E_i - E_j)`` for two expressions ``E_i``, ``E_j`` of
one of the text's ``=`` chains (``x = y = z`` states ``x = y``, ``x = z`` and ``y = z``), or of the
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
from pathlib import Path

import sympy as sp

from rigidsym.core.errors import BadInput
from rigidsym.latex.canonical import definitions, difference, free, roots, same
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.shapes import LatexError
from rigidsym.latex.table import Glyph
from rigidsym.zero import decide_zero

__all__ = ["STATUSES", "check_transcription", "notes", "transcription_words",
           "transcription_for"]

#: the values of a transcription record's ``status``
STATUSES = ("machine-checked", "differs", "not parsed")


@cache
def notes() -> dict:
    """The per-id notes of the transcription check: the book's data (the file its package
    names, ``TRANSCRIPTION_NOTES`` of :data:`rigidsym.core.config.BOOK`).

    Returns:
        ``{id: note}``: how to read one id's LaTeX (instances of a letter that stands for
        several quantities, aliases of the printed names, a lost column separator,
        relations a definition is stated through, a construct the reader does not take);
        ``{}`` where the book names no notes.

    Raises:
        BadInput: the file the book names cannot be read or is not a JSON object.
    """
    import importlib

    from rigidsym.core import config

    path = getattr(importlib.import_module(config.BOOK), "TRANSCRIPTION_NOTES", None)
    if path is None:
        return {}
    try:
        doc = json.loads(Path(path).read_text("utf-8"))
    except (OSError, ValueError) as exc:
        raise BadInput(f"transcription notes {path}: cannot read them ({exc})") from None
    if not isinstance(doc, dict):
        raise BadInput(f"transcription notes {path}: expected a JSON object {{id: note}}")
    return {k: v for k, v in doc.items() if not k.startswith("_")}


def _override(spec: dict, section: str) -> dict:
    out = {}
    for key, value in spec.items():
        name, _, shape = value.partition(":")
        from rigidsym.latex.table import glyph_shape

        kind = "row" if shape.endswith("row") else "instance"
        shape = shape.removesuffix("row").strip()
        out[key] = Glyph(key, section, name, glyph_shape(shape or "scalar"), kind,
                         "per-id note")
    return out


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
                dl, dr = difference(fl, x), difference(fr, y)
                if dl is not None and dr is not None and \
                        decide_zero(roots(dl)).zero and decide_zero(roots(dr)).zero:
                    return plabel + " (side by side: the shapes differ as printed)", None
        return None, None
    last = None
    for plabel, dp in order:
        ok, res = same(dm, dp)
        if ok:
            return plabel, None
        last = last or res
    return None, last


def check_transcription(eq, statement) -> dict:
    """Check one declaration's printed form against its LaTeX.

    Args:
        eq: a registered declaration (:class:`rigidsym.registry.declarations.Equation`).
        statement: its built :class:`~rigidsym.registry.declarations.Statement`.

    Returns:
        The ``transcription`` record: ``{"status": "machine-checked" | "differs" | "not
        parsed", "members": [{"member", "matches"}...], "readings": [...], "note": ...}``
        with, for ``differs``, ``member`` and ``counterexample``; for ``not parsed``,
        ``construct`` and ``why``.
    """
    from rigidsym.core import work as _work

    _work.count("transcribe", eq.id)
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
    defs = dict(definitions(eq.section))
    for name, tex in note.get("defs", {}).items():  # a declaration's own notational atom
        defs[name] = parse_latex(tex, eq.section).chains[0][0]  # "X = ..." gives X
    free_rels, sides = [], []
    for label, a, b in rels:
        fa, fb = free(a, defs, {}), free(b, defs, {})
        d = difference(fa, fb)
        if d is not None:
            free_rels.append((label, d))
        sides.append((label, fa, fb))
    members = [(r.label or f"member {k + 1}", r) for k, r in enumerate(statement.printed)]
    out_members = []
    for k, (label, rel) in enumerate(members):
        fl, fr = free(rel.lhs, defs, aliases), free(rel.rhs, defs, aliases)
        dm = difference(fl, fr)
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


#: records of this process, by (id, key): a report's three files read each once
_DONE: dict[tuple, dict] = {}


def _key(eq_id: str, deps: dict | None = None):
    """``(id, disk key)`` of ``eq_id``'s record, found without building the declaration
    (:func:`rigidsym.checking.verdict_cache.transcription_key`); a declaration that is
    never cached is keyed by its object, so that a replaced one is checked again."""
    from rigidsym.checking.verdict_cache import transcription_key
    from rigidsym.registry.declarations import REGISTRY

    key = transcription_key(eq_id, deps)
    return (eq_id, key) if key else (eq_id, REGISTRY[eq_id])  # held: no id reused


def _path(key: str):
    from rigidsym.core import cache as _cache

    return _cache.folder("verdicts") / key[:2] / f"transcription-{key}.json"


def _wanted(eq_id: str) -> bool:
    from rigidsym.registry.declarations import REGISTRY

    eq = REGISTRY.get(eq_id)  # check --latex: the LaTeX is the printed form itself,
    return eq is not None and bool(eq.latex) and not eq_id.startswith("latex:")  # nothing
    # was transcribed by hand


def cached_transcriptions(ids: list[str], deps: dict | None = None) -> list[str]:
    """Read the stored records of ``ids`` into this process (no declaration is built);
    return the ids that have a record to compute (none stored)."""
    from rigidsym.core import cache as _cache

    todo, deps = [], {} if deps is None else deps
    for i in ids:
        if not _wanted(i):
            continue
        k = _key(i, deps)
        if k in _DONE:
            continue
        data = _cache.get(_path(k[1])) if isinstance(k[1], str) else None
        if data is None:
            todo.append(i)
        else:
            _DONE[k] = json.loads(data)
    return todo


def remember(eq_id: str, record: dict | None) -> None:
    """Keep a record computed elsewhere (a worker of the runner) for this process."""
    if record is not None:
        _DONE[_key(eq_id)] = record


def transcription_for(eq_id: str) -> dict | None:
    """The transcription record of a registered id, through the user cache.

    Args:
        eq_id: a registered id (book or ``namespace:name``).

    Returns:
        The record of :func:`check_transcription`, computed once: kept for the process and
        stored in the user cache under a key found without building the declaration (the
        declaration's source and metadata, the package, sympy's version: a change to the
        repair settings does not recompute it), or ``None`` for an id that is not
        registered or gives no LaTeX. LaTeX that cannot be read gives a ``not parsed``
        record, not an exception.
    """
    from rigidsym.core import cache as _cache
    from rigidsym.registry.declarations import REGISTRY

    if not _wanted(eq_id):
        return None
    k = _key(eq_id)
    hit = _DONE.get(k)
    if hit is None and isinstance(k[1], str):
        data = _cache.get(_path(k[1]))
        hit = None if data is None else json.loads(data)
    if hit is None:
        hit, keep = _computed(REGISTRY[eq_id])
        hit = json.loads(json.dumps(hit))  # as read back: a warm run's record is the same
        if keep and isinstance(k[1], str):
            _cache.put(_path(k[1]), json.dumps(hit).encode())
    _DONE[k] = hit
    return hit


def _computed(eq) -> tuple[dict, bool]:
    """The record of ``eq`` (built here) and whether it may be stored: a declaration or
    reader that fails with anything but :class:`LatexError` gives a ``not parsed`` record
    for this process only (it may be a defect of the run, worth a new look)."""
    try:
        st = eq.build()
        if st.from_latex:  # the printed form is the reader's: nothing hand-written to check
            return {"status": "machine-checked", "readings": [],
                    "members": [{"member": r.label or f"member {k + 1}",
                                 "matches": "read from the LaTeX"}
                                for k, r in enumerate(st.printed)],
                    "note": "the printed form is read from the LaTeX by the reader"}, True
        return check_transcription(eq, st), True
    except LatexError as exc:
        return {"status": "not parsed", "construct": exc.construct, "why": str(exc)}, True
    except Exception as exc:  # noqa: BLE001 -- a reader's declaration the reader cannot
        # take (an unknown sympy object in its printed form) is reported, never fatal
        return {"status": "not parsed", "construct": f"{type(exc).__name__} while reading",
                "why": str(exc)}, False
