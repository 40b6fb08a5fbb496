"""Symbol-table lines of sections 3.3, 3.4.1 and 3.4.2's first screws: how
certcheck's second reader binds the glyphs the page defines in words, or by a display
below the one that uses them, to a certificate's atoms, each line in the book's glyphs for
a referee to hold against the page.

Section 3.3 (``derivations/sec3_3.py``, ``fixed_point_motion_model``): ``Q(t)`` of the
natural invariants (the table's ``Q`` as printed in (2.49)), the fixed point O at the
origin, so ``p = Q p_0`` (the words before (3.41): ``p_0`` mapped by ``Q``), ``p-dot`` its
time derivative (``p_0`` constant), ``Omega = Q-dot Q^T`` (3.44), ``omega = vect(Omega)``
(3.45).

Section 3.4.1 (``derivations/sec3_4_1.py``, ``sec3_4_1_isa_point.py``): the generic motion
(``Q`` of the quaternion, ``a``, ``a-dot`` free); ``Omega``, ``omega`` are read through
their printed definitions (3.44), (3.45). The lines:

- ``p'_0``, the ISA's point closest to the origin (the words before (3.64)): the ISA is
  the line through ``r = a + Omega a-dot / ||omega||^2`` along ``omega`` ((3.62a)-(3.63)),
  so its point closest to the origin is ``r``'s component normal to ``omega`` ((2.6b)).
  This is not (3.70)'s closed form, which the certificates prove against it;
- ``p``, a point of the ISA, ``p'_0 + alpha omega`` (``alpha`` free: the words after
  (3.63), a vector ``alpha omega`` added to a point of the ISA), where the table has
  ``alpha``; in (3.63), the solution the model takes, the ISA point nearest A (the foot
  of the perpendicular from A onto the ISA);
- ``r``, ``A``, ``b`` as printed in (3.62b), (3.66), the displays that define them just
  below their first use ((3.62a), (3.65));
- ``a-dot_par``, ``a-dot_perp``, the components of ``a-dot`` along and normal to
  ``omega`` (the words before (3.56); (2.6a), (2.6b) with ``e = omega / ||omega||``);
- ``v_0``, Theorem 3.4.2's velocity common to the ISA's points: every point's axial
  component ((3.59)'s first brace), the normal one vanishing on the ISA (3.60);
- ``p-dot = a-dot + Q-dot r``, a generic body point's velocity (``r`` constant), in
  (3.53), whose certificate has ``r`` but no ``a`` (cancelled); not in (3.59), whose one
  printed relation in the certificate is its ``p-dot_perp`` brace's, which ``p-dot`` is
  not.

Section 3.4.2 (``derivations/sec3_4_2_twists.py``): the screw's pitch ``p`` (the atom
``pitch``: the words before (3.71)); a pure translation's ``||v||`` (the atom
``sec342_sigma``), ``v = ||v|| e``, ``omega = 0`` (``Q`` constant) and ``t = [omega; v]``
(3.72); the arrays ``s``, ``s_inf``, ``nu``, ``lambda``, ``eta`` as printed in (3.71),
(3.74), (3.75) (their own displays: the ids that print them are definitions).
"""

from __future__ import annotations

__all__ = ["INSTANT_SCREW_GLYPHS", "instant_screw_symbols"]

