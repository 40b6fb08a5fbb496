"""Certificates of verdicts: each decided id written as a statement and its
evidence, in the format of ``docs/certificates.md``, for the independent checker
``certcheck/`` (standard library only; it never imports rigidsym or sympy).

The statement is the id's relations with the model substituted (the same entries the zero
test decides), printed in a small grammar (``+ - * /``, integer powers, integers, names,
``cos``/``sin`` of rational combinations of declared angles and ``pi``) with every shared
subexpression written once as a ``let`` (:mod:`rigidsym.checking.certifying.statement`); the atoms
are declared with their kinds, whose hypotheses the checker generates itself. The evidence by
verdict:

- verified: every printed member and claim an ``identity`` (the checker re-computes it
  with its own parametrisations);
- does-not-hold: the first failing member with a ``shape`` mismatch or an exact
  ``counterexample`` point (atoms, jets, ``tan(phi / 2M)``), and the corrected form, when
  there is one, as identities;
- definition: the printed form as a ``statement``, the claims as identities;
- restatement: a verified id whose printed relations derive nothing (:func:`constants_only`
  on both sides of each: 3.30's ``det U = 1`` expanded), its evidence a verified one's.

An id whose entries leave the grammar (``acos``, ``atan2``, square roots, floats) gets no
certificate; :func:`write_certificates` says which and why.
"""

from __future__ import annotations

import json
import re
from contextlib import suppress
from fractions import Fraction
from pathlib import Path

import sympy as sp

from rigidsym.checking.certifying import reading_table
from rigidsym.checking.certifying.for_every import for_every_evidence
from rigidsym.checking.certifying.reading_table import id_lets, reading_of
from rigidsym.checking.certifying.statement import StatementPrinter, Unprintable, relation_record
from rigidsym.checking.deciding.evidence import small_witness
from rigidsym.checking.deciding.explicit import (
    EXPLICIT_CACHE,
    derived_sides,
    entries_of,
    explicit,
    same_text,
    shape_of,
)
from rigidsym.core.files import write_atomic
from rigidsym.reading import Reading
from rigidsym.registry.declarations import REGISTRY, book_reading, is_user_id
from rigidsym.zero.decide import Unsupported, decide_zero, evaluate, make_plan

__all__ = ["FORMAT", "VERSION", "Unprintable", "certificate", "certificate_or_reason",
           "write_certificates", "certificate_file", "recheck_folder", "write_manifest",
           "cause_record", "CAUSE_CLASSES", "symbol_table", "page_reading", "reading_for"]

FORMAT = "rigidsym-certificate"
VERSION = 1


def certificate_file(eq_id: str) -> str:
    """The file name of an id's certificate (``3.16.json``; user ids keep their text,
    characters outside ``[A-Za-z0-9._-]`` become ``_``)."""
    return re.sub(r"[^A-Za-z0-9._-]", "_", eq_id) + ".json"


# ----------------------------------------------------------------------------- evidence
def _point(pr: StatementPrinter, lhs, rhs, seed: int) -> dict:
    """An exact counterexample of ``lhs = rhs``: values of every atom and jet, and
    ``tan(phi / 2M)`` of every angle."""
    diff = [a - b for a, b in zip(entries_of(lhs), entries_of(rhs), strict=True)]
    zr = decide_zero(diff, seed=seed)
    if zr.zero is not False:
        raise Unprintable(f"no counterexample found ({zr.method}: {zr.detail})")
    plan = make_plan(entries_of(lhs) + entries_of(rhs))
    pt = small_witness(diff, plan, seed) or \
        {p: zr.witness.get(p, Fraction(1, 2)) for p in plan.params}
    return {"type": "counterexample", **_atom_point(pr, plan, pt)}


