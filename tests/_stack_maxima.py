"""A small, independent interpreter of the STACK questions ``stack.xml`` holds: the Maxima
of the feedback variables (the subset the export writes, read by its documented
semantics, not by rigidsym's code) and the walk of each potential response tree.

Maxima, as documented: ``a: b;`` assigns; ``if c then x else y``; ``and``, ``or``,
``not``; ``=`` is syntactic equality (a matrix is never the symbol ``EMPTYANSWER``);
``<``, ``<=``, ``>``, ``>=`` on numbers; ``+ - * / ^`` act entry by entry on lists and
matrices (a number with a list or matrix: on each entry); ``.`` is the matrix product;
``matrix([r1], [r2], ...)`` a matrix of rows; ``args(M)`` the list of M's rows;
``flatten`` a nested list made flat; ``abs`` entry by entry; ``lmax`` (``lmin``) the
largest (smallest) entry of a list; ``max`` of numbers; ``floor``; ``is(b)`` the truth of
b; ``%pi``. Anything else is an error: the export must write no Maxima this reader does
not know.

STACK, as documented: a question's inputs are the student's answers (``allowempty``: a
blank input is ``EMPTYANSWER``); each PRT's feedback variables are evaluated, then its
nodes walked from node 0, each answer test setting the score (mode ``=``) and the next
node (-1: the end); the question's mark is the sum of each PRT's value times its score,
over the sum of the values.
"""

from __future__ import annotations

import functools
import math
import re
import xml.etree.ElementTree as ET

import numpy as np

EMPTY = "EMPTYANSWER"
_TOKEN = re.compile(r"\s*(?:(\d+\.\d*(?:[eE][-+]?\d+)?|\d+(?:[eE][-+]?\d+)?)|"
                    r"([A-Za-z%_][A-Za-z0-9%_]*)|(<=|>=|[-+*/^.=<>:;()\[\],]))")


@functools.lru_cache(maxsize=4096)
def _tokens(text: str) -> tuple[tuple[str, str], ...]:
    """The tokens of one statement (cached: a question's tests run its PRTs again)."""
    return tuple(_scan(text))


def _scan(text: str) -> list[tuple[str, str]]:
    out, i, text = [], 0, text.strip()
    while i < len(text):
        m = _TOKEN.match(text, i)
        if not m or m.end() == i:
            raise SyntaxError(f"Maxima: cannot read {text[i:i + 30]!r}")
        num, name, op = m.groups()
        out.append(("num", num) if num else ("name", name) if name else ("op", op))
        i = m.end()
        while i < len(text) and text[i].isspace():
            i += 1
    return out


def _ew(f, a, b):
    """An arithmetic operator entry by entry on lists and matrices."""
    if isinstance(a, list) or isinstance(b, list):
        if isinstance(a, list) and isinstance(b, list):
            if len(a) != len(b):
                raise ValueError("Maxima: lists of unequal length")
            return [_ew(f, x, y) for x, y in zip(a, b, strict=True)]
        return [_ew(f, x, b) for x in a] if isinstance(a, list) else [_ew(f, a, y) for y in b]
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.shape != b.shape:
        raise ValueError(f"Maxima: matrices of shapes {a.shape} and {b.shape}")
    if isinstance(a, str) or isinstance(b, str) or isinstance(a, bool) or isinstance(b, bool):
        raise ValueError(f"Maxima: arithmetic on {a!r}, {b!r}")
    return f(a, b)


def _flatten(x):
    if isinstance(x, list):
        return [y for v in x for y in _flatten(v)]
    return [x]


def _abs(x):
    if isinstance(x, list):
        return [_abs(v) for v in x]
    return np.abs(x) if isinstance(x, np.ndarray) else abs(x)


_FUNCTIONS = {
    "matrix": lambda *rows: np.array(rows, dtype=float),
    "args": lambda m: [list(map(float, r)) for r in m] if isinstance(m, np.ndarray) else
    (_ for _ in ()).throw(ValueError("Maxima: args of a non-matrix")),
    "flatten": _flatten,
    "abs": _abs,
    "lmax": lambda lst: max(lst),
    "lmin": lambda lst: min(lst),
    "max": lambda *xs: max(xs),
    "floor": lambda x: float(math.floor(x)),
    "is": lambda b: b if isinstance(b, bool) else
    (_ for _ in ()).throw(ValueError(f"Maxima: is({b!r})")),
}


