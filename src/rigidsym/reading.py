"""The reading of a page as data: what a person decided a text means, one TOML file per text.

Three things are kept apart: the *page* (the text, read verbatim, never edited), the
*reading* (this file: each glyph's kind or model, the conventions, each id's class, where
the page says it) and the *evidence* (what rigidsym computes). A statement is built from
page and reading only. The same format serves the chapter and a reader's own notes; its
words are those of ``--let`` (``docs/reading-files.md`` is the reference)::

    [reading]
    format = 1
    page = "notes.md"                      # the text this is the reading of (relative)
    glyphs = "notes.glyphs.csv"            # optional: its glyph table (relative); the
                                           # book's is read by the LaTeX reader for the
                                           # declarations' LaTeX and --book SECTION

    [conventions]                          # each said back in every report
    quaternion_product = "hamilton"        # or "jpl", "hamilton-scalar-last"
    tangent_order = "angular-first"        # or "linear-first"

    [[let]]                                # one declaration, in --let's words
    let = '\\mathbf{e}: unit vector'
    where = "the words after (1): the unit vector e"

    [[let]]
    let = '\\mathbf{E} = \\mathrm{CPM}(\\mathbf{e})'
    where = "(2)"
    scope = "2"                            # optional: a section; the let holds in it only

    [classes]                              # what the page prints each id as
    relation = ["1", "3"]                  # relation | definition | theorem | not-checked
    definition = ["2"]

    [id."2"]                               # optional: a note on one id
    class = "definition"
    where = "printed with \\equiv"

Every key is checked: an unknown key, table or value is an error naming it and the file
(fail closed: what could not be read is never taken as "nothing said").
"""

from __future__ import annotations

import hashlib
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from rigidsym.core.errors import BadInput

__all__ = ["CLASSES", "CONVENTIONS", "FORMAT", "IdReading", "Let", "Reading", "lets_for",
           "glyph_file", "load_reading", "parse_reading", "reading_sha256", "sidecar"]

#: the format this module reads (``[reading] format``)
FORMAT = 1
#: the conventions a reading may fix, each with the values it admits
CONVENTIONS: dict[str, tuple[str, ...]] = {
    "quaternion_product": ("hamilton", "jpl", "hamilton-scalar-last"),
    "quaternion_order": ("scalar-first", "scalar-last"),
    "tangent_order": ("angular-first", "linear-first"),
    "rotation": ("active", "passive"),
    "euler_sequence": ("zyx", "zyz", "xyz", "zxz", "xyx", "yzy", "xzy", "yxz", "yzx",
                       "zxy", "xzx", "yxy"),
    "cross_product_bracket": ("content", "binding"),
}
#: an id's class as the page prints it
CLASSES = ("relation", "definition", "theorem", "not-checked")
_LET_KEYS = {"let", "where", "scope", "ids", "cites", "family", "reads_as", "particles",
             "relation", "unit", "atoms_of"}
_ID_KEYS = {"class", "where", "relations", "page_reading", "words", "states", "why"}
_TOP = {"reading", "conventions", "let", "id", "classes"}


@dataclass(frozen=True)
class Let:
    """One declaration of a reading.

    Attributes:
        let: the declaration in ``--let``'s words (``"\\mathbf{e}: unit vector"``).
        where: where the page says it (free text for a reviewer), ``""`` if not given.
        scope: the section it holds in, ``None`` for the whole text.
        ids: the ids it is for (``()``: every id of its scope).
        line: its ``[[let]]`` entry's number, from 1 (for messages).
        cites: the display of another text the page reproduces for it (``"(2.49)"``).
        family: the indices of a family the page states in words (``"ij"``: i, j = 1, 2, 3).
        reads_as: how a run-together of the converted text is read (``"text"``).
        relation: the one relation of the id it holds for (a member of a family or a unit
            alternative: ``"p in m/rad"``), ``""`` for the whole id.
        unit: the unit the glyph is read in for that relation (``"m/turn"``).
        atoms_of: for a kind, where its values come from when the glyph is not a model
            symbol's own: another glyph (``"\\mathbf{o}"``: ``[\\mathbf{o}]_{\\mathcal{F}}``,
            o's components in F), a model scalar (``"ell"``) or a model array, its entries
            in index order (``"s38_P_*"``).
        particles: a body of point masses: per particle, the glyphs it gives values to.
    """

    let: str
    where: str = ""
    scope: str | None = None
    ids: tuple[str, ...] = ()
    line: int = 0
    cites: str = ""
    family: str = ""
    reads_as: str = ""
    relation: str = ""
    unit: str = ""
    atoms_of: str = ""
    particles: tuple[tuple[tuple[str, str], ...], ...] = ()