def _atom_point(pr: StatementPrinter, plan, pt: dict) -> dict:
    """``{"point", "angles"}``: the atoms' and jets' values at the parameter point ``pt``."""
    point, angles = {}, {}
    for atom, rule in plan.rules.items():
        if atom in plan.bare or atom is sp.pi:
            continue
        base = atom.expr if isinstance(atom, sp.Derivative) else atom
        k = 0 if base is atom else sum(int(n) for _, n in atom.variable_count)
        v = evaluate(rule, plan, pt) if rule != atom else pt[atom]
        point[pr.atom(base) + "'" * k] = str(Fraction(str(v)))
    for a, (tau, M) in plan.angles.items():
        angles[pr.atom(a)] = {"M": int(M), "tan": str(pt[tau])}
    return {"point": dict(sorted(point.items())), "angles": dict(sorted(angles.items()))}


def _candidate_points(pr: StatementPrinter, sides: list, seed: int, n: int = 6) -> list:
    """Exact points of the constraint set for the atoms of ``sides`` (small rationals; the
    angles' M those of all the sides, as the checker's)."""
    import random

    plan = make_plan([e for s in sides for e in entries_of(s)])
    rng = random.Random(seed)
    small = [Fraction(k, d) for k in range(-3, 4) for d in (1, 2, 3)]
    out = []
    for _ in range(4 * n):
        pt = {p: rng.choice(small) for p in plan.params}
        try:
            out.append(_atom_point(pr, plan, pt))
        except ZeroDivisionError:
            continue
        if len(out) == n:
            break
    return out


def _angle_M(sides) -> dict:
    """Angle atom -> the lcm of the denominators of its coefficients in the cos/sin
    arguments of ``sides`` (the checker's ``M``)."""
    from math import lcm

    out: dict = {}
    for s in sides:
        for e in entries_of(s):
            for f in sp.sympify(e).atoms(sp.cos, sp.sin):
                for term in sp.Add.make_args(sp.expand(f.args[0])):
                    c, rest = term.as_coeff_Mul()
                    if rest is not sp.pi and c.is_Rational:
                        out[rest] = lcm(out.get(rest, 1), int(c.q))
    return out


def _fails(r, model: dict, seed: int) -> bool:
    """Whether the relation ``r`` fails: a shape mismatch, or a counterexample."""
    if shape_of(r.lhs) != shape_of(r.rhs):
        return True
    lhs, rhs = explicit(r.lhs, model), explicit(r.rhs, model)
    diff = [a - b for a, b in zip(entries_of(lhs), entries_of(rhs), strict=True)]
    return decide_zero(diff, seed=seed).zero is False


