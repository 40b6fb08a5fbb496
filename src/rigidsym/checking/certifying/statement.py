"""The statement of a certificate (:mod:`rigidsym.checking.certifying.certificates`) in its grammar:
sympy entries printed with ``+ - * /``, integer powers, integers, names and ``cos``/``sin``,
every atom given a safe name and its kind's group, and every repeated subexpression written
once as a ``let`` (``docs/certificates.md``). What leaves the grammar raises
:class:`Unprintable`.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement

from rigidsym.algebra.symbols import TIME, constraint_of

__all__ = ["Unprintable"]

#: the kinds the checker knows (``certcheck.kinds``); an atom of another kind: no certificate
_KNOWN = {"unit", "unit4", "rotation", "transform", "angle", "angle_pi"}
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_.]*\Z")
_RESERVED = {"cos", "sin", "pi"}


class Unprintable(ValueError):
    """The statement leaves the certificate grammar (the message names what)."""


class StatementPrinter:
    """Prints sympy entries in the grammar; atoms get safe names, repeated subexpressions
    become ``let``s."""

    def __init__(self):
        self.names: dict = {}      # base atom (Symbol / f(t)) -> safe name
        self.book: dict = {}       # safe name -> book name, where they differ
        self.groups: dict = {}     # group key -> declaration
        self.lets: list = []
        self._let_of: dict = {}
        self._count: dict = {}

    # atoms ---------------------------------------------------------------------
    def _safe(self, name: str) -> str:
        s = name if _NAME.match(name) else re.sub(r"[^A-Za-z0-9_.]", "_", name)
        if not s[:1].isalpha():
            s = "a" + s
        taken = set(self.names.values())
        base, k = s, 1
        while s in taken or s in _RESERVED or s.startswith("let"):
            k += 1
            s = f"{base}_{k}"
        if s != name:
            self.book[s] = name
        return s

    def atom(self, a) -> str:
        if a in self.names:
            return self.names[a]
        c = constraint_of(a)
        if c is None:
            name = a.name if isinstance(a, sp.Symbol) else a.func.__name__
            self.names[a] = self._safe(name)
            self.groups[("free", a)] = {"group": self.names[a], "kind": "free",
                                        "names": [self.names[a]],
                                        "timed": isinstance(a, AppliedUndef)}
            return self.names[a]
        if c.kind not in _KNOWN:
            raise Unprintable(f"an atom of kind {c.kind!r}, which the checker does not know")
        from rigidsym.algebra.symbols import constrained_atom
        safe = [self._safe(n) for n in c.names]
        for n, s in zip(c.names, safe, strict=True):
            self.names[constrained_atom(n, c)] = s
        group = safe[0] if len(safe) == 1 else self._safe(c.name)
        self.groups[c] = {"group": group, "kind": c.kind, "names": safe, "timed": c.timed}
        if a not in self.names:
            raise Unprintable(f"atom {a} is not among its group's names")
        return self.names[a]

    # expressions ---------------------------------------------------------------
    def count(self, e) -> None:
        stack = [e]
        while stack:
            x = stack.pop()
            if x.is_Atom or isinstance(x, AppliedUndef | sp.Derivative | MatrixElement):
                continue
            self._count[x] = self._count.get(x, 0) + 1
            if self._count[x] == 1:
                stack.extend(x.args)

    def text(self, e) -> str:
        """``e`` in the grammar (lets made for repeated subexpressions on the way)."""
        return self._p(e, top=True)

    def _p(self, e, top=False) -> str:
        if e in self._let_of:
            return self._let_of[e]
        s = self._raw(e)
        if not top and self._count.get(e, 0) > 1 and len(s) > 12:
            name = f"let{len(self.lets) + 1}"
            self.lets.append([name, s])
            self._let_of[e] = name
            return name
        return s

    def _raw(self, e) -> str:
        if e.is_Integer:
            return str(int(e))
        if e.is_Rational:
            return f"{int(e.p)}/{int(e.q)}"
        if e is sp.pi:
            return "pi"
        if isinstance(e, sp.Symbol):
            if e == TIME:
                return self.atom(e)
            return self.atom(e)
        if isinstance(e, AppliedUndef):
            if e.args != (TIME,):
                raise Unprintable(f"a function of something other than time: {e}")
            return self.atom(e)
        if isinstance(e, sp.Derivative):
            if not isinstance(e.expr, AppliedUndef):
                raise Unprintable(f"an unevaluated derivative: {e}")
            k = 0
            for v, n in e.variable_count:
                if v != TIME:
                    raise Unprintable(f"a derivative with respect to {v}")
                k += int(n)
            return self.atom(e.expr) + "'" * k
        if isinstance(e, sp.Add):
            terms = [self._p(a) for a in e.args]
            out = terms[0]
            for t in terms[1:]:
                out += f" - {t[1:]}" if t.startswith("-") else f" + {t}"
            return out
        if isinstance(e, sp.Mul):
            c, rest = e.as_coeff_Mul()
            if c.is_negative:
                pos = rest if c == -1 else sp.Mul(-c, rest, evaluate=False)
                return "-" + self._factor(pos) if not isinstance(pos, sp.Mul) else \
                    "-" + "*".join(self._factor(a) for a in sp.Mul.make_args(pos))
            return "*".join(self._factor(a) for a in e.args)
        if isinstance(e, sp.Pow):
            if e.exp in (sp.S.Half, -sp.S.Half):  # only a definition's statement holds one
                root = f"sqrt({self._p(e.base, top=True)})"
                return root if e.exp > 0 else f"1/{root}"
            if not e.exp.is_Integer:
                raise Unprintable(f"a non-integer power: {e}")
            return f"{self._factor(e.base)}^{int(e.exp)}"
        if isinstance(e, MatrixElement) and isinstance(e.parent, sp.MatrixSymbol):
            # an entry of a matrix the model leaves free: a free atom
            return self.atom(sp.Symbol(f"{e.parent.name}_{int(e.i) + 1}{int(e.j) + 1}"))
        if isinstance(e, sp.cos | sp.sin):
            return f"{type(e).__name__}({self._p(e.args[0], top=True)})"
        raise Unprintable(f"{type(e).__name__} ({sp.sstr(e)[:60]})")

    def _factor(self, e) -> str:
        s = self._p(e)
        if s.startswith("-") or any(c in s for c in "+-*/ ") and not _NAME.match(s):
            return f"({s})"
        return s


def _side(x) -> list:
    if isinstance(x, sp.MatrixBase):
        return [list(x.row(i)) for i in range(x.rows)]
    return [[x]]


def relation_record(pr: StatementPrinter, label: str, role: str, lhs, rhs, evidence: dict) -> dict:
    """A relation of a certificate as a record: its ``label``, ``role``, both sides as rows of
    entries printed in the statement's grammar by ``pr``, and its ``evidence``."""
    return {"label": label, "role": role,
            "lhs": [[pr.text(e) for e in row] for row in _side(lhs)],
            "rhs": [[pr.text(e) for e in row] for row in _side(rhs)],
            "evidence": evidence}
