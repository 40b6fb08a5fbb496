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

from certcheck.limits import MAX_NESTING

__all__ = ["ParseError", "parse", "names_in"]

_TOKEN = re.compile(r"\s*(?:(\d+|[A-Za-z][A-Za-z0-9_.]*'*|[-^*/+()])|(\S))")


class ParseError(ValueError):
    """Text outside the grammar."""


def _tokens(text: str) -> list[str]:
    """The tokens (an integer, a name or an operator, told apart by the first character)."""
    found = _TOKEN.findall(text)
    bad = [b for _, b in found if b]
    if bad:
        raise ParseError(f"unexpected character {bad[0]!r}")
    return [t for t, _ in found]


class _Parser:
    def __init__(self, text: str, lets: dict):
        self.toks, self.i, self.lets, self.depth = _tokens(text), 0, lets, 0

    def deeper(self) -> None:
        """One more level of parentheses or minus signs; past :data:`MAX_NESTING`, a
        refusal (never a recursion error)."""
        self.depth += 1
        if self.depth > MAX_NESTING:
            raise ParseError(f"nested deeper than {MAX_NESTING} levels (certcheck's limit)")

    def peek(self) -> str:
        return self.toks[self.i] if self.i < len(self.toks) else ""

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if not tok or want is not None and tok != want:
            raise ParseError(f"expected {want or 'more'}, got {tok or 'the end'!r}")
        self.i += 1
        return tok

    def expr(self):
        node = self.term()
        while self.peek() in ("+", "-"):
            node = ("add" if self.take() == "+" else "sub", node, self.term())
        return node

    def term(self):
        node = self.unary()
        while self.peek() in ("*", "/"):
            node = ("mul" if self.take() == "*" else "div", node, self.unary())
        return node

    def unary(self):
        if self.peek() == "-":
            self.take()
            self.deeper()
            node = ("neg", self.unary())
            self.depth -= 1
            return node
        return self.power()

    def power(self):
        node = self.atom()
        if self.peek() == "^":
            self.take()
            sign = -1 if self.peek() == "-" else 1
            self.i += sign < 0
            if not (n := self.take()).isdigit():
                raise ParseError(f"expected an integer exponent, got {n!r}")
            node = ("pow", node, sign * int(n))
        return node

    def atom(self):
        tok = self.take()
        if tok[0].isdigit():
            return ("num", int(tok))
        if tok in ("cos", "sin", "sqrt"):
            self.take("(")
            self.deeper()
            arg = self.expr()
            self.take(")")
            self.depth -= 1
            return (tok, arg)
        if tok[0].isalpha():
            return ("pi",) if tok == "pi" else self.lets[tok] if tok in self.lets else \
                ("name", tok)
        if tok == "(":
            self.deeper()
            node = self.expr()
            self.take(")")
            self.depth -= 1
            return node
        raise ParseError(f"unexpected {tok!r}")


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
        raise ParseError(f"trailing text after position {p.i}: {p.toks[p.i]!r}")
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
