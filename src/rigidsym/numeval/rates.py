"""Declared rates of the functions of time, the second semantics' own: with a
``--let '\\dot{\\mathbf{q}} = ...'`` the rate of ``q`` is a model (the kinematic
differential equations of the attitude books), so ``q`` cannot follow a random motion of
its own; ``\\frac{d}{dt}X`` and ``\\dot X`` of a model ``X`` are then the derivative of
``X`` along the rates: every function of time ``x`` moved to ``x + s xdot`` (its declared
rate, or the derivative of its own motion where none is declared; time to ``t + s``), ``X``
evaluated again there and differentiated in ``s`` by central differences of order 4 at the
evaluator's precision. A declared rate also makes its symbol a function of time, as the
reader takes it.

Imports lark, mpmath and the standard library only (the import-linter contract of
:mod:`rigidsym.numeval`); the evaluator's classes come in with the evaluator asking.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import lark
import mpmath as mp

from rigidsym.numeval import motion, names
from rigidsym.numeval import values as V
from rigidsym.numeval.values import NotCovered

__all__ = ["with_rates", "declared", "is_model", "time_derivative"]

_TIME_TREE = lark.Tree("glyph", [lark.Tree("base", [lark.Token("LETTER", "t")])])
_TIME = "glyph(base(t))"


def _rate_target(d, key_of) -> str:
    """The glyph key of ``X`` when ``d`` declares ``\\dot X = ...`` (a model), else ``""``."""
    t = names.canonical(d.name)  # \dot\theta_1 is \dot{\theta_1}
    if d.body is None or d.params or not isinstance(t, lark.Tree):
        return ""
    if t.data in ("accented", "accented_bare") and len(t.children) == 2 \
            and str(t.children[0]).strip() == "\\dot":
        return key_of(_under_dot(t))
    return ""


def with_rates(decls: list, key_of: Callable[[object], str]) -> list:
    """``decls`` with each symbol whose rate a ``--let '\\dot X = ...'`` declares marked a
    function of time (``timed``), as the reader marks it.

    Args:
        decls: the declarations (:class:`rigidsym.numeval.evaluator.Decl`).
        key_of: the evaluator's glyph key of a tree.
    """
    rated = {_rate_target(d, key_of): d for d in decls}
    rated.pop("", None)
    out = [dataclasses.replace(d, timed=True) if key_of(d.name) in rated and d.kind
           and not d.timed else d for d in decls]
    own = {key_of(d.name) for d in decls}
    for key, d in rated.items():  # a rate alone: its symbol of the book's conventional shape
        if key not in own:
            inner = _under_dot(names.canonical(d.name))
            out.append(type(d)(inner, (), _conventional(inner), None, f"{key}(t)", True))
    return out


def _under_dot(t):
    inner = t.children[1]
    if inner.data == "bare":
        inner = lark.Tree("glyph", [lark.Tree("base", list(inner.children))])
    return inner


def _conventional(t) -> str:
    """The kind of a free glyph by the book's convention: bold lower-case a vector, bold
    capital a matrix, anything else a scalar."""
    base = t.children[0] if t.data == "glyph" and t.children else None
    toks = [str(c) for c in base.children] if isinstance(base, lark.Tree) \
        and base.data == "base" else []
    if len(toks) == 2:
        return "matrix" if toks[-1].lstrip("\\")[:1].isupper() else "vector"
    return "scalar"


def declared(decls: dict, key_of: Callable[[object], str]) -> dict:
    """The declared rates: glyph key of X -> the declaration of ``\\dot X``."""
    out = {}
    for d in decls.values():
        k = _rate_target(d, key_of)
        if k and k in decls and decls[k].timed:
            out[k] = d
    return out


def is_model(d: object) -> bool:
    """``d`` is a ``--let NAME = LATEX`` model (no parameters): its ``\\dot`` is d/dt of its
    value."""
    return d is not None and d.body is not None and not d.params


def time_derivative(ev: object, expr: lark.Tree, key_of: Callable[[object], str],
                    digits: int) -> object:
    """d/dt of the subtree ``expr`` along the declared rates (see the module's text).

    Args:
        ev: the evaluator asking (its environment gives the point).
        expr: the parse subtree.
        key_of: the evaluator's glyph key of a tree.
        digits: the working precision (decimal digits); the step is ``10^(-digits/5)``.

    Returns:
        The derivative, of the value's shape (an mpmath scalar or matrix).

    Raises:
        NotCovered: a function of time with no motion of its kind, or a derivative of an
            unsized identity or zero.
    """
    env = ev.env
    rates = declared(env.decls, key_of)
    t0 = V.scalar(env.lookup(_TIME, _TIME_TREE))
    h = mp.mpf(10) ** (-digits // 5)
    start, step = {_TIME: t0}, {_TIME: mp.mpf(1)}
    needed = _depends(expr, env.decls, key_of)
    for key, d in env.decls.items():
        if not (d.timed and d.kind) or key not in needed:
            continue  # a function of time expr does not depend on: its rate is not read
        start[key] = env.lookup(key, d.name)
        if key in rates:
            step[key] = env.lookup(key_of(rates[key].name), rates[key].name)
        else:
            c = env.point[key]  # drawn by the lookup above
            f = [motion.at(c, t0 + k * h) for k in (-2, -1, 1, 2)]
            step[key] = _combine(f, [1, -8, 8, -1], 12 * h)

    def at(s):
        binds = dict(env.binds)
        for key, x0 in start.items():
            binds[key] = V.add(x0, V.mul(s, step[key]))
        moved = type(env)(env.decls, env.point, env.rng, binds, None, env.depth + 1)
        v = type(ev)(moved).value(expr)
        if isinstance(v, V.Eye | V.Zero):
            raise NotCovered("the derivative of an unsized identity or zero")
        return v

    return _combine([at(k * h) for k in (-2, -1, 1, 2)], [1, -8, 8, -1], 12 * h)


_GLYPH_RULES = ("glyph", "accented", "accented_bare", "indexed_accent", "label_first", "arrow")


def _depends(expr, decls: dict, key_of: Callable[[object], str]) -> set[str]:
    """The glyph keys ``expr`` mentions, through the models of the declarations it mentions
    (their bodies, transitively): the functions of time whose rates its derivative needs.
    Reading only these keeps a rate's model that mentions the derivative being taken (Mahony
    et al.'s ``\\dot{\\hat R} = \\hat R(\\Omega + \\omega)_\\times`` beside ``\\Omega``, the body
    angular velocity of ``R``) from being evaluated inside it."""
    by_letter: dict[str, list[str]] = {}  # q_1 is an entry of q: a glyph's letter's names
    for key, d in decls.items():
        by_letter.setdefault(_letter(d.name), []).append(key)
    seen: set[str] = set()
    todo = [expr]
    while todo:
        t = todo.pop()
        for sub in t.iter_subtrees() if isinstance(t, lark.Tree) else ():
            if sub.data == "bare":
                sub = lark.Tree("glyph", [lark.Tree("base", list(sub.children))])
            elif sub.data not in _GLYPH_RULES:
                continue
            letter = _letter(sub)
            whole = _unsliced(sub)  # \bar{q}_{1:1}: an entry of \bar{q}, which it needs
            for key in [key_of(sub), *([key_of(whole)] if whole is not None else ()),
                        *(by_letter.get(letter, ()) if letter else ())]:
                if key in seen:
                    continue
                seen.add(key)
                d = decls.get(key)
                if d is not None and d.body is not None:
                    todo.append(d.body)
    return seen


def _unsliced(t):
    """The glyph tree ``t`` without its subscripts (``\\bar{q}`` of ``\\bar{q}_{1:1}``),
    ``None`` where it has none."""
    kept = [c for c in t.children if not (isinstance(c, lark.Tree) and c.data == "subscript")]
    return lark.Tree(t.data, kept) if len(kept) < len(t.children) and kept else None


def _letter(t) -> str:
    """The letter of a plain glyph tree (``q`` of ``q_1``, of ``\\mathbf{q}``), else ``""``."""
    if not (isinstance(t, lark.Tree) and t.data in ("glyph", "label_first") and t.children
            and isinstance(t.children[0], lark.Tree) and t.children[0].children):
        return ""
    return str(t.children[0].children[-1]).strip()


def _combine(vals, coeffs, den):
    out = None
    for v, c in zip(vals, coeffs, strict=True):
        term = v * c
        out = term if out is None else out + term
    return out / den
