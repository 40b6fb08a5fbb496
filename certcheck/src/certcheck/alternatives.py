"""A display that defines one glyph twice, its alternatives joined by ``\\quad \\text{or}
\\quad``, each in its own unit ((3.7), (3.53), (3.109): ``p \\equiv X \\quad \\text{or}
\\quad p \\equiv Y``, "which has units of m/rad or, correspondingly, of m/turn").

One table line of ``p`` cannot serve both (``X = Y`` only where the pitch vanishes), so each
certificate relation of an alternative carries its own line of ``p``:

- :func:`check_units` (the page): the words after the display name one unit per
  alternative; the relations' lines, in order, are the alternatives' in order, each the
  glyph the display defines, printed as its alternative's first member (verbatim, spaces
  aside), with that alternative's unit; an alternative dropped, swapped, copied or changed
  is a failure naming the id.
- :func:`read_alternatives` (the reader): each alternative read under the table and its own
  line, the page's relations assigned to the certificate's in order; the relations of one
  alternative carry one line, or the reading fails.

The glyph is read through the page's own definiens: what a definition can be held to (the
certificate's side for ``p`` is the page's definiens under the lines of ``d_0``, ``v_0``,
``n_0``, in the alternative's unit); the chain's other members are read against it.
"""

from __future__ import annotations

import re

__all__ = ["alternatives", "check_units", "read_alternatives"]

_OR = re.compile(r"\\quad\s*\\text\{or\}\s*\\quad")
_UNITS = re.compile(r"units of (m/\w+) or, correspondingly, of (m/\w+)")


def alternatives(page: str) -> list[str]:
    """The display's alternatives (one: no ``\\quad \\text{or} \\quad``)."""
    return [p.strip() for p in _OR.split(page)]


def _lines(book: str, eq_id: str, page: str) -> list[dict]:
    """The line each alternative gives its glyph: the first member, the words' unit."""
    parts = alternatives(page)
    tag = re.search(r"\(\s*" + re.escape(eq_id) + r"\s*\)\s*\$\$", book)
    after = book[tag.end():].split("$$", 1)[0] if tag else ""
    units = _UNITS.search(after)
    members = [re.split(r"\\equiv|=", p) for p in parts]
    glyph = members[0][0].strip()
    if units is None or len(units.groups()) != len(parts) or any(
            len(m) < 2 or m[0].strip() != glyph for m in members):
        return []
    return [{"glyph": glyph, "latex": m[1].strip(), "printed_as": f"({eq_id})", "unit": u}
            for m, u in zip(members, units.groups(), strict=True)]


def _squash(lines: list) -> list:
    return [{k: re.sub(r"\s+", "", str(v)) for k, v in s.items()} if isinstance(s, dict)
            else s for s in lines]


def check_units(eq_id: str, fam: list, book: str, page: str) -> bool:
    """The certificate's relations with lines ``fam`` against the alternatives of ``page``
    (False: the display has one). Raises BookError: they are not the page's alternatives,
    each under its first member and unit, in order."""
    from certcheck.book import BookError

    if len(alternatives(page)) < 2:
        return False
    want = _squash(_lines(book, eq_id, page))
    got = [_squash(r.get("symbols") or []) for r in fam]
    runs = [g for k, g in enumerate(got) if k == 0 or g != got[k - 1]]
    if not want or runs != [[w] for w in want]:
        raise BookError(f"({eq_id}): the page defines {want[0]['glyph'] if want else 'a glyph'}"
                        f" in {len(alternatives(page))} alternatives, each in its unit "
                        "(the words after the display): the relations' lines are not those,"
                        " one per alternative, in order")
    return True


def read_alternatives(page: str, printed: list, symbols: list, defs: dict, lets: list,
                      read) -> list | None:
    """The page's relations, each alternative read by ``read`` (``read_relations``) under
    the table and the line its relations carry; None: one alternative, or a relation of the
    certificate's printed ones without lines (the glyph then NOT READ, as before)."""
    parts = alternatives(page)
    own = [r for r in printed if r.get("role") == "printed"]
    if len(parts) < 2 or not own or not all(r.get("symbols") for r in own):
        return None
    out, at = [], 0
    for part in parts:
        n = sum(len(c) - 1 for c in read(part, symbols, defs, []))
        lines = [r["symbols"] for r in printed[at:at + n] if r.get("role") == "printed"]
        if not lines or any(x != lines[0] for x in lines):
            raise ValueError("the relations of one alternative carry different lines, or "
                             "none")
        out += read(part, [*symbols, *lines[0]], defs, lets)
        at += n
    return out