def certificate(eq_id: str, verdict: str, members: list[dict] | None = None,
                seed: int | None = None, cofactors: bool = True,
                reading: str | Path | Reading | None = None) -> dict:
    """The certificate of an id's verdict (a plain dict; ``json.dumps`` writes it).

    Args:
        eq_id: a registered id (book or user).
        verdict: its computed verdict: ``verified``, ``does-not-hold`` or ``definition``.
        members: the result's member records (``Outcome.members``): a does-not-hold
            certifies its first member whose status is ``fails``; ``None``: the first member
            the zero test finds failing.
        seed: the seed of the counterexample search (default: the id's).
        cofactors: give an identity cofactor evidence where
            :func:`rigidsym.checking.certifying.cofactors.cofactor_evidence` finds it (else, and
            when ``False``, a re-computation certificate).
        reading: the reading file of a reader's own text (:mod:`rigidsym.reading`): a user
            id's symbol table, relation tables and page reading are its lines
            (:func:`reading_for`), or a :class:`rigidsym.reading.Reading` (a document's
            relation: :mod:`rigidsym.documents.certifying`); ignored for a book id, whose
            reading is the book's.

    Raises:
        Unprintable: the statement leaves the grammar, an atom has a kind the checker does
            not know, or no counterexample was found.
        BadInput: ``reading`` is not a readable reading file.
        ValueError: an undecided verdict (nothing to certify).
    """
    from rigidsym.checking.deciding.explicit import seed_of

    if verdict not in ("verified", "does-not-hold", "definition"):
        raise ValueError(f"verdict: expected verified, does-not-hold or definition, got "
                         f"{verdict!r}")
    eq = REGISTRY[eq_id]
    st = eq.build()
    EXPLICIT_CACHE.clear()
    seed = seed_of(eq_id) if seed is None else seed
    pr = StatementPrinter()
    pairs = []  # (label, role, lhs, rhs, evidence or None for a counterexample)
    asserted = st.printed + st.claims
    if verdict == "verified":
        pairs = [(r, "printed" if i < len(st.printed) else "claim", "identity")
                 for i, r in enumerate(asserted)]
    elif verdict == "definition":
        pairs = [(r, "printed", "statement") for r in st.printed]
        pairs += [(r, "claim", "identity") for r in st.claims]
    else:
        if members is None:
            bad = next((i for i, r in enumerate(asserted) if _fails(r, st.model, seed)), None)
        else:
            status = [m.get("status") for m in members][:len(asserted)]
            bad = next((i for i, s in enumerate(status) if s == "fails"), None)
        if bad is None:
            raise Unprintable("no failing member on record")
        pairs = [(st.for_every[0], "printed", "fails")] if st.for_every else [
            (asserted[bad], "printed" if bad < len(st.printed) else "claim", "fails")]
        pairs += [(r, "corrected", "identity") for r in st.corrected or []]
    sides = []
    for r, role, ev in pairs:
        lhs, rhs = explicit(r.lhs, st.model), explicit(r.rhs, st.model)
        if isinstance(lhs, sp.MatrixBase) != isinstance(rhs, sp.MatrixBase) and \
                shape_of(lhs) == shape_of(rhs):  # a 1 x 1 matrix against a scalar
            lhs, rhs = (x[0, 0] if isinstance(x, sp.MatrixBase) else x for x in (lhs, rhs))
        if ev == "fails":
            ev = {"type": "shape"} if shape_of(r.lhs) != shape_of(r.rhs) else None
        else:
            ev = {"type": ev}
            if ev["type"] == "identity" and same_text(lhs, rhs):  # sympy's evaluation did it
                lhs, rhs = derived_sides(r, st.model, lhs, rhs)
        sides.append((r, role, lhs, rhs, ev))
    for _, _, lhs, rhs, _ in sides:
        for e in entries_of(lhs) + entries_of(rhs):
            pr.count(sp.sympify(e))
    for r in (r for r, role, *_ in sides if role == "printed"):  # (p' - a' = Q(p - a): c)
        _glyph_atoms(pr, r, st.model, _defined_through(eq_id, eq.section))
    rels = []
    for r, role, lhs, rhs, ev in sides:
        try:  # a counterexample's point (for every value of an array the page never gives)
            ev = ev or (for_every_evidence(pr, lhs, rhs, *st.for_every[1:], st.model, seed)
                        if st.for_every else _point(pr, lhs, rhs, seed))
        except (Unsupported, ValueError) as exc:
            raise Unprintable(str(exc)) from None
        rels.append(relation_record(pr, r.label, role, lhs, rhs, ev))
        if role != "corrected" and (pair := _restated_pair(eq.latex or "", lhs, rhs)):
            rels[-1]["restated"] = {"printed": "X^{-1} = Y", "proved": "X Y = 1",
                                    "X": pair[0], "Y": pair[1]}
        if role != "corrected" and (own := relation_table(eq_id, r.label, reading)):
            rels[-1]["symbols"] = own  # F = N, L or H: this member's F (the page's words)
        if role == "claim" and getattr(r, "page", 0):  # a chain's member the page prints
            rels[-1]["page"] = r.page
    printed = [(lhs, rhs) for _, role, lhs, rhs, _ in sides if role == "printed"]
    if verdict == "verified" and printed and all(map(constants_only, sum(printed, ()))):
        verdict = "restatement"  # 1 1 1 = 1: nothing derived (certcheck calls it vacuous)
    # the groups in a fixed order (their first naming follows sympy's traversal, which
    # differs across PYTHONHASHSEED): the same statement gives the same bytes
    atoms = sorted(pr.groups.values(), key=lambda g: g["group"])
    if cofactors:
        _add_cofactors(pr, rels, sides, atoms, seed)
    out = {"format": FORMAT, "version": VERSION, "id": eq_id, "title": eq.title,
           "verdict": verdict, "book_latex": eq.latex or "", "atoms": atoms,
           "book_names": dict(sorted(pr.book.items())), "let": pr.lets, "relations": rels}
    out["symbols"] = symbol_table(atoms, eq_id, reading)
    if verdict == "does-not-hold":
        out["cause"] = cause_record(eq, reading)
    return out