@dataclass(frozen=True)
class IdReading:
    """What the page prints one id as.

    Attributes:
        id: the id (``"3.77b"``, a label of a document).
        cls: one of :data:`CLASSES`.
        where: where the page says so.
        relations: the number of relations the page prints under the id, ``None`` if not
            stated.
        page_reading: for a slip of a converted text, what the printed page is read to show
            and how that reading was decided (``"verified: ..."`` or ``"its own erratum:
            ..."``), ``""`` if none.
        words: for a theorem in words, its statement as the page prints it.
        states: the relation(s) those words state, in the page's glyphs (LaTeX).
        why: why the relation is what the words say, no stronger, no weaker.
    """

    id: str
    cls: str
    where: str = ""
    relations: int | None = None
    page_reading: str = ""
    words: str = ""
    states: str = ""
    why: str = ""


@dataclass(frozen=True)
class Reading:
    """A reading file, checked.

    Attributes:
        path: the file (``None`` for a reading parsed from text).
        sha256: the SHA-256 of the file's bytes (hex).
        page: the page it reads, relative to the file (``None`` if not named).
        glyphs: its glyph table, a CSV relative to the file (``None`` if not named):
            each glyph's name, shape and kind per section (:mod:`rigidsym.latex.table`).
            The book's reading's is the one the LaTeX reader consults (a declaration's
            LaTeX, ``check --latex --book``); a document's relations take their glyphs
            from its ``[[let]]`` lines.
        conventions: the conventions it fixes (keys of :data:`CONVENTIONS`).
        lets: its declarations, in order.
        ids: what it says of ids, by id.
    """

    path: Path | None
    sha256: str
    page: str | None
    conventions: dict[str, str] = field(default_factory=dict)
    lets: tuple[Let, ...] = ()
    ids: dict[str, IdReading] = field(default_factory=dict)
    glyphs: str | None = None


def reading_sha256(data: bytes) -> str:
    """The SHA-256 (hex) of a reading file's bytes, as a run's manifest states it."""
    return hashlib.sha256(data).hexdigest()


def _bad(where: str, what: str) -> BadInput:
    return BadInput(f"reading {where}: {what}")


def _text(value, where: str, key: str, *, allow_empty: bool = False) -> str:
    if not isinstance(value, str) or (not allow_empty and not value.strip()):
        raise _bad(where, f"{key} must be a non-empty string, got {value!r}")
    return value


