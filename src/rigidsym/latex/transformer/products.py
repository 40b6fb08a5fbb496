"""Products written without parentheses, read by the shapes (the outside trial of 16
books): ``a \\cdot b \\times c`` (Goldstein's and Kane's triple product) and a
chain of ``\\cdot`` (``a \\cdot b \\cdot c``). The grammar groups a chain from the left,
which TeX does not say; :func:`rigidsym.latex.rewrites.mixed_products` marks such chains and
these functions, a part of the LaTeX transformer
(:class:`rigidsym.latex.transformer.chapter.LatexTransformer`) called by its
:class:`~rigidsym.latex.transformer.book_notations.BookNotationRules` with the transformer ``r``
(its ``_val``, ``dot``, ``cross``, ``readings`` and ``_note``), read every grouping, keep
the ones whose shapes fit, and refuse where those differ: never one of them by hope. Such a
refusal is of construct ``grouping``: its fix is parentheses, so the reader neither retries
other shapes nor suggests a ``--let``.
"""

from __future__ import annotations

from rigidsym.latex.shapes import LatexError, matrix_shape


def dot_chain(r, items):
    """``x \\cdot y \\cdot z ...`` with no parentheses. The grammar grouped it from the
    left; its groupings give one value where at most two operands are vectors (the others
    scalars: every grouping is the scalars' product times the one dot product), and
    differ with three (``(a \\cdot b) c`` against ``a (b \\cdot c)``), which is refused
    naming both rather than read as one of them."""
    from rigidsym.printing import notation

    vals = [r._val(i) for i in items]
    if sum(matrix_shape(v) is not None for v in vals) >= 3:
        t = [notation.text(v) for v in vals]
        raise LatexError(f"{' · '.join(t)} (no parentheses): with three vectors its "
                         f"groupings differ, ({t[0]} · {t[1]}) {t[2]} against {t[0]} "
                         f"({t[1]} · {t[2]}); write parentheses", "grouping")
    out = vals[0]
    for v in vals[1:]:
        out = r.dot([out, v])
    return out


def mixed(r, items, first: str):
    """Both groupings of ``x op y op' z`` are read; those whose shapes fit are kept.

    One: it is the reading (``a \\cdot (b \\times c)`` of 3-vectors: ``(a \\cdot b)``
    is a scalar, and a scalar has no cross product). Two: only where the ``\\cdot`` has a
    scalar operand (``s \\cdot b \\times c``, ``a \\times b \\cdot s``), the ``\\cdot``
    then a scalar multiple, and every ``\\times`` the reader reads (the cross product,
    ``CPM(a) M``, Featherstone's ``crm(v) m``) is linear in each factor, so
    ``(s b) \\times c = s (b \\times c)``: one value, either reading. Two otherwise
    (no such case with the shapes of the rules today) and none are refused, naming
    both groupings."""
    from rigidsym.printing import notation

    x, y, z = (r._val(i) for i in items)
    f, g = (r.dot, r.cross) if first == "dot" else (r.cross, r.dot)
    op = {"dot": "·", "cross": "×"}
    o1, o2 = (op[first], op["cross" if first == "dot" else "dot"])
    tx, ty, tz = (notation.text(v) for v in (x, y, z))
    said = {"left": f"({tx} {o1} {ty}) {o2} {tz}", "right": f"{tx} {o1} ({ty} {o2} {tz})"}
    got: dict = {}
    for side in ("left", "right"):
        n = len(r.readings)
        try:
            v = g([f([x, y]), z]) if side == "left" else f([x, g([y, z])])
            got[side] = (v, r.readings[n:])
        except LatexError as exc:
            got[side] = str(exc).split(": expected")[0]
        del r.readings[n:]
    ok = [s for s in ("left", "right") if isinstance(got[s], tuple)]
    chain = f"{tx} {o1} {ty} {o2} {tz}"
    if not ok:
        raise LatexError(f"{chain} (no parentheses): neither grouping fits the shapes: "
                         f"{said['left']}: {got['left']}; {said['right']}: "
                         f"{got['right']} (\\cdot takes two vectors of one size or a "
                         f"scalar, \\times two 3-vectors or 6-vectors)", "shapes")
    if len(ok) == 2:
        scalar = x if first == "dot" else z
        if matrix_shape(scalar) is not None:
            raise LatexError(f"{chain} (no parentheses): both groupings fit the shapes "
                             f"and may differ, {said['left']} and {said['right']}; write "
                             f"parentheses", "grouping")
        side = "right" if first == "dot" else "left"
        other = "right" if side == "left" else "left"
        why = (f"{said[other]} is the same value ({notation.text(scalar)} a scalar, × "
               f"linear in each factor)")
    else:
        side = ok[0]
        other = "right" if side == "left" else "left"
        why = f"the one grouping whose shapes fit ({said[other]}: {got[other]})"
    why = "; " + why if len(ok) == 2 else ", " + why
    v, notes = got[side]
    for note in notes:
        r._note(note)
    r._note(f"{chain}: read as {said[side]}{why}")
    return v
