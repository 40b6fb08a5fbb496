r"""The second semantics' reading of ``q_4`` beside a declared vector ``\mathbf{q}`` (issue 63,
wave 11), written from the attitude books, not from the reader: a ``--let``'s vector of n
entries has entries ``q_1 ... q_n`` (Markley & Crassidis, Shuster); a 4-vector may be
counted from 0 instead (Diebel's, Kuipers' ``q_0 ... q_3``, scalar first), a choice point of
the letter whose reading fails where its count does not fit (``q_0`` from 1, ``q_4`` from
0); another subscript (Kuipers' ``q_0`` beside a 3-vector) names a symbol of its own.
Imports lark and the standard library only (the contract of :mod:`rigidsym.numeval`)."""

from __future__ import annotations

import lark

from rigidsym.numeval import values as V

__all__ = ["entry_of_declared"]


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
    for d in decls.values():
        if not (isinstance(d.name, lark.Tree) and base_letter(d.name)[0] == letter
                and base_letter(d.name)[2]):
            continue
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
