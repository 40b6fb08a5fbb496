r"""The second semantics' reading of ``q_4`` beside a declared vector ``\mathbf{q}``,
written from the attitude books, not from the reader: a ``--let``'s vector of n
entries has entries ``q_1 ... q_n`` (Markley & Crassidis, Shuster); a 4-vector may be
counted from 0 instead (Diebel's, Kuipers' ``q_0 ... q_3``, scalar first), a choice point of
the letter whose reading fails where its count does not fit (``q_0`` from 1, ``q_4`` from
0); a declared 3-vector's ``n_x``, ``n_y``, ``n_z`` are its entries 1 to 3; another
subscript (Kuipers' ``q_0`` beside a 3-vector) names a symbol of its own.
Imports lark and the standard library only (the contract of :mod:`rigidsym.numeval`)."""

from __future__ import annotations

import lark
import mpmath as mp

from rigidsym.numeval import values as V

__all__ = ["entry_of_declared", "entries_of", "range_under_accent"]


def entry_of_declared(ev, t, k: int, letter: str, decls: dict, base_letter, text_of):
    r"""The entry ``q_k`` (the glyph ``t``) of the declared vector of ``letter``, or ``None``
    where it names a symbol of its own.

    Args:
        ev: the :class:`rigidsym.numeval.evaluator.Evaluator`.
        t: the glyph tree; k: its subscript.
        letter: its letter; decls: the declarations by key.
        base_letter, text_of: the evaluator's own readers of a glyph tree.

    Raises:
        NotCovered: a 4-vector's ``q_0`` counted from 1 or ``q_4`` from 0 (the reading
            is dropped).
    """
    busy = ev.env.point.get(" evaluating", ())
    for key, d in decls.items():
        if not (isinstance(d.name, lark.Tree) and base_letter(d.name)[0] == letter
                and base_letter(d.name)[2]) or key in busy:
            continue  # (a model written in its own entries, \mathbf{q} = [q_1; ...]: names)
        if base_letter(t)[1]:  # a bold q_4 (a vector's name in the books): a choice
            if ev.choose(f"entries of {letter}", ("name", "entry")) == "name":
                return None
            v = ev.value(d.name)
            if not V.is_matrix(v) or v.cols != 1 or not 1 <= k <= v.rows:
                raise V.NotCovered(f"{text_of(t)}: entry {k} of {text_of(d.name)}")
            return v[k - 1]
        v = ev.value(d.name)
        if not V.is_matrix(v) or v.cols != 1 or v.rows == 1:
            return None
        if v.rows == 4 and k <= 4:
            zero = ev.choose(f"count of {letter}", ("from 1", "from 0")) == "from 0"
            i = k if zero else k - 1
            if not 0 <= i <= 3:
                raise V.NotCovered(f"{text_of(t)}: entry {k} of the 4-vector "
                                   f"{text_of(d.name)} counted from {int(not zero)}")
            return v[i]
        return v[k - 1] if 1 <= k <= v.rows else None
    return None


def _axis_entry(ev, i: int, letter: str, base_letter):
    """``n_x``, ``n_y``, ``n_z``: entry ``i`` (from 0) of the declared 3-vector of
    ``letter``, as the books write a unit axis's components; ``None`` where no declared
    3-vector has that letter (a symbol of its own)."""
    busy = ev.env.point.get(" evaluating", ())
    for key, d in ev.env.decls.items():
        if not (isinstance(d.name, lark.Tree) and base_letter(d.name)[0] == letter
                and base_letter(d.name)[2]) or key in busy:
            continue  # (Meriam & Kraige's omega = [omega_x; ...]: the body's own names)
        v = ev.value(d.name)
        if V.is_matrix(v) and v.cols == 1 and v.rows == 3:
            return v[i]
    return None


def entries_of(ev, t, base_letter, text_of):
    r"""``q_{1:3}``: entries 1 to 3 of the vector q (1-based, inclusive), ``q_{4:4}`` entry 4;
    ``q_4`` beside a declared ``q`` or ``\mathbf{q}`` (:func:`entry_of_declared`); ``None``
    where the glyph ``t`` is neither.

    Raises:
        NotCovered: a range of a value that is no vector or past its entries."""
    if t.data != "glyph" or len(t.children) != 2:
        return None
    sub = t.children[1]
    if not isinstance(sub, lark.Tree) or sub.data != "subscript" or len(sub.children) != 1:
        return None
    tok = sub.children[0]
    if not (isinstance(tok, lark.Token) and tok.type == "SUBRANGE"):
        if isinstance(tok, lark.Token) and tok.type == "SUBATOM" and str(tok).isdigit():
            return entry_of_declared(ev, t, int(str(tok)), base_letter(t)[0], ev.env.decls,
                                     base_letter, text_of)
        if isinstance(tok, lark.Token) and tok.type == "SUBATOM" and str(tok) in "xyz" \
                and len(str(tok)) == 1 and not base_letter(t)[1]:
            return _axis_entry(ev, "xyz".index(str(tok)), base_letter(t)[0], base_letter)
        return None
    lo, hi = (int(x) for x in str(tok).replace(" ", "").split(":"))
    v = ev.value(lark.Tree("glyph", [t.children[0]]))
    if not V.is_matrix(v) or v.cols != 1 or not 1 <= lo <= hi <= v.rows:
        raise V.NotCovered(f"the entries {text_of(t)}")
    if lo == hi:
        return v[lo - 1]
    return mp.matrix([v[i] for i in range(lo - 1, hi)])


def range_under_accent(t) -> tuple | None:
    r"""``\bar{q}_{1:3}`` (an accented tree whose glyph ends in a range subscript, as
    :func:`rigidsym.numeval.names.canonical` moves it under the accent): ``(whole, lo,
    hi)``, ``whole`` the accented glyph without the range (``\bar{q}``, whose entries
    ``lo`` to ``hi`` are meant, 1-based, inclusive); ``None`` for any other tree."""
    if not isinstance(t, lark.Tree) or t.data != "accented" or len(t.children) != 2:
        return None
    accent, inner = t.children
    if not isinstance(inner, lark.Tree) or inner.data != "glyph" or len(inner.children) != 2:
        return None
    sub = inner.children[1]
    if not isinstance(sub, lark.Tree) or sub.data != "subscript" or len(sub.children) != 1:
        return None
    tok = sub.children[0]
    if not (isinstance(tok, lark.Token) and tok.type == "SUBRANGE"):
        return None
    lo, hi = (int(x) for x in str(tok).replace(" ", "").split(":"))
    return lark.Tree("accented", [accent, lark.Tree("glyph", [inner.children[0]])]), lo, hi