class _Parser:
    def __init__(self, tokens, env):
        self.t, self.i, self.env, self.skip = tokens, 0, env, 0

    def ap(self, f, *args):
        """``f(*args)``, or nothing in a branch not taken (Maxima's ``if`` evaluates
        only the branch it takes)."""
        return None if self.skip else f(*args)

    def peek(self):
        return self.t[self.i] if self.i < len(self.t) else ("end", "")

    def take(self, want=None):
        tok = self.peek()
        if want is not None and tok[1] != want:
            raise SyntaxError(f"Maxima: expected {want!r}, got {tok[1]!r}")
        self.i += 1
        return tok

    def expr(self):
        if self.peek() == ("name", "if"):
            self.take()
            c = self.expr()
            if not self.skip and not isinstance(c, bool):
                raise ValueError(f"Maxima: if of {c!r}")
            self.take("then")
            self.skip += not c
            a = self.expr()
            self.skip -= not c
            self.take("else")
            self.skip += bool(c)
            b = self.expr()
            self.skip -= bool(c)
            return a if c else b
        return self.or_()

    def or_(self):
        v = self.and_()
        while self.peek() == ("name", "or"):
            self.take()
            w = self.and_()
            v = self.ap(lambda x, y: _truth(x) or _truth(y), v, w)
        return v

    def and_(self):
        v = self.not_()
        while self.peek() == ("name", "and"):
            self.take()
            w = self.not_()
            v = self.ap(lambda x, y: _truth(x) and _truth(y), v, w)
        return v

    def not_(self):
        if self.peek() == ("name", "not"):
            self.take()
            return self.ap(lambda x: not _truth(x), self.not_())
        return self.cmp()

    def cmp(self):
        a = self.sum()
        op = self.peek()[1]
        if op in ("=", "<", "<=", ">", ">="):
            self.take()
            b = self.sum()
            if self.skip:
                return None
            if op == "=":
                return type(a) is type(b) and bool(np.all(a == b)) \
                    if not isinstance(a, np.ndarray) else \
                    isinstance(b, np.ndarray) and a.shape == b.shape and bool(np.all(a == b))
            if not all(isinstance(x, float | int) and not isinstance(x, bool) for x in (a, b)):
                raise ValueError(f"Maxima: {op} on {a!r}, {b!r}")
            return {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b}[op]
        return a

    def sum(self):
        v = self.prod()
        while self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            w = self.prod()
            v = self.ap(_ew, (lambda x, y: x + y) if op == "+" else (lambda x, y: x - y), v, w)
        return v

    def prod(self):
        v = self.dot()
        while self.peek()[1] in ("*", "/"):
            op = self.take()[1]
            w = self.dot()
            v = self.ap(_ew, (lambda x, y: x * y) if op == "*" else (lambda x, y: x / y), v, w)
        return v

    def dot(self):
        v = self.unary()
        while self.peek()[1] == ".":
            self.take()
            w = self.unary()
            v = self.ap(_dot, v, w)
        return v

    def unary(self):
        if self.peek()[1] == "-":
            self.take()
            return self.ap(_ew, lambda x, y: x * y, -1.0, self.unary())
        return self.power()

    def power(self):
        v = self.atom()
        if self.peek()[1] == "^":
            self.take()
            v = self.ap(_ew, lambda x, y: x ** y, v, self.unary())
        return v

    def atom(self):
        kind, text = self.take()
        if kind == "num":
            return float(text)
        if text == "(":
            v = self.expr()
            self.take(")")
            return v
        if text == "[":
            items = self.items("]")
            return items
        if kind == "name":
            if self.peek()[1] == "(":
                self.take()
                args = self.items(")")
                if text not in _FUNCTIONS:
                    raise NameError(f"Maxima: no function {text!r} in this reader")
                return self.ap(_FUNCTIONS[text], *args)
            if text == "%pi":
                return math.pi
            if text in ("true", "false"):
                return text == "true"
            if text == EMPTY:
                return EMPTY
            if text not in self.env and not self.skip:
                raise NameError(f"Maxima: {text!r} is not defined")
            return self.env.get(text)
        raise SyntaxError(f"Maxima: unexpected {text!r}")

    def items(self, close):
        out = []
        if self.peek()[1] == close:
            self.take()
            return out
        while True:
            out.append(self.expr())
            if self.take()[1] == close:
                return out


