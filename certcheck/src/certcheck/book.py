"""Bind certificates to the page and a folder to one run.

- :func:`locate`: the printed text of an id in the book's text (the referee's copy; never
  shipped): the display ``$$ ... $$`` tagged ``(3.xx)`` or ``\\tag{3.xx}``, its tag cut
  off, or the paragraph of ``**Theorem 3.x.y.**``; a reader's own id ``ns:name`` in a
  reader's own text likewise, tagged ``\\tag{ns:name}`` or ``(ns:name)``
  (:data:`READER_ID`); a document's relations are located by
  :mod:`certcheck.document`.
- :func:`check_page`: a certificate's ``book_latex`` is that text (spaces collapsed, a
  closing comma or full stop dropped; a theorem's words a part of its paragraph), and the
  cause of a does-not-hold is one of the three classes, a conversion slip with its
  declared page reading; a relation's members held to the page's words and, where it says
  "In the first two cases", to the displays defining each case.
- :func:`check_manifest`: ``MANIFEST.json`` lists the SHA-256 of every certificate of the
  folder and of the book text, so a folder is one run of ``rigidsym verify``.
"""

from __future__ import annotations

import hashlib
import json
import os
import re

from certcheck.alternatives import check_units

__all__ = ["BookError", "locate", "check_page", "check_manifest", "sha256", "CAUSES",
           "definitions_before", "symbol_words", "READER_ID"]

#: the causes of a does-not-hold a certificate may give
CAUSES = ("book erratum", "conversion slip", "undetermined")

#: a reader's own id, ``namespace:name`` (rigidsym's user ids): printed in a reader's text
READER_ID = re.compile(r"[a-z][a-z0-9_-]*:[A-Za-z0-9_.-]+")

_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.S)
_TAG = re.compile(r"\s*(?:\\quad\s*)?(?:\\tag\{[^}]*\}|\((?:3\.\d+[a-z]?)"
                  r"(?:\s*,\s*3\.\d+[a-z]?)*\)|\(" + READER_ID.pattern + r"\))\s*$")


class BookError(Exception):
    """A certificate or a folder is not bound to the page or to one run (says why)."""


def sha256(data: bytes) -> str:
    """The SHA-256 of ``data`` in hexadecimal."""
    return hashlib.sha256(data).hexdigest()


def _tagged(eq_id: str) -> re.Pattern:
    return re.compile(r"(?:\(\s*|\\tag\{)" + re.escape(eq_id) + r"\s*[)}]")


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip().rstrip(",.").strip()


def locate(book: str, eq_id: str) -> str:
    """The printed text of ``eq_id`` (``3.16``, ``3.96e``, ``thm3.2.1``) in ``book``.

    Raises:
        BookError: the id is printed nowhere, or in more than one display.
    """
    prose = re.fullmatch(r"(thm|cor|caveat)(3\.[\d.]+)", eq_id)
    if prose:  # a theorem's, corollary's or caveat's paragraph
        word = {"thm": "Theorem", "cor": "Corollary", "caveat": "Caveat"}[prose.group(1)]
        num = "" if word == "Caveat" else " " + re.escape(prose.group(2)) + r"[. ]"
        head = re.compile(r"\*\*" + word + num)
        hits = [line for line in book.splitlines() if head.match(line)]
    else:
        hits = [_TAG.sub("", d) for d in _DISPLAY.findall(book) if _tagged(eq_id).search(d)]
    if len(hits) != 1:
        raise BookError(f"({eq_id}) is printed in {len(hits)} places of the book, not one")
    return _norm(hits[0])