_W2 = r"\|\boldsymbol{\omega}\|^2"
_R = rf"\mathbf{{a}} + \frac{{1}}{{{_W2}}}\boldsymbol{{\Omega}}\dot{{\mathbf{{a}}}}"
_PAR = rf"\frac{{\boldsymbol{{\omega}}\boldsymbol{{\omega}}^T}}{{{_W2}}}"
#: section 3.3, the body turning about O fixed at the origin: (glyph, LaTeX, words)
_FIXED_POINT = (
    (r"\mathbf{p}", r"\mathbf{Q}\mathbf{p}_0", "point P of the body turning about O fixed at "
     "the origin: its original position p_0 mapped by Q (the words before (3.41))"),
    (r"\dot{\mathbf{p}}", r"\dot{\mathbf{Q}}\mathbf{p}_0",
     "velocity of P, the time derivative of Q p_0 (p_0 constant)"),
    (r"\boldsymbol{\Omega}", r"\dot{\mathbf{Q}}\mathbf{Q}^T",
     "angular-velocity matrix, Q-dot Q^T (3.44)"),
    (r"\boldsymbol{\omega}", r"\text{vect}(\boldsymbol{\Omega})",
     "angular-velocity vector, vect(Omega) (3.45)"),
)
#: section 3.4.1, the instant screw of the generic motion
_ISA = (
    (r"\mathbf{p}'_0", rf"(\mathbf{{1}} - {_PAR})({_R})", "ISA point closest to the origin "
     "(the words before (3.64)): the component normal to omega ((2.6b)) of the ISA's point "
     "r = a + Omega a-dot / ||omega||^2 ((3.62b)-(3.63): the ISA is the line through r "
     "along omega)"),
    (r"\mathbf{r}", _R, "ISA point r as printed in (3.62b)"),
    (r"\mathbf{A}", r"\begin{bmatrix} \boldsymbol{\Omega} \\ \boldsymbol{\omega}^T "
     r"\end{bmatrix}", "4 x 3 matrix of the system (3.65), as printed in (3.66)"),
    (r"\mathbf{b}", rf"\begin{{bmatrix}} \boldsymbol{{\Omega}}\mathbf{{a}} + "
     rf"\frac{{1}}{{{_W2}}}\boldsymbol{{\Omega}}^2\dot{{\mathbf{{a}}}} \\ 0 \end{{bmatrix}}",
     "right side of the system (3.65), as printed in (3.66)"),
    (r"\dot{\mathbf{a}}_{\parallel}", rf"{_PAR}\dot{{\mathbf{{a}}}}", "component of a-dot "
     "along omega, e e^T a-dot with e = omega / ||omega|| ((2.6a); the words before (3.56))"),
    (r"\dot{\mathbf{a}}_{\perp}", rf"(\mathbf{{1}} - {_PAR})\dot{{\mathbf{{a}}}}",
     "component of a-dot normal to omega, (1 - e e^T) a-dot with e = omega / ||omega|| "
     "((2.6b); the words before (3.56))"),
)
#: Theorem 3.4.2's v_0, where (3.52) prints it
_V0 = (r"\mathbf{v}_0", rf"{_PAR}\dot{{\mathbf{{a}}}}", "minimum-magnitude velocity common to "
       "the ISA's points (Theorem 3.4.2): the axial component of every point's velocity "
       "((3.59)'s first brace), the normal one vanishing on the ISA (3.60)")
#: (3.52)'s signed magnitude v_0 (the words after (3.52)); (3.55)'s e', n' and (3.54)'s array
_V0_SIGNED = ("v_0", r"\frac{\mathbf{v}_0 \cdot \boldsymbol{\omega}}{\|\boldsymbol{\omega}\|}",
              "signed magnitude of v_0, bearing the sign of v_0 . omega (the words after (3.52))")
_ISA_LINE = ((r"\mathbf{e}'", r"\frac{\boldsymbol{\omega}}{\|\boldsymbol{\omega}\|}",
              "unit vector of the ISA as printed in (3.55)"),
             (r"\mathbf{n}'", r"\mathbf{p} \times \mathbf{e}'",
              "moment of the ISA about the origin as printed in (3.55)"),
             (r"\mathbf{p}_{\mathcal{L}'}", r"\begin{bmatrix} \mathbf{e}' \\ \mathbf{n}' "
              r"\end{bmatrix}", "Plücker array of the ISA as printed in (3.54)"))
#: the velocity of a generic body point p = a + Q r (r constant), where a is not in the table
_BODY_VELOCITY = (r"\dot{\mathbf{p}}", r"\dot{\mathbf{a}} + \dot{\mathbf{Q}}\mathbf{r}",
                  "velocity of the body point P = a + Q r, r constant (the words before "
                  "(3.47): any point of the body)")
#: (3.59)'s braces: p-dot's components along and normal to omega, p-dot the body point's
_BRACES = ((r"\dot{\mathbf{p}}_{\parallel}", rf"{_PAR}\dot{{\mathbf{{p}}}}", "component of "
            "p-dot along omega, e e^T p-dot with e = omega / ||omega|| ((2.6a); the words after "
            "(3.59): the axial component)"),
           (r"\dot{\mathbf{p}}_{\perp}", rf"(\mathbf{{1}} - {_PAR})\dot{{\mathbf{{p}}}}",
            "component of p-dot normal to omega, (1 - e e^T) p-dot with e = omega / ||omega|| "
            "((2.6b); the words after (3.59): the normal component)"))
