"""A reader's document as the page: its displayed relations read here, with the standard
library alone (no code shared with rigidsym), so that a certificate of ``rigidsym check
NOTES.md --certificates DIR`` is bound to the relation the page prints under its id, to
the class the page gives it and to the symbol lines the reading and the page give it.

- :func:`relations`: every displayed relation of the text, in reading order, with its line
  and label: ``$$...$$``, ``\\[...\\]``, a ```` ```math ```` fence and the display
  environments (``equation``, ``align``, ``gather``, ``multline``, ... starred or not);
  ``aligned``, ``split``, ``gathered`` inside them; a chain ``A = B = C`` is ``A = B`` and
  ``B = C``; a line that begins ``&= D`` relates to the right side before it; ``,``, ``;``,
  ``\\quad``, ``\\qquad`` and ``\\text{...}`` separate relations outside brackets, groups and
  matrices; ``\\label{x}``/``\\tag{x}`` (or a printed ``(3.9a)`` closing a line) name the
  relations of their line, or of the display where it has one label.
- :func:`locate`: the relation an id names: a label (``eq:rodrigues-E``, or ``label:X`` for
  a label ``X`` that is not of the form ``ns:name``), else its line, ``line:L`` (the one
  relation that stands on line L of the text) or ``line:L.K`` (the K-th of several).
- :func:`page_reading`: the class the page gives the located relation (a definition: a
  defining symbol, ``:=``, ``\\triangleq``, ``\\equiv``, ..., or ``=`` after one glyph that
  neither the reading declares nor the page defined before) and the symbol lines it may
  carry: the reading's ``[[let]]`` lines that hold for it (no ``ids``, or its label among
  them; no ``scope``, or its label in it) and the page's own definitions at or before it
  (the latest of each glyph, replacing the reading's line of that glyph).
"""

from __future__ import annotations

import re

from certcheck.book import READER_ID, BookError
from certcheck.book import locate as locate_display

__all__ = ["DEFINING", "DocumentError", "bind_document", "document_id", "locate",
           "page_reading", "printed", "relations"]


class DocumentError(BookError):
    """An id the page does not print (or prints more than once), or a text not read."""


#: relation symbols that define the glyph on their left, as the relation prints them
DEFINING = {":=": ":=", "\\coloneqq": ":=", "\\triangleq": ":=", "\\equiv": "\\equiv",
            "\\defeq": ":=", "\\doteq": ":="}
#: the other relation symbols (macro names): each splits a line into relations
_OPS = {"approx", "simeq", "sim", "propto", "cong", "le", "leq", "ge", "geq", "ll", "gg",
        "neq", "ne", "in", "subset", "subseteq", "colon", "to", "rightarrow", "mapsto",
        "Rightarrow", "implies", "iff", "Leftrightarrow", "eqqcolon", "coloneqq",
        "triangleq", "equiv", "defeq", "doteq"}
#: environments whose ``\\`` ends a line of the display
_FLAT = {"align", "align*", "aligned", "alignat", "alignat*", "alignedat", "split", "gather",
         "gather*", "gathered", "multline", "multline*", "eqnarray", "eqnarray*", "equation",
         "equation*", "displaymath", "flalign", "flalign*", "math"}
_SEPARATORS = {"quad", "qquad", "text", "textrm", "mbox", "hbox", "textnormal", "intertext",
               "shortintertext"}
_OPENERS = {"left": 1, "bigl": 0, "Bigl": 0, "biggl": 0, "Biggl": 0}
_CLOSERS = {"right": -1, "bigr": 0, "Bigr": 0, "biggr": 0, "Biggr": 0}
_ELISIONS = ("\\cdots", "\\ldots", "\\dots", "\\vdots", "\\ddots")
_SPACES = ("\\,", "\\;", "\\!", "\\:", "\\ ", "~")
#: a glyph a definition may define: a letter or a Greek command, bold, dotted, subscripted
GLYPH = re.compile(r"(\\(dot|ddot|hat|bar|tilde)\{)?(\\(mathbf|boldsymbol|bm)\{\\?[A-Za-z]+\}|"
                   r"\\?[A-Za-z]+)\}?(_\{?\\?\w+\}?)?'*")


