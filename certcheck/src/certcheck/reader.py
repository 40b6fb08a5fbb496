"""A second reader of the printed LaTeX, sharing no code with rigidsym's: it reads an id's
printed text (found by :mod:`certcheck.book`) under the certificate's symbol table, one
line per book glyph: an atom group with its kind (``{"glyph": "\\mathbf{e}", "kind":
"unit", "atoms": [...]}``), a cross-product matrix (``"cpm_of"``), a formula printed
elsewhere (``"printed_as"``, its alignment marks dropped) or the model's words for a glyph
the page defines in words (``"model"``), both read firmly, or a citation (``"defined_by"``:
not read here). The notation: bold and Greek glyphs with dots, primes and subscripts,
``^T``, ``^2``, ``\\times``, ``\\cdot``, juxtaposition, ``\\frac``, ``/``, ``\\cos``,
``\\sin``, ``\\mathrm{tr}``, ``\\mathrm{CPM}(\\mathbf{e})`` (the cross-product matrix),
``\\mathbf{1}``, ``\\mathbf{0}``, ``\\mathbf{O}``, brackets and ``bmatrix`` blocks,
``\\|x\\|^2``, ``\\|x\\|`` (a square root), powers of a square matrix,
``\\underbrace{X}_{...}`` (X), ``[X]_{K}`` (each glyph G of X read from the line
``[G]_{K}``; ``[G]`` with no frame, 3.40's, is not read) and the integral over the body
(:meth:`_Reader.integral`). A side not read is reported, never passed; a side read, a matrix
of grammar texts (:mod:`certcheck.arrays`), :mod:`certcheck.compare` holds to the certificate's.
"""

from __future__ import annotations

import functools
import itertools
import re

from certcheck.arrays import M, NotRead, add, cpm, cross, det, inverse, mul, scalar, vec3

__all__ = ["NotRead", "read_relations", "tokens"]

_TOKEN = re.compile(
    r"\\begin\{bmatrix\}|\\end\{bmatrix\}|\\begin\{aligned\}|\\end\{aligned\}"
    r"|\\(?:mathbf|boldsymbol|mathrm|text|dot|ddot|tilde|frac|left|right)\b"
    r"|\\[A-Za-z]+|\\\\|\\\||\\[,;! ]|\d+|[A-Za-z]|[{}()\[\]^_'+\-=&/|]|\s+|.")


def tokens(text: str) -> list[str]:
    """The tokens of printed LaTeX, spacing and alignment marks dropped."""
    out = [t for t in _TOKEN.findall(text) if not t.isspace()]
    return [t for t in out if t not in ("\\,", "\\;", "\\!", "\\ ", "\\quad", "\\qquad",
                                        "\\begin{aligned}", "\\end{aligned}",
                                        "\\left", "\\right")]