def definitions_before(book: str, eq_id: str) -> dict:
    """The glyphs defined on the page before ``eq_id``'s display, the nearest last: glyph
    (spaces removed) -> ``(its printed definition's right side, the defining id, the sign)``,
    from every tagged display ``G \\equiv rhs`` or ``G = rhs`` (a bare glyph on the left,
    one relation) above it; ``\\equiv`` is a definition, ``=`` an equation of the page whose
    certificate the referee checks too (so a side read through it that differs from the
    certificate's is NOT READ, not a rejection: the model's glyph may be another's)."""
    out: dict = {}
    for m in _DISPLAY.finditer(book):
        if _tagged(eq_id).search(m.group(1)):
            break
        tags = re.findall(r"(?:\((3\.\d+[a-z]?)\)|\\tag\{(3\.\d+[a-z]?)\})\s*$", m.group(1))
        if not tags:
            continue
        for part in re.split(r",\s*\\quad", _TAG.sub("", m.group(1))):
            for sign in ("\\equiv", "="):  # an equation G = rhs: a definition read second
                lhs, eq, rhs = part.partition(sign)
                key = lhs.replace(" ", "").strip("&").removesuffix("(t)")  # p(t): p
                if eq and re.fullmatch(_GLYPH, key) and "\\equiv" not in rhs and "=" not in rhs \
                        and (sign != "=" or out.get(key, ("", "", "="))[2] == "="):
                    out[key] = (_norm(rhs), tags[0][0] or tags[0][1], sign)
                    break
    return out


# a bare glyph: bold or Greek, with a dot, a prime or a subscript
_GLYPH = (r"(\\dot\{|\\ddot\{)?\\(mathbf|boldsymbol)\{[^{}]*\}\}?(_\{?\w+\}?)?'*"
          r"|\\?\w+(_\{?\w+\}?)?")


def check_page(cert: dict, book: str, printed: str | None = None) -> list[str]:
    """The certificate's id, printed text and cause against the page; lines to print.

    Args:
        cert: the certificate.
        book: the page's text.
        printed: the relation a document prints under the id
            (:func:`certcheck.document.locate`), ``None``: the id's display, found by
            :func:`locate`.

    Raises:
        BookError: ``book_latex`` is not the text printed as the certificate's id, or a
            does-not-hold gives no cause of :data:`CAUSES`.
    """
    eq_id = str(cert.get("id", ""))
    book_id = re.fullmatch(r"3\.\d+[a-z]?|(thm|cor)3\.\d\.\d|caveat3\.\d", eq_id)
    # a reader's own id: printed in their text
    if printed is None and not book_id and not READER_ID.fullmatch(eq_id):
        if cert.get("book_latex"):
            raise BookError(f"({eq_id}): not a printed id, yet it gives a printed text")
        return [f"({eq_id}) is the project's own statement (not printed in the book): bound "
                "to no page"] + cause_lines(cert)
    page = locate(book, eq_id) if printed is None else _norm(printed)
    latex = _norm(str(cert.get("book_latex") or ""))
    bound = latex == page or (printed is None and not eq_id[0].isdigit() and len(latex) >= 20
                              and latex in page)  # a document's relation: exactly its text
    if not bound:
        where = next((i for i, (a, b) in enumerate(zip(latex, page, strict=False)) if a != b),
                     min(len(latex), len(page)))
        raise BookError(f"({eq_id}): book_latex is not the text printed as ({eq_id}); they "
                        f"differ from character {where}: certificate {latex[where:where + 50]!r}"
                        f", page {page[where:where + 50]!r}")
    for s in cert.get("symbols") or []:  # a citation of this chapter: its display prints it
        cited = str(s.get("printed_as", "")).strip("()") if isinstance(s, dict) else ""
        if re.fullmatch(r"3\.\d+[a-z]?", cited) and not _prints(locate(book, cited), s):
            raise BookError(f"({eq_id}): symbol {s.get('glyph')} cited as printed in "
                            f"({cited}), which does not print {s.get('latex')!r}")
    fam = [r for r in cert.get("relations") or [] if isinstance(r, dict) and
           r.get("role") == "printed" and r.get("symbols")]  # F = N, L, H: every member
    if fam and cert.get("verdict") != "does-not-hold":
        _family(eq_id, fam, book, page)
    lines = [f"printed as ({eq_id}): {page if len(page) < 400 else page[:400] + ' ...'}"]
    lines += [f"symbol: {symbol_words(s)}" for s in cert.get("symbols") or []]
    lines += [f"symbol of {r.get('label')}: {symbol_words(s)}" for r in cert.get("relations")
              or [] if isinstance(r, dict) for s in r.get("symbols") or []]
    return lines + cause_lines(cert)