def _displays(text: str) -> list[tuple[int, str]]:
    """``(offset of the body, body)`` of each display of ``text`` in order: ``$$...$$``,
    ``\\[...\\]``, a display environment outside them, a ```` ```math ```` fence; other
    fenced code is skipped."""
    out: list[tuple[int, str]] = []
    envs = "|".join(re.escape(e) for e in sorted(_FLAT - {"math"}, key=len, reverse=True))
    pat = re.compile(r"(?m)^[ \t]*```+[ \t]*(\w*)[^\n]*\n(.*?)^[ \t]*```+[ \t]*$"
                     r"|\$\$(.*?)\$\$|\\\[(.*?)\\\]"
                     r"|\\begin\{(" + envs + r")\}(.*?)\\end\{\5\}", re.S)
    for m in pat.finditer(text):
        if m.group(2) is not None:  # a fence: math, else code
            if m.group(1) == "math":
                out.append((m.start(2), m.group(2)))
        elif m.group(3) is not None:
            out.append((m.start(3), m.group(3)))
        elif m.group(4) is not None:
            out.append((m.start(4), m.group(4)))
        else:
            out.append((m.start(6), m.group(6)))
    return out


def _group(s: str, i: int) -> int:
    """The offset after the brace group that opens at ``s[i]``."""
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0) if s[j - 1:j] != "\\" or j == i else 0
        if depth == 0:
            return j + 1
    return len(s)


def _tokens(body: str) -> list[tuple[str, str, int]]:
    """The display's tokens ``(kind, text, offset)``: ``text``, ``op``, ``sep``, ``br``,
    ``label``; a matrix, a ``cases`` or a group stays one text."""
    out: list[tuple[str, str, int]] = []
    depth, delim, i = 0, 0, 0

    def add(kind, t, at):
        out.append(("text" if kind == "op" and depth else kind, t, at))
    while i < len(body):
        c = body[i]
        if c == "%" and body[i - 1:i] != "\\":
            i = body.find("\n", i) if "\n" in body[i:] else len(body)
            continue
        if delim and c != "\\" and not c.isspace():  # \left( : the delimiter
            depth += delim
            delim = 0
            add("text", c, i)
            i += 1
            continue
        if c == "{":
            j = _group(body, i)
            add("text", body[i:j], i)
            i = j
            continue
        if c == "&":
            i += 1
            continue
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+\*?|.)", body[i:])
            name = m.group(1)
            end = i + m.end()
            if name == "\\":
                if depth == 0:
                    add("br", "\\\\", i)
                i = end
                continue
            if name in ("label", "tag", "tag*") and body[end:end + 1] == "{":
                j = _group(body, end)
                add("label", body[end + 1:j - 1].strip(), i)
                i = j
                continue
            if name in ("nonumber", "notag"):
                i = end
                continue
            if name == "begin" and body[end:end + 1] == "{":
                j = _group(body, end)
                env = body[end + 1:j - 1]
                if env in _FLAT:
                    i = j
                    continue
                close = _env_end(body, j, env)
                add("text", body[i:close], i)
                i = close
                continue
            if name == "end" and body[end:end + 1] == "{":
                i = _group(body, end)
                continue
            if name in _OPENERS:
                delim = _OPENERS[name]
            elif name in _CLOSERS:
                delim = _CLOSERS[name]
            elif delim:
                pass
            elif name in ("{", "langle", "lVert", "lvert", "lbrace"):
                depth += 1
            elif name in ("}", "rangle", "rVert", "rvert", "rbrace"):
                depth -= 1
            if name in _SEPARATORS and depth == 0:
                j = end
                while body[j:j + 1].isspace():
                    j += 1
                if name not in ("quad", "qquad") and body[j:j + 1] == "{":
                    j = _group(body, j)
                    end = j
                add("sep", body[i:end], i)
                i = end
                continue
            if name in _OPS:
                add("op", "\\" + name, i)
                i = end
                continue
            if name in ("stackrel", "overset") and depth == 0:
                j = end
                groups = []
                while len(groups) < 2 and body[j:j + 1] == "{":
                    k = _group(body, j)
                    groups.append(body[j + 1:k - 1])
                    j = k
                if len(groups) == 2 and groups[1].strip() == "=":
                    add("op", ":=" if "def" in groups[0] else "=", i)
                    i = j
                    continue
            if delim and name not in _OPENERS and name not in _CLOSERS:
                depth += delim
                delim = 0
            add("text", body[i:end], i)
            i = end
            continue
        if depth == 0 and c == ":" and body[i + 1:i + 2] == "=":
            add("op", ":=", i)
            i += 2
            continue
        if depth == 0 and c in "=<>:":
            if c == "=" and out and out[-1][0] == "op" and out[-1][1] in ("<", ">"):
                out[-1] = ("op", "\\le" if out[-1][1] == "<" else "\\ge", out[-1][2])
            else:
                add("op", c, i)
            i += 1
            continue
        if depth == 0 and c in ",;":
            add("sep", c, i)
            i += 1
            continue
        add("text", c, i)
        i += 1
    return out


