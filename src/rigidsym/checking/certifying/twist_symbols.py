"""Symbol-table lines of section 3.8's twists and momenta: how certcheck's second
reader binds the book's twist ``t``, momentum screw ``mu``, wrench ``w``, momenta ``m``,
``h_C``, the resultant ``f`` and moment ``n_C`` and their rates to a certificate's atoms,
each line in the book's glyphs for a referee to hold against the page.

The project's model (``derivations/sec3_8_newton_euler.py``, ``dynamics_model``) is the
moving body of four point masses of :mod:`rigidsym.checking.certifying.body_symbols`, with

- ``t = [omega; c-dot]``: "the twist of the body, defined at its center of mass" (the page's
  words in Exercise 3.17; (3.72) with ``v = c-dot``), and ``t-dot`` its rate;
- ``m = m c-dot``, ``h_C = I_C omega`` as printed in (3.135), their rates the time
  derivatives (``m`` constant; ``I_C-dot`` the derivative of the integral of (3.130));
- ``W`` as printed in (3.140); ``mu = M t`` as printed in (3.142), ``mu-dot`` the time
  derivative of ``M(t) t(t)``, ``M-dot = diag(I_C-dot, O)`` (``M`` of (3.138) the page's);
- ``f`` and ``n_C``, the force and the moment about the centre of mass of the wrench acting
  on the body (the page's words before (3.134a)), as the model has them: the wrench the
  motion requires, the integrals of ``rho p-ddot`` and ``rho r x p-ddot`` (internal forces
  cancel in pairs); ``w = [n_C; f]``, (3.113)'s wrench about C.

``M`` is read through its printed definition (3.138); a body whose table has no ``o`` (the
certificate's relation free of it) or no ``s_i`` gets no lines (3.134a, 3.138, 3.141).

Section 3.4.2's twist at a point A (``derivations/sec3_4_2.py``, ``rates_model``): ``v =
a-dot``, the velocity of the model's reference point A, ``t = [omega; v]`` as printed in
(3.72), ``t_A``, ``t_P`` as printed in (3.81) (``v_A``, ``v_P`` the model's lines).
Section 3.5's twist at a body point P (``derivations/sec3_5.py``): ``v = p-dot``, ``v-dot =
p-ddot``, ``t = [omega; v]`` (3.72) and ``t-dot = [omega-dot; v-dot]`` as printed in (3.90).
"""

from __future__ import annotations

__all__ = ["TWIST_GLYPHS", "twist_symbols"]

_R_DOT = r"(\dot{\mathbf{p}} - \dot{\mathbf{c}})"
#: (glyph, LaTeX in the table's glyphs, the model's words)
_LINES = (
    (r"\mathbf{t}", r"\begin{bmatrix} \boldsymbol{\omega} \\ \dot{\mathbf{c}} \end{bmatrix}",
     "twist at the centre of mass, [omega; c-dot] ((3.72) with v = c-dot)"),
    (r"\dot{\mathbf{t}}", r"\begin{bmatrix} \dot{\boldsymbol{\omega}} \\ \ddot{\mathbf{c}} "
     r"\end{bmatrix}", "rate of the twist at the centre of mass"),
    (r"\mathbf{m}", r"m\dot{\mathbf{c}}", "momentum as printed in (3.135)"),
    (r"\mathbf{h}_C", r"\mathbf{I}_C\boldsymbol{\omega}",
     "angular momentum about C as printed in (3.135)"),
    (r"\dot{\mathbf{I}}_C", r"\int_{\mathcal{B}} \rho (2\mathbf{r}^T" + _R_DOT + r"\mathbf{1} - "
     + _R_DOT + r"\mathbf{r}^T - \mathbf{r}" + _R_DOT + r"^T) d\mathcal{B}",
     "rate of I_C (3.130): the time derivative of its integral, r-dot = p-dot - c-dot"),
    (r"\dot{\mathbf{m}}", r"m\ddot{\mathbf{c}}", "rate of m = m c-dot (3.135), m constant"),
    (r"\dot{\mathbf{h}}_C", r"\dot{\mathbf{I}}_C\boldsymbol{\omega} + \mathbf{I}_C"
     r"\dot{\boldsymbol{\omega}}", "rate of h_C = I_C omega (3.135)"),
    (r"\mathbf{W}", r"\begin{bmatrix} \boldsymbol{\Omega} & \mathbf{O} \\ \mathbf{O} & "
     r"\mathbf{O} \end{bmatrix}", "angular-velocity dyad as printed in (3.140)"),
    (r"\boldsymbol{\mu}", r"\mathbf{M}\mathbf{t}", "momentum screw, mu = M t (3.142)"),
    (r"\dot{\mathbf{M}}", r"\begin{bmatrix} \dot{\mathbf{I}}_C & \mathbf{O} \\ \mathbf{O} & "
     r"\mathbf{O} \end{bmatrix}", "rate of M (3.138), m constant"),
    (r"\dot{\boldsymbol{\mu}}", r"\dot{\mathbf{M}}\mathbf{t} + \mathbf{M}\dot{\mathbf{t}}",
     "rate of mu = M t (3.142)"),
    (r"\mathbf{f}", r"\int_{\mathcal{B}} \rho\ddot{\mathbf{p}} d\mathcal{B}",
     "force of the wrench acting on the body, the one the motion requires: the integral of "
     "rho p-ddot (internal forces cancel in pairs)"),
    (r"\mathbf{n}_C", r"\int_{\mathcal{B}} \rho\mathbf{r} \times \ddot{\mathbf{p}} "
     r"d\mathcal{B}", "moment about C of that wrench: the integral of rho r x p-ddot"),
    (r"\mathbf{w}", r"\begin{bmatrix} \mathbf{n}_C \\ \mathbf{f} \end{bmatrix}",
     "the wrench about C, [n_C; f] ((3.113) at C)"),
)