def _family(eq_id: str, fam: list, book: str, page: str = "") -> None:
    """Each member of a family carries its own lines; of each glyph the page's words list
    ("$F$ is one of $N$, $L$, or $H$") every listed glyph is one member's line, each once, and
    the words list one at least: a member dropped, or replaced by another's copy, leaves a
    relation the page prints uncarried, a failure naming the id."""
    words: dict = {}  # the first list the page's words give each glyph, spaces removed
    for m in re.finditer(r"\$\s*([^$]+?)\s*\$\s+is(?:,\s*correspondingly,|\s+one of)\s+"
                         r"((?:\$[^$]+\$\s*,?\s*(?:or\s+)?)+)", book):
        words.setdefault(m.group(1).replace(" ", ""), [
            x.replace(" ", "") for x in re.findall(r"\$([^$]+)\$", m.group(2))])
    lines = [{str(s.get("glyph")).replace(" ", ""): str(s.get("latex")).replace(" ", "")
              for s in r["symbols"] if isinstance(s, dict)} for r in fam]
    named = [(g, words[g]) for g in dict.fromkeys(k for m in lines for k in m) if g in words]
    if not named and (_cases(eq_id, lines, book) or check_units(eq_id, fam, book, page)):
        return
    for g, listed in named or [("its glyphs", ["a member"])]:  # words list none: a failure
        carried = [m.get(g) for m in lines]
        if sorted(listed) != sorted(map(str, carried)):
            x = next((x for x in listed if x not in carried), None)
            raise BookError(f"({eq_id}): " + (f"the certificate carries {len(carried)} "
                            f"members of {g}, the page's words {len(listed)}" if x is None else
                            f"the page prints the relation for {g} = {x} (its words list "
                            f"{len(listed)}), which the certificate does not carry"))


def _cases(eq_id: str, lines: list, book: str) -> bool:
    """The words "In the first k cases" between the id and the tagged display above it: the
    members are those k cases, the untagged displays there (``G \\equiv X, \\quad ...``),
    in order, each member's lines exactly its case's definitions (False: no such words)."""
    text = book[:next(m.start() for m in _DISPLAY.finditer(book) if _tagged(eq_id).search(m[1]))]
    text = text[max((m.end() for m in _DISPLAY.finditer(text) if _TAG.search(m[1])), default=0):]
    k = re.search(r"[Ii]n the first (two|three|four) cases", text)
    cases = [dict(p.replace(" ", "").split("\\equiv", 1) for p in re.split(r",\s*\\quad", d)
                  if "\\equiv" in p) for d in _DISPLAY.findall(text)]
    if k and lines != cases[:("two", "three", "four").index(k[1]) + 2]:
        raise BookError(f"({eq_id}): the page prints the relation in the first {k[1]} cases "
                        "above it, each defining its glyphs: the members' lines are not those")
    return bool(k)


def _prints(display: str, s: dict) -> bool:
    """``display`` prints the symbol line's glyph and its text (spaces aside)."""
    return all(re.sub(r"\s+", "", str(s.get(k))) in re.sub(r"\s+", "", display)
               for k in ("glyph", "latex"))


def symbol_words(s) -> str:
    """A symbol-table line in words (glyph: what it stands for)."""
    if not isinstance(s, dict):
        return repr(s)
    if "particles" in s:  # section 3.8's body: its model and each particle's glyphs
        return f"{s.get('glyph')}: {s.get('model')}; particles " + "; ".join(
            ", ".join(f"{g} = {x}" for g, x in p.items()) for p in s["particles"])
    if "cpm_of" in s:
        return f"{s.get('glyph')}: the cross-product matrix of {s['cpm_of']}"
    if "latex" in s and "model" in s:
        return f"{s.get('glyph')}: {s['latex']} (the model's {s['model']})"
    if "latex" in s:
        return f"{s.get('glyph')}: printed as {s.get('printed_as', '?')}: {s['latex']}" + (
            f", in {s['unit']}" if "unit" in s else "")  # an alternative's unit (m/turn)
    if "defined_by" in s:
        return f"{s.get('glyph')}: defined by ({s['defined_by']})"
    return f"{s.get('glyph')}: {s.get('kind')}, atoms {', '.join(s.get('atoms', []))}"