#: the ISA point p: a generic one (alpha in the table), or (3.63)'s, nearest A
_ON_ISA = (r"\mathbf{p}'_0 + \alpha\boldsymbol{\omega}", "point of the ISA, p'_0 + alpha "
           "omega, alpha free (the words after (3.63): alpha omega added to an ISA point)")
_NEAREST_A = (rf"\mathbf{{p}}'_0 + \frac{{\boldsymbol{{\omega}}^T(\mathbf{{a}} - "
              rf"\mathbf{{p}}'_0)}}{{{_W2}}}\boldsymbol{{\omega}}", "solution of (3.61) that "
              "(3.63) takes: the ISA point nearest A, the foot of the perpendicular from A")
#: the velocity of a point P of the ISA, (3.49) (Theorem 3.4.2's words)
_ISA_VELOCITY = (r"\dot{\mathbf{p}}", r"\dot{\mathbf{a}} + \boldsymbol{\Omega}(\mathbf{p} - "
                 r"\mathbf{a})", "velocity of the point P of the ISA, a-dot + Omega (p - a) "
                 "as printed in (3.49)")
#: section 3.4.2's pure translation (the atom sec342_sigma its speed ||v||)
_TRANSLATION = (
    (r"\mathbf{v}", r"\|\mathbf{v}\|\mathbf{e}", "velocity of the pure translation along the "
     "unit e (the words before (3.73)), of magnitude ||v||"),
    (r"\boldsymbol{\omega}", r"\mathbf{0}", "angular velocity of a pure translation: Q "
     "constant, Omega = Q-dot Q^T = O (the twist of infinite pitch, before (3.73))"),
    (r"\mathbf{t}", r"\begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v} \end{bmatrix}",
     "twist as printed in (3.72)"),
    (r"\mathbf{s}_\infty", r"\begin{bmatrix} \mathbf{0} \\ \mathbf{e} \end{bmatrix}",
     "screw of infinite pitch as printed in (3.74)"),
)
#: section 3.4.2's arrays printed in (3.71) and (3.75): (glyph, LaTeX, words, needed)
_ARRAYS = (
    (r"\mathbf{s}", r"\begin{bmatrix} \mathbf{e} \\ \mathbf{p} \times \mathbf{e} + p\mathbf{e}"
     r" \end{bmatrix}", "screw of the line through p along e, of pitch p, as printed in "
     "(3.71)", "p"),
    (r"\boldsymbol{\nu}", r"\begin{bmatrix} \mathbf{e} \\ \phi \end{bmatrix}",
     "natural invariants as printed in (3.75)", r"\phi"),
    (r"\boldsymbol{\lambda}", r"\begin{bmatrix} (\sin \phi)\mathbf{e} \\ \cos \phi "
     r"\end{bmatrix}", "linear invariants as printed in (3.75)", r"\phi"),
    (r"\boldsymbol{\eta}", r"\begin{bmatrix} [\sin(\phi/2)]\mathbf{e} \\ \cos(\phi/2) "
     r"\end{bmatrix}", "Euler-Rodrigues parameters as printed in (3.75)", r"\phi"),
)
#: the glyphs of the lines in the book's LaTeX (those given by a model's words or an atom)
INSTANT_SCREW_GLYPHS = tuple(dict.fromkeys(
    [g for rows in (_FIXED_POINT, _ISA, _TRANSLATION, [_V0, _V0_SIGNED], _ISA_LINE)
     for g, _, _ in rows]
    + ["\\mathbf{p}"]
    + [g for g, _, _, _ in _ARRAYS] + ["p", "\\|\\mathbf{v}\\|"]))


def _lines(rows, have: set) -> list[dict]:
    return [{"glyph": g, "latex": x, "model": w} for g, x, w in rows if g not in have]


