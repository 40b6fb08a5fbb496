"""A counterexample is the point it claims: the rate of a unit vector printed tangent.

The reader reads the rate of a unit vector ``\\mathbf{e}(t)`` as ``(1 - e e^T) ė`` with ``ė``
free (:mod:`rigidsym.latex.transformer.book_notations`), so the symbolic path's point gives
the free ``ė``; the statement used its projection on the tangent of the sphere. The printed
point gives the projection, the value the check used, which satisfies ``e · ė = 0``: a
reader substituting the printed values by hand finds both printed sides.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.deciding.point_values import decimal_text
from rigidsym.printing import notation

__all__ = ["project_rates"]


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