def _env_end(body: str, j: int, env: str) -> int:
    """The offset after the ``\\end{env}`` that closes the environment opened before ``j``."""
    pat = re.compile(r"\\(begin|end)\{" + re.escape(env) + r"\}")
    depth = 1
    for m in pat.finditer(body, j):
        depth += 1 if m.group(1) == "begin" else -1
        if depth == 0:
            return m.end()
    return len(body)


def _clean(text: str) -> str:
    """A side without surrounding space, spacing macros and a closing period or comma."""
    t = " ".join(text.split())
    changed = True
    while changed and t:
        changed = False
        for s in _SPACES + (".", ","):
            if t.endswith(s) and not t.endswith("\\" + s):
                t, changed = t[:-len(s)].rstrip(), True
            if t.startswith(s) and s not in (".", ","):
                t, changed = t[len(s):].lstrip(), True
    return t


def _printed_number(line: list) -> str | None:
    """The equation number printed at the end of a line after a separator (``x = y \\quad
    (3.9a)``): the last segment when it is a parenthesised number alone and a relation
    stands before it."""
    if len(line) < 2 or any(k == "op" for k, _, _ in line[-1]) or \
            not any(k == "op" for seg in line[:-1] for k, _, _ in seg):
        return None
    text = "".join(t for _, t, _ in line[-1]).strip().rstrip(".").strip()
    if len(text) < 3 or text[0] != "(" or text[-1] != ")":
        return None
    inner = text[1:-1].strip()
    core = inner[:-1] if inner[-1:].isalpha() and inner[-1:].islower() else inner
    return inner if core and all(p.isdigit() for p in core.split(".")) else None


def _display_relations(text: str, start: int, body: str, number: int) -> list[dict]:
    """The relations of one display (its body at ``start`` of ``text``)."""
    lines: list = [[[]]]
    labels: list = [[]]
    for tok in _tokens(body):
        if tok[0] == "br":
            lines.append([[]])
            labels.append([])
        elif tok[0] == "sep":
            lines[-1].append([])
        elif tok[0] == "label":
            labels[-1].append(tok[1])
        else:
            lines[-1][-1].append(tok)
    for li, line in enumerate(lines):
        n = _printed_number(line)
        if n is not None:
            line.pop()
            labels[li].append(n)
    every = [x for ls in labels for x in ls]
    pending: list[dict] = []
    carry = ""
    for li, line in enumerate(lines):
        first = True
        for seg in line:
            parts: list = [["", None]]
            ops: list = []
            for kind, t, pos in seg:
                if kind == "op":
                    ops.append((t, pos))
                    parts.append(["", None])
                else:
                    if parts[-1][1] is None and t.strip():
                        parts[-1][1] = pos + (len(t) - len(t.lstrip()))
                    parts[-1][0] += t
            if not ops:
                if not parts[0][0].strip():
                    continue
                if first and li > 0 and pending and pending[-1]["li"] < li:
                    pending[-1]["rhs"] += " " + parts[0][0]
                elif first and li + 1 < len(lines) and not pending:
                    carry += parts[0][0]
                first = False
                continue
            first = False
            lhs, at = carry + parts[0][0], parts[0][1]
            carry = ""
            if not _clean(lhs):
                if not pending:
                    raise DocumentError(f"display {number} begins with a relation symbol")
                lhs, at = pending[-1]["rhs"], None
            for (op, op_at), (rhs, _) in zip(ops, parts[1:], strict=True):
                pending.append({"lhs": lhs, "op": op, "rhs": rhs,
                                "at": at if at is not None else op_at, "li": li})
                lhs, at = rhs, None
    out = []
    for p in pending:
        own = labels[p["li"]]
        label = own[0] if own else (every[0] if len(every) == 1 else None)
        out.append({"line": text.count("\n", 0, start + p["at"]) + 1, "label": label,
                    "lhs": _clean(p["lhs"]), "op": p["op"], "rhs": _clean(p["rhs"]),
                    "display": number})
    return out


