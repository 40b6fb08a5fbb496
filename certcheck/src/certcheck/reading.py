"""The reading of the page: the one file a referee reviews (each glyph's kind or model, each
id's class), read here with the standard library's ``tomllib`` and a parser of the ``--let``
lines of its own (no code shared with rigidsym).

A certificate supplies evidence only. Its symbol table (the top-level ``symbols`` and each
relation's own ``symbols``) must be exactly the lines the reading gives its id, and its
verdict must agree with the class the reading gives the id: a kind, a model, a citation,
a word or a relation-level table of the certificate's own is a failure naming the id.
"""

from __future__ import annotations

import hashlib
import json
import tomllib

__all__ = ["ReadingError", "bind", "line_of", "load_reading", "reading_sha256"]

#: the words of a KIND -> (the certificate's kind, its number of atoms)
_FIXED = {"unit vector": ("unit", 3), "unit 4-vector": ("unit4", 4), "rotation": ("rotation", 9),
          "transform": ("transform", 16), "angle": ("angle", 1),
          "angle in [0, pi]": ("angle_pi", 1), "scalar": ("free", 1)}
_CLASSES = ("relation", "definition", "theorem", "not-checked")
_LET_KEYS = {"let", "where", "scope", "ids", "cites", "family", "reads_as", "particles",
             "relation", "unit", "atoms_of"}
#: the most lines one certificate's table may have (the chapter's largest has 78)
MAX_LINES = 400


class ReadingError(ValueError):
    """A reading that cannot be read, or a certificate that differs from it."""


def reading_sha256(data: bytes) -> str:
    """The SHA-256 (hex) of a reading file's bytes."""
    return hashlib.sha256(data).hexdigest()


def _kind(words: str, where: str) -> tuple[str, int]:
    w = " ".join(words.lower().replace("×", "x").split())
    if w in _FIXED:
        return _FIXED[w]
    head, _, tail = w.partition("-")
    if tail == "vector" and head.isdigit() and int(head) > 0:
        return "free", int(head)
    r, x, c = w.removesuffix(" matrix").partition("x")
    if w.endswith(" matrix") and x and r.strip().isdigit() and c.strip().isdigit():
        return "free", int(r) * int(c)
    raise ReadingError(f"{where}: unknown kind {words!r}")


def _top(text: str, ch: str) -> int:
    depth = 0
    for i, c in enumerate(text):
        depth += {"{": 1, "}": -1}.get(c, 0)
        if c == ch and depth == 0:
            return i
    return -1


def _nospace(s: str) -> str:
    return "".join(s.split())


def line_of(entry: dict, where: str) -> tuple:
    """One ``[[let]]`` entry (``{"let": ..., "where": ...}``) as the canonical line a
    certificate's entry must equal.

    Raises:
        ReadingError: a let that is neither ``NAME: KIND`` nor ``NAME = LATEX``, or of an
            unknown kind (``where`` names it).
    """
    text = entry["let"].strip()
    colon, eq = _top(text, ":"), _top(text, "=")
    if colon >= 0 and (eq < 0 or colon < eq):
        name, kind = text[:colon].strip(), text[colon + 1:].strip()
        for k, word in ((2, "second rate of "), (1, "rate of ")):
            if kind.startswith(word):
                return ("rate", name, k, kind[len(word):].strip())
        timed = name.endswith("(t)")
        return ("kind", name.removesuffix("(t)").strip(), *_kind(kind, where), timed)
    if eq < 0:
        raise ReadingError(f"{where}: expected 'NAME: KIND' or 'NAME = LATEX', got {text!r}")
    name, latex = text[:eq].strip(), text[eq + 1:].strip()
    if latex.startswith("\\mathrm{CPM}(") and latex.endswith(")"):
        return ("cpm", name, latex[len("\\mathrm{CPM}("):-1].strip())
    particles = entry.get("particles") or []
    return ("model", name, None if particles else _nospace(latex), entry.get("where", ""),
            entry.get("cites", ""), entry.get("family", ""), entry.get("reads_as", ""),
            entry.get("unit", ""), json.dumps(particles, sort_keys=True))