def _defined_through(eq_id: str, section: str) -> dict:
    """The glyphs no definition defines that each glyph is defined through by the
    definitions of ``section`` declared before ``eq_id`` (3.22's ``e``: ``p_2``, ``p_1``,
    ``||p_2 - p_1||``; a defined glyph is read through its own definition: 3.125's ``q_O``)."""
    out, ids = {}, list(REGISTRY)
    for d in (REGISTRY[i] for i in ids[:ids.index(eq_id)]):
        st = d.build() if d.section == section and d.kind == "definition" else None
        for r in (r for r in st.printed if str(r.lhs) in st.defines) if st else ():
            out.setdefault(r.lhs, set()).update(getattr(r.rhs, "free_symbols", set()))
    return {g: hs - set(out) for g, hs in out.items()}


def _glyph_atoms(pr: StatementPrinter, rel, model: dict, through: dict) -> None:
    """Name in ``pr`` the atoms of the model's value of each glyph of a printed relation
    and of the glyphs a definition before it defines that glyph through (``through``: 3.24's
    ``e`` read through (3.22)'s ``p_2``), also where it cancels them (an atom of a kind the
    checker does not know stays out)."""
    from sympy.core.function import AppliedUndef

    from rigidsym.algebra.symbols import TIME

    glyphs = [g for side in (rel.lhs, rel.rhs) for g in sorted(getattr(side, "free_symbols",
                                                                      set()), key=str)]
    glyphs += sorted({h for g in glyphs for h in through.get(g, ())}, key=str)
    for e in (e for g in glyphs if g in model for e in entries_of(explicit(g, model))):
        for a in sorted(sp.sympify(e).atoms(sp.Symbol, AppliedUndef) - {TIME}, key=str):
            with suppress(Unprintable):
                pr.atom(a)


def constants_only(side) -> bool:
    """Whether every entry of ``side`` (a sympy scalar or matrix, as written) is free of
    atoms once each product with a literal 0 factor is dropped: ``1*1*1``, a determinant of
    a unit triangular block matrix expanded by its entries (3.30). A verified relation of
    two such sides derives nothing: the certificate calls its id a ``restatement``."""
    def walk(e) -> tuple[bool, bool]:  # (literally zero, free of atoms)
        if e.is_Number:
            return e == 0, True
        if e.is_Mul or e.is_Add:
            parts = [walk(a) for a in e.args]
            zero = any(z for z, _ in parts) if e.is_Mul else all(z for z, _ in parts)
            return zero, zero or all(f for _, f in parts)
        z, f = walk(e.base) if e.is_Pow and e.exp.is_Integer else (False, False)
        return z and bool(e.is_Pow and e.exp > 0), f
    return all(walk(sp.sympify(x))[1] for x in entries_of(side))


def _restated_pair(latex: str, lhs, rhs) -> tuple[str, str] | None:
    """The printed sides ``(X, Y)`` of a printed ``X^{-1} = Y`` (one relation, X a glyph or
    a bracketed product) whose relation is proved as ``X Y = 1``: ``rhs`` the identity and
    ``lhs`` a square matrix of its size (:func:`derived_sides`, or a model written so, 3.14).
    certcheck reads X and Y from the page and requires ``lhs`` to be their product; ``None``
    where the page or the relation is not of that form."""
    m = re.fullmatch(r"\s*(\\mathbf\{\w\}|\([^=]*\))\^\{-1\}\s*=\s*([^=,]*?)\s*", latex)
    n = shape_of(rhs)[0]
    if m is None or not isinstance(rhs, sp.MatrixBase) or rhs != sp.eye(n) or \
            shape_of(lhs) != (n, n):
        return None
    return m.group(1), m.group(2)