class _Reader:
    def __init__(self, tokens: list[str], table: dict, defs: dict | None = None,
                 cited: list | None = None, lets: list | None = None,
                 seen: dict | None = None):
        self.t, self.i, self.table, self.top = tokens, 0, table, False  # top: a page's side
        self.lets = [] if lets is None else lets  # [name, text]: a glyph's entries, once
        self.seen = {} if seen is None else seen  # key -> (named value, loose, used, cites)
        self.used: set = set()  # the glyphs looked up (through definitions too)
        self.defs = defs or {}  # glyph -> (its printed definition, the id): read in turn
        self.cited = [] if cited is None else cited
        self.frame = None  # inside [...]_{K}: glyphs are looked up as [G]_{K}
        self.norm = 0  # inside \\|...\\|: a \\| closes the norm

    def peek(self, k: int = 0):
        return self.t[self.i + k] if self.i + k < len(self.t) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise NotRead(f"expected {want or 'more'}, found {tok!r}")
        self.i += 1
        return tok

    def group(self) -> str:
        """A braced group's raw text (or one token)."""
        if self.peek() != "{":
            return self.take()
        self.take("{")
        depth, out = 1, []
        while True:
            tok = self.take()
            depth += (tok == "{") - (tok == "}")
            if depth == 0:
                return "".join(out)
            out.append(tok)

    def chain(self) -> list[M]:
        sides = [self.expr()]
        if self.peek() is not None:
            raise NotRead(f"unread text from {self.peek()!r}")
        return sides

    def expr(self) -> M:
        sign = self.take() if self.peek() in ("+", "-") else "+"
        v = self.term()
        if sign == "-":
            v = mul(scalar("-1"), v)
        while self.peek() in ("+", "-"):
            op = self.take()
            v = add(v, self.term(), op)
        return v

    _STOP = (None, "+", "-", "=", "\\equiv", ")", "]", "}", "&", "\\\\", "\\end{bmatrix}",
             ",", "|", "\\|")

    def term(self) -> M:
        v = self.factor()
        while self.peek() not in self._STOP or self.peek() == "\\|" and not self.norm:
            if self.peek() == "\\times":
                self.take()
                w = self.factor()  # a x B c: a x (B c), B c the vector
                while w.shape == (3, 3) and self.peek() not in (*self._STOP, "\\times",
                                                                "\\cdot", "/"):
                    w = mul(w, self.factor())
                v = cross(v, w)
            elif self.peek() == "\\cdot":
                self.take()
                w = self.factor()
                v = scalar(" + ".join(f"({x})*({y})" for x, y in zip(vec3(v), vec3(w),
                                                                   strict=True)))
            elif self.peek() == "/":
                self.take()
                d = self.factor()
                if d.shape != (1, 1):
                    raise NotRead("a division by a matrix")
                v = M([[f"({x})/({d.rows[0][0]})" for x in r] for r in v.rows], v.loose)
            else:
                v = mul(v, self.factor())
        return v

    def factor(self) -> M:
        v = self.primary()
        while self.peek() == "^":
            self.take()
            e = self.group()
            if e == "T":
                v = v.t()
            elif e.isdigit() and v.shape == (1, 1):
                v = scalar(f"({v.rows[0][0]})^{e}")
            elif e.isdigit() and 1 < int(e) < 5 and v.shape[0] == v.shape[1]:
                w = v
                for _ in range(int(e) - 1):
                    w = mul(w, v)
                v = w
            elif e == "-1":
                v = inverse(v)
            else:
                raise NotRead(f"the power ^{{{e}}}")
        return v

    def primary(self) -> M:
        tok = self.peek()
        if tok is None:
            raise NotRead("an expression ends early")
        if tok.isdigit():
            return scalar(self.take())
        if tok == "\\|":  # a norm: ||x||^2 = x^T x, ||x|| its square root
            self.take()
            end = self.t.index("\\|", self.i) if "\\|" in self.t[self.i:] else self.i
            if (key := "\\|" + "".join(self.t[self.i:end]) + "\\|") in self.table:
                self.i = end + 1  # a norm the table gives (the model's magnitude)
                return self.lookup(key)
            self.norm += 1
            x = vec3(self.expr())
            self.norm -= 1
            self.take("\\|")
            square = " + ".join(f"({c})^2" for c in x)
            if self.t[self.i:self.i + 2] != ["^", "2"] and \
                    self.t[self.i:self.i + 4] != ["^", "{", "2", "}"]:
                return scalar(f"sqrt({square})")  # ||x||: decided in K(sqrt(x^T x))
            self.take("^")
            self.group()
            return scalar(square)
        if tok in ("(", "["):
            self.take()
            outer, frame = self.frame, self.frame_after() if tok == "[" else None
            self.frame, start = frame or outer, self.i
            try:
                v = self.expr()
            except NotRead as exc:  # [A + c B v]: a block row [A + c B, v] (its & lost)
                if tok != "[" or frame or not str(exc).startswith("a sum of shapes"):
                    raise
                v = self.block_row(start)
            if tok == "[" and not frame and self.i - start == 4 and self.t[start] in (
                    "\\mathbf", "\\boldsymbol"):  # [G]: its frame in the table's line
                if (key := "[" + "".join(self.t[start:self.i]) + "]") not in self.table:
                    raise NotRead("[G] without a frame: G's components in a frame the page "
                                  "does not name")
                v = self.lookup(key)
            self.take(")" if tok == "(" else "]")
            self.frame = outer
            if frame:  # [X]_{K}: X's components in the frame K (its subscript read)
                self.take("_")
                self.group()
            return v
        if tok in ("\\underbrace", "\\overbrace"):  # a brace's label is a name, not a term
            self.take()
            v = self.sub_expr()
            if self.peek() in ("_", "^"):
                self.take()
                self.group()
            return v
        if tok == "\\frac":
            self.take()
            a, b = (self.sub_expr() for _ in range(2))
            if b.shape != (1, 1):
                raise NotRead("a fraction over a matrix")
            return M([[f"({x})/({b.rows[0][0]})" for x in r] for r in a.rows], a.loose)
        if tok in ("\\cos", "\\sin", "\\det"):  # det: a square array's determinant
            self.take()
            arg = self.factor() if self.peek() in ("(", "{") else self.primary()
            return det(arg) if tok == "\\det" else scalar(f"{tok[1:]}({arg.rows[0][0]})")
        if tok in ("\\mathrm", "\\text", "\\operatorname"):
            start = self.i
            self.take()
            word = self.group()
            if word in ("tr", "vect", "CPM"):
                self.take("(")
                v = self.expr()
                self.take(")")
                if v.shape != (3, 3) and word == "vect":
                    raise NotRead(f"vect of a {v.shape} array")
                if word == "CPM":  # the reading's word: the cross-product matrix of v
                    if v.shape != (3, 1):
                        raise NotRead(f"CPM of a {v.shape} array")
                    return cpm(v)
                if word == "tr":
                    return scalar(" + ".join(v.rows[i][i] for i in range(v.shape[0])))
                a = v.rows  # vect(A): the axial vector of A's skew part, (1/2) of the sums
                return M([[f"(1/2)*(({a[j][k]}) - ({a[k][j]}))"] for j, k in
                          ((2, 1), (0, 2), (1, 0))])
            self.i = start
        if tok == "\\begin{bmatrix}":
            return self.bmatrix()
        if tok == "\\int":
            return self.integral()
        return self.glyph()

    def integral(self) -> M:
        """``\\int_{\\mathcal{B}} f d\\mathcal{B}`` (section 3.8's body of point masses):
        the table's line ``{"glyph": "\\int_{\\mathcal{B}}", "model", "particles"}`` gives
        the particles, each a table of its own glyphs (its mass as ``\\rho``, its position
        as ``\\mathbf{p}``, their rates) bound inside the integral only; f is read once per
        particle, every glyph afresh, and the readings summed."""
        self.take("\\int")
        self.take("_")
        key = f"\\int_{{{self.group()}}}"
        entry = self.table.get(key)
        if entry is None or not entry.get("particles"):
            raise NotRead(f"the integral {key} (no body line in the symbol table)")
        depth, j = 0, self.i  # the integrand runs to d\mathcal{B} at depth 0
        while j < len(self.t) and not (depth == 0 and self.t[j:j + 2] == ["d", "\\mathcal"]):
            depth += (self.t[j] in ("{", "(", "[")) - (self.t[j] in ("}", ")", "]"))
            j += 1
        if j >= len(self.t):
            raise NotRead(f"the integral {key} without its d\\mathcal{{B}}")
        body, self.i = self.t[self.i:j], j + 2
        self.group()
        total, bound = None, {g for part in entry["particles"] for g in part}
        common = {k: v for k, v in self.seen.items() if not v[2] & bound}
        for part in entry["particles"]:  # a glyph free of the particle's is read once
            table = {**self.table, **{g: {"glyph": g, "latex": x, "model": entry["model"]}
                                      for g, x in part.items()}}
            inner = _Reader(body, table, self.defs, self.cited, self.lets, dict(common))
            v = inner.chain()[0]
            common.update({k: w for k, w in inner.seen.items() if not w[2] & bound})
            self.used |= inner.used - bound
            total = v if total is None else add(total, v, "+")
        for k, w in common.items():
            self.seen.setdefault(k, w)
        self.cited.append(f"{key} as the model's {entry['model']}")
        return total

    def block_row(self, start: int) -> M:
        """``[A + c B v]``, its column separator lost, n x n and n x 1: ``[A + c B, v]`` (3.97a,
        3.77b), the sign before v its own; c scalar: ``[A, -c v]`` (3.77c), by shapes; cited."""
        self.i, terms = start, []
        while not terms or self.peek() in ("+", "-"):
            terms.append([self.take() if self.peek() in ("+", "-") else "+"])
            while self.peek() not in (*self._STOP, "\\times", "\\cdot", "/"):
                terms[-1].append(self.factor())
        v = terms[-1].pop()
        if len(terms[-1]) > 1 and (c := functools.reduce(mul, terms[-1][1:])).shape == (1, 1):
            v, terms[-1] = mul(c, v), terms[-1][:1]  # the scalar c is the column's
        a = M([["0"] * (n := v.shape[0])] * n)
        for sign, *f in (t for t in terms if len(t) > 1):
            a = add(a, functools.reduce(mul, f), sign)
        if v.shape != (n, 1) or self.peek() != "]":
            raise NotRead("a sum of arrays of different shapes in [...]")
        self.cited.append("[...] read as a block row [A, v] (its column separator lost)")
        return M([r + [f"-({x})" if terms[-1][0] == "-" else x] for r, (x,) in zip(
            a.rows, v.rows, strict=True)], a.loose)

    def frame_after(self) -> str | None:
        """The frame K of ``[...]_{K}`` opened just before (``None``: a plain bracket)."""
        depth, j = 1, self.i
        while j < len(self.t) and depth:
            depth += (self.t[j] == "[") - (self.t[j] == "]")
            j += 1
        if j >= len(self.t) or self.t[j] != "_":
            return None
        if self.t[j + 1:j + 2] != ["{"]:
            return self.t[j + 1] if j + 1 < len(self.t) else None
        k, depth = j + 2, 1
        while k < len(self.t) and depth:
            depth += (self.t[k] == "{") - (self.t[k] == "}")
            k += 1
        return "".join(self.t[j + 2:k - 1])

    def sub_expr(self) -> M:
        self.take("{")
        v = self.expr()
        self.take("}")
        return v

    def block(self) -> M | str:
        """A block of a block matrix: an expression, or ``0`` / ``1`` for a bare zero or
        identity, sized by the other blocks of its row and column."""
        bare = self.t[self.i:self.i + 4]
        if bare[:2] + bare[3:] == ["\\mathbf", "{", "}"] and bare[2] in "0O1" and \
                self.peek(4) in ("&", "\\\\", "\\end{bmatrix}"):
            self.i += 4
            return "1" if bare[2] == "1" else "0"
        return self.expr()

    def bmatrix(self) -> M:
        self.take("\\begin{bmatrix}")
        start, rows, row = self.i, [], [self.block()]
        while self.peek() != "\\end{bmatrix}":
            sep = self.take()
            if sep == "\\\\":
                rows.append(row)
                row = []
            row.append(self.block())
        self.take()
        rows.append(row)
        raw, whole = [list(r) for r in rows], self.top and self.i == len(self.t) and start == 1
        hs = [next((b.shape[0] for b in r if isinstance(b, M)), None) for r in rows]
        ws = [next((r[k].shape[1] for r in rows if k < len(r) and isinstance(r[k], M)), None)
              for k in range(max(map(len, rows)))]
        loose = any(isinstance(b, M) and b.loose for r in rows for b in r)
        for r, h in zip(rows, hs, strict=True):  # a bare block's size: its row's, column's
            for k, b in enumerate(r):
                if isinstance(b, str):
                    loose = loose or h is None or ws[k] is None
                    r[k] = M([[("1" if i == j and b == "1" else "0") for j in range(ws[k] or 3)]
                              for i in range(h or 3)])
        width = max(sum(b.shape[1] for b in r) for r in rows)
        for k, r in enumerate(rows):  # [B \\ e-dot] (3.96a): a row printed as a column, the
            if len(rows) > 1 and len(r) == 1 and r[0].shape == (width, 1) != (1, 1):  # only
                rows[k] = [r[0].t()]  # reading the block matrix admits: its ^T lost; cited
                self.cited.append(f"a column in a block matrix {width} wide: read as a row")
        out = []
        for blocks in rows:
            h = blocks[0].shape[0]
            if any(b.shape[0] != h for b in blocks) or len({sum(b.shape[1] for b in r)
                                                            for r in rows}) != 1:
                exc = NotRead("the blocks do not fit")
                exc.blocks = raw if whole else []  # the whole side's (certcheck.compare's)
                raise exc
            out += [sum((b.rows[k] for b in blocks), []) for k in range(h)]
        return M(out, loose)

    def glyph(self) -> M:
        start = self.i
        tok = self.take()
        if tok in ("\\mathbf", "\\boldsymbol", "\\dot", "\\ddot", "\\tilde", "\\mathrm",
                   "\\overrightarrow"):  # AP_1 of (3.37): the vector from A to P_1, a glyph
            self.group()
        elif not (tok.startswith("\\") or tok.isalpha()):
            raise NotRead(f"unexpected {tok!r}")
        while self.peek() in ("'", "_"):
            if self.take() == "_":
                self.group()
        name = "".join(self.t[start:self.i])
        if (slip := self.table.get(name.replace(" ", ""), {})).get("reads_as") == "text":
            self.t[self.i:self.i] = tokens(str(slip.get("latex", "")))  # a converted slip:
            self.cited.append(f"{name} read as {slip.get('latex')}")  # its words in its place
            return self.primary()
        if self.t[self.i:self.i + 3] == ["(", "t", ")"]:  # p(t): the glyph at time t
            self.i += 3
        return self.lookup(name)

    def named(self, key: str, v: M, used: set) -> M:
        """``v`` with each compound entry written once as a let (``page1``, ...), so that
        a glyph read through a definition is a name in every product it enters."""
        if key not in self.seen:
            rows = []
            for r in v.rows:
                rows.append([])
                for x in r:
                    if not re.fullmatch(r"[\w']+", x):
                        self.lets.append([f"page{len(self.lets) + 1}", x])
                        x = self.lets[-1][0]
                    rows[-1].append(x)
            self.seen[key] = (M(rows, v.loose), v.loose, used, [])
        return self.seen[key][0]

    def again(self, key: str) -> M | None:
        """A glyph read before on this page (under the same particle), or ``None``."""
        if key not in self.seen:
            return None
        v, _, used, cites = self.seen[key]
        self.used = self.used | used
        self.cited.extend(cites)  # what it was read through, cited again
        return v

    def lookup(self, name: str) -> M:
        key = name.replace(" ", "")
        self.used.add(key)
        if key in ("\\mathbf{1}", "\\mathbf{O}"):  # sized 3 x 3 by the reader: loose
            return M([[("1" if i == j and key[-2] == "1" else "0") for j in range(3)]
                      for i in range(3)], True)
        if key == "\\mathbf{0}":
            return M([["0"] for _ in range(3)], True)
        if m := re.fullmatch(r"\\mathbf\{1\}_\{(\d)\\times\1\}", key):  # 1_{6 x 6}
            return M([[str(int(i == j)) for j in range(int(m[1]))] for i in range(int(m[1]))])
        if m := re.fullmatch(r"\\delta_\{(\d)(\d)\}", key):  # Kronecker's delta
            return scalar(str(int(m[1] == m[2])))
        if key == "\\pi":  # the grammar's pi
            return scalar("pi")
        if self.frame:  # a glyph inside [...]_{K}: only the table's [G]_{K} is read
            key = f"[{key}]_{{{self.frame}}}"
            if key not in self.table:
                raise NotRead(f"the glyph {key} (components in a frame) is not in the "
                              "symbol table")
        entry = self.table.get(key)
        if entry is None and key in self.defs:  # defined on the page before: read that
            text, where, sign = (*self.defs[key], "\\equiv")[:3]
            if (v := self.again(key)) is not None:
                return v
            rest, n = {k: v for k, v in self.defs.items() if k != key}, len(self.cited)
            inner = _Reader(tokens(text), self.table, rest, self.cited, self.lets,
                            self.seen)
            value = self.named(key, inner.chain()[0], inner.used | {key})
            self.used |= inner.used
            self.cited.append(f"{name} by ({where})" + (", an equation" if sign == "=" else ""))
            self.seen[key] = (*self.seen[key][:3], self.cited[n:])
            return value
        if entry is None:
            raise NotRead(f"the glyph {name} is neither in the symbol table nor defined "
                          "(\\equiv) on the page before")
        if "defined_by" in entry:
            raise NotRead(f"{name} is defined by ({entry['defined_by']})")
        if "latex" in entry and (v := self.again(key)) is not None:
            return v
        if "latex" in entry:  # printed elsewhere (another chapter), or the model's own
            n = len(self.cited)
            inner = _Reader(_unaligned(tokens(str(entry["latex"]))), self.table,
                            {k: v for k, v in self.defs.items() if k != key}, self.cited,
                            self.lets, self.seen)
            value = self.named(key, inner.chain()[0], inner.used | {key})
            self.used |= inner.used
            self.cited.append(f"{key} as the model's {entry['model']}" if "model" in entry
                              else f"{key} as printed in {entry.get('printed_as', '?')}")
            self.seen[key] = (*self.seen[key][:3], self.cited[n:])
            return value
        if "cpm_of" in entry:
            return cpm(self.lookup(entry["cpm_of"]))
        atoms = list(entry.get("atoms", []))
        if not atoms:
            raise NotRead(f"the glyph {name} names no atoms")
        if len(atoms) in (9, 16, 36):  # a rotation, transform or 6 x 6 array, row-major
            n = {9: 3, 16: 4, 36: 6}[len(atoms)]
            return M([atoms[n * i:n * i + n] for i in range(n)])
        return scalar(atoms[0]) if len(atoms) == 1 else M([[a] for a in atoms])