def load_reading(data: bytes, name: str = "the reading") -> dict:
    """A reading file's bytes, checked: ``{"sha256", "lines": {(id, relation): [line]},
    "classes": {id: class}, "atoms_of": {id: {glyph: source}}, "words": {id: (statement,
    relation, why)}, "page_lets": [(entry, scope, ids, line)]}`` (``words``: the theorems
    the page states in words; ``page_lets``: every ``[[let]]`` with its scope and ids, a
    document's relations' lines, :mod:`certcheck.document`; a let with no ids serves no
    listed id).

    Raises:
        ReadingError: not TOML, an unknown key, kind or class, an id given two classes.
    """
    try:
        doc = tomllib.loads(data.decode("utf-8-sig"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise ReadingError(f"{name}: not TOML ({exc})") from None
    if not isinstance(doc.get("reading"), dict) or doc["reading"].get("format") != 1:
        raise ReadingError(f"{name}: expected a [reading] table with format = 1")
    unknown = set(doc) - {"reading", "conventions", "let", "id", "classes"}
    if unknown:
        raise ReadingError(f"{name}: unknown table {sorted(unknown)[0]!r}")
    lines: dict = {}
    page_lets: list = []  # every entry: (entry, scope, ids, line), a document's relations'
    sources: dict = {}   # id -> glyph -> where its atoms come from (atoms_of)
    for n, entry in enumerate(doc.get("let", []), start=1):
        where = f"{name}: [[let]] {n}"
        if not isinstance(entry, dict) or not isinstance(entry.get("let"), str):
            raise ReadingError(f"{where}: expected a table with a let")
        if set(entry) - _LET_KEYS:
            raise ReadingError(f"{where}: unknown key {sorted(set(entry) - _LET_KEYS)[0]!r}")
        line = line_of(entry, where)
        scope = entry.get("scope")
        page_lets.append((entry, None if scope is None else str(scope),
                          tuple(str(i) for i in entry.get("ids") or ()), line))
        for i in entry.get("ids") or ():
            lines.setdefault((str(i), entry.get("relation", "")), []).append(line)
            if entry.get("atoms_of"):
                if line[0] != "kind":
                    raise ReadingError(f"{where}: atoms_of on a line that is not a kind")
                sources.setdefault(str(i), {})[line[1]] = str(entry["atoms_of"])
    classes: dict = {}
    for cls, ids in (doc.get("classes") or {}).items():
        if cls not in _CLASSES:
            raise ReadingError(f"{name}: [classes]: unknown class {cls!r}")
        for i in ids:
            if i in classes:
                raise ReadingError(f"{name}: [classes]: {i!r} given two classes")
            classes[str(i)] = cls
    words: dict = {}
    for i, entry in (doc.get("id") or {}).items():
        cls = entry.get("class") if isinstance(entry, dict) else None
        if cls not in _CLASSES or classes.get(i, cls) != cls:
            raise ReadingError(f"{name}: [id.{i!r}]: class {cls!r} (or another than "
                               f"[classes]' {classes.get(i)!r})")
        classes[i] = cls
        said = [entry.get(k) for k in ("words", "states", "why")]
        if any(said):
            if not all(isinstance(x, str) and x for x in said):
                raise ReadingError(f"{name}: [id.{i!r}]: words, states and why go together")
            words[i] = tuple(said)
    return {"sha256": reading_sha256(data), "lines": lines, "classes": classes,
            "atoms_of": sources, "words": words, "page_lets": page_lets}


def _cert_lines(cert: dict, table: list, atoms: dict, where: str) -> list:
    """A certificate's table as canonical lines (checking each line's own structure)."""
    if not isinstance(table, list) or len(table) > MAX_LINES:
        raise ReadingError(f"{where}: a symbol table of at most {MAX_LINES} lines expected")
    out = []
    for e in table:
        if not isinstance(e, dict) or not isinstance(e.get("glyph"), str):
            raise ReadingError(f"{where}: a symbol line without a glyph: {e!r}")
    for e in table:
        g = e["glyph"]
        keys = set(e) - {"glyph"}
        if keys == {"kind", "atoms"}:
            names = e["atoms"]
            if not isinstance(names, list) or not names:
                raise ReadingError(f"{where}: {g}'s atoms: expected a list")
            primes = {len(a) - len(a.rstrip("'")) for a in names}
            base = [a.rstrip("'") for a in names]
            groups = [atoms.get(a) for a in base]
            if None in groups or len(primes) != 1:
                raise ReadingError(f"{where}: {g}'s atoms are not the certificate's atoms")
            if any(grp["kind"] != e["kind"] for grp in groups):
                raise ReadingError(f"{where}: {g} is declared {e['kind']} but its atoms' "
                                   f"group is {groups[0]['kind']}")
            k = primes.pop()
            if k:
                out.append(("rate-of", g, k, e["kind"], tuple(base)))
            else:
                out.append(("kind", g, e["kind"], len(names),
                            any(bool(grp.get("timed")) for grp in groups)))
        elif keys == {"cpm_of"}:
            out.append(("cpm", g, e["cpm_of"]))
        elif "latex" in keys or "particles" in keys:
            if keys - {"latex", "model", "printed_as", "family", "reads_as", "unit",
                       "particles"}:
                raise ReadingError(f"{where}: {g}'s line has keys the reading cannot give: "
                                   f"{sorted(keys)}")
            particles = e.get("particles") or []
            out.append(("model", g, None if particles else _nospace(str(e.get("latex", ""))),
                        e.get("model", ""), e.get("printed_as", ""), e.get("family", ""),
                        e.get("reads_as", ""), e.get("unit", ""),
                        json.dumps(particles, sort_keys=True)))
        else:
            raise ReadingError(f"{where}: {g}'s line has keys the reading cannot give: "
                               f"{sorted(keys)}")
    return out


def _said(x: tuple) -> str:
    if x[0] == "kind":
        return f"{x[1]}{'(t)' if x[4] else ''}: {x[2]} of {x[3]} atoms"
    if x[0] in ("rate", "rate-of"):
        return f"{x[1]}: rate {x[2]}"
    if x[0] == "cpm":
        return f"{x[1]} = CPM({x[2]})"
    return f"{x[1]} = {x[2]}" + (f" [{x[3]}]" if x[3] else "") + (f" cites {x[4]}" if x[4] else "")


def bind(cert: dict, reading: dict) -> list[str]:
    """Hold a certificate to the reading: its tables and its class.

    Returns:
        The lines to print (what was bound).

    Raises:
        ReadingError: an id the reading does not list, a verdict of another class than the
            reading's, a symbol line (top-level or a relation's) that is not the reading's,
            a line of the reading the certificate lacks, a rate whose atoms are not its
            glyph's.
    """
    i = str(cert.get("id"))
    where = f"({i})"
    cls = reading["classes"].get(i)
    if cls is None:
        raise ReadingError(f"{where}: not an id of the reading (its class is not given)")
    verdict = cert.get("verdict")
    if (verdict == "definition") != (cls == "definition"):
        raise ReadingError(f"{where}: the certificate says {verdict}, the reading prints the "
                           f"id as a {cls}")
    atoms = {}
    for grp in cert.get("atoms") or []:
        for a in grp.get("names", []):
            atoms[a] = grp
    tables = [("", cert.get("symbols") or [])]
    tables += [(str(r.get("label", "")), r["symbols"]) for r in cert.get("relations") or []
               if isinstance(r, dict) and "symbols" in r]
    given = {rel for (j, rel) in reading["lines"] if j == i}
    seen, n, named = set(), 0, set()
    top = [e for e in tables[0][1] if isinstance(e, dict)]
    first: dict = {}
    for rel, table in tables:
        here = where + (f" relation '{rel}'" if rel else "")
        if rel in first:  # a relation printed and claimed under one label: one table
            if table != first[rel]:
                raise ReadingError(f"{here}: two different tables under one label")
            continue
        first[rel] = table
        have = _cert_lines(cert, table, atoms, here)
        lines = top + [e for e in table if isinstance(e, dict)] if rel else top
        bases = {e["glyph"]: (e.get("kind"), tuple(e.get("atoms") or ())) for e in lines
                 if "kind" in e and not any(str(a).endswith("'") for a in e.get("atoms") or ())}
        _check(reading["lines"].get((i, rel), []), have, bases, here)
        seen.add(rel)
        n += len(have)
        named |= {str(a).rstrip("'") for e in table if isinstance(e, dict)
                  for a in e.get("atoms") or ()}
    _sources(cert, reading.get("atoms_of", {}).get(i, {}), top, where)
    missing = sorted(given - seen)
    if missing:
        raise ReadingError(f"{where}: the reading gives relation '{missing[0]}' its own lines; "
                           "the certificate has no such relation table")
    for grp in cert.get("atoms") or []:
        if not set(grp.get("names", [])) <= named:
            raise ReadingError(f"{where}: atom group {grp.get('group')!r} is named by no "
                               "line of the reading (its kind would be the certificate's word)")
    return [f"reading: {n} symbol lines and the class ({cls}) are the reading's"]


def _family(prefix: str, names: list[str]) -> list[str]:
    found = []
    for n in names:
        rest = n[len(prefix):] if n.startswith(prefix) else ""
        rest = rest[1:] if rest.startswith("_") else rest
        if rest.isdigit():
            found.append((int(rest), n))
    return [n for _, n in sorted(found)]


def _sources(cert: dict, sources: dict, top: list, where: str) -> None:
    """Each glyph the reading gives ``atoms_of``: its line's atoms are those (another
    glyph's, a model scalar, a model array's entries in index order)."""
    names = [n for g in cert.get("atoms") or [] for n in g.get("names", [])]
    lines = {e["glyph"]: e for e in top if "kind" in e}
    for glyph, src in sources.items():
        if src.endswith("_*"):
            want = _family(src[:-2], names)
        elif src in lines and src != glyph:
            want = list(lines[src].get("atoms") or [])
        else:
            want = [src]
        have = list((lines.get(glyph) or {}).get("atoms") or [])
        if not want or have != want:
            raise ReadingError(f"{where}: {glyph}'s atoms are not those the reading names "
                               f"({src})")


def _check(want: list, have: list, bases: dict, where: str) -> None:
    """``want`` (the reading's) and ``have`` (the certificate's) are the same lines; a rate
    is the rate of the glyph the reading names (``bases``: glyph -> (kind, atoms)): its atoms
    those atoms primed, its kind theirs."""
    used: set = set()
    for x in want:
        if x[0] == "rate":
            _, g, k, of = x
            hit = next((n for n, y in enumerate(have) if n not in used and y[0] == "rate-of"
                        and y[1] == g and y[2] == k), None)
            if hit is None or of not in bases or have[hit][3:] != bases[of]:
                raise ReadingError(f"{where}: the reading's '{g}: rate of {of}' is not the "
                                   "certificate's line (its atoms must be those of "
                                   f"{of}, primed {k} time(s), of its kind)")
        else:
            hit = next((n for n, y in enumerate(have) if n not in used and y == x), None)
            if hit is None:
                near = next((y for y in have if y[1] == x[1]), None)
                raise ReadingError(f"{where}: the line of {x[1]} is not the reading's "
                                   f"(reading: {_said(x)}; certificate: "
                                   f"{_said(near) if near else 'no line'})")
        used.add(hit)
    extra = [y for n, y in enumerate(have) if n not in used]
    if extra:
        raise ReadingError(f"{where}: a symbol line the reading does not give: "
                           f"{_said(extra[0])}")