def _dot(v, w):
    if not (isinstance(v, np.ndarray) and isinstance(w, np.ndarray)):
        raise ValueError("Maxima: . of non-matrices")
    return v @ w


def _truth(v):
    if not isinstance(v, bool):
        raise ValueError(f"Maxima: {v!r} is not a truth")
    return v


def run_maxima(text: str, env: dict) -> dict:
    """Evaluate ``name: expr;`` statements in order, in ``env`` (updated and returned)."""
    for stmt in [s for s in text.split(";") if s.strip()]:
        toks = _tokens(stmt)
        if len(toks) < 3 or toks[0][0] != "name" or toks[1][1] != ":":
            raise SyntaxError(f"Maxima: not an assignment: {stmt.strip()[:40]!r}")
        p = _Parser(toks[2:], env)
        env[toks[0][1]] = p.expr()
        if p.i != len(p.t):
            raise SyntaxError(f"Maxima: left over in {stmt.strip()[:60]!r}")
    return env


def _answer_test(name: str, sans, tans) -> bool:
    if name != "AlgEquiv" or not isinstance(tans, bool) or not isinstance(sans, bool):
        raise ValueError(f"this reader knows AlgEquiv of truths only, not {name}")
    return sans == tans


def questions(xml_text: str) -> dict[str, ET.Element]:
    """The STACK questions of a Moodle XML file by ``idnumber``."""
    root = ET.fromstring(xml_text.encode("utf-8"))
    return {q.findtext("idnumber"): q for q in root.iter("question")
            if q.get("type") == "stack"}


def boxes(q: ET.Element) -> dict[str, tuple[str, str]]:
    """Answer box name -> (input name, input type), read from each PRT's answer notes."""
    types = {i.findtext("name"): i.findtext("type") for i in q.iter("input")}
    out = {}
    for prt in q.iter("prt"):
        note = prt.find("node").findtext("trueanswernote")
        inp = prt.findtext("name").removeprefix("prt_")
        out[note.rsplit(": ", 1)[0]] = (inp, types[inp])
    return out


def mark(q: ET.Element, responses: dict) -> tuple[float, dict]:
    """The question's mark as a fraction, and each PRT's score and last answer note.

    ``responses``: input name -> the student's value (a float, a 2-D float array for a
    matrix input, or :data:`EMPTY`)."""
    env = dict(responses)
    run_maxima(q.findtext("questionvariables/text") or "", env)
    total = got = 0.0
    notes = {}
    for prt in q.iter("prt"):
        local = run_maxima(prt.findtext("feedbackvariables/text") or "", dict(env))
        nodes = {n.findtext("name"): n for n in prt.iter("node")}
        score, name, note = 0.0, "0", ""
        while name != "-1":
            n = nodes[name]
            sans = _Parser(_tokens(n.findtext("sans")), local).expr()
            tans = _Parser(_tokens(n.findtext("tans")), local).expr()
            branch = "true" if _answer_test(n.findtext("answertest"), sans, tans) else "false"
            if n.findtext(f"{branch}scoremode") != "=":
                raise ValueError("this reader knows score mode = only")
            score = float(n.findtext(f"{branch}score"))
            note = n.findtext(f"{branch}answernote")
            name = n.findtext(f"{branch}nextnode")
        value = float(prt.findtext("value"))
        total += value
        got += value * score
        notes[prt.findtext("name")] = (score, note)
    return got / total, notes


def question_tests(q: ET.Element) -> list[tuple[str, bool]]:
    """Run a question's own STACK question tests (``<qtest>``): each test input evaluated
    in Maxima with the question variables, the question marked, each PRT's score and
    last answer note compared with the expected. Returns ``[(description, passed)]``."""
    qvars = run_maxima(q.findtext("questionvariables/text") or "", {})
    out = []
    for t in q.iter("qtest"):
        responses = {i.findtext("name"): _Parser(_tokens(i.findtext("value")), qvars).expr()
                     for i in t.iter("testinput")}
        _, notes = mark(q, responses)
        ok = all(notes[x.findtext("name")] == (float(x.findtext("expectedscore")),
                                                x.findtext("expectedanswernote"))
                 for x in t.iter("expected"))
        out.append((t.findtext("description"), ok))
    return out