def reading_for(eq_id: str, reading: str | Path | Reading | None = None):
    """The reading whose lines an id's certificate carries: the book's
    (:func:`rigidsym.registry.declarations.book_reading`) for a book id, whatever
    ``reading`` is; ``reading`` (a reader's own reading file) for a user id ``ns:name``,
    ``None`` without one. A user id never takes a line of the book's reading (its glyphs
    may look the same, ``\\mathbf{Q}``, and mean the reader's model).

    Returns:
        A :class:`rigidsym.reading.Reading`, or ``None``.

    Raises:
        BadInput: ``reading`` is not a readable reading file.
    """
    if is_user_id(eq_id):
        return reading_of(reading)
    return reading_of(book_reading())


def symbol_table(atoms: list[dict], eq_id: str,
                 reading: str | Path | None = None) -> list[dict]:
    """One entry per glyph the statement's atoms stand for, for a referee to hold against
    the page (certcheck reads the printed LaTeX under it, docs/certificates.md): the model
    symbols' own lines (``{"glyph", "kind", "atoms"}``, their rates), then the lines the
    book's reading gives the id (:func:`rigidsym.registry.declarations.book_reading`,
    :mod:`rigidsym.checking.certifying.reading_table`): a cross-product matrix, a formula of
    another chapter as the page reproduces it, what the page says in words. A reader's own
    id takes the lines of ``reading``, the reading file of the reader's text
    (:func:`reading_for`); without one, the model symbols' lines alone.

    Raises:
        Unprintable: the reading gives a line the statement's atoms cannot back.
        BadInput: ``reading`` is not a readable reading file.
    """
    try:
        return reading_table.table(atoms, id_lets(reading_for(eq_id, reading), eq_id))
    except reading_table.ReadingMismatch as exc:
        raise Unprintable(f"({eq_id}): {exc}") from None


def relation_table(eq_id: str, label: str, reading: str | Path | None = None) -> list[dict]:
    """The table the reading (:func:`reading_for`) gives one relation of ``eq_id`` (a
    member of a family, a unit alternative: its label), ``[]`` where it gives none."""
    if not label:
        return []
    lets = id_lets(reading_for(eq_id, reading), eq_id, label)
    return reading_table.table([], lets, own=False) if lets else []


#: the declared cause of a does-not-hold -> the certificate's cause class
CAUSE_CLASSES = {"erratum": "book erratum", "conversion": "conversion slip"}


def page_reading(eq_id: str, reading: str | Path | None = None) -> str:
    """The reading's (:func:`reading_for`) decided page reading of ``eq_id`` (a slip of
    the converted text: what the printed page is read to show, ``"verified: ..."`` or
    ``"its own erratum: ..."``), ``""`` where it gives none."""
    found = reading_for(eq_id, reading)
    entry = found.ids.get(eq_id) if found is not None else None
    return entry.page_reading if entry is not None else ""


def cause_record(eq, reading: str | Path | None = None) -> dict:
    """The cause of a does-not-hold declaration for its certificate: ``{"class": "book
    erratum" | "conversion slip" | "undetermined", "why": the declared evidence (a
    reader's id: its evidence, else its ``cause=`` words)}``, and for
    a conversion slip ``"page_reading"``: what the printed page is declared to show, a
    conjecture about the page (the source is a converted text) whose corrected form the
    certificate proves."""
    cls = CAUSE_CLASSES.get(eq.cause, "undetermined")
    # a reader's cause= is their words (the book's is one of CAUSE_CLASSES' keys)
    out = {"class": cls, "why": eq.evidence or (eq.cause if is_user_id(eq.id) else "") or ""}
    if cls == "conversion slip":
        decided = page_reading(eq.id, reading)
        out["page_reading"] = ("conjecture: the printed page shows the corrected form below, "
                               "the converted text lost or changed a glyph: "
                               + (eq.evidence or "(no evidence declared)")
                               + (f" Decided: {decided}" if decided else ""))
    return out




def _add_cofactors(pr: StatementPrinter, rels: list, sides: list, atoms: list, seed: int) -> None:
    """Replace identity evidence by cofactors where they are found (in place)."""
    from rigidsym.checking.certifying.cofactors import NoCofactors, cofactor_evidence

    every = [x for s in sides for x in s[2:4]]
    M = {pr.atom(a): m for a, m in _angle_M(every).items()}
    points = None
    for rel, (_, _, lhs, rhs, _) in zip(rels, sides, strict=True):
        if rel["evidence"]["type"] != "identity":
            continue
        try:
            points = points or _candidate_points(pr, every, seed)
            rel["evidence"] = cofactor_evidence(lhs, rhs, atoms, pr.atom, M, points)
        except (NoCofactors, Unsupported) as exc:
            rel["evidence"] = {"type": "identity", "why_not_cofactors": str(exc)}