def relations(text: str) -> list[dict]:
    """Every displayed relation of ``text`` in reading order.

    Args:
        text: the page (Markdown or LaTeX).

    Returns:
        One ``{"line", "label", "lhs", "op", "rhs", "display"}`` per relation: ``line`` from
        1, where its left side starts (or its relation symbol, on a line that begins with
        one); ``label`` its line's or its display's one label, or ``None``; ``op`` as
        printed (``=``, ``\\triangleq``, ``:=`` for ``\\stackrel{\\text{def}}{=}``);
        ``display`` from 1.

    Raises:
        DocumentError: a display that begins with a relation symbol.
    """
    out: list[dict] = []
    for n, (start, body) in enumerate(_displays(text), start=1):
        out += _display_relations(text, start, body, n)
    return out


def printed(rel: dict) -> str:
    """A relation as the page prints it.

    Args:
        rel: a record of :func:`relations`.

    Returns:
        ``lhs op rhs``, one space around the relation symbol.
    """
    return f"{rel['lhs']} {rel['op']} {rel['rhs']}"


def locate(text: str, eq_id: str) -> tuple[int, list[dict]]:
    """The relation ``eq_id`` names on the page: the one whose label is ``eq_id``; for
    ``label:X``, the one whose label is ``X``; for ``line:L``, the one relation that stands
    on line L; for ``line:L.K``, the K-th of the relations on line L (two or more).

    Args:
        text: the page.
        eq_id: the id.

    Returns:
        ``(its index in the relations, the relations)`` (:func:`relations`).

    Raises:
        DocumentError: the id names no relation of the page, or more than one.
    """
    rels = relations(text)
    hits = [k for k, r in enumerate(rels) if r["label"] == eq_id]
    m = re.fullmatch(r"line:(\d+)(?:\.(\d+))?", eq_id)
    if not hits and eq_id.startswith("label:"):
        hits = [k for k, r in enumerate(rels) if r["label"] == eq_id[len("label:"):]]
    elif not hits and m:
        on = [k for k, r in enumerate(rels) if r["line"] == int(m.group(1))]
        if m.group(2) is None:
            hits = on
        elif 1 <= int(m.group(2)) <= len(on) and len(on) > 1:
            hits = [on[int(m.group(2)) - 1]]
    if len(hits) != 1:
        raise DocumentError(f"({eq_id}) names {len(hits)} relations of the page, not one")
    return hits[0], rels


def _holds(entry_scope, entry_ids, label) -> bool:
    """Whether a reading's ``[[let]]`` holds for a relation labelled ``label``."""
    if entry_scope is not None and (label is None or not (
            label == entry_scope or label.startswith(entry_scope + "."))):
        return False
    return not entry_ids or label in entry_ids


def _nospace(s: str) -> str:
    return "".join(s.split())