def cause_lines(cert: dict) -> list[str]:
    """The cause of a does-not-hold in words (none for another verdict).

    Raises:
        BookError: a does-not-hold without a cause of :data:`CAUSES`, a conversion slip
            without its page reading, or a cause on another verdict.
    """
    eq_id, cause = cert.get("id"), cert.get("cause")
    if cert.get("verdict") != "does-not-hold":
        if cause:
            raise BookError(f"({eq_id}): a {cert.get('verdict')} has no cause, {cause!r} given")
        return []
    if not isinstance(cause, dict) or cause.get("class") not in CAUSES:
        raise BookError(f"({eq_id}): a does-not-hold needs a cause, one of {', '.join(CAUSES)}"
                        f"; got {cause!r}")
    out = [f"cause: {cause['class']}: {cause.get('why', '')}".rstrip(": ")]
    if cause["class"] == "conversion slip":
        reading = cause.get("page_reading")
        if not reading:
            raise BookError(f"({eq_id}): a conversion slip names the page's declared reading")
        out.append(f"the page's declared reading (a conjecture about the printed page, the "
                   f"source being a converted text): {reading}")
    if not any(r.get("role") == "corrected" for r in cert.get("relations", [])):
        out.append("corrected form: none declared")
    return out


def check_manifest(folder: str, files: list[str], book: bytes | None,
                   whole: bool = True, reading: str | None = None) -> list[str]:
    """``folder/MANIFEST.json`` against the folder's certificates and the book.

    Args:
        folder: the folder of certificates.
        files: the certificate files that will be checked (paths).
        book: the book's bytes, or ``None`` when no book is given.
        whole: the folder was given (every listed certificate must be there), not some of
            its files (each of them must still be listed, with its SHA-256).
        reading: the SHA-256 of the reading given, or ``None``: the manifest must state it.

    Raises:
        BookError: no manifest, a certificate missing from it, listed but absent, or whose
            SHA-256 differs, or a book whose SHA-256 is not the manifest's.
    """
    path = os.path.join(folder, "MANIFEST.json")
    try:
        with open(path, encoding="utf-8") as f:
            man = json.load(f)
    except (OSError, ValueError) as exc:
        raise BookError(f"{folder}: no readable MANIFEST.json ({exc})") from None
    listed = dict(man.get("certificates") or {})
    names = {os.path.basename(p): p for p in files}
    for name in sorted(set(names) | set(listed)):
        if name not in listed:
            raise BookError(f"{name}: not in MANIFEST.json (not of this run)")
        if name not in names and not whole:
            continue
        if name not in names:
            raise BookError(f"{name}: listed in MANIFEST.json, absent from the folder")
        with open(names[name], "rb") as f:
            if sha256(f.read()) != listed[name]:
                raise BookError(f"{name}: its SHA-256 is not the manifest's (changed after "
                                "the run)")
    lines = [f"manifest: {len(listed)} certificates of one run of rigidsym "
             f"{man.get('rigidsym', '?')}"]
    if book is not None:
        if man.get("book_sha256") != sha256(book):
            raise BookError(f"the book given has SHA-256 {sha256(book)[:16]}..., the run's "
                            f"was {str(man.get('book_sha256'))[:16]}...")
        lines.append(f"manifest: the book text's SHA-256 {sha256(book)[:16]}... is the run's")
    if reading is not None:
        if man.get("reading_sha256") != reading:
            raise BookError(f"the reading given has SHA-256 {reading[:16]}..., the run's was "
                            f"{str(man.get('reading_sha256'))[:16]}...")
        lines.append(f"manifest: the reading's SHA-256 {reading[:16]}... is the run's")
    return lines
