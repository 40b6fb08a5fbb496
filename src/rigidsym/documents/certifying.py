"""Certificates of a document's verdicts: ``rigidsym check NOTES.md --certificates DIR``.

Each relation the document check decided (``verified``, ``does-not-hold`` with its
counterexample and corrected form, a ``definition`` as the document's own) gets one
certificate (:mod:`rigidsym.checking.certifying.certificates`), bound to the document as its
page and to its reading file, so that ``python -m certcheck --book NOTES.md --reading
NOTES.reading.toml DIR`` checks it as a referee would (``certcheck.document`` locates the
relation, decides its class from the page and holds its symbol lines to the reading's
``[[let]]`` lines and the page's own definitions).

Ids (docs/check-documents.md, "Certificates"): the relation's label where one relation of
the page carries it and the page prints it (``\\label{L}``, ``\\tag{L}`` or ``(L)``): ``L``
itself when it is of a reader's id's form ``ns:name`` (``eq:rodrigues-E``), else
``label:L`` (a printed ``(3.9a)``: ``label:3.9a``); otherwise its line, ``line:L`` for the
one relation that stands on line L of the document, ``line:L.K`` for the K-th of several.

A relation is listed as not certified, with the reason, where a certificate cannot state
it: not decided, decided under each convention the document leaves open (a certificate
states one reading), in a file the document inputs (certcheck binds one page), read with
its macros expanded (the page prints another text), a declaration that is no line of the
reading file, or a statement outside the certificates' grammar.
"""

from __future__ import annotations

import dataclasses
import json
import re
from pathlib import Path

from rigidsym.core.errors import BadInput
from rigidsym.documents.checking import DocumentResult
from rigidsym.documents.declarations import CONVENTION_LETS, plan
from rigidsym.documents.relations import Relation
from rigidsym.reading import Let, Reading

__all__ = ["CERTIFIED", "certify_document", "document_ids"]

#: the verdicts a certificate states
CERTIFIED = ("verified", "does-not-hold", "definition")
#: a reader's id (``ns:name``), as rigidsym's user ids and certcheck's locator read it
_READER_ID = re.compile(r"[a-z][a-z0-9_-]*:[A-Za-z0-9_.-]+")
#: a glyph a page's definition defines (certcheck.document's)
_GLYPH = re.compile(r"(\\(dot|ddot|hat|bar|tilde)\{)?(\\(mathbf|boldsymbol|bm)\{\\?[A-Za-z]+\}|"
                    r"\\?[A-Za-z]+)\}?(_\{?\\?\w+\}?)?'*")


def _printed_label(text: str, label: str) -> bool:
    """Whether ``text`` prints ``label`` as ``\\label{L}``, ``\\tag{L}`` or ``(L)``."""
    return re.search(r"(\\label\{|\\tag\*?\{|\()\s*" + re.escape(label) + r"\s*[})]",
                     text) is not None


def document_ids(relations: list[Relation], text: str, main: str) -> dict[int, str]:
    """The certificate id of each relation of the page ``main`` (by its position in
    ``relations``): its label, or ``line:L`` / ``line:L.K`` (the module's docstring). A
    relation of another file (an input) has none; nor one whose line id is another
    relation's label (certcheck's locator reads the label first).

    Args:
        relations: the document's relations, in reading order.
        text: the page's text (the file ``main``).
        main: the page's file name, as the relations carry it.

    Returns:
        ``{index in relations: id}`` for each relation of ``main`` that has an id.
    """
    mine = [(k, r) for k, r in enumerate(relations) if r.file == main]
    labels: dict[str, list[int]] = {}
    for k, r in mine:
        if r.label:
            labels.setdefault(r.label, []).append(k)
    out: dict[int, str] = {}
    for k, r in mine:
        eq_id = None
        if r.label and len(labels[r.label]) == 1 and _printed_label(text, r.label):
            if _READER_ID.fullmatch(r.label):
                eq_id = r.label
            elif re.fullmatch(r"[A-Za-z0-9_.-]+", r.label):
                eq_id = f"label:{r.label}"
        if eq_id is None:
            on = [j for j, x in mine if x.line == r.line]
            eq_id = f"line:{r.line}" if len(on) == 1 else f"line:{r.line}.{on.index(k) + 1}"
        if labels.get(eq_id, [k]) == [k]:
            out[k] = eq_id
    return out


