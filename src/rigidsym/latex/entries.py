r"""A subscripted letter beside a declared vector of that letter: ``q_4``
beside ``--let '\mathbf{q}: unit 4-vector'`` is entry 4 of ``\mathbf{q}``, as every attitude
book writes a vector's entries (Markley & Crassidis' ``q_4``, Shuster's ``q_1 ... q_4``).

- A vector declared by a ``--let`` (a kind or a model), n entries: ``q_k`` with 1 <= k <= n is
  entry k, counted from 1 (said under ``read as:``; ``--let 'q_k: scalar'`` makes it a symbol
  of its own); another ``q_k`` (Kuipers' ``q_0`` beside the vector part ``\mathbf{q}``) is a
  symbol of its own, as before.
- A declared 4-vector (a quaternion) is counted from 1 (``q_1 ... q_4``, scalar last) or from
  0 (Diebel's, Kuipers' ``q_0 ... q_3``, scalar first): a choice point of the letter, both
  readings read; a ``q_0`` makes counting from 1 fail and a ``q_4`` counting from 0, so the
  reading is unique wherever the LaTeX writes either; where it writes neither and the two
  verdicts differ, the statement is refused naming the entry that settles it
  (``\mathbf{q}_{1:1}``).
- A 3-vector declared by a ``--let``: ``n_x``, ``n_y``, ``n_z`` are its entries 1, 2, 3
  (Rotations.jl's ``R_{\bm{n}}`` written out in ``n_x ... n_z``; :data:`AXES`), said under
  ``read as:`` the same way; ``--let 'n_x: scalar'`` makes one a symbol of its own.
- A bold subscripted name, ``\mathbf{p}_1`` beside ``\mathbf{p}``, is a vector's name in the
  books (point 1) as often as an entry: a choice point between a symbol of its own and the
  entry; the rule above reads the plain (or Greek) letters only.
- A function's parameter that no ``--let`` declares globally (``R(\mathbf{q})`` with only its
  body's ``q_i``): a choice point between a symbol of its own and an entry,
  since the statement's own ``q_i`` are then no entries of anything.

The entry reading is not a choice point for a declared vector's letter because the two
readings disagree on any identity of a unit quaternion: a choice there would refuse every
such identity as ambiguous.
"""

from __future__ import annotations

__all__ = ["AXES", "DECLARED_PARAM", "BASE_READINGS", "entry_index", "is_base_point", "base_point",
           "base_words", "base_settles"]

#: the end of a parameter glyph's meaning when a ``--let`` declares the global vector of
#: that name too (its subscripts are entries in the body as outside it)
DECLARED_PARAM = " (a --let declares it too)"

#: the readings of a 4-vector's subscripts, the default first: counted from 1, from 0
BASE_READINGS = ("entry", "entry0")

_BASE = " counted from 1 or 0"

#: the axis subscripts of a 3-vector's entries, and the entry each names (from 1)
AXES = {"x": 1, "y": 2, "z": 3}


def is_base_point(key: str) -> bool:
    """The choice point ``key`` is the counting of a 4-vector's subscripts."""
    return key.endswith(_BASE)


def base_point(vkey: str) -> str:
    r"""The choice point of the 4-vector ``vkey``'s subscripts: one for the letter, so that
    every ``q_k`` is counted alike (a subscript met only past another's failure, too)."""
    return f"the entries of {vkey}{_BASE}"


def entry_index(key: str, vkey: str, k: int, n: int, choices: dict,
                points: dict) -> tuple[int | None, str]:
    r"""Which entry of the declared n-vector ``vkey`` the glyph ``key`` (subscript ``k``)
    is, counted from 0, and the note; ``(None, note)`` where it is a symbol of its own.

    Args:
        key, vkey: the glyph (``q_{4}``) and the vector's key (``\mathbf{q}``).
        k: the subscript; n: the vector's entries.
        choices: the reading of each choice point; points: the points met, updated.

    Raises:
        ValueError: a 4-vector's ``q_0`` counted from 1, or its ``q_4`` counted from 0 (the
            reading does not fit; the caller makes it a ``LatexError`` and the reading is
            dropped).
    """
    if n != 4:
        if 1 <= k <= n:
            return k - 1, (f"{key}: read as entry {k} of {vkey} (counted from 1; --let "
                           f"'{key}: scalar' for a symbol of its own)")
        return None, ""
    if k > 4:
        return None, ""
    point = base_point(vkey)
    points[point] = BASE_READINGS
    if choices.get(point, BASE_READINGS[0]) == "entry0":
        if not 0 <= k <= 3:
            raise ValueError(f"{key} beside the 4-vector {vkey} counted from 0 (q_0 to q_3)")
        return k, f"{key}: read as entry {k + 1} of {vkey}, counted from 0 (a choice: or from 1)"
    if not 1 <= k <= 4:
        raise ValueError(f"{key} beside the 4-vector {vkey} counted from 1 (q_1 to q_4)")
    return k - 1, f"{key}: read as entry {k} of {vkey}, counted from 1 (a choice: or from 0)"


def base_words(key: str, choice: str) -> str:
    """One reading of the point ``key`` in words."""
    return f"{key[:-len(_BASE)]} counted from {0 if choice == 'entry0' else 1}"


def base_settles(key: str) -> str:
    """The ways to write what the subscripts of ``key``'s vector mean, for a refusal."""
    vec = key[len("the entries of "):-len(_BASE)]
    return (f"write the entry meant as {vec}_{{k:k}}, counted from 1 (q_1 is {vec}_{{1:1}} "
            f"counted from 1, {vec}_{{2:2}} counted from 0), or --let 'q_k: scalar' for a "
            f"symbol of its own")