def certificate_or_reason(eq_id: str, verdict: str, members: list[dict] | None,
                          reading: str | Path | None = None) -> dict | str:
    """:func:`certificate` of a result (a user id's tables from ``reading``), or why it has
    none (an undecided verdict, a statement :class:`Unprintable`): what a folder's
    ``SKIPPED.txt`` says of the id."""
    if verdict == "undecided":
        return "undecided: nothing to certify"
    try:
        return certificate(eq_id, verdict, members, reading=reading)
    except (Unprintable, ValueError) as exc:
        return str(exc)


def write_certificates(results, directory, recheck: bool = False,
                       book: str | None = None, made: dict | None = None,
                       reading: str | Path | None = None) -> dict:
    """Write one certificate per decided result into ``directory`` (created), and a
    ``SKIPPED.txt`` naming the ids without one and why.

    Args:
        results: outcomes of :func:`rigidsym.checking.runner.run_checks` (``id``,
            ``verdict``, ``members``).
        directory: the folder.
        recheck: run the independent checker on the folder afterwards
            (:func:`recheck_folder`).
        book: the book's text file (the referee's copy, never shipped): its SHA-256 goes
            into ``MANIFEST.json`` and the checker binds each certificate to its page.
        made: id -> :func:`certificate_or_reason`, made before (the export's workers or
            store: :mod:`rigidsym.checking.export`); an id not in it is made here.
        reading: the reading file the certificates are bound to (its SHA-256 into
            ``MANIFEST.json``, ``--reading`` for the checker; the user ids' symbol tables
            are its lines, :func:`reading_for`); ``None``: the book's reading
            (:func:`rigidsym.registry.declarations.book_reading`) where every id written is
            the book's, else none.

    Returns:
        ``{"written": [ids], "skipped": {id: why}, "rechecked": {id: passed} or None,
        "checker": its location or None, "failures": {id: the checker's reason},
        "evidence": {id: [evidence type per relation]}}``; undecided ids are skipped.
    """
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    written, skipped, files, evidence = [], {}, {}, {}
    for r in results:
        cert = (made or {}).get(r.id) or certificate_or_reason(r.id, r.verdict, r.members,
                                                               reading)
        if isinstance(cert, str):
            skipped[r.id] = cert
            continue
        write_atomic(out / certificate_file(r.id), json.dumps(cert, indent=1) + "\n")
        written.append(r.id)
        files[certificate_file(r.id)] = r.id
        evidence[r.id] = [rel["evidence"]["type"] for rel in cert["relations"]]
    write_atomic(out / "SKIPPED.txt",
                 "".join(f"{i}: {why}\n" for i, why in skipped.items()) or "none\n")
    if reading is None and written and all(":" not in i for i in written):
        reading = book_reading()
    write_manifest(out, list(files), book, reading)
    summary = {"written": written, "skipped": skipped, "rechecked": None, "checker": None,
               "failures": {}, "evidence": evidence, "reading": reading}
    if recheck and written:
        summary.update(recheck_folder(out, files, book, reading=reading))
    return summary


def _checker_path() -> str | None:
    """Where ``certcheck`` is: the checkout's ``certcheck/src`` beside ``src/``, or ``""``
    when it is installed; ``None`` when it is nowhere."""
    import importlib.util

    here = Path(__file__).resolve().parents[4] / "certcheck" / "src"
    if (here / "certcheck" / "__main__.py").is_file():
        return str(here)
    return "" if importlib.util.find_spec("certcheck") is not None else None


