"""Symbol-table lines of sections 3.7 and 3.8 that the page defines on the id itself:
the glyph an id introduces with ``\\equiv`` (certcheck's reader does not read it through
its own definition), the wrench transfer ``V`` printed below its first use, and section 3.8's
centre of mass, body point and inertia dyad at a point where the certificate's table has no
point-mass body line. Each line is in the book's glyphs, for a referee to hold against the
page.

The models (``derivations/sec3_7.py``, ``sec3_7_reciprocity.py``, ``sec3_8.py``,
``sec3_8_mass_properties.py``, ``sec3_8_newton_euler.py``):

- ``Gamma`` of the reciprocity product, the 6 x 6 ``[[O, 1], [1, O]]`` (3.112);
- the wrench arrays ``w_A = [n_A; f]``, ``w_P = [n_P; f]`` of the system of forces, (3.113)'s
  array about A and P (3.118), and ``V`` as printed in (3.119b) (in (3.119a), one line above
  its definition, the nearest ``V \\equiv`` above is (3.97d)'s, another matrix);
- the body of four point masses placed so that ``sum m_i rho_i = 0``: its centre of mass
  ``c`` is ``o`` (the model's words, ``sec3_8.POINT_BODY_WORDS``), and ``c-dot = o-dot``;
  a body point ``p = o + Q s_P`` (or ``p_P`` at rest) and its velocity, ``omega = vect(Q-dot
  Q^T)``, ``R``, ``C`` the cross-product matrices of ``r``, ``c``, where no body line gives
  them (the certificate's relation free of the body's shape ``s_i``: 3.127, 3.128, 3.132,
  3.134a, whose ``c-ddot`` is then ``o-ddot``);
- ``q_O``, ``T``, ``M``, ``I_A`` as printed in (3.124), (3.126), (3.138), (3.131) (the
  model's integrals and dyad are these), and ``r = p - c`` as printed in (3.127), on the id
  that defines them;
- ``M_A``, the model's inertia dyad at A: the Hessian of the kinetic energy ``1/2 int rho
  ||v + omega x (p - a)||^2`` in the twist ``[omega; v]`` at A, which is the integral of
  ``rho [[(P_i - A)^T (P_i - A), P_i - A], [(P_i - A)^T, 1]]`` (``P_i``, ``A`` the
  cross-product matrices of the particle's ``p`` and of ``a``: the page's ``P`` of (3.148) is
  another); ``M_C``, the ``M`` of (3.138) that the words after (3.146) subscript with C.
"""

from __future__ import annotations

__all__ = ["wrench_inertia_symbols"]

_O, _1 = r"\mathbf{O}", r"\mathbf{1}"
_INT = r"\int_{\mathcal{B}} \rho "
_PA = r"(\mathbf{P}_i - \mathbf{A})"
#: (glyph defined on the id with \equiv, section, LaTeX in the table's glyphs, words)
_OWN = (
    (r"\mathbf{\Gamma}", "3.7", rf"\begin{{bmatrix}} {_O} & {_1} \\ {_1} & {_O} \end{{bmatrix}}",
     "6 x 6 Gamma of the reciprocity product s_w^T Gamma s_t, as printed in (3.112)"),
    (r"\mathbf{q}_O", "3.8", _INT + r"\mathbf{p} d\mathcal{B}",
     "mass first moment about O, the integral over the body as printed in (3.124)"),
    (r"\mathbf{c}", "3.8", r"\mathbf{o}", "centre of mass C: the body's points are placed so "
     "that the sum of m_i rho_i is 0, so C is at o"),
    (r"\mathbf{r}", "3.8", r"\mathbf{p} - \mathbf{c}", "position of P from C as printed in "
     "(3.127)"),
    ("T", "3.8", _INT + r"\frac{1}{2}\|\dot{\mathbf{p}}\|^2 d\mathcal{B}",
     "kinetic energy as printed in (3.126)"),
    (r"\mathbf{M}", "3.8", rf"\begin{{bmatrix}} \mathbf{{I}}_C & {_O} \\ {_O} & m{_1} "
     r"\end{bmatrix}", "inertia dyad as printed in (3.138)"),
    (r"\mathbf{I}_A", "3.8", _INT + r"[\|\mathbf{p} - \mathbf{a}\|^2 \mathbf{1} - (\mathbf{p} - "
     r"\mathbf{a})(\mathbf{p} - \mathbf{a})^T] d\mathcal{B}",
     "moment of inertia about A as printed in (3.131)"),
)
_V = (r"\mathbf{V}", rf"\begin{{bmatrix}} {_1} & \mathbf{{A}} - \mathbf{{P}} \\ \mathbf{{0}} & "
      rf"{_1} \end{{bmatrix}}", "wrench transfer from A to P as printed in (3.119b)")
_M_A = (r"\mathbf{M}_A", _INT + rf"\begin{{bmatrix}} {_PA}^T{_PA} & {_PA} \\ {_PA}^T & {_1} "
        r"\end{bmatrix} d\mathcal{B}", "inertia dyad at A: the Hessian of the kinetic energy "
        "1/2 int rho ||v + omega x (p - a)||^2 in the twist [omega; v] at A, P_i = CPM(p)")