def instant_screw_symbols(have: set, section: str, latex: str,
                          table: list[dict]) -> list[dict]:
    """The lines of sections 3.3, 3.4.1 and 3.4.2's screws for a table whose glyphs are
    ``have``.

    Args:
        have: the glyphs the table already gives (atoms' glyphs and the lines before).
        section: the id's section (``3.3``, ``3.4.1``, ``3.4.2``; ``[]`` elsewhere).
        latex: the id's printed text (a line of section 3.4.2 only where its glyph is
            printed; (3.63)'s point ``p`` where ``p = r`` is printed).
        table: the table's entries (an atom's entry, bound to the page's glyph for it).

    Returns:
        Entries ``{"glyph", "latex", "model"}`` (or an atom's entry under the page's glyph),
        only for glyphs the table lacks: in section 3.3 ``p``, ``p-dot`` (where the table
        has ``p_0``), ``Omega``, ``omega`` (where it has ``Q-dot``); in section 3.4.1, where
        it has ``a`` and ``a-dot`` (and no body vector ``r``), ``p'_0``, ``r``, ``A``,
        ``b``, and ``p`` where it has ``alpha`` or the page prints (3.63); ``a-dot_par``,
        ``a-dot_perp``, ``v_0`` where they are printed (``v_0`` in (3.53) too); ``p-dot``
        of the body point ``a + Q r`` where it has the body vector ``r`` and ``p-dot .`` is
        printed; in section 3.4.2 the pitch ``p`` and ``s`` (the atom ``pitch``), the pure
        translation's ``||v||``, ``v``, ``omega``, ``t``, ``s_inf`` (the atom
        ``sec342_sigma``), ``nu``, ``lambda``, ``eta`` where (3.75) is printed.
    """
    dot_q, adot = "\\dot{\\mathbf{Q}}", "\\dot{\\mathbf{a}}"
    if section == "3.3" and dot_q in have:
        return _lines(_FIXED_POINT if "\\mathbf{p}_0" in have else _FIXED_POINT[2:], have)
    if section == "3.4.1" and adot in have:
        rows = list(_ISA[4:]) if "\\dot{\\mathbf{a}}_{\\parallel}" in latex else []
        rows += [_V0, _V0_SIGNED] if "\\mathbf{v}_0 =" in latex or \
            "\\equiv \\frac{v_0}" in latex else []  # (3.53)'s v_0 (its m/rad alternative)
        if "\\mathbf{r}" in have and "\\dot{\\mathbf{p}} \\cdot" in latex:  # (3.53), not
            rows.append(_BODY_VELOCITY)  # (3.59): its certificate's relation is a brace's
        if "\\dot{\\mathbf{p}}_{\\perp}" in latex and "\\mathbf{r}" in have:  # (3.59)
            rows += _BRACES
        if "\\mathbf{a}" in have and "\\mathbf{r}" not in have:
            rows[:0] = _ISA[:4]
            if "\\alpha" in have or "\\mathbf{p} = \\mathbf{r}" in latex:
                rows.append(("\\mathbf{p}", *(_ON_ISA if "\\alpha" in have else _NEAREST_A)))
                if "\\alpha" in have and any(f"{g} \\equiv" in latex for g, _, _ in _ISA_LINE):
                    rows += _ISA_LINE  # (3.54), (3.55): e', n' and the array as printed
        return _lines(rows, have)
    if section == "3.4" and dot_q in have and "angular-velocity vector" in latex:  # the
        return _lines(_FIXED_POINT[2:], have)  # words of Corollary 3.4.1: Omega, omega
    if section == "3.4" and "\\mathbf{v}_0" in latex and "\\alpha" in have:  # Thm 3.4.2
        return _lines([*_FIXED_POINT[2:], _ISA[0], _V0, ("\\mathbf{p}", *_ON_ISA),
                       _ISA_VELOCITY], have)
    if section != "3.4.2":
        return []
    atom = {e["glyph"]: e for e in table if "atoms" in e}
    out = []
    if "pitch" in atom and "p" not in have:  # the screw's pitch, printed p
        out.append({**atom["pitch"], "glyph": "p"})
    if "sec342_sigma" in atom and "\\|\\mathbf{v}\\|" not in have:  # the speed ||v||
        out.append({**atom["sec342_sigma"], "glyph": "\\|\\mathbf{v}\\|"})
        out += _lines(_TRANSLATION, have)
    have = have | {e["glyph"] for e in out}
    out += [{"glyph": g, "latex": x, "model": w} for g, x, w, need in _ARRAYS
            if g not in have and need in have and f"{g} \\equiv" in latex]
    return out
