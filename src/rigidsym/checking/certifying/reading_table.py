"""A certificate's symbol table: the lines the statement's atoms give every model symbol
(its glyph by the model's name, its kind, its time derivatives), then the lines a reading
file (:mod:`rigidsym.reading`) gives the id: kinds of glyphs that are not a model symbol's
own, cross-product matrices, and what the page says in words or by another display, each in
the table's glyphs. Nothing here knows a book: the book's lines are its reading's, which
certcheck holds every certificate to (``certcheck --reading``).
"""

from __future__ import annotations

import functools
import re
from pathlib import Path

from rigidsym.core.errors import BadInput
from rigidsym.reading import Let, Reading, load_reading

__all__ = ["ReadingMismatch", "atom_lines", "glyph_of", "id_lets", "reading_of", "table"]

class ReadingMismatch(ValueError):
    """The reading gives an id a line the statement's atoms cannot back."""


_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "eta", "theta", "kappa", "lambda",
          "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega"}


def glyph_of(base: str, vector: bool) -> str:
    """The book's glyph of an atom group's name (``e`` -> ``\\mathbf{e}``, ``omega`` ->
    ``\\boldsymbol{\\omega}``, ``phi`` -> ``\\phi``, ``r0`` -> ``r_0``, ``p0`` ->
    ``\\mathbf{p}_0``, ``adot`` -> ``\\dot{\\mathbf{a}}``)."""
    base = re.sub(r"^s\d+_", "", base)  # a section's prefix
    m = re.fullmatch(r"([A-Za-z]+?)(dot)?_?(\d?)", base)  # p0 -> p_0, adot -> dot a
    core, dot, sub = m.groups() if m else (base, None, "")
    if core in _GREEK or core.capitalize() in {g.capitalize() for g in _GREEK}:
        out = f"\\boldsymbol{{\\{core}}}" if vector else f"\\{core}"
    elif vector and m:
        out = f"\\mathbf{{{core}}}"
    elif len(core) == 1:
        out = core
    else:  # a name the book does not print (the model's own)
        return f"\\mathbf{{{base}}}" if vector else base
    return (f"\\dot{{{out}}}" if dot else out) + (f"_{sub}" if sub else "")


def atom_lines(atoms: list[dict]) -> list[dict]:
    """The table's lines of the model's own symbols: ``{"glyph", "kind", "atoms"}`` for a
    3-vector (atoms ``x_1, x_2, x_3`` of one group or three free scalars), a rotation or
    transform (row-major) and a scalar; a timed one's first and second time derivatives
    (its atoms' jets ``x'``, ``x''``)."""
    vectors: dict = {}
    scalars = []
    for g in atoms:
        names = g["names"]
        if len(names) == 3 and all(re.fullmatch(rf"{re.escape(g['group'])}_[123]", n)
                                   for n in names):
            vectors[g["group"]] = (g["kind"], names, g["timed"])
        elif len(names) == 1:
            m = re.fullmatch(r"(.+)_([123])", names[0])
            if m and g["kind"] == "free":
                vectors.setdefault(m.group(1), ("free", [], g["timed"]))[1].append(names[0])
            else:
                scalars.append((names[0], g["kind"], g["timed"]))
    out: list[dict] = []

    def add(glyph, entry, timed):
        out.append({"glyph": glyph, **entry})
        if timed:
            for dots, primes in (("dot", "'"), ("ddot", "''")):
                out.append({"glyph": f"\\{dots}{{{glyph}}}", **entry,
                            "atoms": [a + primes for a in entry["atoms"]]})

    for base, (kind, names, timed) in sorted(vectors.items()):
        if sorted(names) == [f"{base}_{k}" for k in (1, 2, 3)]:
            add(glyph_of(base, True), {"kind": kind, "atoms": sorted(names)}, timed)
    for g in atoms:
        if g["kind"] in ("rotation", "transform"):
            add(glyph_of(g["group"], True), {"kind": g["kind"], "atoms": list(g["names"])},
                g["timed"])
    for name, kind, timed in scalars:
        add(glyph_of(name, False), {"kind": kind, "atoms": [name]}, timed)
    return out


@functools.lru_cache(maxsize=8)
def _load(path: str, stamp: float) -> Reading:
    return load_reading(path)


def reading_of(path: str | Path | Reading | None) -> Reading | None:
    """The reading file at ``path`` (parsed once per change of the file), ``None`` for
    ``None``; a :class:`rigidsym.reading.Reading` itself (a document's relation: the lines
    its reading file and the page's own definitions give it, built by
    :mod:`rigidsym.documents.certifying`).

    Raises:
        BadInput: the file is missing or unreadable, or not a reading
            (:func:`rigidsym.reading.parse_reading`), naming it.
    """
    if path is None or isinstance(path, Reading):
        return path
    p = Path(path)
    try:
        stamp = p.stat().st_mtime
    except OSError as exc:
        raise BadInput(f"reading {p}: cannot read the file ({exc.strerror})") from None
    return _load(str(p), stamp)


