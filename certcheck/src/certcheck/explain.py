"""``certcheck explain ID --book BOOK DIR``: a referee's path from the page to the proof of
one id: the printed line; the symbol-table lines its glyphs use, and the lines those use in
turn (each in words: an atom group and its kind, a cross-product matrix, a formula cited,
the model's line, the body of point masses), with the displays of the page above the id
that define a glyph; what the second reader read; the relations proved, each with its
evidence; and the Coq file ``rigidsym verify --coq DIR`` writes for it.
"""

from __future__ import annotations

import argparse
import os
import re
import sys

from certcheck.book import (
    BookError,
    check_manifest,
    check_page,
    definitions_before,
    locate,
    symbol_words,
)
from certcheck.braces import displays_after
from certcheck.by_definition import unread_vacuous
from certcheck.check import CheckError, check_certificate, load
from certcheck.compare import compare
from certcheck.reader import tokens
from certcheck.reading import ReadingError, bind, load_reading
from certcheck.words import stated, use

__all__ = ["explain", "run"]


def _names(glyph: str, text: list[str]) -> bool:
    """``glyph``'s tokens stand in ``text`` (a token list) as one run, not as a sub- or
    superscript (the ``T`` of ``^T``) nor inside a longer glyph's braces."""
    g = tokens(glyph)
    n = len(g)
    return bool(g) and any(text[k:k + n] == g and (k == 0 or text[k - 1] not in "^_{") and
                           text[k + n:k + n + 1] not in (["_"], ["'"])
                           for k in range(len(text) - n + 1))


def explain(cert: dict, book: str, fast: bool = True) -> tuple[bool, list[str]]:
    """The lines of a referee's path for ``cert`` against ``book`` (the chapter's text).

    Returns:
        ``(passed, lines)``: ``passed`` is false when the certificate fails on the page or
        in the mathematics (the lines then say why), or a printed side is not read.
    """
    eq_id = str(cert.get("id"))
    defs = definitions_before(book, eq_id) if eq_id[0].isdigit() else {}
    page = stated(eq_id, text := locate(book, eq_id))  # a theorem in words: what they state
    out = [f"({eq_id}) {'stated in words' if page != text else 'printed'} as: {page}",
           "the symbol-table lines its glyphs use:"]
    table = [s for s in cert.get("symbols") or [] if isinstance(s, dict)]
    for r in cert.get("relations") or []:
        table += [s for s in r.get("symbols") or [] if isinstance(s, dict)]
    todo, used = [tokens(page)], []
    glyphs = {re.sub(r"\s", "", str(s.get("glyph"))) for s in table}  # read before defs
    while todo:  # the page's glyphs, then the glyphs of their lines and definitions
        text = todo.pop()
        for s in table:
            if s not in used and _names(str(s.get("glyph", "")), text):
                used.append(s)
                todo.append(tokens(" ".join(str(s.get(k, "")) for k in ("latex", "cpm_of"))))
        for g, (rhs, where, sign) in defs.items():
            line = f"    {g} {sign} {rhs}   (the page's ({where}))"
            if line not in out and g not in glyphs and _names(g, text):
                out.append(line)
                todo.append(tokens(rhs))
    out[2:2] = [f"    {symbol_words(s)}" for s in used]
    passed = True
    try:
        check_page(cert, book)
        verdict, lines = check_certificate(cert, fast=fast)
        read = compare(cert, page, fast=fast, defs=defs, counts=(counts := []),
                       later=displays_after(book, eq_id))
        (k, n, firm), = counts
        unread, lines_read = unread_vacuous(cert, firm)  # a vacuous relation: read, or not
        passed, read = k - 2 * unread == n, read + lines_read
    except CheckError as exc:
        return False, [*out, f"FAILED: {exc}"]
    except Exception as exc:  # noqa: BLE001 (a page or manifest error is a failure too)
        return False, [*out, f"FAILED: {type(exc).__name__}: {exc}"]
    out += ["what the second reader read from the page:", *(f"    {x}" for x in read),
            f"the relations proved ({verdict}; the lets: {len(cert.get('let', []))} named "
            "subexpressions of the file):"]
    for r in cert.get("relations") or []:
        sides = [" ; ".join(", ".join(row) for row in r.get(s, [])) for s in ("lhs", "rhs")]
        text = f"{sides[0]} = {sides[1]}"
        out.append(f"    {r.get('role')} {r.get('label') or ''}: "
                   f"{text if len(text) < 300 else text[:300] + ' ...'}")
    out += [f"    {x}" for x in lines]
    name = "eq" + re.sub(r"[^A-Za-z0-9_]", "_", eq_id) + ".v"
    out.append(f"Coq: {name} of `rigidsym verify --coq DIR` (check it with coqc -q {name}; "
               "an id Coq is not given is listed, with why, in DIR/NO-PROOF.txt)")
    return passed, out


def run(argv: list[str]) -> int:
    """``certcheck explain ID PATH --book BOOK [--reading READING]``: print one id's path
    from the page to the proof. Exit 0: it passes, read on every side; 1: it fails or a
    side is not read; 2: bad arguments (no such file, another id's file, no book)."""
    ap = argparse.ArgumentParser(prog="certcheck explain", description=__doc__.split("\n\n")[0])
    ap.add_argument("id", help="the id, as the reading names it")
    ap.add_argument("path", help="the folder of certificates (or the id's file)")
    ap.add_argument("--book", metavar="FILE", required=True, help="the book's text")
    ap.add_argument("--reading", metavar="FILE",
                    help="the reading of the book: the id's table and class bound to it, and "
                         "the theorems in words read")
    ap.add_argument("--no-flint", action="store_true", help="standard-library arithmetic only")
    args = ap.parse_args(argv)
    path = args.path if not os.path.isdir(args.path) else os.path.join(
        args.path, re.sub(r"[^A-Za-z0-9._-]", "_", args.id) + ".json")
    try:
        cert = load(path)
        with open(args.book, "rb") as f:
            book = f.read()
        reading = None
        if args.reading:
            with open(args.reading, "rb") as f:
                reading = load_reading(f.read(), args.reading)
    except (OSError, ValueError, CheckError) as exc:
        print(f"certcheck explain: {exc}", file=sys.stderr)
        return 2
    use(reading)
    if str(cert.get("id")) != args.id:
        print(f"certcheck explain: {path} holds ({cert.get('id')}), not ({args.id})",
              file=sys.stderr)
        return 2
    try:  # the file is held to its folder's manifest, as a file given to certcheck is
        check_manifest(os.path.dirname(path) or ".", [path], book, whole=False,
                       reading=None if reading is None else reading["sha256"])
    except BookError as exc:
        print(f"FAILED ({args.id}) MANIFEST.json: {exc}")
        return 1
    if reading is not None:
        try:
            print("\n".join(bind(cert, reading)))
        except ReadingError as exc:
            print(f"FAILED {exc}")
            return 1
    passed, lines = explain(cert, book.decode("utf-8"), fast=not args.no_flint)
    print("\n".join(lines))
    return 0 if passed else 1
