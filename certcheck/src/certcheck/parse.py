"""The statement's grammar: a tokenizer and a recursive-descent parser.

::

    expr   := term (("+" | "-") term)*
    term   := unary (("*" | "/") unary)*
    unary  := "-" unary | power
    power  := atom ("^" ["-"] INTEGER)?
    atom   := INTEGER | NAME | "pi" | "(" expr ")" | ("cos" | "sin" | "sqrt") "(" expr ")"
    NAME   := letter (letter | digit | "_" | ".")* "'"*     (a prime per time derivative)

A rational is an integer quotient (``3/4``). A name refers to an atom of the statement or
to an earlier ``let`` (a named subexpression, so a shared part is written once). The
argument of ``cos``/``sin`` must be a rational combination of declared angles and ``pi``;
that is checked where it is evaluated. ``sqrt`` may stand in a definition's statement (which
is not evaluated); the checker decides nothing that holds one. The parse is a tree of tuples:
``("num", int)``, ``("name", str)``, ``("pi",)``, ``("add", a, b)``, ``("sub", a, b)``,
``("mul", a, b)``, ``("div", a, b)``, ``("neg", a)``, ``("pow", a, n)``,
``("cos", a)``, ``("sin", a)``, ``("sqrt", a)``.
"""

from __future__ import annotations

import re

__all__ = ["ParseError", "parse", "names_in"]

_TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z][A-Za-z0-9_.]*'*)|(\^|\*|/|\+|-|\(|\)))")


class ParseError(ValueError):
    """Text outside the grammar."""


def _tokens(text: str) -> list[tuple[str, str]]:
    out = []
    pos = 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise ParseError(f"unexpected character {text[pos:pos + 10]!r} at {pos}")
        pos = m.end()
        if m.group(1) is not None:
            out.append(("int", m.group(1)))
        elif m.group(2) is not None:
            out.append(("name", m.group(2)))
        else:
            out.append(("op", m.group(3)))
    return out


class _Parser:
    def __init__(self, text: str, lets: dict):
        self.toks = _tokens(text)
        self.i = 0
        self.lets = lets

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else ("end", "")

    def take(self, kind=None, value=None):
        tok = self.peek()
        if (kind and tok[0] != kind) or (value and tok[1] != value):
            raise ParseError(f"expected {value or kind}, got {tok[1] or 'the end'!r}")
        self.i += 1
        return tok

    def expr(self):
        node = self.term()
        while self.peek() in (("op", "+"), ("op", "-")):
            op = self.take()[1]
            node = ("add" if op == "+" else "sub", node, self.term())
        return node

    def term(self):
        node = self.unary()
        while self.peek() in (("op", "*"), ("op", "/")):
            op = self.take()[1]
            node = ("mul" if op == "*" else "div", node, self.unary())
        return node

    def unary(self):
        if self.peek() == ("op", "-"):
            self.take()
            return ("neg", self.unary())
        return self.power()

    def power(self):
        node = self.atom()
        if self.peek() == ("op", "^"):
            self.take()
            sign = 1
            if self.peek() == ("op", "-"):
                self.take()
                sign = -1
            node = ("pow", node, sign * int(self.take("int")[1]))
        return node

    def atom(self):
        kind, value = self.peek()
        if kind == "int":
            self.take()
            return ("num", int(value))
        if kind == "name":
            self.take()
            if value in ("cos", "sin", "sqrt"):
                self.take("op", "(")
                arg = self.expr()
                self.take("op", ")")
                return (value, arg)
            if value == "pi":
                return ("pi",)
            if value in self.lets:
                return self.lets[value]
            return ("name", value)
        if (kind, value) == ("op", "("):
            self.take()
            node = self.expr()
            self.take("op", ")")
            return node
        raise ParseError(f"unexpected {value or 'end'!r}")


def parse(text: str, lets: dict | None = None):
    """The tree of ``text``; names bound in ``lets`` (name -> tree) are replaced by their
    trees (shared, not copied).

    Raises:
        ParseError: text outside the grammar.
    """
    if not isinstance(text, str):
        raise ParseError(f"expected an expression string, got {type(text).__name__}")
    p = _Parser(text, lets or {})
    node = p.expr()
    if p.i != len(p.toks):
        raise ParseError(f"trailing text after position {p.i}: {p.toks[p.i][1]!r}")
    return node


def names_in(node, acc: set | None = None, seen: set | None = None) -> set:
    """The atom names a tree uses outside cos/sin arguments (shared subtrees visited
    once)."""
    acc = set() if acc is None else acc
    seen = set() if seen is None else seen
    stack = [node]
    while stack:
        n = stack.pop()
        if id(n) in seen:
            continue
        seen.add(id(n))
        if n[0] == "name":
            acc.add(n[1])
        elif n[0] in ("add", "sub", "mul", "div"):
            stack.extend((n[1], n[2]))
        elif n[0] in ("neg", "pow", "sqrt"):
            stack.append(n[1])
    return acc