def id_lets(reading: Reading | None, eq_id: str, relation: str = "") -> list[Let]:
    """The reading's lines of ``eq_id`` (of its relation ``relation``, ``""`` for the id's
    own table), in the file's order."""
    if reading is None:
        return []
    return [x for x in reading.lets if eq_id in x.ids and x.relation == relation]


def _top(text: str, ch: str) -> int:
    depth = 0
    for i, c in enumerate(text):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == ch and depth == 0:
            return i
    return -1


def _family(prefix: str, names: list[str]) -> list[str]:
    """The atoms ``prefix_1``, ``prefix_2`` ... (or ``prefix1`` ...) in index order."""
    found = [(int(m.group(1)), n) for n in names
             if (m := re.fullmatch(re.escape(prefix) + r"_?(\d+)", n))]
    return [n for _, n in sorted(found)]


def table(atoms: list[dict], lets: list[Let], own: bool = True) -> list[dict]:
    """The symbol table of a statement whose atoms are ``atoms`` under the reading's lines
    ``lets`` (:func:`id_lets`): the model's own symbols (:func:`atom_lines`) the reading
    declares (all of them where it gives the id no line), then each line of the reading;
    with ``own=False`` (a relation's own table), the reading's lines alone.

    Raises:
        ReadingMismatch: a kind whose glyph is no model symbol and names no atoms
            (``atoms_of``), a rate of a glyph with no line, a model symbol of another kind
            than the reading's.
    """
    names = [n for g in atoms for n in g["names"]]
    declared = {x.let[:_top(x.let, ":")].strip().removesuffix("(t)").strip() for x in lets
                if 0 <= _top(x.let, ":") and (_top(x.let, "=") < 0
                                              or _top(x.let, ":") < _top(x.let, "="))}
    mine = [e for e in atom_lines(atoms) if not lets or e["glyph"] in declared]
    out = list(mine) if own else []
    by_glyph = {e["glyph"]: e for e in mine}
    for x in lets:
        text = x.let
        colon, eq = _top(text, ":"), _top(text, "=")
        if colon >= 0 and (eq < 0 or colon < eq):
            name, kind = text[:colon].strip(), text[colon + 1:].strip()
            name = name.removesuffix("(t)").strip()
            rate = next((k for k, w in ((2, "second rate of "), (1, "rate of "))
                         if kind.startswith(w)), 0)
            if name in by_glyph and not x.atoms_of:
                continue   # a model symbol's own line (certcheck holds its kind)
            if name in by_glyph:   # the reading names its atoms: not the symbol's of that name
                old = by_glyph.pop(name)
                if old in out:
                    out.remove(old)
            if rate:
                base = by_glyph.get(kind.split(" of ", 1)[1].strip())
                if base is None:
                    raise ReadingMismatch(f"the reading's '{text}': no line of its glyph")
                line = {"glyph": name, "kind": base["kind"],
                        "atoms": [a + "'" * rate for a in base["atoms"]]}
            elif x.atoms_of:
                src = x.atoms_of
                if src.endswith("_*"):
                    got = _family(src[:-2], names)
                elif src in by_glyph:
                    got = list(by_glyph[src]["atoms"])
                else:
                    got = [src] if src in names else []
                group = {n: g for g in atoms for n in g["names"]}
                if not got or any(a not in group for a in got):
                    raise ReadingMismatch(f"the reading's '{text}': its atoms_of {src!r} names "
                                          "no atoms of the statement")
                line = {"glyph": name, "kind": group[got[0]]["kind"], "atoms": got}
            else:
                raise ReadingMismatch(f"the reading's '{text}': {name} is no model symbol "
                                      "and the line names no atoms_of")
            out.append(line)
            by_glyph[name] = line
            continue
        name, latex = text[:eq].strip(), text[eq + 1:].strip()
        if latex.startswith("\\mathrm{CPM}(") and latex.endswith(")"):
            line = {"glyph": name, "cpm_of": latex[len("\\mathrm{CPM}("):-1].strip()}
        elif x.particles:
            line = {"glyph": name, "model": x.where,
                    "particles": [dict(p) for p in x.particles]}
        else:
            line = {"glyph": name, "latex": latex}
            if x.where:
                line["model"] = x.where
            for key, value in (("printed_as", x.cites), ("family", x.family),
                               ("reads_as", x.reads_as), ("unit", x.unit)):
                if value:
                    line[key] = value
        out.append(line)
        by_glyph.setdefault(name, line)
    return out