def parse_reading(data: bytes | str, *, path: Path | None = None) -> Reading:
    """A reading from its TOML text.

    Args:
        data: the file's bytes (or text; a UTF-8 byte-order mark is allowed).
        path: where it came from (named in messages).

    Returns:
        The :class:`Reading`.

    Raises:
        BadInput: TOML that does not parse, a format other than :data:`FORMAT`, an unknown
            key, table, convention or class, a declaration that is not a non-empty string,
            an id described twice (each message names the file and the key).
    """
    raw = data.encode("utf-8") if isinstance(data, str) else bytes(data)
    where = str(path) if path is not None else "<text>"
    try:
        doc = tomllib.loads(raw.decode("utf-8-sig"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise _bad(where, f"not TOML: {exc}") from None
    unknown = sorted(set(doc) - _TOP)
    if unknown:
        raise _bad(where, f"unknown table or key {unknown[0]!r}; expected "
                          f"{', '.join(sorted(_TOP))}")
    head = doc.get("reading")
    if not isinstance(head, dict) or head.get("format") != FORMAT:
        raise _bad(where, f"expected a [reading] table with format = {FORMAT}")
    extra = sorted(set(head) - {"format", "page", "title", "glyphs"})
    if extra:
        raise _bad(where, f"[reading]: unknown key {extra[0]!r}")
    page = head.get("page")
    if page is not None:
        _text(page, where, "[reading] page")
    glyphs = head.get("glyphs")
    if glyphs is not None:
        _text(glyphs, where, "[reading] glyphs")
    conventions = doc.get("conventions", {})
    if not isinstance(conventions, dict):
        raise _bad(where, "[conventions] must be a table")
    for key, value in conventions.items():
        if key not in CONVENTIONS:
            raise _bad(where, f"[conventions]: unknown convention {key!r}; expected one of "
                              f"{', '.join(CONVENTIONS)}")
        if value not in CONVENTIONS[key]:
            raise _bad(where, f"[conventions] {key} = {value!r}; expected one of "
                              f"{', '.join(CONVENTIONS[key])}")
    lets = _lets(doc, where)
    ids_out = _ids(doc, where)
    return Reading(path, reading_sha256(raw), page, dict(conventions), tuple(lets), ids_out,
                   glyphs)



def _lets(doc: dict, where: str) -> list[Let]:
    """The ``[[let]]`` entries of a parsed reading, checked."""
    lets = []
    entries = doc.get("let", [])
    if not isinstance(entries, list):
        raise _bad(where, "let must be an array of tables [[let]]")
    for n, entry in enumerate(entries, start=1):
        here = f"[[let]] {n}"
        if not isinstance(entry, dict):
            raise _bad(where, f"{here} must be a table")
        extra = sorted(set(entry) - _LET_KEYS)
        if extra:
            raise _bad(where, f"{here}: unknown key {extra[0]!r}; expected "
                              f"{', '.join(sorted(_LET_KEYS))}")
        text = _text(entry.get("let"), where, f"{here} let")
        ids = entry.get("ids", [])
        if not isinstance(ids, list) or not all(isinstance(i, str) and i for i in ids):
            raise _bad(where, f"{here} ids must be a list of ids")
        scope = entry.get("scope")
        if scope is not None:
            _text(scope, where, f"{here} scope")
        extras = {k: _text(entry.get(k, ""), where, f"{here} {k}", allow_empty=True)
                  for k in ("cites", "family", "reads_as", "relation", "unit",
                                    "atoms_of")}
        particles = entry.get("particles", [])
        if not isinstance(particles, list) or not all(
                isinstance(p, dict) and all(isinstance(v, str) for v in p.values())
                for p in particles):
            raise _bad(where, f"{here} particles must be a list of tables of strings")
        lets.append(Let(text.strip(), _text(entry.get("where", ""), where, f"{here} where",
                                            allow_empty=True),
                        scope, tuple(ids), n, **extras,
                        particles=tuple(tuple(sorted(p.items())) for p in particles)))
    return lets


def _ids(doc: dict, where: str) -> dict[str, IdReading]:
    """What a parsed reading says of ids (``[classes]``, ``[id."..."]``), checked."""
    ids_out: dict[str, IdReading] = {}
    classes = doc.get("classes", {})
    if not isinstance(classes, dict):
        raise _bad(where, "[classes] must be a table of class = [ids]")
    for cls, members in classes.items():
        if cls not in CLASSES:
            raise _bad(where, f"[classes]: unknown class {cls!r}; expected one of "
                              f"{', '.join(CLASSES)}")
        if not isinstance(members, list) or not all(isinstance(i, str) for i in members):
            raise _bad(where, f"[classes] {cls} must be a list of ids")
        for i in members:
            if i in ids_out:
                raise _bad(where, f"[classes]: {i!r} is given two classes")
            ids_out[i] = IdReading(i, cls)
    ids_table = doc.get("id", {})
    if not isinstance(ids_table, dict):
        raise _bad(where, "id must be a table of ids ([id.\"ID\"])")
    for i, entry in ids_table.items():
        here = f"[id.{i!r}]"
        if not isinstance(entry, dict):
            raise _bad(where, f"{here} must be a table")
        extra = sorted(set(entry) - _ID_KEYS)
        if extra:
            raise _bad(where, f"{here}: unknown key {extra[0]!r}")
        cls = entry.get("class")
        if cls not in CLASSES:
            raise _bad(where, f"{here} class = {cls!r}; expected one of {', '.join(CLASSES)}")
        rel = entry.get("relations")
        if rel is not None and (not isinstance(rel, int) or isinstance(rel, bool) or rel < 1):
            raise _bad(where, f"{here} relations must be a positive integer")
        if i in ids_out and ids_out[i].cls != cls:
            raise _bad(where, f"{here} class {cls!r} but [classes] gives {ids_out[i].cls!r}")
        ids_out[i] = IdReading(i, cls, _text(entry.get("where", ""), where, f"{here} where",
                                             allow_empty=True), rel,
                               *(_text(entry.get(k, ""), where, f"{here} {k}", allow_empty=True)
                                 for k in ("page_reading", "words", "states", "why")))
    return ids_out


def load_reading(path: str | Path) -> Reading:
    """The reading file at ``path``.

    Raises:
        BadInput: the file is missing or unreadable (naming it), or as :func:`parse_reading`.
    """
    p = Path(path)
    try:
        data = p.read_bytes()
    except OSError as exc:
        raise BadInput(f"reading {p}: cannot read the file ({exc.strerror})") from None
    return parse_reading(data, path=p)


def glyph_file(reading: Reading) -> Path | None:
    """The glyph table a reading names (``[reading] glyphs``), beside the reading file.

    Returns:
        Its path, or ``None`` where the reading names none.

    Raises:
        BadInput: the reading names a table but was parsed from text (no file to be
            beside), naming the key.
    """
    if reading.glyphs is None:
        return None
    if reading.path is None:
        raise BadInput(f"reading <text>: [reading] glyphs = {reading.glyphs!r} names a file, "
                       f"but the reading has no path to find it beside")
    return reading.path.parent / reading.glyphs


def sidecar(page: str | Path) -> Path:
    """The reading file beside a page: ``notes.md`` -> ``notes.reading.toml``."""
    p = Path(page)
    return p.with_name(p.stem + ".reading.toml")


def lets_for(reading: Reading, *, scope: str | None = None, id: str | None = None) -> list[str]:
    """The declarations of ``reading`` that hold in ``scope`` for ``id``, in ``--let`` words.

    A declaration with no scope holds everywhere; one with a scope holds in that section
    and its subsections (``"3.2"`` holds in ``"3.2.1"``); one with ids holds for those only.
    """
    out = []
    for x in reading.lets:
        if x.scope is not None and (scope is None or not (
                scope == x.scope or scope.startswith(x.scope + "."))):
            continue
        if x.ids and (id is None or id not in x.ids):
            continue
        out.append(x.let)
    return out