def _unaligned(toks: list[str]) -> list[str]:
    """A table line's tokens without an aligned display's ``&``, ``\\\\`` at depth 0 (3.96e)."""
    o, c = ("{", "(", "[", "\\begin{bmatrix}"), ("}", ")", "]", "\\end{bmatrix}")
    depth = itertools.accumulate((t in o) - (t in c) for t in toks)
    return [t for t, d in zip(toks, depth, strict=True) if d or t not in ("&", "\\\\")]


def _split(tokens: list[str]) -> list[list[list[str]]]:
    """The printed relations: chains ``a = b = ...`` (or ``\\equiv``) separated by commas
    or ``\\text{or}``, each a list of sides, split at depth 0; a family's range (``, i, j =
    1, 2, 3``) becomes a token ``@ij`` closing its relation's last side."""
    chains, sides, cur, depth = [], [], [], 0
    text = " ".join(tokens).replace("\\text { o r }", ",")  # a or b: two relations
    text = re.sub(r" , ([ijk])(?: , ([ijk]))? = 1 , 2 , 3(?= ,|$)", r" @\1\2", text)
    for tok in text.split(" ") if tokens else []:
        depth += tok in ("{", "(", "[", "\\begin{bmatrix}")
        depth -= tok in ("}", ")", "]", "\\end{bmatrix}")
        if depth == 0 and tok in ("=", "\\equiv"):
            sides.append(cur)
            cur = []
        elif depth == 0 and tok == ",":
            chains.append([*sides, cur])
            sides, cur = [], []
        elif depth or tok not in ("&", "\\\\"):  # an aligned display's marks
            cur.append(tok)
    return [*chains, [*sides, cur]]


