"""The canonical form of the transcription check (:mod:`rigidsym.latex.transcription`): a
side of a relation as an explicit value with the book symbols as free atoms, only notational
atoms (a glyph-table row with a definition) replaced by their definitions, and the zero test
of a difference up to sign.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.algebra.symbols import angle
from rigidsym.checking.deciding.explicit import explicit
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.table import glyph_table
from rigidsym.zero import decide_zero

__all__ = ["definitions", "free", "difference", "same", "roots"]

_ANGLES = ("phi", "theta")


def _definitions(section: str) -> dict:
    """Notational atoms of a section: name -> parsed definition."""
    out = {}
    rows = [g for g in glyph_table() if g.definition]
    best: dict = {}
    for g in rows:
        if g.section == "*" or section == g.section or section.startswith(g.section + "."):
            prev = best.get(g.name)
            if prev is None or len(g.section) > len(prev.section):
                best[g.name] = g
    for name, g in best.items():
        p = parse_latex(f"{g.latex} = {g.definition}", section)
        out[name] = p.chains[0][1]
    return out


@cache
def definitions(section: str) -> dict:
    """The notational atoms of ``section`` with a definition in the glyph table: ``{name: the
    parsed definition}``, the most specific section's row winning (cached)."""
    return _definitions(section)


def free(x, defs: dict, aliases: dict):
    """The explicit value of ``x`` with book symbols as free atoms (see the module doc)."""
    if not isinstance(x, sp.Basic):
        x = sp.sympify(x)
    for _ in range(3):  # notational atoms may refer to one another
        swap = {}
        for s in x.atoms(sp.MatrixSymbol, sp.Symbol):
            name = aliases.get(s.name, s.name)
            if name in defs and defs[name] is not s:
                swap[s] = defs[name]
            elif name.startswith("norm_"):
                swap[s] = _norm(name[5:], defs)
            elif name != s.name:
                swap[s] = (sp.MatrixSymbol(name, *s.shape) if isinstance(s, sp.MatrixSymbol)
                           else sp.Symbol(name, real=True))
        if not swap:
            break
        x = x.xreplace(swap)
    # an inverse stays an atom of its own, keyed by what it inverts (never expanded)
    for inv in sorted(x.atoms(sp.Inverse), key=lambda v: len(str(v))):
        key = "inv(" + sp.srepr(inv.arg) + ")"
        x = x.xreplace({inv: sp.MatrixSymbol(f"inv{abs(hash(key)) % 10**8}", *inv.shape)})
    for p in sorted(x.atoms(sp.MatPow), key=lambda v: len(str(v))):
        if p.exp == -1:
            key = "inv(" + sp.srepr(p.base) + ")"
            x = x.xreplace({p: sp.MatrixSymbol(f"inv{abs(hash(key)) % 10**8}", *p.shape)})
    # the determinant of a larger matrix stays an atom too (a 6 x 6 of free entries expands
    # to 720 terms); keyed by its argument, so det(U) in both forms is one atom
    from rigidsym.algebra.operators import Det

    for d in sorted(x.atoms(Det, sp.Determinant), key=lambda v: len(str(v))):
        if d.args[0].shape[0] > 3:
            key = "det(" + sp.srepr(d.args[0]) + ")"
            x = x.xreplace({d: sp.Symbol(f"det{abs(hash(key)) % 10**8}", real=True)})
    atoms = {}
    for s in x.atoms(sp.MatrixSymbol):
        atoms[s] = _entries(s.name, *s.shape)
    for s in x.atoms(sp.Symbol):
        if isinstance(s, sp.Dummy) or s in atoms:
            continue
        atoms[s] = angle(s.name) if s.name in _ANGLES else sp.Symbol(s.name, real=True)
    x = x.xreplace(atoms)
    # evaluated structurally on the explicit operands (the checker's explicit()): sympy's
    # doit()/as_explicit() of a product goes through symbolic summation, which took 95 %
    # of the transcription check's time
    x = explicit(x)
    if isinstance(x, sp.MatrixBase):
        return x.applyfunc(lambda e: e.doit())
    return x.doit() if hasattr(x, "doit") else x


def _norm(name: str, defs: dict):
    v = sp.MatrixSymbol({"p21": "p_2"}.get(name, name), 3, 1)
    if name == "p21":
        v = sp.MatrixSymbol("p_2", 3, 1) - sp.MatrixSymbol("p_1", 3, 1)
    return sp.sqrt((v.T * v)[0, 0])


def roots(entries: list) -> list:
    """Odd powers of square roots -> powers of a free positive atom per radicand (exact for
    deciding zero: an identity in a free atom holds at its value)."""
    atoms: dict = {}

    def rep(e):
        for p in sorted(e.atoms(sp.Pow), key=sp.count_ops, reverse=True):
            if p.exp.is_Rational and p.exp.q == 2 and p in e.atoms(sp.Pow):
                r = atoms.setdefault(p.base, sp.Symbol(f"root{len(atoms)}", positive=True))
                e = e.xreplace({p: r ** int(p.exp * 2)})
        return e

    return [rep(e) for e in entries]


def difference(l, r):
    """``l - r`` as a list of entries, or ``None`` when the shapes differ."""
    def shape(v):
        return (v.rows, v.cols) if isinstance(v, sp.MatrixBase) else (1, 1)

    if not isinstance(l, sp.MatrixBase) and l == 0 and isinstance(r, sp.MatrixBase):
        l = sp.zeros(*r.shape)
    if not isinstance(r, sp.MatrixBase) and r == 0 and isinstance(l, sp.MatrixBase):
        r = sp.zeros(*l.shape)
    if shape(l) != shape(r):
        return None
    lv = list(l) if isinstance(l, sp.MatrixBase) else [l]
    rv = list(r) if isinstance(r, sp.MatrixBase) else [r]
    return [a - b for a, b in zip(lv, rv, strict=True)]


def same(dm: list, dp: list) -> tuple[bool | None, object]:
    """Whether ``dm = dp`` or ``dm = -dp`` identically (zero test), with the result."""
    if len(dm) != len(dp):
        return False, None
    best = None
    for sign in (1, -1):
        res = decide_zero(roots([a - sign * b for a, b in zip(dm, dp, strict=True)]))
        if res.zero:
            return True, res
        best = best or res
    return False, best


@cache
def _entries(name: str, rows, cols) -> sp.ImmutableMatrix:
    """The matrix of free real entries ``name[i,j]`` (made once: a fifth of the check's time
    went to building the same ones again)."""
    return sp.ImmutableMatrix(rows, cols, lambda i, j: sp.Symbol(f"{name}[{i},{j}]", real=True))
