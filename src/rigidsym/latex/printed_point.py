"""A counterexample is the point it claims, in the user's words.

- The rate of a unit vector printed tangent: the reader reads the rate of ``\\mathbf{e}(t)``
  as ``(1 - e e^T) ė`` with ``ė`` free (:mod:`rigidsym.latex.transformer.book_notations`), so
  the symbolic path's point gives the free ``ė``; the statement used its projection on the
  tangent of the sphere. The printed point gives the projection, the value the check used,
  which satisfies ``e · ė = 0``: a reader substituting the printed values by hand finds both
  printed sides (:func:`project_rates`).
- A symbol the reader introduced (a rotation's body velocity ``Q_w``) is printed with what
  it is, never as if the user had written it (:func:`own_symbols_said`).
"""

from __future__ import annotations

import re

import sympy as sp

from rigidsym.checking.deciding.point_values import decimal_text
from rigidsym.printing import notation

__all__ = ["body_velocities", "project_rates", "own_symbols_said"]


def _vector(point: dict, name: str, n: int) -> sp.Matrix | None:
    keys = [f"{name}_{i}" for i in range(1, n + 1)]
    if not all(k in point for k in keys):
        return None
    return sp.Matrix([sp.Rational(sp.sympify(point[k])) for k in keys])


def project_rates(counterexample: dict | None, rows: dict) -> None:
    """Replace, in ``counterexample`` (the symbolic path's, exact strings), each unit
    vector's free rate by its projection ``ė - e (e·ė)``: the value the statement used.

    Args:
        counterexample: ``point`` (atom name -> exact value) and ``symbols`` (the book
            symbols' entries with ``latex``, ``exact``, ``text``, ``decimal``); changed in
            place. ``None``: nothing to do.
        rows: the reading's glyph key -> glyph (``name``, ``meaning``, ``shape``): a glyph
            whose meaning is a unit vector and the free rate ``NAMEdot`` beside it.
    """
    if not counterexample or not counterexample.get("point"):
        return
    point = counterexample["point"]
    for key, g in rows.items():
        shape = tuple(getattr(g, "shape", ()) or ())
        if not str(getattr(g, "meaning", "")).startswith("unit") or len(shape) != 2 \
                or shape[1] != 1:
            continue
        n = shape[0]
        e, d = _vector(point, g.name, n), _vector(point, f"{g.name}dot", n)
        if e is None or d is None or e.dot(e) != 1:
            continue
        tangent = d - e * e.dot(d)
        for i in range(n):
            point[f"{g.name}dot_{i + 1}"] = str(tangent[i])
        for s in counterexample.get("symbols") or []:
            if s.get("latex") in (f"\\dot{{{key}}}", f"\\dot{key}"):
                s.update(exact=sp.sstr(tangent), text=notation.text(tangent),
                         decimal=decimal_text(tangent))


#: the key the reader gives a rotation's (a transform's) body velocity: OWNER_{w}, or
#: OWNER_{w2} ... where a declaration of the user's holds OWNER_{w}
_BODY_KEY = re.compile(r"^(?P<owner>.+)_\{w\d*\}$")


def body_velocities(rows: dict) -> dict[str, str]:
    """The body velocities the reader introduced, by their owners' keys.

    Args:
        rows: the reading's glyph key -> glyph (the reader's own have the meaning
            ``body velocity``).

    Returns:
        owner's glyph key (``\\mathbf{Q}``) -> its body velocity's key (``\\mathbf{Q}_{w}``).
    """
    return {m.group("owner"): key for key, g in (rows or {}).items()
            if getattr(g, "meaning", "") == "body velocity" and (m := _BODY_KEY.match(key))}


def own_symbols_said(counterexample: dict | None, rows: dict) -> None:
    """Name, in ``counterexample``'s ``symbols`` (changed in place), each symbol the reader
    introduced by what it is: ``w, the body angular velocity of \\mathbf{Q}, introduced by
    the reader`` for a rotation's (``... velocity`` for a transform's).

    Args:
        counterexample: the symbolic path's, or ``None``.
        rows: the reading's glyph key -> glyph; the reader's own have the meaning
            ``body velocity`` (:func:`body_velocities`).
    """
    if not counterexample:
        return
    said = {}
    for owner, key in body_velocities(rows).items():
        g = rows[key]
        what = "angular velocity" if tuple(getattr(g, "shape", ()) or ()) == (3, 1) \
            else "twist"
        of = getattr(rows.get(owner), "name", owner)
        said[key] = f"{g.name}, the body {what} of {of}, introduced by the reader"
    for s in counterexample.get("symbols") or []:
        if s.get("latex") in said:
            s["symbol"] = said[s["latex"]]