def page_reading(text: str, eq_id: str, reading: dict) -> tuple[dict, str, list[tuple]]:
    """The relation ``eq_id`` names on the page, its class, and the symbol lines it may
    carry.

    Args:
        text: the page (the document's text).
        eq_id: the certificate's id (:func:`locate`).
        reading: :func:`certcheck.reading.load_reading`'s reading of the document.

    Returns:
        ``(relation, class, lines)``: the relation (:func:`relations`' record), its class
        (``definition`` or ``relation``) and the canonical lines (those of
        :func:`certcheck.reading.load_reading`) the reading and the page's definitions give
        it.

    Raises:
        DocumentError: as :func:`locate`.
    """
    from certcheck.reading import line_of

    k, rels = locate(text, eq_id)
    rel = rels[k]
    label = rel["label"]
    lets = [(e, line) for e, scope, ids, line in reading.get("page_lets", [])
            if _holds(scope, ids, label)]
    declared = {_nospace(line[1]) for _, line in lets}
    defined: dict = {}  # glyph -> its canonical line, the latest at or before the relation
    cls = "relation"
    for j, r in enumerate(rels[:k + 1]):
        if any(e in printed(r) for e in _ELISIONS):
            continue  # terms not written: no definition, no verdict
        glyph = _nospace(r["lhs"])
        is_glyph = GLYPH.fullmatch(glyph) is not None
        if is_glyph and (r["op"] in DEFINING or (
                r["op"] == "=" and glyph not in declared and glyph not in defined)):
            if j == k:
                cls = "definition"
            defined[glyph] = line_of({"let": f"{r['lhs']} = {r['rhs']}",
                                      "where": f"defined on the page, line {r['line']}"},
                                     f"the page's line {r['line']}")
    lines = [line for _, line in lets if _nospace(line[1]) not in defined]
    return rel, cls, lines + list(defined.values())


def document_id(cert: dict, book: str | None, reading: dict | None) -> bool:
    """Whether ``cert`` is of a document's relation: its id is a reader's (``ns:name``),
    a page is given, and the reading gives the id no class (a module's ids are listed in
    its ``[classes]``); without a reading, the page's tagged displays do not print it.

    Args:
        cert: the certificate.
        book: the page's text, or ``None``.
        reading: :func:`certcheck.reading.load_reading`'s reading, or ``None``.

    Returns:
        ``True`` where :func:`bind_document` binds it.
    """
    eq_id = str(cert.get("id"))
    if book is None or not READER_ID.fullmatch(eq_id):
        return False
    if reading is not None:
        return eq_id not in reading["classes"]
    try:
        locate_display(book, eq_id)
    except BookError:
        return True
    return False


def bind_document(cert: dict, book: str, reading: dict | None) -> tuple[dict, list[str]]:
    """Hold a document's certificate to its page and reading: the class is the page's
    (:func:`page_reading`), each symbol line one the reading or the page's definitions give
    the relation (a line the relation does not use may be left out: a glyph the page prints
    and the table lacks leaves that side not read, and an atom no line names fails).

    Args:
        cert: the certificate.
        book: the page's text.
        reading: the reading, or ``None`` (the class and the relation only).

    Returns:
        ``(the relation, the lines to print)``.

    Raises:
        DocumentError: the id names no relation of the page, or more than one.
        certcheck.reading.ReadingError: a line the reading and the page do not give, a
            class not the page's, a relation's own table (a document gives none).
    """
    from certcheck.reading import ReadingError, _cert_lines, bind

    eq_id = str(cert.get("id"))
    rel, cls, offered = page_reading(book, eq_id, reading or {"page_lets": []})
    verdict = cert.get("verdict")
    if (verdict == "definition") != (cls == "definition"):
        raise ReadingError(f"({eq_id}): the certificate says {verdict}, the page prints the "
                           f"relation on line {rel['line']} as a {cls}")
    if reading is None:
        return rel, [f"page: ({eq_id}) is the relation on line {rel['line']}, a {cls}"]
    if any(isinstance(r, dict) and "symbols" in r for r in cert.get("relations") or []):
        raise ReadingError(f"({eq_id}): a relation's own symbol table, which a document's "
                           "reading does not give")
    atoms = {a: g for g in cert.get("atoms") or [] for a in g.get("names", [])}
    have = _cert_lines(cert, cert.get("symbols") or [], atoms, f"({eq_id})")
    chosen, free = [], list(offered)
    for h in have:
        hit = next((x for x in free if x == h or (
            h[0] == "rate-of" and x[0] == "rate" and x[1:3] == h[1:3])), None)
        if hit is not None:
            free.remove(hit)
            chosen.append(hit)
    derived = {**reading, "classes": {eq_id: cls}, "lines": {(eq_id, ""): chosen},
               "atoms_of": {}}
    lines = bind(cert, derived)
    return rel, [f"page: ({eq_id}) is the relation on line {rel['line']}, a {cls} on the "
                 f"page; its {len(chosen)} symbol lines are the reading's and the page's "
                 f"(of {len(offered)} they give)"] + lines