def _unboxed(latex: str) -> str:
    """``latex`` with each ``\\boxed{X}`` (a repair's edit) written ``{X}``."""
    return latex.replace("\\boxed{", "{")


def _table_reading(eq_id: str, lets: list[str], reading: Reading | None,
                   defined: dict[str, int]) -> Reading:
    """The reading whose lines the certificate of ``eq_id`` carries: each declaration it
    is checked with, a line of the reading file (its ``where``, ``cites`` ...) or a
    definition of the page (``defined``: let text -> its line, ``where`` "defined on the
    page, line L", as certcheck.document writes it).

    Raises:
        ValueError: a declaration that is neither (a split ``--let``), or a function's
            definition (certcheck's page reads a glyph's).
    """
    out = []
    own = {x.let: x for x in reading.lets} if reading is not None else {}
    for text in lets:
        if text in CONVENTION_LETS.values():
            continue
        if text in defined:
            name = text.split("=", 1)[0].strip()
            if not _GLYPH.fullmatch("".join(name.split())):
                raise ValueError(f"uses the page's definition of {name}, a function's "
                                 "(certcheck reads a glyph's definition)")
            out.append(Let(text, where=f"defined on the page, line {defined[text]}",
                           ids=(eq_id,)))
        elif text in own:
            out.append(dataclasses.replace(own[text], ids=(eq_id,), scope=None))
        else:
            raise ValueError(f"the declaration '{text}' is no line of the reading file "
                             "(certcheck holds each certificate's table to its lines)")
    return Reading(None, "", None, lets=tuple(out))


def _statement(p, rec: dict, lets: list[str]):
    """The statement of a relation's plan ``p`` read from its LaTeX with ``lets`` (a
    definition: ``NAME = LATEX`` under its own model; a false one with its corrected form,
    read from the record's ``corrected_latex``)."""
    from rigidsym.documents.declarations import rate_line
    from rigidsym.latex.statement import declare_latex

    r = p.relation
    lets = [t for t in lets if rate_line(t) is None]  # \dot X of X(t): read from X(t)
    if p.action == "definition":
        eq, _ = declare_latex(f"{r.lhs} = {r.rhs}", [*lets, p.let])
        return eq.build()
    eq, _ = declare_latex(p.checked or r.latex, lets)
    st = eq.build()
    if rec["verdict"] == "does-not-hold" and rec.get("corrected_latex"):
        fixed, _ = declare_latex(_unboxed(rec["corrected_latex"]), lets)
        st = dataclasses.replace(st, corrected=list(fixed.build().printed))
    return st