def read_relations(page: str, symbols: list, defs: dict | None = None,
                   lets: list | None = None) -> list:
    """The sides of the printed chain ``a = b = ...`` (or ``\\equiv``), each a matrix of
    grammar texts, or the :class:`NotRead` saying why the reader cannot read it; the
    texts name the lets appended to ``lets`` (``[name, text]``, in order).

    Raises:
        NotRead: a malformed symbol table.
    """
    table = {}
    for e in symbols:
        if not isinstance(e, dict) or "glyph" not in e:
            raise NotRead(f"a symbol-table entry without a glyph: {e!r}")
        table[str(e["glyph"]).replace(" ", "")] = e
    out, seen, lets = [], {}, [] if lets is None else lets  # a glyph read once per page
    words = next((str(e["family"]) for e in table.values() if e.get("family")), "")
    for chain in _split(tokens(page.rstrip(",. "))):  # a range printed, or the table's
        idx = chain[-1].pop()[1:] if chain[-1][-1:] and chain[-1][-1][0] == "@" else \
            re.sub(r"[^ijk]", "", words)[:2]  # (the page's family in words: 3.39's q_ij)
        out.append([])
        for toks in chain:
            read, cited = [], []
            for vals in itertools.product("123", repeat=len(idx)):  # a family: each member
                r = _Reader(_bind(toks, dict(zip(idx, vals, strict=True))), table, defs,
                            cited, lets, seen)
                r.top = True
                try:
                    read.append(r.chain()[0])
                except (NotRead, IndexError) as exc:
                    read = [exc if isinstance(exc, NotRead) else NotRead("unbalanced text")]
                    break
            v = read[0] if len(read) == 1 else _family(read, len(idx))
            out[-1].append((v, getattr(v, "loose", False), list(dict.fromkeys(cited))))
    return out


def _bind(toks: list[str], vals: dict) -> list[str]:
    """A family's member: each index (``i``, ``j``) in a subscript given its value."""
    out, inside = [], False
    for k, t in enumerate(toks):
        prev = toks[k - 1] if k else None
        if t in vals and (inside or prev == "_"):
            t = vals[t]
        inside = inside and t != "}" or prev == "_" and t == "{"
        out.append(t)
    return out


def _family(read: list, n: int):
    """The members of a family over ``n`` indices, each 1 x 1, as one array: a column
    (``i = 1, 2, 3``) or a 3 x 3 matrix (``i, j = 1, 2, 3``, row i, column j)."""
    if any(isinstance(v, NotRead) for v in read) or any(v.shape != (1, 1) for v in read):
        return next((v for v in read if isinstance(v, NotRead)),
                    NotRead("a family of arrays (its members not scalars)"))
    entries = [v.rows[0][0] for v in read]
    return M([entries[3 * i:3 * i + 3] for i in range(3)] if n == 2 else [[x] for x in entries])