def _defines(latex: str, glyph: str) -> bool:
    """Whether ``latex`` defines ``glyph`` itself (``glyph \\equiv`` on the page)."""
    return glyph.replace(" ", "") + "\\equiv" in latex.replace(" ", "")


def wrench_inertia_symbols(have: set, section: str, latex: str) -> list[dict]:
    """The lines of the glyphs sections 3.7 and 3.8 define on the id itself, and of section
    3.8's body point and centre of mass where the table has no point-mass body.

    Args:
        have: the glyphs the table already gives (atoms, model lines, body and twist lines).
        section: the id's section (``3.7`` or ``3.8``; ``[]`` elsewhere).
        latex: the id's printed text (its own ``\\equiv`` definitions, ``V``, ``M_A``).

    Returns:
        Entries ``{"glyph", "latex", "model"}`` or ``{"glyph", "cpm_of"}``, only for glyphs
        the table lacks: ``Gamma``, ``q_O``, ``c``, ``r``, ``T``, ``M``, ``I_A`` where the
        id defines them (``c``, ``q_O``, ``T``, ``M``, ``I_A`` on a body line); ``c`` and
        its rates, ``p``, ``p-dot``, ``omega``, ``R``, ``C`` where the table has ``o`` but
        not the body's shape ``s_i``; ``w_A``, ``w_P`` where printed with ``n_A``, ``n_P``
        and ``f`` given; ``V`` where printed with ``A``, ``P`` given; ``M_A`` where printed
        on a static body with ``a``.
    """
    sec = section.split(".")[:2]
    if sec not in (["3", "7"], ["3", "8"]):
        return []
    sec = ".".join(sec)
    out: list[dict] = []
    got = set(have)

    def line(glyph: str, text: str, words: str) -> None:
        if glyph not in got:
            out.append({"glyph": glyph, "latex": text, "model": words})
            got.add(glyph)

    body = "\\int_{\\mathcal{B}}" in have
    # the body's shape s_i is absent from the relation: no body line gives c, p
    bare = sec == "3.8" and "\\mathbf{o}" in have and "\\mathbf{s}_1" not in have
    for glyph, where, text, words in _OWN:
        if where == sec and _defines(latex, glyph) and (body or where == "3.7" or bare
                                                        and glyph == "\\mathbf{r}"):
            line(glyph, text, words)
    if sec == "3.7":
        for x in ("A", "P"):
            if {f"\\mathbf{{n}}_{x}", "\\mathbf{f}"} <= have and f"\\mathbf{{w}}_{x}" in latex:
                line(f"\\mathbf{{w}}_{x}", f"\\begin{{bmatrix}} \\mathbf{{n}}_{x} \\\\ "
                     "\\mathbf{f} \\end{bmatrix}", f"wrench array (3.113) about {x}")
        if "\\mathbf{V}" in latex and {"\\mathbf{A}", "\\mathbf{P}"} <= have:
            line(*_V)
        return out
    if bare:  # no body line gives them: the centre of mass and a body point as modelled
        line("\\mathbf{c}", "\\mathbf{o}", _OWN[2][3])
        for dots, word in (("dot", "velocity"), ("ddot", "acceleration")):
            if f"\\{dots}{{\\mathbf{{o}}}}" in have:
                line(f"\\{dots}{{\\mathbf{{c}}}}", f"\\{dots}{{\\mathbf{{o}}}}",
                     f"{word} of C, the rate of c = o")
        if "\\mathbf{pP}" in have:
            line("\\mathbf{p}", "\\mathbf{pP}", "a body point P, anywhere")
        if {"\\mathbf{sP}", "\\dot{\\mathbf{Q}}"} <= have:
            line("\\mathbf{p}", "\\mathbf{o} + \\mathbf{Q}\\mathbf{sP}",
                 "a body point P, sP its body coordinates")
            line("\\dot{\\mathbf{p}}", "\\dot{\\mathbf{o}} + \\dot{\\mathbf{Q}}\\mathbf{sP}",
                 "the body point P's velocity")
            line("\\boldsymbol{\\omega}", "\\text{vect}(\\dot{\\mathbf{Q}}\\mathbf{Q}^T)",
                 "angular velocity, omega = vect(Omega) (3.45), Omega = Q-dot Q^T (3.44)")
        for cap, vec in (("\\mathbf{R}", "\\mathbf{r}"), ("\\mathbf{C}", "\\mathbf{c}")):
            if cap not in got:
                out.append({"glyph": cap, "cpm_of": vec})
    if body and "\\mathbf{M}_A" in latex and "\\mathbf{a}" in have and \
            "\\dot{\\mathbf{Q}}" not in have:
        out += [{"glyph": g, "cpm_of": v} for g, v in (("\\mathbf{P}_i", "\\mathbf{p}"), (
            "\\mathbf{A}", "\\mathbf{a}")) if g not in got]  # P_i: a particle's, inside
        line(*_M_A)
    if body and "\\mathbf{M}_C" in latex:  # (3.148): the words after (3.146) subscript M with C
        line("\\mathbf{M}_C", _OWN[5][2], "M of (3.138), subscripted C as the words after "
             "(3.146) say (its moment of inertia centroidal)")
    return out