def certify_document(result: DocumentResult, directory: str | Path,
                     recheck: bool = True) -> dict:
    """Write one certificate per decided relation of ``result`` into ``directory``
    (created), a ``SKIPPED.txt`` naming each relation without one and why, and the
    ``MANIFEST.json`` binding the folder to the document and its reading file; then run
    certcheck on it, bound to both.

    Args:
        result: :func:`rigidsym.documents.check_document`'s result (checked without
            command-line ``--let``s or ``--notation``: a certificate's table is the reading
            file's and the page's).
        directory: the folder.
        recheck: run certcheck (``python -m certcheck --book DOC --reading READING``).

    Returns:
        ``{"written": {id: "FILE:LINE"}, "skipped": {"FILE:LINE": why}, "rechecked":
        {id: passed} or None, "checked": [ids CHECKED], "failures": {id: reason},
        "not_read": {id: what}, "exit": certcheck's exit status or None}``.

    Raises:
        BadInput: the document or its reading file cannot be read.
    """
    from rigidsym.checking.certifying.certificates import (
        Unprintable,
        certificate,
        certificate_file,
        recheck_folder,
        write_manifest,
    )
    from rigidsym.core.files import write_atomic
    from rigidsym.latex import LatexError
    from rigidsym.registry.declarations import REGISTRY, equation

    doc, reading = result.document, result.reading
    main = str(doc.path)
    try:
        text = doc.path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise BadInput(f"{main}: cannot read the file ({exc})") from None
    relations = list(doc.relations)
    plans = plan(relations, reading, [])
    ids = document_ids(relations, text, main)
    by_place = {(r["display"], r["index"], r["file"]): r for r in result.records}
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    written: dict[str, str] = {}
    skipped: dict[str, str] = {}
    defined: dict[str, int] = {}  # a page's definition's let text -> its line
    made: list[str] = []
    try:
        for k, p in enumerate(plans):
            r = p.relation
            rec = by_place.get((r.display, r.index, r.file))
            where = f"{r.file}:{r.line}"
            if rec is not None and p.action == "definition" and r.file == main:
                defined[p.let] = r.line
            why = _why_not(rec, r, main, k, ids, text)
            if why:
                skipped[f"{where} ({r.latex})"] = why
                continue
            eq_id = ids[k]
            try:
                lets = list(p.lets) + ([p.let] if p.action == "definition" else [])
                table = _table_reading(eq_id, lets, reading, defined)
                st = _statement(p, rec, list(p.lets))

                def built(st=st):
                    return st
                kind = "definition" if p.action == "definition" else "identity"
                cause = ("does not hold as printed" + (f"; corrected: {rec['cause']}"
                                                       if rec.get("cause") else ""))
                equation(eq_id, where, section="document", latex=r.latex, kind=kind,
                         expected=rec["verdict"],
                         cause=cause if rec["verdict"] == "does-not-hold" else None)(built)
                made.append(eq_id)
                cert = certificate(eq_id, rec["verdict"], None, reading=table)
            except (Unprintable, ValueError, BadInput, LatexError) as exc:
                skipped[f"{where} ({r.latex})"] = f"no certificate: {exc}"
                continue
            write_atomic(out / certificate_file(eq_id), json.dumps(cert, indent=1) + "\n")
            written[eq_id] = where
    finally:
        for eq_id in made:  # the page's ids are this run's, never the process's
            REGISTRY.pop(eq_id, None)
    write_atomic(out / "SKIPPED.txt",
                 "".join(f"{w}: {why}\n" for w, why in skipped.items()) or "none\n")
    read_path = reading.path if reading is not None else None
    write_manifest(out, [certificate_file(i) for i in written], main, read_path)
    summary = {"written": written, "skipped": skipped, "rechecked": None, "checked": [],
               "failures": {}, "not_read": {}, "exit": None}
    if recheck and written:
        summary.update(recheck_folder(out, {certificate_file(i): i for i in written}, main,
                                      reading=read_path))
    return summary


def _why_not(rec: dict | None, r: Relation, main: str, k: int, ids: dict[int, str],
             text: str) -> str:
    """Why the relation ``r`` (its record ``rec``) gets no certificate, ``""`` where it
    gets one."""
    if rec is None:
        return "not decided (the run was interrupted before it)"
    if rec["verdict"] not in CERTIFIED:
        return f"not decided ({rec['verdict']}): {rec.get('reason') or rec.get('method')}"
    if rec.get("under"):
        return ("decided under each convention the document leaves open: a certificate "
                "states one reading (fix the convention in the reading file's [conventions])")
    if r.file != main:
        return f"stands in {r.file}, which {main} inputs: certcheck binds one page"
    if k not in ids:
        return "its line's id is another relation's label on the page"
    flat = "".join(text.split())
    if not all("".join(side.split()) in flat for side in (r.lhs, r.rhs)):
        return ("read with the document's macros expanded: the page prints another text, "
                "which a certificate's printed relation must be")
    return ""