def write_manifest(directory, names: list[str], book: str | None = None,
                   reading: str | Path | None = None) -> dict:
    """Write ``directory/MANIFEST.json``: the SHA-256 of each certificate file of ``names``,
    of the book text and of the reading file (``None`` without one), and rigidsym's version,
    so that the folder is one run (certcheck verifies it). Returns the manifest.

    Raises:
        BadInput: ``book`` or ``reading`` is not a readable file.
    """
    import hashlib

    from rigidsym import __version__
    from rigidsym.core.errors import BadInput

    out = Path(directory)
    book_sha = None
    if book is not None:
        try:
            book_sha = hashlib.sha256(Path(book).read_bytes()).hexdigest()
        except OSError as exc:
            raise BadInput(f"book: expected a readable text file, got {book!r} ({exc})") from None
    reading_sha = None
    if reading is not None:
        try:
            reading_sha = hashlib.sha256(Path(reading).read_bytes()).hexdigest()
        except OSError as exc:
            raise BadInput(f"reading: expected a readable file, got {str(reading)!r} "
                           f"({exc})") from None
    man = {"format": "rigidsym-certificate-manifest", "rigidsym": __version__,
           "book_sha256": book_sha, "reading_sha256": reading_sha,
           "certificates": {n: hashlib.sha256((out / n).read_bytes()).hexdigest()
                            for n in sorted(names)}}
    write_atomic(out / "MANIFEST.json", json.dumps(man, indent=1) + "\n")
    return man


def recheck_folder(directory, files: dict, book: str | None = None, jobs: int = 1,
                   reading: str | Path | None = None) -> dict:
    """Run the independent checker (``python -m certcheck``, a separate process that
    imports no rigidsym) on ``directory``.

    Args:
        directory: the folder of certificates.
        files: certificate file name -> id.
        book: the book's text file, passed on as ``--book`` (each certificate is then
            bound to the text printed as its id, the folder to its manifest).
        jobs: certcheck's processes (``--jobs``).
        reading: the reading file, passed on as ``--reading`` (each id's symbol table and
            class are then the reading's).

    Returns:
        ``{"rechecked": {id: passed}, "checker": where it was found, "failures": {id:
        reason}, "not_read": {id: what}, "checked": [ids], "exit": certcheck's exit
        status}``; ``rechecked`` is ``None`` (and ``exit`` ``None``) when certcheck is not
        found; ``not_read``: ids proved whose printed sides are not all read from the page
        (certcheck's exit 3); ``checked``: the ids certcheck printed ``CHECKED (id)`` for,
        proved with every printed side read from the page.
    """
    import os
    import subprocess
    import sys

    where = _checker_path()
    if where is None:
        return {"rechecked": None, "checker": None, "failures": {}, "not_read": {},
                "checked": [], "exit": None}
    env = dict(os.environ)
    if where:
        env["PYTHONPATH"] = where + os.pathsep + env.get("PYTHONPATH", "")
    book_args = [] if book is None else ["--book", str(book)]
    book_args += [] if reading is None else ["--reading", str(reading)]
    proc = subprocess.run([sys.executable, "-m", "certcheck", "--quiet", "--jobs", str(jobs),
                           *book_args, str(directory)],
                          capture_output=True, text=True, env=env, check=False)
    failures, not_read, checked = {}, {}, []
    for line in proc.stdout.splitlines():
        if line.startswith("CHECKED ("):
            checked.append(line[len("CHECKED ("):].split(") ", 1)[0])
        if line.startswith("NOT READ "):
            name, _, why = line[len("NOT READ "):].partition(": ")
            not_read[files.get(name, name)] = why
        if line.startswith("FAILED "):
            name, _, why = line[len("FAILED "):].partition(": ")
            if name in files:
                failures[files[name]] = why
            else:  # the folder's manifest: no id of its own
                failures[f"({name.split(' ')[0]})"] = why
    if proc.returncode not in (0, 1, 3) or (proc.returncode == 1 and not failures):
        failures["(certcheck)"] = (f"exit {proc.returncode}: "  # never a silent pass
                                   + (proc.stderr.strip() or proc.stdout.strip())[-300:])
    passed = {i: i not in failures and proc.returncode in (0, 1, 3) for i in files.values()}
    return {"rechecked": passed, "checker": where or "installed certcheck",
            "failures": failures, "not_read": not_read, "checked": checked,
            "exit": proc.returncode}