#: section 3.4.2's twist at the point A (``derivations/sec3_4_2.py``, ``rates_model``)
_AT_A = (
    (r"\mathbf{v}", r"\dot{\mathbf{a}}", "the velocity of the twist's point A"),
    (r"\mathbf{t}", r"\begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v} \end{bmatrix}",
     "the twist at A as printed in (3.72)"),
    (r"\mathbf{t}_A", r"\begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v}_A "
     r"\end{bmatrix}", "the twist at A as printed in (3.81)"),
    (r"\mathbf{t}_P", r"\begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v}_P "
     r"\end{bmatrix}", "the twist at P as printed in (3.81)"),
)
#: section 3.5's twist at a body point P (``derivations/sec3_5.py``, ``_generic``)
_AT_P = (
    (r"\mathbf{v}", r"\dot{\mathbf{p}}", "the velocity of the twist's body point P"),
    (r"\dot{\mathbf{v}}", r"\ddot{\mathbf{p}}", "the acceleration of the twist's point P"),
    (r"\mathbf{t}", r"\begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v} \end{bmatrix}",
     "the twist at P as printed in (3.72)"),
    (r"\dot{\mathbf{t}}", r"\begin{bmatrix} \dot{\boldsymbol{\omega}} \\ \dot{\mathbf{v}}"
     r" \end{bmatrix}", "the twist's rate as printed in (3.90)"),
)
#: the glyphs of section 3.8's lines, in order
TWIST_GLYPHS = tuple(g for g, _, _ in _LINES)


def twist_symbols(have: set, section: str) -> list[dict]:
    """The lines of the twists and momenta for a table whose glyphs are ``have``.

    Args:
        have: the glyphs the table already gives (atoms' glyphs, model lines and the lines
            of :func:`rigidsym.checking.certifying.body_symbols.point_body_symbols`).
        section: the id's section: ``3.8`` (and its subsections), ``3.4.2`` (the twist
            at A, where the table has ``a-dot``) or ``3.5`` (at P, where it has ``p-ddot``).

    Returns:
        Entries ``{"glyph", "latex", "model"}``, only for glyphs the table lacks: ``W``
        where it has ``Q-dot``, ``t`` where it has ``Q-dot`` and ``c-dot`` or ``o-dot``, the
        others only where it has the moving body (``omega``, ``c-dot``, ``c-ddot``,
        ``omega-dot``, ``I_C``, ``p-dot``, ``p-ddot`` through the body line); in section
        3.4.2 ``v``, ``t``, ``t_A`` and ``t_P`` (where ``v_P`` is given); in section 3.5
        ``v``, ``v-dot``, ``t``, ``t-dot``; ``[]`` elsewhere.
    """
    need = {"\\boldsymbol{\\omega}", "\\dot{\\boldsymbol{\\omega}}", "\\dot{\\mathbf{c}}",
            "\\ddot{\\mathbf{c}}", "\\mathbf{I}_C", "\\boldsymbol{\\Omega}", "\\ddot{\\mathbf{o}}"}
    if section == "3.4.2" and "\\dot{\\mathbf{a}}" in have:  # the twist at a point A
        return [{"glyph": g, "latex": x, "model": w} for g, x, w in _AT_A if g not in have
                and (g != "\\mathbf{t}_P" or "\\mathbf{v}_P" in have)]
    if section == "3.5" and "\\ddot{\\mathbf{p}}" in have:  # the twist at a body point P
        return [{"glyph": g, "latex": x, "model": w} for g, x, w in _AT_P if g not in have]
    if not section.startswith("3.8"):
        return []
    body = need <= have  # W needs only Omega (its printed definition (3.44) if not a line),
    spin = "\\dot{\\mathbf{Q}}" in have  # t only omega (3.45) and c-dot (3.141: W t = 0;
    # c-dot the line of the moving body's o-dot)
    return [{"glyph": g, "latex": x, "model": w} for g, x, w in _LINES if g not in have
            and (body or g == "\\mathbf{W}" and spin or g == "\\mathbf{t}" and spin and
                 {"\\dot{\\mathbf{c}}", "\\dot{\\mathbf{o}}"} & have)]
